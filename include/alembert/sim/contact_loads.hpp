// SPDX-License-Identifier: MIT
// Contact loads in simulation: unknown load measures the motion determines, solved with q''.
#pragma once

#include <string>
#include <vector>

#include "alembert/eom/equations.hpp"
#include "alembert/mech/system.hpp"

namespace alembert {

/// The load measures a simulation solves for with the accelerations because the road-map
/// determines them: in minimal coordinates a contact force does no work, so Kane's equations
/// do not hold it, but its free-body row ("release the contact along u") does; a Coulomb
/// friction's normal force |Fn| enters the equations of motion through that measure.
struct ContactLoads {
    /// The measures, in the model's order of declaration.
    std::vector<ex> measures{};
    /// The arguments of abs() in the loads that hold one of `measures` (a friction's normal
    /// force Fn in -mu |Fn| csgn(v.u)): their signs are assumed when the equations are formed
    /// (form_contact_equations) and checked while the run lasts.
    std::vector<ex> abs_arguments{};
};

/// Finds the contact loads of `sys` in coordinates `q`: the load measures (SymbolKind::unknown)
/// that are neither in `inputs` nor in `solved` (constraint forces, declared joint reactions)
/// and that a friction's normal holds (inside abs()) or an expression of `reads` (outputs,
/// stop conditions) depends on, when plan_roadmap with q'', `solved` and them gives each a row.
/// A measure no row determines is left out when it does work in the coordinates (an applied
/// load, such as an idle motor's torque: zero unless given by an input), and refused otherwise.
/// The planner is called once when every candidate has a row; one more time per candidate
/// otherwise, to name those without one.
/// @throws alembert::ModelError naming a friction's normal force or a workless measure read by
///         an output that no row determines, with the fix (give it by an input, apply it as a
///         force on the body it holds, or declare a reaction), prefixed by `who`; the
///         planner's message when the determined measures cannot be solved together.
ContactLoads find_contact_loads(const System& sys, const std::vector<TimeVariable>& q,
                                const std::vector<ex>& solved, const exmap& inputs,
                                const std::vector<ex>& reads, const std::string& who);

/// The road-map of `sys` for the unknowns q'' and `measures` (plan_roadmap, Analysis::dynamics)
/// as residuals, once: form_contact_equations turns them into A x = b for assumed signs.
struct ContactRows {
    std::vector<ex> residuals{};
    std::vector<ex> unknowns{};
};

/// Plans the rows (see ContactRows).
/// @throws as plan_roadmap.
ContactRows plan_contact_rows(const System& sys, const std::vector<TimeVariable>& q,
                              const std::vector<ex>& measures);

/// The rows as A x = b with |a_i| = s_i a_i for each a_i of `abs_arguments` and its assumed
/// sign s_i (+1 or -1) in `signs`: linear in the unknowns where the rows are, once the signs
/// are fixed.
/// @throws alembert::SolveError (form_linear_system) if a row is not linear in the unknowns.
LinearSystem form_contact_equations(const ContactRows& rows, const std::vector<ex>& abs_arguments,
                                    const std::vector<int>& signs);

}  // namespace alembert
