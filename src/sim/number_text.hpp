// SPDX-License-Identifier: MIT
// Private to sim: numbers as the layer's messages print them.
#pragma once

#include <cstdio>
#include <string>

namespace alembert::detail {

/// `v` with six significant digits (printf's %.6g); -0 prints as 0 (its sign depends on the
/// order GiNaC happens to give terms, which may change from run to run).
inline std::string number(double v) {
    if (v == 0) v = 0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace alembert::detail
