// SPDX-License-Identifier: MIT
// Brute-force Newton–Euler: a free-body diagram per body with every joint reaction unknown.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// How many equations each body contributes.
enum class NewtonEulerMode {
    automatic,  ///< planar when the model is planar (see below), else spatial
    planar,     ///< 3 per rigid body (2 force, 1 moment), 2 per particle; ModelError if not planar
    spatial,    ///< 6 per rigid body (3 force, 3 moment), 3 per particle, even for a planar model
};

/// Options of alembert::form_newton_euler_equations.
struct NewtonEulerOptions {
    NewtonEulerMode mode = NewtonEulerMode::automatic;
};

/// A joint inferred from the model: body B joined to its parent at point J.
///
/// The reaction force (sum of the force components) acts on B at J and its opposite on the
/// parent at the same place; the reaction torque acts on B and its opposite on the torque
/// parent. For a rigid body the torque parent is the body whose frame B's frame is oriented
/// from (N: the ground), the force parent the owner of the point J is located from; both are
/// the same body in a chain.
struct NewtonEulerJoint {
    const Body* body = nullptr;           ///< B, the body the reaction acts on
    const Body* parent = nullptr;         ///< the body exerting the force (nullptr: the ground)
    const Body* torque_parent = nullptr;  ///< the body exerting the torque (nullptr: the ground,
                                          ///< and for a particle, which takes no torque)
    const Point* at = nullptr;            ///< J, the joint point of B
    int free_slides = 0;     ///< independent partial velocities of J relative to the parent
    int free_rotations = 0;  ///< independent partial angular velocities of B relative to its
                             ///< torque parent (0 for a particle)
    std::vector<ReactionComponent> reactions{};
    Vector force{};   ///< sum of the force components, on B
    Vector torque{};  ///< sum of the torque components, on B
};

/// The brute-force Newton–Euler equations of a model.
///
/// What is counted. Equations: per rigid body F = m ^N a^{cm} and M^{B/Bcm} = ^N d/dt H^{B/Bcm}
/// = I . alpha + w x I . w (Euler), per particle F = m ^N a; spatial: 3 force components
/// (along Nx>, Ny>, Nz>) and 3 moment components (along the body's axes), planar: the 2 force
/// components in the plane and the moment about the plane's normal. Unknowns: the caller's
/// (accelerations q'' for forward dynamics, or load measures such as motor torques for inverse
/// dynamics), then every joint-reaction measure. A joint transmits a force in the orthogonal
/// complement of its free slides and a torque in the complement of its free rotations; planar,
/// only the in-plane force components and the torque about the normal are formed (the
/// out-of-plane reactions do not enter the in-plane equations, which are exact).
///
/// For the seed's triple pendulum with the motor torques as unknowns this gives, planar,
/// 9 equations in 9 unknowns (6 joint-force components + 3 motor torques), and spatial,
/// 18 equations in 18 unknowns (9 force + 6 reaction-torque components, the 2 bending
/// torques of each hinge, + 3 motor torques). Mitiguy (ch. 21) quotes "15 in 3D"; Alembert's 15
/// is the number of joint-reaction components, and the motor torques make it 18.
struct NewtonEulerEquations {
    bool planar = false;
    Vector normal{};                   ///< planar: the plane's normal (an axis of N)
    std::vector<ex> equations{};       ///< residuals E = applied - inertial (= 0)
    std::vector<std::string> labels{}; ///< per equation, e.g. "B: force . Nx>"
    std::vector<ex> unknowns{};        ///< the caller's unknowns, then `reactions`
    std::vector<ex> reactions{};       ///< every joint-reaction measure, joint by joint
    std::vector<NewtonEulerJoint> joints{};
    std::size_t caller_unknowns = 0;   ///< how many of `unknowns` the caller gave
    std::size_t force_reactions = 0;   ///< force measures among `reactions`
    std::size_t torque_reactions = 0;  ///< torque measures among `reactions`
};

/// Forms the brute-force Newton–Euler equations of `sys`: Newton's second law and Euler's
/// equations for every body with every joint reaction an unknown (the method MG road-maps
/// improve on by choosing systems and about points, Mitiguy ch. 21).
///
/// Joints are inferred from the model. A rigid body B is joined at J, B's origin B_o (or the
/// first point of B located from outside B), to the owner of the point J is located from
/// (through points of no body; the ground when there is none), and to the body whose frame
/// its frame is oriented from (through frames of no body; N is the ground). Its free
/// rotations are spanned by the partial angular velocities d(^P w^B)/dq_r' over the
/// coordinates `q`; J's free slides by the partial velocities of J relative to the parent
/// (^N v^J - ^N v^{P'} - ^N w^P x r^{J/P'}, P' the parent's point). Particles are joined the
/// same way, with forces only. Independence is decided numerically at a random state (generic
/// rank). Reaction measures are new unknowns of the symbol table, named F_<parent><B>_<axis>
/// and M_<torque parent><B>_<axis> (action on B; the axis is of the frame whose axis the
/// direction is, "n", "1", "2" otherwise); forming the equations again reuses them.
///
/// @throws alembert::ModelError if a body is located or oriented from nothing, if
///         NewtonEulerMode::planar is asked of a model that is not planar, or if a reaction name
///         is taken by a symbol that is not an unknown.
NewtonEulerEquations form_newton_euler_equations(const System& sys,
                                                 const std::vector<TimeVariable>& q,
                                                 const std::vector<ex>& unknowns,
                                                 const NewtonEulerOptions& options = {});

/// The joint of one body as count_newton_euler_equations counts it.
struct NewtonEulerJointCount {
    const Body* body = nullptr;    ///< B
    const Body* parent = nullptr;  ///< the body B is joined to (nullptr: the ground)
    const Point* at = nullptr;     ///< J, the joint point of B
    int free_slides = 0;           ///< independent partial velocities of J relative to the parent
    int free_rotations = 0;        ///< independent partial angular velocities of B (0: particle)
    std::size_t forces = 0;        ///< reaction force components: the slides it forbids
    std::size_t torques = 0;       ///< reaction torque components: the rotations it forbids
};

/// How many equations and unknowns brute-force Newton–Euler takes, counted as
/// form_newton_euler_equations forms them, without forming them (no symbol is created).
/// Equations: per rigid body 3 in the plane (2 force, 1 moment) and 6 in space, per particle
/// 2 and 3. Unknowns: `caller_unknowns` (the accelerations or driving loads asked for) and, per
/// joint, a force component along each direction its point may not slide relative to the
/// parent and a torque component about each direction the body may not turn relative to it:
/// a pin in the plane 2 + 0, a hinge in space 3 + 2, a ball joint 3 + 0, a two-axis joint
/// 3 + 1, a slider in the plane 1 + 1. Constraints the model declares (loops, rolling) are not
/// counted: they add equations and forces of their own.
struct NewtonEulerCount {
    bool planar = false;
    std::size_t rigid_bodies = 0, particles = 0;
    std::size_t equations = 0;
    std::size_t unknowns = 0;  ///< caller_unknowns + force_reactions + torque_reactions
    std::size_t caller_unknowns = 0, force_reactions = 0, torque_reactions = 0;
    std::vector<NewtonEulerJointCount> joints{};
};

/// @throws alembert::ModelError as form_newton_euler_equations does (a body located from nothing).
NewtonEulerCount count_newton_euler_equations(const System& sys,
                                              const std::vector<TimeVariable>& q,
                                              std::size_t caller_unknowns,
                                              const NewtonEulerOptions& options = {});

/// One line comparing the counts with the road-map (one equation per caller unknown):
/// "brute-force Newton–Euler (planar): 9 equations in 9 unknowns (6 joint reactions: 6 force,
/// 0 torque) vs 3 road-map equations".
std::string summarize(const NewtonEulerEquations& ne);

}  // namespace alembert
