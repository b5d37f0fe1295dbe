// SPDX-License-Identifier: MIT
// A straight-line program in single-assignment form: what code emitters print.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace alembert {

/// One operation of a straight-line program (and of the compiled tape it is read from).
enum class ProgramOp : std::uint8_t {
    combine,  ///< sum of c_k v_k over a range of terms (a linear combination)
    sincos,   ///< sin and cos of one argument, two results
    add, sub, mul, div, pow, atan2,  ///< binary: a op b (atan2(a, b) is atan2(y = a, x = b))
    neg, sqrt, sin, cos, tan, exp, log, abs, asin, acos, atan, sinh, cosh, tanh, asinh, acosh,
    atanh, csgn, step,  ///< unary: f(a); csgn is the sign (-1, 0, 1), step is Heaviside (0, 1/2, 1)
};

/// True for the operations of one operand (neg ... step).
constexpr bool is_unary(ProgramOp op) { return op >= ProgramOp::neg; }

/// The lowercase name of an operation ("add", "sin", ...), as C's <math.h> spells the
/// functions (the operators are named add, sub, mul, div, neg).
const char* to_string(ProgramOp op);

/// What a value of a program is: its number tells (see StraightLineProgram).
enum class ValueKind : std::uint8_t {
    input,      ///< passed at every call
    parameter,  ///< passed once per parameter set
    literal,    ///< a number
    hoisted,    ///< computed by the prelude from parameters and numbers only
    temporary,  ///< computed by the body, at every call
};

/// An instruction: `result` = a op b.
///  - binary operations read values a and b, unary ones a (b equals a);
///  - combine: result = sum of c_k v_k over the terms [a, a + b) of StraightLineProgram::terms;
///  - sincos: result = sin(a) and b = cos(a) (b is a second result, numbered result + 1).
struct ProgramInstruction {
    ProgramOp op;
    std::uint32_t result;
    std::uint32_t a;
    std::uint32_t b;
};

/// A term c v of a linear combination.
struct ProgramTerm {
    double c;
    std::uint32_t value;
};

/// A straight-line program over doubles in single-assignment form: every value is defined
/// once and instructions are in dependency order, so it prints directly as a sequence of
/// `const double` definitions. Values are numbered
///   [0, inputs)                               inputs, in the order they are passed
///   [inputs, inputs + parameters)             parameters, in the order they are passed
///   [.., .. + literals.size())                numbers (literals[k])
///   then the results of the prelude, then those of the body, in instruction order.
/// The prelude depends on parameters and numbers only: it runs once per parameter set. The
/// body runs at every call. An output may be any value (an input, a number, a hoisted value).
/// Read from a CompiledExpressions (calc_program); the compiler has already hash-consed
/// shared subexpressions, folded numbers and turned sums into linear combinations.
struct StraightLineProgram {
    std::size_t input_count = 0;
    std::size_t parameter_count = 0;
    std::vector<double> literals{};
    std::vector<ProgramInstruction> prelude{};
    std::vector<ProgramInstruction> body{};
    std::vector<ProgramTerm> terms{};       ///< of the linear combinations of both parts
    std::vector<std::uint32_t> outputs{};   ///< the value of each output
    std::size_t value_count = 0;            ///< one past the last value
    std::size_t first_temporary = 0;        ///< the first value the body defines

    /// The first literal's number.
    std::size_t first_literal() const { return input_count + parameter_count; }
    /// The first value the prelude defines.
    std::size_t first_hoisted() const { return first_literal() + literals.size(); }
    /// What value `v` is.
    ValueKind kind(std::uint32_t v) const;
    /// The number of a literal value.
    double literal(std::uint32_t v) const { return literals[v - first_literal()]; }

    /// Arithmetic operations and function calls of `code` (prelude or body), counted as
    /// CompiledExpressions::operation_count counts them: a linear combination of n terms is
    /// n - 1 additions plus one product per coefficient other than +-1 (a number term costs
    /// only its addition), sincos is two calls.
    std::size_t operation_count(const std::vector<ProgramInstruction>& code) const;
    /// The function calls of `code` (sin, cos, sqrt, ...; sincos counts two), a subset of its
    /// operation count.
    std::size_t call_count(const std::vector<ProgramInstruction>& code) const;
};

/// Evaluates `p` by interpretation (a reference and a check, not a fast path: use
/// CompiledExpressions or generated code for speed): `inputs` and `parameters` in program
/// order, `outputs` one per program output.
void evaluate(const StraightLineProgram& p, const double* inputs, const double* parameters,
              double* outputs);

/// The linear split of a program whose outputs E_i are linear in some of its inputs x_j
/// (`unknowns`, input positions): a program of the other inputs (in their order) and the same
/// parameters whose outputs are A (row by row, outputs x unknowns) and then b, with
/// E = b - A x (A_ij = -dE_i/dx_j, b_i = E_i at x = 0), the form of
/// alembert::form_linear_system. Each instruction that depends on x is split into its part
/// free of x and its coefficients of the x_j (sums term by term, products and quotients with a
/// factor or divisor free of x), so the cost is linear in the program's length times the
/// number of unknowns each value holds; the prelude is kept as it is.
/// @throws alembert::SolveError naming the output and the unknown (by position) if an output
///         is not linear in the unknowns (a product of two, a function of one).
StraightLineProgram split_linear(const StraightLineProgram& p,
                                 const std::vector<std::size_t>& unknowns);

}  // namespace alembert
