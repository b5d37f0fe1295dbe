// SPDX-License-Identifier: MIT
// Partial derivatives by one symbol, each shared sub-expression differentiated once.
#include "alembert/sym/derivative.hpp"

namespace alembert {

DerivativeMemo::DerivativeMemo(const GiNaC::symbol& s) : s_(s) {}

ex DerivativeMemo::operator()(const ex& e) {
    // leaves need no memo
    if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) return 0;
    if (GiNaC::is_a<GiNaC::symbol>(e)) return e.is_equal(s_) ? ex(1) : ex(0);
    const GiNaC::basic* key = &GiNaC::ex_to<GiNaC::basic>(e);
    if (auto it = memo_.find(key); it != memo_.end()) return it->second.value;
    ex d = derivative_of(e);
    memo_.emplace(key, Entry{e, d});
    return d;
}

namespace {

// The pairs of a sum or product as GiNaC stores them (its `seq` and `overall_coeff`, which
// it does not expose): a pointer to the protected members named through a derived class.
struct PairsOf : GiNaC::expairseq {
    static const GiNaC::epvector& pairs(const GiNaC::expairseq& e) { return e.*(&PairsOf::seq); }
    static const GiNaC::numeric& overall(const GiNaC::expairseq& e) {
        return GiNaC::ex_to<GiNaC::numeric>(e.*(&PairsOf::overall_coeff));
    }
};

// A factor as a pair basis^exponent (mul::split_ex_to_pair)
GiNaC::expair factor_pair(const ex& f) {
    if (GiNaC::is_exactly_a<GiNaC::power>(f) && GiNaC::is_exactly_a<GiNaC::numeric>(f.op(1)))
        return GiNaC::expair(f.op(0), f.op(1));
    return GiNaC::expair(f, ex(1));
}

}  // namespace

// One node, as GiNaC's add::derivative, mul::derivative, power::derivative and
// function::derivative form it, the children's derivatives taken from the memo.
ex DerivativeMemo::derivative_of(const ex& e) {
    if (GiNaC::is_exactly_a<GiNaC::add>(e)) {
        // D(c0 + c1 a1 + c2 a2 + ...) = c1 D(a1) + c2 D(a2) + ...
        const GiNaC::epvector& seq = PairsOf::pairs(GiNaC::ex_to<GiNaC::add>(e));
        GiNaC::epvector terms;
        terms.reserve(seq.size());
        bool free = true;
        for (const GiNaC::expair& p : seq) {
            ex d = (*this)(p.rest);
            if (!d.is_zero()) free = false;
            terms.emplace_back(d, p.coeff);
        }
        if (free) return 0;
        return GiNaC::dynallocate<GiNaC::add>(std::move(terms), ex(0));
    }
    if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        // D(a*b*c) = D(a)*b*c + a*D(b)*c + a*b*D(c), each factor a pair basis^exponent
        const auto& m = GiNaC::ex_to<GiNaC::mul>(e);
        const GiNaC::epvector& seq = PairsOf::pairs(m);
        const GiNaC::numeric& overall = PairsOf::overall(m);
        GiNaC::exvector terms;
        GiNaC::epvector with = seq;
        for (std::size_t i = 0; i < seq.size(); ++i) {
            const ex d = (*this)(seq[i].rest);
            if (d.is_zero()) continue;  // GiNaC's term is 0
            GiNaC::expair p = factor_pair(GiNaC::pow(seq[i].rest, seq[i].coeff - ex(1)) * d);
            p.swap(with[i]);
            terms.push_back(GiNaC::dynallocate<GiNaC::mul>(
                with, overall.mul(GiNaC::ex_to<GiNaC::numeric>(seq[i].coeff))));
            p.swap(with[i]);
        }
        if (terms.empty()) return 0;
        return GiNaC::dynallocate<GiNaC::add>(terms);
    }
    if (GiNaC::is_exactly_a<GiNaC::power>(e) && GiNaC::is_exactly_a<GiNaC::numeric>(e.op(1))) {
        // D(b^r) = r b^(r-1) D(b)
        const ex d = (*this)(e.op(0));
        if (d.is_zero()) return 0;
        const ex& r = e.op(1);
        const GiNaC::epvector factors = {GiNaC::expair(e.op(0), r - ex(1)),
                                         GiNaC::expair(d, ex(1))};
        return GiNaC::dynallocate<GiNaC::mul>(factors, r);
    }
    if (GiNaC::is_exactly_a<GiNaC::function>(e)) {
        // the chain rule: sum_i (d f/d x_i) D(x_i) over the arguments that hold s
        bool free = true;
        for (std::size_t i = 0; i < e.nops() && free; ++i)
            if (!(*this)(e.op(i)).is_zero()) free = false;
        if (free) return 0;
        const unsigned serial = GiNaC::ex_to<GiNaC::function>(e).get_serial();
        // sin' = cos and cos' = -sin, as GiNaC's sin_deriv and cos_deriv give them
        if (serial == GiNaC::sin_SERIAL::serial) return GiNaC::cos(e.op(0)) * (*this)(e.op(0));
        if (serial == GiNaC::cos_SERIAL::serial) return -GiNaC::sin(e.op(0)) * (*this)(e.op(0));
        return e.diff(GiNaC::ex_to<GiNaC::symbol>(s_));
    }
    return e.diff(GiNaC::ex_to<GiNaC::symbol>(s_));
}

ex calc_derivative(const ex& e, const GiNaC::symbol& s) { return DerivativeMemo(s)(e); }

}  // namespace alembert
