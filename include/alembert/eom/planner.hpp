// SPDX-License-Identifier: MIT
// The automatic road-map planner: picks S, the direction and the about point for each unknown.
#pragma once

#include <vector>

#include "alembert/eom/roadmap.hpp"

namespace alembert {

/// Plans and forms an MG road-map: one row per unknown.
///
/// For each coordinate q_i it freezes the others and finds what moves: S is the set of bodies
/// whose velocity or angular velocity has a non-zero partial with respect to q_i'. If S turns,
/// the row rotates about u = the partial angular velocity direction (the joint axis), about a
/// point O of S whose partial velocity is zero (the joint, where the unknown forces between S
/// and the rest act, so they drop out); if S only slides, the row translates along the
/// partial velocity direction. The planner then checks that S moves as one rigid body about
/// O (partial velocities of every mass centre equal u x r^{cm/O}); where that fails (closed
/// loops, rolling), it says so in the row's note.
///
/// `unknowns` are what the rows solve for: accelerations q_i'' (forward dynamics), torque or
/// force measures (inverse dynamics, statics), or coordinates q_i (statics). A coordinate's own
/// derivative is assigned to its row; a load measure to the row whose equation holds it with
/// the fewest other unknowns.
/// The constraints the model declares (System::add_configuration_constraint,
/// add_motion_constraint) add rows of Motion::constraint: the configuration constraints
/// themselves for statics, their time derivatives at the acceleration level for dynamics.
/// Unknowns are matched to rows by a minimum-cost assignment: each coordinate to its own row
/// when it can, load measures to the rows that hold them with the fewest other unknowns, and
/// the later (dependent) coordinates to the constraint rows. Where a row keeps load measures
/// no choice of S and O eliminated (a closed loop's pin force), its note says so.
/// @throws alembert::ModelError naming the unknown if no row holds it, or if there are more
///         unknowns than coordinates and constraint rows.
std::vector<RoadmapRow> plan_roadmap(const System& sys,
                                     const std::vector<TimeVariable>& coordinates,
                                     const std::vector<ex>& unknowns,
                                     Analysis analysis = Analysis::dynamics);

}  // namespace alembert
