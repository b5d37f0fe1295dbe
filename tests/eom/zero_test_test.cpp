// SPDX-License-Identifier: MIT
// Zero tests at random states: identities that do not look zero, and which symbols an
// expression changes with.
#include "alembert/eom/zero_test.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {
struct Table {
    SymbolTable st;
    ex q = st.add_variable("q"), L = st.add_constant("L", 0.7), m = st.add_constant("m");
    ex T1 = st.add_unknown("T1"), T2 = st.add_unknown("T2"), T3 = st.add_unknown("T3");
};
}  // namespace

TEST(ZeroTest, SeesIdentitiesThatDoNotLookZero) {
    Table x;
    EXPECT_TRUE(is_zero_at_random_states(x.st, pow(sin(x.q), 2) + pow(cos(x.q), 2) - 1));
    EXPECT_TRUE(is_zero_at_random_states(x.st, sin(2 * x.q) - 2 * sin(x.q) * cos(x.q)));
    EXPECT_FALSE(is_zero_at_random_states(x.st, sin(x.q) - cos(x.q)));
    // through an intermediate, never written out
    const ex z = x.st.add_intermediate(x.L * sin(x.q), "z");
    EXPECT_TRUE(is_zero_at_random_states(x.st, z * cos(x.q) - x.L * sin(2 * x.q) / 2));
}

TEST(ZeroTest, ChangesWithTheSymbolsWhoseCoefficientIsNotZero) {
    Table x;
    const ex z = x.st.add_intermediate(x.m * x.L * cos(x.q), "z");
    // T1's coefficient is not zero; T2's is zero though it does not look it; T3's is the
    // intermediate z; m is held only inside z
    const ex e = x.L * x.T1 + (pow(sin(x.q), 2) + pow(cos(x.q), 2) - 1) * x.T2 + z * x.T3;
    const std::vector<bool> c =
        calc_changes_with_at_random_states(x.st, e, {x.T1, x.T2, x.T3, x.m, x.q});
    ASSERT_EQ(c.size(), 5u);
    EXPECT_TRUE(c[0]);
    EXPECT_FALSE(c[1]);
    EXPECT_TRUE(c[2]);
    EXPECT_TRUE(c[3]);  // through z
    EXPECT_TRUE(c[4]);
    // a symbol e does not hold
    const ex absent = x.st.add_unknown("T4");
    EXPECT_FALSE(calc_changes_with_at_random_states(x.st, e, {absent}).at(0));
    // agreement with the derivative's zero test, symbol by symbol
    for (const ex& s : {x.T1, x.T2, x.T3})
        EXPECT_EQ(calc_changes_with_at_random_states(x.st, e, {s}).at(0),
                  !is_zero_at_random_states(x.st, e.diff(GiNaC::ex_to<GiNaC::symbol>(s))));
}

TEST(ZeroTest, WhereTheExpressionCannotBeEvaluatedEachSymbolIsTestedByItsDerivative) {
    Table x;
    // log of a negative number at every state: not evaluable, so the derivative decides
    const ex bad = GiNaC::log(-pow(x.q, 2) - 1);
    const ex e = bad + x.T1 * x.L + 0 * x.T2;
    const std::vector<bool> c = calc_changes_with_at_random_states(x.st, e, {x.T1, x.T2});
    EXPECT_TRUE(c[0]);
    EXPECT_FALSE(c[1]);
}

TEST(ZeroTest, ADeepChainOfSharedIntermediatesIsEvaluatedOncePerIntermediate) {
    // z_k uses z_(k-1) twice: walked as a tree, 2^300 paths; each intermediate's value is
    // computed once per state, and depends_on finds a leaf in the gathered leaf sets
    Table x;
    ex z = x.st.add_intermediate(cos(x.q), "z0");
    for (int k = 1; k <= 300; ++k)
        z = x.st.add_intermediate(z * x.L / 2 + z * x.L / 2 + sin(x.q) - sin(x.q), "z" + std::to_string(k));
    EXPECT_TRUE(x.st.depends_on(z, x.q));
    EXPECT_FALSE(x.st.depends_on(z, x.T1));
    // z_300 = L^300 cos q, and 0.7^300 is far below the zero test's tolerance: scale by T1
    EXPECT_FALSE(is_zero_at_random_states(x.st, z * x.T1 + x.T2));
    EXPECT_TRUE(is_zero_at_random_states(x.st, z - z));
    const std::vector<bool> c = calc_changes_with_at_random_states(x.st, z + x.T1, {x.T1, x.q, x.T2});
    EXPECT_TRUE(c[0]);
    EXPECT_FALSE(c[2]);
}

TEST(ZeroTest, MeasuresChangeByTheirPartialsWhenOneSymbolMoves) {
    // a velocity's measures, linear in the speeds u and w, with coefficients through an
    // intermediate: moving u by 1 changes them by their partials with respect to u, which
    // are the values of the symbolic derivative at the same states
    Table x;
    const ex u = x.st.add_variable("u"), w = x.st.add_variable("w");
    const ex z = x.st.add_intermediate(x.m * x.L * sin(x.q), "zq");
    const Col3 c{{x.L * cos(x.q) * u, z * u + w, (pow(sin(x.q), 2) + pow(cos(x.q), 2) - 1) * w}};
    MeasuresAtRandomStates at(x.st);
    const Col3 by_u = c.map([&](const ex& e) { return e.diff(GiNaC::ex_to<GiNaC::symbol>(u)); });
    EXPECT_TRUE(MeasuresAtRandomStates::agree(at.calc_changes(c, u), at.calc_values(by_u)));
    EXPECT_FALSE(MeasuresAtRandomStates::agree(at.calc_changes(c, w), at.calc_values(by_u)));
    EXPECT_TRUE(at.calc_changes_with(c, u));
    EXPECT_TRUE(at.calc_changes_with(c, w));
    EXPECT_TRUE(at.calc_changes_with(c, x.m));  // inside zq
    EXPECT_FALSE(at.calc_changes_with(c, x.T1));
    // the third measure's coefficient of w is zero though it does not look it
    const Col3 third{{0, 0, c[2]}};
    EXPECT_FALSE(at.calc_changes_with(third, w));
    // asked again after another symbol moved: the same partials
    EXPECT_TRUE(MeasuresAtRandomStates::agree(at.calc_changes(c, u), at.calc_values(by_u)));
    // not evaluable at the states: an error, for the caller's symbolic test
    const Col3 bad{{GiNaC::log(-pow(x.q, 2) - 1), 0, 0}};
    EXPECT_THROW(at.calc_values(bad), std::exception);
}
