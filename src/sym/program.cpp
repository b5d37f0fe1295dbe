// SPDX-License-Identifier: MIT
// A straight-line program in single-assignment form: value kinds and operation counts.
#include "alembert/sym/program.hpp"

#include <cmath>

namespace alembert {

const char* to_string(ProgramOp op) {
    switch (op) {
        case ProgramOp::combine: return "combine";
        case ProgramOp::sincos: return "sincos";
        case ProgramOp::add: return "add";
        case ProgramOp::sub: return "sub";
        case ProgramOp::mul: return "mul";
        case ProgramOp::div: return "div";
        case ProgramOp::pow: return "pow";
        case ProgramOp::atan2: return "atan2";
        case ProgramOp::neg: return "neg";
        case ProgramOp::sqrt: return "sqrt";
        case ProgramOp::sin: return "sin";
        case ProgramOp::cos: return "cos";
        case ProgramOp::tan: return "tan";
        case ProgramOp::exp: return "exp";
        case ProgramOp::log: return "log";
        case ProgramOp::abs: return "abs";
        case ProgramOp::asin: return "asin";
        case ProgramOp::acos: return "acos";
        case ProgramOp::atan: return "atan";
        case ProgramOp::sinh: return "sinh";
        case ProgramOp::cosh: return "cosh";
        case ProgramOp::tanh: return "tanh";
        case ProgramOp::asinh: return "asinh";
        case ProgramOp::acosh: return "acosh";
        case ProgramOp::atanh: return "atanh";
        case ProgramOp::csgn: return "csgn";
        case ProgramOp::step: return "step";
    }
    return "?";
}

ValueKind StraightLineProgram::kind(std::uint32_t v) const {
    if (v < input_count) return ValueKind::input;
    if (v < first_literal()) return ValueKind::parameter;
    if (v < first_hoisted()) return ValueKind::literal;
    if (v < first_temporary) return ValueKind::hoisted;
    return ValueKind::temporary;
}

std::size_t StraightLineProgram::operation_count(
    const std::vector<ProgramInstruction>& code) const {
    std::size_t n = 0;
    for (const ProgramInstruction& in : code) {
        if (in.op == ProgramOp::sincos) {
            n += 2;
        } else if (in.op == ProgramOp::combine) {
            n += in.b - 1;
            for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                if (kind(terms[k].value) != ValueKind::literal && std::fabs(terms[k].c) != 1) ++n;
        } else {
            ++n;
        }
    }
    return n;
}

std::size_t StraightLineProgram::call_count(const std::vector<ProgramInstruction>& code) const {
    std::size_t n = 0;
    for (const ProgramInstruction& in : code) {
        if (in.op == ProgramOp::sincos)
            n += 2;
        else if (in.op == ProgramOp::pow || in.op == ProgramOp::atan2 || in.op >= ProgramOp::sqrt)
            ++n;
    }
    return n;
}

}  // namespace alembert
