// SPDX-License-Identifier: MIT
// Inertia forces and torques of bodies: the "mass times acceleration" side of every method.
#pragma once

#include "alembert/mech/system.hpp"

namespace alembert {

/// The inertia force and torque of one body in N (Kane 1985, sec. 4.11):
/// R* = -m ^N a^{cm}, T* = -(I . ^N alpha^B + ^N w^B x I . ^N w^B) (T* = 0 for a particle).
struct InertiaLoads {
    Vector force;
    Vector torque;
};

/// R* and T* of body B in frame N.
InertiaLoads calc_inertia_loads(const Body& B, const Frame& N);

/// Sum over S of m ^N a^{cm}: the right-hand side of F^S = m^S ^N a^{Scm}.
Vector calc_inertial_force(const BodySet& S, const Frame& N);

/// Sum over S of I . alpha + w x I . w + r^{cm/O} x m ^N a^{cm}. For any point O, fixed or
/// moving, this equals ^N d/dt ^N H^{S/O} + ^N v^O x ^N L^S (Mitiguy ch. 21, the moving-point
/// form), with H formed with absolute mass-centre velocities; it is cheaper because it never
/// differentiates H.
Vector calc_inertial_moment(const BodySet& S, const Point& O, const Frame& N);

}  // namespace alembert
