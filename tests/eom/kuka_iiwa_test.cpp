// SPDX-License-Identifier: MIT
// The KUKA LBR iiwa 14 arm: road-map rows for its 7 motor torques and 35 joint reaction
// measures, checked against brute-force Newton–Euler at random states and by hand in statics.
#include <cstdio>

#include "alembert/eom/cross_check.hpp"
#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "kuka_iiwa_model.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::kAgree;

namespace {

std::vector<ex> torques_and_reactions(const test::KukaIiwa& m) {
    std::vector<ex> x = m.torques;
    x.insert(x.end(), m.reactions.begin(), m.reactions.end());
    return x;
}

}  // namespace

TEST(KukaIiwa, EveryTorqueAndReactionMeasureGetsARowOfItsOwn) {
    test::KukaIiwa m = test::make_kuka_iiwa();
    std::vector<ex> x = torques_and_reactions(m);
    ASSERT_EQ(x.size(), 42u);
    std::vector<RoadmapRow> rows = plan_roadmap(m.sys, m.q, x);
    ASSERT_EQ(rows.size(), 42u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        // a chain: each measure's row moves what lies beyond its joint, so it keeps no other
        // unknown and can be solved on its own, in any order
        EXPECT_TRUE(rows[i].variable.is_equal(x[i])) << rows[i].variable;
        EXPECT_TRUE(rows[i].additional_unknowns.empty()) << rows[i].variable;
        EXPECT_TRUE(rows[i].note.empty()) << rows[i].variable << ": " << rows[i].note;
    }
}

TEST(KukaIiwa, ForwardDynamicsReactionsMatchNewtonEuler) {
    test::KukaIiwa m = test::make_kuka_iiwa();
    ReactionComparison c = compare_reactions(m.sys, m.q, 3);
    EXPECT_EQ(c.measures.size(), 35u);
    EXPECT_LT(c.max_difference, kAgree);
    std::printf("KUKA iiwa, forward dynamics: %zu reaction measures, largest difference %.2g\n",
                c.measures.size(), c.max_difference);
}

TEST(KukaIiwa, InverseDynamicsTorquesAndReactionsMatchNewtonEuler) {
    test::KukaIiwa m = test::make_kuka_iiwa();
    ReactionComparison c = compare_reactions(m.sys, m.q, 3, 7, m.torques);
    ASSERT_EQ(c.measures.size(), 42u);
    EXPECT_TRUE(c.measures[0].is_equal(m.torques[0]));
    EXPECT_LT(c.max_difference, kAgree);
    std::printf("KUKA iiwa, inverse dynamics: 7 torques and 35 reaction measures, largest "
                "difference %.2g\n",
                c.max_difference);
}

TEST(KukaIiwa, HeldStillTheBaseJointCarriesTheWeightAndItsMoment) {
    // statics by hand: the whole arm's free-body diagram. The base joint's force on L1 is the
    // weight upward, F1 = M g Nz>, and its torque (reaction and motor) balances the moment of
    // the weights about L1_o: M1x L1x> + M1y L1y> + T1 L1z> = sum_i r^{Licm/L1_o} x m_i g Nz>
    test::KukaIiwa m = test::make_kuka_iiwa();
    const SymbolTable& st = m.sys.symbols();
    std::vector<ex> x = torques_and_reactions(m);
    std::vector<ex> E;
    for (const RoadmapRow& r : plan_roadmap(m.sys, m.q, x)) E.push_back(r.equation);
    LinearSystem L = form_linear_system(E, x);
    const Frame& N = m.sys.newtonian();
    const Frame& L1 = m.links[0]->body_frame();
    const Point& L1o = m.sys.point("L1_o");
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-2.5, 2.5);
    for (int k = 0; k < 3; ++k) {
        exmap state;
        for (const TimeVariable& qi : m.q) {
            state[qi.symbol()] = angle(rng);
            state[qi.d(1)] = 0;
            state[qi.d(2)] = 0;
        }
        Eigen::VectorXd v = solve_numeric(st, L, state);
        ex mass = 0;
        Vector moment;
        for (const RigidBody* B : m.links) {
            mass += B->mass();
            moment += cross(B->cm().pos_from(L1o), B->mass() * m.g * N.z());
        }
        Vector F1 = v(7) * L1.x() + v(8) * L1.y() + v(9) * L1.z();
        Vector M1 = v(10) * L1.x() + v(11) * L1.y() + v(0) * L1.z();
        const double weight = st.evaluate(mass * m.g, state);
        EXPECT_NEAR(weight, (5.76 + 6.35 + 3 * 3.5 + 1.8 + 1.2) * 9.81, 1e-12);
        for (Axis a : {Axis::x, Axis::y, Axis::z}) {
            const double up = a == Axis::z ? weight : 0.0;
            EXPECT_NEAR(st.evaluate(dot(F1, N.unit(a)), state), up, 1e-12 * weight);
            EXPECT_NEAR(st.evaluate(dot(M1 - moment, N.unit(a)), state), 0.0, 1e-12 * weight);
        }
        // gravity along the first joint's axis: its motor holds nothing
        EXPECT_NEAR(v(0), 0.0, 1e-12 * weight);
    }
}
