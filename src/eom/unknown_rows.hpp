// SPDX-License-Identifier: MIT
// What the planner needs for speeds and for the loads that drive specified motions.
#pragma once

#include <vector>

#include "alembert/eom/roadmap.hpp"

namespace alembert::detail {

/// The specified quantities declared with derivatives (`specified theta''`) that are not among
/// `coordinates`, in declaration order. Treated like coordinates for planning (the road-map's
/// column 4), each has a row: S = what moves when only it changes. That row holds the load that
/// drives it, and is for loads only (its acceleration is given, never solved for).
std::vector<TimeVariable> calc_driven_quantities(const System& sys,
                                                 const std::vector<TimeVariable>& coordinates);

/// The index of the coordinate whose speed `x` is (x = q', q declared to order 2 or more), or
/// -1 when x is no coordinate's speed.
int calc_speed_of(const ex& x, const std::vector<TimeVariable>& coordinates);

/// The symbols a speed row is tested with at zero: every derivative of the coordinates but x
/// (the other speeds and all accelerations).
std::vector<ex> calc_other_rates(const ex& x, const std::vector<TimeVariable>& coordinates);

/// True if the measure x multiplies loads of the model only along u (forces, for a translate
/// row) or about u (torques, for a rotate row), and at least one: the row's own driving load
/// (a motor torque about the joint axis the row turns about).
bool acts_only_along(const System& sys, const ex& x, Motion motion, const Vector& u);

}  // namespace alembert::detail
