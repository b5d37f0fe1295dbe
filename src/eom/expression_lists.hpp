// SPDX-License-Identifier: MIT
// Private to eom: looking expressions up in lists by structural equality.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert::detail {

/// The position of the first element of `xs` structurally equal to `x`; xs.size() if none.
inline std::size_t index_of(const std::vector<GiNaC::ex>& xs, const GiNaC::ex& x) {
    for (std::size_t i = 0; i < xs.size(); ++i)
        if (xs[i].is_equal(x)) return i;
    return xs.size();
}

/// Whether an element of `xs` is structurally equal to `x`.
inline bool contains(const std::vector<GiNaC::ex>& xs, const GiNaC::ex& x) {
    return index_of(xs, x) < xs.size();
}

/// Throws if a coordinate is listed twice: its equation would be formed twice and the
/// equations could not be solved.
/// @throws alembert::ArgumentError naming `fn` and the coordinate.
inline void require_distinct_coordinates(const std::vector<TimeVariable>& q, const std::string& fn) {
    for (std::size_t i = 0; i < q.size(); ++i)
        for (std::size_t j = i + 1; j < q.size(); ++j)
            if (q[i].symbol().is_equal(q[j].symbol()))
                throw ArgumentError(fn + ": the coordinate '" + q[i].name() +
                                    "' is listed twice; list each coordinate once");
}

}  // namespace alembert::detail
