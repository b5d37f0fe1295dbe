// SPDX-License-Identifier: MIT
// The rows' equations laid out to be read: solved for the row's unknown where that is exact,
// collected in the accelerations, and written so that TeX and KaTeX break a long one between
// its terms (no \left( ... \right) group around a sum, which neither can break inside).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "alembert/eom/readable_equation.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

// equations of more operations than this are typeset abbreviated, with numbered intermediates
// (written out as a tree, the TeX of a large model's equation grows exponentially with the
// sharing in it; and simplifying a row of 1,500 to 4,000 operations for the page cost the
// arm's report 2 of its 3.6 s while leaving a wall of a hundred terms)
constexpr std::size_t kAbbreviateOps = 1500;

using report_detail::kUnbreakableChars;
using report_detail::longest_unbreakable;

}  // namespace

std::size_t report_detail::longest_unbreakable(const std::string& tex) {
    std::size_t longest = 0, start = 0;
    int depth = 0;
    for (std::size_t i = 0; i < tex.size(); ++i) {
        const char ch = tex[i];
        if (ch == '{') ++depth;
        else if (ch == '}') --depth;
        else if (depth == 0 && (ch == '+' || ch == '-' || ch == '=') && i > 0 && tex[i - 1] == ' ') {
            longest = std::max(longest, i - start);
            start = i;
        }
    }
    return std::max(longest, tex.size() - start);
}

namespace {

// whether the term holds an acceleration of the model
bool holds_acceleration(const SymbolTable& st, const ex& term) {
    for (const ex& s : symbols_of(term))
        if (st.owns(s) && st.kind(s) == SymbolKind::variable && st.derivative_order(s) == 2)
            return true;
    return false;
}

// "lhs = t1 + t2 ...": the terms holding the row's variable first (in 0 = E), then those of
// the accelerations (their coefficients gathered), then the rest, each group in the order of
// the terms' printed form
std::string terms_tex(const SymbolTable& st, const ReadableRelation& r, const ex& variable) {
    std::vector<std::string> terms;
    const ex& e = r.rhs;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        struct Term {
            int group;
            std::string key;
            ex term;
        };
        std::vector<Term> keyed;
        for (std::size_t i = 0; i < e.nops(); ++i)
            keyed.push_back({e.op(i).has(variable) ? 0 : holds_acceleration(st, e.op(i)) ? 1 : 2,
                             to_string(e.op(i)), e.op(i)});
        std::stable_sort(keyed.begin(), keyed.end(), [](const Term& a, const Term& b) {
            return a.group != b.group ? a.group < b.group : a.key < b.key;
        });
        for (const Term& k : keyed) terms.push_back(to_latex(k.term));
    } else {
        terms.push_back(to_latex(e));
    }
    std::string out = (r.solved() ? to_latex(r.lhs) : std::string("0")) + " = ";
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const std::string& t = terms[i];
        const bool neg = !t.empty() && t[0] == '-';
        if (i == 0)
            out += t;
        else
            out += neg ? " - " + t.substr(1) : " + " + t;
    }
    return out;
}

// "lhs = ..." with the named parts of the right side on the lines below it, w_1 = ..., each
// short, the parts in the order they are needed
std::string abbreviated_equation_tex(const std::string& lhs, const ex& e) {
    const AbbreviatedForm f = abbreviate_form({e}, 100, "w");
    std::string out = lhs + " = " + to_latex(f.results.at(0));
    for (std::size_t i = 0; i < f.definitions.size(); ++i)
        out += std::string(report_detail::kTexLineBreak) + (i == 0 ? "\\text{with } " : "") +
               to_latex(f.definitions[i].first) + " = " + to_latex(f.definitions[i].second);
    return out;
}

// the relation as terms_tex writes it, or, when a piece of it too long for a line would be
// left unbroken (a fraction over a long root), abbreviated with named parts
std::string relation_tex(const SymbolTable& st, const ReadableRelation& r, const ex& variable) {
    const std::string whole = terms_tex(st, r, variable);
    if (longest_unbreakable(report_detail::breakable_tex(whole)) <= kUnbreakableChars)
        return whole;
    return abbreviated_equation_tex(r.solved() ? to_latex(r.lhs) : "0", r.rhs);
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

}  // namespace

std::string report_detail::breakable_tex(std::string tex) {
    replace_all(tex, "\\left(", "(");
    replace_all(tex, "\\right)", ")");
    replace_all(tex, "\\left|", "|");
    replace_all(tex, "\\right|", "|");
    return tex;
}

std::vector<std::string> report_detail::tex_lines(const std::string& tex) {
    std::vector<std::string> out;
    const std::string sep = kTexLineBreak;
    std::size_t start = 0;
    for (std::size_t at = tex.find(sep); at != std::string::npos; at = tex.find(sep, start)) {
        out.push_back(tex.substr(start, at - start));
        start = at + sep.size();
    }
    out.push_back(tex.substr(start));
    return out;
}

std::vector<std::string> report_detail::typeset_equations(const ReportContent& c) {
    std::vector<std::string> out;
    if (!c.system) return out;
    out.reserve(c.rows.size());
    Simplifier simplifier;  // the rows share their kinematics: each node is simplified once
    const auto typeset = [&](const ex& e, const ex& variable) {
        return breakable_tex(count_ops(e) > kAbbreviateOps
                                 ? abbreviated_equation_tex("0", e)
                                 : relation_tex(c.system->symbols(),
                                                calc_solved_equation(*c.system, e, variable, simplifier),
                                                variable));
    };
    for (const RoadmapRow& r : c.rows) out.push_back(typeset(r.equation, r.variable));
    for (const ReportEquationSet& set : c.equation_sets)
        for (const ex& e : set.equations) out.push_back(typeset(e, ex()));
    return out;
}

}  // namespace alembert
