// SPDX-License-Identifier: MIT
// Equations of motion of a tree of bodies formed recursively: road-map rows about successive
// joints (inverse dynamics in O(n)) and the articulated-body accelerations (O(n) forward dynamics).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "alembert/mech/free_joint.hpp"
#include "alembert/mech/system.hpp"

namespace alembert {

/// One body of a tree and the joint that connects it to its parent.
struct TreeJoint {
    const Body* body = nullptr;
    /// The body it hangs from (nullptr: the Newtonian frame).
    const Body* parent = nullptr;
    /// The point the recursion refers the body's motion and loads to: the topmost point of the
    /// body on the path from its mass centre towards N_o (B_o for a rigid body declared with
    /// add_rigid_body and located from its parent, the particle itself for a particle).
    const Point* origin = nullptr;
    /// Indices into the coordinates of the joint's own coordinates: those that move the body
    /// relative to its parent (none for a body welded to its parent). With chosen speeds
    /// (TreeEquations::speeds), indices into the speeds instead.
    std::vector<std::size_t> coordinates{};
};

/// Equations of motion formed recursively on the tree of bodies (see form_tree_equations).
struct TreeEquations {
    /// The bodies, parents before children.
    std::vector<TreeJoint> joints{};
    /// The speeds u the rows and accelerations are formed for, in order: the coordinates'
    /// rates q' (the default), or the speeds chosen (a free or ball joint's angular velocity).
    std::vector<ex> speeds{};
    /// One residual per coordinate, in the order of the coordinates: for a coordinate q_r of the
    /// joint of body B, the road-map row with system S = B and every body beyond it, about B's
    /// origin O, in the direction of the joint's motion,
    ///     E_r = F_r - (dw_r . M*^{S/O} + dv_r . F*^S),
    /// where F*^S and M*^{S/O} (the system's inertia force and moment about O, gravity
    /// included) are accumulated from the tip inward, each joint's from its children's, and
    /// dw_r, dv_r are the joint's partial angular velocity and partial velocity of O. F_r is the
    /// generalized active force of the loads external to S (gravity is in the inertia terms);
    /// a joint's motor torque enters its own rows only, with exact number coefficients. A
    /// declared joint reaction (System::add_joint_reaction) that does no work, its measures
    /// changing no row at random states, is left out of the rows and of the accelerations,
    /// which then do not hold its measures. The rows equal Kane's
    /// equations with u = q' and are linear in q'' and the loads; each body's kinematics,
    /// inertia forces and accumulated sums are named intermediates, so their size grows
    /// linearly in the number of bodies.
    std::vector<ex> residuals{};
    /// q'' explicitly, one per coordinate in their order, as functions of t, q, q', the load
    /// measures and the constants: Featherstone's articulated-body recursion done symbolically
    /// (articulated inertias and bias forces inward, accelerations outward), every step a named
    /// intermediate; it needs no mass matrix and no linear solve.
    std::vector<ex> accelerations{};
    /// The mass matrix M(q) alone, row by row (formed with TreeOptions::mass_matrix; empty
    /// otherwise) (speeds x speeds, symmetric): Featherstone's
    /// composite-rigid-body recursion (2008, sec. 6.2) done symbolically. Composite inertias
    /// I^c_B = I_B + sum over children C of X_C^T I^c_C X_C are accumulated from the tip
    /// inward; for each partial motion S_r of joint B, F = I^c_B S_r is carried towards the
    /// root, M_sr = S_s . F for every joint on the way (zero for joints on other branches).
    /// Every step is a named intermediate; M does not depend on q', the loads or gravity. Each
    /// X^T I^c X is formed as a rotation and a parallel-axis shift, so M equals the rows' mass
    /// matrix where every R_PB is a rotation (Euler parameters of unit length).
    std::vector<ex> mass_matrix{};
    /// The bias forces alone, one per speed (with TreeOptions::mass_matrix; empty otherwise): h(q, u) = C(q, u) u + g(q), the generalized
    /// inertia forces at u' = 0 (the rows' recursion with no accelerations of the speeds,
    /// gravity through the base acceleration -g), so that residuals = F - (M u' + h) with F
    /// the generalized active forces of the loads.
    std::vector<ex> bias_forces{};
};

/// What the recursive formation forms besides the rows and the accelerations.
struct TreeOptions {
    /// Also the mass matrix alone and the bias forces alone (TreeEquations::mass_matrix,
    /// bias_forces): O(n d) more intermediates for n joints at depth up to d (an 80-link
    /// chain's formation takes about 2.3 times as long).
    bool mass_matrix = false;
};

/// Why the recursive formation does not apply to `sys` in the coordinates `q`, or "" when it
/// does. It needs: no constraints; every body and particle hanging from exactly one parent (the
/// body owning the first point on the path of its origin towards N_o, or N); each coordinate
/// moving exactly one body relative to its parent (relative coordinates, as joint angles are;
/// absolute angles tie every body to the coordinates of those below it); each rigid body's
/// mass centre fixed in its frame. Road-map, Kane's and Lagrange's equations need none of this.
std::string explain_not_tree(const System& sys, const std::vector<TimeVariable>& q);

/// Forms the tree's residuals and explicit accelerations (TreeEquations); uniform gravity
/// enters as an acceleration -g of N (exactly the weight of every body). Cost and size grow
/// linearly in the number of bodies (the planar n-link chain's inverse dynamics is a few dozen
/// operations per link, its forward dynamics about a hundred).
/// @throws alembert::ModelError with explain_not_tree's reason if the model is not such a tree.
TreeEquations form_tree_equations(const System& sys, const std::vector<TimeVariable>& q,
                                  const TreeOptions& options = {});

/// The same equations in chosen speeds u (one row and one rate u' per speed, in their order):
/// each u a symbol with a declared derivative (SymbolTable::add_variable(name, 1)) that the
/// angular velocity of a frame is set in with Frame::set_ang_vel, or a coordinate's rate q'.
/// Each joint owns the speeds whose rates its body's relative accelerations hold; the joint's
/// partial motions are the derivatives of those accelerations by the u'. The rows equal Kane's
/// equations in these speeds (Kane 1985, sec. 2.12) and are linear in the u'. The kinematic
/// equations q' = k(q, u) are the caller's (FreeJoint::coordinate_rates and
/// BallJoint::coordinate_rates for the free and ball joints).
/// @throws alembert::ArgumentError if a speed is not such a symbol; alembert::ModelError if
///         the model is not a tree (explain_not_tree) or a speed moves no joint or two.
TreeEquations form_tree_equations(const System& sys, const std::vector<TimeVariable>& q,
                                  const std::vector<ex>& speeds, const TreeOptions& options = {});

/// The same equations, or nothing where explain_not_tree would give a reason: for callers that
/// fall back to other methods, with the tree found once.
std::optional<TreeEquations> form_tree_equations_if_tree(const System& sys,
                                                         const std::vector<TimeVariable>& q,
                                                         const TreeOptions& options = {});

}  // namespace alembert
