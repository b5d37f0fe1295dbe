// SPDX-License-Identifier: MIT
// Compiled numeric evaluation: expressions compiled once into a flat tape of double operations.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "alembert/sym/program.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

namespace detail {

/// One operation of a compiled tape: combine reads r[dst] = sum of c_k r[reg_k] over the terms
/// [a, a + b) of the term list, sincos writes r[dst] = sin(r[a]) and r[b] = cos(r[a]).
using TapeOp = ProgramOp;

/// An instruction of a compiled tape over registers r: r[dst] = r[a] op r[b] (b unused by
/// unary operations; a linear combination reads its terms from a separate list, sincos writes
/// a second result to r[b]).
struct TapeInstruction {
    TapeOp op;
    std::uint32_t dst;
    std::uint32_t a;
    std::uint32_t b;
};

/// A term c r[reg] of a linear combination.
struct TapeTerm {
    double c;
    std::uint32_t reg;
};

}  // namespace detail

/// How CompiledExpressions compiles, beyond its inputs and outputs.
struct CompileOptions {
    /// Symbols passed once per parameter set (see CompiledExpressions, parameters).
    std::vector<ex> parameters{};
    /// Computes sin and cos of a sum a + t from those of a and t by the angle-sum formulas
    /// (sin(a + t) = sin a cos t + cos a sin t, cos(a + t) = cos a cos t - sin a sin t), t the
    /// term compiled last, recursively: the angles q_i + ... + q_j of a planar chain then cost
    /// six arithmetic operations each instead of a sine and a cosine, because the shorter sums
    /// are shared. More operations, less time wherever such sums are many; results differ
    /// from the direct functions by rounding only.
    bool expand_angle_sums = false;
};

/// Expressions of a symbol table compiled once into a flat tape of double-precision
/// operations, then evaluated many times at numbers (cross-checks, simulation, inverse
/// dynamics), orders of magnitude faster than `SymbolTable::evaluate` (GiNaC subs + evalf).
///
/// Compilation:
///  - every distinct subexpression is computed once, across all outputs: GiNaC subtrees are
///    hash-consed (equal `ex` compile to one register), and so are equal operations on equal
///    operands, so an expression whose tree is exponentially large but whose graph is small
///    compiles to a small tape;
///  - named intermediates z = definition reached by the outputs are compiled once each, in
///    dependency order, through their definitions (including derivatives z' made by
///    `SymbolTable::dt`);
///  - constants with a value in the table are folded to numbers unless listed as inputs (an
///    input overrides the table's value), and operations on numbers only are folded;
///  - a sum of three or more terms becomes one linear combination sum c_k t_k (numeric
///    coefficients c_k), evaluated in one tight loop rather than one operation per term;
///  - integer powers become products by repeated squaring (a negative power a division),
///    powers k + 1/2 use sqrt, other powers std::pow;
///  - sin(x) and cos(x) of one argument are computed together.
///
/// Supported: + - * /, powers, sqrt, sin, cos, tan, exp, log, abs, asin, acos, atan,
/// atan2(y, x), sinh, cosh, tanh, asinh, acosh, atanh, csgn (sign: -1, 0, 1) and step
/// (Heaviside: 0, 1/2, 1), real numbers and GiNaC constants such as Pi.
///
/// Evaluation follows IEEE double arithmetic: results agree with `SymbolTable::evaluate` to
/// rounding (terms are summed in another order), and a value outside a function's real domain
/// gives NaN instead of an exception.
///
/// Parameters: symbols listed as parameters are passed once per parameter set
/// (`set_parameters`) instead of at every call. The operations that depend on parameters and
/// numbers only form a prelude, run by `set_parameters`; `evaluate` runs the rest (the body)
/// and reads the prelude's results. Code generators use the same split (`calc_program`):
/// constants kept as named parameters cost nothing per call beyond what folding them would.
///
/// Thread safety: `evaluate(inputs, outputs)` uses a scratch buffer owned by the object, so one
/// object serves one thread at a time; copies are independent, and the overload taking a
/// workspace is safe to call concurrently on one object.
class CompiledExpressions {
public:
    /// An empty tape: no inputs, no outputs.
    CompiledExpressions() = default;

    /// Compiles `outputs` as functions of `inputs` (symbols, in the order their values will be
    /// passed), with the constants, intermediates and time of `table`. The table is read
    /// during construction only.
    /// @throws alembert::ArgumentError if an input is not a symbol or is listed twice, or if an
    ///         output uses a symbol that is neither an input, nor a constant with a value, nor
    ///         an intermediate (the message names the symbol and where it is used);
    ///         alembert::NotImplemented for a function or object that cannot be compiled.
    CompiledExpressions(const SymbolTable& table, std::vector<ex> inputs,
                        const std::vector<ex>& outputs);

    /// As above with `parameters`: symbols (usually constants) whose values are set once per
    /// parameter set with set_parameters() rather than passed at every call. A parameter
    /// starts at its value in the table, or NaN when it has none.
    /// @throws alembert::ArgumentError as above, and if a parameter is not a symbol or is
    ///         listed twice or also as an input.
    CompiledExpressions(const SymbolTable& table, std::vector<ex> inputs,
                        const std::vector<ex>& outputs, std::vector<ex> parameters);

    /// As above with the options (parameters, angle sums) of `options`.
    CompiledExpressions(const SymbolTable& table, std::vector<ex> inputs,
                        const std::vector<ex>& outputs, const CompileOptions& options);

    /// The input symbols, in the order their values are passed.
    const std::vector<ex>& inputs() const { return inputs_; }
    /// Number of inputs.
    std::size_t input_count() const { return inputs_.size(); }
    /// Number of outputs.
    std::size_t output_count() const { return outputs_.size(); }
    /// The parameter symbols, in the order their values are passed to set_parameters().
    const std::vector<ex>& parameters() const { return parameters_; }
    /// Number of parameters.
    std::size_t parameter_count() const { return parameters_.size(); }
    /// The current parameter values.
    std::vector<double> parameter_values() const;
    /// Arithmetic operations and function calls of one evaluation, counted as count_ops counts
    /// a tree: a linear combination of n terms is n - 1 additions plus one multiplication per
    /// coefficient other than +-1. The prelude (see parameters) is not included.
    std::size_t operation_count() const { return operation_count_; }
    /// Operations of the prelude, run once per parameter set (0 without parameters).
    std::size_t prelude_operation_count() const { return prelude_operation_count_; }
    /// Number of instructions of the tape run at every call (a linear combination is one
    /// instruction).
    std::size_t instruction_count() const { return tape_.size(); }

    /// Sets the parameter values (parameter_count() of them, in the order of parameters())
    /// and runs the prelude.
    /// @throws alembert::ArgumentError if `values` has the wrong size.
    void set_parameters(std::span<const double> values);

    /// The compiled program in single-assignment form, for code generators: instructions in
    /// dependency order split into the prelude and the body, the terms of the linear
    /// combinations, the numbers, and the value of each output. Built from the tape in time
    /// linear in its length; inputs and parameters keep their order.
    StraightLineProgram calc_program() const;
    /// Number of doubles a workspace must hold (inputs, numbers and temporaries).
    std::size_t workspace_size() const { return register_count_; }

    /// Evaluates the outputs at `inputs` (input_count() values, in the order of inputs())
    /// into `outputs` (output_count() values). Allocates nothing; uses the object's scratch
    /// buffer, so one object serves one thread at a time.
    void evaluate(const double* inputs, double* outputs) const;
    /// As above with a caller-owned `workspace` of workspace_size() doubles; safe to call
    /// concurrently on one object with distinct workspaces and outputs.
    void evaluate(const double* inputs, double* outputs, double* workspace) const;
    /// The same tape in extended precision (long double; 64-bit significand on x86-64), for
    /// checks whose answer must not be blurred by rounding in large sums (cross-checks of
    /// methods on ill-conditioned models). Numbers of the expressions are stored as doubles.
    /// Allocates its workspace.
    void evaluate_extended(const long double* inputs, long double* outputs) const;
    /// evaluate(inputs, outputs) with the sizes checked (scratch buffer: one thread at a time).
    /// @throws alembert::ArgumentError if a span has the wrong size.
    void evaluate(std::span<const double> inputs, std::span<double> outputs) const;
    /// The outputs at `inputs`, newly allocated (scratch buffer: one thread at a time).
    /// @throws alembert::ArgumentError if `inputs` has the wrong size.
    std::vector<double> evaluate(std::span<const double> inputs) const;

private:
    void check_input_size(std::size_t n) const;

    template <class T>
    void run_prelude(T* workspace) const;
    template <class T>
    void run(const T* inputs, T* outputs, T* workspace) const;

    std::vector<ex> inputs_;
    std::vector<ex> parameters_;
    std::vector<detail::TapeInstruction> prelude_;  // parameter-only: once per parameter set
    std::vector<detail::TapeInstruction> tape_;     // every call
    std::vector<detail::TapeTerm> terms_;  // of the linear combinations of both
    std::size_t operation_count_ = 0;
    std::size_t prelude_operation_count_ = 0;

    // registers: inputs, parameters, numbers, prelude results, then temporaries; fixed_
    // holds the values of [inputs, inputs + fixed_.size()): parameters, numbers, prelude
    std::vector<double> literals_;
    std::vector<double> fixed_;
    std::vector<std::uint32_t> outputs_;  // register of each output
    std::size_t register_count_ = 0;
    mutable std::vector<double> scratch_;
};

}  // namespace alembert
