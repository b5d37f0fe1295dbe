// SPDX-License-Identifier: MIT
// Symbol table: declarations, the chain rule, intermediates and numeric evaluation.
#include "alembert/sym/symbol_table.hpp"

#include <cmath>

#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/simplify.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

TEST(SymbolTable, VariableDeclaresItsDerivativesWithPrimedNames) {
    SymbolTable s;
    TimeVariable q = s.add_variable("qA", 2);
    EXPECT_EQ(q.order(), 2);
    EXPECT_EQ(s.name(q.d(1)), "qA'");
    EXPECT_EQ(s.name(q.d(2)), "qA''");
    EXPECT_TRUE(s.symbol("qA''").is_equal(q.d(2)));
    EXPECT_EQ(s.kind(q.d(1)), SymbolKind::variable);
    EXPECT_EQ(s.derivative_order(q.d(2)), 2);
    EXPECT_TRUE(s.base(q.d(2)).is_equal(q));
    TimeVariable again = s.variable("qA");
    EXPECT_EQ(again.order(), 2);
    EXPECT_TRUE(again.d(2).is_equal(q.d(2)));
}

TEST(SymbolTable, KindsAreRecorded) {
    SymbolTable s;
    ex m = s.add_constant("m", 2.5);
    ex T = s.add_unknown("T");
    TimeVariable u = s.add_specified("u", 1);
    EXPECT_EQ(s.kind(m), SymbolKind::constant);
    EXPECT_EQ(s.kind(T), SymbolKind::unknown);
    EXPECT_EQ(s.kind(u), SymbolKind::specified);
    EXPECT_EQ(s.kind(s.time()), SymbolKind::time);
    ASSERT_TRUE(s.value(m).has_value());
    EXPECT_DOUBLE_EQ(*s.value(m), 2.5);
    EXPECT_EQ(s.symbols(SymbolKind::constant).size(), 1u);
}

TEST(SymbolTable, TimeDerivativeFollowsTheChainRule) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2), r = s.add_variable("r", 2);
    ex L = s.add_constant("L");
    const ex& t = s.time();
    // d/dt (L sin q r'^2) = L cos q q' r'^2 + 2 L sin q r' r''
    EXPECT_TRUE(same(s.dt(L * sin(q) * pow(r.d(1), 2)),
                     L * cos(q) * q.d(1) * pow(r.d(1), 2) + 2 * L * sin(q) * r.d(1) * r.d(2)));
    EXPECT_TRUE(same(s.dt(t * q), q + t * q.d(1)));
    EXPECT_TRUE(s.dt(L).is_zero());
    EXPECT_TRUE(same(s.dt(s.dt(sin(q))), -sin(q) * pow(q.d(1), 2) + cos(q) * q.d(2)));
}

TEST(SymbolTable, SpecifiedFunctionsDifferentiateLikeVariables) {
    SymbolTable s;
    TimeVariable u = s.add_specified("u", 2);
    EXPECT_TRUE(same(s.dt(pow(u, 3)), 3 * pow(u, 2) * u.d(1)));
}

TEST(SymbolTable, DerivativeBeyondDeclaredOrderIsAModelError) {
    SymbolTable s;
    TimeVariable q = s.add_variable("qB", 1);
    EXPECT_THROW_MSG(s.dt(q.d(1)), ModelError, "derivative of 'qB'' is not declared");
    EXPECT_THROW_MSG(s.dt(q.d(1)), ModelError, "order 2");
    EXPECT_THROW_MSG(q.d(2), ModelError, "qB''");
}

TEST(SymbolTable, UnknownsHaveNoTimeDerivative) {
    SymbolTable s;
    ex T = s.add_unknown("T_A");
    EXPECT_THROW_MSG(s.dt(2 * T), ModelError, "'T_A' is an unknown");
}

TEST(SymbolTable, DuplicateAndMalformedNamesAreRejected) {
    SymbolTable s;
    s.add_constant("m");
    EXPECT_THROW_MSG(s.add_variable("m"), ModelError, "'m' is already declared as a constant");
    EXPECT_THROW_MSG(s.add_constant("2x"), ArgumentError, "'2x' is not a valid name");
    EXPECT_THROW_MSG(s.add_constant(""), ArgumentError, "not a valid name");
    EXPECT_THROW_MSG(s.symbol("nope"), ModelError, "no symbol named 'nope'");
    EXPECT_THROW_MSG(s.variable("m"), ModelError, "'m' is a constant");
}

TEST(SymbolTable, ForeignSymbolsAreRejectedByName) {
    SymbolTable s;
    GiNaC::realsymbol x("x");
    EXPECT_THROW_MSG(s.dt(x), ArgumentError, "'x' is not a symbol of this table");
    EXPECT_THROW_MSG(s.add_intermediate(2 * x), ArgumentError, "uses the symbol 'x'");
}

TEST(SymbolTable, IntermediateDerivativeIsNamedAndEqualsDerivativeOfDefinition) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex L = s.add_constant("L");
    ex z = s.add_intermediate(L * sin(q) * cos(q));
    EXPECT_EQ(s.name(z), "z1");
    ex dz = s.dt(3 * z);
    // the derivative refers to a new intermediate z1'
    EXPECT_TRUE(s.contains("z1'"));
    ex expected = 3 * L * (pow(cos(q), 2) - pow(sin(q), 2)) * q.d(1);
    EXPECT_TRUE(same(s.expand_intermediates(dz), expected));
    // a second derivative goes through z1' again
    ex ddz = s.dt(dz);
    EXPECT_TRUE(same(s.expand_intermediates(ddz), s.dt(expected)));
}

TEST(SymbolTable, PartialDerivativeGoesThroughIntermediates) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex a = s.add_constant("a");
    ex z1 = s.add_intermediate(a * sin(q));
    ex z2 = s.add_intermediate(z1 * q.d(1));
    ex e = pow(z2, 2) + q.d(1);
    // e = a^2 sin^2 q q'^2 + q' => de/dq' = 2 a^2 sin^2 q q' + 1, de/dq = 2 a^2 sin q cos q q'^2
    EXPECT_TRUE(same(s.expand_intermediates(s.diff(e, q.d(1))),
                     2 * pow(a, 2) * pow(sin(q), 2) * q.d(1) + 1));
    EXPECT_TRUE(same(s.expand_intermediates(s.diff(e, q)),
                     2 * pow(a, 2) * sin(q) * cos(q) * pow(q.d(1), 2)));
    EXPECT_TRUE(s.depends_on(e, q));
    EXPECT_FALSE(s.depends_on(z1, q.d(1)));
    EXPECT_TRUE(s.diff(z1, q.d(1)).is_zero());
}

TEST(SymbolTable, EvaluateUsesConstantValuesAndIntermediates) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex L = s.add_constant("L", 2.0);
    ex z = s.add_intermediate(L * cos(q));
    double v = s.evaluate(z * z + q.d(1), {{q, 0.3}, {q.d(1), 0.5}});
    EXPECT_NEAR(v, 4.0 * std::cos(0.3) * std::cos(0.3) + 0.5, 1e-14);
    EXPECT_THROW_MSG(s.evaluate(z + q.d(1), {{q, 0.3}}), ArgumentError, "'q'' has no value");
    s.set_value(L, 3.0);
    EXPECT_NEAR(s.evaluate(L), 3.0, 0);
    EXPECT_THROW_MSG(s.set_value(q, 1.0), ArgumentError, "is not a constant");
}

TEST(SymbolTable, EvaluateAtAPoleIsAnArgumentErrorNamingTheIntermediate) {
    // 1/x at x = 0, log(0) and a square root of a negative number have no real value: the
    // error says so (and GiNaC never sees the division by zero, which it cannot undo cleanly;
    // the sanitizer pass checks there is no leak)
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex L = s.add_constant("L", 2.0);
    ex z = s.add_intermediate(L / q, "z");
    EXPECT_THROW_MSG(s.evaluate(z + 1, {{q, 0.0}}), ArgumentError, "'z' is not a finite real");
    EXPECT_THROW_MSG(s.evaluate(L / GiNaC::sin(ex(q)), {{q, 0.0}}), ArgumentError,
                     "the expression is not a finite real number");
    EXPECT_THROW_MSG(s.evaluate(GiNaC::log(ex(q)), {{q, 0.0}}), ArgumentError, "division by zero");
    EXPECT_THROW_MSG(s.evaluate(sqrt(q - L), {{q, 1.0}}), ArgumentError, "not a finite real");
    // near the pole, and where the walk meets a constant such as Pi, the value is as before
    EXPECT_NEAR(s.evaluate(z, {{q, 1e-3}}), 2000.0, 1e-9);
    EXPECT_NEAR(s.evaluate(GiNaC::Pi / q, {{q, 2.0}}), M_PI / 2, 1e-15);
}

TEST(SymbolTable, EvaluateWithAMemoGivesEachExpressionItsValueAtTheSameValues) {
    // z1 = L q, z2 = z1^2 + q at L = 2, q = 3: z1 = 6, z2 = 39; expressions met one after the
    // other through a memo (each intermediate evaluated once) take their values by hand
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex L = s.add_constant("L", 2.0);
    ex z1 = s.add_intermediate(L * q, "z1");
    ex z2 = s.add_intermediate(pow(z1, 2) + q, "z2");
    SymbolTable::EvaluationMemo memo({{q, 3.0}});
    EXPECT_NEAR(s.evaluate(z1 + 1, memo), 7.0, 1e-12);
    EXPECT_NEAR(s.evaluate(z2 - z1, memo), 33.0, 1e-12);
    EXPECT_NEAR(s.evaluate(GiNaC::sin(z1) * z2, memo), std::sin(6.0) * 39.0, 1e-12);
    // a pole is still reported, naming the intermediate, and the memo serves on after it
    ex z3 = s.add_intermediate(L / (q - 3), "z3");
    EXPECT_THROW_MSG(s.evaluate(z3 + z1, memo), ArgumentError, "'z3' is not a finite real");
    EXPECT_NEAR(s.evaluate(z2 / z1, memo), 6.5, 1e-12);
}

TEST(SymbolTable, DerivativeOfAVelocityIntermediateKeepsTheAccelerationExplicit) {
    // z = L q' cos(q) is a velocity measure; z' = L q'' cos(q) - L q'^2 sin(q) must show q''
    // (equations are later solved for it) and hide only the rest
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex L = s.add_constant("L");
    ex z = s.add_intermediate(L * q.d(1) * cos(q) + pow(q.d(1), 3) * sin(q) * sin(q));
    ex dz = s.dt(z);
    ex expected = L * q.d(2) * cos(q) - L * pow(q.d(1), 2) * sin(q) +
                  3 * pow(q.d(1), 2) * q.d(2) * pow(sin(q), 2) +
                  2 * pow(q.d(1), 4) * sin(q) * cos(q);
    EXPECT_TRUE(same(s.expand_intermediates(dz), expected));
    // linear in q'' with coefficients free of q'', every intermediate free of q''
    const GiNaC::symbol& a = GiNaC::ex_to<GiNaC::symbol>(q.d(2));
    EXPECT_TRUE(dz.diff(a, 2).is_zero());
    EXPECT_TRUE(same(s.expand_intermediates(dz.diff(a)),
                     L * cos(q) + 3 * pow(q.d(1), 2) * pow(sin(q), 2)));
    for (const ex& zi : s.intermediates()) EXPECT_FALSE(s.depends_on(zi, q.d(2))) << s.name(zi);
}

TEST(SymbolTable, NameIfLargeNamesTheBulkAndKeepsUnknownsAndAccelerationsExplicit) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex T = s.add_unknown("T"), m = s.add_constant("m");
    ex big = 0;
    for (int k = 1; k <= 6; ++k) big += m * pow(sin(k * q), k) * q.d(1);
    ex e = T + (big + m) * q.d(2) + big * q.d(1);
    ex small = s.name_if_large(q.d(1) * m, 20);
    EXPECT_TRUE(small.is_equal(q.d(1) * m));  // small: left as it is
    ex named = s.name_if_large(e, 20);
    EXPECT_TRUE(same(s.expand_intermediates(named), e));
    EXPECT_LT(count_ops(named), 10u);
    const GiNaC::symbol& a = GiNaC::ex_to<GiNaC::symbol>(q.d(2));
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(T);
    EXPECT_TRUE(named.diff(t).is_equal(1));
    EXPECT_TRUE(same(s.expand_intermediates(named.diff(a)), big + m));
    for (const ex& zi : s.intermediates()) {
        EXPECT_FALSE(s.depends_on(zi, q.d(2))) << s.name(zi);
        EXPECT_FALSE(s.depends_on(zi, T)) << s.name(zi);
    }
    // not linear in the unknown: left as it is
    ex nonlinear = T * T * big;
    EXPECT_TRUE(s.name_if_large(nonlinear, 20).is_equal(nonlinear));
}

TEST(SymbolTable, PartialDerivativeOfALongChainOfIntermediatesStaysSmall) {
    // z_k = cos(q) z_{k-1} + sin(q) w_{k-1}, w_k = -sin(q) z_{k-1} + cos(q) w_{k-1}: a rotation
    // applied 60 times. Written out, d z_60 / d q would have about 2^60 terms; through named
    // partial derivatives it is a chain of small ones. z_60 = cos(60 q) z_0 + sin(60 q) w_0.
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex z = s.add_constant("a"), w = s.add_constant("b");
    const ex z0 = z, w0 = w;
    for (int k = 1; k <= 60; ++k) {
        ex zk = s.add_intermediate(cos(q) * z + sin(q) * w);
        ex wk = s.add_intermediate(-sin(q) * z + cos(q) * w);
        z = zk, w = wk;
    }
    ex dz = s.diff(z, q);
    EXPECT_LT(count_ops(dz), 20u);
    CompiledExpressions f(s, {q, z0, w0}, {dz});
    for (double qv : {0.1, -0.7, 2.3}) {
        double expected = 60 * (-std::sin(60 * qv) * 0.8 + std::cos(60 * qv) * -0.3);
        std::vector<double> x{qv, 0.8, -0.3};
        EXPECT_NEAR(f.evaluate(x)[0], expected, 1e-9);
    }
}

TEST(SymbolTable, LeafSymbolsLookThroughIntermediatesToTheirDefinitions) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex a = s.add_constant("a", 2.0), b = s.add_constant("b"), c = s.add_unknown("c");
    ex z1 = s.add_intermediate(a * GiNaC::sin(q.symbol()));
    ex z2 = s.add_intermediate(z1 * z1 + b);
    GiNaC::exset leaves = s.calc_leaf_symbols(z2 * c + z1);
    EXPECT_EQ(leaves, (GiNaC::exset{a, b, c, q.symbol()}));
    EXPECT_EQ(s.calc_leaf_symbols(ex(3)), GiNaC::exset{});
}

TEST(SymbolTable, LinearFormSplitsAccumulatedIntermediatesByTheirAccelerations) {
    // z_k = z_(k-1) + (coefficient) q_k'' + (rest), as a chain's accumulated sums are: the
    // coefficients of every q'' and the rest through the intermediates, equal by meaning to the
    // derivative and to e at q'' = 0
    SymbolTable s;
    const int n = 6;
    std::vector<TimeVariable> q;
    for (int k = 0; k < n; ++k) q.push_back(s.add_variable("q" + std::to_string(k), 2));
    const ex L = s.add_constant("L", 0.4), T = s.add_unknown("T");
    ex z = 0;
    for (int k = 0; k < n; ++k)
        z = s.add_intermediate(z * cos(q[k]) + L * sin(q[k]) * q[k].d(2) + pow(q[k].d(1), 2) * L,
                               "acc" + std::to_string(k));
    const ex e = 3 * z + T * L;
    std::map<ex, ex, GiNaC::ex_is_less> coeffs;
    ex rest = 0;
    ASSERT_TRUE(s.calc_linear_form(e, coeffs, rest));
    EXPECT_EQ(coeffs.size(), static_cast<std::size_t>(n + 1));  // each q'' and T
    GiNaC::exmap at_zero{{T, 0}};
    for (int k = 0; k < n; ++k) at_zero[q[k].d(2)] = 0;
    const ex full = s.expand_intermediates(e);
    for (int k = 0; k < n; ++k)
        EXPECT_TRUE(same(s.expand_intermediates(coeffs.at(q[k].d(2))),
                         full.diff(GiNaC::ex_to<GiNaC::symbol>(q[k].d(2)))));
    EXPECT_TRUE(same(s.expand_intermediates(coeffs.at(T)), L));
    EXPECT_TRUE(same(s.expand_intermediates(rest), full.subs(at_zero)));
    // the coefficients and rest hold no solve-level symbol
    for (const auto& [x, c] : coeffs)
        for (const ex& leaf : s.calc_leaf_symbols(c)) EXPECT_FALSE(s.is_solve_level(leaf));
    // not linear: q'' squared inside an intermediate
    const ex w = s.add_intermediate(pow(q[0].d(2), 2) + L, "w");
    std::map<ex, ex, GiNaC::ex_is_less> c2;
    ex r2 = 0;
    EXPECT_FALSE(s.calc_linear_form(w * L + z, c2, r2));
}

TEST(SymbolTable, LinearFormOfALongChainOfIntermediatesIsSplitOncePerIntermediate) {
    // 2,000 nested sums, each a few terms on the previous one: each split once
    SymbolTable s;
    const TimeVariable q = s.add_variable("q", 2);
    const ex L = s.add_constant("L", 0.4);
    ex z = q.d(2);
    for (int k = 0; k < 2000; ++k) z = s.add_intermediate(z + L * q.d(2) + L, "chain" + std::to_string(k));
    std::map<ex, ex, GiNaC::ex_is_less> coeffs;
    ex rest = 0;
    ASSERT_TRUE(s.calc_linear_form(z, coeffs, rest));
    ASSERT_EQ(coeffs.size(), 1u);
    EXPECT_NEAR(s.evaluate(coeffs.at(q.d(2))), 1 + 2000 * 0.4, 1e-9);
    EXPECT_NEAR(s.evaluate(rest), 2000 * 0.4, 1e-9);
}

TEST(SymbolTable, LinearFormOfAChainLongerThanTheStackHoldsCallsIsSplit) {
    // 100,000 intermediates, each the previous one plus L q'' + L: split one after the other
    // (a call per link would overflow the thread's stack); the coefficient of q'' is
    // 1 + 100,000 L, the rest 100,000 L
    constexpr int kLinks = 100000;
    SymbolTable s;
    const TimeVariable q = s.add_variable("q", 2);
    const ex L = s.add_constant("L", 0.25);
    ex z = q.d(2);
    for (int k = 0; k < kLinks; ++k) z = s.add_intermediate(z + L * q.d(2) + L, "link" + std::to_string(k));
    std::map<ex, ex, GiNaC::ex_is_less> coeffs;
    ex rest = 0;
    ASSERT_TRUE(s.calc_linear_form(z, coeffs, rest));
    ASSERT_EQ(coeffs.size(), 1u);
    EXPECT_NEAR(s.evaluate(coeffs.at(q.d(2))), 1 + kLinks * 0.25, 1e-6);
    EXPECT_NEAR(s.evaluate(rest), kLinks * 0.25, 1e-6);
}
