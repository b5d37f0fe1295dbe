// SPDX-License-Identifier: MIT
// Forward simulation of Kane's equations in generalized speeds, with motion constraints.
#pragma once

#include "alembert/eom/kane.hpp"
#include "alembert/sim/simulation.hpp"

namespace alembert {

/// Simulates Kane's equations in chosen generalized speeds (form_kane_equations with
/// KaneOptions::speeds, kinematic equations and motion constraints; Kane & Levinson 1985,
/// ch. 2 and 6). The state is x = (q, u_r), the coordinates and the independent speeds; at
/// each evaluation
///  - the dependent speeds u_s = sum_r A_sr u_r + B_s come from their values
///    (KaneEquations::dependent_speed_values), so the motion constraints hold by
///    construction;
///  - q' = k(q, u_r, t) from the kinematic equations solved for q'
///    (KaneEquations::coordinate_rates);
///  - u_r' from M(q, t) u_r' = f(q, u_r, t) (KaneEquations::dynamics), M factored
///    numerically: LDLT when symmetric positive definite, a partial-pivoting LU otherwise.
/// The load measures are `request.inputs`' formulas of t, q, q' and the speeds (a measure not
/// given is zero), specified quantities `request.specified`'s. Initial values: the
/// coordinates q and the independent speeds u_r (others 0); a dependent speed or a
/// coordinate's rate may be given too, and must then agree with the value the constraints and
/// kinematic equations give (within options.constraint_tolerance): it is checked, not used.
/// Outputs and events are expressions of t, q, q', every speed, the rates u_r' and u_s' and,
/// for coordinates declared to second order, q'' (q'' and u_s' replaced by their expressions
/// in the state and u_r'). The result's table is that of run_simulation; with
/// `request.checks` it adds "energy" (kinetic plus potential) when energy is conserved (the
/// loads without a potential do no work once the inputs are substituted, nothing is
/// specified, and q' and u_s vanish with u_r: no driven motion, constraints without B_s; and
/// the potential energy can be formed: every mass centre located from N_o),
/// one "drift_motion_<i>" column per motion constraint of `kane` (its residual evaluated with
/// the dependent speeds from their values: 0 up to rounding), and one "drift_<name>" column
/// per constraint declared on `sys` (System::add_configuration_constraint, which Kane's
/// equations do not enforce: a configuration constraint whose rate is among the motion
/// constraints drifts with the integration error).
/// The declared constraints must hold at the initial state (residuals, and rates of
/// configuration residuals), and every drift column stays within
/// options.constraint_tolerance, else the run stops, as run_simulation.
/// `sys`'s table gains the time derivatives of the kinematic equations an output of q''
/// needs. request.coordinates and request.constraint_forces are not used (must be empty or
/// `kane`'s coordinates).
/// With auxiliary speeds (KaneOptions::auxiliary_speeds) the motion is that of the dynamical
/// equations (the auxiliary speeds and their rates are zero in it), and the load measures
/// without an input that the auxiliary equations hold (auxiliary_measures) are solved from
/// them at each output row: outputs and events may read them, as constraint forces of the
/// motion (Kane & Levinson 1985, sec. 5.7).
/// @throws alembert::ArgumentError if `kane` has no chosen speeds, if its auxiliary equations
///         do not determine their load measures (not as many measures as equations, or a
///         measure that also acts in the dynamical equations: it does work in the motion), an
///         output or event reads another load measure without an input, an initial value names
///         no coordinate or speed or disagrees with the constraints, or as compile_outputs;
///         alembert::SolveError naming the state where q', u_s, M or f are not finite or M is
///         singular, where a drift column passes the tolerance, or as simulate.
SimulationResult run_speed_simulation(System& sys, const KaneEquations& kane,
                                      const SimulationRequest& request);

/// The load measures Kane's auxiliary equations determine in a simulation: the measures with
/// no entry in `inputs` that the auxiliary equations hold (through intermediates), in the
/// symbol table's order. Empty without auxiliary speeds.
std::vector<ex> auxiliary_measures(const SymbolTable& table, const KaneEquations& kane, const exmap& inputs);

}  // namespace alembert
