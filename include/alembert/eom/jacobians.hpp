// SPDX-License-Identifier: MIT
// Point and frame Jacobians: velocities as linear maps of the coordinates' rates, for
// task-space control and trajectory optimisation.
#pragma once

#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// Where a point or a frame is, the Jacobian that maps the coordinates' rates q' to its
/// velocity, and the velocity-product term of its acceleration:
///     v = J(q) q',   a = J(q) q'' + J'(q, q') q'.
/// Every entry is a function of t, q (and q' for J' q') and the constants, expressed in N.
struct KinematicJacobian {
    /// A point P: p^{P/N_o} in N (3 entries). A frame B located by a point O: R_NB row by row,
    /// then p^{O/N_o} in N (12 entries).
    std::vector<ex> position{};
    /// Row by row, rows x n (n coordinates): a point's 3 rows are ^N v^P in N; a frame's 6 rows
    /// are ^N w^B in N, then ^N v^O in N (Pinocchio's frame Jacobian in the world's axes, angular
    /// rows first).
    std::vector<ex> jacobian{};
    /// J' q' (one per row): the acceleration at q'' = 0, sum_j (dJ/dq_j q'_j) q' (a point's
    /// ^N a^P, a frame's ^N alpha^B then ^N a^O, each formed by d/dt and q'' set to 0).
    std::vector<ex> jacobian_dot_rates{};
    std::size_t rows() const { return jacobian_dot_rates.size(); }
};

/// The point Jacobian of P: v^P = J q' with J_ij = d(^N v^P . N_i)/dq'_j, from P's position
/// from N_o (Kane & Levinson 1985, sec. 2.14: the partial velocities of P, in N's axes).
/// @throws alembert::ModelError if P is not located from N_o; alembert::ArgumentError if a
///         coordinate has no second derivative declared.
KinematicJacobian form_point_jacobian(const System& sys, const std::vector<TimeVariable>& q,
                                      const Point& P);

/// The frame Jacobian of B with its origin O: ^N w^B = J_w q' (partial angular velocities,
/// Kane & Levinson 1985, sec. 2.14) and ^N v^O = J_v q', stacked [J_w; J_v], in N's axes.
/// @throws alembert::ModelError if B is not oriented in N or O not located from N_o.
KinematicJacobian form_frame_jacobian(const System& sys, const std::vector<TimeVariable>& q,
                                      const Frame& B, const Point& O);

}  // namespace alembert
