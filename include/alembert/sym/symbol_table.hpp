// SPDX-License-Identifier: MIT
// The symbol table: every symbol of a model, its kind, and the chain rule that ties q, q', q''.
#pragma once

#include <ginac/ginac.h>
#include <ginac/hash_map.h>

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace alembert {

using GiNaC::ex;
using GiNaC::exmap;
// GiNaC's arithmetic, visible to argument-dependent look-up on Alembert types such as
// TimeVariable, so that qA + qB and 2*qA read as in the textbook
using GiNaC::operator+;
using GiNaC::operator-;
using GiNaC::operator*;
using GiNaC::operator/;

/// What a symbol of the table stands for.
enum class SymbolKind {
    time,          ///< the independent variable t
    constant,      ///< a parameter such as a mass or a length, optionally with a value
    variable,      ///< a time-varying coordinate or speed (q, q', q'' tied together)
    specified,     ///< a known function of time and its derivatives (a prescribed input)
    unknown,       ///< a time-free unknown to solve for (a torque or force measure)
    intermediate,  ///< a named subexpression z = definition (the "z variables")
};

/// Returns the lowercase word for a kind ("constant", "variable", ...).
const char* to_string(SymbolKind kind);

/// A time-varying quantity and its declared derivatives: q, q', q'', ... as one handle.
///
/// Converts to the symbol q itself, so `sin(qA)` reads as in the textbook; `qA.d(1)` is qA'.
class TimeVariable {
public:
    TimeVariable() = default;
    TimeVariable(std::string name, std::vector<ex> derivatives)
        : name_(std::move(name)), d_(std::move(derivatives)) {}

    /// The base name, without primes.
    const std::string& name() const { return name_; }
    /// The highest declared derivative order.
    int order() const { return static_cast<int>(d_.size()) - 1; }
    /// The k-th time derivative symbol (k = 0 is q itself).
    /// @throws alembert::ModelError if k exceeds the declared order.
    const ex& d(int k) const;
    /// q itself.
    operator const ex&() const { return d_.at(0); }  // NOLINT(google-explicit-constructor)
    /// q itself, explicitly.
    const ex& symbol() const { return d_.at(0); }

private:
    std::string name_;
    std::vector<ex> d_;
};

/// Owns every symbol of a model.
///
/// GiNaC tells symbols apart by identity, not by name, so symbols are created here once and
/// looked up by name afterwards. The table knows which symbols vary in time and their
/// derivatives, so it can take total time derivatives by the chain rule
///     d/dt f = df/dt + sum_i (df/ds_i) s_i'
/// over the time-varying symbols s_i of f, including named intermediates z = definition.
class SymbolTable {
public:
    SymbolTable();
    SymbolTable(const SymbolTable&) = delete;
    SymbolTable& operator=(const SymbolTable&) = delete;
    SymbolTable(SymbolTable&&) = default;
    SymbolTable& operator=(SymbolTable&&) = default;

    // ---- declaration ---------------------------------------------------------------------
    /// The independent variable t.
    const ex& time() const { return t_; }
    /// Declares a constant, optionally with a numeric value (SI units). A `positive` one is
    /// known to GiNaC to be greater than 0 (a possymbol), so sqrt(L^2) is L and |L| is L.
    /// @throws alembert::ArgumentError if the name is not an identifier or a positive
    ///         constant's value is not greater than 0, alembert::ModelError if it is declared
    ///         already.
    ex add_constant(const std::string& name, std::optional<double> value = std::nullopt,
                    bool positive = false);
    /// Declares a time-varying variable and its derivatives up to `order` (q, q', ..., q^(order)).
    TimeVariable add_variable(const std::string& name, int order = 2);
    /// Declares a specified (prescribed, known) function of time and its derivatives.
    TimeVariable add_specified(const std::string& name, int order = 2);
    /// Declares an unknown to solve for (a torque or force measure); it has no time derivative.
    ex add_unknown(const std::string& name);
    /// Names the subexpression `definition` as an intermediate; the name defaults to z1, z2, ...
    /// The definition may use earlier intermediates only (they are created in dependency order).
    ex add_intermediate(const ex& definition, const std::string& name = "");

    /// The intermediate whose definition is `definition`, named z1, z2, ... the first time and
    /// the same symbol afterwards, so formation steps that meet a subexpression again share it.
    ex name_subexpression(const ex& definition);

    /// Sets (or replaces) the value of a constant.
    void set_value(const ex& constant, double value);

    // ---- look-up -------------------------------------------------------------------------
    /// True if a symbol with this printed name (e.g. "qA'") exists.
    bool contains(const std::string& name) const { return by_name_.count(name) != 0; }
    /// The symbol of this printed name.
    /// @throws alembert::ModelError naming the symbol and the declared ones if absent.
    const ex& symbol(const std::string& name) const;
    /// The time variable (or specified) with this base name.
    /// @throws alembert::ModelError if absent.
    TimeVariable variable(const std::string& name) const;
    /// True if `s` is a symbol created by this table.
    bool owns(const ex& s) const { return info_.count(s) != 0; }
    /// The kind of a symbol of this table.
    SymbolKind kind(const ex& s) const;
    /// The printed name of a symbol of this table.
    const std::string& name(const ex& s) const;
    /// The derivative order of a time-varying symbol (q: 0, q': 1, ...), 0 for the others.
    int derivative_order(const ex& s) const;
    /// The base symbol q of a derivative symbol q^(k) (itself for non time-varying symbols).
    const ex& base(const ex& s) const;
    /// The value of a constant, if one was given.
    std::optional<double> value(const ex& s) const;
    /// The definition of an intermediate.
    const ex& definition(const ex& z) const;
    /// Symbols of one kind in declaration order.
    std::vector<ex> symbols(SymbolKind kind) const;
    /// Intermediates in dependency order.
    const std::vector<ex>& intermediates() const { return intermediates_; }

    // ---- calculus ------------------------------------------------------------------------
    /// Total time derivative of `e` by the chain rule over the table.
    ///
    /// The derivative of an intermediate z is itself named as an intermediate z' when it is not
    /// zero, so derivatives stay as compact as their definitions; where z' holds solve-level
    /// symbols (z a velocity measure, z' holding q''), z' = r + sum_k c_k x_k is kept as that
    /// sum with r named z' and the coefficients named where large, so q'' stays explicit.
    /// This is the only reason dt is not const.
    /// @throws alembert::ModelError if a derivative beyond the declared order is needed or `e`
    ///         holds an unknown (which has no time derivative).
    ex dt(const ex& e);
    /// Partial derivative de/ds with respect to a symbol of the table, differentiating through
    /// intermediates (de/ds = del e/del s + sum_z del e/del z dz/ds). The partial derivative
    /// dz/ds of each intermediate is taken once and, when it is not small, named as an
    /// intermediate itself, so a chain of intermediates (velocities formed body by body)
    /// differentiates in time linear in its length instead of exponential. This is the only
    /// reason diff is not const.
    ex diff(const ex& e, const ex& s);
    /// `e` itself when it is small (at most `min_ops` operations); otherwise `e` with its bulk
    /// named as intermediates (shared with earlier equal definitions). Symbols that equations
    /// are later solved for stay explicit, never hidden inside an intermediate: the highest
    /// declared derivatives of variables and specified quantities (q'' of a q declared to order
    /// 2) and unknowns. An `e` linear in those, sum_k c_k x_k + r, becomes the same sum with
    /// the coefficients c_k and the rest r named where large; an `e` not linear in them is
    /// returned unchanged.
    ex name_if_large(const ex& e, std::size_t min_ops);
    /// Splits `e` into sum_x c_x x + rest over the solve-level symbols x (is_solve_level)
    /// through the intermediates: an intermediate that holds them is split once, its
    /// coefficients and rest named where large and remembered, so the coefficients of a sum of
    /// accumulated intermediates (each a few terms on the previous one) cost one pass over the
    /// new terms, not a derivative per symbol over every term below. `coeffs` and `rest` are
    /// added to; the c_x and rest are free of solve-level symbols. False (and the outputs left
    /// partial) when `e` or an intermediate it reaches is not visibly linear in them.
    bool calc_linear_form(const ex& e, std::map<ex, ex, GiNaC::ex_is_less>& coeffs, ex& rest);
    /// True if `s` is a symbol equations are solved for: an unknown, the highest declared
    /// derivative of a variable or specified quantity, or an intermediate that depends on one.
    bool is_solve_level(const ex& s) const;
    /// True if `e` depends on `s`, directly or through intermediates.
    bool depends_on(const ex& e, const ex& s) const;
    /// The symbols `e` depends on, looking through intermediates to their definitions: every
    /// constant, variable, specified, unknown and t it holds, but no intermediate. Each
    /// intermediate's leaves are read from what was gathered when it was made: linear in the
    /// size of `e` and of the leaf sets.
    GiNaC::exset calc_leaf_symbols(const ex& e) const;
    /// `e` with every intermediate replaced by its definition (recursively).
    ex expand_intermediates(const ex& e) const;

    // ---- numbers -------------------------------------------------------------------------
    /// Map from each constant that has a value to that value.
    exmap constant_values() const;
    /// Numeric value of `e` given values for its non-constant symbols; intermediates are
    /// evaluated from their definitions.
    /// @throws alembert::ArgumentError naming the first symbol left without a value.
    double evaluate(const ex& e, const exmap& values = {}) const;
    /// What evaluate() builds for one set of values, kept for the next expression at the same
    /// values: the map of the constants and the values, and each intermediate's value once
    /// found. Valid while the table's constants keep their values.
    class EvaluationMemo {
    public:
        explicit EvaluationMemo(exmap values) : values_(std::move(values)) {}

    private:
        friend class SymbolTable;
        exmap values_;
        exmap m_;                            // constants, values, intermediates found
        GiNaC::exhashmap<double> at_, memo_;  // the same in doubles, for the pole guard
        bool ready_ = false;
    };
    /// evaluate(e, values) with the values and what was found for earlier expressions at
    /// them in `memo`: each intermediate is evaluated once over all the expressions.
    double evaluate(const ex& e, EvaluationMemo& memo) const;

private:
    struct Info {
        SymbolKind kind = SymbolKind::constant;
        std::string name{};
        ex base{};  // q for q^(k)
        int order = 0;  // k
        ex next{};  // q^(k+1), or 0
        std::optional<double> value{};
        ex definition{};        // intermediates
        GiNaC::exset leaves{};  // intermediates: the non-intermediate symbols they depend on
        std::size_t index = 0;
    };

    ex make_symbol(const std::string& name, Info info, bool positive = false);
    ex make_intermediate(const ex& definition, const std::string& name);
    TimeVariable add_time_varying(const std::string& name, int order, SymbolKind kind);
    void check_new_name(const std::string& name) const;
    std::string unique_name(const std::string& name) const;
    ex diff_intermediate(const ex& z, const ex& s);
    ex name_derivative(const ex& d, const std::string& name);
    ex name_parts(const ex& e, std::size_t min_ops, const std::string& rest_name);
    bool collect_linear(const ex& e, const ex& factor, std::map<ex, ex, GiNaC::ex_is_less>& coeffs,
                        ex& rest) const;
    struct LinearForm {
        std::map<ex, ex, GiNaC::ex_is_less> coeffs;
        ex rest;
    };
    bool collect_linear_through(const ex& e, const ex& factor,
                                std::map<ex, ex, GiNaC::ex_is_less>& coeffs, ex& rest,
                                ex* unsplit = nullptr);
    const LinearForm* linear_form_of(const ex& z);
    const Info& info(const ex& s, const char* caller) const;
    const ex& expanded_definition(const ex& z) const;

    ex t_;
    std::map<ex, Info, GiNaC::ex_is_less> info_;
    std::unordered_map<std::string, ex> by_name_;
    std::vector<ex> order_;          // every symbol in declaration order
    std::array<std::vector<ex>, 6> by_kind_{};  // the same, one list per SymbolKind
    std::vector<ex> intermediates_;  // dependency order
    std::map<ex, ex, GiNaC::ex_is_less> z_dt_;
    std::map<ex, std::map<ex, ex, GiNaC::ex_is_less>, GiNaC::ex_is_less> z_diff_;  // dz/ds
    std::map<ex, ex, GiNaC::ex_is_less> z_by_definition_;
    std::map<ex, std::optional<LinearForm>, GiNaC::ex_is_less> z_linear_;  // calc_linear_form
    mutable std::map<ex, ex, GiNaC::ex_is_less> z_expanded_;
    std::size_t next_z_ = 1;
};

/// Every symbol occurring in `e` (intermediates as themselves), in GiNaC's canonical order.
GiNaC::exset symbols_of(const ex& e);

}  // namespace alembert
