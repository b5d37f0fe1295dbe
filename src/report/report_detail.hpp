// SPDX-License-Identifier: MIT
// Helpers shared by the report's sources (private to src/report).
#pragma once

#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/moving_bodies.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/roadmap.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {
struct ReportContent;
struct ReportSweep;
}

namespace alembert::report_detail {

/// Between the lines of an equation typeset on several (an abbreviated row's named parts, a
/// mass matrix written entry by entry): KaTeX breaks the line there; the LaTeX document
/// writes each line as a paragraph of its own (tex_lines).
inline constexpr const char* kTexLineBreak = " \\newline ";

/// `tex` with \left( \right) (and | |) written \bigl( \bigr): TeX and KaTeX break a formula in
/// text style after a + or - at its outer level, never inside a \left ... \right group.
std::string breakable_tex(std::string tex);

/// The longest piece of an equation's TeX that may stand unbroken on a line (about 300 pt of a
/// 450 pt line): a longer one is abbreviated.
inline constexpr std::size_t kUnbreakableChars = 160;

/// The longest stretch of `tex` (breakable_tex's form) with no place to break a line: between
/// the + - = at its outer brace level (a \frac, a \sqrt, a power's exponent is one piece).
std::size_t longest_unbreakable(const std::string& tex);

/// The lines of a typeset equation (split at kTexLineBreak).
std::vector<std::string> tex_lines(const std::string& tex);

/// `s` for LaTeX's text mode: _ & % # $ { } < > ^ ~ and the backslash written as commands.
std::string tex_text(const std::string& s);

/// Whether roadmap.tex has a sweep of `w` to show (as the page: a swept column, at least one
/// series, one axis name per series, at least one sample).
bool sweep_shown(const ReportSweep& w);

/// The preamble's lines a document with sweep plots needs: pgfplots and the page's ten colours.
std::string sweep_preamble();

/// A result's sweep in roadmap.tex, under the text the statement printed: with `plots`, the
/// series of each axis (the real parts, the imaginary parts) against the swept value, one plot
/// per axis (pgfplots), each series a line of its own colour and marks with a legend entry,
/// the series 0 at every sample one line; then a table of the samples (at most 25 rows: every
/// k-th sample and the last where there are more), the series 0 at every sample left out and
/// named. Numbers to 6 significant digits, as the page's data; values within 1e-12 of the
/// sweep's largest magnitude written 0, and the caption says so. `figure` numbers the plots.
std::string sweep_latex(const ReportSweep& w, bool plots, int* figure);

/// Each row's equation typeset (LaTeX, readable form: calc_solved_equation, "T_A = ..." when
/// solved, "0 = ..." otherwise; rows over 1,500 operations abbreviated with named parts w1 = ...
/// on the following lines), written breakable (breakable_tex). Simplifying an equation for the reader
/// is the costly part of a report (seconds for a 42-row arm), so write_report typesets once
/// and hands the result to both the page and roadmap.tex.
/// After the rows', the equations of content.equation_sets, set after set, typeset alike
/// (0 = ..., readable or abbreviated).
std::vector<std::string> typeset_equations(const ReportContent& content);

/// render_report_json / render_report_latex / render_report_html with the rows' equations
/// already typeset (`equations`, one per row of `content`).
/// `steps`: the rows' derivations (calc_rows_steps), formed here when null; `count`: the
/// brute-force count (calc_brute_force_count), counted here when null.
struct RowSteps;
struct BruteForceCount;
std::string render_json(const ReportContent& content, const std::vector<std::string>& equations,
                        const std::vector<RowSteps>* steps = nullptr,
                        const BruteForceCount* count = nullptr);
std::string render_latex(const ReportContent& content, const std::vector<std::string>& equations,
                         const std::vector<RowSteps>* steps = nullptr,
                         const BruteForceCount* count = nullptr);
std::string render_html(const ReportContent& content, const std::vector<std::string>& equations,
                        const std::string& katex_dir, const std::string& three_dir,
                        const std::vector<RowSteps>* steps = nullptr,
                        const BruteForceCount* count = nullptr);

/// The viewer's script and style (src/report/viewer), compiled in.
extern const char* const kViewerScript;
extern const char* const kViewerStyle;

// ---- shared by the page's data (report_json.cpp) and the LaTeX document (latex_document.cpp)

/// Values for evaluating the model's geometry: the configuration, every other variable and
/// rate 0, unknowns and specified quantities 1 (so a load's arrow shows its positive sense).
struct Evaluation {
    const System& sys;
    exmap values;

    Evaluation(const System& s, const exmap& configuration) : sys(s) {
        const SymbolTable& st = sys.symbols();
        for (SymbolKind k : {SymbolKind::variable, SymbolKind::specified})
            for (const ex& x : st.symbols(k)) values[x] = 0;
        for (const ex& x : st.symbols(SymbolKind::unknown)) values[x] = 1;
        for (const auto& [x, v] : configuration) values[x] = v, given_.insert(x);
        memo_ = std::make_unique<SymbolTable::EvaluationMemo>(values);
    }
    /// Whether the configuration places `p`: its position holds no specified quantity the
    /// configuration leaves out (a force plate's centre of pressure, which its record gives
    /// only where the diagrams are drawn at a row of the motion it was read with). Once per point.
    bool places(const Point* p) const;
    /// Whether the configuration gives `l`'s value: its vector holds no specified quantity
    /// and no rate (q', q'', ...) the configuration leaves out (a force plate's free moment
    /// drawn at `report at` angles, whose record gives it only at its own rows; a damper
    /// where the configuration gives no speed). Once per load.
    bool gives(const Load& l) const;
    /// The value of `e`, or NaN if it needs what is not known.
    double at(const ex& e) const {
        try {
            return sys.symbols().evaluate(e, *memo_);
        } catch (const std::exception&) {
            return std::nan("");  // a library error, or GiNaC's (a spring of length 0 at rest)
        }
    }
    std::vector<double> in_newtonian(const Vector& v) const {
        Col3 c = v.components_in(sys.newtonian());
        return {at(c[0]), at(c[1]), at(c[2])};
    }
    /// Where `p` is, measured from the origin in N: evaluated once per point, since every
    /// row's diagram places the same points
    const std::vector<double>& position(const Point* p) const {
        auto it = positions_.find(p);
        if (it == positions_.end())
            it = positions_.emplace(p, in_newtonian(p->pos_from(sys.origin()))).first;
        return it->second;
    }
    /// position(p) from its components in N, already at hand
    const std::vector<double>& position(const Point* p, const Col3& in_n) const {
        auto it = positions_.find(p);
        if (it == positions_.end())
            it = positions_.emplace(p, std::vector<double>{at(in_n[0]), at(in_n[1]), at(in_n[2])})
                     .first;
        return it->second;
    }

    /// A load's vector in N: evaluated once per load, since every row's diagram that shows
    /// the load draws the same arrow
    const std::vector<double>& load_vector(const Load& l) const {
        auto it = loads_.find(&l);
        if (it == loads_.end()) it = loads_.emplace(&l, in_newtonian(l.vector)).first;
        return it->second;
    }

private:
    GiNaC::exset given_;
    mutable std::map<const Point*, bool> places_;
    mutable std::map<const Load*, bool> gives_;
    // every intermediate evaluated once over all the page's expressions (the values are fixed)
    std::unique_ptr<SymbolTable::EvaluationMemo> memo_;
    mutable std::map<const Point*, std::vector<double>> positions_;
    mutable std::map<const Load*, std::vector<double>> loads_;
};

/// The model's points that have a path to the origin (those a drawing can place); with `ev`,
/// those of them its configuration places (Evaluation::places).
std::vector<const Point*> placed_points(const System& sys, const Evaluation* ev = nullptr);

/// A rate or specified quantity the configuration gives (a speed, a push, a plate's force at
/// a motion's first row): its value in SI and as shown, in its unit.
struct ConfigurationDatum {
    std::string name;
    double si = 0, shown = 0;
    std::string unit;
};

/// The configuration's rates (the coordinates' order) and specified quantities (the symbol
/// table's order), those it gives.
std::vector<ConfigurationDatum> configuration_data(const ReportContent& c);

/// "qA = 60 deg, qB = -41.6 deg (the configuration solve found at line 31)", its data after
/// the coordinates ("x = 0.6 m, with x' = 0 m/s, F = 10 N (...)")
std::string configuration_words(const ReportContent& c);

/// A stick of the drawing: `body`'s (empty: the ground's) from point `from` to point `to`.
struct Segment {
    std::string body, from, to;
};

/// The sticks the drawings show, from how the placed points are located.
std::vector<Segment> segments_of(const System& sys, const std::vector<const Point*>& placed);

/// "up" in N: against gravity, else Ny for planar models and Nz for others
std::vector<double> view_up(const System& sys, const Evaluation& ev, bool planar);

/// The about point the planner located off the model's points for row `r`
/// (RoadmapRow::about_owned: an instantaneous centre IC_q, where two unknown forces' lines
/// meet) where the configuration places it at a finite place; else null. It is drawn in the
/// diagrams of the rows about it only.
const Point* row_about_point(const RoadmapRow& r, const Evaluation& ev);

/// row_about_point of each of `rows`, once each by name.
std::vector<const Point*> row_about_points(const std::vector<RoadmapRow>& rows,
                                           const Evaluation& ev);

/// The drawing's points and sticks as the page's JSON, the rows' own about points
/// (row_about_points) after the model's, marked "about_only"; sets *planar (decided at random
/// states, by the model's points).
std::string geometry_json(const System& sys, const Evaluation& ev,
                          const std::vector<const Point*>& placed, bool* planar,
                          const std::vector<const Point*>& about_only = {});

/// A load's part in the row's equation: it holds the row's own unknown; it holds another
/// unknown the equation keeps; it is known and the equation holds it; or the equation does not
/// hold it (it passes through O, is square to u, or is a joint's force the planner left out).
enum class LoadRole { own, held, known, drops_out };

/// "own", "held", "known", "drops" (the page's classes)
std::string role_word(LoadRole r);

/// One arrow of a free-body diagram: a load external to S at its point.
struct DiagramLoad {
    std::string kind, label;  ///< kind: force, torque, gravity, joint
    std::string tex{};        ///< the label as TeX math (a weight's), empty: the label as text
    const Point* at = nullptr;
    const Body* on = nullptr;      ///< the body of S it acts on
    std::vector<double> vector{};  ///< in N at the configuration (empty for a joint, or not given)
    /// A known load that is zero at the configuration (a damper at rest, a push of 0 N there),
    /// or whose value the configuration does not give (`given` false): its positive sense in
    /// N, with its rates and specified quantities taken as 1, to draw its arrow along at its
    /// point (labelled as zero there, or with no value); empty otherwise, or if that is zero too
    std::vector<double> sense{};
    /// False for a known load whose value the configuration does not give
    /// (Evaluation::gives): `vector` is empty, the label holds no value, and the diagram's
    /// legend says the value is not given at this configuration
    bool given = true;
    /// False for a load at a point the configuration does not place (Evaluation::places): it
    /// is not drawn, and the diagram's legend says so
    bool placed = true;
    bool unknown = false;
    LoadRole role = LoadRole::known;
};

/// The loads of one free-body diagram, as the viewer and the TikZ picture draw them.
std::vector<DiagramLoad> diagram_loads(const System& sys, const Evaluation& ev,
                                       const RoadmapRow& r);

/// A body's weight as a diagram labels it: its mass times the gravity constant, as the model
/// writes them ("m_A g"; "(m_1 + m_2) g"; "2*g").
struct WeightLabel {
    std::string text, tex;
};
WeightLabel weight_label(const System& sys, const Evaluation& ev, const Body& b);

/// The points a diagram names: O, the joints of S's bodies (with the outside and between
/// them), and the points the loads act at (mass centres among them), once each.
std::vector<const Point*> diagram_points(const System& sys, const RoadmapRow& r,
                                         const std::vector<DiagramLoad>& loads);

/// A rotation coordinate's angle in a planar model: body's frame turned from its parent's
/// about z by `name`, drawn at `at` (where the body is joined to the rest) between the
/// parent's axis `from` and the body's `to` (axis x or y: the one the body's stick from `at`
/// lies along), both in N; `value` the angle (radians, about +z) at the configuration.
struct DiagramAngle {
    const Body* body = nullptr;
    std::string name;
    const Point* at = nullptr;
    int axis = 0;
    std::vector<double> from{}, to{};
    double value = 0;
};
std::vector<DiagramAngle> planar_angles(const System& sys, const Evaluation& ev);

/// "translate", "rotate" or "constraint"
std::string motion_word(Motion m);

// the intermediates the rows use, each once for the whole page, in dependency order: their
// names, their definitions as TeX, and for each row the positions of those it uses (rows of
// one model share most of theirs; repeating them per row made a 7-joint arm's page 2 MB)
struct PageIntermediates {
    std::vector<std::string> names, tex;
    std::vector<std::vector<std::size_t>> of_row;
    std::vector<std::vector<std::size_t>> of_steps;  ///< those of each row's derivation
};

PageIntermediates page_intermediates(const System& sys, const std::vector<RoadmapRow>& rows,
                                     const std::vector<RowSteps>* steps = nullptr);

/// The direction as the road-map table writes it: in N when it is constant there.
std::string direction_words(const System& sys, const Vector& u);

/// M q'' = f typeset (breakable_tex): the matrix, the column of accelerations and the forcing
/// when the widest row of entries takes at most kMatrixRowChars characters of TeX; else the
/// equation with the accelerations' column, then each entry on a line of its own,
/// M_{ij} = ... and f_{i} = ... (kTexLineBreak between them). Entries are written with the
/// intermediates written out and simplified (simplify) when that takes at most
/// kReadableSimplifyOps operations.
inline constexpr std::size_t kMatrixRowChars = 90;
std::string matrices_tex(const SymbolTable& st, const LinearSystem& m);

// ---- a row's derivation step by step (row_steps.cpp) --------------------------------------

/// One step of a row's derivation: what it is, a sentence, and its formula (TeX, breakable;
/// empty: none).
struct DerivationStep {
    std::string label, text, tex;
};

/// A row's steps (alembert::calc_row_derivation typeset) and the measures of the quantities
/// they show, whose intermediates the page defines.
struct RowSteps {
    std::vector<DerivationStep> steps;
    std::vector<ex> quantities;
};

/// The steps of row `r`, ending with its typeset `equation`; `moving` and `printer` (the
/// texts that measure abbreviated lines) are shared by the rows.
RowSteps calc_row_steps(const System& sys, const RoadmapRow& r, const std::string& equation,
                        Simplifier& simplifier, MovingBodies& moving, TextPrinter& printer);

/// Every row's steps (a row whose derivation cannot be formed says why in one step).
std::vector<RowSteps> calc_rows_steps(const ReportContent& c, const std::vector<std::string>& equations);

/// Brute-force Newton–Euler counted for the model (alembert::count_newton_euler_equations)
/// with the rows' unknowns other than declared joint reactions' measures as those asked for.
struct BruteForceCount {
    bool formed = false;
    NewtonEulerCount count{};
    std::vector<std::string> asked{};
    std::size_t reaction_rows = 0;  ///< rows for declared joint reactions' measures
    std::size_t constraints = 0;    ///< the model's declared constraints
    std::size_t constraint_rows = 0;  ///< the road-map's constraint rows (counted as equations)
    std::string why{};              ///< why not formed
};
BruteForceCount calc_brute_force_count(const ReportContent& c);

/// The count in a paragraph, beside the road-map's `rows` rows.
std::string brute_force_words(const BruteForceCount& b, std::size_t rows);

}  // namespace alembert::report_detail
