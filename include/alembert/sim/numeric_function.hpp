// SPDX-License-Identifier: MIT
// A numeric function y = F(x) behind one call, so a compiled tape or generated code can serve.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "alembert/sym/evaluator.hpp"

namespace alembert {

/// A numeric function y = F(x) of fixed sizes, called as `evaluate(x, y)` with
/// `void(const double* inputs, double* outputs)`: reads input_count doubles, writes
/// output_count doubles. The sim layer evaluates every model quantity through this interface,
/// so a compiled tape (make_tape_function) and a function of generated C code loaded with
/// dlopen (`extern "C" void f(const double*, double*)`, wrapped by make_c_function) are
/// interchangeable. The order of inputs and outputs is fixed by whoever builds the function
/// and documented there (ForwardDynamics, InverseDynamics, OutputFunction).
///
/// One call at a time per object (a tape reuses its scratch buffer); copies share the
/// underlying tape.
struct NumericFunction {
    std::size_t input_count = 0;
    std::size_t output_count = 0;
    /// Arithmetic operations and function calls per call, when known (0 otherwise).
    std::size_t operation_count = 0;
    /// What evaluates: "tape" or "compiled" (for messages and benchmarks).
    std::string kind{};
    std::function<void(const double* inputs, double* outputs)> evaluate{};
};

/// `outputs` as functions of `inputs` (symbols, in order), compiled to a CompiledExpressions
/// tape with the constants and intermediates of `table`; constants with values are folded, so
/// a changed constant needs a new function (compile once per parameter set).
/// @throws as CompiledExpressions' constructor.
NumericFunction make_tape_function(const SymbolTable& table, const std::vector<ex>& inputs,
                                   const std::vector<ex>& outputs);
/// The same for a tape already compiled (its inputs and outputs in its order).
NumericFunction make_tape_function(CompiledExpressions tape);

/// How the sim layer turns expressions into a NumericFunction: `outputs` as functions of
/// `inputs` (symbols, in order) with the constants and intermediates of the table. The
/// default is make_tape_function; a front end that can compile native code (the codegen
/// layer's NativeExpressions, wired in by the language layer) passes its own.
using FunctionMaker = std::function<NumericFunction(
    const SymbolTable& table, const std::vector<ex>& inputs, const std::vector<ex>& outputs)>;

/// `make(table, inputs, outputs)`, or make_tape_function when `make` is empty.
NumericFunction make_numeric_function(const SymbolTable& table, const std::vector<ex>& inputs,
                                      const std::vector<ex>& outputs, const FunctionMaker& make);

/// A plain C function (such as one loaded from generated code) with the stated sizes.
/// @throws alembert::ArgumentError if `fn` is null.
NumericFunction make_c_function(void (*fn)(const double* inputs, double* outputs),
                                std::size_t input_count, std::size_t output_count);

}  // namespace alembert
