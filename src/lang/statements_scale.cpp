// SPDX-License-Identifier: MIT
// A model's lengths from a static trial: `scale L_T from "static.trc" between HIP and KNEE`
// declares the constant L_T as the mean distance between two joint-centre markers.
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

void parse_scale(StatementParser& p, Statement& s) {
    const std::string example = "(scale L_T from \"static.trc\" between HIP and KNEE)";
    s.words["name"] = p.name("the name of the length to declare");
    p.expect_word("from", example);
    s.words["from"] = p.text("the static trial's path (.trc or .c3d)");
    p.expect_word("between", example);
    s.words["a"] = p.peek().kind == TokenKind::string ? p.text("a marker's name in the trial")
                                                      : p.name("a marker's name in the trial");
    p.expect_word("and", example);
    s.words["b"] = p.peek().kind == TokenKind::string ? p.text("a marker's name in the trial")
                                                      : p.name("a marker's name in the trial");
    if (p.accept_word("within")) s.quantities["within"] = p.quantity();
    if (!p.at_end()) p.fail_expected("'within' (... between HIP and KNEE within 5 mm) or the end of the statement");
}

// ---- meaning -----------------------------------------------------------------------------

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
    // the trial: a .trc, or a C3D file's markers
    const std::string path = m.input_path(file.text);
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const MarkerTable trial = m.guard(file.location, [&] { return ext == ".c3d" ? read_c3d(path).markers : read_trc(path); });
    const StaticLength L = m.guard(a.location, [&] { return calc_static_length(trial, a.text, b.text, options); });
    // the constant, a length
    m.declare_name(name, NameKind::symbol);
    m.guard(name.location, [&] { sys.symbols().add_constant(name.text, L.length_m); });
    m.units[name.text] = SymbolUnits{Dimension::length(), std::nullopt};
    m.transcript.result(name.text + " = " + m.transcript.number(L.length_m) + " m: the mean distance from " + a.text +
                        " to " + b.text + " over " + std::to_string(L.frames) + " frames of " + file.text + " (SD " +
                        m.transcript.number(L.sd_m * 1000) + " mm, largest deviation " +
                        m.transcript.number(L.max_deviation_m * 1000) + " mm at t = " +
                        m.transcript.number(L.max_deviation_t) + " s)");
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
    };
}

}  // namespace alembert::lang
