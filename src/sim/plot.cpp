// SPDX-License-Identifier: MIT
// gnuplot driven through a pipe: one panel per unit, PNG then SVG.
#include "alembert/sim/plot.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "alembert/error.hpp"

namespace alembert {

namespace {

// gnuplot strings in single quotes: a quote is doubled
std::string gp_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

std::string shell_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string label(const Table& t, std::size_t c) {
    return t.units[c].empty() ? t.names[c] : t.names[c] + " [" + t.units[c] + "]";
}

}  // namespace

std::string gnuplot_program() {
    const char* env = std::getenv("ALEMBERT_GNUPLOT");
    return env && *env ? env : "gnuplot";
}

bool gnuplot_available() {
    const std::string cmd = shell_quoted(gnuplot_program()) + " --version >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

PlotResult plot_csv(const Table& table, const std::string& csv_path, const std::string& output_base,
                    const PlotOptions& options) {
    // columns: x, then the y columns grouped by unit (first appearance order)
    const std::size_t xc = options.x.empty() ? 0 : table.column_index(options.x);
    std::vector<std::size_t> ys;
    if (options.y.empty()) {
        for (std::size_t c = 0; c < table.names.size(); ++c)
            if (c != xc) ys.push_back(c);
    } else {
        for (const std::string& name : options.y) ys.push_back(table.column_index(name));
    }
    std::vector<std::string> units;
    std::map<std::string, std::vector<std::size_t>> by_unit;
    for (std::size_t c : ys) {
        if (!by_unit.count(table.units[c])) units.push_back(table.units[c]);
        by_unit[table.units[c]].push_back(c);
    }

    PlotResult result;
    if (!gnuplot_available()) {
        result.message = "plot not drawn: gnuplot ('" + gnuplot_program() +
                         "') was not found; install it (Debian: apt install gnuplot-nox) or set "
                         "ALEMBERT_GNUPLOT to its path. The numbers are in " +
                         csv_path;
        return result;
    }
    if (ys.empty()) {
        result.message = "plot not drawn: the table has no columns to draw";
        return result;
    }

    // the gnuplot script: one multiplot per terminal, one panel per unit
    std::string panels;
    panels +=
        "set datafile separator ','\nset grid\nset key outside right top\nset autoscale xfix\n";
    panels += "set xlabel " + gp_quoted(label(table, xc)) + "\n";
    std::string title = options.title;
    const std::size_t rows = units.size();
    std::string body;
    body += "set multiplot layout " + std::to_string(rows) + ",1" +
            (title.empty() ? "" : " title " + gp_quoted(title)) + "\n";
    for (const std::string& unit : units) {
        body += "set ylabel " + gp_quoted(unit.empty() ? "value" : "[" + unit + "]") + "\n";
        body += "plot ";
        bool first = true;
        for (std::size_t c : by_unit[unit]) {
            body += (first ? "" : ", ") + gp_quoted(csv_path) + " every ::1 using " +
                    std::to_string(xc + 1) + ":" + std::to_string(c + 1) +
                    " with lines lw 2 title " + gp_quoted(table.names[c]);
            first = false;
        }
        body += "\n";
    }
    body += "unset multiplot\n";
    const std::string height = std::to_string(300 + 300 * rows);
    std::string script = panels;
    script += "set terminal pngcairo size 900," + height + " font 'sans,10' noenhanced\n";
    script += "set output " + gp_quoted(output_base + ".png") + "\n" + body;
    script += "set terminal svg size 900," + height + " dynamic font 'sans,10' noenhanced\n";
    script += "set output " + gp_quoted(output_base + ".svg") + "\n" + body;
    script += "set output\n";

    // run it; gnuplot's complaints go to a temporary file that becomes the message
    const std::string err = output_base + ".gnuplot-errors";
    const std::string cmd = shell_quoted(gnuplot_program()) + " 2>" + shell_quoted(err);
    std::FILE* pipe = ::popen(cmd.c_str(), "w");
    if (!pipe) {
        result.message = "plot not drawn: cannot start gnuplot";
        return result;
    }
    std::fputs(script.c_str(), pipe);
    const int status = ::pclose(pipe);
    std::string complaints;
    if (std::FILE* f = std::fopen(err.c_str(), "r")) {
        char buf[512];
        while (std::fgets(buf, sizeof buf, f)) complaints += buf;
        std::fclose(f);
    }
    std::remove(err.c_str());
    namespace fs = std::filesystem;
    const bool files = fs::exists(output_base + ".png") && fs::exists(output_base + ".svg");
    if (status != 0 || !files) {
        result.message = "plot not drawn: gnuplot failed: " +
                         (complaints.empty() ? std::string("no message") : complaints);
        return result;
    }
    result.drawn = true;
    result.files = {output_base + ".png", output_base + ".svg"};
    return result;
}

}  // namespace alembert
