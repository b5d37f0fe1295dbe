// SPDX-License-Identifier: MIT
// Forward simulation: adaptive integration with dense output, events, outputs.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "alembert/sim/forward_dynamics.hpp"
#include "alembert/sim/integrator.hpp"
#include "alembert/sim/plot.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// A column of simulation output: any expression of the model (a coordinate, a speed, a
/// point's position measure, an energy, a torque, a constraint residual) and the unit to print
/// it in (parse_unit; the expression is in SI, the column is divided by the unit's factor).
struct OutputSpec {
    std::string name{};
    ex expression{};
    std::string unit{};
    /// SI value per unit of `unit` (value_SI = factor * printed). 0: parse_unit(unit) gives it;
    /// a front end with its own unit system (the language layer) states it and any unit text.
    double factor = 0.0;
};

/// Which zero crossings of an event expression stop the run.
enum class EventDirection { any, rising, falling };

/// An event: the run stops where `expression` crosses zero (in `direction`), located by
/// bisection on the integrator's dense output.
struct EventSpec {
    std::string name{};
    ex expression{};
    EventDirection direction = EventDirection::any;
};

/// Integration settings (SI units).
struct SimulationOptions {
    double t_initial = 0.0;
    double t_final = 1.0;
    /// The integration method (see Integrator): Dormand-Prince 5(4) by default; rkf78 or
    /// bulirsch_stoer for tight tolerances, bdf for stiff models.
    Integrator integrator = Integrator::dopri5;
    /// Output every output_step from t_initial to t_final (t_final included).
    double output_step = 0.01;
    /// Output exactly at these times instead (sorted, within [t_initial, t_final]).
    std::vector<double> output_times{};
    /// Error tolerances per step: |err_i| <= abs_tol + rel_tol |x_i| (odeint's controller).
    double abs_tol = 1e-8;
    double rel_tol = 1e-8;
    /// First step tried; 0: output_step / 100 (the controller adapts it at once).
    double initial_step = 0.0;
    /// Stop with SolveError after this many steps (a stiff or singular model).
    std::size_t max_steps = 50'000'000;
    /// Refuse (ArgumentError, before integrating) a run whose output times would make more
    /// rows than this: a tiny output step over a long run would otherwise fill the memory.
    /// Raise it for long runs that need every row; a row takes 8 bytes per column.
    std::size_t max_output_rows = 1'000'000;
    /// Largest residual (SI: m, rad, m/s, ...) a declared constraint may have at the initial
    /// state (configuration residuals, their rates, motion residuals) and in the drift columns
    /// during the run; beyond it run_simulation refuses the initial values or stops with the
    /// time and the residual.
    double constraint_tolerance = 1e-6;
    /// Progress line on a terminal for runs longer than a second.
    bool progress = true;
};

/// Output columns as one NumericFunction over
///   inputs  [t, q_1..q_n, q_1'..q_n', x_1..x_k (the unknowns: q'' and constraint forces),
///            input_1..input_m]
///   outputs one value per column, in SI (divide by factors[c] to print).
struct OutputFunction {
    NumericFunction function{};
    std::vector<std::string> names{};
    std::vector<std::string> units{};
    std::vector<double> factors{};
};

/// Compiles `outputs` over the layout of a forward dynamics (see OutputFunction).
/// @throws alembert::ArgumentError naming an output with an unknown unit or a symbol that is
///         not in the layout (nor a constant with a value).
OutputFunction compile_outputs(const SymbolTable& table, const StateLayout& layout,
                               const std::vector<OutputSpec>& outputs,
                               const FunctionMaker& make = {});

/// Event expressions as one NumericFunction over the same inputs as OutputFunction.
struct EventFunction {
    NumericFunction function{};
    std::vector<std::string> names{};
    std::vector<EventDirection> directions{};
};

/// Compiles `events` over the layout of a forward dynamics.
/// @throws alembert::ArgumentError as compile_outputs.
EventFunction compile_events(const SymbolTable& table, const StateLayout& layout,
                             const std::vector<EventSpec>& events, const FunctionMaker& make = {});

/// The run-time inputs (load measures such as motor torques, in layout().inputs order) at a
/// state: a controller, or a prescribed torque history.
using InputFunction =
    std::function<void(double t, const double* q, const double* qd, double* inputs)>;

/// What a simulation produced.
struct SimulationResult {
    /// Column "t [s]", then the outputs in their units, one row per output time reached (and a
    /// last row at the event time when an event stopped the run).
    Table table{};
    /// Empty if the run reached t_final; else the name of the event that stopped it.
    std::string stopped_by{};
    double t_end = 0.0;
    std::vector<double> q_end{}, qd_end{};  ///< state at t_end (SI)
    /// run_speed_simulation: the independent speeds u_r at t_end (SI); qd_end then holds the
    /// coordinates' rates from the kinematical equations there.
    std::vector<double> u_end{};
    std::size_t steps = 0;                  ///< accepted steps
    /// run_simulation: empty, or why the run stopped early because a contact load it solves
    /// for changed sign (stopped_by then reads "contact lost: 'N_w' changes sign"): the measure,
    /// the time and the state. The table ends at that instant; the motion after it is not the
    /// model's (the contact would pull), so a front end reports it as an error.
    std::string contact_lost{};
    /// run_simulation: true if q'' came from the recursive tree formation (explicit
    /// accelerations, no solve), false for the dense equations A x = b.
    bool recursive = false;
};

/// Integrates the forward dynamics `fd` from q(t_initial) = q0, q'(t_initial) = qd0 with
/// options.integrator (Dormand-Prince 5(4) by default) under error control and dense output:
/// outputs are interpolated exactly at the requested times (each method's dense output),
/// events are checked at every accepted step and located by bisection on the dense
/// output to 1e-12 s (a sign change inside one step is found; two crossings inside one step
/// cancel). `inputs` gives the run-time inputs (empty: all zero). `check_row`, if given, sees
/// each output row as it is written (the table so far and the row's index) and stops the run
/// by throwing (run_simulation's constraint drift check).
/// @throws alembert::ArgumentError for bad options or state sizes (named), or more output
///         rows than options.max_output_rows (checked up front: calc_output_row_count);
///         alembert::SolveError naming the model and the time if the dynamics fail (singular
///         mass matrix) or the step count exceeds options.max_steps; what check_row throws.
SimulationResult simulate(const ForwardDynamics& fd, const std::vector<double>& q0,
                          const std::vector<double>& qd0, const SimulationOptions& options,
                          const OutputFunction& outputs, const EventFunction& events = {},
                          const InputFunction& inputs = {},
                          const std::function<void(const Table&, std::size_t)>& check_row = {});

/// The number of output rows `options` asks for from t_initial to t_final (output_times, or
/// one every output_step with t_final included), computed without listing them.
/// @throws alembert::ArgumentError naming `who`, the step, the span and the limit if it
///         exceeds options.max_output_rows (or the output step is not positive).
double calc_output_row_count(const SimulationOptions& options, const std::string& who);

/// Everything a script's simulation statements state, for run_simulation.
struct SimulationRequest {
    /// The model's name in messages and the progress line.
    std::string model = "model";
    std::vector<TimeVariable> coordinates{};
    /// Load measures solved with the accelerations in a constrained model (closed loop's pin
    /// force); see compile_forward_dynamics.
    std::vector<ex> constraint_forces{};
    /// Values of the other load measures as formulas of t, q, q' (a motor law); a load
    /// measure of the model not given here is zero, except a measure of a declared joint
    /// reaction that an output or event reads, and a contact load the road-map determines
    /// (find_contact_loads: a friction's normal force, a contact force an output or event
    /// reads): they are solved for with the accelerations.
    exmap inputs{};
    /// Values of specified symbols and of the derivatives of them the model uses, as formulas
    /// of t, q, q' (a driven base motion x_b = 0.1*sin(2*pi*t), x_b' and x_b''); substituted
    /// into the equations, outputs and events.
    exmap specified{};
    /// Initial values (SI) of coordinates q_i and rates q_i'; those not given are 0.
    exmap initial_values{};
    std::vector<OutputSpec> outputs{};
    std::vector<EventSpec> events{};
    SimulationOptions options{};
    /// Add the checks users rely on: "energy [J]" (kinetic plus potential) when the model is
    /// conservative (no non-conservative generalized force once the inputs are substituted),
    /// and one "drift_<name>" column per declared constraint (its residual).
    bool checks = true;
    /// The evaluator of the dynamics, outputs and events (empty: the tape; see FunctionMaker).
    FunctionMaker make{};
    /// The SI unit of each constraint's residual by constraint name ("m" for a loop closed by
    /// positions), for the drift columns' headers and messages; a constraint not listed has
    /// its residual printed without a unit.
    std::map<std::string, std::string> constraint_units{};
};

/// Forms the forward dynamics of `sys`, compiles outputs, checks and events, and simulates.
/// A model without constraints whose bodies form a tree in relative coordinates
/// (form_tree_equations_if_tree) is integrated on its explicit accelerations from the
/// articulated-body recursion, with the load measures evaluated from their formulas at each
/// call; any other model on compile_forward_dynamics' equations with the inputs substituted.
/// The measures of declared joint reactions (System::add_joint_reaction) that an output or an
/// event reads are solved for at each step with the accelerations, from the road-map's
/// reaction rows (they do no work, so Kane's equations alone do not hold them). So are the
/// contact loads (find_contact_loads), from the rows of plan_roadmap with q'' and them, with
/// |a| = s a for each abs() argument a that holds one (a friction's normal force), the sign s
/// taken from the solution at the initial state; each contact load and s a is watched as an
/// event from its sign at the start, and where one crosses zero the run stops there with
/// SimulationResult::contact_lost set (the contact is lost). The declared constraints must hold at
/// the initial state (their residuals, the rates of configuration residuals, within
/// options.constraint_tolerance): the initial values are not moved onto them silently; and
/// their drift columns must stay within the same tolerance during the run.
/// @throws as compile_forward_dynamics, compile_outputs and simulate; alembert::ArgumentError
///         naming the constraint and its residual (with its unit) if the initial state
///         violates it; alembert::SolveError naming the constraint, the time and the residual
///         if its drift grows beyond the tolerance; as find_contact_loads; alembert::SolveError
///         naming a friction's normal force that is zero at the initial state, or abs()
///         arguments whose signs no pass makes agree with the solution there.
SimulationResult run_simulation(const System& sys, const SimulationRequest& request);

/// Writes `table` to `dir`/`name`.csv (atomically) and plots it to `dir`/`name`.png and .svg
/// (plot_csv; the first column along the horizontal axis). Creates `dir` if needed.
/// @throws alembert::ArgumentError if the CSV cannot be written.
PlotResult write_table_and_plot(const Table& table, const std::string& dir, const std::string& name,
                                const PlotOptions& options = {});

}  // namespace alembert
