// SPDX-License-Identifier: MIT
// The rows' equations laid out to be read: solved for the row's unknown where that is exact,
// collected in the accelerations, and written so that TeX and KaTeX break a long one between
// its terms (no \left( ... \right) group around a sum, which neither can break inside).
#include <algorithm>
#include <map>
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

// whether the term holds an acceleration or an unknown load of the model
bool holds_acceleration(const SymbolTable& st, const ex& term) {
    for (const ex& s : symbols_of(term))
        if (st.owns(s) && (st.kind(s) == SymbolKind::variable || st.kind(s) == SymbolKind::unknown) &&
             st.is_solve_level(s))
            return true;
    return false;
}

// the names of the accelerations and unknown loads `term` holds, in order: the key that
// sorts the terms of qA'', qB'', F_x, F_y by their symbol
std::string gathering_names(const SymbolTable& st, const ex& term) {
    std::vector<std::string> names;
    for (const ex& s : symbols_of(term))
        if (holds_acceleration(st, s)) names.push_back(to_string(s));
    std::sort(names.begin(), names.end());
    std::string out;
    for (const std::string& n : names) out += n + " ";
    return out;
}

// "lhs = t1 + t2 ...": the terms holding the row's variable first (in 0 = E), then those of
// the accelerations and unknown loads (their coefficients gathered), then the rest, each group in the order of
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
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const ex& t = e.op(i);
            const int group = t.has(variable) ? 0 : holds_acceleration(st, t) ? 1 : 2;
            keyed.push_back({group, group == 1 ? gathering_names(st, t) : to_string(t), t});
        }
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

// radicands of more operations than this are named when a root leaves a line unbroken
constexpr std::size_t kNamedRadicandOps = 8;

// each root of a long sum in an expression (a spring's length sqrt(h^2 + L^2 - ...)) with the
// sum named w1, w2, ... in the order met; the names and what they stand for in `names`
struct NamedRadicands : GiNaC::map_function {
    NamedRadicands(const SymbolTable& table, Simplifier& simplify) : st(table), simplifier(simplify) {}
    const SymbolTable& st;
    Simplifier& simplifier;
    std::vector<std::pair<ex, ex>> names;
    std::map<ex, ex, GiNaC::ex_is_less> of;
    ex operator()(const ex& e) override {
        if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e)) return e;
        const ex m = e.map(*this);
        if (!GiNaC::is_a<GiNaC::power>(m) || !GiNaC::is_a<GiNaC::add>(m.op(0)) ||
            !GiNaC::is_a<GiNaC::numeric>(m.op(1)) || GiNaC::ex_to<GiNaC::numeric>(m.op(1)).is_integer() ||
            count_ops(m.op(0)) <= kNamedRadicandOps)
            return m;
        auto [it, added] = of.try_emplace(m.op(0), ex());
        if (added) {
            it->second = GiNaC::symbol("w" + std::to_string(names.size() + 1));
            names.push_back({it->second, group_by_varying_factors(st, simplifier(m.op(0)))});
        }
        return GiNaC::pow(it->second, m.op(1));
    }
};

// whether no line of `tex` (lines split by kTexLineBreak) has a piece too long to break
bool breaks_well(const std::string& tex) {
    for (const std::string& line : report_detail::tex_lines(report_detail::breakable_tex(tex)))
        if (longest_unbreakable(line) > kUnbreakableChars) return false;
    return true;
}

// the relation as terms_tex writes it; when a piece of it too long for a line would be left
// unbroken, with the long sums under its roots named on the lines below it (w1 = ...); when
// that is not enough (a fraction over a long sum), abbreviated with named parts
std::string relation_tex(const SymbolTable& st, const ReadableRelation& r, const ex& variable,
                         Simplifier& simplifier) {
    const std::string whole = terms_tex(st, r, variable);
    if (breaks_well(whole)) return whole;
    NamedRadicands named(st, simplifier);
    const ReadableRelation shorter{r.lhs, named(r.rhs)};
    if (!named.names.empty()) {
        std::string out = terms_tex(st, shorter, variable);
        for (std::size_t i = 0; i < named.names.size(); ++i)
            out += std::string(report_detail::kTexLineBreak) + (i == 0 ? "\\text{with } " : "") +
                   to_latex(named.names[i].first) + " = " + to_latex(named.names[i].second);
        if (breaks_well(out)) return out;
    }
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
                                                variable, simplifier));
    };
    for (const RoadmapRow& r : c.rows) out.push_back(typeset(r.equation, r.variable));
    for (const ReportEquationSet& set : c.equation_sets)
        for (std::size_t k = 0; k < set.equations.size(); ++k)
            out.push_back(typeset(set.equations[k], k < set.unknowns.size() ? set.unknowns[k] : ex()));
    return out;
}

}  // namespace alembert
