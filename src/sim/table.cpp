// SPDX-License-Identifier: MIT
// Units, tables and CSV files.
#include "alembert/sim/table.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <utility>

#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

namespace alembert {

namespace {

struct KnownUnit {
    const char* name;
    double factor;
    const char* quantity;
};

const std::vector<KnownUnit>& unit_table() {
    constexpr double deg = std::numbers::pi / 180;
    static const std::vector<KnownUnit> units = {
        {"", 1, ""},
        {"1", 1, ""},
        {"s", 1, "time"},
        {"ms", 1e-3, "time"},
        {"min", 60, "time"},
        {"rad", 1, "angle"},
        {"deg", deg, "angle"},
        {"rev", 2 * std::numbers::pi, "angle"},
        {"m", 1, "length"},
        {"cm", 1e-2, "length"},
        {"mm", 1e-3, "length"},
        {"km", 1e3, "length"},
        {"kg", 1, "mass"},
        {"g", 1e-3, "mass"},
        {"N", 1, "force"},
        {"kN", 1e3, "force"},
        {"N m", 1, "torque"},
        {"N*m", 1, "torque"},
        {"N.m", 1, "torque"},
        {"Nm", 1, "torque"},
        {"N\u00b7m", 1, "torque"},
        {"J", 1, "energy"},
        {"kJ", 1e3, "energy"},
        {"W", 1, "power"},
        {"Hz", 1, "frequency"},
        {"rad/s", 1, "angular velocity"},
        {"deg/s", deg, "angular velocity"},
        {"rpm", 2 * std::numbers::pi / 60, "angular velocity"},
        {"rad/s^2", 1, "angular acceleration"},
        {"deg/s^2", deg, "angular acceleration"},
        {"m/s", 1, "velocity"},
        {"km/h", 1 / 3.6, "velocity"},
        {"m/s^2", 1, "acceleration"},
        {"N m/kg", 1, "torque per mass"},
        {"N/kg", 1, "force per mass"},
        {"W/kg", 1, "power per mass"},
        {"kg m^2", 1, "moment of inertia"}};
    return units;
}

std::string trim(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
        std::size_t comma = line.find(',', start);
        cells.push_back(trim(line.substr(start, comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return cells;
}

// the first lines of an OpenSim .mot/.sto file: "version=1", "nRows=...", "endheader"
bool looks_like_opensim_header(const std::string& line) {
    for (const char* key : {"version=", "nRows=", "nColumns=", "inDegrees=", "DataType="})
        if (line.rfind(key, 0) == 0) return true;
    return line == "endheader";
}

}  // namespace

Unit parse_unit(const std::string& name) {
    const std::string n = trim(name);
    for (const KnownUnit& known : unit_table())
        if (known.name == n) return Unit{n, known.factor, known.quantity};
    std::string list;
    for (const KnownUnit& known : unit_table())
        if (*known.name) list += (list.empty() ? "" : ", ") + std::string(known.name);
    throw ArgumentError("unknown unit '" + n + "'; use one of: " + list);
}

std::size_t Table::add_column(const std::string& name, const std::string& unit) {
    names.push_back(name);
    units.push_back(unit);
    columns.emplace_back();
    return columns.size() - 1;
}

std::size_t Table::column_index(const std::string& name) const {
    for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c] == name) return c;
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw ArgumentError("the table has no column '" + name + "'; its columns are: " + list);
}

std::string format_csv_number(double v, int digits) {
    char buf[40];
    if (digits == 0) {
        // the shortest text that reads back as the same double
        auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        return ec == std::errc{} ? std::string(buf, end) : std::string("nan");
    }
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

void write_csv(const Table& table, const std::string& path, int digits) {
    if (digits < 0 || digits > 17)
        throw ArgumentError("write_csv(): " + std::to_string(digits) +
                            " significant digits asked for '" + path +
                            "'; give 1 to 17, or 0 for the shortest exact form");
    // written to a temporary file renamed into place: an interrupted run leaves no partial table
    std::string text;
    // header: name [unit]
    for (std::size_t c = 0; c < table.names.size(); ++c) {
        if (c) text += ',';
        text += table.names[c];
        if (!table.units[c].empty()) text += " [" + table.units[c] + "]";
    }
    text += '\n';
    // rows
    for (std::size_t r = 0; r < table.row_count(); ++r) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            if (c) text += ',';
            text += format_csv_number(table.columns[c][r], digits);
        }
        text += '\n';
    }
    write_file_atomically(path, text, "write_csv()");
}

Table read_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ArgumentError("read_csv(): cannot open '" + path + "'; check the file name");
    Table table;
    std::string line;
    int line_no = 0;
    bool have_header = false;
    while (std::getline(in, line)) {
        ++line_no;
        // a UTF-8 byte-order mark (spreadsheets write one) is not part of the first cell
        if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
        // a binary file (a spreadsheet's .xlsx is a zip archive): its bytes are never printed
        for (unsigned char c : line)
            if (c == 0x7f || (c < 0x20 && c != '\t' && c != '\r' && c != '\f')) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "0x%02x", c);
                throw ArgumentError(path + ":" + std::to_string(line_no) + ": not a text file (byte " + byte +
                                    "); read_csv() reads CSV text, a header row such as 't [s],qA [deg]' and "
                                    "rows of numbers separated by commas: save a spreadsheet as CSV");
            }
        // an OpenSim motion or storage file: its header ends with a line "endheader"
        if (table.lines.empty() && looks_like_opensim_header(trim(line)))
            throw ArgumentError(path + ":" + std::to_string(line_no) + ": '" + trim(line) +
                                "': this looks like an OpenSim .mot/.sto file; reading it is "
                                "not supported yet: export the coordinates as CSV with a "
                                "header row such as 't [s],q1 [deg]' (the OpenSim header up "
                                "to 'endheader' removed, columns separated by commas)");
        const std::string where = path + ":" + std::to_string(line_no) + ": ";
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        std::vector<std::string> cells = split(t);
        if (!have_header) {
            // header cells: name [unit]
            for (const std::string& cell : cells) {
                std::string name = cell, unit;
                std::size_t open = cell.find('[');
                if (open != std::string::npos) {
                    std::size_t close = cell.find(']', open);
                    if (close == std::string::npos)
                        throw ArgumentError(where + "header cell '" + cell +
                                            "' opens '[' without ']'; write units as 'qA [deg]'");
                    name = trim(cell.substr(0, open));
                    unit = trim(cell.substr(open + 1, close - open - 1));
                }
                if (name.empty())
                    throw ArgumentError(where +
                                        "a header cell has no column name; the first "
                                        "row must name every column");
                for (std::size_t c = 0; c < table.names.size(); ++c)
                    if (table.names[c] == name)
                        throw ArgumentError(where + "column '" + name + "' appears twice (cells " +
                                            std::to_string(c + 1) + " and " +
                                            std::to_string(table.names.size() + 1) +
                                            "); name each column once");
                table.add_column(name, unit);
            }
            have_header = true;
            continue;
        }
        if (cells.size() != table.names.size())
            throw ArgumentError(where + "the row has " + std::to_string(cells.size()) +
                                " cells but the header names " +
                                std::to_string(table.names.size()) + " columns");
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const char* s = cells[c].c_str();
            char* end = nullptr;
            errno = 0;
            double v = std::strtod(s, &end);
            // ERANGE with a finite result is a subnormal number or an underflow to zero: kept
            if (cells[c].empty() || end != s + cells[c].size() ||
                (errno == ERANGE && std::fabs(v) > 1) || !std::isfinite(v))
                throw ArgumentError(where + "cell " + std::to_string(c + 1) + " ('" +
                                    table.names[c] + "') is '" + cells[c] +
                                    "', not a finite number" +
                                    (cells[c].find_first_of(";\t") != std::string::npos
                                         ? "; separate the columns with commas"
                                         : ""));
            table.columns[c].push_back(v);
        }
        table.lines.push_back(line_no);
    }
    if (!have_header)
        throw ArgumentError("read_csv(): '" + path +
                            "' is empty; it needs a header row "
                            "naming the columns and rows of numbers");
    if (table.row_count() == 0)
        throw ArgumentError(path + ":" + std::to_string(line_no) + ": the file has a header " +
                            "but no rows of numbers");
    return table;
}

std::vector<std::size_t> calc_plot_rows(const Table& table, std::size_t max_rows) {
    const std::size_t n = table.row_count();
    std::vector<std::size_t> rows;
    const std::size_t series = table.columns.size() > 1 ? table.columns.size() - 1 : 1;
    const std::size_t runs = std::max<std::size_t>(1, max_rows / (2 * series));
    if (n <= std::max<std::size_t>(max_rows, 2) || n <= 2 * runs) {
        for (std::size_t r = 0; r < n; ++r) rows.push_back(r);
        return rows;
    }
    rows.push_back(0);
    for (std::size_t k = 0; k < runs; ++k) {
        // rows [begin, end) of run k
        const std::size_t begin = k * n / runs, end = (k + 1) * n / runs;
        std::vector<std::size_t> picked;
        for (std::size_t c = 1; c < table.columns.size(); ++c) {
            const std::vector<double>& v = table.columns[c];
            std::size_t lo = begin, hi = begin;
            for (std::size_t r = begin; r < end; ++r) {
                if (v[r] < v[lo]) lo = r;
                if (v[r] > v[hi]) hi = r;
            }
            picked.push_back(lo);
            picked.push_back(hi);
        }
        if (picked.empty()) picked.push_back(begin);
        std::sort(picked.begin(), picked.end());
        for (std::size_t r : picked)
            if (r != rows.back()) rows.push_back(r);
    }
    if (rows.back() != n - 1) rows.push_back(n - 1);
    return rows;
}

Table calc_table_rows(const Table& table, const std::vector<std::size_t>& rows) {
    Table out;
    out.names = table.names;
    out.units = table.units;
    for (const std::vector<double>& column : table.columns) {
        std::vector<double> v;
        v.reserve(rows.size());
        for (std::size_t r : rows) v.push_back(column[r]);
        out.columns.push_back(std::move(v));
    }
    return out;
}

}  // namespace alembert
