// SPDX-License-Identifier: MIT
// Zero tests at random states, through named intermediates.
#include "alembert/eom/zero_test.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
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

// ---- values at the random states, intermediates remembered across tests ---------------------
//
// Every zero test of one model reaches the same kinematics (a chain's rows all hold the
// rotations of its links); compiling each tested expression with the intermediates it reaches
// made a road-map's zero tests grow as n^3. Here each intermediate's values at the two states
// are computed once and remembered (by its symbol, unique in the process), and a test walks
// only its own expression. A leaf's value depends on its name and the state alone; a constant
// with a value keeps it (the remembered values are dropped when the table's constant values
// change).

constexpr int kStates = 2;

long double leaf_value(const std::string& name, int state) {
    std::uint64_t h = 1469598103934665603ULL ^ static_cast<std::uint64_t>(state + 1);
    for (unsigned char c : name) h = (h ^ c) * 1099511628211ULL;
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 32;
    const long double u = static_cast<long double>(h >> 11) / static_cast<long double>(1ULL << 53);
    const long double mag = 0.3L + 1.4L * u;
    return (h & 1) ? -mag : mag;
}

struct RememberedValues {
    std::uint64_t constants = 0;  // fingerprint of the constant values they were computed with
    std::unordered_map<ex, std::array<long double, kStates>, std::hash<ex>, GiNaC::ex_is_equal>
        intermediates;
};

RememberedValues& remembered() {
    static thread_local RememberedValues r;
    return r;
}

std::uint64_t constants_fingerprint(const SymbolTable& st) {
    std::uint64_t h = 1469598103934665603ULL;
    for (const ex& c : st.symbols(SymbolKind::constant)) {
        const std::optional<double> v = st.value(c);
        std::uint64_t bits = 0;
        if (v) std::memcpy(&bits, &*v, sizeof bits);
        h = (h ^ (std::hash<ex>()(c) + (v ? bits : 0x9e3779b97f4a7c15ULL))) * 1099511628211ULL;
    }
    return h;
}

// the remembered values, forgotten when `st`'s constant values differ from those they were
// computed with
RememberedValues& remembered_for(const SymbolTable& st) {
    RememberedValues& r = remembered();
    const std::uint64_t fp = constants_fingerprint(st);
    if (r.constants != fp) {
        r.intermediates.clear();
        r.constants = fp;
    }
    return r;
}

}  // namespace

// the values at one state (a named namespace: MeasuresAtRandomStates keeps some)
namespace zero_test_detail {

class StateValues {
public:
    StateValues(const SymbolTable& st, int state) : st_(st), state_(state) {}

    /// The value with `moved` (a symbol) moved by 1; intermediates that depend on it are
    /// computed afresh, not remembered
    void move(const ex& moved) { moved_ = moved; }

    long double at(const ex& e) {
        using namespace GiNaC;
        if (is_a<numeric>(e)) {
            const numeric& n = ex_to<numeric>(e);
            if (!n.is_real()) throw std::domain_error("complex");
            return n.to_double();
        }
        if (is_a<symbol>(e)) return symbol_value(e);
        const basic* key = &ex_to<basic>(e);
        auto it = memo_.find(key);
        if (it != memo_.end()) return it->second;
        long double v = 0;
        if (is_a<add>(e)) {
            for (std::size_t i = 0; i < e.nops(); ++i) v += at(e.op(i));
        } else if (is_a<mul>(e)) {
            v = 1;
            for (std::size_t i = 0; i < e.nops(); ++i) v *= at(e.op(i));
        } else if (is_a<power>(e)) {
            const long double b = at(e.op(0)), x = at(e.op(1));
            v = x == 0.5L ? std::sqrt(b) : std::pow(b, x);
        } else if (is_a<function>(e)) {
            v = function_value(ex_to<function>(e).get_name(), e);
        } else {
            throw std::domain_error("not arithmetic");
        }
        keep_.push_back(e);  // the address stays this node's while it is remembered
        memo_.emplace(key, v);
        return v;
    }

private:
    long double symbol_value(const ex& s) {
        if (!moved_.is_zero() && s.is_equal(moved_)) return base_value(s) + 1;
        return base_value(s);
    }

    long double base_value(const ex& s) {
        if (!st_.owns(s)) return leaf_value(GiNaC::ex_to<GiNaC::symbol>(s).get_name(), state_);
        switch (st_.kind(s)) {
            case SymbolKind::intermediate: return intermediate_value(s);
            case SymbolKind::constant:
                if (std::optional<double> v = st_.value(s)) return *v;
                break;
            default: break;
        }
        return leaf_value(GiNaC::ex_to<GiNaC::symbol>(s).get_name(), state_);
    }

    long double intermediate_value(const ex& z) {
        const bool fresh = !moved_.is_zero() && st_.depends_on(z, moved_);
        RememberedValues& r = remembered();
        if (fresh) {
            auto it = fresh_->find(z);
            if (it != fresh_->end()) return it->second;
        } else {
            auto it = r.intermediates.find(z);
            if (it != r.intermediates.end() && !std::isnan(it->second[state_]))
                return it->second[state_];
        }
        // a definition is evaluated with a memory of its own nodes (they are not this
        // expression's); its intermediates are remembered in turn, those that move with the
        // moved symbol for this evaluation only
        StateValues inner(st_, state_);
        inner.moved_ = fresh ? moved_ : ex(0);
        inner.fresh_ = fresh_;
        const long double v = inner.at(st_.definition(z));
        if (fresh) {
            fresh_->emplace(z, v);
        } else {
            auto [it, added] = r.intermediates.try_emplace(z);
            if (added) it->second.fill(std::numeric_limits<long double>::quiet_NaN());
            it->second[state_] = v;
        }
        return v;
    }

    long double function_value(const std::string& f, const ex& e) {
        const long double a = at(e.op(0));
        if (f == "sin") return std::sin(a);
        if (f == "cos") return std::cos(a);
        if (f == "tan") return std::tan(a);
        if (f == "exp") return std::exp(a);
        if (f == "log") return std::log(a);
        if (f == "abs") return std::fabs(a);
        if (f == "asin") return std::asin(a);
        if (f == "acos") return std::acos(a);
        if (f == "atan") return std::atan(a);
        if (f == "atan2") return std::atan2(a, at(e.op(1)));
        if (f == "sinh") return std::sinh(a);
        if (f == "cosh") return std::cosh(a);
        if (f == "tanh") return std::tanh(a);
        throw std::domain_error("function " + f);
    }

    const SymbolTable& st_;
    int state_;
    ex moved_ = 0;
    // the values of intermediates that move with moved_, shared with the inner evaluations
    using Values = std::unordered_map<ex, long double, std::hash<ex>, GiNaC::ex_is_equal>;
    std::shared_ptr<Values> fresh_ = std::make_shared<Values>();
    std::unordered_map<const GiNaC::basic*, long double> memo_;
    std::vector<ex> keep_;
};

}  // namespace zero_test_detail

namespace {

using zero_test_detail::StateValues;

// the same test through a compiled tape, for expressions the walk above cannot evaluate; it
// falls back in turn to a symbolic test
bool all_zero_compiled(const SymbolTable& st, const std::vector<ex>& es);

bool all_zero(const SymbolTable& st, const std::vector<ex>& es) {
    remembered_for(st);
    try {
        for (int state = 0; state < kStates; ++state) {
            StateValues values(st, state);
            for (const ex& e : es) {
                if (e.is_zero()) continue;
                long double scale = 1;
                if (GiNaC::is_a<GiNaC::add>(e))
                    for (std::size_t i = 0; i < e.nops(); ++i)
                        scale = std::max(scale, std::abs(values.at(e.op(i))));
                else
                    scale = std::max(scale, std::abs(values.at(e)));
                const long double v = values.at(e);
                if (!std::isfinite(static_cast<double>(v)) ||
                    !std::isfinite(static_cast<double>(scale)))
                    throw std::domain_error("not finite");
                if (std::abs(v) > 1e-11L * scale) return false;
            }
        }
        return true;
    } catch (const std::exception&) {
        return all_zero_compiled(st, es);
    }
}

bool all_zero_compiled(const SymbolTable& st, const std::vector<ex>& es) {
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
    // the remembered intermediates' values first (all_zero's fast path); then compiled
    try {
        remembered_for(st);
        std::vector<bool> fast(symbols.size(), false);
        auto measured = [&](StateValues& v, long double* value) {
            long double scale = 1;
            for (const ex& o : outputs) scale = std::max(scale, std::abs(v.at(o)));
            *value = v.at(e);
            if (!std::isfinite(static_cast<double>(*value)) ||
                !std::isfinite(static_cast<double>(scale)))
                throw std::domain_error("not finite");
            return scale;
        };
        for (int state = 0; state < kStates; ++state) {
            StateValues base(st, state);
            long double v0 = 0;
            const long double s0 = measured(base, &v0);
            for (std::size_t k = 0; k < symbols.size(); ++k) {
                if (fast[k] || slot[k] == inputs.size()) continue;
                StateValues moved(st, state);
                moved.move(symbols[k]);
                long double v1 = 0;
                const long double s1 = measured(moved, &v1);
                if (std::abs(v1 - v0) > 1e-11L * std::max(s0, s1)) fast[k] = true;
            }
        }
        return fast;
    } catch (const std::exception&) {
        // the compiled path below
    }
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

bool calc_changes_with_others_zero_at_random_states(const SymbolTable& st, const ex& e,
                                                    const ex& x, const std::vector<ex>& zeroed) {
    if (e.is_zero()) return false;
    std::vector<ex> inputs;
    {
        GiNaC::exset all;
        for (const ex& s : zero_test_leaves(st, e)) all.insert(s);
        inputs.assign(all.begin(), all.end());
    }
    const auto slot = std::find_if(inputs.begin(), inputs.end(), [&](const ex& s) { return s.is_equal(x); });
    if (slot == inputs.end()) return false;
    std::vector<bool> held_zero(inputs.size(), false);
    for (std::size_t j = 0; j < inputs.size(); ++j)
        held_zero[j] = std::any_of(zeroed.begin(), zeroed.end(), [&](const ex& z) { return z.is_equal(inputs[j]); });
    // the terms of a sum, so that a change is measured against their size, then e
    std::vector<ex> outputs;
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) outputs.push_back(e.op(i));
    outputs.push_back(e);
    try {
        CompiledExpressions f(st, inputs, outputs);
        std::mt19937 rng(20261128);
        std::uniform_real_distribution<double> mag(0.3, 1.7);
        std::bernoulli_distribution negative(0.5);
        std::vector<long double> in(inputs.size()), base(outputs.size()), moved(outputs.size());
        const auto k = static_cast<std::size_t>(slot - inputs.begin());
        for (int state = 0; state < kStates; ++state) {
            for (std::size_t j = 0; j < in.size(); ++j)
                in[j] = held_zero[j] ? 0.0L : (negative(rng) ? -1 : 1) * mag(rng);
            f.evaluate_extended(in.data(), base.data());
            in[k] += 1;
            f.evaluate_extended(in.data(), moved.data());
            long double scale = 1;
            for (std::size_t o = 0; o < outputs.size(); ++o)
                scale = std::max({scale, std::abs(base[o]), std::abs(moved[o])});
            const long double change = std::abs(moved.back() - base.back());
            if (!std::isfinite(static_cast<double>(change)) || !std::isfinite(static_cast<double>(scale)))
                return false;
            if (change > 1e-11L * scale) return true;
        }
    } catch (const std::exception&) {
        // not evaluable there: taken not to change (callers then prefer other rows)
    }
    return false;
}

bool is_zero_at_random_states(const SymbolTable& st, const Vector& v, const Frame& F) {
    Col3 c = v.components_in(F);
    return all_zero(st, {c[0], c[1], c[2]});
}

using zero_test_detail::StateValues;

struct MeasuresAtRandomStates::Impl {
    explicit Impl(const SymbolTable& table)
        : st(table), base{StateValues(table, 0), StateValues(table, 1)} {}
    const SymbolTable& st;
    std::array<StateValues, kStates> base;
    ex moved = 0;
    std::vector<StateValues> at_moved;  // for `moved`, one per state

    long double value(StateValues& v, const ex& e) {
        const long double x = v.at(e);
        if (!std::isfinite(static_cast<double>(x))) throw std::domain_error("not finite");
        return x;
    }
    StateValues& moved_state(const ex& s, int state) {
        if (at_moved.empty() || !moved.is_equal(s)) {
            at_moved.clear();
            for (int k = 0; k < kStates; ++k) {
                at_moved.emplace_back(st, k);
                at_moved.back().move(s);
            }
            moved = s;
        }
        return at_moved[static_cast<std::size_t>(state)];
    }
};

static_assert(MeasuresAtRandomStates::kStates == kStates);

MeasuresAtRandomStates::MeasuresAtRandomStates(const SymbolTable& st)
    : impl_(std::make_unique<Impl>(st)) {
    remembered_for(st);
}

MeasuresAtRandomStates::~MeasuresAtRandomStates() = default;

MeasuresAtRandomStates::Values MeasuresAtRandomStates::calc_values(const Col3& c) {
    Values out{};
    for (int k = 0; k < kStates; ++k)
        for (int i = 0; i < 3; ++i)
            out[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)] =
                impl_->value(impl_->base[static_cast<std::size_t>(k)], c[i]);
    return out;
}

MeasuresAtRandomStates::Values MeasuresAtRandomStates::calc_changes(const Col3& c, const ex& moved) {
    Values out = calc_values(c);
    for (int k = 0; k < kStates; ++k)
        for (int i = 0; i < 3; ++i) {
            long double& x = out[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)];
            x = impl_->value(impl_->moved_state(moved, k), c[i]) - x;
        }
    return out;
}

bool MeasuresAtRandomStates::calc_changes_with(const Col3& c, const ex& moved) {
    const Values before = calc_values(c);
    const Values change = calc_changes(c, moved);
    for (std::size_t k = 0; k < kStates; ++k)
        for (std::size_t i = 0; i < 3; ++i) {
            const long double scale =
                std::max({1.0L, std::abs(before[k][i]), std::abs(before[k][i] + change[k][i])});
            if (std::abs(change[k][i]) > 1e-11L * scale) return true;
        }
    return false;
}

bool MeasuresAtRandomStates::agree(const Values& a, const Values& b) {
    for (std::size_t k = 0; k < kStates; ++k)
        for (std::size_t i = 0; i < 3; ++i) {
            const long double scale = std::max({1.0L, std::abs(a[k][i]), std::abs(b[k][i])});
            if (std::abs(a[k][i] - b[k][i]) > 1e-11L * scale) return false;
        }
    return true;
}

}  // namespace alembert
