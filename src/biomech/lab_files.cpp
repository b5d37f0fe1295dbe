// SPDX-License-Identifier: MIT
// OpenSim .trc and .mot/.sto files read with checks and written atomically; CSV by extension.
#include "alembert/biomech/lab_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "alembert/biomech/c3d_file.hpp"
#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"
#include "text_cells.hpp"

namespace alembert {

namespace {

using detail::parse_number;
using detail::split_blanks;
using detail::split_tabs;
using detail::trim_cell;

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
    throw ArgumentError(path + ":" + std::to_string(line) + ": " + what);
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// a line of a text file, not a spreadsheet's or another binary file's bytes (never printed)
void not_binary(const std::string& path, std::size_t line_no, const std::string& line, const std::string& reads) {
    const std::string byte = detail::binary_byte(line);
    if (byte.empty()) return;
    fail(path, static_cast<int>(line_no),
         "not a text file (byte " + byte + "); this reader reads " + reads +
             ": export the data from the lab's software in that format (a spreadsheet such as .xlsx "
             "must be saved as text first)");
}

// "qA [m]": the label's name and unit (a label without "[...]" has no unit)
void split_label(const std::string& label, std::string& name, std::string& unit) {
    name = label, unit.clear();
    const std::size_t open = label.find('['), close = label.rfind(']');
    if (open == std::string::npos || close == std::string::npos || close < open) return;
    name = trim_cell(label.substr(0, open));
    unit = trim_cell(label.substr(open + 1, close - open - 1));
}

// the times of a table read from a file must increase, row by row
void check_times_increase(const Table& table, const std::string& path) {
    const auto& t = table.columns.front();
    for (std::size_t r = 1; r < t.size(); ++r)
        if (!(t[r] > t[r - 1]))
            fail(path, table.lines[r],
                 "time " + format_csv_number(t[r]) + " does not come after " +
                     format_csv_number(t[r - 1]) +
                     " on the row before; sort the rows by time and remove repeated frames");
}

}  // namespace

std::size_t MarkerTable::column(const std::string& marker, int axis) const {
    for (std::size_t m = 0; m < markers.size(); ++m)
        if (markers[m] == marker) return 1 + 3 * m + static_cast<std::size_t>(axis);
    std::string list;
    for (const auto& name : markers) list += (list.empty() ? "" : ", ") + name;
    throw ArgumentError("MarkerTable::column(): no marker '" + marker +
                        "' in the marker file; its markers are: " + list);
}

MarkerTable select_markers(const MarkerTable& trial, const std::vector<std::string>& names) {
    MarkerTable out;
    out.data_rate_hz = trial.data_rate_hz;
    out.file_unit = trial.file_unit;
    out.notes = trial.notes;
    out.table.add_column(trial.table.names[0], trial.table.units[0]);
    out.table.columns[0] = trial.table.columns[0];
    out.table.lines = trial.table.lines;
    // the named markers in the file's order, each once
    for (const std::string& m : trial.markers) {
        if (std::find(names.begin(), names.end(), m) == names.end()) continue;
        out.markers.push_back(m);
        for (int axis = 0; axis < 3; ++axis) {
            const std::size_t c = trial.column(m, axis);
            out.table.add_column(trial.table.names[c], trial.table.units[c]);
            out.table.columns.back() = trial.table.columns[c];
        }
    }
    for (const std::string& m : names) trial.column(m, 0);  // every name is in the file
    return out;
}

MarkerTable read_trc(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ArgumentError("read_trc(): cannot open '" + path + "'; check the file name");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
        not_binary(path, lines.size(), line, "OpenSim marker files (.trc: tab-separated text)");
    }
    auto line_at = [&](std::size_t i) { return i < lines.size() ? lines[i] : std::string(); };

    // line 1: PathFileType
    std::string first = line_at(0);
    if (first.rfind("\xEF\xBB\xBF", 0) == 0) first.erase(0, 3);
    if (split_blanks(first).empty() || split_blanks(first)[0] != "PathFileType")
        fail(path, 1,
             "not an OpenSim marker file: its first line should start with 'PathFileType' "
             "(\"PathFileType 4 (X/Y/Z) name.trc\"); export the markers as .trc");

    // lines 2-3: header keys and their values
    std::vector<std::string> keys = split_tabs(line_at(1)), values = split_tabs(line_at(2));
    if (split_blanks(line_at(1)).size() > keys.size()) keys = split_blanks(line_at(1));
    if (split_blanks(line_at(2)).size() > values.size()) values = split_blanks(line_at(2));
    auto header_value = [&](const std::string& key) -> std::string {
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == key) {
                if (i >= values.size() || values[i].empty())
                    fail(path, 3, "no value for the header key '" + key +
                                      "' (line 2 names it); give one under it");
                return values[i];
            }
        fail(path, 2, "the header has no key '" + key +
                          "'; line 2 should name DataRate, CameraRate, NumFrames, NumMarkers, "
                          "Units, OrigDataRate, OrigDataStartFrame, OrigNumFrames");
    };
    auto header_number = [&](const std::string& key) {
        double v = 0;
        std::string text = header_value(key);
        if (!parse_number(text, v) || !(v > 0) || !std::isfinite(v))
            fail(path, 3, "the header's " + key + " is '" + text + "'; it must be a positive, finite number");
        return v;
    };
    MarkerTable result;
    result.data_rate_hz = header_number("DataRate");
    const double frames_declared = header_number("NumFrames");
    const double markers_declared = header_number("NumMarkers");
    result.file_unit = header_value("Units");
    Unit unit;
    try {
        unit = parse_unit(result.file_unit);
    } catch (const ArgumentError&) {
        fail(path, 3, "the header's Units is '" + result.file_unit + "'; use mm, cm or m");
    }
    if (unit.quantity != "length")
        fail(path, 3, "the header's Units is '" + result.file_unit +
                          "', not a length; marker coordinates are in mm, cm or m");

    // line 4: Frame# Time M1 (blank) (blank) M2 ...
    std::vector<std::string> names = split_tabs(line_at(3));
    if (names.size() < 2 || lower(names[0]).rfind("frame", 0) != 0 || lower(names[1]) != "time")
        fail(path, 4, "the marker names' line should start with 'Frame#' and 'Time', then one "
                      "name above each marker's X column");
    for (std::size_t i = 2; i < names.size(); ++i) {
        if (names[i].empty()) continue;
        if ((i - 2) % 3 != 0)
            fail(path, 4, "the marker name '" + names[i] +
                              "' is not above an X column (names come every third column, after "
                              "Frame# and Time); put one name per marker, followed by two tabs");
        for (const auto& m : result.markers)
            if (m == names[i])
                fail(path, 4, "the marker '" + names[i] + "' is named twice; rename one");
        result.markers.push_back(names[i]);
    }
    if (static_cast<double>(result.markers.size()) != markers_declared)
        fail(path, 4, std::to_string(result.markers.size()) + " marker names, but the header's "
                      "NumMarkers says " + format_csv_number(markers_declared) +
                      "; make them agree");
    if (result.markers.empty()) fail(path, 4, "no marker names; the file holds no markers");

    // columns: time, then X Y Z of each marker in SI
    Table& table = result.table;
    table.add_column("time", "s");
    for (const auto& m : result.markers)
        for (const char* axis : {".X", ".Y", ".Z"}) table.add_column(m + axis, "m");
    const std::size_t cells_max = 2 + 3 * result.markers.size();

    // rows from line 6 on (line 5 is X1 Y1 Z1 ...)
    for (std::size_t i = 5; i < lines.size(); ++i) {
        const int line_no = static_cast<int>(i) + 1;
        if (trim_cell(lines[i]).empty()) continue;
        std::vector<std::string> cells = split_tabs(lines[i]);
        if (cells.size() < cells_max && split_blanks(lines[i]).size() == cells_max)
            cells = split_blanks(lines[i]);  // written with spaces, no missing markers
        while (cells.size() > cells_max && cells.back().empty()) cells.pop_back();
        if (cells.size() > cells_max)
            fail(path, line_no, std::to_string(cells.size()) + " cells, more than the " +
                                    std::to_string(cells_max) + " of Frame#, Time and " +
                                    std::to_string(result.markers.size()) +
                                    " markers' X, Y, Z; remove the extra cells or name the marker");
        double t = 0;
        if (cells.size() < 2 || !parse_number(cells[1], t) || !std::isfinite(t))
            fail(path, line_no, "the time cell '" + (cells.size() > 1 ? cells[1] : "") +
                                    "' is not a finite number; each row starts with frame and time");
        table.columns[0].push_back(t);
        for (std::size_t c = 2; c < cells_max; ++c) {
            double v = kMissing;
            // an infinite coordinate is refused here, where its marker and row are known
            // (NaN, as some exporters write a gap, is a gap)
            if (c < cells.size() && !cells[c].empty() &&
                (!parse_number(cells[c], v) || std::isinf(v))) {
                const std::size_t m = (c - 2) / 3;
                fail(path, line_no, "marker '" + result.markers[m] + "' " + "XYZ"[(c - 2) % 3] +
                                        ": '" + cells[c] +
                                        "' is not a finite number; leave the cell empty where the "
                                        "marker was not seen");
            }
            table.columns[c - 1].push_back(v * unit.factor);
        }
        table.lines.push_back(line_no);
    }
    if (table.row_count() == 0)
        fail(path, static_cast<int>(lines.size()), "no rows of marker data after the header");
    check_times_increase(table, path);
    if (static_cast<double>(table.row_count()) != frames_declared)
        result.notes.push_back(path + ": the header's NumFrames is " +
                               format_csv_number(frames_declared) + " but " +
                               std::to_string(table.row_count()) + " rows were read");
    return result;
}

StorageFile read_storage(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw ArgumentError("read_storage(): cannot open '" + path + "'; check the file name");
    StorageFile result;
    std::string line;
    int line_no = 0;
    bool ended = false;
    // header: a name, key=value lines and free text up to endheader
    const std::string reads = "OpenSim storage files (.sto, .mot: a header to 'endheader', then columns of text)";
    while (std::getline(in, line)) {
        ++line_no;
        not_binary(path, static_cast<std::size_t>(line_no), line, reads);
        std::string text = trim_cell(line);
        if (line_no == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        if (text == "endheader") {
            ended = true;
            break;
        }
        const std::size_t eq = text.find('=');
        if (eq == std::string::npos || text.find(' ') < eq) continue;
        const std::string key = trim_cell(text.substr(0, eq)), value = trim_cell(text.substr(eq + 1));
        result.header[key] = value;
        if (key == "inDegrees") {
            if (value != "yes" && value != "no")
                fail(path, line_no, "inDegrees is '" + value + "'; write inDegrees=yes or inDegrees=no");
            result.in_degrees = value == "yes";
        }
    }
    if (!ended)
        fail(path, line_no,
             "no 'endheader' line; an OpenSim storage file (.sto, .mot) ends its header with a "
             "line 'endheader' before the column labels");

    // column labels
    std::vector<std::string> labels;
    while (labels.empty() && std::getline(in, line)) {
        ++line_no;
        not_binary(path, static_cast<std::size_t>(line_no), line, reads);
        // labels separated by tabs may hold a unit after a space ("qA [m]")
        labels = line.find('\t') != std::string::npos ? split_tabs(line) : split_blanks(line);
        while (!labels.empty() && labels.back().empty()) labels.pop_back();
        if (std::all_of(labels.begin(), labels.end(), [](const std::string& l) { return l.empty(); })) labels.clear();
    }
    if (labels.empty()) fail(path, line_no, "no column labels after 'endheader'");
    const int labels_line = line_no;
    std::string first_name, first_unit;
    split_label(labels[0], first_name, first_unit);
    if (lower(first_name) != "time")
        fail(path, line_no, "the first column is '" + labels[0] +
                                "'; a storage file's first column is 'time'");
    if (auto it = result.header.find("nColumns"); it != result.header.end()) {
        double n = 0;
        if (!parse_number(it->second, n) || n != static_cast<double>(labels.size()))
            fail(path, line_no, std::to_string(labels.size()) + " column labels, but the header says nColumns=" +
                                    it->second + "; make them agree");
    }
    Table& table = result.table;
    for (std::size_t c = 0; c < labels.size(); ++c) {
        std::string name, unit;
        split_label(labels[c], name, unit);
        if (name.empty())
            fail(path, labels_line, "column " + std::to_string(c + 1) + " has no label; name every column");
        for (std::size_t d = 0; d < c; ++d)
            if (table.names[d] == name)
                fail(path, labels_line, "the column '" + name + "' appears twice; rename one");
        if (!unit.empty()) {
            try {
                parse_unit(unit);
            } catch (const ArgumentError& e) {
                fail(path, labels_line, "column '" + labels[c] + "': " + e.what());
            }
        }
        if (c == 0 && !unit.empty() && parse_unit(unit).quantity != "time")
            fail(path, labels_line, "the time column is labelled '" + labels[c] + "'; give it a time unit (s, ms) or none");
        table.add_column(c == 0 ? "time" : name, c == 0 && unit.empty() ? "s" : unit);
    }
    // rows
    while (std::getline(in, line)) {
        ++line_no;
        not_binary(path, static_cast<std::size_t>(line_no), line, reads);
        std::vector<std::string> cells = split_blanks(line);
        if (cells.empty()) continue;
        if (cells.size() != labels.size())
            fail(path, line_no, std::to_string(cells.size()) + " cells, but there are " +
                                    std::to_string(labels.size()) + " column labels; give every column a value");
        for (std::size_t c = 0; c < cells.size(); ++c) {
            double v = 0;
            if (!parse_number(cells[c], v) || std::isinf(v) || (c == 0 && std::isnan(v)))
                fail(path, line_no, "column '" + labels[c] + "': '" + cells[c] + "' is not a finite number");
            table.columns[c].push_back(v);
        }
        table.lines.push_back(line_no);
    }
    if (table.row_count() == 0) fail(path, line_no, "no rows of numbers after the column labels");
    check_times_increase(table, path);
    if (auto it = result.header.find("nRows"); it != result.header.end()) {
        double n = 0;
        if (!parse_number(it->second, n) || n != static_cast<double>(table.row_count()))
            result.notes.push_back(path + ": the header says nRows=" + it->second + " but " +
                                   std::to_string(table.row_count()) + " rows were read");
    }
    return result;
}

Table motion_table_from_storage(const StorageFile& storage,
                                const std::vector<std::string>& angle_columns) {
    Table table = storage.table;
    table.names[0] = "t";
    // inDegrees applies to the listed (rotational) columns that state no unit of their own
    for (const auto& name : angle_columns) {
        std::string& unit = table.units[table.column_index(name)];
        if (unit.empty()) unit = storage.in_degrees ? "deg" : "rad";
    }
    return table;
}

void write_storage(const Table& table, const std::string& path, const std::string& name) {
    std::vector<double> factor;
    for (std::size_t c = 0; c < table.columns.size(); ++c) factor.push_back(parse_unit(table.units[c]).factor);
    const bool time_first =
        !table.columns.empty() && parse_unit(table.units[0]).quantity == "time";
    std::string text = name + "\nversion=1\nnRows=" + std::to_string(table.row_count()) +
                       "\nnColumns=" + std::to_string(table.columns.size()) +
                       "\ninDegrees=no\nendheader\n";
    for (std::size_t c = 0; c < table.names.size(); ++c) {
        if (c) text += '\t';
        text += c == 0 && time_first ? std::string("time") : table.names[c];
    }
    text += '\n';
    // rows in SI
    for (std::size_t r = 0; r < table.row_count(); ++r) {
        for (std::size_t c = 0; c < table.columns.size(); ++c) {
            if (c) text += '\t';
            text += format_csv_number(table.columns[c][r] * factor[c]);
        }
        text += '\n';
    }
    write_file_atomically(path, text, "write_storage()");
}

Table read_lab_table(const std::string& path) {
    const std::string ext = lower(std::filesystem::path(path).extension().string());
    if (ext == ".trc") return read_trc(path).table;
    if (ext == ".sto" || ext == ".mot") return read_storage(path).table;
    if (ext == ".csv") return read_csv(path);
    if (ext == ".c3d") return read_c3d(path).markers.table;
    throw ArgumentError("read_lab_table(): '" + path + "' has the extension '" + ext +
                        "'; known lab files are .trc (markers), .sto and .mot (OpenSim "
                        "storage), .c3d (C3D trials: their markers) and .csv (\"name [unit]\" headers)");
}

}  // namespace alembert
