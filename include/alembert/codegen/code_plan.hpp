// SPDX-License-Identifier: MIT
// What every emitter prints: the compiled programs of the generated functions and their names.
#pragma once

#include <string>
#include <vector>

#include "alembert/codegen/codegen.hpp"
#include "alembert/sym/program.hpp"

namespace alembert {

/// A named value of the generated code with its unit and a default (parameters).
struct CodeSymbol {
    std::string name;  ///< identifier in the generated code (e.g. "qAp" for qA')
    std::string unit{};
    double value = 0;  ///< default value (parameters only)
};

/// One generated function: its straight-line program and how its inputs are passed.
/// Inputs are always, in order: t, then the arrays listed in `arrays` (each with
/// CodePlan::coordinate_count or load_count entries). Outputs go to `results` in order.
struct CodeFunction {
    std::string name;                 ///< "mass_forcing", "inverse_dynamics", ...
    std::string summary;              ///< one line for its comment
    std::vector<std::string> arrays;  ///< input arrays after t: "q", "qp", "qpp", "u"
    std::vector<std::string> results; ///< output arrays: {"M", "f"}, {"u"}, {"y"}
    std::vector<std::size_t> result_sizes;
    StraightLineProgram program;
    std::vector<std::string> input_names;      ///< identifier of each program input
    std::vector<std::string> parameter_names;  ///< identifier of each program parameter
    bool empty() const { return program.outputs.empty(); }
};

/// Everything an emitter needs, prepared once per model (plan_code): identifiers for each
/// symbol (q, q' as qp, q'' as qpp after MotionGenesis; every name made unique and kept clear
/// of each language's keywords by the emitter), parameters with defaults and units, and the
/// programs of the mass matrix and forcing, inverse dynamics, outputs and load laws, each
/// compiled with the constants as parameters so the constant-only work sits in preludes.
struct CodePlan {
    std::string name;
    std::string source;
    std::string version;
    std::size_t coordinate_count = 0;
    std::size_t load_count = 0;
    std::vector<CodeSymbol> q, qp, qpp;  ///< per coordinate
    std::vector<CodeSymbol> loads;
    std::vector<CodeSymbol> parameters;  ///< the parameters the programs read
    std::vector<CodeSymbol> outputs;     ///< the requested outputs
    /// Constrained models: the constraint forces (unknowns with q''), the constraints' names
    /// and kinds; the mass_forcing function then gives A ((nq + nc) x (nq + nc)) and b of
    /// A (qpp, lambda) = b, its last nc rows the constraints at the acceleration level.
    std::vector<CodeSymbol> constraint_forces;
    std::vector<std::string> constraint_names;
    std::vector<ConstraintKind> constraint_kinds;
    std::size_t constraint_count() const { return constraint_forces.size(); }
    /// Equations in generalized speeds (Kane's with chosen speeds): the state is (q, u_r);
    /// `qp` and `qpp` then hold the independent speeds u_r and their rates u_r', the arrays
    /// "ur" and "urp" of the functions, and `dependent_speeds` the u_s (array "us").
    bool speed_form = false;
    std::vector<CodeSymbol> coordinate_rates;  ///< speed form: q' (named in comments)
    std::vector<CodeSymbol> dependent_speeds;  ///< speed form: u_s
    /// The number of entries of a function's input or result array by its name: "u" the
    /// loads, "ur", "urp" the independent speeds, "us" the dependent ones, "qp" and "qpp" the
    /// coordinates (or the speeds, in speed form outside the functions), others the coordinates.
    std::size_t array_length(const std::string& array) const;
    bool symmetric_mass_matrix = false;
    CodeFunction mass_forcing;      ///< inputs t, q, qp, u; results M (row-major), f
    CodeFunction accelerations;     ///< inputs t, q, qp, u; result qpp (empty if not given)
    CodeFunction mass_matrix;       ///< inputs t, q; result M (row-major; empty if not given)
    CodeFunction bias_forces;       ///< inputs t, q, qp; result bias (empty if not given)
    /// Per requested Jacobian: its position (t, q; result pos), its Jacobian (t, q; result J)
    /// and J' q' (t, q, qp; result Jdqp), in that order.
    std::vector<CodeFunction> jacobian_functions;
    CodeFunction inverse_dynamics;  ///< inputs t, q, qp, qpp; result u (empty if not formed)
    /// d u/d q and d u/d q' at fixed qpp (DynamicsEquations::inverse_dynamics_dq, _dqp):
    /// inputs t, q, qp, qpp; results dtau_dq, dtau_dqp (nu x nq each, row-major). Empty if
    /// not given. With it, `load_coefficients` holds A (nq x nq, row-major) of the residuals
    /// E = b - A u (-I for M qpp + h = u): forward dynamics' derivatives are
    /// d qpp/d q = M^-1 A du/dq and d qpp/d qp = M^-1 A du/dqp at qpp.
    CodeFunction inverse_dynamics_derivatives;
    std::vector<double> load_coefficients;
    /// A is -I (no product needed: d qpp/d q = -M^-1 du/dq)
    bool negated_identity_loads() const;
    /// Joint-reaction measures (DynamicsEquations::reactions): inputs t, q, qp, qpp, u (its
    /// entries for the measures unread); result reaction, one per measure, reaction[k]
    /// the load loads[reaction_loads[k]]. Empty without them.
    CodeFunction reactions;
    std::vector<std::size_t> reaction_loads;
    CodeFunction output_function;   ///< inputs t, q, qp, qpp, u; result y
    CodeFunction load_laws;         ///< inputs t, q, qp; result u (simulation only)
    /// Constrained models: inputs t, q, qp; result e, per constraint its value c (0 for a
    /// motion constraint) and its velocity-level value c' (g for a motion constraint).
    CodeFunction constraint_drift;
    /// Speed form: inputs t, q, ur; results qp (q' = k(q, u_r, t)) and us (the dependent
    /// speeds; empty without motion constraints).
    CodeFunction kinematics;
    CodeFunction dependent_speed_function;
    bool simulation = false;
    SimulationSpec simulation_spec{};

    /// The functions with programs, in the order emitters print them.
    std::vector<const CodeFunction*> functions() const;
};

/// Prepares the programs and names of `equations` (see generate_code for what is formed and
/// what is thrown).
CodePlan plan_code(const SymbolTable& table, const DynamicsEquations& equations,
                   const CodegenOptions& options);

/// Prepares the programs and names of Kane's equations in generalized speeds (see the
/// generate_code overload on KaneEquations).
CodePlan plan_speed_code(const SymbolTable& table, const KaneEquations& kane,
                         const std::vector<ex>& loads, const CodegenOptions& options);

}  // namespace alembert
