// SPDX-License-Identifier: MIT
// Loads: forces at points and torques on bodies, with the body they act on and come from.
#pragma once

#include <string>
#include <vector>

#include "alembert/vec/vector.hpp"

namespace alembert {

class Body;
class Point;

/// Whether a load is a force (bound to a point of application) or a torque (a couple).
enum class LoadKind { force, torque };

/// One load: a force applied at a point, or a torque, acting on one body and exerted by
/// another (or by the surroundings).
///
/// Action/reaction pairs are stored as two loads whose `on` and `from` are swapped, so a
/// system that holds both bodies of a pair sees neither: loads between members of a system
/// are internal and are left out of its resultants.
struct Load {
    LoadKind kind = LoadKind::force;
    std::string label;           ///< the user's name for the load ("T_A", "spring k1")
    const Point* point = nullptr;  ///< point of application (forces only)
    Vector vector;               ///< the force or torque vector
    const Body* on = nullptr;    ///< the body it acts on
    const Body* from = nullptr;  ///< the body exerting it; nullptr for the surroundings
    /// True if the load derives from a potential the System accounts for in
    /// calc_potential_energy() (springs, inverse-square gravity); Lagrange's method takes
    /// such loads through the potential energy instead of generalized forces.
    bool conservative = false;
};

/// One measure of a joint reaction: the unknown times a direction (a force along it or a
/// torque about it).
struct ReactionComponent {
    ex measure{};        ///< the unknown symbol, e.g. F_AB_x
    Vector direction{};  ///< the vector it multiplies (a unit vector where one was found)
    LoadKind kind = LoadKind::force;
};

/// A joint reaction the user declares: the force sum R_i d_i (force components) that the
/// parent exerts on the child at the point `at`, with the torque sum R_j d_j (torque
/// components), and their opposites on the parent. Its measures R are unknowns a road-map
/// solves for (alembert::plan_roadmap gives each its own row).
struct JointReaction {
    std::string name;                           ///< the user's name for the joint ("knee")
    const Body* parent = nullptr;               ///< the body exerting it; nullptr for the ground
    const Body* child = nullptr;                ///< the body it acts on
    const Point* at = nullptr;                  ///< where the force acts (the joint)
    std::vector<ReactionComponent> components;  ///< force components, then torque components
};

}  // namespace alembert
