// SPDX-License-Identifier: MIT
// The sit-to-stand motion as formulas of time: minimum jerk from seat-off to standing.
#pragma once

#include <alembert/alembert.hpp>
#include <numbers>
#include <vector>

/// qA, qB, qC (rad) of rising from a chair: minimum-jerk transitions (Flash & Hogan 1985)
/// from seat-off (-25, 105, -130) deg to standing (-5, 10, -10) deg; knee and hip move over
/// [0, 1.5] s, the ankle over [0.15, 1.5] s.
inline std::vector<alembert::ex> sit_to_stand_motion(const alembert::ex& t) {
    using alembert::minimum_jerk;
    const double deg = std::numbers::pi / 180;
    return {(-25 + 20 * minimum_jerk(t, 0.15, 1.5)) * deg,
            (105 - 95 * minimum_jerk(t, 0.0, 1.5)) * deg,
            (-130 + 120 * minimum_jerk(t, 0.0, 1.5)) * deg};
}
