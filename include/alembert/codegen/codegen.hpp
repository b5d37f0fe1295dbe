// SPDX-License-Identifier: MIT
// Code generation: standalone C, C++, MATLAB/Octave and Python from equations of motion.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/jacobians.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/mech/constraint.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// A target language of the code generator.
enum class Language {
    c,       ///< C99: NAME.h, NAME.c (and NAME_main.c with a simulation)
    cpp,     ///< C++17: NAME.hpp, NAME.cpp (and NAME_main.cpp)
    matlab,  ///< MATLAB/Octave function files NAME_*.m (the right-hand side runs under ode45)
    python,  ///< Python 3 with NumPy: NAME.py (its rhs runs under scipy.integrate.solve_ivp)
};

/// The word for a language as the command line spells it: "c", "cpp", "matlab", "python".
const char* to_string(Language language);

/// The language named `word` ("c", "cpp" or "c++", "matlab" or "octave", "python").
/// @throws alembert::ArgumentError naming the word and the accepted ones.
Language parse_language(std::string_view word);

/// Alembert's version, as the generated files name it ("0.1.0").
const char* generator_version();

/// A constraint of a closed loop or a rolling contact as the generated code uses it: its value
/// and derivatives (differentiate_constraints forms them). A configuration constraint
/// c(q, t) = 0 holds at the acceleration level as c'' = 0, a motion constraint g(q, q', t) = 0
/// as g' = 0; the generated simulation adds Baumgarte's stabilisation, c'' + 2 a c' + a^2 c = 0
/// and g' + a g = 0, so drift decays at the rate a.
struct CodegenConstraint {
    std::string name;
    ConstraintKind kind = ConstraintKind::configuration;
    ex value;         ///< c, or g for a motion constraint
    ex rate;          ///< c' (linear in q'), or g' (linear in q'') for a motion constraint
    ex acceleration;  ///< c'' (linear in q''), or g' for a motion constraint
};

/// The constraints with their time derivatives (SymbolTable::dt, which names intermediates in
/// `table`, hence not const).
/// @throws alembert::ModelError if a derivative needs more than the declared order.
std::vector<CodegenConstraint> differentiate_constraints(SymbolTable& table,
                                                         const std::vector<Constraint>& constraints);

/// Equations of motion to generate code from: residuals E_i(q, q', q'', loads, t) = 0, one
/// per coordinate, linear in the accelerations q'' and in the load measures. Road-map rows
/// (`residuals_of(rows)`), Kane's residuals (`KaneEquations::residuals`) and Lagrange's all
/// have this form. From it the generator forms
///  - the mass matrix and forcing, M(q, t) q'' = f(q, q', loads, t) (A and b of
///    form_linear_system(residuals, q''), or `mass_forcing` when given);
///  - forward dynamics, q'' = M^-1 f, by a dense Cholesky solve in the generated code when M
///    is symmetric (Kane's and Lagrange's M are; checked at random states), by LU with
///    partial pivoting otherwise; or the explicit `accelerations` when given;
///  - inverse dynamics, the load measures from q, q', q'' (the residuals solved for the
///    loads symbolically, one decoupled block at a time), when there are as many loads as
///    coordinates, or from `inverse_residuals` (one per load) when given: road-map rows for
///    motor torques and joint-reaction measures, more loads than coordinates.
struct DynamicsEquations {
    /// The generalized coordinates q (with q', q'' declared).
    std::vector<TimeVariable> coordinates{};
    /// E_i = 0, one per coordinate.
    std::vector<ex> residuals{};
    /// The load measures (joint torques, forces): inputs of forward dynamics, outputs of
    /// inverse dynamics. Unknowns of the table.
    std::vector<ex> loads{};
    /// M and f already formed (e.g. `KaneEquations::dynamics`), unknowns the q''; formed from
    /// the residuals when absent.
    std::optional<LinearSystem> mass_forcing{};
    /// q'' given explicitly, one per coordinate, as functions of t, q, q', the loads and the
    /// constants (`TreeEquations::accelerations`, the articulated-body recursion); when given,
    /// forward dynamics evaluates them instead of solving M q'' = f, in time linear in the
    /// number of bodies. The mass matrix and forcing are still generated from the residuals.
    std::vector<ex> accelerations{};
    /// Residuals for inverse dynamics, one per load, linear in the loads (road-map rows
    /// `residuals_of(plan_roadmap(sys, q, loads))` with joint-reaction measures among the
    /// loads); when given, inverse dynamics solves these instead of `residuals`.
    std::vector<ex> inverse_residuals{};
    /// Joint-reaction measures among `loads` (System::joint_reactions) that the generated code
    /// computes rather than takes as inputs: non-contributing, they are absent from the
    /// equations of motion, so the load laws cannot give them (an idle motor's 0 would be a
    /// wrong answer). `reaction_residuals` holds their road-map rows, row i for reactions[i],
    /// in the planner's order (`residuals_of(plan_roadmap(sys, q, reactions))`), linear in the
    /// measures; they may hold q'' and the other loads. A `reactions` function then gives them
    /// from t, q, q', q'' and the other loads (the rows solved block by block in their order),
    /// and the simulation writes them at every sample after forward dynamics. Not with
    /// constraints (their forces are solved with q'' instead).
    std::vector<ex> reactions{};
    std::vector<ex> reaction_residuals{};
    /// Closed loops and rolling: the constraints, and the load measures that hold them (a
    /// loop's pin force, a contact's friction force), one per constraint, which appear in the
    /// residuals. With constraints the unknowns are x = (q'', constraint forces): the residuals
    /// and the constraints at the acceleration level form a square system A x = b, linear in
    /// x, solved per call by LU with partial pivoting (C, C++ and Python; `mass_forcing`, `accelerations`
    /// and inverse dynamics are not used).
    std::vector<CodegenConstraint> constraints{};
    std::vector<ex> constraint_forces{};
    /// The mass matrix alone, M(q, t), row by row (coordinates x coordinates), as functions
    /// of t, q and the constants (`TreeEquations::mass_matrix`, the composite-rigid-body
    /// recursion); when given, a `mass_matrix` function is generated (no forcing, no q').
    std::vector<ex> mass_matrix{};
    /// The bias forces alone, h(q, q', t) = C(q, q') q' + g(q), one per coordinate
    /// (`TreeEquations::bias_forces`), so that M q'' + h are the generalized inertia forces
    /// with gravity; when given, a `bias_forces` function is generated (no loads, no q'').
    std::vector<ex> bias_forces{};
    /// The derivatives of inverse dynamics, d u_i/d q_j and d u_i/d q'_j at fixed q'' (loads x
    /// coordinates, row by row), as add_dynamics_derivatives forms them; when given, functions
    /// `inverse_dynamics_derivatives` (t, q, q', q'') and `forward_dynamics_derivatives`
    /// (t, q, q', u: q'' with d q''/d q and d q''/d q') are generated. d u/d q'' is the mass
    /// matrix when the loads enter the equations as M q'' + h = u.
    std::vector<ex> inverse_dynamics_dq{};
    std::vector<ex> inverse_dynamics_dqp{};
};

/// Forms the derivatives of inverse dynamics (DynamicsEquations::inverse_dynamics_dq and
/// inverse_dynamics_dqp) of `equations`: the residuals solved for the loads u(q, q', q''), as
/// generate_code solves them, then differentiated with respect to each q_j and q'_j through
/// the named intermediates (SymbolTable::diff, forward mode: each intermediate's derivative
/// taken once and named), never by expanding them, so the derivatives share the dynamics'
/// intermediates and cost a bounded multiple of the dynamics per coordinate. Needs as many
/// loads as coordinates, each entering the equations with a numeric coefficient (joint
/// torques and forces: forward dynamics' derivatives then follow from these by
/// d q''/d q = M^-1 A du/dq with A the loads' coefficients, -I for M q'' + h = u), and no
/// constraints; equations in generalized speeds are not covered.
/// @throws alembert::ArgumentError naming what does not fit; alembert::SolveError if the
///         residuals are not linear in the loads.
void add_dynamics_derivatives(SymbolTable& table, DynamicsEquations& equations);

/// A quantity the generated code computes on request (an output column of a simulation):
/// any expression of t, q, q', q'', the loads and the constants.
struct CodegenOutput {
    std::string name;  ///< an identifier, e.g. "KE" or "p_NoQ_x"
    ex expression;
    std::string unit{};  ///< printed in comments and CSV headers, e.g. "J"
};

/// A point's or a frame's Jacobian to generate (form_point_jacobian, form_frame_jacobian):
/// functions NAME_<name>_position (t, q), NAME_<name>_jacobian (t, q; rows x nq, row by row)
/// and NAME_<name>_jacobian_dot_rates (t, q, qp; J' q', one per row).
struct CodegenJacobian {
    std::string name;  ///< an identifier, e.g. "flange"
    KinematicJacobian jacobian;
};

/// What the generated simulation program does (Language::c and cpp write a main program with
/// an adaptive Dormand-Prince RK45 integrator; Python and MATLAB a `simulate` function on
/// solve_ivp / ode45). Its CSV has a header row naming each column with its unit.
struct SimulationSpec {
    double final_time = 10;      ///< [s]
    double output_step = 0.01;   ///< [s] rows of the CSV, exactly at these times
    double absolute_tolerance = 1e-9;
    double relative_tolerance = 1e-9;
    std::vector<double> initial_q{};    ///< q(0); zeros when empty
    /// q'(0); zeros when empty. For equations in generalized speeds (KaneEquations), the
    /// independent speeds u_r(0) instead.
    std::vector<double> initial_qp{};
    /// The loads during the simulation, one expression of t, q, q' and constants per load
    /// (a control law, a prescribed torque); zero loads when empty.
    std::vector<ex> load_laws{};
};

/// How code is generated.
struct CodegenOptions {
    /// Prefix of the generated files and identifiers (an identifier: letters, digits, _).
    std::string name = "model";
    /// What the code was generated from (a script path, a model name), named in the header.
    std::string source = "";
    /// The constants kept as named parameters, changeable in the generated code without
    /// regenerating (their arithmetic is done once per parameter set, not per call); the
    /// others are folded into numbers. Absent: every constant the equations use; empty:
    /// none. Each parameter needs a value in the table (its default in the code).
    std::optional<std::vector<ex>> parameters{};
    /// Units by symbol or output name ("L_A" -> "m", "qA" -> "rad", "T_A" -> "N*m"), shown in
    /// comments and CSV headers; a rate's unit is its coordinate's per second.
    std::map<std::string, std::string> units{};
    /// Sines and cosines of sums of angles from those of shorter sums (CompileOptions::
    /// expand_angle_sums): a chain's q_i + ... + q_j cost six operations each instead of two
    /// calls. More operations, less time.
    bool expand_angle_sums = true;
    /// Extra outputs computed by an `outputs` function (and written by the simulation).
    std::vector<CodegenOutput> outputs{};
    /// Point and frame Jacobians, three functions each (CodegenJacobian); C, C++ and Python.
    std::vector<CodegenJacobian> jacobians{};
    /// Also write a complete simulation program (see SimulationSpec).
    bool simulation = false;
    SimulationSpec simulation_spec{};
};

/// What generate_code wrote and what the generated functions cost.
struct GeneratedCode {
    std::vector<std::filesystem::path> files{};  ///< in the order written
    /// Operations per call (as CompiledExpressions::operation_count counts them) of the mass
    /// matrix and forcing, of inverse dynamics (0 when not generated) and of the outputs;
    /// and the operations done once per parameter set (all preludes together).
    std::size_t mass_forcing_operations = 0;
    std::size_t accelerations_operations = 0;  ///< explicit q'' (0 when not given)
    std::size_t mass_matrix_operations = 0;    ///< M alone (0 when not given)
    std::size_t bias_forces_operations = 0;    ///< h alone (0 when not given)
    std::size_t inverse_dynamics_operations = 0;
    /// d u/d q and d u/d q' together (0 when not generated)
    std::size_t inverse_dynamics_derivatives_operations = 0;
    std::size_t outputs_operations = 0;
    std::size_t prelude_operations = 0;
    bool symmetric_mass_matrix = false;  ///< Cholesky (true) or LU (false) in forward dynamics
    bool inverse_dynamics = false;       ///< whether inverse dynamics was generated
    std::size_t constraint_count = 0;    ///< constraints (and constraint forces) of the model
    /// Equations in generalized speeds: the operations of q' = k(q, u_r) and of the dependent
    /// speeds per call (0 otherwise).
    std::size_t kinematics_operations = 0;
    std::size_t dependent_speeds_operations = 0;
};

/// Generates standalone code in `language` for `equations` of the model whose symbols are in
/// `table`, writing the files into `out_dir` (created if missing; each file written to a
/// temporary name and renamed, so a reader never sees half a file). Functions, in every
/// language: default parameters and a context that holds the values computed once per
/// parameter set; the mass matrix and forcing; forward dynamics (accelerations); inverse
/// dynamics (loads from q, q', q''); the joint reactions (`equations.reactions`, from their
/// road-map rows at q''); the requested outputs; the right-hand side of
/// x' = (q', q'') for an integrator; and, with `options.simulation`, a simulation program.
/// Common subexpressions are computed once and numbers folded (CompiledExpressions), so
/// generation time is linear in the size of the reduced program.
///
/// This is the library call behind `alembert codegen MODEL --lang c|cpp|matlab|python --out DIR`.
/// @throws alembert::ArgumentError if the name is not an identifier, the output directory
///         cannot be created or written (naming it and the reason), the counts of the
///         equations do not fit, a parameter has no value, an expression uses a symbol that is
///         neither t, a coordinate, a rate, a load nor a constant, or the simulation
///         specification is malformed; alembert::SolveError if the residuals are not linear
///         in q'' or in the loads, or the loads cannot be solved for.
GeneratedCode generate_code(const SymbolTable& table, const DynamicsEquations& equations,
                            Language language, const std::filesystem::path& out_dir,
                            const CodegenOptions& options = {});

/// Generates standalone code for Kane's equations in generalized speeds (Kane & Levinson
/// 1985, ch. 2 and 6; form_kane_equations with KaneOptions::speeds): the state is
/// x = (q, u_r), the coordinates and the independent speeds, and
///  - q' = k(q, u_r, t) from `kane.coordinate_rates` (the kinematic differential equations
///    with the dependent speeds already replaced),
///  - u_s = sum_r A_sr u_r + B_s from `kane.dependent_speed_values` (the motion constraints
///    solved),
///  - M(q, t) u_r' = f(q, u_r, loads, t) from `kane.dynamics`, solved per call by Cholesky
///    (M symmetric at random states) or LU.
/// The motion constraints hold at every state by construction (the dependent speeds are
/// computed from them), so the right-hand side x' = (k, M^-1 f) is an ordinary differential
/// equation that needs no stabilisation; a configuration constraint written as a motion
/// constraint (the bicycle's front contact height) drifts only by the integration error.
/// `loads` are the load measures the equations hold (inputs); outputs and load laws may hold
/// t, q, q', u_r, u_r', the dependent speeds and their rates, the loads and the constants
/// (q' and the dependent speeds are replaced by their expressions). In C, C++ and Python.
/// @throws alembert::ArgumentError as generate_code above, and if `kane` has no chosen speeds,
///         the language is MATLAB/Octave, or the counts do not fit;
///         alembert::SolveError never (nothing is solved symbolically).
GeneratedCode generate_code(const SymbolTable& table, const KaneEquations& kane,
                            const std::vector<ex>& loads, Language language,
                            const std::filesystem::path& out_dir,
                            const CodegenOptions& options = {});

}  // namespace alembert
