// SPDX-License-Identifier: MIT
// Sample models shared by tests, benchmarks and examples.
#pragma once

#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// A built model with handles to what users of the sample usually need.
struct SampleModel {
    System system;
    std::vector<TimeVariable> q;    ///< generalized coordinates, in joint order
    std::vector<ex> unknowns;       ///< joint torque (or force) measures, in joint order
    std::vector<RigidBody*> links;  ///< bodies, base first (empty for particle models)
    /// Chosen generalized speeds u, one per equation (empty: u = q', the coordinates' rates).
    std::vector<ex> speeds{};
    /// q' in terms of q and u, one per coordinate (empty when u = q').
    std::vector<ex> coordinate_rates{};
};

/// The seed's sit-to-stand model, an inverted triple pendulum (Mitiguy, ch. 21): Newtonian
/// frame N (the foot, fixed), shank A turning about Nz by qA at the ankle A_o (at N_o), thigh
/// B by qB relative to A at the knee B_o (L_A along Ay), head-arms-trunk C by qC relative to
/// B at the hip C_o (L_B along By); mass centres at d_A, d_B, d_C along each body's y axis;
/// central inertias I_A, I_B, I_C about z; gravity -g Ny; motor torques T_A on A from N,
/// T_B on B from A, T_C on C from B, about Nz (unknowns). Constants carry the values of a
/// 70 kg, 1.70 m person from Winter's anthropometric table (Winter 2009, Table 4.1).
SampleModel make_triple_pendulum();

/// Joint type of a sample chain.
enum class ChainKind {
    planar,   ///< one revolute joint about z per link (relative angles q1..qn)
    spatial,  ///< two-axis joints: about z by qz_i, then about the new x by qx_i
};

/// An n-link pendulum of uniform rods hanging from N_o: link B_i (length L_i, mass m_i,
/// values 1 m and 1 kg) lies along its own -y axis, mass centre at L_i/2, central inertia
/// m_i L_i^2/12 about x and z; gravity -g Ny (g = 9.81); joint torques T_i (planar) or
/// Tz_i, Tx_i (spatial) on B_i from B_{i-1}.
/// @throws alembert::ArgumentError if n < 1.
SampleModel make_n_link_pendulum(int n, ChainKind kind = ChainKind::planar);

/// The planar chain of the dynamics benchmarks (bench/README.md): n uniform rods standing on
/// N_o, link B_i turning about Nz by q_i relative to B_{i-1} (N for the first), lying along its
/// own +y axis (q = 0: every link upright), joint B_i_o at the tip of B_{i-1}; L_i = 1 m,
/// m_i = 1 kg, mass centre at L_i/2, central inertia m_i L_i^2/12 = 1/12 kg m^2 about x and z;
/// gravity -g Ny (g = 9.81); joint torques T_i Nz on B_i from B_{i-1}.
/// @throws alembert::ArgumentError if n < 1.
SampleModel make_planar_chain(int n);

/// A particle Q of mass m sliding along Nx, connected to N_o by a spring (stiffness k,
/// natural length 0) and a damper (coefficient c); x is its coordinate.
SampleModel make_mass_spring_damper();

/// A four-bar linkage in the vertical plane, a closed loop: ground pivots N_o and N_c
/// (L_N along Nx); crank A (length L_A) turning about Nz at N_o by qA from Nx; coupler B
/// (L_B) pinned at the crank's tip A_tip, turning by qB relative to A; rocker C (L_C) pinned
/// at N_c, turning by qC from Nx. Each link lies along its own x axis; uniform rods (mass
/// centre at mid-length, central inertia m L^2/12 about z); gravity -g Ny. The loop closes
/// where the coupler's tip B_tip meets the rocker's tip C_tip: the configuration constraints
/// loop_x, loop_y (r^{B_tip/C_tip} . Nx, . Ny = 0), and the pin force there, F_x Nx + F_y Ny
/// on B from C (unknowns F_x, F_y). The crank torque T Nz acts on A from N (unknown T).
/// Values: L_N = 1, L_A = 0.4, L_B = 1.2, L_C = 0.8 m (a crank-rocker), m_A = 1,
/// m_B = 2, m_C = 1.5 kg, g = 9.81. q = {qA, qB, qC}; unknowns = {T, F_x, F_y}.
SampleModel make_four_bar();

/// The KUKA LBR iiwa 14, a 7-joint spatial arm, with the joint origins, masses, mass
/// centres and principal central inertias of its public URDF (RobotLocomotion/drake,
/// iiwa14_no_collision.urdf): link B_i turns by q_i about the z axis of the joint frame J_i,
/// which is fixed in link B_{i-1} (N for i = 1, the base being fixed) at the URDF joint origin
/// (xyz in B_{i-1}, rpy exact multiples of pi/2); B_i's frame is the URDF link frame. Gravity
/// -g Nz (g = 9.81), no joint damping; joint torques T_i B_iz on B_i from B_{i-1} (unknowns).
SampleModel make_kuka_iiwa14();

/// A standing human of 15 segments on a floating base, 32 degrees of freedom, with the segment
/// masses, mass centres and radii of gyration of de Leva (1996, J. Biomech. 29:1223, Table 4,
/// male, 73 kg) and his mean segment lengths. Segments: pelvis (his lower trunk), torso (middle
/// and upper trunk as one body), head, and per side upper arm, forearm, hand, thigh, shank,
/// foot; every frame parallel to N when all angles are zero and all Euler parameters
/// (1, 0, 0, 0) (x forward, y left, z up).
/// Joints: the pelvis free in N (add_free_joint: x, y, z and Euler parameters e0..e3 of
/// pelvis, speeds x', y', z', w1..w3 in the pelvis frame; force F_pelvis at pelvis_o along N,
/// torque T_pelvis along the pelvis axes); ball joints (add_ball_joint: Euler parameters
/// e0_B..e3_B of segment B in its parent, speeds w1_B..w3_B its angular velocity in the
/// parent in B's axes) at the lumbar joint, neck, shoulders and hips, each with the motor
/// torque T_B_x Bx> + T_B_y By> + T_B_z Bz> on B from its parent (each component the
/// generalized force of its speed); hinges about y (q_B) at the elbows, wrists, knees and
/// ankles with a motor torque T_B about the axis between the bodies it joins: 15 bodies, one
/// joint each. The joints' lateral offsets (hips +-0.085 m, shoulders +-0.175 m) and the
/// ankle's place over the foot are round values, not from the table. Gravity -g Nz
/// (g = 9.81). q (39), segment by segment: the free joint's 7 coordinates, each ball's 4 Euler
/// parameters, each hinge's angle; speeds (32) likewise: the free joint's 6, each ball's
/// w1..w3, each hinge angle's rate; coordinate_rates: q' in these speeds (e' = 1/2 Q(e) w);
/// unknowns: one per speed, in their order; links: the 15 segments, pelvis first.
SampleModel make_humanoid();

/// A built model with chosen speeds and motion constraints, in the terms of Kane's method.
struct SampleNonholonomicModel {
    System system;
    std::vector<TimeVariable> q;           ///< generalized coordinates
    std::vector<TimeVariable> u;           ///< generalized speeds, dependent ones included
    std::vector<ex> kinematic_equations;   ///< one per coordinate, = 0
    std::vector<ex> motion_constraints;    ///< = 0, linear in the speeds
    std::vector<ex> dependent_speeds;      ///< the speeds the constraints are solved for
    std::vector<RigidBody*> links;         ///< the bodies
};

/// The Whipple bicycle with the benchmark parameters of Meijaard, Papadopoulos, Ruina &
/// Schwab (2007, Proc. R. Soc. A 463, Table 1; constants w, c, lambda, g, r_R, m_R, I_Rxx, ...
/// named as there): rear frame B, front fork H, rear and front wheels R and F (knife-edge,
/// rolling without slip on the plane of N, Nz up). Yaw frame Y about Nz by q1, lean frame L
/// about Yx by q2, B pitched about Ly by q4 (0 in the reference configuration), R about By by
/// q3, H steered about the steer axis (tilted back by lambda from Lz at zero pitch) by q5, F
/// about Hy by q6. Body axes are x forward, y left, z up when upright (Table 1's y right,
/// z down flips the sign of the xz products of inertia). Speeds u_i = q_i'. The rear wheel's
/// contact point P_R is at rest; the front wheel's contact point P_F at rest along Yx, Yy
/// and Yz gives three motion constraints, solved for the yaw, pitch and front wheel rates
/// u1, u4, u6. Upright straight running at speed v: every q and u zero but u3 = v/r_R.
SampleNonholonomicModel make_whipple_bicycle();

/// A thin disk D (mass, radius) rolling without slip on the plane of Nx, Ny (Nz up), as
/// examples/rolling_disk/model.alb has it: heading q1 about Nz (frame Y), lean q2 about Yx
/// (frame L), spin q3 about Ly; the contact point P at x Nx + y Ny; speeds u1..u3 the measures
/// of D's angular velocity in L, u4 = x', u5 = y'; no slip at D's point at the contact (D_P),
/// solved for u4 and u5. With `axle_torque`, a torque T Ly on D about its axle (an unknown
/// load measure T).
SampleNonholonomicModel make_rolling_disk(double mass, double radius, double gravity,
                                          bool axle_torque);

}  // namespace alembert
