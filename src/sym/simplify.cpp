// SPDX-License-Identifier: MIT
// Trigonometric simplification by term pairing, and semantic equality.
#include "alembert/sym/simplify.hpp"

#include <cmath>
#include <complex>
#include <algorithm>
#include <map>
#include <random>

#include "alembert/sym/print.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

using namespace GiNaC;

std::size_t count_ops(const ex& e) {
    if (is_a<symbol>(e)) return 0;
    if (is_a<numeric>(e)) {
        const numeric& n = ex_to<numeric>(e);
        return (n.is_negative() ? 1 : 0) + (n.is_rational() && !n.is_integer() ? 1 : 0);
    }
    std::size_t n = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) n += count_ops(e.op(i));
    if (is_a<add>(e) || is_a<mul>(e)) {
        // -x is one negation, not a product by -1 plus a negative number
        const ex& last = e.op(e.nops() - 1);
        if (is_a<mul>(e) && is_a<numeric>(last) && last.is_equal(-1)) return n + e.nops() - 2;
        return n + e.nops() - 1;
    }
    return n + 1;  // power, function, other
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
bool fold_angle_sums(std::vector<Term>& terms) {
    std::map<ex, std::size_t, ex_is_less> index;
    for (std::size_t i = 0; i < terms.size(); ++i) index.emplace(terms[i].rest, i);
    std::vector<bool> used(terms.size(), false);
    std::vector<Term> out;
    bool changed = false;
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
                ex partner = sin_cos ? base * cos(a) * sin(b) : base * sin(a) * sin(b);
                auto it = index.find(partner);
                if (it == index.end() || used[it->second] || it->second == i) continue;
                const numeric& cj = terms[it->second].c;
                // a difference of angles is written the shorter (then alphabetically first) way
                ex diff = a - b;
                numeric flip = 1;
                if (count_ops(b - a) < count_ops(diff) ||
                    (count_ops(b - a) == count_ops(diff) && to_string(b - a) < to_string(diff)))
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

ex pythagorean(const ex& e) {
    ex best = e;
    for (const ex& x : squared_angles(e)) {
        ex c1 = expand(best.subs(pow(cos(x), 2) == 1 - pow(sin(x), 2), subs_options::algebraic));
        ex c2 = expand(best.subs(pow(sin(x), 2) == 1 - pow(cos(x), 2), subs_options::algebraic));
        std::size_t nb = count_ops(best), n1 = count_ops(c1), n2 = count_ops(c2);
        if (n1 < nb && n1 <= n2) best = c1;
        else if (n2 < nb) best = c2;
    }
    return best;
}

ex fold(const ex& expanded) {
    ex cur = expanded;
    for (int iter = 0; iter < 8; ++iter) {
        ex next = pythagorean(cur);
        std::vector<Term> terms;
        for (const ex& t : terms_of(next)) terms.push_back(split(t));
        bool changed = fold_angle_sums(terms);
        ex sum = 0;
        for (const Term& t : terms) sum += t.c * t.rest;
        next = expand(sum);
        if (!changed && next.is_equal(cur)) break;
        cur = next;
    }
    return cur;
}

bool has_trig(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_trig(*it, "sin") || is_trig(*it, "cos")) return true;
    return false;
}

bool has_symbolic_denominator(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_a<power>(*it) && is_a<numeric>(it->op(1)) && ex_to<numeric>(it->op(1)) < 0)
            return true;
    return false;
}

}  // namespace

ex trig_simplify(const ex& e) {
    if (!has_trig(e)) return e;
    ex r = fold(expand(e));
    return count_ops(r) < count_ops(e) ? r : e;
}

namespace {
// one node, its children already simplified: the shortest of as-is, expanded and folded,
// and (with symbolic denominators) normalised
ex simplify_node(const ex& e) {
    ex best = e;
    if (!is_a<add>(e) && !is_a<mul>(e) && !is_a<power>(e)) return best;
    ex x = expand(e);
    if (count_ops(x) < count_ops(best)) best = x;
    if (has_trig(e)) {
        ex t = fold(x);
        if (count_ops(t) < count_ops(best)) best = t;
    }
    if (has_symbolic_denominator(e)) {
        ex n = normal(best);
        if (has_trig(n)) n = fold(expand(numer(n))) / fold(expand(denom(n)));
        if (count_ops(n) < count_ops(best)) best = n;
    }
    return best;
}

struct BottomUp : map_function {
    ex operator()(const ex& e) override {
        if (is_a<symbol>(e) || is_a<numeric>(e)) return e;
        return simplify_node(e.map(*this));
    }
};
}  // namespace

ex simplify(const ex& e) {
    BottomUp f;
    return f(e);
}

ex collect_in(const ex& e, const std::vector<ex>& syms) {
    lst l;
    for (const ex& s : syms) l.append(s);
    ex c = collect(expand(e), l);
    // simplify each coefficient of the collected form
    if (!is_a<add>(c)) return c;
    ex out = 0;
    for (std::size_t i = 0; i < c.nops(); ++i) out += c.op(i).map([](const ex& f) {
        return is_a<add>(f) ? simplify(f) : f;
    });
    return out;
}

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
    if (has_trig(d) && fold(d).is_zero()) return true;
    if (has_symbolic_denominator(d) && normal(d).is_zero()) return true;
    return max_numeric_difference(a, b) <= tol;
}

}  // namespace alembert
