// SPDX-License-Identifier: MIT
// Zero tests at random states, through named intermediates.
#include "alembert/eom/zero_test.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/vec/frame.hpp"

namespace alembert {

namespace {

// the symbols e depends on, through intermediates, other than constants with a value
std::vector<ex> zero_test_leaves(const SymbolTable& st, const ex& e) {
    std::vector<ex> out;
    for (const ex& s : st.calc_leaf_symbols(e))
        if (!(st.owns(s) && st.kind(s) == SymbolKind::constant && st.value(s))) out.push_back(s);
    return out;
}

bool all_zero(const SymbolTable& st, const std::vector<ex>& es) {
    std::vector<ex> outputs;
    std::vector<ex> inputs;
    {
        GiNaC::exset all;
        for (const ex& e : es) {
            if (e.is_zero()) continue;
            // the terms of a sum, so that cancellation is measured against their size
            if (GiNaC::is_a<GiNaC::add>(e))
                for (std::size_t i = 0; i < e.nops(); ++i) outputs.push_back(e.op(i));
            else
                outputs.push_back(e);
            outputs.push_back(e);
            for (const ex& s : zero_test_leaves(st, e)) all.insert(s);
        }
        inputs.assign(all.begin(), all.end());
    }
    if (outputs.empty()) return true;
    try {
        CompiledExpressions f(st, inputs, outputs);
        std::mt19937 rng(20261124);
        std::uniform_real_distribution<double> mag(0.3, 1.7);
        std::bernoulli_distribution negative(0.5);
        std::vector<long double> in(inputs.size()), out(outputs.size());
        for (int k = 0; k < 2; ++k) {
            for (long double& x : in) x = (negative(rng) ? -1 : 1) * mag(rng);
            f.evaluate_extended(in.data(), out.data());
            // walk the outputs: the terms of each expression, then the expression itself
            std::size_t o = 0;
            for (const ex& e : es) {
                if (e.is_zero()) continue;
                long double scale = 1;
                const std::size_t terms = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
                for (std::size_t i = 0; i < terms; ++i) scale = std::max(scale, std::abs(out[o++]));
                const long double v = out[o++];
                if (!std::isfinite(static_cast<double>(v)) ||
                    !std::isfinite(static_cast<double>(scale)))
                    throw std::domain_error("not finite");
                if (std::abs(v) > 1e-11L * scale) return false;
            }
        }
        return true;
    } catch (const std::exception&) {
        // not evaluable at the drawn states: decide symbolically when that is quick, else
        // say "not zero" (the callers then keep a term or a note they could have dropped)
        constexpr std::size_t kMaxSymbolicOps = 2000;
        return std::all_of(es.begin(), es.end(), [&](const ex& e) {
            ex full = st.expand_intermediates(e);
            return count_ops(full) <= kMaxSymbolicOps && simplify(full).is_zero();
        });
    }
}

}  // namespace

bool is_zero_at_random_states(const SymbolTable& st, const ex& e) { return all_zero(st, {e}); }

std::vector<bool> calc_changes_with_at_random_states(const SymbolTable& st, const ex& e,
                                                     const std::vector<ex>& symbols) {
    std::vector<bool> out(symbols.size(), false);
    if (symbols.empty() || e.is_zero()) return out;
    const GiNaC::exset present = symbols_of(e);
    std::vector<ex> inputs;
    {
        GiNaC::exset all;
        for (const ex& s : zero_test_leaves(st, e)) all.insert(s);
        inputs.assign(all.begin(), all.end());
    }
    std::vector<std::size_t> slot(symbols.size(), inputs.size());
    for (std::size_t k = 0; k < symbols.size(); ++k)
        for (std::size_t j = 0; j < inputs.size(); ++j)
            if (inputs[j].is_equal(symbols[k])) slot[k] = j;
    // the terms of a sum, so that a change is measured against their size, then e
    std::vector<ex> outputs;
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) outputs.push_back(e.op(i));
    outputs.push_back(e);
    auto by_derivative = [&](std::size_t k) {
        return !is_zero_at_random_states(st, e.diff(GiNaC::ex_to<GiNaC::symbol>(symbols[k])));
    };
    try {
        CompiledExpressions f(st, inputs, outputs);
        std::mt19937 rng(20261127);
        std::uniform_real_distribution<double> mag(0.3, 1.7);
        std::bernoulli_distribution negative(0.5);
        std::vector<long double> in(inputs.size()), base(outputs.size()), bumped(outputs.size());
        auto scale_of = [&](const std::vector<long double>& v) {
            long double m = 1;
            for (long double x : v) m = std::max(m, std::abs(x));
            return m;
        };
        for (int state = 0; state < 2; ++state) {
            for (long double& x : in) x = (negative(rng) ? -1 : 1) * mag(rng);
            f.evaluate_extended(in.data(), base.data());
            for (std::size_t k = 0; k < symbols.size(); ++k) {
                if (out[k] || slot[k] == inputs.size()) continue;
                const long double keep = in[slot[k]];
                in[slot[k]] = keep + 1;
                f.evaluate_extended(in.data(), bumped.data());
                in[slot[k]] = keep;
                const long double scale = std::max(scale_of(base), scale_of(bumped));
                const long double change = std::abs(bumped.back() - base.back());
                if (!std::isfinite(static_cast<double>(change)) ||
                    !std::isfinite(static_cast<double>(scale)))
                    throw std::domain_error("not finite");
                if (change > 1e-11L * scale) out[k] = true;
            }
        }
    } catch (const std::exception&) {
        // not evaluable at the drawn states: one symbol at a time, by its derivative where e
        // holds it directly, else (inside an intermediate) taken to change e
        for (std::size_t k = 0; k < symbols.size(); ++k)
            out[k] = slot[k] != inputs.size() && (!present.count(symbols[k]) || by_derivative(k));
    }
    return out;
}

bool is_zero_at_random_states(const SymbolTable& st, const Vector& v, const Frame& F) {
    Col3 c = v.components_in(F);
    return all_zero(st, {c[0], c[1], c[2]});
}

}  // namespace alembert
