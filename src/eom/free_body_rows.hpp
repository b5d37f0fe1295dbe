// SPDX-License-Identifier: MIT
// Free-body rows for contact forces in minimal coordinates: the planner's search over S, u, O.
#pragma once

#include <vector>

#include "alembert/eom/roadmap.hpp"

namespace alembert::detail {

/// True if point P of a body B is joined there to another body C (or to the ground, C =
/// nullptr): P is located (through points of no body) from a point of C by an offset that
/// stays constant in C's frame (N for the ground), so P is a point of both (a pin or a weld).
/// An offset that changes with the coordinates (a centre placed by x Nx> + r Ny>, a rod's foot
/// at L sin q Nx>) only describes where P is: no joint there. `other` receives C.
bool joined_at(const System& sys, const Point& P, const Body** other);

/// True if the model's constraints act only through declared loads whose measures are among
/// `unknowns`: at two pseudo-random states, each constraint's generalized force direction
/// (the coefficients of the speeds q_r' in a motion constraint, in the time derivative of a
/// configuration constraint) lies in the span of the generalized active forces of those
/// measures (the loop's pin force declared as a force pair, a wall's push on a rod's top).
/// Then every body's free-body equations hold with the declared loads alone, as the
/// coordinates' rows do; when it fails, a constraint's force is nowhere declared and the bodies
/// its coordinates move keep an undeclared force. True when there are no constraints.
bool constraint_forces_declared(const System& sys, const std::vector<TimeVariable>& coordinates,
                                const std::vector<ex>& unknowns);

/// A row the free-body planner may choose besides its own: a coordinate's row (`coordinate`
/// is its index; only that coordinate's derivatives may take it) or a constraint row
/// (`coordinate` = kAnyCoordinate). Formed with no variable.
struct FixedRow {
    static constexpr int kAnyCoordinate = -2;
    RoadmapRow row;
    int coordinate = -1;
};

/// One row per unknown of `shared` (coordinates' derivatives and load measures) chosen so
/// that each row holds as few unknowns as possible, in an order of solution: a row that
/// brings one new unknown first (the others it holds known from the rows before), else the
/// smallest block of rows solved together. Besides `fixed`, the candidates are free-body
/// rows of every system S that carries an unknown load and meets the rest of the model only
/// through declared loads (S = a body with the bodies joined to it, none joined to the
/// ground, and none moved by a coordinate in a declared constraint unless
/// constraint_forces_declared): translate along the axes of the model's frames and the
/// unknown forces' directions, rotate about those axes through the points of S and the
/// intersections of the lines of two unknown forces; and of every system S that meets the
/// rest at one joint alone (the bodies on the far side of a joint from the ground, when
/// that joint parts them: the rod and slider beyond a crank pin), rotated about the
/// directions the joint lets S turn, about the joint, where its force drops out.
/// Each row is formed with `unknowns` (its additional unknowns, FBD);
/// `constraint_forces_are_loads` is constraint_forces_declared(sys, coordinates, unknowns).
/// @throws alembert::ModelError naming the unknowns left if no such choice exists.
std::vector<RoadmapRow> plan_free_body_rows(const System& sys,
                                            const std::vector<TimeVariable>& coordinates,
                                            const std::vector<FixedRow>& fixed,
                                            const std::vector<ex>& shared,
                                            const std::vector<ex>& unknowns, Analysis analysis,
                                            bool constraint_forces_are_loads);

}  // namespace alembert::detail
