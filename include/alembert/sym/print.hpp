// SPDX-License-Identifier: MIT
// Deterministic printing of expressions: primes for derivatives, stable term order.
#pragma once

#include <ginac/ginac.h>

#include <ostream>
#include <string>
#include <vector>

namespace alembert {

using GiNaC::ex;

/// Prints `e` in a deterministic order that does not depend on GiNaC's internal (hash and
/// creation-order dependent) ordering: factors of a product are sorted symbols first, then
/// functions, then parenthesised sums, by name; terms of a sum by their printed symbols, then
/// by degree. Derivatives print with primes (qA', qA'') because that is their symbol name.
std::string to_string(const ex& e);

/// Streams `to_string(e)`.
void print(std::ostream& os, const ex& e);

class SymbolTable;

/// The definitions a reader needs before `printed`: one line "z3 = ..." for each intermediate
/// of `table` that `printed` names, directly or through another definition, in dependency order
/// (calc_used_intermediates, definitions made readable with calc_readable); empty if none.
std::string format_intermediates(const SymbolTable& table, const std::vector<ex>& printed);

}  // namespace alembert
