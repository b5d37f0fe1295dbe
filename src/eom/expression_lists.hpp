// SPDX-License-Identifier: MIT
// Private to eom: looking expressions up in lists by structural equality.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <vector>

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

}  // namespace alembert::detail
