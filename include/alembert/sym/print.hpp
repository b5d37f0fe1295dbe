// SPDX-License-Identifier: MIT
// Deterministic printing of expressions: primes for derivatives, stable term order.
#pragma once

#include <ginac/ginac.h>

#include <ostream>
#include <string>

namespace alembert {

using GiNaC::ex;

/// Prints `e` in a deterministic order that does not depend on GiNaC's internal (hash and
/// creation-order dependent) ordering: factors of a product are sorted symbols first, then
/// functions, then parenthesised sums, by name; terms of a sum by their printed symbols, then
/// by degree. Derivatives print with primes (qA', qA'') because that is their symbol name.
std::string to_string(const ex& e);

/// Streams `to_string(e)`.
void print(std::ostream& os, const ex& e);

}  // namespace alembert
