// SPDX-License-Identifier: MIT
// Private to sim: numbers as the layer's messages print them.
#pragma once

#include <cstdio>
#include <string>

namespace alembert::detail {

/// `v` with six significant digits (printf's %.6g).
inline std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace alembert::detail
