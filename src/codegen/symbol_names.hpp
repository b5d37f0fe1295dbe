// SPDX-License-Identifier: MIT
// Private to codegen: the names of a plan's symbols in the comments of generated files.
#pragma once

#include <string>
#include <vector>

#include "alembert/codegen/code_plan.hpp"

namespace alembert::detail {

/// The symbols' names, comma separated; "none" if there are none.
inline std::string names_of(const std::vector<CodeSymbol>& v) {
    std::string s;
    for (const CodeSymbol& x : v) s += (s.empty() ? "" : ", ") + x.name;
    return s.empty() ? "none" : s;
}

}  // namespace alembert::detail
