// SPDX-License-Identifier: MIT
// A free (6-dof) joint to the Newtonian frame with a singularity-free orientation.
#pragma once

#include <vector>

#include "alembert/mech/ball_joint.hpp"
#include "alembert/mech/system.hpp"

namespace alembert {

/// A free (6-dof) joint of a body to the Newtonian frame N, singularity-free: the origin B_o at
/// x Nx> + y Ny> + z Nz> from N_o with speeds x', y', z', and the orientation by Euler
/// parameters (a unit quaternion e0 + e1 i + e2 j + e3 k) with the body-frame angular velocity
/// ^N w^B = w1 Bx> + w2 By> + w3 Bz> as speeds (Euler parameters: Kane, Likins & Levinson,
/// Spacecraft Dynamics, 1983, ch. 1; the same free joint in Featherstone, Rigid Body Dynamics
/// Algorithms, 2008, ch. 4, and MuJoCo's free joint). Why these: every orientation has Euler parameters and the
/// map is smooth everywhere (three angles have a gimbal lock, at which the recursion's partial
/// motions lose rank), and with body-frame speeds the partial angular velocities are the
/// body's axes, constant in B: for a lone body the angular rows are Euler's equations with no
/// orientation in them. The kinematic equations
///     e' = 1/2 Q(e) w:   e0' = -1/2 (e1 w1 + e2 w2 + e3 w3),
///                        (e1, e2, e3)' = 1/2 (e0 w + (e1, e2, e3) x w)
/// keep |e| = 1 exactly; a numerical integration drifts off it slowly (normalise e now and
/// then). R_NB = (e0^2 - ev.ev) I + 2 ev ev^T + 2 e0 [ev]x, with ev = (e1, e2, e3). Its
/// rotation is a ball joint to N (add_ball_joint), whose code it shares.
struct FreeJoint {
    std::vector<TimeVariable> position{};    ///< x, y, z (declared to second order)
    std::vector<TimeVariable> quaternion{};  ///< e0, e1, e2, e3 (to second order, for methods
                                            ///< that differentiate the orientation twice)
    std::vector<TimeVariable> angular{};     ///< w1, w2, w3 (first order)
    /// x, y, z, e0, e1, e2, e3.
    std::vector<TimeVariable> coordinates() const;
    /// x', y', z', w1, w2, w3.
    std::vector<ex> speeds() const;
    /// x', y', z', then e' = 1/2 Q(e) w: the coordinates' rates in terms of the speeds.
    std::vector<ex> coordinate_rates() const;
};

/// Frees rigid body `B` (declared with System::add_rigid_body, not yet oriented or located):
/// orients its frame in N by Euler parameters, sets its angular velocity in N in the body-frame
/// speeds and locates B_o from N_o (see FreeJoint). The symbols are named with B's name:
/// x_B, y_B, z_B, e0_B..e3_B, w1_B..w3_B.
/// @throws alembert::ModelError if a symbol of these names exists or B's frame is oriented.
FreeJoint add_free_joint(System& sys, RigidBody& B);

}  // namespace alembert
