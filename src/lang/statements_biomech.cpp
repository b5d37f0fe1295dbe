// SPDX-License-Identifier: MIT
// Body-segment parameters: `segment m, d, I from TABLE ROW mass M length L` declares a
// segment's mass, centre-of-mass distance and moment of inertia scaled from a published table.
#include "alembert/biomech/segment_parameters.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// ---- grammar -----------------------------------------------------------------------------

void parse_segment(StatementParser& p, Statement& s) {
    s.lists["names"] = p.name_list("the names of the segment's mass, centre-of-mass distance and inertia");
    p.expect_word("from", "(segment m_B, d_B, I_B from winter thigh mass 56.7 kg length 41.65 cm)");
    s.words["table"] = p.name("a table: winter, de_leva_male or de_leva_female");
    s.words["row"] = p.name("a segment of the table (thigh, leg, shank, ...)");
    p.expect_word("mass", "(... from winter thigh mass 56.7 kg length 41.65 cm)");
    s.quantities["mass"] = p.quantity();
    p.expect_word("length", "(... mass 56.7 kg length 41.65 cm)");
    s.quantities["length"] = p.quantity();
}

// ---- meaning -----------------------------------------------------------------------------

// the segment's length: a number with its unit (41.65 cm), or constants with values and their
// units (L_T, from `scale L_T from "static.trc" between HIP and KNEE`)
double segment_length(Interpreter::Impl& m, System& sys, const Quantity& q) {
    const Value v = m.eval(*q.value);
    const bool number = v.kind == Value::Kind::scalar && GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(v.s));
    if (number || !q.unit.empty())
        return m.number_of(q, Dimension::length(), "the segment's length", q.value->location);
    const ex e = m.scalar(*q.value, Dimension::length(), "the segment's length");
    const ex n = m.guard(q.value->location, [&] { return GiNaC::evalf(e.subs(sys.symbols().constant_values())); });
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real())
        throw ScriptError(q.value->location, "the segment's length " + to_string(e) + " has no value",
                          "give a number with its unit (length 41.65 cm) or constants with values (constant L = 0.4 m; "
                          "scale L from \"static.trc\" between HIP and KNEE)");
    return GiNaC::ex_to<GiNaC::numeric>(n).to_double();
}

void run_segment(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const std::vector<Word>& names = s.lists.at("names");
    if (names.size() != 3)
        throw ScriptError(names.front().location,
                          std::to_string(names.size()) + " name(s) given; a segment gives three",
                          "name its mass, centre-of-mass distance and inertia: segment m_B, d_B, I_B from ...");
    const Word& table_word = s.word("table");
    const Word& row_word = s.word("row");
    const SegmentTable& table = m.guard(table_word.location, [&]() -> const SegmentTable& {
        return segment_table(table_word.text);
    });
    const SegmentRow* row = nullptr;
    std::string rows;
    for (const SegmentRow& r : table.rows) {
        if (r.name == row_word.text) row = &r;
        rows += (rows.empty() ? "" : ", ") + std::string(r.name);
    }
    if (!row)
        throw ScriptError(row_word.location, "the table '" + table_word.text + "' has no segment '" + row_word.text + "'",
                          "its segments are: " + rows);
    const Quantity& mass_q = s.quantities.at("mass");
    const Quantity& length_q = s.quantities.at("length");
    const double body_mass = m.number_of(mass_q, Dimension::mass(), "the subject's mass", mass_q.value->location);
    const double length = segment_length(m, sys, length_q);
    const SegmentParameters p = m.guard(row_word.location, [&] {
        return calc_segment_parameters(table, row_word.text, body_mass, length);
    });
    if (std::isnan(p.inertia_flexion))
        throw ScriptError(row_word.location, "the table '" + table_word.text + "' gives no radius of gyration for '" +
                                                 row_word.text + "', so its moment of inertia is unknown",
                          "use a composite segment that has one (hat, trunk_head_neck), or another table");
    // three constants with their units
    const Dimension dims[3] = {Dimension::mass(), Dimension::length(), Dimension::mass() * pow(Dimension::length(), 2)};
    const double values[3] = {p.mass, p.com_distance, p.inertia_flexion};
    SymbolTable& symbols = sys.symbols();
    std::string said;
    for (int i = 0; i < 3; ++i) {
        const Word& w = names[static_cast<std::size_t>(i)];
        m.declare_name(w, NameKind::symbol);
        m.guard(w.location, [&] { symbols.add_constant(w.text, values[i]); });
        m.units[w.text] = SymbolUnits{dims[i], std::nullopt};
        said += (i ? ", " : "") + w.text + " = " + m.transcript.number(values[i]) +
                (si_unit(dims[i]).empty() ? "" : " " + si_unit(dims[i]));
    }
    // the row used, with its source
    m.transcript.result("segment " + row_word.text + " (" + std::string(row->endpoints) + ") from " +
                        std::string(table.key) + ": " + said + "\n  mass " + m.transcript.number(row->mass_fraction) +
                        " of the body, centre of mass " + m.transcript.number(row->com_fraction) +
                        " of the length from the proximal end, radius of gyration " +
                        m.transcript.number(row->rg_flexion) + " of the length\n  source: " +
                        std::string(table.source));
}

}  // namespace

std::vector<StatementSpec> biomech_statements() {
    return {
        {.keyword = "segment", .family = "Mass and loads",
         .help = "a segment's mass, centre-of-mass distance and inertia from a published table (Winter, de Leva)",
         .forms = {{"`segment` *m*, *d*, *I* `from` `winter`/`de_leva_male`/`de_leva_female` *segment* `mass` *M* `length` *L*",
                    "segment m_B, d_B, I_B from winter thigh mass 56.7 kg length 41.65 cm",
                    "`calc_segment_parameters` (declares the three constants; prints the table's row and source); "
                    "the length a number with its unit or constants with values (`scale L_T from ...`, then "
                    "`length L_T`)"}},
         .clauses = {"from", "length"},
         .parse = parse_segment, .run = run_segment},
    };
}

}  // namespace alembert::lang
