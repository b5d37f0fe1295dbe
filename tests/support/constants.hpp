// SPDX-License-Identifier: MIT
// Constants the tests share.
#pragma once

#include <numbers>

namespace alembert::test {

inline constexpr double kPi = std::numbers::pi;
/// One degree in radians.
inline constexpr double kDeg = std::numbers::pi / 180;

}  // namespace alembert::test
