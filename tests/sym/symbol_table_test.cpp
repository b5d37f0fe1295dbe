// SPDX-License-Identifier: MIT
// Symbol table: declarations, the chain rule, intermediates and numeric evaluation.
#include "alembert/sym/symbol_table.hpp"

#include <cmath>

#include "alembert/error.hpp"
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
