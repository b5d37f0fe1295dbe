// SPDX-License-Identifier: MIT
// The deterministic expression printer.
#include "alembert/sym/print.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "alembert/sym/simplify.hpp"

namespace alembert {

using namespace GiNaC;

// named, not anonymous: TextPrinter's memory holds a Printer
namespace print_detail {

enum Prec { kSum = 1, kProduct = 2, kPower = 3, kAtom = 4 };

struct Printed {
    std::string text;
    int prec;
    bool negative = false;  // text starts with '-'
};

std::string print_double(double v) {
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    if (ec != std::errc()) return std::to_string(v);
    std::string s(buf, end);
    return s;
}

std::string print_numeric(const numeric& n) {
    if (n.is_integer()) return n.to_cl_N() == 0 ? "0" : [&] {
            std::ostringstream os;
            os << n;
            return os.str();
        }();
    if (n.is_rational()) {
        std::ostringstream os;
        os << n.numer() << "/" << n.denom();
        return os.str();
    }
    if (n.is_real()) return print_double(n.to_double());
    std::ostringstream os;
    os << n;
    return os.str();
}

// GiNaC's hash of an expression, for memo tables keyed by expressions
struct PrintKeyHash {
    std::size_t operator()(const ex& e) const { return e.gethash(); }
};
template <class V>
using PrintMemo = std::unordered_map<ex, V, PrintKeyHash, ex_is_equal>;

std::string paren(const Printed& x, int min_prec) {
    return x.prec < min_prec ? "(" + x.text + ")" : x.text;
}

// sort key of a factor: symbols and their powers, then functions, then the rest
int factor_rank(const ex& f) {
    const ex& b = is_a<power>(f) ? f.op(0) : f;
    if (is_a<symbol>(b)) return 0;
    if (is_a<function>(b)) return 1;
    return 2;
}

// <0, 0, >0 as a is before, equal to, after b with both lower-cased
int compare_ignoring_case(const std::string& a, const std::string& b) {
    const std::size_t n = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < n; ++i) {
        const int x = std::tolower(static_cast<unsigned char>(a[i])), y = std::tolower(static_cast<unsigned char>(b[i]));
        if (x != y) return x < y ? -1 : 1;
    }
    return a.size() < b.size() ? -1 : a.size() > b.size() ? 1 : 0;
}

// -s, negated term by term (GiNaC may hold -s as the product (-1)*s)
ex negated(const ex& s) {
    ex neg = 0;
    for (std::size_t i = 0; i < s.nops(); ++i) neg += -s.op(i);
    return neg;
}

ex flip_trig(const ex& f) {
    const std::string& name = ex_to<function>(f).get_name();
    ex a = negated(f.op(0));
    return name == "sin" ? sin(a) : name == "cos" ? cos(a) : tan(a);
}

// Prints expressions with every decision about a subexpression (its text, its sign, its sort
// key) made once and remembered: an expression is a DAG whose shared nodes are reached many
// times, and deciding a product's sign prints its sums, so without the memo the cost grows
// exponentially with the depth of nesting. With it, each distinct node is printed once and the
// cost is the size of the text written.
class Printer {
public:
    const Printed& p(const ex& e) {
        auto it = printed_.find(e);
        if (it != printed_.end()) return it->second;
        Printed out = print_node(e);
        return printed_.emplace(e, std::move(out)).first->second;
    }

    // `f` as a factor of a product prints it (TextPrinter::canonical_factor)
    ex factor_as_printed(const ex& f, bool& flip) {
        const bool before = flip;
        ex g = canonical_factor(f, flip);
        if (is_a<mul>(g)) {  // as print_mul: factors of a product are never products
            flip = before;
            return f;
        }
        return g;
    }

private:
    PrintMemo<Printed> printed_;
    PrintMemo<bool> flips_;
    PrintMemo<std::vector<std::string>> names_;

    Printed print_node(const ex& e) {
        if (is_a<symbol>(e)) return {ex_to<symbol>(e).get_name(), kAtom};
        if (is_a<numeric>(e)) {
            const numeric& n = ex_to<numeric>(e);
            std::string s = print_numeric(n);
            bool neg = n.is_real() && n < 0;
            return {s, neg || (n.is_rational() && !n.is_integer()) ? kSum : kAtom, neg};
        }
        if (is_a<add>(e)) return print_add(e);
        if (is_a<mul>(e)) return print_mul(e);
        if (is_a<power>(e)) return print_power(e);
        if (is_a<function>(e)) {
            bool odd = false;
            if (trig_of_negative(e, odd)) {
                const Printed& t = p(flip_trig(e));
                return odd ? Printed{"-" + t.text, kSum, true} : t;
            }
            std::string s = ex_to<function>(e).get_name() + "(";
            for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + p(e.op(i)).text;
            return {s + ")", kAtom};
        }
        if (is_a<relational>(e)) {
            const char* op = " = ";
            return {p(e.op(0)).text + op + p(e.op(1)).text, 0};
        }
        std::ostringstream os;
        os << e;
        return {os.str(), kAtom};
    }

    std::string print_factors(const std::vector<ex>& fs) {
        // sorted by rank, then by text ignoring case, then by text (compared in place: a
        // lower-cased copy of every factor cost as much as printing it)
        std::vector<std::pair<int, std::string>> items;
        for (const ex& f : fs)
            items.emplace_back(factor_rank(f), is_a<add>(f) ? "(" + p(f).text + ")" : paren(p(f), kProduct + 1));
        std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
            if (a.first != b.first) return a.first < b.first;
            const int c = compare_ignoring_case(a.second, b.second);
            return c != 0 ? c < 0 : a.second < b.second;
        });
        std::string out;
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (i) out += '*';
            out += items[i].second;
        }
        return out;
    }

    // GiNaC's choice between s and -s inside a product depends on its internal
    // (address-dependent) term order, so products print their sums in one canonical sign and
    // carry the sign themselves.
    // True if the sum s should print as -(-s): -s prints with a leading plus and s does not,
    // or, when both or neither do, -s prints first in text order. The choice is the same for s
    // and -s, so a sign taken out once is never taken out again.
    bool should_flip(const ex& s) {
        if (!is_a<add>(s)) return false;
        auto it = flips_.find(s);
        if (it != flips_.end()) return it->second;
        bool flip = false;
        ex n = negated(s);
        if (is_a<add>(n)) {
            const Printed &a = p(s), &b = p(n);
            flip = a.negative != b.negative ? a.negative : b.text < a.text;
        }
        flips_.emplace(s, flip);
        return flip;
    }

    // sin, cos or tan of a sum that leads negative: the argument's sign is taken out
    // (cos(-s) = cos(s), sin(-s) = -sin(s)), for the same reason
    bool trig_of_negative(const ex& f, bool& odd) {
        if (!is_a<function>(f) || f.nops() != 1 || !should_flip(f.op(0))) return false;
        const std::string& name = ex_to<function>(f).get_name();
        odd = name == "sin" || name == "tan";
        return odd || name == "cos";
    }

    // a factor with the sign of a sum (or of a trigonometric function's argument) fixed as
    // above; `flip` toggles for each sign moved out of the factor
    ex canonical_factor(const ex& f, bool& flip) {
        bool odd = false;
        if (should_flip(f)) {
            flip = !flip;
            return negated(f);
        }
        if (trig_of_negative(f, odd)) {
            if (odd) flip = !flip;
            return flip_trig(f);
        }
        if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_integer()) {
            bool inner = false;
            ex b = canonical_factor(f.op(0), inner);
            if (inner && ex_to<numeric>(f.op(1)).is_odd()) flip = !flip;
            return pow(b, f.op(1));
        }
        return f;
    }

    Printed print_mul(const ex& e) {
        numeric c = 1;
        std::vector<ex> num, den;
        bool flip = false;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const bool flip_before = flip;
            ex f = is_a<numeric>(e.op(i)) ? e.op(i) : canonical_factor(e.op(i), flip);
            if (is_a<mul>(f)) {
                // GiNaC may return the canonical form as a product (a power of a sum with a
                // numeric content, say); printing that would come back here without end, so
                // the factor keeps its own form (factors of a product are never products)
                f = e.op(i);
                flip = flip_before;
            }
            if (is_a<numeric>(f)) {
                c *= ex_to<numeric>(f);
            } else if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)) < 0) {
                den.push_back(pow(f.op(0), -f.op(1)));
            } else {
                num.push_back(f);
            }
        }
        if (flip) c = -c;
        bool neg = c.is_real() && c < 0;
        if (neg) c = -c;
        numeric cn = c.is_rational() ? c.numer() : c, cd = c.is_rational() ? c.denom() : numeric(1);
        std::string s;
        if (!(cn == 1) || num.empty()) s = print_numeric(cn);
        if (!num.empty()) s += (s.empty() ? "" : "*") + print_factors(num);
        if (!(cd == 1)) den.push_back(cd);
        if (!den.empty()) {
            bool single = den.size() == 1 && !is_a<mul>(den[0]) && !is_a<add>(den[0]);
            std::string d = den.size() == 1 && is_a<numeric>(den[0])
                                ? print_numeric(ex_to<numeric>(den[0]))
                                : print_factors(den);
            s += "/" + (single ? paren(p(den[0]), kPower) : "(" + d + ")");
        }
        return {neg ? "-" + s : s, neg ? kSum : kProduct, neg};
    }

    // the names of the symbols of e, one for each place a symbol stands, sorted
    const std::vector<std::string>& names(const ex& e) {
        auto it = names_.find(e);
        if (it != names_.end()) return it->second;
        std::vector<std::string> out;
        if (is_a<symbol>(e)) {
            out.push_back(ex_to<symbol>(e).get_name());
        } else {
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const std::vector<std::string>& c = names(e.op(i));
                std::vector<std::string> merged;
                merged.reserve(out.size() + c.size());
                std::merge(out.begin(), out.end(), c.begin(), c.end(), std::back_inserter(merged));
                out = std::move(merged);
            }
        }
        return names_.emplace(e, std::move(out)).first->second;
    }

    // sort key of a term: the names of its symbols, then higher degree first
    std::tuple<std::string, int, std::string> term_key(const ex& t, const std::string& text) {
        const std::vector<std::string>& ns = names(t);
        std::string k;
        for (const auto& n : ns) k += n + ",";
        int degree = static_cast<int>(ns.size());
        std::string body = text[0] == '-' ? text.substr(1) : text;
        return {k, -degree, body};
    }

    Printed print_add(const ex& e) {
        std::vector<std::pair<std::tuple<std::string, int, std::string>, const Printed*>> terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const Printed& t = p(e.op(i));
            terms.push_back({term_key(e.op(i), t.text), &t});
        }
        // numbers go last
        std::stable_sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) {
            bool an = std::get<0>(a.first).empty(), bn = std::get<0>(b.first).empty();
            if (an != bn) return bn;
            return a.first < b.first;
        });
        std::string s;
        for (std::size_t i = 0; i < terms.size(); ++i) {
            const Printed& t = *terms[i].second;
            if (i == 0) s = t.text;
            else if (t.negative) s.append(" - ").append(t.text, 1);
            else s.append(" + ").append(t.text);
        }
        return {s, kSum, !s.empty() && s[0] == '-'};
    }

    Printed print_power(const ex& e) {
        const ex &b = e.op(0), &x = e.op(1);
        if (x.is_equal(numeric(1, 2))) return {"sqrt(" + p(b).text + ")", kAtom};
        if (is_a<numeric>(x) && ex_to<numeric>(x) < 0) {
            const Printed& d = p(pow(b, -x));
            return {"1/" + paren(d, kPower), kProduct};
        }
        // an even power of a sum prints the sum with a leading plus: (-s)^2 = s^2
        bool even = is_a<numeric>(x) && ex_to<numeric>(x).is_even();
        bool flip = false;
        ex base = is_a<numeric>(x) && ex_to<numeric>(x).is_integer() ? canonical_factor(b, flip) : b;
        std::string text = paren(p(base), kAtom) + "^" + paren(p(x), kAtom);
        // an odd power carries the sign out, printed here: GiNaC would fold -(base^x) back
        // into the power it came from
        if (flip && !even) return {"-" + text, kSum, true};
        return {text, kPower};
    }
};

}  // namespace print_detail

using print_detail::Printer;
using print_detail::PrintMemo;

std::string to_string(const ex& e) { return Printer().p(e).text; }

struct TextPrinter::Memo {
    Printer printer;
};

TextPrinter::TextPrinter() : memo_(std::make_unique<Memo>()) {}
TextPrinter::~TextPrinter() = default;
TextPrinter::TextPrinter(TextPrinter&&) noexcept = default;
TextPrinter& TextPrinter::operator=(TextPrinter&&) noexcept = default;

const std::string& TextPrinter::operator()(const ex& e) { return memo_->printer.p(e).text; }

ex TextPrinter::canonical_factor(const ex& f, bool& flip) { return memo_->printer.factor_as_printed(f, flip); }

std::vector<std::string> to_strings(const std::vector<ex>& exprs) {
    Printer printer;
    std::vector<std::string> out;
    out.reserve(exprs.size());
    for (const ex& e : exprs) out.push_back(printer.p(e).text);
    return out;
}

namespace {

// Names subexpressions bottom-up over the DAG so that every printed line stays short.
class Abbreviator : public map_function {
public:
    // `printer` measures the lines: one shared with other abbreviations (and with the
    // printing of the result) prints a node met again from its memory
    Abbreviator(std::size_t width, std::string stem, std::size_t first, Printer& printer)
        : width_(std::max<std::size_t>(width, 20)),
          stem_(std::move(stem)),
          next_(first),
          printer_(printer) {}

    // how many parents each node has, a node's children counted on its first visit only
    void count_uses(const ex& e) {
        if (e.nops() == 0) return;
        if (++uses_[e] > 1) return;
        for (std::size_t i = 0; i < e.nops(); ++i) count_uses(e.op(i));
    }

    ex operator()(const ex& e) override {
        if (e.nops() == 0) return e;
        auto it = done_.find(e);
        if (it != done_.end()) return it->second;
        // the operands in the order of their text, so that the names given below them follow
        // the expression, not GiNaC's (creation-order dependent) order of operands
        for (const ex& o : in_text_order(e)) (void)(*this)(o);
        ex out = shortened(e.map(*this));
        auto u = uses_.find(e);
        if (u != uses_.end() && u->second > 1 && out.nops() > 0 && count_ops(out) >= 2)
            out = name(out);
        done_.emplace(e, out);
        return out;
    }

    // the root of a result: shortened, never named
    ex result(const ex& e) { return e.nops() == 0 ? e : (*this)(e); }

    std::vector<std::pair<ex, ex>> definitions;  // (name, what it stands for)

private:
    std::size_t width_;
    std::string stem_;
    std::size_t next_;
    PrintMemo<std::size_t> uses_;
    PrintMemo<ex> done_;
    Printer& printer_;  // the operands' texts, printed once for all the lines they are measured in

    std::size_t length(const ex& x) { return printer_.p(x).text.size(); }

    // the operands of x sorted by their text (each printed once, by the memo)
    std::vector<ex> in_text_order(const ex& x) {
        std::vector<std::pair<const std::string*, ex>> keyed;
        for (std::size_t i = 0; i < x.nops(); ++i) keyed.emplace_back(&printer_.p(x.op(i)).text, x.op(i));
        std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return *a.first < *b.first; });
        std::vector<ex> out;
        out.reserve(keyed.size());
        for (auto& k : keyed) out.push_back(k.second);
        return out;
    }

    ex name(const ex& x) {
        const ex z = symbol(stem_ + std::to_string(next_++));
        definitions.emplace_back(z, x);
        return z;
    }

    // x, whose operands are already short, with operands named until its line fits: the
    // longest first, then, for a sum or product of many short operands, runs of them
    ex shortened(ex x) {
        if (length(x) <= width_ || x.nops() == 0) return x;
        if (is_a<add>(x) || is_a<mul>(x) || is_a<power>(x) || is_a<function>(x)) {
            // the longest first; of equal lengths, the first in text order
            const std::vector<ex> ops = in_text_order(x);
            std::vector<std::pair<std::size_t, std::size_t>> longest;  // (length, place in ops)
            for (std::size_t i = 0; i < ops.size(); ++i)
                if (ops[i].nops() > 0) longest.push_back({length(ops[i]), i});
            std::stable_sort(longest.begin(), longest.end(),
                             [](const auto& a, const auto& b) { return a.first > b.first; });
            exmap named;
            std::size_t total = length(x);
            for (const auto& [len, i] : longest) {
                if (total <= width_ || len <= stem_.size() + 4) break;
                named[ops[i]] = name(ops[i]);
                total -= len;
            }
            if (!named.empty()) x = x.subs(named, subs_options::no_pattern);
        }
        if ((is_a<add>(x) || is_a<mul>(x)) && length(x) > width_) {
            // runs of operands, each run a line of its own
            const bool sum = is_a<add>(x);
            ex whole = sum ? ex(0) : ex(1), run = sum ? ex(0) : ex(1);
            std::size_t run_length = 0;
            for (const ex& o : in_text_order(x)) {
                const std::size_t len = length(o) + 3;
                if (run_length + len > width_ && run_length > 0) {
                    const ex r = run.nops() > 0 ? name(run) : run;
                    whole = sum ? whole + r : whole * r;
                    run = sum ? ex(0) : ex(1);
                    run_length = 0;
                }
                run = sum ? run + o : run * o;
                run_length += len;
            }
            whole = sum ? whole + run : whole * run;
            x = shortened(whole);
        }
        return x;
    }
};

}  // namespace

namespace {

AbbreviatedForm abbreviate_with(const std::vector<ex>& exprs, std::size_t width,
                                const std::string& stem, std::size_t first, Printer& printer) {
    Abbreviator a(width, stem, first, printer);
    for (const ex& e : exprs) a.count_uses(e);
    AbbreviatedForm out;
    for (const ex& e : exprs) {
        out.results.push_back(a.result(e));
        out.defined_before.push_back(a.definitions.size());
    }
    out.definitions = std::move(a.definitions);
    return out;
}

}  // namespace

AbbreviatedForm abbreviate_form(const std::vector<ex>& exprs, std::size_t width,
                                const std::string& stem, std::size_t first) {
    Printer printer;
    return abbreviate_with(exprs, width, stem, first, printer);
}

AbbreviatedForm abbreviate_form(const std::vector<ex>& exprs, TextPrinter& printer,
                                std::size_t width, const std::string& stem, std::size_t first) {
    return abbreviate_with(exprs, width, stem, first, printer.memo_->printer);
}

AbbreviatedText abbreviate(const std::vector<ex>& exprs, std::size_t width, const std::string& stem,
                           std::size_t first) {
    // one printer for measuring the lines and for writing them: the lines' nodes were printed
    // while they were measured
    Printer printer;
    AbbreviatedForm f = abbreviate_with(exprs, width, stem, first, printer);
    AbbreviatedText out;
    for (const auto& [z, d] : f.definitions) out.definitions.push_back(printer.p(z).text + " = " + printer.p(d).text);
    for (const ex& r : f.results) out.results.push_back(printer.p(r).text);
    out.defined_before = std::move(f.defined_before);
    return out;
}

void print(std::ostream& os, const ex& e) { os << to_string(e); }

std::string format_intermediates(const SymbolTable& table, const std::vector<ex>& printed) {
    std::string out;
    for (const auto& [z, d] : calc_used_intermediates(table, printed))
        out += to_string(z) + " = " + to_string(d) + "\n";
    return out;
}

}  // namespace alembert
