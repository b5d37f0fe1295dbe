// SPDX-License-Identifier: MIT
// Trigonometric simplification by term pairing, and semantic equality.
#include "alembert/sym/simplify.hpp"

#include <cmath>
#include <complex>
#include <algorithm>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <limits>
#include <set>
#include <unordered_map>

#include "alembert/sym/print.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

using namespace GiNaC;

// named, not anonymous: Simplifier's memory holds a NodeIndex
namespace simplify_detail {

// the (rest, coefficient) pairs and the numeric coefficient of a sum or product, read where
// GiNaC keeps them: op(i) of a sum or product makes a new node for each term with a
// coefficient (3*x, x^2), which walking a large expression would allocate again and again
struct Pairs : expairseq {
    static const epvector& of(const expairseq& e) { return e.*(&Pairs::seq); }
    static const ex& coefficient(const expairseq& e) { return e.*(&Pairs::overall_coeff); }
};

const numeric& one() {
    static const numeric n(1);
    return n;
}

const numeric& minus_one() {
    static const numeric n(-1);
    return n;
}

std::size_t numeric_ops(const numeric& n) {
    return (n.is_negative() ? 1 : 0) + (n.is_rational() && !n.is_integer() ? 1 : 0);
}

// what simplification asks of a node, computed over the DAG: each distinct node once (a shared
// node reached by many parents would otherwise be walked once per path, exponentially many
// with depth); operation counts saturate instead of wrapping
struct Facts {
    std::size_t ops = 0;       // count_ops
    bool trig = false;         // holds sin or cos
    bool denominator = false;  // holds a power with a negative exponent
};

class NodeIndex {
public:
    std::size_t ops(const ex& e) { return facts(e).ops; }

    Facts facts(const ex& e) {
        if (is_a<symbol>(e)) return {};
        if (is_a<numeric>(e)) return {numeric_ops(ex_to<numeric>(e)), false, false};
        const basic* key = &ex_to<basic>(e);
        auto it = memo_.find(key);
        if (it != memo_.end()) return it->second;
        Facts f;
        auto take = [&](const Facts& c) {
            f.ops = plus(f.ops, c.ops);
            f.trig = f.trig || c.trig;
            f.denominator = f.denominator || c.denominator;
        };
        if (is_a<add>(e) || is_a<mul>(e)) {
            const bool sum = is_a<add>(e);
            const expairseq& s = ex_to<expairseq>(e);
            std::size_t operands = 0;
            for (const expair& p : Pairs::of(s)) {
                ++operands;
                take(facts(p.rest));
                const numeric& c = ex_to<numeric>(p.coeff);
                if (c.is_equal(one())) continue;
                if (sum) {
                    // rest*c: one more factor, a negation only when c is -1
                    f.ops = plus(f.ops, c.is_equal(minus_one()) ? 1 : 1 + numeric_ops(c));
                } else {
                    // rest^c: one power and its exponent
                    f.ops = plus(f.ops, 1 + numeric_ops(c));
                    if (c.is_negative()) f.denominator = true;
                }
            }
            const numeric& oc = ex_to<numeric>(Pairs::coefficient(s));
            const bool has_coefficient = sum ? !oc.is_zero() : !oc.is_equal(one());
            if (has_coefficient) {
                ++operands;
                f.ops = plus(f.ops, numeric_ops(oc));
            }
            // -x is one negation, not a product by -1 plus a negative number
            if (!sum && has_coefficient && oc.is_equal(minus_one())) f.ops = plus(f.ops, operands - 2);
            else f.ops = plus(f.ops, operands - 1);
        } else {
            for (std::size_t i = 0; i < e.nops(); ++i) take(facts(e.op(i)));
            f.ops = plus(f.ops, 1);  // power, function, other
            if (is_a<function>(e)) {
                const std::string& name = ex_to<function>(e).get_name();
                f.trig = f.trig || name == "sin" || name == "cos";
            }
            if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_real() &&
                ex_to<numeric>(e.op(1)).is_negative())
                f.denominator = true;
        }
        alive_.push_back(e);  // the address stays this node's while it is remembered
        memo_.emplace(key, f);
        return f;
    }

private:
    static std::size_t plus(std::size_t a, std::size_t b) {
        return a > std::numeric_limits<std::size_t>::max() - b ? std::numeric_limits<std::size_t>::max() : a + b;
    }
    std::unordered_map<const basic*, Facts> memo_;
    std::vector<ex> alive_;
};

}  // namespace simplify_detail

using simplify_detail::Facts;
using simplify_detail::NodeIndex;

std::size_t count_ops(const ex& e) { return NodeIndex().ops(e); }

std::size_t count_ops(const std::vector<ex>& exprs) {
    NodeIndex index;  // one memory: a node shared by several expressions is measured once
    std::size_t n = 0;
    for (const ex& e : exprs) {
        const std::size_t k = index.ops(e);
        n = n > std::numeric_limits<std::size_t>::max() - k
                ? std::numeric_limits<std::size_t>::max()
                : n + k;
    }
    return n;
}

namespace {

// the number of terms expand() would form for each node, an upper bound (no cancellation);
// shared subexpressions are counted once
class ExpansionCounter {
public:
    double largest = 1;

    double terms(const ex& e) {
        if (e.nops() == 0) return 1;
        auto it = memo_.find(e);
        if (it != memo_.end()) return it->second;
        double t = 1;
        if (is_a<add>(e)) {
            t = 0;
            for (std::size_t i = 0; i < e.nops(); ++i) t += terms(e.op(i));
        } else if (is_a<mul>(e)) {
            for (std::size_t i = 0; i < e.nops(); ++i) t *= terms(e.op(i));
        } else if (is_a<power>(e)) {
            const double k = terms(e.op(0));
            const ex& n = e.op(1);
            if (is_a<numeric>(n) && ex_to<numeric>(n).is_integer()) {
                // (t_1 + ... + t_k)^n has C(n+k-1, n) monomials; a negative power expands its
                // denominator and stays one term
                const double m = std::abs(ex_to<numeric>(n).to_double());
                const double p = monomials(k, m);
                largest = std::max(largest, p);
                t = ex_to<numeric>(n).is_positive() ? p : 1;
            } else {
                terms(n);
            }
        } else {
            for (std::size_t i = 0; i < e.nops(); ++i) terms(e.op(i));  // arguments expand apart
        }
        largest = std::max(largest, t);
        memo_.emplace(e, t);
        return t;
    }

private:
    std::map<ex, double, ex_is_less> memo_;

    // C(n+k-1, n): the monomials of degree n in k terms, infinity past 1e300
    static double monomials(double k, double n) {
        if (k <= 1 || n <= 1) return n < 1 ? 1 : k;
        const double m = std::min(n, k - 1), top = n + k - 1;
        double c = 1;
        for (double i = 1; i <= m; ++i) {
            c = c * (top - m + i) / i;
            if (c > 1e300) return HUGE_VAL;
        }
        return std::round(c);
    }
};

}  // namespace

double estimate_expansion_terms(const ex& e) {
    ExpansionCounter counter;
    counter.terms(e);
    return counter.largest;
}

namespace {

// one term of an expanded sum split into its numeric coefficient and the rest
struct Term {
    numeric c;
    ex rest;
};

Term split(const ex& t) {
    if (is_a<numeric>(t)) return {ex_to<numeric>(t), 1};
    if (is_a<mul>(t)) {
        const ex& last = t.op(t.nops() - 1);
        if (is_a<numeric>(last)) return {ex_to<numeric>(last), t / last};
    }
    return {1, t};
}

bool is_trig(const ex& f, const char* name) {
    return is_a<function>(f) && ex_to<function>(f).get_name() == name;
}

// (base, exponent) factors of a term's non-numeric part
std::vector<std::pair<ex, int>> factors(const ex& rest) {
    std::vector<std::pair<ex, int>> out;
    auto one = [&](const ex& f) {
        if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_integer())
            out.emplace_back(f.op(0), ex_to<numeric>(f.op(1)).to_int());
        else
            out.emplace_back(f, 1);
    };
    if (is_a<mul>(rest))
        for (std::size_t i = 0; i < rest.nops(); ++i) one(rest.op(i));
    else
        one(rest);
    return out;
}

std::vector<ex> terms_of(const ex& e) {
    std::vector<ex> out;
    if (is_a<add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) out.push_back(e.op(i));
    else
        out.push_back(e);
    return out;
}

// one pass of angle-sum folding over an expanded sum; returns true if anything folded
bool fold_angle_sums(std::vector<Term>& terms, NodeIndex& n) {
    std::map<ex, std::size_t, ex_is_less> index;
    for (std::size_t i = 0; i < terms.size(); ++i) index.emplace(terms[i].rest, i);
    std::vector<bool> used(terms.size(), false);
    std::vector<Term> out;
    bool changed = false;
    // sin and cos of each angle formed once for the call (GiNaC evaluates each one formed)
    std::map<ex, std::pair<ex, ex>, ex_is_less> trig_of;
    const auto sin_cos_of = [&](const ex& x) -> const std::pair<ex, ex>& {
        auto it = trig_of.find(x);
        if (it == trig_of.end()) it = trig_of.emplace(x, std::make_pair(sin(x), cos(x))).first;
        return it->second;
    };
    for (std::size_t i = 0; i < terms.size(); ++i) {
        if (used[i]) continue;
        const Term ti = terms[i];
        auto fs = factors(ti.rest);
        bool done = false;
        for (std::size_t p = 0; p < fs.size() && !done; ++p) {
            if (fs[p].second != 1) continue;
            for (std::size_t r = 0; r < fs.size() && !done; ++r) {
                if (r == p || fs[r].second != 1) continue;
                const ex &fa = fs[p].first, &fb = fs[r].first;
                bool sin_cos = is_trig(fa, "sin") && is_trig(fb, "cos");
                bool cos_cos = is_trig(fa, "cos") && is_trig(fb, "cos") && p < r;
                if (!sin_cos && !cos_cos) continue;
                ex a = fa.op(0), b = fb.op(0);
                if (a.is_equal(b)) continue;
                ex base = ti.rest / (fa * fb);
                const ex& sin_b = sin_cos_of(b).first;
                ex partner = sin_cos ? base * sin_cos_of(a).second * sin_b
                                     : base * sin_cos_of(a).first * sin_b;
                auto it = index.find(partner);
                if (it == index.end() || used[it->second] || it->second == i) continue;
                const numeric& cj = terms[it->second].c;
                // a difference of angles is written the shorter (then alphabetically first) way
                ex diff = a - b;
                numeric flip = 1;
                const ex ba = b - a;
                if (n.ops(ba) < n.ops(diff) ||
                    (n.ops(ba) == n.ops(diff) && to_string(ba) < to_string(diff)))
                    diff = b - a, flip = -1;
                ex folded;
                if (sin_cos) {
                    if (cj == ti.c) folded = sin(a + b);
                    else if (cj == -ti.c) folded = flip * sin(diff);
                } else {
                    if (cj == -ti.c) folded = cos(a + b);
                    else if (cj == ti.c) folded = cos(diff);
                }
                if (folded.is_zero() && !is_a<function>(folded)) continue;
                used[i] = used[it->second] = true;
                out.push_back(split(ti.c * base * folded));
                changed = done = true;
            }
        }
    }
    // unpaired terms last: a term left alone early may still be taken by a later one
    for (std::size_t i = 0; i < terms.size(); ++i)
        if (!used[i]) out.push_back(terms[i]);
    terms = std::move(out);
    return changed;
}

// angles x that occur as sin(x)^n or cos(x)^n with n >= 2
std::vector<ex> squared_angles(const ex& e) {
    exset seen;
    std::vector<ex> out;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        const ex& f = *it;
        if (is_a<power>(f) && (is_trig(f.op(0), "sin") || is_trig(f.op(0), "cos")) &&
            is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_integer() &&
            ex_to<numeric>(f.op(1)) >= 2 && seen.insert(f.op(0).op(0)).second)
            out.push_back(f.op(0).op(0));
    }
    return out;
}

// `terms` (an expanded sum's) with sin^2 x + cos^2 x = 1 substituted by `rule` and each
// changed term expanded: the same sum as expand(sum.subs(rule)), but only the terms that hold
// a square of sin x or cos x are rewritten and expanded
ex substituted_in_terms(const std::vector<ex>& terms, const std::vector<bool>& holds,
                        const ex& rule) {
    exvector out;
    out.reserve(terms.size());
    for (std::size_t i = 0; i < terms.size(); ++i)
        out.push_back(holds[i] ? expand(terms[i].subs(rule, subs_options::algebraic)) : terms[i]);
    return expand(add(out));
}

ex pythagorean(const ex& e, NodeIndex& n) {
    ex best = e;
    for (const ex& x : squared_angles(e)) {
        const std::vector<ex> terms = terms_of(best);
        std::vector<bool> holds(terms.size());
        bool any = false;
        for (std::size_t i = 0; i < terms.size(); ++i) {
            for (const ex& y : squared_angles(terms[i]))
                if (y.is_equal(x)) holds[i] = any = true;
        }
        if (!any) continue;
        ex c1 = substituted_in_terms(terms, holds, pow(cos(x), 2) == 1 - pow(sin(x), 2));
        ex c2 = substituted_in_terms(terms, holds, pow(sin(x), 2) == 1 - pow(cos(x), 2));
        std::size_t nb = n.ops(best), n1 = n.ops(c1), n2 = n.ops(c2);
        if (n1 < nb && n1 <= n2) best = c1;
        else if (n2 < nb) best = c2;
    }
    return best;
}

ex fold(const ex& expanded, NodeIndex& n) {
    ex cur = expanded;
    for (int iter = 0; iter < 8; ++iter) {
        ex next = pythagorean(cur, n);
        std::vector<Term> terms;
        for (const ex& t : terms_of(next)) terms.push_back(split(t));
        bool changed = fold_angle_sums(terms, n);
        ex sum = 0;
        for (const Term& t : terms) sum += t.c * t.rest;
        next = expand(sum);
        if (!changed && next.is_equal(cur)) break;
        cur = next;
    }
    return cur;
}

}  // namespace

ex trig_simplify(const ex& e) {
    NodeIndex n;
    if (!n.facts(e).trig) return e;
    ex r = fold(expand(e), n);
    return n.ops(r) < n.ops(e) ? r : e;
}

namespace {
// one node, its children already simplified: the shortest of as-is, expanded and folded,
// and (with symbolic denominators) normalised
ex simplify_node(const ex& e, NodeIndex& index) {
    ex best = e;
    if (!is_a<add>(e) && !is_a<mul>(e) && !is_a<power>(e)) return best;
    const Facts facts = index.facts(e);
    ex x = expand(e);
    if (index.ops(x) < index.ops(best)) best = x;
    if (facts.trig) {
        ex t = fold(x, index);
        if (index.ops(t) < index.ops(best)) best = t;
    }
    if (facts.denominator) {
        ex n = normal(best);
        if (index.facts(n).trig) {
            // numerator and denominator from one call: numer() and denom() each normalise
            // anew, and GiNaC may return (a, b) from one and (-a, -b) from the other, which
            // flipped the sign of the result
            const ex nd = n.numer_denom();
            n = fold(expand(nd.op(0)), index) / fold(expand(nd.op(1)), index);
        }
        if (index.ops(n) < index.ops(best)) best = n;
    }
    return best;
}

}  // namespace

// each distinct node simplified once: a node shared in the expression's DAG (a mass-matrix
// entry in several rows, a sine in many terms) is looked up, not simplified again
struct Simplifier::Memo : map_function {
    std::unordered_map<ex, ex, std::hash<ex>, GiNaC::ex_is_equal> done;
    NodeIndex index;
    ex operator()(const ex& e) override {
        if (is_a<symbol>(e) || is_a<numeric>(e)) return e;
        auto it = done.find(e);
        if (it != done.end()) return it->second;
        ex r = simplify_node(e.map(*this), index);
        done.emplace(e, r);
        return r;
    }
};


Simplifier::Simplifier() : memo_(std::make_unique<Memo>()) {}
Simplifier::~Simplifier() = default;
Simplifier::Simplifier(Simplifier&&) noexcept = default;
Simplifier& Simplifier::operator=(Simplifier&&) noexcept = default;

ex Simplifier::operator()(const ex& e) { return (*memo_)(fold_angle_shifts(e)); }

ex Simplifier::collected(const ex& e, const std::vector<ex>& syms) {
    lst l;
    for (const ex& s : syms) l.append(s);
    ex c = collect(expand(e), l);
    // simplify each coefficient of the collected form
    if (!is_a<add>(c)) return c;
    struct Coefficients : map_function {
        Simplifier& s;
        explicit Coefficients(Simplifier& simplifier) : s(simplifier) {}
        ex operator()(const ex& f) override { return is_a<add>(f) ? s(f) : f; }
    } coefficients(*this);
    ex out = 0;
    for (std::size_t i = 0; i < c.nops(); ++i) out += c.op(i).map(coefficients);
    return out;
}

ex simplify(const ex& e) { return Simplifier()(e); }

namespace {

// k where t = k*Pi/2: Pi times a rational, or a decimal number within 1e-12 of a multiple
std::optional<long> quarter_turns(const ex& t) {
    if (!t.has(Pi)) {
        if (!is_a<numeric>(t) || !ex_to<numeric>(t).is_real() || ex_to<numeric>(t).is_rational())
            return std::nullopt;
        const double k = ex_to<numeric>(t).to_double() / (std::numbers::pi / 2);
        if (std::abs(k) > 1e6 || std::abs(k - std::round(k)) > 1e-12 * std::max(1.0, std::abs(k)))
            return std::nullopt;
        return static_cast<long>(std::round(k));
    }
    ex c = t / Pi;
    if (!is_a<numeric>(c) || !ex_to<numeric>(c).is_rational()) return std::nullopt;
    numeric k = ex_to<numeric>(c) * 2;
    if (!k.is_integer() || abs(k) > 1000000) return std::nullopt;
    return k.to_long();
}

// sin, cos or tan of x + k*Pi/2 without the shift; `e` itself if it has none
ex fold_shift(const ex& e) {
    if (!is_a<function>(e) || e.nops() != 1 || !is_a<add>(e.op(0))) return e;
    const std::string& name = ex_to<function>(e).get_name();
    if (name != "sin" && name != "cos" && name != "tan") return e;
    const ex& arg = e.op(0);
    for (std::size_t i = 0; i < arg.nops(); ++i) {
        std::optional<long> k = quarter_turns(arg.op(i));
        if (!k) continue;
        const ex x = arg - arg.op(i);
        const long r = ((*k % 4) + 4) % 4;
        if (name == "tan") {
            if (r % 2 != 0) continue;  // tan(x + Pi/2) = -1/tan(x) is no shorter
            return fold_shift(tan(x));
        }
        static const int sin_sign[4] = {1, 1, -1, -1}, cos_sign[4] = {1, -1, -1, 1};
        const bool same = r % 2 == 0;  // sin stays sin for even quarter turns
        if (name == "sin") return sin_sign[r] * fold_shift(same ? sin(x) : cos(x));
        return cos_sign[r] * fold_shift(same ? cos(x) : sin(x));
    }
    return e;
}

struct AngleShifts : map_function {
    ex operator()(const ex& e) override {
        if (is_a<symbol>(e) || is_a<numeric>(e)) return e;
        return fold_shift(e.map(*this));
    }
};

}  // namespace

ex fold_angle_shifts(const ex& e) {
    AngleShifts f;
    return f(e);
}

namespace {

// the common factor of the terms of the sum `s`: numeric content (negative when every term
// is) and each base dividing every term, at its lowest power (all positive or all negative)
ex common_factor(const ex& s) {
    std::map<ex, int, ex_is_less> common;
    numeric num = 0, den = 1;
    bool all_negative = true, first = true;
    for (std::size_t i = 0; i < s.nops(); ++i) {
        Term t = split(s.op(i));
        if (!t.c.is_rational()) return 1;
        num = gcd(num, abs(t.c.numer()));
        den = lcm(den, t.c.denom());
        if (!t.c.is_negative()) all_negative = false;
        std::map<ex, int, ex_is_less> here;
        for (const auto& [b, n] : factors(t.rest))
            if (!b.is_equal(1)) here[b] += n;
        if (first) {
            common = here;
            first = false;
            continue;
        }
        for (auto it = common.begin(); it != common.end();) {
            auto h = here.find(it->first);
            if (h == here.end() || (h->second > 0) != (it->second > 0)) {
                it = common.erase(it);
                continue;
            }
            it->second = it->second > 0 ? std::min(it->second, h->second)
                                        : std::max(it->second, h->second);
            ++it;
        }
    }
    ex f = all_negative ? -num / den : num / den;
    if (num.is_zero()) f = 1;
    for (const auto& [b, n] : common) f *= pow(b, n);
    return f;
}

ex take_common(const ex& s) {
    if (!is_a<add>(s)) return s;
    ex f = common_factor(s);
    if (f.is_equal(1) || is_a<numeric>(f)) return s;  // GiNaC spreads a number over a sum
    ex inner = 0;
    for (std::size_t i = 0; i < s.nops(); ++i) inner += s.op(i) / f;
    return f * inner;
}

struct CommonFactors : map_function {
    ex operator()(const ex& e) override {
        if (is_a<symbol>(e) || is_a<numeric>(e)) return e;
        return take_common(e.map(*this));
    }
};

}  // namespace

ex factor_common(const ex& e) {
    CommonFactors f;
    return f(e);
}

std::vector<ex> solve_level_symbols(const SymbolTable& table, const ex& e) {
    const exset present = symbols_of(e);
    std::vector<ex> out;
    for (SymbolKind k : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
        for (const ex& s : table.symbols(k))
            if (present.count(s) && table.is_solve_level(s)) out.push_back(s);
    return out;
}

// the terms of a sum gathered by the factors they share that vary in time: first by their
// functions (sin(qB)), then by the rest (qA'*qB'), each group's constant coefficient with
// its common factors out: sin(qB)*L_A*(L_B*m_C + d_B*m_B)*(2*qA'*qB' + qB'^2)
ex group_by_varying_factors(const SymbolTable& table, const ex& e) {
    if (!is_a<add>(e)) return e;
    // term = constant part * function part * other varying part
    struct Split {
        ex constant = 1, functions = 1, others = 1;
    };
    auto split_term = [&](const ex& t) {
        Split p;
        Term nt = split(t);
        p.constant = nt.c;
        for (const auto& [b, n] : factors(nt.rest)) {
            bool fixed = true;
            for (const ex& sym : symbols_of(b)) fixed = fixed && (!table.owns(sym) || table.kind(sym) == SymbolKind::constant);
            ex f = pow(b, n);
            if (fixed) p.constant *= f;
            else if (is_a<function>(b)) p.functions *= f;
            else p.others *= f;
        }
        return p;
    };
    std::map<ex, std::map<ex, ex, ex_is_less>, ex_is_less> groups;  // functions -> others -> constant
    for (std::size_t i = 0; i < e.nops(); ++i) {
        Split p = split_term(e.op(i));
        groups[p.functions][p.others] += p.constant;
    }
    ex out = 0;
    for (const auto& [functions, by_others] : groups) {
        ex inner = 0;
        for (const auto& [others, constant] : by_others) inner += factor_common(constant) * others;
        out += functions * factor_common(inner);
    }
    return count_ops(out) < count_ops(e) ? out : e;
}

namespace {

// the intermediates of a table written out where short, and equations made readable
class Readable {
public:
    Readable(const SymbolTable& table, std::size_t inline_ops) : t_(table), inline_ops_(inline_ops) {}

    // `e` with every intermediate whose written-out definition is short replaced by it
    ex write_out(const ex& e) {
        exmap m;
        for (const ex& s : symbols_of(e)) {
            if (!is_intermediate(s)) continue;
            ex r = inlined(s);
            if (!r.is_equal(s)) m[s] = r;
        }
        return m.empty() ? e : e.subs(m, subs_options::no_pattern);
    }

    ex readable(const ex& e, bool factor) {
        ex x = write_out(e);
        if (count_ops(x) > kReadableSimplifyOps || estimate_expansion_terms(x) > 20000) return x;
        x = simplify(x);
        std::vector<ex> acc = solve_level_symbols(t_, x);
        if (!acc.empty()) x = collected(x, acc, factor);
        else if (factor) x = grouped(x);
        return factor ? factor_common(x) : x;
    }

    bool is_intermediate(const ex& s) const {
        return t_.owns(s) && t_.kind(s) == SymbolKind::intermediate;
    }

private:
    ex inlined(const ex& z) {
        auto it = memo_.find(z);
        if (it != memo_.end()) return it->second;
        ex d = write_out(t_.definition(z));
        ex r = count_ops(d) <= inline_ops_ ? d : z;
        memo_.emplace(z, r);
        return r;
    }

    // sum_k c_k x_k + r with c_k and r simplified, when x is linear in the x_k; collect_in
    // (coefficients only) otherwise
    ex collected(const ex& x, const std::vector<ex>& acc, bool group) const {
        ex xe = expand(x);
        exmap zero;
        for (const ex& a : acc) zero[a] = 0;
        auto part = [&](const ex& p) { return group ? grouped(simplify(p)) : simplify(p); };
        ex out = 0;
        for (const ex& a : acc) {
            if (xe.degree(a) > 1) return collect_in(x, acc);
            ex c = xe.coeff(a, 1);
            for (const ex& b : acc)
                if (c.has(b)) return collect_in(x, acc);
            out += part(c) * a;
        }
        return out + part(xe.subs(zero, subs_options::no_pattern));
    }

    ex grouped(const ex& e) const { return group_by_varying_factors(t_, e); }

    const SymbolTable& t_;
    std::size_t inline_ops_;
    std::map<ex, ex, ex_is_less> memo_;
};

}  // namespace

ex calc_readable(const SymbolTable& table, const ex& e, bool factor, std::size_t inline_ops) {
    Readable r(table, inline_ops);
    return r.readable(e, factor);
}

ex calc_inlined_intermediates(const SymbolTable& table, const ex& e, std::size_t inline_ops) {
    Readable r(table, inline_ops);
    return r.write_out(e);
}

std::vector<std::pair<ex, ex>> calc_used_intermediates(const SymbolTable& table,
                                                       const std::vector<ex>& printed,
                                                       std::size_t inline_ops) {
    Readable r(table, inline_ops);
    std::map<ex, std::size_t, ex_is_less> position;
    const std::vector<ex>& all = table.intermediates();
    for (std::size_t i = 0; i < all.size(); ++i) position.emplace(all[i], i);
    std::map<std::size_t, std::pair<ex, ex>> used;  // by dependency order
    std::vector<ex> work;
    auto visit = [&](const ex& e) {
        for (const ex& s : symbols_of(e))
            if (r.is_intermediate(s) && !used.count(position.at(s))) {
                used.emplace(position.at(s), std::make_pair(s, ex(0)));
                work.push_back(s);
            }
    };
    for (const ex& e : printed) visit(e);
    while (!work.empty()) {
        ex z = work.back();
        work.pop_back();
        ex d = r.readable(table.definition(z), false);
        used.at(position.at(z)).second = d;
        visit(d);
    }
    std::vector<std::pair<ex, ex>> out;
    for (auto& [i, zd] : used) out.push_back(zd);
    return out;
}

ex collect_in(const ex& e, const std::vector<ex>& syms) { return Simplifier().collected(e, syms); }

double max_numeric_difference(const ex& a, const ex& b, int points) {
    // every symbol of a and of b gets a value, including those that cancel in a - b
    exset syms = symbols_of(a), sb = symbols_of(b);
    syms.insert(sb.begin(), sb.end());
    std::mt19937_64 rng(0x5eed5eedULL);
    std::uniform_real_distribution<double> mag(0.3, 1.7);
    std::bernoulli_distribution sign(0.5);
    double worst = 0;
    for (int k = 0; k < points; ++k) {
        exmap m;
        for (const ex& s : syms) m[s] = numeric(sign(rng) ? mag(rng) : -mag(rng));
        ex va = evalf(a.subs(m)), vb = evalf(b.subs(m));
        if (!is_a<numeric>(va) || !is_a<numeric>(vb)) return INFINITY;
        std::complex<double> ca(ex_to<numeric>(va).real().to_double(),
                                ex_to<numeric>(va).imag().to_double());
        std::complex<double> cb(ex_to<numeric>(vb).real().to_double(),
                                ex_to<numeric>(vb).imag().to_double());
        double diff = std::abs(ca - cb) / std::max(1.0, std::max(std::abs(ca), std::abs(cb)));
        if (!(diff <= worst)) worst = diff;  // NaN propagates as infinity below
        if (std::isnan(diff)) return INFINITY;
    }
    return worst;
}

bool equal(const ex& a, const ex& b, double tol) {
    ex d = expand(a - b);
    if (d.is_zero()) return true;
    NodeIndex n;
    if (n.facts(d).trig && fold(d, n).is_zero()) return true;
    if (n.facts(d).denominator && normal(d).is_zero()) return true;
    return max_numeric_difference(a, b) <= tol;
}

}  // namespace alembert
