// SPDX-License-Identifier: MIT
// Expressions as TeX, in a deterministic order, for KaTeX in the report.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {

using GiNaC::is_a;

std::string latex_name(const std::string& name) {
    // split off primes: qA'' -> qA, ''
    std::size_t end = name.size();
    while (end > 0 && name[end - 1] == '\'') --end;
    std::string base = name.substr(0, end), primes = name.substr(end);
    // the first underscore starts the subscript; later ones are the name's own characters
    // (ankle_angle_l: ankle_{angle\_l}, not a subscript's subscript)
    std::size_t us = base.find('_');
    const bool subscript = us != std::string::npos && us > 0 && us + 1 < base.size();
    // TeX specials other than the subscript are escaped
    std::string safe;
    for (std::size_t i = 0; i < base.size(); ++i) {
        const char c = base[i];
        if (subscript && i == us) {
            safe += "_{";
            continue;
        }
        if (c == '#' || c == '$' || c == '%' || c == '&' || c == '_') safe += '\\';
        safe += c;
    }
    if (subscript) safe += "}";
    if (!primes.empty()) safe = "{" + safe + "}" + primes;
    return safe;
}

std::string nstr(const GiNaC::numeric& n) { return to_string(ex(n)); }

std::string latex_numeric(const GiNaC::numeric& n) {
    if (n.is_integer()) return nstr(n);
    if (n.is_rational()) {
        std::string s = "\\frac{" + nstr(GiNaC::numer(n)) + "}{" + nstr(GiNaC::denom(n)) + "}";
        return n.is_negative() ? "-" + std::string("\\frac{") + nstr((-GiNaC::numer(n))) + "}{" +
                                     nstr(GiNaC::denom(n)) + "}"
                               : s;
    }
    std::ostringstream os;
    os.precision(6);
    os << n.to_double();
    return os.str();
}

std::string latex(const ex& e, TextPrinter& text);

// a factor of a product: sums in parentheses
std::string latex_factor(const ex& e, TextPrinter& text) {
    if (is_a<GiNaC::add>(e)) return "\\left(" + latex(e, text) + "\\right)";
    if (is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_negative())
        return "\\left(" + latex(e, text) + "\\right)";
    return latex(e, text);
}

std::vector<ex> sorted_operands(const ex& e, TextPrinter& text) {
    std::vector<std::pair<std::string, ex>> keyed;
    for (std::size_t i = 0; i < e.nops(); ++i) keyed.emplace_back(text(e.op(i)), e.op(i));
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<ex> out;
    for (auto& k : keyed) out.push_back(k.second);
    return out;
}

// the factors of a product, each in the sign the text printer gives it (a sum s or -s as
// GiNaC's term order happened to leave it), sorted by their text; the signs taken out in `coeff`
std::vector<ex> canonical_factors(const ex& e, TextPrinter& text, GiNaC::numeric& coeff) {
    bool flip = false;
    std::vector<std::pair<std::string, ex>> keyed;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        if (is_a<GiNaC::numeric>(e.op(i))) {
            coeff *= GiNaC::ex_to<GiNaC::numeric>(e.op(i));
            continue;
        }
        const ex f = text.canonical_factor(e.op(i), flip);
        keyed.emplace_back(text(f), f);
    }
    if (flip) coeff = -coeff;
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<ex> out;
    for (auto& k : keyed) out.push_back(k.second);
    return out;
}

std::string latex_mul(const ex& e, TextPrinter& text) {
    GiNaC::numeric coeff = 1;
    std::vector<std::string> num, den;
    for (const ex& f : canonical_factors(e, text, coeff)) {
        if (is_a<GiNaC::power>(f) && is_a<GiNaC::numeric>(f.op(1)) &&
                   GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
            ex inv = GiNaC::pow(f.op(0), -f.op(1));
            den.push_back(latex_factor(inv, text));
        } else {
            num.push_back(latex_factor(f, text));
        }
    }
    std::string sign = coeff.is_negative() ? "-" : "";
    GiNaC::numeric c = GiNaC::abs(coeff);
    std::string numer;
    if (c.is_rational() && !c.is_integer()) {
        if (GiNaC::numer(c) != 1 || num.empty()) num.insert(num.begin(), nstr(GiNaC::numer(c)));
        den.insert(den.begin(), nstr(GiNaC::denom(c)));
    } else if (c != 1) {
        num.insert(num.begin(), latex_numeric(c));
    }
    auto join = [](const std::vector<std::string>& v) {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " \\, " : "") + v[i];
        return s;
    };
    numer = num.empty() ? "1" : join(num);
    if (den.empty()) return sign + numer;
    return sign + "\\frac{" + numer + "}{" + join(den) + "}";
}

std::string latex_add(const ex& e, TextPrinter& text) {
    std::string out;
    bool first = true;
    for (const ex& t : sorted_operands(e, text)) {
        std::string s = latex(t, text);
        if (first)
            out = s;
        else if (!s.empty() && s[0] == '-')
            out += " - " + s.substr(1);
        else
            out += " + " + s;
        first = false;
    }
    return out;
}

std::string latex(const ex& e, TextPrinter& text) {
    if (is_a<GiNaC::numeric>(e)) return latex_numeric(GiNaC::ex_to<GiNaC::numeric>(e));
    if (is_a<GiNaC::symbol>(e)) return latex_name(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    if (is_a<GiNaC::add>(e)) return latex_add(e, text);
    if (is_a<GiNaC::mul>(e)) return latex_mul(e, text);
    if (is_a<GiNaC::power>(e) || is_a<GiNaC::function>(e)) {
        // (-s)^3 and sin(-s) as the text printer writes them: -s^3, -sin(s)
        bool flip = false;
        const ex c = text.canonical_factor(e, flip);
        if (!c.is_equal(e)) return (flip ? "-" : "") + latex(c, text);
    }
    if (is_a<GiNaC::power>(e)) {
        const ex& b = e.op(0);
        const ex& p = e.op(1);
        if (p.is_equal(GiNaC::numeric(1, 2))) return "\\sqrt{" + latex(b, text) + "}";
        if (is_a<GiNaC::numeric>(p) && GiNaC::ex_to<GiNaC::numeric>(p).is_negative())
            return "\\frac{1}{" + latex_factor(GiNaC::pow(b, -p), text) + "}";
        std::string base = is_a<GiNaC::symbol>(b) && text(b).find('\'') == std::string::npos
                               ? latex(b, text)
                               : "\\left(" + latex(b, text) + "\\right)";
        return base + "^{" + latex(p, text) + "}";
    }
    if (is_a<GiNaC::function>(e)) {
        std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        static const char* known[] = {"sin", "cos", "tan", "exp", "log", "sinh", "cosh", "tanh"};
        std::string head = "\\operatorname{" + name + "}";
        for (const char* k : known)
            if (name == k) head = std::string("\\") + k;
        if (name == "abs") return "\\left|" + latex(e.op(0), text) + "\\right|";
        std::string args;
        for (std::size_t i = 0; i < e.nops(); ++i) args += (i ? ", " : "") + latex(e.op(i), text);
        return head + "\\left(" + args + "\\right)";
    }
    // anything else (relations, constants such as Pi): GiNaC's own form, escaped
    const std::string& s = text(e);
    return s == "Pi" ? "\\pi" : "\\mathrm{" + s + "}";
}

}  // namespace

std::string to_latex(const ex& e) {
    TextPrinter text;  // the operands' sort keys at every level, each node printed once
    return latex(e, text);
}

}  // namespace alembert
