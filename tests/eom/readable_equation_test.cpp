// SPDX-License-Identifier: MIT
// A row's equation as the report shows it: solved for the row's unknown where that is exact,
// collected in the accelerations; checked by meaning (numbers at random states), never by the
// printed order.
#include "alembert/eom/readable_equation.hpp"

#include <random>

#include "alembert/eom/planner.hpp"
#include "alembert/eom/roadmap.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::kAgree;
using alembert::test::random_state;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {

struct Triple {
    SampleModel m = make_triple_pendulum();
    SymbolTable& s = m.system.symbols();
    TimeVariable &qA = m.q[0], &qB = m.q[1], &qC = m.q[2];
    ex g = s.symbol("g"), L_A = s.symbol("L_A"), L_B = s.symbol("L_B");
    ex d_C = s.symbol("d_C"), m_C = s.symbol("m_C"), I_C = s.symbol("I_C"), T_C = s.symbol("T_C");

    // the hip row: S = {C} about the hip C_o, direction Nz (roadmap_test's hand derivation)
    ex hip_row() {
        System& sys = m.system;
        RoadmapRow row{.variable = T_C, .motion = Motion::rotate, .direction = sys.newtonian().z(),
                       .system = sys.bodies({"C"}), .about = &sys.point("C_o")};
        form_roadmap_row(sys, row, m.unknowns);
        return row.equation;
    }
};

// |a - b| relative to max(1, |a|, |b|) at `states` random states
double worst_difference(const SymbolTable& st, const ex& a, const ex& b, int states = 5) {
    std::mt19937 rng(20261127);
    double worst = 0;
    for (int k = 0; k < states; ++k) {
        const exmap x = random_state(st, rng, {});
        const double va = st.evaluate(a, x), vb = st.evaluate(b, x);
        worst = std::max(worst, std::abs(va - vb) / std::max({1.0, std::abs(va), std::abs(vb)}));
    }
    return worst;
}

// how many terms of the sum `e` hold `s` (1: its coefficient is gathered in one term)
int terms_holding(const ex& e, const ex& s) {
    if (!GiNaC::is_a<GiNaC::add>(e)) return e.has(s) ? 1 : 0;
    int n = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) n += e.op(i).has(s) ? 1 : 0;
    return n;
}

// how many terms of the sum `e` hold the product a^i b^j of rates (in their expansion)
int terms_with_rates(const ex& e, const ex& a, int i, const ex& b, int j) {
    const auto holds = [&](const ex& t) {
        return !GiNaC::expand(t).coeff(a, i).coeff(b, j).is_zero();
    };
    if (!GiNaC::is_a<GiNaC::add>(e)) return holds(e) ? 1 : 0;
    int n = 0;
    for (std::size_t k = 0; k < e.nops(); ++k) n += holds(e.op(k)) ? 1 : 0;
    return n;
}

}  // namespace

TEST(ReadableEquation, HipRowIsSolvedForItsTorqueAsDerivedByHand) {
    // E = T_C + m_C g d_C sin(theta) - I_C theta'' - m_C d_C [d_C theta'' + L_A (qA'' cos(beta)
    //     + qA'^2 sin(beta)) + L_B (phi'' cos(qC) + phi'^2 sin(qC))] = 0, with theta = qA+qB+qC,
    // phi = qA+qB, beta = qB+qC; T_C enters with coefficient 1, so
    // T_C = -m_C g d_C sin(theta) + I_C theta'' + m_C d_C [d_C theta'' + L_A (...) + L_B (...)]
    Triple t;
    const TimeVariable &qA = t.qA, &qB = t.qB, &qC = t.qC;
    const ex th2 = qA.d(2) + qB.d(2) + qC.d(2), ph1 = qA.d(1) + qB.d(1), ph2 = qA.d(2) + qB.d(2);
    const ex beta = qB + qC, theta = qA + qB + qC;
    const ex T_C_by_hand =
        -t.m_C * t.g * t.d_C * sin(theta) + t.I_C * th2 +
        t.m_C * t.d_C *
            (t.d_C * th2 + t.L_A * (qA.d(2) * cos(beta) + pow(qA.d(1), 2) * sin(beta)) +
             t.L_B * (ph2 * cos(qC) + pow(ph1, 2) * sin(qC)));
    const ex E = t.hip_row();
    Simplifier simplifier;
    const ReadableRelation r = calc_solved_equation(t.m.system, E, t.T_C, simplifier);
    ASSERT_TRUE(r.solved());
    EXPECT_TRUE(r.lhs.is_equal(t.T_C));
    EXPECT_FALSE(r.rhs.has(t.T_C));
    EXPECT_LE(worst_difference(t.s, r.rhs, T_C_by_hand), kAgree);
    // the solved form satisfies the row: E with T_C = rhs is zero
    EXPECT_LE(worst_difference(t.s, E.subs(GiNaC::lst{t.T_C == r.rhs}), 0), kAgree);
    // each acceleration's coefficient gathered in one term of the right side: qA'' has
    // I_C + m_C d_C (d_C + L_A cos(beta) + L_B cos(qC)) (from theta'', L_A qA'' cos(beta) and
    // L_B phi'' cos(qC)); qC'' has I_C + m_C d_C^2
    for (const TimeVariable* q : {&qA, &qB, &qC}) EXPECT_EQ(terms_holding(r.rhs, q->d(2)), 1);
    const ex cA = t.I_C + t.m_C * t.d_C * (t.d_C + t.L_A * cos(beta) + t.L_B * cos(qC));
    const ex cC = t.I_C + t.m_C * t.d_C * t.d_C;
    EXPECT_LE(worst_difference(t.s, r.rhs.coeff(qA.d(2), 1), cA), kAgree);
    EXPECT_LE(worst_difference(t.s, r.rhs.coeff(qC.d(2), 1), cC), kAgree);
}

TEST(ReadableEquation, RowForAnAccelerationIsSolvedByItsConstantCoefficientAndGathered) {
    // the hip row read for qC'': its coefficient -(I_C + m_C d_C^2) is the same at every state,
    // so qC'' = [T_C + m_C g d_C sin(theta) - (I_C + m_C d_C^2)(qA'' + qB'')
    //            - m_C d_C (L_A (qA'' cos(beta) + qA'^2 sin(beta)) + L_B (phi'' cos(qC)
    //            + phi'^2 sin(qC)))] / (I_C + m_C d_C^2)
    Triple t;
    const TimeVariable &qA = t.qA, &qB = t.qB, &qC = t.qC;
    const ex E = t.hip_row();
    Simplifier simplifier;
    const ReadableRelation r = calc_solved_equation(t.m.system, E, qC.d(2), simplifier);
    ASSERT_TRUE(r.solved());
    EXPECT_TRUE(r.lhs.is_equal(qC.d(2)));
    EXPECT_FALSE(r.rhs.has(qC.d(2)));
    const ex J = t.I_C + t.m_C * t.d_C * t.d_C, beta = qB + qC, theta = qA + qB + qC;
    const ex ph1 = qA.d(1) + qB.d(1), ph2 = qA.d(2) + qB.d(2);
    const ex by_hand = (t.T_C + t.m_C * t.g * t.d_C * sin(theta) - J * ph2 -
                        t.m_C * t.d_C *
                            (t.L_A * (qA.d(2) * cos(beta) + pow(qA.d(1), 2) * sin(beta)) +
                             t.L_B * (ph2 * cos(qC) + pow(ph1, 2) * sin(qC)))) /
                       J;
    EXPECT_LE(worst_difference(t.s, r.rhs, by_hand), kAgree);
    EXPECT_LE(worst_difference(t.s, E.subs(GiNaC::lst{qC.d(2) == r.rhs}), 0), kAgree);
    // each acceleration, the torque and each product of rates in one term of the right side
    for (const TimeVariable* q : {&qA, &qB}) EXPECT_EQ(terms_holding(r.rhs, q->d(2)), 1);
    EXPECT_EQ(terms_holding(r.rhs, t.T_C), 1);
    const ex a = qA.d(1), b = qB.d(1);
    EXPECT_EQ(terms_with_rates(r.rhs, a, 2, b, 0), 1);
    EXPECT_EQ(terms_with_rates(r.rhs, a, 1, b, 1), 1);
    EXPECT_EQ(terms_with_rates(r.rhs, a, 0, b, 2), 1);
    EXPECT_LE(worst_difference(t.s, r.rhs.coeff(qA.d(2), 1),
                               -(J + t.m_C * t.d_C * (t.L_A * cos(beta) + t.L_B * cos(qC))) / J),
              kAgree);
}

TEST(ReadableEquation, AnEquationNotLinearInItsUnknownIsGatheredByItsUnknownLoads) {
    // a statics row for qA: qA sits inside sines, so 0 = E stays, its torques gathered
    // (T_C: L_A sin(qA) + L_B cos(qB); T_B: -L_A), the rest by its functions
    Triple t;
    const ex qA = t.qA.symbol(), qB = t.qB.symbol();
    const ex T_B = t.s.symbol("T_B");
    const ex e = t.T_C * t.L_A * sin(qA) - T_B * t.L_A + t.g * t.m_C * sin(qA) + t.T_C * t.L_B * cos(qB) +
                 t.g * t.d_C * t.m_C * sin(qA) - 2 * T_B * t.L_A;
    Simplifier simplifier;
    const ReadableRelation r = calc_solved_equation(t.m.system, e, qA, simplifier);
    EXPECT_FALSE(r.solved());
    EXPECT_LE(worst_difference(t.s, r.rhs, e), kAgree);
    EXPECT_EQ(terms_holding(r.rhs, t.T_C), 1);
    EXPECT_EQ(terms_holding(r.rhs, T_B), 1);
    EXPECT_LE(worst_difference(t.s, r.rhs.coeff(t.T_C, 1), t.L_A * sin(qA) + t.L_B * cos(qB)), kAgree);
}

TEST(ReadableEquation, ParticleDoublePendulumRowsRunAlongTheRodsAndAreSolved) {
    // Q1 moves along Ax when only q1 changes (v = L1 q1' Ax, L1 = 1.1 m): the row's direction is
    // Ax itself, with no L1/sqrt(L1^2); E = -(m1 + m2)(g sin(q1) + L1 q1'')
    //   - m2 L2 (q2'' cos(q2 - q1) + q2'^2 sin(q1 - q2)), so
    // q1'' = -g sin(q1)/L1 - m2 L2 (q2'' cos(q1 - q2) + q2'^2 sin(q1 - q2)) / ((m1 + m2) L1)
    test::Model md = test::make_particle_double_pendulum();
    const SymbolTable& s = md.sys.symbols();
    const std::vector<RoadmapRow> rows = plan_default_roadmap(md.sys, md.q);
    ASSERT_EQ(rows.size(), 2u);
    const Col3 u1 = rows[0].direction.components_in(md.sys.frame("A"));
    const Col3 u2 = rows[1].direction.components_in(md.sys.frame("B"));
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(u1[i].is_equal(i == 0 ? 1 : 0)) << u1[i];
        EXPECT_TRUE(u2[i].is_equal(i == 0 ? 1 : 0)) << u2[i];
    }
    const ex q1 = md.q[0].symbol(), q2 = md.q[1].symbol();
    const ex L1 = s.symbol("L1"), L2 = s.symbol("L2"), m1 = s.symbol("m1"), m2 = s.symbol("m2"), g = s.symbol("g");
    Simplifier simplifier;
    const ReadableRelation r = calc_solved_equation(md.sys, rows[0].equation, md.q[0].d(2), simplifier);
    ASSERT_TRUE(r.solved());
    EXPECT_TRUE(r.lhs.is_equal(md.q[0].d(2)));
    const ex by_hand = -g * sin(q1) / L1 - m2 * L2 *
                                               (md.q[1].d(2) * cos(q1 - q2) +
                                                pow(md.q[1].d(1), 2) * sin(q1 - q2)) /
                                               ((m1 + m2) * L1);
    EXPECT_LE(worst_difference(s, r.rhs, by_hand), kAgree);
    EXPECT_EQ(terms_holding(r.rhs, md.q[1].d(2)), 1);
}

TEST(ReadableEquation, SolvedOnlyWhereTheCoefficientIsAConstantAndTheUnknownLinear) {
    Triple t;
    Simplifier simplifier;
    const System& sys = t.m.system;
    const ex qA = t.qA.symbol();
    // L_A T_C - m_C g d_C sin(qA) = 0: T_C = m_C g d_C sin(qA) / L_A at every state
    const ReadableRelation r1 =
        calc_solved_equation(sys, t.L_A * t.T_C - t.m_C * t.g * t.d_C * sin(qA), t.T_C, simplifier);
    ASSERT_TRUE(r1.solved());
    EXPECT_LE(worst_difference(t.s, r1.rhs, t.m_C * t.g * t.d_C * sin(qA) / t.L_A), kAgree);
    // cos(qA) T_C - m_C g = 0: solving divides by cos(qA), which vanishes at qA = 90 deg: kept
    const ex e2 = cos(qA) * t.T_C - t.m_C * t.g;
    const ReadableRelation r2 = calc_solved_equation(sys, e2, t.T_C, simplifier);
    EXPECT_FALSE(r2.solved());
    EXPECT_LE(worst_difference(t.s, r2.rhs, e2), kAgree);
    // T_C^2 - m_C g d_C = 0 is not linear in T_C; T_C sin(T_C) + g neither
    for (const ex& e3 : {pow(t.T_C, 2) - t.m_C * t.g * t.d_C, t.T_C * sin(t.T_C) + t.g}) {
        const ReadableRelation r3 = calc_solved_equation(sys, e3, t.T_C, simplifier);
        EXPECT_FALSE(r3.solved());
        EXPECT_LE(worst_difference(t.s, r3.rhs, e3), kAgree);
    }
}
