// SPDX-License-Identifier: MIT
// Numeric functions from compiled tapes and from plain C functions.
#include "alembert/sim/numeric_function.hpp"

#include <memory>
#include <utility>

#include "alembert/error.hpp"

namespace alembert {

NumericFunction make_tape_function(const SymbolTable& table, const std::vector<ex>& inputs,
                                   const std::vector<ex>& outputs) {
    return make_tape_function(CompiledExpressions(table, inputs, outputs));
}

NumericFunction make_tape_function(CompiledExpressions compiled) {
    auto tape = std::make_shared<const CompiledExpressions>(std::move(compiled));
    NumericFunction f;
    f.input_count = tape->input_count();
    f.output_count = tape->output_count();
    f.operation_count = tape->operation_count();
    f.kind = "tape";
    f.evaluate = [tape](const double* x, double* y) { tape->evaluate(x, y); };
    return f;
}

NumericFunction make_numeric_function(const SymbolTable& table, const std::vector<ex>& inputs,
                                      const std::vector<ex>& outputs, const FunctionMaker& make) {
    if (!make) return make_tape_function(table, inputs, outputs);
    NumericFunction f = make(table, inputs, outputs);
    if (f.input_count != inputs.size() || f.output_count != outputs.size() || !f.evaluate)
        throw InternalError("make_numeric_function(): the function maker returned a function of " +
                            std::to_string(f.input_count) + " inputs and " +
                            std::to_string(f.output_count) + " outputs for " +
                            std::to_string(inputs.size()) + " and " + std::to_string(outputs.size()));
    return f;
}

NumericFunction make_c_function(void (*fn)(const double* inputs, double* outputs),
                                std::size_t input_count, std::size_t output_count) {
    ALEMBERT_CHECK_ARG(fn != nullptr,
                       "make_c_function(): the function pointer is null; pass the "
                       "address of a function void f(const double*, double*)");
    NumericFunction f;
    f.input_count = input_count;
    f.output_count = output_count;
    f.kind = "compiled";
    f.evaluate = fn;
    return f;
}

}  // namespace alembert
