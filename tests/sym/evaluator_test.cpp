// SPDX-License-Identifier: MIT
// Compiled expressions agree with hand computation and with SymbolTable::evaluate.
#include "alembert/sym/evaluator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "alembert/error.hpp"
#include "support/expect.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {

constexpr double kPi = std::numbers::pi;

// one output, one call
double eval1(const SymbolTable& s, const std::vector<ex>& inputs, const ex& e,
             const std::vector<double>& at) {
    return CompiledExpressions(s, inputs, {e}).evaluate(at).at(0);
}

// |a - b| within `tol` relative to the larger magnitude (absolute below 1)
::testing::AssertionResult close(double a, double b, double tol) {
    double scale = std::max({1.0, std::fabs(a), std::fabs(b)});
    if (std::fabs(a - b) <= tol * scale) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a << " vs " << b << " (difference " << a - b << ")";
}

}  // namespace

// ---- hand-computed values ---------------------------------------------------------------------

TEST(CompiledExpressions, PolynomialMatchesHandComputation) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    // 2^3 - 2*2*3 + 3^2/4 + 7 = 8 - 12 + 2.25 + 7
    ex p = pow(x, 3) - 2 * x * y + pow(y, 2) / 4 + 7;
    EXPECT_DOUBLE_EQ(eval1(s, {x, y}, p, {2, 3}), 5.25);
    // (3 + 1)/(3 - 1)^2 = 1 and (x - y)(x + y) at (5, 3) = 16
    CompiledExpressions f(s, {x, y}, {(x + 1) / pow(x - 1, 2), (x - y) * (x + y), -x - y});
    EXPECT_EQ(f.evaluate(std::vector<double>{3, 0}).at(0), 1.0);
    std::vector<double> out = f.evaluate(std::vector<double>{5, 3});
    EXPECT_EQ(out[1], 16.0);
    EXPECT_EQ(out[2], -8.0);
}

TEST(CompiledExpressions, TrigonometricIdentitiesHold) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    CompiledExpressions f(s, {x, y},
                          {pow(sin(x), 2) + pow(cos(x), 2), sin(2 * x) - 2 * sin(x) * cos(x),
                           GiNaC::tan(x) - sin(x) / cos(x),
                           pow(GiNaC::cosh(x), 2) - pow(GiNaC::sinh(x), 2),
                           GiNaC::exp(GiNaC::log(y)), sin(x), GiNaC::atan2(y, x)});
    for (double a : {0.1, 0.7, 2.5, -1.3}) {
        std::vector<double> v = f.evaluate(std::vector<double>{a, 4.5});
        EXPECT_NEAR(v[0], 1.0, 1e-15);
        EXPECT_NEAR(v[1], 0.0, 1e-15);
        EXPECT_NEAR(v[2], 0.0, 1e-14);
        EXPECT_NEAR(v[3], 1.0, 1e-14);
        EXPECT_NEAR(v[4], 4.5, 1e-14);
    }
    EXPECT_NEAR(f.evaluate(std::vector<double>{kPi / 6, 1})[5], 0.5, 1e-15);
    // atan2(y, x) takes the quadrant from both signs
    EXPECT_NEAR(f.evaluate(std::vector<double>{-1, 1})[6], 3 * kPi / 4, 1e-15);
    EXPECT_NEAR(f.evaluate(std::vector<double>{-1, -1})[6], -3 * kPi / 4, 1e-15);
    EXPECT_NEAR(f.evaluate(std::vector<double>{1, -1})[6], -kPi / 4, 1e-15);
}

TEST(CompiledExpressions, SineAndCosineOfOneAngleAreComputedTogether) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    // x + y, then sin and cos of it (counted as two calls), then the product
    CompiledExpressions f(s, {x, y}, {cos(x + y) * sin(x + y), sin(x + y), cos(x + y)});
    EXPECT_EQ(f.operation_count(), 4u);
    std::vector<double> v = f.evaluate(std::vector<double>{0.4, 0.9});
    EXPECT_EQ(v[1], std::sin(0.4 + 0.9));
    EXPECT_EQ(v[2], std::cos(0.4 + 0.9));
    EXPECT_EQ(v[0], v[1] * v[2]);
}

TEST(CompiledExpressions, EverySupportedFunctionMatchesStdAndSymbolTable) {
    SymbolTable s;
    ex x = s.add_constant("x");
    struct Case {
        const char* name;
        ex e;
        std::function<double(double)> f;
        double at;
    };
    const std::vector<Case> cases{
        {"sin", sin(x), [](double a) { return std::sin(a); }, 0.4},
        {"cos", cos(x), [](double a) { return std::cos(a); }, 0.4},
        {"tan", GiNaC::tan(x), [](double a) { return std::tan(a); }, 0.4},
        {"exp", GiNaC::exp(x), [](double a) { return std::exp(a); }, 0.4},
        {"log", GiNaC::log(x), [](double a) { return std::log(a); }, 0.4},
        {"abs", GiNaC::abs(x), [](double a) { return std::fabs(a); }, -0.4},
        {"asin", GiNaC::asin(x), [](double a) { return std::asin(a); }, 0.4},
        {"acos", GiNaC::acos(x), [](double a) { return std::acos(a); }, 0.4},
        {"atan", GiNaC::atan(x), [](double a) { return std::atan(a); }, 0.4},
        {"atan2", GiNaC::atan2(x, x - 1), [](double a) { return std::atan2(a, a - 1); }, 0.4},
        {"sinh", GiNaC::sinh(x), [](double a) { return std::sinh(a); }, 0.4},
        {"cosh", GiNaC::cosh(x), [](double a) { return std::cosh(a); }, 0.4},
        {"tanh", GiNaC::tanh(x), [](double a) { return std::tanh(a); }, 0.4},
        {"asinh", GiNaC::asinh(x), [](double a) { return std::asinh(a); }, 0.4},
        {"acosh", GiNaC::acosh(x), [](double a) { return std::acosh(a); }, 1.4},
        {"atanh", GiNaC::atanh(x), [](double a) { return std::atanh(a); }, 0.4},
        {"sqrt", GiNaC::sqrt(x), [](double a) { return std::sqrt(a); }, 0.4},
        {"x^y", pow(x, x), [](double a) { return std::pow(a, a); }, 0.4},
        {"Pi", GiNaC::Pi * x, [](double a) { return kPi * a; }, 0.4},
    };
    for (const Case& c : cases) {
        CompiledExpressions f(s, {x}, {c.e});
        double v = f.evaluate(std::vector<double>{c.at}).at(0);
        EXPECT_TRUE(close(v, c.f(c.at), 1e-15)) << c.name;
        EXPECT_TRUE(close(v, s.evaluate(c.e, {{x, c.at}}), 1e-14)) << c.name;
        EXPECT_GE(f.operation_count(), 1u) << c.name;
    }
}

TEST(CompiledExpressions, SignAndStepFunctionsAreSteps) {
    SymbolTable s;
    ex x = s.add_constant("x");
    CompiledExpressions f(s, {x}, {GiNaC::csgn(x), GiNaC::step(x)});
    const std::vector<std::array<double, 3>> table{
        {-2.0, -1.0, 0.0}, {0.0, 0.0, 0.5}, {3.0, 1.0, 1.0}};  // x, csgn, step
    for (const auto& [at, sign, step] : table) {
        std::vector<double> v = f.evaluate(std::vector<double>{at});
        EXPECT_EQ(v[0], sign) << "csgn(" << at << ")";
        EXPECT_EQ(v[1], step) << "step(" << at << ")";
    }
}

// ---- powers -------------------------------------------------------------------------------

TEST(CompiledExpressions, IntegerAndNegativePowersMatchStdPow) {
    SymbolTable s;
    ex x = s.add_constant("x");
    for (int n = -9; n <= 17; ++n) {
        for (double a : {1.3, -0.7}) {
            double v = eval1(s, {x}, pow(x, n), {a});
            EXPECT_TRUE(close(v, std::pow(a, n), 1e-14)) << "x^" << n << " at " << a;
        }
    }
    // by repeated squaring: x^8 = ((x^2)^2)^2, x^13 = ((x^2 x)^2)^2 x, x^-1 one division
    EXPECT_EQ(CompiledExpressions(s, {x}, {pow(x, 8)}).operation_count(), 3u);
    EXPECT_EQ(CompiledExpressions(s, {x}, {pow(x, 13)}).operation_count(), 5u);
    EXPECT_EQ(CompiledExpressions(s, {x}, {pow(x, -1)}).operation_count(), 1u);
    // squares shared between powers of one base
    EXPECT_EQ(CompiledExpressions(s, {x}, {pow(x, 2), pow(x, 4), pow(x, 8)}).operation_count(),
              3u);
}

TEST(CompiledExpressions, FractionalAndSymbolicPowersMatchStdPow) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    const double a = 2.7, b = -0.35;
    CompiledExpressions f(s, {x, y},
                          {pow(x, GiNaC::numeric(3, 2)), pow(x, GiNaC::numeric(-1, 2)),
                           pow(x, GiNaC::numeric(-5, 2)), pow(x, GiNaC::numeric(1, 3)),
                           pow(x, y), pow(2, y), pow(x, GiNaC::numeric(1.25)),
                           x * y / pow(x + y, 3)});
    std::vector<double> v = f.evaluate(std::vector<double>{a, b});
    EXPECT_TRUE(close(v[0], std::pow(a, 1.5), 1e-15));
    EXPECT_TRUE(close(v[1], 1 / std::sqrt(a), 1e-15));
    EXPECT_TRUE(close(v[2], std::pow(a, -2.5), 1e-15));
    EXPECT_TRUE(close(v[3], std::cbrt(a), 1e-15));
    EXPECT_TRUE(close(v[4], std::pow(a, b), 1e-15));
    EXPECT_TRUE(close(v[5], std::pow(2, b), 1e-15));
    EXPECT_TRUE(close(v[6], std::pow(a, 1.25), 1e-15));
    EXPECT_TRUE(close(v[7], a * b / std::pow(a + b, 3), 1e-15));
}

// ---- constants, inputs, time --------------------------------------------------------------

TEST(CompiledExpressions, InputsOverrideConstantValues) {
    SymbolTable s;
    ex m = s.add_constant("m", 2.0), x = s.add_constant("x");
    ex e = m * pow(x, 2);
    EXPECT_EQ(eval1(s, {x}, e, {3}), 18.0);        // m = 2 from the table
    EXPECT_EQ(eval1(s, {x, m}, e, {3, 5}), 45.0);  // m = 5 as an input
    EXPECT_EQ(eval1(s, {m, x}, e, {5, 3}), 45.0);  // in the order listed
}

TEST(CompiledExpressions, ValuedConstantsFoldIntoNumbers) {
    SymbolTable s;
    ex L = s.add_constant("L", 1.0), m = s.add_constant("m", 2.0), g = s.add_constant("g", 9.81);
    TimeVariable q = s.add_variable("q");
    // L*q' needs no operation at L = 1; m*g*L*sin(q) needs sin and one product by 19.62
    CompiledExpressions f(s, {q, q.d(1)}, {L * q.d(1), m * g * L * sin(q), m * L - 2});
    EXPECT_EQ(f.operation_count(), 2u);
    std::vector<double> v = f.evaluate(std::vector<double>{0.3, -1.5});
    EXPECT_EQ(v[0], -1.5);
    EXPECT_DOUBLE_EQ(v[1], 2 * 9.81 * std::sin(0.3));
    EXPECT_EQ(v[2], 0.0);
}

TEST(CompiledExpressions, TimeIsAnInput) {
    SymbolTable s;
    ex w = s.add_constant("w", 2.0);
    const ex& t = s.time();
    EXPECT_DOUBLE_EQ(eval1(s, {t}, sin(w * t), {0.25}), std::sin(0.5));
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {}, {sin(w * t)}), ArgumentError,
                     "the time 't' (in output 0) has no value; list it as an input");
}

// ---- intermediates ------------------------------------------------------------------------

TEST(CompiledExpressions, IntermediateIsCompiledOnce) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    ex z = s.add_intermediate(x * y + sin(x));
    // z: x*y, sin(x), + (3); z^2: one product; sin(z): one call
    CompiledExpressions f(s, {x, y}, {z, pow(z, 2), sin(z)});
    EXPECT_EQ(f.operation_count(), 5u);
    std::vector<double> v = f.evaluate(std::vector<double>{0.5, 3});
    const double zv = 1.5 + std::sin(0.5);
    EXPECT_DOUBLE_EQ(v[0], zv);
    EXPECT_DOUBLE_EQ(v[1], zv * zv);
    EXPECT_DOUBLE_EQ(v[2], std::sin(zv));
}

TEST(CompiledExpressions, IntermediateDerivativesMatchHandDerivation) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex L = s.add_constant("L", 0.5);
    ex z = s.add_intermediate(L * sin(q), "z");
    ex zd = s.dt(z);    // the intermediate z' = L cos(q) q'
    ex zdd = s.dt(zd);  // z'' = L (cos(q) q'' - sin(q) q'^2)
    ASSERT_TRUE(s.owns(zd) && s.kind(zd) == SymbolKind::intermediate);
    CompiledExpressions f(s, {q, q.d(1), q.d(2)}, {z, zd, zdd});
    const double a = 0.8, ad = -1.7, a2 = 2.3;
    std::vector<double> v = f.evaluate(std::vector<double>{a, ad, a2});
    EXPECT_DOUBLE_EQ(v[0], 0.5 * std::sin(a));
    EXPECT_DOUBLE_EQ(v[1], 0.5 * std::cos(a) * ad);
    EXPECT_NEAR(v[2], 0.5 * (std::cos(a) * a2 - std::sin(a) * ad * ad), 1e-15);
}

TEST(CompiledExpressions, IntermediateListedAsInputIsNotExpanded) {
    SymbolTable s;
    ex x = s.add_constant("x");
    ex k = s.add_constant("k");  // no value: the definition cannot be compiled
    ex z = s.add_intermediate(k * x, "z");
    EXPECT_EQ(eval1(s, {z}, 2 * z + 1, {3}), 7.0);
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {2 * z}), ArgumentError,
                     "the constant 'k' (in the definition of 'z') has no value");
}

// z_k = z_{k-1}/2 + x: compiled in dependency order, not by recursing through 20,000
// definitions
TEST(CompiledExpressions, LongChainOfIntermediatesCompiles) {
    SymbolTable s;
    ex x = s.add_constant("x");
    ex z = x;
    for (int k = 0; k < 20000; ++k) z = s.add_intermediate(z / 2 + x);
    CompiledExpressions f(s, {x}, {z});
    EXPECT_EQ(f.operation_count(), 2u * 20000u - 1);  // z_1 = 3/2 x is one product
    double r = 0.75;
    for (int k = 0; k < 20000; ++k) r = r * 0.5 + 0.75;
    EXPECT_DOUBLE_EQ(f.evaluate(std::vector<double>{0.75}).at(0), r);
}

// random expressions over variables, derivatives, valued constants and intermediates
// (with their time derivatives), compiled together, agree with SymbolTable::evaluate
TEST(CompiledExpressions, RandomExpressionsMatchSymbolTableEvaluate) {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1", 3), q2 = s.add_variable("q2", 3);
    ex m = s.add_constant("m", 1.3), L = s.add_constant("L", 0.7);
    std::mt19937 rng(20240611);
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    std::vector<ex> leaves{q1, q2, q1.d(1), q2.d(1), m, L, GiNaC::numeric(3, 4), ex(2)};
    std::function<ex(int)> random_ex = [&](int depth) -> ex {
        if (depth == 0) return leaves[pick(leaves.size())];
        ex a = random_ex(depth - 1), b = random_ex(depth - 1);
        switch (pick(12)) {
            case 0: return a + b;
            case 1: return a - 2 * b;
            case 2: return a * b;
            case 3: return a / (2 + sin(b));
            case 4: return pow(a, static_cast<int>(pick(4)) + 2);
            case 5: return pow(GiNaC::numeric(3, 2) + cos(a), -static_cast<int>(pick(3)) - 1);
            case 6: return GiNaC::sqrt(2 + sin(a)) * b;
            case 7: return GiNaC::log(1 + pow(a, 2)) - b;
            case 8: return GiNaC::exp(sin(a)) * cos(b);
            case 9: return GiNaC::atan2(a, 1 + pow(b, 2));
            case 10: return GiNaC::tanh(a) + GiNaC::atan(b);
            default: return m * a * b - L;
        }
    };
    // intermediates built on one another, and their derivatives (z', z'')
    ex z1 = s.add_intermediate(random_ex(3));
    ex z2 = s.add_intermediate(random_ex(2) * z1 + sin(z1));
    ex z1d = s.dt(z1), z2d = s.dt(z2), z2dd = s.dt(z2d);
    for (const ex& z : {z1, z2, z1d, z2d, z2dd}) leaves.push_back(z);

    std::vector<ex> outputs;
    for (int i = 0; i < 40; ++i) outputs.push_back(random_ex(1 + static_cast<int>(pick(3))));
    outputs.push_back(z2dd);
    const std::vector<ex> inputs{q1, q2, q1.d(1), q2.d(1), q1.d(2), q2.d(2), q1.d(3), q2.d(3)};
    CompiledExpressions f(s, inputs, outputs);

    std::uniform_real_distribution<double> value(-1.2, 1.2);
    for (int point = 0; point < 3; ++point) {
        std::vector<double> at;
        GiNaC::exmap values;
        for (const ex& x : inputs) {
            at.push_back(value(rng));
            values[x] = at.back();
        }
        std::vector<double> v = f.evaluate(at);
        for (std::size_t k = 0; k < outputs.size(); ++k)
            EXPECT_TRUE(close(v[k], s.evaluate(outputs[k], values), 1e-11))
                << "output " << k << " at point " << point;
    }
}

// ---- sharing ------------------------------------------------------------------------------

// x_{k+1} = x_k^2 + sin(x_k) forty times: the tree has ~3^40 nodes, the graph 3 per level
TEST(CompiledExpressions, HugeSharedSubtreeCompilesLinearly) {
    SymbolTable s;
    ex x = s.add_constant("x");
    auto build = [&] {
        ex e = x;
        for (int k = 0; k < 40; ++k) e = e * e + sin(e);
        return e;
    };
    ex e = build();
    CompiledExpressions f(s, {x}, {e});
    EXPECT_LE(f.operation_count(), 3u * 40u);
    for (double a : {-0.5, 0.01, -1e-3}) {
        double r = a;
        for (int k = 0; k < 40; ++k) r = r * r + std::sin(r);
        EXPECT_DOUBLE_EQ(f.evaluate(std::vector<double>{a}).at(0), r) << "x = " << a;
    }
    // a second copy built separately is recognised as the same graph
    CompiledExpressions twice(s, {x}, {e, build(), sin(build())});
    EXPECT_EQ(twice.operation_count(), f.operation_count() + 1);
}

TEST(CompiledExpressions, CommonSubexpressionsAcrossOutputsAreShared) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    ex shared = sin(x + y) * cos(x - y);
    CompiledExpressions one(s, {x, y}, {shared});
    CompiledExpressions three(s, {x, y}, {shared, 2 * shared + x, sin(shared)});
    // one product by 2, one sum, one call on top of the shared part
    EXPECT_EQ(three.operation_count(), one.operation_count() + 3);
}

// ---- evaluation API -----------------------------------------------------------------------

TEST(CompiledExpressions, EvaluationOverloadsAgree) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    CompiledExpressions f(s, {x, y}, {x * y + sin(y), pow(x - y, 3), ex(4)});
    EXPECT_EQ(f.input_count(), 2u);
    EXPECT_EQ(f.output_count(), 3u);
    ASSERT_EQ(f.inputs().size(), 2u);
    EXPECT_TRUE(f.inputs()[1].is_equal(y));
    const double in[2] = {1.5, -0.25};
    double a[3], b[3], c[3];
    f.evaluate(in, a);
    std::vector<double> workspace(f.workspace_size());
    f.evaluate(in, b, workspace.data());
    const CompiledExpressions copy = f;
    copy.evaluate(std::span<const double>(in), std::span<double>(c));
    std::vector<double> d = f.evaluate(std::span<const double>(in));
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a[k], b[k]);
        EXPECT_EQ(a[k], c[k]);
        EXPECT_EQ(a[k], d[static_cast<std::size_t>(k)]);
    }
    EXPECT_DOUBLE_EQ(a[0], -0.375 + std::sin(-0.25));
    EXPECT_EQ(a[1], 1.75 * 1.75 * 1.75);
    EXPECT_EQ(a[2], 4.0);

    CompiledExpressions empty;
    EXPECT_EQ(empty.evaluate(std::vector<double>{}).size(), 0u);
}

// ---- errors -------------------------------------------------------------------------------

TEST(CompiledExpressions, SymbolWithoutValueIsNamed) {
    SymbolTable s;
    TimeVariable q = s.add_variable("qA");
    ex k = s.add_constant("k"), x = s.add_constant("x");
    ex z = s.add_intermediate(k * x, "z1");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {x + 1, sin(q.d(1))}), ArgumentError,
                     "the variable 'qA'' (in output 1) has no value; list it as an input");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {k * x}), ArgumentError,
                     "'k' (in output 0) has no value; give it a value with "
                     "SymbolTable::set_value() or list it as an input");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {z + 1}), ArgumentError,
                     "'k' (in the definition of 'z1')");
    GiNaC::realsymbol w("w");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {w * x}), ArgumentError,
                     "'w' (in output 0) is not an input and not a symbol of the table");
    EXPECT_NO_THROW((void)CompiledExpressions(s, {x, w}, {w * x}));
}

TEST(CompiledExpressions, UnsupportedFunctionsAreNamed) {
    SymbolTable s;
    ex x = s.add_constant("x");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {x + GiNaC::tgamma(x)}), NotImplemented,
                     "the function 'tgamma' (in output 0) cannot be compiled");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {GiNaC::Li2(x)}), NotImplemented, "'Li2'");
    ex dcsgn = GiNaC::csgn(x).diff(GiNaC::ex_to<GiNaC::symbol>(x));  // D[0](csgn)(x)
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {dcsgn}), NotImplemented,
                     "derivative of the function 'csgn'");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {GiNaC::I * x}), NotImplemented,
                     "complex number");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x}, {x == 1}), NotImplemented,
                     "cannot compile a 'relational'");
}

TEST(CompiledExpressions, MalformedInputsAreRejected) {
    SymbolTable s;
    ex x = s.add_constant("x");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x + 1}, {x}), ArgumentError,
                     "input 0 ('1+x') is not a symbol");
    EXPECT_THROW_MSG((void)CompiledExpressions(s, {x, x}, {x}), ArgumentError,
                     "'x' is listed twice as an input");
    CompiledExpressions f(s, {x}, {sin(x), cos(x)});
    EXPECT_THROW_MSG(f.evaluate(std::vector<double>{1, 2}), ArgumentError,
                     "2 input values given, 1 expected");
    std::vector<double> out(1);
    EXPECT_THROW_MSG(f.evaluate(std::vector<double>{1}, out), ArgumentError,
                     "room for 1 outputs given, 2 expected");
}

TEST(CompiledExpressions, ExtendedPrecisionSurvivesCancellation) {
    // (a + b)^2 - a^2 - 2 a b = b^2 exactly; with a = 1e8 the square is near 1e16, where a
    // double's spacing is 2, so double evaluation may be off by about 2 while long double
    // (spacing 2^-10 there) stays within a few thousandths
    SymbolTable t;
    ex a = t.add_constant("a"), b = t.add_constant("b");
    CompiledExpressions f(t, {a, b}, {pow(a + b, 2) - a * a - 2 * a * b});
    const long double in[2] = {1e8L, 1.5L};
    long double out = 0;
    f.evaluate_extended(in, &out);
    EXPECT_NEAR(static_cast<double>(out), 2.25, 5e-3);
    // and both precisions agree on an ordinary expression
    CompiledExpressions g(t, {a, b}, {sin(a) * cos(b) + pow(a, 3) / (1 + b * b)});
    const double ind[2] = {0.7, -1.3};
    const long double inl[2] = {0.7L, -1.3L};
    double d = 0;
    long double l = 0;
    g.evaluate(ind, &d);
    g.evaluate_extended(inl, &l);
    EXPECT_NEAR(d, static_cast<double>(l), 1e-15);
    EXPECT_NEAR(d, std::sin(0.7) * std::cos(-1.3) + 0.343 / (1 + 1.69), 1e-15);
}

TEST(CompiledExpressions, AngleSumsReuseTheSinesAndCosinesOfShorterSums) {
    // the angles of a 4-link chain, q_i + ... + q_j: with the option one sine and cosine per
    // coordinate, the sums by the angle-sum formulas; the values agree to rounding
    SymbolTable s;
    std::vector<ex> q;
    for (int i = 1; i <= 4; ++i) q.push_back(s.add_constant("q" + std::to_string(i)));
    std::vector<ex> outputs;
    for (std::size_t i = 0; i < q.size(); ++i) {
        ex sum = 0;
        for (std::size_t j = i; j < q.size(); ++j) {
            sum += q[j];
            outputs.push_back(sin(sum));
            outputs.push_back(cos(sum) * q[i]);
        }
    }
    CompiledExpressions direct(s, q, outputs);
    CompiledExpressions expanded(s, q, outputs, CompileOptions{.expand_angle_sums = true});
    StraightLineProgram d = direct.calc_program(), e = expanded.calc_program();
    EXPECT_EQ(d.call_count(d.body), 2u * 10u);  // ten distinct sums
    EXPECT_EQ(e.call_count(e.body), 2u * 4u);   // one sincos per coordinate
    const std::vector<double> at{0.3, -1.1, 2.4, 0.7};
    std::vector<double> a = direct.evaluate(at), b = expanded.evaluate(at);
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-15) << k;
}
