// SPDX-License-Identifier: MIT
// A ball (3-dof spherical) joint with a singularity-free orientation, and the Euler-parameter
// kinematics it shares with the free joint.
#pragma once

#include <string>
#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// R_PB of the Euler parameters (unit quaternion e0 + e1 i + e2 j + e3 k) of frame B in P:
///     R_PB = (e0^2 - ev.ev) I + 2 ev ev^T + 2 e0 [ev]x,   ev = (e1, e2, e3)
/// (Kane, Likins & Levinson, Spacecraft Dynamics, 1983, sec. 1.3). A rotation for unit e only.
Mat3 euler_parameter_rotation(const ex& e0, const ex& e1, const ex& e2, const ex& e3);

/// The Euler parameters' rates e' = 1/2 Q(e) w for the angular velocity ^P w^B = w1 Bx> +
/// w2 By> + w3 Bz> in B's axes:
///     e0' = -1/2 (e1 w1 + e2 w2 + e3 w3),   (e1, e2, e3)' = 1/2 (e0 w + ev x w)
/// (Kane, Likins & Levinson 1983, sec. 1.13). They keep |e| constant exactly.
/// @throws alembert::ArgumentError unless e has 4 entries and w 3.
std::vector<ex> euler_parameter_rates(const std::vector<ex>& e, const std::vector<ex>& w);

/// A ball (spherical, 3-dof) joint of a body B to a parent frame P, singularity-free: B's
/// orientation in P by Euler parameters e0..e3 (a unit quaternion, R_PB by
/// euler_parameter_rotation) and B's angular velocity relative to P in B's axes as speeds,
/// ^P w^B = w1 Bx> + w2 By> + w3 Bz>. This is the free joint's rotation (FreeJoint) between
/// two bodies: Kane, Likins & Levinson, Spacecraft Dynamics (1983), ch. 1 for the Euler
/// parameters; Featherstone, Rigid Body Dynamics Algorithms (2008), sec. 4.4 (the spherical
/// joint, S = [I 0]^T in body coordinates); MuJoCo's ball joint (qpos a quaternion w x y z,
/// qvel the angular velocity in the child's frame). Why: three joint angles lock where two
/// axes align (the recursion's partial angular velocities lose rank there) and need two
/// massless gimbal frames between the bodies; with body-frame speeds the joint's partial
/// angular velocities relative to P are B's own axes, so a torque pair T1 Bx> + T2 By> +
/// T3 Bz> on B from P has generalized forces exactly T1, T2, T3. The kinematic equations are
/// e' = 1/2 Q(e) w (euler_parameter_rates); a numerical integration keeps |e| = 1 to its
/// truncation error (normalise e now and then). Every orientation has Euler parameters with
/// e0 >= 0 (e and -e are the same rotation).
struct BallJoint {
    std::vector<TimeVariable> quaternion{};  ///< e0, e1, e2, e3 (to second order, for methods
                                             ///< that differentiate the orientation twice)
    std::vector<TimeVariable> angular{};     ///< w1, w2, w3 (first order)
    /// e0, e1, e2, e3.
    std::vector<TimeVariable> coordinates() const;
    /// w1, w2, w3.
    std::vector<ex> speeds() const;
    /// e' = 1/2 Q(e) w: the coordinates' rates in terms of the speeds.
    std::vector<ex> coordinate_rates() const;
};

/// Joins rigid body `B` (declared with System::add_rigid_body, its frame not yet oriented) to
/// the frame `parent` by a ball joint: orients B's frame in `parent` by Euler parameters and
/// sets its angular velocity in `parent` in the body-frame speeds (see BallJoint). The joint
/// centre is the caller's to place: locate B_o at a point fixed in `parent` (B_o.set_pos from
/// the parent's origin), as for a hinge. The symbols are named with B's name: e0_B..e3_B,
/// w1_B..w3_B.
/// @throws alembert::ModelError if a symbol of these names exists, B's frame is oriented, or
///         `parent` is B's own frame.
BallJoint add_ball_joint(System& sys, RigidBody& B, const Frame& parent);

}  // namespace alembert
