// SPDX-License-Identifier: MIT
// A sweep's values in roadmap.tex (a linearize's eigenvalues against the swept constant): one
// plot per axis (pgfplots) and a table of the samples, under the statement's printed result.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "alembert/report/report.hpp"
#include "alembert/sim/table.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

using namespace report_detail;

constexpr std::size_t kTableRows = 25;      // a table's rows at most: a page's third
constexpr std::size_t kPlotRows = 400;      // a plot's samples at most (calc_plot_rows)
constexpr std::size_t kSeriesPerPlot = 10;  // as the page: its ten colours, no two alike
constexpr double kRoundOff = 1e-12;         // of the largest magnitude: written 0
// a table's width: at most this of the text's 17 cm, each column as wide as its widest
// cell at \footnotesize (a digit 0.15 cm, a minus sign more) and two 4 pt \tabcolsep
constexpr double kTableCm = 16.0;
constexpr double kCharCm = 0.15;
constexpr double kColumnSepCm = 0.28;

const char* const kMarks[kSeriesPerPlot] = {"*", "square*", "triangle*", "diamond*", "pentagon*",
                                            "o", "square",  "triangle",  "diamond",  "pentagon"};
// the page's ten colours (plots.js's palette)
const char* const kColours[kSeriesPerPlot] = {"1F77B4", "FF7F0E", "2CA02C", "D62728", "9467BD",
                                              "8C564B", "E377C2", "7F7F7F", "BCBD22", "17BECF"};

// the number to 6 significant digits, as the page's data holds it; its exponent, if any,
// without sign or leading zeros ("1.5e-05" as mantissa "1.5", exponent "-5")
struct Digits {
    std::string mantissa, exponent;
};
Digits digits(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6g", v == 0 ? 0.0 : v);  // no -0
    const std::string s = buf;
    const std::size_t e = s.find('e');
    if (e == std::string::npos) return {s, ""};
    const int x = std::stoi(s.substr(e + 1));
    return {s.substr(0, e), std::to_string(x)};
}

// for pgfplots' coordinates: 1.5e-5; nan where not finite (unbounded coords=jump)
std::string coordinate(double v) {
    if (!std::isfinite(v)) return "nan";
    const Digits d = digits(v);
    return d.exponent.empty() ? d.mantissa : d.mantissa + "e" + d.exponent;
}

// for a table's cell, in math: $-5.11468$, $1.5\cdot 10^{-5}$; -- where not finite
std::string cell(double v) {
    if (!std::isfinite(v)) return "--";
    const Digits d = digits(v);
    return "$" + d.mantissa + (d.exponent.empty() ? "" : "\\cdot 10^{" + d.exponent + "}") + "$";
}

// a cell's width estimated (cm)
double cell_cm(double v) {
    if (!std::isfinite(v)) return 2 * kCharCm;
    const Digits d = digits(v);
    double chars = static_cast<double>(d.mantissa.size()) + (v < 0 ? 0.6 : 0);
    if (!d.exponent.empty()) chars += 3 + 0.7 * static_cast<double>(d.exponent.size());
    return chars * kCharCm;
}

// a unit as the page shows it (N*m as N·m)
std::string unit_tex(const std::string& unit) {
    std::string t = tex_text(unit);
    for (std::size_t at = t.find('*'); at != std::string::npos; at = t.find('*', at))
        t.replace(at, 1, "$\\cdot$");
    return t;
}

// names for the reader, runs of one stem with consecutive numbers joined (re_2, ..., re_7 as
// re_2--re_7)
std::string name_list(const std::vector<std::string>& names) {
    const auto split = [](const std::string& s, std::string* stem) {
        std::size_t i = s.size();
        while (i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1]))) --i;
        *stem = s.substr(0, i);
        return i < s.size() && s.size() - i < 9 ? std::stol(s.substr(i)) : -1L;
    };
    std::string out;
    for (std::size_t i = 0; i < names.size();) {
        std::string stem, next_stem;
        const long n = split(names[i], &stem);
        std::size_t j = i + 1;
        while (n >= 0 && j < names.size() &&
               split(names[j], &next_stem) == n + static_cast<long>(j - i) && next_stem == stem)
            ++j;
        out += out.empty() ? "" : ", ";
        if (j - i >= 3) {
            out += tex_text(names[i]) + "--" + tex_text(names[j - 1]);
        } else {
            for (std::size_t k = i; k < j; ++k) out += (k > i ? ", " : "") + tex_text(names[k]);
        }
        i = j;
    }
    return out;
}

// "1st", "2nd", "5th"
std::string ordinal(std::size_t k) {
    const std::size_t tens = k % 100, ones = k % 10;
    const char* suffix = tens >= 11 && tens <= 13 ? "th"
                         : ones == 1              ? "st"
                         : ones == 2              ? "nd"
                         : ones == 3              ? "rd"
                                                  : "th";
    return std::to_string(k) + suffix;
}

// the sweep's values as shown: a value within kRoundOff of the largest magnitude is 0, and a
// series 0 at every sample is one of the zero series
class SweepValues {
public:
    explicit SweepValues(const ReportSweep& w) : t_(w.table), axes_(w.axes) {
        double largest = 0;
        for (std::size_t k = 1; k < t_.columns.size(); ++k)
            for (double v : t_.columns[k])
                if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
        largest_ = largest;
        cutoff_ = kRoundOff * largest;
        zero_.assign(t_.columns.size(), true);
        for (std::size_t k = 1; k < t_.columns.size(); ++k)
            for (double v : t_.columns[k]) {
                if (!std::isfinite(v) || std::abs(v) > cutoff_)
                    zero_[k] = false;
                else if (v != 0)
                    rounded_ = true;
            }
        // the plots: one per axis and unit (the page's plotGroups), in the order they first appear
        for (std::size_t k = 1; k < t_.columns.size(); ++k) {
            const std::string& axis = axes_[k - 1];
            auto it = std::find_if(groups_.begin(), groups_.end(), [&](const Group& g) {
                return g.axis == axis && g.unit == t_.units[k];
            });
            if (it == groups_.end())
                it = groups_.insert(groups_.end(), Group{axis, t_.units[k], {}, {}});
            (zero_[k] ? it->zeros : it->series).push_back(k);
        }
    }
    struct Group {
        std::string axis, unit;
        std::vector<std::size_t> series, zeros;  // columns not 0 at every sample; 0 at each
    };
    double at(std::size_t column, std::size_t row) const {
        const double v = t_.columns[column][row];
        return std::isfinite(v) && std::abs(v) <= cutoff_ ? 0.0 : v;
    }
    const Table& table() const { return t_; }
    const std::vector<Group>& groups() const { return groups_; }
    bool zero(std::size_t column) const { return zero_[column]; }
    bool rounded() const { return rounded_; }
    double largest() const { return largest_; }
    std::string parameter_tex() const {
        return tex_text(t_.names[0]) +
               (t_.units[0].empty() ? "" : " [" + unit_tex(t_.units[0]) + "]");
    }

private:
    const Table& t_;
    const std::vector<std::string>& axes_;
    double largest_ = 0, cutoff_ = 0;
    bool rounded_ = false;
    std::vector<bool> zero_;
    std::vector<Group> groups_;
};

// the words saying which values are round-off written 0
std::string round_off_words(const SweepValues& s) {
    return s.rounded() ? " Values smaller than $10^{-12}$ times the largest magnitude (" +
                             cell(s.largest()) + ") are round-off, written 0."
                       : "";
}

// one plot: the group's `series` (its part `part` of `parts`) against the swept value at
// `rows`, and its zero series as one line on its first part
std::string plot_tex(const ReportSweep& w, const SweepValues& s, const SweepValues::Group& g,
                     const std::vector<std::size_t>& series, std::size_t part, std::size_t parts,
                     const std::vector<std::size_t>& rows, int* figure) {
    const Table& t = s.table();
    const bool zeros = part == 1 && !g.zeros.empty();
    const double x0 = t.columns[0][rows.front()], x1 = t.columns[0][rows.back()];
    double lo = zeros ? 0.0 : INFINITY, hi = zeros ? 0.0 : -INFINITY;
    for (std::size_t k : series)
        for (std::size_t r : rows)
            if (std::isfinite(s.at(k, r)))
                lo = std::min(lo, s.at(k, r)), hi = std::max(hi, s.at(k, r));
    if (!(lo <= hi)) lo = hi = 0;  // no finite value
    const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(0.1 * std::abs(hi), 1.0);
    // marks on about 25 samples of each line
    const std::size_t repeat = rows.size() <= 40 ? 1 : (rows.size() + 24) / 25;
    const std::string y_unit = g.unit.empty() ? "" : " [" + unit_tex(g.unit) + "]";
    std::string o = "\\par\\medskip\\noindent\\begin{minipage}{\\linewidth}\\centering\n";
    o += "\\begin{tikzpicture}\n\\begin{axis}[width=0.66\\linewidth, height=5.4cm, xmin=" +
         coordinate(x0) + ", xmax=" + coordinate(x1) + ", ymin=" + coordinate(lo - pad) +
         ", ymax=" + coordinate(hi + pad) + ",\n  xlabel={" + s.parameter_tex() + "}, ylabel={" +
         tex_text(g.axis) + y_unit +
         "}, grid=major, grid style={black!12}, unbounded coords=jump,\n"
         "  legend pos=outer north east, legend cell align=left, legend "
         "style={font=\\footnotesize},\n"
         "  tick label style={font=\\footnotesize}, label style={font=\\small}]\n";
    for (std::size_t i = 0; i < series.size(); ++i) {
        const std::size_t k = series[i];
        o += "% series: " + tex_text(t.names[k]) + "\n\\addplot[color=alembertC" +
             std::to_string(i) + ", line width=0.9pt, mark=" + kMarks[i] +
             ", mark size=1.4pt, mark repeat=" + std::to_string(repeat) +
             ", mark options={solid}] coordinates {";
        for (std::size_t j = 0; j < rows.size(); ++j)
            o += std::string(j % 6 == 0 ? "\n" : " ") + "(" + coordinate(t.columns[0][rows[j]]) +
                 "," + coordinate(s.at(k, rows[j])) + ")";
        o += "\n};\n\\addlegendentry{" + tex_text(t.names[k]) + "}\n";
    }
    std::vector<std::string> zero_names;
    for (std::size_t k : g.zeros) zero_names.push_back(t.names[k]);
    if (zeros) {
        // the series 0 at every sample: one line along the axis
        const std::string listed = name_list(zero_names);
        o += "% series at 0: " + listed +
             "\n\\addplot[black!55, line width=0.9pt, densely dashed] coordinates {(" +
             coordinate(x0) + ",0) (" + coordinate(x1) + ",0)};\n\\addlegendentry{" +
             (std::count(listed.begin(), listed.end(), ',') < 2
                  ? listed
                  : std::to_string(g.zeros.size()) + " series") +
             ": 0}\n";
    }
    o += "\\end{axis}\n\\end{tikzpicture}\n";
    // the caption: the page's title of the plot, what is thinned, what is 0
    std::string axis_words = g.axis + "s" + (g.unit.empty() ? "" : ", " + g.unit);
    o += "\\par\\smallskip{\\small Figure " + std::to_string(++*figure) + ": " + tex_text(w.title) +
         ": " + unit_tex(axis_words) +
         (parts > 1 ? ", " + std::to_string(part) + " of " + std::to_string(parts) : "") +
         ", against " + tex_text(t.names[0]) + ".";
    if (rows.size() < t.row_count())
        o += " Drawn through " + std::to_string(rows.size()) + " of the " +
             std::to_string(t.row_count()) + " samples, each series' least and greatest kept.";
    if (zeros)
        o += " " + name_list(zero_names) + (g.zeros.size() > 1 ? " are" : " is") +
             " 0 at every sample.";
    o += "}\n\\end{minipage}\n";
    return o;
}

// the samples a table lists: all, or every k-th from the first and the last, at most kTableRows
std::vector<std::size_t> table_rows(std::size_t n) {
    std::vector<std::size_t> rows;
    if (n <= kTableRows) {
        for (std::size_t i = 0; i < n; ++i) rows.push_back(i);
        return rows;
    }
    const std::size_t step = (n - 1 + kTableRows - 3) / (kTableRows - 2);  // ceil((n-1)/23)
    for (std::size_t i = 0; i < n; i += step) rows.push_back(i);
    if (rows.back() != n - 1) rows.push_back(n - 1);
    return rows;
}

// the table of the samples: the swept value and each series not 0 at every sample, in as few
// tabulars as fit the text's width (one; else one per plot group, split where too wide)
std::string table_tex(const ReportSweep& w, const SweepValues& s) {
    const Table& t = s.table();
    const std::vector<std::size_t> rows = table_rows(t.row_count());
    std::vector<std::size_t> listed;
    std::vector<std::string> zero_names;
    for (const SweepValues::Group& g : s.groups())
        for (std::size_t k : g.series) listed.push_back(k);
    for (std::size_t k = 1; k < t.columns.size(); ++k)
        if (s.zero(k)) zero_names.push_back(t.names[k]);
    bool one_unit = true;
    for (std::size_t k : listed) one_unit = one_unit && t.units[k] == t.units[listed.front()];
    const auto header = [&](std::size_t k) {
        return tex_text(t.names[k]) +
               (one_unit || t.units[k].empty() ? "" : " [" + unit_tex(t.units[k]) + "]");
    };
    // each column's width: its widest cell or its header
    const auto width = [&](std::size_t k, const std::string& head) {
        double cm = kCharCm * static_cast<double>(head.size());
        for (std::size_t r : rows)
            cm = std::max(cm, cell_cm(k == 0 ? t.columns[0][r] : s.at(k, r)));
        return cm + kColumnSepCm;
    };
    const double first = width(0, t.names[0] + " [" + t.units[0] + "]");
    std::vector<std::vector<std::size_t>> tabulars;
    double total = first;
    for (std::size_t k : listed) total += width(k, header(k));
    if (total <= kTableCm) {
        tabulars.push_back(listed);
    } else {
        for (const SweepValues::Group& g : s.groups()) {
            double used = kTableCm;  // a new tabular for each group
            for (std::size_t k : g.series) {
                const double cm = width(k, header(k));
                if (used + cm > kTableCm) tabulars.push_back({}), used = first;
                tabulars.back().push_back(k);
                used += cm;
            }
        }
    }
    // the caption: which samples, in which unit, what is left out
    std::string caption = "Table: " + tex_text(w.title) + ": ";
    if (rows.size() == t.row_count()) {
        caption += rows.size() == 1
                       ? std::string("the values at its one sample")
                       : "the values at each of the " + std::to_string(rows.size()) + " samples";
    } else {
        caption +=
            "the values at " + std::to_string(rows.size()) + " of the " +
            std::to_string(t.row_count()) + " samples, every " + ordinal(rows[1] - rows[0]) +
            " from the first" + ((t.row_count() - 1) % (rows[1] - rows[0]) ? " and the last" : "") +
            " (" + tex_text(t.names[0]) + " = " + cell(t.columns[0][rows[0]]) + ", " +
            cell(t.columns[0][rows[1]]) + ", \\ldots, " + cell(t.columns[0][rows.back()]) + ")";
    }
    if (!listed.empty() && one_unit && !t.units[listed.front()].empty())
        caption += ", in " + unit_tex(t.units[listed.front()]);
    caption += ".";
    if (!zero_names.empty())
        caption += " " + name_list(zero_names) + (zero_names.size() > 1 ? " are" : " is") +
                   " 0 at every sample" + (listed.empty() ? "." : ", not listed.");
    caption += round_off_words(s);
    // each tabular in a box of its own, the caption in the first
    const std::string words = "{\\small " + caption + "}";
    if (tabulars.empty()) return "\\par\\medskip\\noindent" + words + "\n";
    std::string o;
    for (std::size_t i = 0; i < tabulars.size(); ++i) {
        o += "\\par\\medskip\\noindent\\begin{minipage}{\\linewidth}\n";
        if (i == 0) o += words + "\\par\\smallskip\n";
        const std::vector<std::size_t>& columns = tabulars[i];
        o += "\\centering\\footnotesize\\setlength{\\tabcolsep}{4pt}\n\\begin{tabular}{@{}r|" +
             std::string(columns.size(), 'r') + "@{}}\n\\hline\n" + s.parameter_tex();
        for (std::size_t k : columns) o += " & " + header(k);
        o += " \\\\\n\\hline\n";
        for (std::size_t r : rows) {
            o += cell(t.columns[0][r]);
            for (std::size_t k : columns) o += " & " + cell(s.at(k, r));
            o += " \\\\\n";
        }
        o += "\\hline\n\\end{tabular}\n\\end{minipage}\n";
    }
    return o;
}

}  // namespace

bool report_detail::sweep_shown(const ReportSweep& w) {
    const Table& t = w.table;
    return t.columns.size() >= 2 && t.row_count() > 0 && w.axes.size() == t.columns.size() - 1 &&
           t.units.size() == t.columns.size() && t.names.size() == t.columns.size();
}

std::string report_detail::sweep_preamble() {
    std::string o = "\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.16}\n";
    for (std::size_t i = 0; i < kSeriesPerPlot; ++i)
        o += "\\definecolor{alembertC" + std::to_string(i) + "}{HTML}{" + kColours[i] + "}\n";
    return o;
}

std::string report_detail::sweep_latex(const ReportSweep& w, bool plots, int* figure) {
    if (!sweep_shown(w)) return "";
    const SweepValues s(w);
    std::string o;
    // the plots, where there is a line to draw: two samples at least, a series not 0 throughout
    if (plots && w.table.row_count() >= 2 &&
        w.table.columns[0].back() > w.table.columns[0].front()) {
        const std::vector<std::size_t> rows = calc_plot_rows(w.table, kPlotRows);
        for (const SweepValues::Group& g : s.groups()) {
            if (g.series.empty()) continue;  // 0 throughout: the table says so
            // more series than colours: over as few plots as hold them, shared evenly
            const std::size_t parts = (g.series.size() + kSeriesPerPlot - 1) / kSeriesPerPlot;
            const std::size_t size = (g.series.size() + parts - 1) / parts;
            for (std::size_t p = 0; p < parts; ++p) {
                const std::vector<std::size_t> part(
                    g.series.begin() + static_cast<std::ptrdiff_t>(p * size),
                    g.series.begin() +
                        static_cast<std::ptrdiff_t>(std::min(g.series.size(), (p + 1) * size)));
                o += plot_tex(w, s, g, part, p + 1, parts, rows, figure);
            }
        }
    }
    return o + table_tex(w, s);
}

}  // namespace alembert
