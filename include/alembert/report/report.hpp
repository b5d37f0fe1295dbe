// SPDX-License-Identifier: MIT
// The HTML report: the model, the road-map with free-body diagrams, equations, plots, motion.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "alembert/eom/cross_check.hpp"
#include "alembert/eom/equations.hpp"
#include "alembert/eom/roadmap.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// A time history to plot: a table whose first column is the time, and, when the motion is
/// known, the coordinates at each of its rows (SI) for the animation. The page plots each unit
/// of the table's columns on its own axis, under the title.
struct ReportHistory {
    /// What computed it, for the reader to tell runs apart: "simulate at line 31
    /// (fall/simulation.csv)" (report_history_title)
    std::string title{};
    int line = 0;                               ///< the statement's line in the script; 0: none
    std::string file{};                         ///< the table as written ("fall/simulation.csv")
    Table table{};                              ///< t, then the series, in their units
    std::vector<TimeVariable> coordinates{};    ///< the coordinates `motion` holds
    std::vector<std::vector<double>> motion{};  ///< motion[k][row]: coordinate k at each row (SI)
    /// The values the run's data gave the model's data symbols at the motion's first row (SI):
    /// a force plate's force, free moment and, where it is in contact there, centre of
    /// pressure. Diagrams drawn at that row take them, so a plate's load is drawn where and as
    /// its record has it.
    exmap first_row_data{};
};

/// A history's title from what computed it: `statement` ("simulate", "inverse"), its `line`
/// (0: not from a script line) and the `file` it wrote: "simulate at line 31
/// (fall/simulation.csv)", "inverse (torques.csv)".
std::string report_history_title(const std::string& statement, int line, const std::string& file);

/// What a sweep computed over a swept value (a `linearize ... for c = a to b step h`: the
/// eigenvalues at each value of c), plotted on the page under the statement's result against
/// the swept value, one plot per axis named in `axes`; in roadmap.tex plotted alike and
/// tabulated at up to 25 of its samples.
struct ReportSweep {
    /// What computed it: "linearize at line 31 (spin_sweep/eigenvalues.csv)"
    /// (report_history_title)
    std::string title{};
    std::string file{};  ///< the table as written ("spin_sweep/eigenvalues.csv"); empty: none
    /// The swept value (its name and unit), then the series in their units: for linearize
    /// re_1..re_n, then im_1..im_n (1/s)
    Table table{};
    /// What each series after the first column is, one per series ("real part",
    /// "imaginary part"): the series of one axis share one plot
    std::vector<std::string> axes{};
};

/// A result the script printed (a `solve`, `evaluate` or `linearize`), shown on the page where
/// the script computed it.
struct ReportResult {
    int line = 0;              ///< the statement's line in the script
    std::string statement{};   ///< the statement as written
    std::string text{};        ///< what it printed
    std::optional<ReportSweep> sweep{};  ///< what a sweep computed, plotted under the text
};

/// Equations of motion the script formed besides the road-map (`kane`, `lagrange`), shown
/// on the page and in roadmap.tex under their name.
struct ReportEquationSet {
    std::string name{};               ///< the script's name for them ("K")
    std::string method{};             ///< "Kane's method", "Lagrange's method"
    int line = 0;                     ///< the statement's line in the script
    std::vector<ex> equations{};      ///< each 0 = equations[i]
    /// what each equation is read for (shown solved for it where its coefficient is a nonzero
    /// constant): the accelerations, or the independent speeds' rates; none when empty
    std::vector<ex> unknowns{};
};

/// The units of one road-map row's equation checked term by term, from the units the script
/// declares (the script's interpreter checks them; a report made without one has none).
struct ReportUnitCheck {
    enum class Verdict { consistent, inconsistent, unchecked };
    Verdict verdict = Verdict::unchecked;
    std::string unit{};     ///< what each term must be in: "N" (translate), "N*m" (rotate)
    /// For the reader: "units: N*m", "the term T_A is in N, not N*m", "not checked (no units
    /// declared for qA)"
    std::string summary{};
    std::vector<std::string> terms{};  ///< the terms that are off, as printed
};

/// Everything a report shows. The page is a function of this alone (no clock, no paths), so
/// the same content gives the same bytes.
struct ReportContent {
    const System* system = nullptr;
    std::string title{};             ///< the model's name
    std::vector<RoadmapRow> rows{};  ///< formed road-map rows
    std::vector<TimeVariable> coordinates{};
    /// Values of coordinates (and rates) at which free-body diagrams are drawn (SI); those
    /// missing are 0. Constants take their values from the model's symbol table. A point
    /// placed by a specified quantity missing here (a plate's centre of pressure out of the
    /// data's reach) has no place at the configuration: it is not drawn, nor the loads at it.
    /// A known load whose vector holds a specified quantity or a rate missing here has no
    /// value at the configuration: it is drawn along its positive sense, labelled with none.
    exmap configuration{};
    /// Where the configuration comes from, for the reader ("the configuration solve found at
    /// line 31", "the initial values"); empty: not said.
    std::string configuration_source{};
    /// The unit each name is shown in ("deg" for qA, "N*m" for T_A); empty names have none.
    std::map<std::string, std::string> units{};
    /// The SI value of one of `units` (1 deg = 0.0174533): values are shown divided by it;
    /// a name missing here is shown in SI.
    std::map<std::string, double> unit_scales{};
    std::vector<ReportHistory> histories{};
    /// The equations of motion the script formed with kane and lagrange, in run order.
    std::vector<ReportEquationSet> equation_sets{};
    /// The results the script printed, in run order.
    std::vector<ReportResult> results{};
    /// Remarks shown at the top of the page (why there is no road-map, ...).
    std::vector<std::string> notes{};
    /// Plot the histories (and the results' sweeps) at all; and which of the histories'
    /// columns (by name; empty: every one).
    bool plot_histories = true;
    std::vector<std::string> plotted{};
    /// The cross-checks between methods, when they were run (alembert::compare_methods,
    /// alembert::compare_reactions).
    std::optional<MethodComparison> methods{};
    std::optional<ReactionComparison> reactions{};
    /// The mass matrix and forcing, M(q) q'' = f(q, q', t) with A = M, b = f and the
    /// accelerations the unknowns, when asked (alembert::form_forward_equations: as simulate
    /// forms them); typeset on the page and in roadmap.tex.
    std::optional<LinearSystem> matrices{};
    /// Each row's unit check, one per row of `rows` (empty: the units are not known, nothing
    /// is said about them).
    std::vector<ReportUnitCheck> unit_checks{};
};

/// One line of the report's checks panel.
struct ReportCheck {
    std::string kind{};     ///< "energy", "constraint", "methods", "reactions"
    std::string name{};     ///< what was checked: "energy", "drift_loop_x", "Kane", "F_Ac"
    std::string source{};   ///< the history it came from ("simulation"), or "random states"
    double value = 0;       ///< the measure: relative energy change, largest residual, difference
    std::string unit{};     ///< the measure's unit ("" for relative measures)
    bool passed = false;    ///< value within the bound below
    std::string summary{};  ///< one sentence for the reader
    bool checked = true;    ///< false: could not be checked (a unit not declared); not a pass
    std::string measure{};  ///< shown in place of the value when not empty ("N*m")
};

/// The checks a report shows, from what was computed: for each history with an `energy`
/// column, its largest change from the start relative to its largest magnitude (passed below
/// 1e-6); for each `drift_*` column, the largest |residual| (passed below 1e-6 in its unit);
/// for the method and reaction comparisons when run, each method's or measure's largest
/// scaled difference (passed below 1e-8); for each row with a unit check (content.unit_checks),
/// its verdict (kind "units").
std::vector<ReportCheck> calc_report_checks(const ReportContent& content);

/// The report as one HTML page: the content as JSON inside the page and the fixed viewer
/// (src/report/viewer) inlined, with KaTeX's script and style when `katex_dir` holds them.
/// Free-body diagrams and animation frames are computed here, from the model's points at the
/// configuration: for each row, the loads external to S (as describe_free_body_diagram lists
/// them; gravity one arrow per mass centre), the about point and the direction.
/// @throws alembert::ArgumentError if the content has no system.
/// With `three_dir` holding three.min.js (Debian's libjs-three) and a motion or a spatial
/// model to show, three.js is inlined too and the page adds a 3D view the reader turns.
std::string render_report_html(const ReportContent& content, const std::string& katex_dir,
                               const std::string& three_dir = "");

/// The content's data alone, as the JSON the page embeds (deterministic key and row order).
std::string render_report_json(const ReportContent& content);

/// The road-map as a LaTeX document (article, amsmath, tikz) for a paper or a homework
/// solution: the table in the seed's columns; each row's free-body diagram drawn in TikZ as the
/// page draws it (the model's sticks at the configuration, S in ink and the rest grey, each load
/// on S as an arrow at its point, the about point and the direction; spatial models in the
/// page's default oblique view), with its loads listed; and the equations, one display each,
/// with the named intermediates they use defined after them.
std::string render_report_latex(const ReportContent& content);

/// Where KaTeX is read from: $ALEMBERT_KATEX_DIR if set, else the build's default (Debian's
/// libjs-katex, /usr/share/javascript/katex).
std::string default_katex_dir();

/// Where three.js is read from: $ALEMBERT_THREE_DIR if set, else the build's default (Debian's
/// libjs-three, /usr/share/javascript/three).
std::string default_three_dir();

/// Writes DIR/index.html (and KaTeX's fonts in DIR/fonts/) and DIR/roadmap.tex
/// (render_report_latex), each written to a temporary and
/// renamed; DIR is created if needed. Without KaTeX the page shows the TeX source and says
/// how to install it. Returns the path of index.html.
/// @throws alembert::ArgumentError naming DIR if it cannot be created or written.
std::string write_report(const ReportContent& content, const std::string& dir);

/// Writes DIR/roadmap.tex alone (render_report_latex), to a temporary and renamed; DIR is
/// created if needed. Returns its path.
/// @throws alembert::ArgumentError naming DIR if it cannot be created or written.
std::string write_report_latex(const ReportContent& content, const std::string& dir);

/// `e` as TeX: terms and factors in a deterministic order (sorted by their printed form),
/// products as \frac where there are negative powers, sin and cos as \sin and \cos, primes
/// kept (qA''), names with an underscore subscripted (T_A -> T_{A}).
std::string to_latex(const ex& e);

}  // namespace alembert
