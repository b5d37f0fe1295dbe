// SPDX-License-Identifier: MIT
// Partial derivatives by one symbol, each shared sub-expression differentiated once.
#pragma once

#include <ginac/ginac.h>

#include <unordered_map>

namespace alembert {

using GiNaC::ex;

/// d/ds of expressions for one symbol s, a memo over their expression DAG: a sub-expression
/// met again (in the same expression or in another one given to the same memo) is
/// differentiated once. Each result is the expression `e.diff(s)` gives, formed the same way
/// (GiNaC's rules for sums, products and powers), but a sub-expression free of s is 0 without
/// differentiating its factors, and sin and cos take the chain rule directly: GiNaC's
/// `function::derivative` first tries an explicit derivative, which sin and cos do not have,
/// and throws and catches an exception for every sine and cosine it differentiates.
/// Other functions of s, and other kinds of expression, are differentiated by GiNaC.
class DerivativeMemo {
public:
    explicit DerivativeMemo(const GiNaC::symbol& s);

    /// d e / d s.
    ex operator()(const ex& e);

    /// How many distinct sub-expressions were differentiated so far.
    std::size_t size() const { return memo_.size(); }

private:
    struct Entry {
        ex key;  // keeps the node alive while its address is the memo's key
        ex value;
    };
    ex derivative_of(const ex& e);

    ex s_;  // as given: a realsymbol stays one (a copy as GiNaC::symbol would not equal it)
    std::unordered_map<const GiNaC::basic*, Entry> memo_;
};

/// d e / d s through a memo for this one expression (DerivativeMemo).
ex calc_derivative(const ex& e, const GiNaC::symbol& s);

}  // namespace alembert
