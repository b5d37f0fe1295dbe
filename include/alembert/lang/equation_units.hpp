// SPDX-License-Identifier: MIT
// Checking an equation's units term by term from the units a script declares.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "alembert/lang/units.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert::lang {

/// Checks that every term of an equation has one dimension. Leaves (constants, variables and
/// their rates, unknowns, t) take the dimension `of_symbol` gives (Dimension::open() for one
/// declared without a unit); intermediates the dimension of their definition, worked out once
/// for every equation checked; sin, cos and the other functions are numbers. A sum inside a
/// term whose terms differ is reported as well. A term holding a leaf without a unit is not
/// checked, even where a sum lends it its other terms' dimension.
class EquationUnitChecker {
public:
    EquationUnitChecker(const SymbolTable& st, std::function<Dimension(const ex&)> of_symbol)
        : st_(st), of_symbol_(std::move(of_symbol)) {}

    /// The check of 0 = `equation`, whose terms must each be `expected` (Dimension::open():
    /// the same as one another, as in a constraint row). Consistent only if every term's
    /// dimension is known and right; a term holding a symbol declared without a unit makes it
    /// unchecked (naming the symbols), unless another term is off. A term off only where it
    /// holds a decimal number (a length written `0.35 m` in the model, kept as its value) makes
    /// it unchecked too, saying so, rather than inconsistent.
    ReportUnitCheck check(const ex& equation, const Dimension& expected);

private:
    struct Found {
        Dimension dimension;
        std::string conflict;  ///< the first sum inside whose terms differ, said for the reader
        bool partial = false;  ///< a leaf declared without a unit is inside (the sum it is in
                               ///< took another term's dimension, unchecked)
        bool decimal = false;  ///< a decimal number is inside: a script's `0.35 m` is kept as
                               ///< its value, its unit gone, so a term off by a unit may be right
    };
    Found of(const ex& e);

    const SymbolTable& st_;
    std::function<Dimension(const ex&)> of_symbol_;
    std::map<ex, Found, GiNaC::ex_is_less> intermediates_;
};

}  // namespace alembert::lang
