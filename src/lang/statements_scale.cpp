// SPDX-License-Identifier: MIT
// A model's lengths from a static trial: `scale L_T from "static.trc" between HIP and KNEE`
// declares the constant L_T as the mean distance between two joint-centre markers;
// `place A, C from "static.trc" marker LKNE between HIP and KNEE` declares a marker's place
// along and across the line between them.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "alembert/biomech/c3d_file.hpp"
#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/static_trial.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// ---- grammar -----------------------------------------------------------------------------

// a marker's name in the trial: a name, or a string for a label that is not one ("R.KNE")
Word parse_marker_name(StatementParser& p) {
    return p.peek().kind == TokenKind::string ? p.text("a marker's name in the trial")
                                              : p.name("a marker's name in the trial");
}

void parse_scale(StatementParser& p, Statement& s) {
    const std::string example = "(scale L_T from \"static.trc\" between HIP and KNEE)";
    s.words["name"] = p.name("the name of the length to declare");
    p.expect_word("from", example);
    s.words["from"] = p.text("the static trial's path (.trc or .c3d)");
    p.expect_word("between", example);
    s.words["a"] = parse_marker_name(p);
    p.expect_word("and", example);
    s.words["b"] = parse_marker_name(p);
    if (p.accept_word("within")) s.quantities["within"] = p.quantity();
    if (!p.at_end()) p.fail_expected("'within' (... between HIP and KNEE within 5 mm) or the end of the statement");
}

void parse_place(StatementParser& p, Statement& s) {
    const std::string example = "(place A_K, C_K from \"static.trc\" marker LKNE between HIP and KNEE)";
    s.words["along"] = p.name("the name of the distance along the segment's line to declare");
    p.expect_punct(",", example);
    s.words["across"] = p.name("the name of the distance across the segment's line to declare");
    p.expect_word("from", example);
    s.words["from"] = p.text("the static trial's path (.trc or .c3d)");
    p.expect_word("marker", example);
    s.words["marker"] = parse_marker_name(p);
    p.expect_word("between", example);
    s.words["a"] = parse_marker_name(p);
    p.expect_word("and", example);
    s.words["b"] = parse_marker_name(p);
    if (!p.at_end()) p.fail_expected("the end of the statement");
}

// ---- meaning -----------------------------------------------------------------------------

// the trial: a .trc, or a C3D file's markers
MarkerTable read_static_trial(Interpreter::Impl& m, const Word& file) {
    const std::string path = m.input_path(file.text);
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return m.guard(file.location, [&] { return ext == ".c3d" ? read_c3d(path).markers : read_trc(path); });
}

// a length constant of the model, in m
void declare_length(Interpreter::Impl& m, System& sys, const Word& name, double value) {
    m.declare_name(name, NameKind::symbol);
    m.guard(name.location, [&] { sys.symbols().add_constant(name.text, value); });
    m.units[name.text] = SymbolUnits{Dimension::length(), std::nullopt};
}

void run_scale(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& name = s.word("name");
    const Word& file = s.word("from");
    const Word& a = s.word("a");
    const Word& b = s.word("b");
    StaticLengthOptions options;
    if (s.quantities.count("within")) {
        const Quantity& q = s.quantities.at("within");
        options.max_deviation_m = m.number_of(q, Dimension::length(), "the largest deviation", q.value->location);
        if (!(options.max_deviation_m > 0) || !std::isfinite(options.max_deviation_m))
            throw ScriptError(q.value->location, "the largest deviation must be a length above 0", "");
    }
    const MarkerTable trial = read_static_trial(m, file);
    const StaticLength L = m.guard(a.location, [&] { return calc_static_length(trial, a.text, b.text, options); });
    declare_length(m, sys, name, L.length_m);
    m.transcript.result(name.text + " = " + m.transcript.number(L.length_m) + " m: the mean distance from " + a.text +
                        " to " + b.text + " over " + std::to_string(L.frames) + " frames of " + file.text + " (SD " +
                        m.transcript.number(L.sd_m * 1000) + " mm, largest deviation " +
                        m.transcript.number(L.max_deviation_m * 1000) + " mm at t = " +
                        m.transcript.number(L.max_deviation_t) + " s)");
}

void run_place(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& along = s.word("along");
    const Word& across = s.word("across");
    const Word& file = s.word("from");
    const Word& marker = s.word("marker");
    const Word& a = s.word("a");
    const Word& b = s.word("b");
    if (along.text == across.text)
        throw ScriptError(across.location, "'" + across.text + "' is named twice; the place needs two names (along, across)",
                          "");
    const MarkerTable trial = read_static_trial(m, file);
    // Nx> forward, Ny> up: the plane of the lab's X and Y, as `inverse` reads a trial
    const StaticPlace P = m.guard(marker.location, [&] { return calc_static_place(trial, a.text, b.text, marker.text); });
    declare_length(m, sys, along, P.along_m);
    declare_length(m, sys, across, P.across_m);
    m.transcript.result(along.text + " = " + m.transcript.number(P.along_m) + " m, " + across.text + " = " +
                        m.transcript.number(P.across_m) + " m: the mean place of " + marker.text +
                        " along the line from " + a.text + " to " + b.text +
                        " and across it (a quarter turn counterclockwise, in the lab's X-Y plane) over " +
                        std::to_string(P.frames) + " frames of " + file.text + " (SD " +
                        m.transcript.number(P.sd_along_m * 1000) + " mm along, " +
                        m.transcript.number(P.sd_across_m * 1000) + " mm across)");
}

}  // namespace

std::vector<StatementSpec> scale_statements() {
    return {
        {.keyword = "scale", .family = "Mass and loads",
         .help = "a length of the model from a static trial: the mean distance between two joint-centre markers",
         .forms = {{"`scale` *L* `from` *\"static.trc\"* `between` *marker* `and` *marker* [`within` *d*]",
                    "scale L_T from \"static.trc\" between HIP and KNEE",
                    "`calc_static_length` (declares the constant L in m, the mean distance over the frames that "
                    "see both markers; refused if it departs from the mean by more than d, default 1 cm); "
                    "`segment ... length L` scales a segment table by it"}},
         .clauses = {"from", "between", "and", "within"},
         .parse = parse_scale, .run = run_scale},
        {.keyword = "place", .family = "Mass and loads",
         .help = "a marker's place on a segment from a static trial: along and across the line between two joint-centre markers",
         .forms = {{"`place` *A*, *C* `from` *\"static.trc\"* `marker` *marker* `between` *marker* `and` *marker*",
                    "place A_K, C_K from \"static.trc\" marker LKNE between HIP and KNEE",
                    "`calc_static_place` in the lab's X-Y plane (declares the constants A and C in m: the marker's "
                    "mean distance along the line from the first joint-centre marker to the second and across it, a "
                    "quarter turn counterclockwise, over the frames that see the three markers); a thigh hanging "
                    "along -Ty> from HIP_P with Tx> forward: `translate LKNE_M from HIP_P by C_K*Tx> - A_K*Ty>`"}},
         .clauses = {"from", "marker", "between", "and"},
         .parse = parse_place, .run = run_place},
    };
}

}  // namespace alembert::lang
