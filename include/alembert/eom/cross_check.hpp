// SPDX-License-Identifier: MIT
// Forming a model by several methods and comparing their solved accelerations.
#pragma once

#include <string>
#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// The outcome of forming one model by several methods.
struct MethodComparison {
    std::vector<std::string> methods;  ///< "road-map", "Kane", "Lagrange", "Newton–Euler"
    int states = 0;                    ///< random states compared
    double max_difference = 0;         ///< largest |q''_method - q''_road-map|, scaled by max(1, |q''|)
    std::vector<double> differences;   ///< the same per method (0 for the road-map itself)
};

/// Forms the equations of motion of `sys` in the coordinates `q` by the planned road-map, by
/// Kane's method, by Lagrange's method and by brute-force Newton–Euler (every joint reaction
/// an unknown, solved for with the accelerations; alembert::form_newton_euler_equations),
/// solves each for the accelerations q'' at `states` pseudo-random states (q, q', specified
/// inputs and unknown load measures drawn from [-1, 1], constants without a value from
/// [0.5, 1.5]; deterministic for a given seed), and reports the largest relative difference
/// from the road-map's. Each method's residuals E (linear in its unknowns x, E = b - A x) are
/// compiled once (alembert::CompiledExpressions); at each state b = E(0) and the columns of A
/// come from evaluations at x = s e_j (s = 2^20), which also check that E is linear in x.
/// @throws alembert::SolveError if a method's coefficient matrix is singular at a drawn
///         state or its equations are not linear in its unknowns, alembert::ModelError if
///         Newton–Euler cannot infer the model's joints.
MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states = 3, unsigned seed = 1);

/// The outcome of comparing the declared joint reactions from road-map rows with brute-force
/// Newton–Euler's.
struct ReactionComparison {
    std::vector<ex> measures;         ///< the loads solved for (inverse dynamics), the
                                      ///< constraint forces, then every declared reaction
                                      ///< measure, reaction by reaction
    int states = 0;                   ///< random states compared
    double max_difference = 0;        ///< largest difference, scaled by max(1, |value|)
    std::vector<double> differences;  ///< the same per measure
};

/// Solves the planned road-map (alembert::plan_roadmap) for its own unknowns and every
/// declared joint reaction measure together and, independently, the brute-force Newton–Euler
/// equations for the same own unknowns and the reactions of the joints it infers (the
/// declared reaction loads set to zero there, so its reactions carry the whole joint load), at
/// `states` pseudo-random states drawn as compare_methods() draws them. The own unknowns are
/// the accelerations (forward dynamics, `loads` empty) or the given `loads` (inverse
/// dynamics: motor torques, applied forces; the accelerations are then drawn with the state,
/// and the loads are compared too). For each declared component R_i d_i it compares d_i . F
/// with d_i . F_NE (force components: F = sum of the reaction's force components, F_NE the
/// force of Newton–Euler's joint of the same child and parent) or d_i . T with
/// d_i . (T_NE + r^{J/P} x F_NE) (torque components, P the reaction's point, J Newton–Euler's
/// joint point).
///
/// Constrained models (closed loops, rolling): `constraint_forces` are the unknown load
/// measures the model's constraints hold (a loop's pin force, a contact's friction force);
/// both methods solve for them with their other unknowns, Newton–Euler with the constraints at
/// the acceleration level as the road-map's constraint rows hold them, and they are compared
/// too. Each drawn state is made to satisfy the constraints first: dependent coordinates by
/// Newton's method, then dependent speeds (and, for inverse dynamics, accelerations) from the
/// constraints' derivatives. `measures` lists the loads, then the constraint forces, then the
/// declared reaction measures.
/// @throws alembert::ModelError if the model declares no joint reaction and no constraint
///         force is given, or Newton–Euler joins a reaction's child to another body than its
///         declared parent; alembert::ArgumentError if a load or constraint force is a reaction measure;
///         alembert::SolveError as compare_methods(), and if no state meeting the constraints
///         is found from 50 draws.
ReactionComparison compare_reactions(const System& sys, const std::vector<TimeVariable>& q,
                                     int states = 3, unsigned seed = 1,
                                     const std::vector<ex>& loads = {},
                                     const std::vector<ex>& constraint_forces = {});

}  // namespace alembert
