// SPDX-License-Identifier: MIT
// The program read from a compiled tape and its parameter prelude: single assignment, values
// that agree with the tape and with the symbol table, hoisting that costs nothing per call.
#include "alembert/sym/program.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "support/expect.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {

// an interpreter of the program written apart from the tape's, with <cmath> only
std::vector<double> interpret(const StraightLineProgram& p, const std::vector<double>& inputs,
                              const std::vector<double>& parameters) {
    std::vector<double> v(p.value_count, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < p.input_count; ++i) v[i] = inputs[i];
    for (std::size_t i = 0; i < p.parameter_count; ++i) v[p.input_count + i] = parameters[i];
    for (std::size_t k = 0; k < p.literals.size(); ++k) v[p.first_literal() + k] = p.literals[k];
    auto run = [&](const std::vector<ProgramInstruction>& code) {
        for (const ProgramInstruction& in : code) {
            double a = v[in.a], b = in.op == ProgramOp::combine ? 0 : v[in.b], r = 0;
            switch (in.op) {
                case ProgramOp::combine:
                    for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                        r += p.terms[k].c * v[p.terms[k].value];
                    break;
                case ProgramOp::sincos:
                    r = std::sin(a);
                    v[in.b] = std::cos(a);
                    break;
                case ProgramOp::add: r = a + b; break;
                case ProgramOp::sub: r = a - b; break;
                case ProgramOp::mul: r = a * b; break;
                case ProgramOp::div: r = a / b; break;
                case ProgramOp::pow: r = std::pow(a, b); break;
                case ProgramOp::neg: r = -a; break;
                case ProgramOp::sqrt: r = std::sqrt(a); break;
                case ProgramOp::sin: r = std::sin(a); break;
                case ProgramOp::cos: r = std::cos(a); break;
                case ProgramOp::exp: r = std::exp(a); break;
                default: ADD_FAILURE() << "operation " << to_string(in.op) << " not expected";
            }
            v[in.result] = r;
        }
    };
    run(p.prelude);
    run(p.body);
    std::vector<double> out;
    for (std::uint32_t o : p.outputs) out.push_back(v[o]);
    return out;
}

// every value is defined once, after what it reads; prelude values read no input
::testing::AssertionResult single_assignment(const StraightLineProgram& p) {
    std::vector<char> defined(p.value_count, 0);
    for (std::size_t v = 0; v < p.first_hoisted(); ++v) defined[v] = 1;
    auto check = [&](const std::vector<ProgramInstruction>& code, bool prelude) -> std::string {
        for (const ProgramInstruction& in : code) {
            std::vector<std::uint32_t> reads;
            if (in.op == ProgramOp::combine)
                for (std::uint32_t k = in.a; k < in.a + in.b; ++k) reads.push_back(p.terms[k].value);
            else
                reads = in.op == ProgramOp::sincos || is_unary(in.op)
                            ? std::vector<std::uint32_t>{in.a}
                            : std::vector<std::uint32_t>{in.a, in.b};
            for (std::uint32_t r : reads) {
                if (!defined[r]) return "value " + std::to_string(r) + " read before defined";
                if (prelude && p.kind(r) == ValueKind::input) return "prelude reads an input";
            }
            std::vector<std::uint32_t> writes{in.result};
            if (in.op == ProgramOp::sincos) writes.push_back(in.b);
            for (std::uint32_t w : writes) {
                if (defined[w]) return "value " + std::to_string(w) + " defined twice";
                defined[w] = 1;
                if (p.kind(w) != (prelude ? ValueKind::hoisted : ValueKind::temporary))
                    return "value " + std::to_string(w) + " numbered out of its part";
            }
        }
        return "";
    };
    for (auto msg : {check(p.prelude, true), check(p.body, false)})
        if (!msg.empty()) return ::testing::AssertionFailure() << msg;
    for (std::uint32_t o : p.outputs)
        if (!defined[o]) return ::testing::AssertionFailure() << "output " << o << " undefined";
    return ::testing::AssertionSuccess();
}

struct Pendulum {
    // a pendulum's equation, with named intermediates and valued constants
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m", 2.0), L = s.add_constant("L", 0.75), g = s.add_constant("g", 9.81);
    ex z = s.add_intermediate(m * L * L / 3, "I_O");
    std::vector<ex> outputs{z * q.d(2) + m * g * L / 2 * sin(q),
                            pow(cos(q), 2) * L + sin(q) * GiNaC::exp(q.d(1)) - m * q.d(1) / 7,
                            GiNaC::sqrt(m * g) * q.d(1) + 3};
    std::vector<ex> inputs{q, q.d(1), q.d(2)};
    std::vector<double> state{0.7, -1.3, 0.4};
};

}  // namespace

TEST(StraightLineProgram, IsSingleAssignmentAndComputesWhatTheTapeComputes) {
    Pendulum P;
    CompiledExpressions f(P.s, P.inputs, P.outputs);
    StraightLineProgram p = f.calc_program();
    EXPECT_TRUE(single_assignment(p));
    EXPECT_EQ(p.input_count, 3u);
    EXPECT_EQ(p.parameter_count, 0u);
    EXPECT_TRUE(p.prelude.empty());  // constants folded: nothing to hoist
    EXPECT_EQ(p.operation_count(p.body), f.operation_count());
    EXPECT_GE(p.call_count(p.body), 3u);  // sincos (two), exp, and no sqrt (folded)
    std::vector<double> tape = f.evaluate(P.state);
    std::vector<double> prog = interpret(p, P.state, {});
    ASSERT_EQ(prog.size(), 3u);
    exmap at{{P.q.d(0), 0.7}, {P.q.d(1), -1.3}, {P.q.d(2), 0.4}};
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(prog[k], tape[k], 1e-14 * std::max(1.0, std::fabs(tape[k])));
        EXPECT_NEAR(prog[k], P.s.evaluate(P.outputs[k], at), 1e-13);
    }
}

TEST(StraightLineProgram, ParametersHoistTheirArithmeticIntoThePrelude) {
    Pendulum P;
    std::vector<ex> params{P.m, P.L, P.g};
    CompiledExpressions folded(P.s, P.inputs, P.outputs);
    CompiledExpressions kept(P.s, P.inputs, P.outputs, params);
    EXPECT_EQ(kept.parameter_count(), 3u);
    EXPECT_EQ(kept.parameter_values(), (std::vector<double>{2.0, 0.75, 9.81}));
    // m L^2/3, m g L/2, sqrt(m g), m/7 are computed once: per call it costs no more than
    // folding the constants into numbers
    EXPECT_GE(kept.prelude_operation_count(), 4u);
    EXPECT_LE(kept.operation_count(), folded.operation_count());
    StraightLineProgram p = kept.calc_program();
    EXPECT_TRUE(single_assignment(p));
    EXPECT_EQ(p.operation_count(p.prelude), kept.prelude_operation_count());
    EXPECT_EQ(p.operation_count(p.body), kept.operation_count());
    // no body instruction reads parameters, numbers and hoisted values only
    for (const ProgramInstruction& in : p.body) {
        if (in.op == ProgramOp::combine) continue;
        bool fixed = p.kind(in.a) != ValueKind::input && p.kind(in.a) != ValueKind::temporary &&
                     p.kind(in.b) != ValueKind::input && p.kind(in.b) != ValueKind::temporary;
        EXPECT_FALSE(fixed) << to_string(in.op) << " belongs in the prelude";
    }
    // same values as with folded constants, and as the program read from it
    std::vector<double> a = folded.evaluate(P.state), b = kept.evaluate(P.state);
    std::vector<double> c = interpret(p, P.state, kept.parameter_values());
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_NEAR(b[k], a[k], 1e-14 * std::max(1.0, std::fabs(a[k])));
        EXPECT_NEAR(c[k], b[k], 1e-14 * std::max(1.0, std::fabs(a[k])));
    }
}

TEST(StraightLineProgram, NewParameterValuesChangeTheResults) {
    Pendulum P;
    CompiledExpressions kept(P.s, P.inputs, P.outputs, {P.m, P.L, P.g});
    const std::vector<double> values{3.0, 1.25, 1.62};  // a heavier, longer pendulum on the Moon
    kept.set_parameters(values);
    EXPECT_EQ(kept.parameter_values(), values);
    // the same model with those values in another table, evaluated by GiNaC
    SymbolTable t;
    TimeVariable q = t.add_variable("q");
    ex m = t.add_constant("m", 3.0), L = t.add_constant("L", 1.25), g = t.add_constant("g", 1.62);
    ex expected = m * L * L / 3 * q.d(2) + m * g * L / 2 * sin(q);
    exmap at{{q.d(0), 0.7}, {q.d(1), -1.3}, {q.d(2), 0.4}};
    std::vector<double> out = kept.evaluate(P.state);
    EXPECT_NEAR(out[0], t.evaluate(expected, at), 1e-13);
    EXPECT_NEAR(out[2], std::sqrt(3.0 * 1.62) * -1.3 + 3, 1e-14);
    // extended precision runs its own prelude from the same values
    const long double in[3] = {0.7L, -1.3L, 0.4L};
    long double ext[3];
    kept.evaluate_extended(in, ext);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(static_cast<double>(ext[k]), out[k], 1e-13);
}

TEST(StraightLineProgram, AParameterWithoutValueIsNaNUntilSet) {
    SymbolTable s;
    ex x = s.add_constant("x"), k = s.add_constant("k");
    CompiledExpressions f(s, {x}, {k * k * x + 1}, {k});
    EXPECT_TRUE(std::isnan(f.evaluate(std::vector<double>{2.0})[0]));
    f.set_parameters(std::vector<double>{3.0});
    EXPECT_EQ(f.evaluate(std::vector<double>{2.0})[0], 19.0);
}

TEST(StraightLineProgram, MalformedParametersAreRejected) {
    SymbolTable s;
    ex x = s.add_constant("x"), k = s.add_constant("k", 1.0);
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {k * x}, {x}), ArgumentError,
                     "'x' is listed both as an input and as a parameter");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {k * x}, {k, k}), ArgumentError,
                     "'k' is listed twice as a parameter");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {k * x}, {k + 1}), ArgumentError,
                     "parameter 0 ('1+k') is not a symbol");
    CompiledExpressions f(s, {x}, {k * x}, {k});
    EXPECT_THROW_MSG(f.set_parameters(std::vector<double>{1, 2}), ArgumentError,
                     "set_parameters(): 2 values given, 1 expected");
}

TEST(StraightLineProgram, LinearSplitGivesTheCoefficientsAndTheRest) {
    // E = b - A x for E linear in x1, x2 (inside sums, products, quotients and intermediates)
    SymbolTable s;
    ex a = s.add_constant("a"), k = s.add_constant("k", 3.0), x1 = s.add_constant("x1"),
       x2 = s.add_constant("x2");
    ex z = s.add_intermediate(sin(a) * x1 - x2 / k, "z");
    std::vector<ex> E{(cos(a) + 2) * (z + 4 * x2) + a * a, x1 / (1 + a * a) - 7 + z * cos(a)};
    CompiledExpressions f(s, {a, x1, x2}, E, {k});
    StraightLineProgram split = split_linear(f.calc_program(), {1, 2});
    EXPECT_EQ(split.input_count, 1u);
    EXPECT_EQ(split.outputs.size(), 2u * 2u + 2u);
    EXPECT_TRUE(single_assignment(split));
    for (double av : {0.3, -1.2}) {
        std::vector<double> out(6);
        const double kv = 3.0;
        evaluate(split, &av, &kv, out.data());
        // A_ij = -dE_i/dx_j, b_i = E_i at x = 0, by hand
        const double c = std::cos(av), sn = std::sin(av);
        EXPECT_NEAR(out[0], -(c + 2) * sn, 1e-14);
        EXPECT_NEAR(out[1], -(c + 2) * (4 - 1 / kv), 1e-14);
        EXPECT_NEAR(out[2], -(1 / (1 + av * av) + sn * c), 1e-14);
        EXPECT_NEAR(out[3], c / kv, 1e-14);
        EXPECT_NEAR(out[4], av * av, 1e-14);
        EXPECT_NEAR(out[5], -7, 1e-14);
    }
    // a product of unknowns is not linear
    CompiledExpressions g(s, {a, x1, x2}, {x1 * x2 + a});
    EXPECT_THROW_MSG(split_linear(g.calc_program(), {1, 2}), SolveError, "not linear in unknown");
    CompiledExpressions h(s, {a, x1, x2}, {sin(x1)});
    EXPECT_THROW_MSG(split_linear(h.calc_program(), {1, 2}), SolveError, "not linear in unknown 0");
}

TEST(StraightLineProgram, InterpretationAgreesWithTheTape) {
    Pendulum P;
    CompiledExpressions f(P.s, P.inputs, P.outputs, {P.m, P.L, P.g});
    StraightLineProgram p = f.calc_program();
    std::vector<double> params = f.parameter_values(), out(3);
    evaluate(p, P.state.data(), params.data(), out.data());
    std::vector<double> tape = f.evaluate(P.state);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], tape[k], 1e-14 * std::max(1.0, std::fabs(tape[k])));
}
