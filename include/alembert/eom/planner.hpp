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
/// O (partial angular velocities of every rigid body of S equal u, partial velocities of
/// every mass centre equal u x r^{cm/O}); where that fails (closed loops, rolling), it says
/// so in the row's note. These zero tests, and those that decide which unknowns a row holds,
/// are made at random states through the named intermediates (a symbolic test misses
/// cancellations inside them), with a symbolic fallback for small expressions that cannot
/// be evaluated there.
///
/// `unknowns` are what the rows solve for: accelerations q_i'' (forward dynamics), torque or
/// force measures (inverse dynamics, statics), coordinates q_i (statics), or speeds q_i'
/// (dynamics: a steady motion's rate). A coordinate or its acceleration is assigned to its own
/// row; a load measure to the row whose equation holds it (by meaning, at random states) with
/// the fewest other unknowns, among those preferably the row whose motion it drives (a torque
/// about the row's direction, a force along it); a speed to a row whose dynamic equation
/// changes with it, preferably one that still does with the other speeds and all
/// accelerations 0 (a top's precession rate: the row about the nodal axis, not psi's own row,
/// which holds psi' only times theta'). Specified quantities declared with derivatives that are
/// not among `coordinates` get rows planned as coordinates' are (S = what moves when only
/// they change), for the loads that drive them only (a torque about the row's direction, a
/// force along it: another load there would stand in for an actuator the model leaves out).
/// When no point of S stays fixed, O is a point of the model on the axis of S's motion (a
/// point of S first, then a fixed one such as a top's tip), else the instantaneous centre.
/// The constraints the model declares (System::add_configuration_constraint,
/// add_motion_constraint) add rows of Motion::constraint: the configuration constraints
/// themselves for statics, their time derivatives at the acceleration level for dynamics.
/// Unknowns are matched to rows by a minimum-cost assignment: each coordinate to its own row
/// when it can, load measures to the rows that hold them with the fewest other unknowns, and
/// the later (dependent) coordinates to the constraint rows. Where a row keeps load measures
/// no choice of S and O eliminated (a closed loop's pin force), its note says so.
///
/// Measures of joint reactions the model declares (System::add_joint_reaction) have rows of
/// their own (the road-map's column 4: treat a force measure as a velocity measure, a torque
/// measure as an angular velocity measure, and see what moves). For a force measure along u
/// at the joint between S's parent and S, the row translates along u with S = what would move
/// if the joint could slide along u: the child and every body placed from it
/// (alembert::calc_bodies_beyond); for a torque measure about u it rotates about u with the
/// same S, about the joint point. Every other joint force of the model is internal to S or
/// acts on the rest, so the row keeps the measure, the accelerations (dynamics) and the loads
/// on S. Where S meets the rest at a second joint (a closed loop), the row's note says so.
///
/// When reaction measures are among the unknowns, the rows come out in an order in which
/// they can be solved one block after another (without, in the order of `unknowns`): each
/// block needs only the unknowns of the blocks before it (a stable topological order of the
/// strongly connected components of "row i holds the unknown of row j"); where a block with
/// reaction rows has more than one row, their notes name the rows solved with them.
/// @throws alembert::ModelError naming the unknown if no row holds it (a speed: "no road-map
///         row holds the speed"), or if there are more
///         unknowns (besides reaction measures) than coordinates and constraint rows.
std::vector<RoadmapRow> plan_roadmap(const System& sys,
                                     const std::vector<TimeVariable>& coordinates,
                                     const std::vector<ex>& unknowns,
                                     Analysis analysis = Analysis::dynamics);

/// Plans the road-map of a model whose unknowns are not listed: one row per degree of
/// freedom, as in forward dynamics, where the accelerations are the unknowns. With no unknown
/// load measures declared, the rows of the accelerations q'' of `coordinates`. Else the rows of
/// the model's unknown load measures (SymbolKind::unknown, in their order, as plan_roadmap
/// plans them), and when those take fewer coordinate and constraint rows than there are (an
/// under-actuated model: a cart-pole pushed at the cart, an acrobot driven at the elbow), the
/// accelerations of the coordinates whose motion no unknown load's row determines, after
/// them: each on its own coordinate's row (S = what moves when only it changes, as for any
/// coordinate), or on a free constraint row that holds it (the later, dependent coordinates
/// first). When the unknown loads take every such row (a motor at each joint), the rows are
/// theirs alone.
/// @throws as plan_roadmap.
std::vector<RoadmapRow> plan_default_roadmap(const System& sys,
                                             const std::vector<TimeVariable>& coordinates);

/// The system S of a joint reaction's rows: the child and every body whose mass centre is
/// placed (through located-from points) from a point of the child, or whose frame is
/// oriented (through parent frames) from the child's frame.
/// @throws alembert::ModelError if the reaction's parent is among them (parent and child
///         swapped).
BodySet calc_bodies_beyond(const System& sys, const JointReaction& reaction);

}  // namespace alembert
