// SPDX-License-Identifier: MIT
// Joint reactions as road-map unknowns: a row per measure, checked by hand and against
// brute-force Newton–Euler at random states.
#include <cmath>
#include <cstdio>

#include "alembert/eom/cross_check.hpp"
#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::kAgree;

namespace {

std::vector<std::string> body_names(const BodySet& S) {
    std::vector<std::string> n;
    for (const Body* b : S) n.push_back(b->name());
    return n;
}

bool holds(const std::vector<ex>& xs, const ex& x) {
    return std::any_of(xs.begin(), xs.end(), [&](const ex& y) { return y.is_equal(x); });
}

}  // namespace

TEST(JointReactions, TriplePendulumInverseDynamicsGivesEveryMeasureARowOfItsOwn) {
    SampleModel m = make_triple_pendulum();
    std::vector<ex> R = test::declare_chain_reactions(m, false);
    std::vector<ex> unknowns = m.unknowns;  // T_A, T_B, T_C, then the six force measures
    unknowns.insert(unknowns.end(), R.begin(), R.end());
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, unknowns);
    ASSERT_EQ(rows.size(), 9u);
    // one unknown per row, so they come out in the order of the unknowns
    const std::vector<std::vector<std::string>> S{{"A", "B", "C"}, {"B", "C"}, {"C"}};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_TRUE(rows[i].variable.is_equal(unknowns[i])) << rows[i].variable;
        EXPECT_TRUE(rows[i].additional_unknowns.empty()) << rows[i].variable;
        EXPECT_TRUE(rows[i].note.empty()) << rows[i].note;
    }
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 2; ++k) {
            const RoadmapRow& r = rows[3 + 2 * j + k];
            // the force along û moves what lies beyond the joint, translating along û
            EXPECT_EQ(r.motion, Motion::translate);
            EXPECT_EQ(body_names(r.system), S[j]);
            EXPECT_EQ(r.about, &m.system.point(m.links[j]->name() + "_o"));
            const Frame& F = m.links[j]->body_frame();
            EXPECT_TRUE(test::same(r.direction, k ? F.y() : F.x(), F));
        }
}

TEST(JointReactions, ForwardDynamicsSolvesTheAccelerationsFirstThenEachReaction) {
    SampleModel m = make_triple_pendulum();
    std::vector<ex> R = test::declare_chain_reactions(m, false);
    // the reactions listed first: the planner still puts the coupled accelerations first
    std::vector<ex> unknowns = R;
    for (const TimeVariable& q : m.q) unknowns.push_back(q.d(2));
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, unknowns);
    ASSERT_EQ(rows.size(), 9u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(rows[i].variable.is_equal(m.q[i].d(2))) << rows[i].variable;
        EXPECT_TRUE(rows[i].note.empty()) << rows[i].note;
    }
    for (std::size_t i = 3; i < 9; ++i) {
        EXPECT_TRUE(rows[i].variable.is_equal(R[i - 3])) << rows[i].variable;
        EXPECT_TRUE(rows[i].note.empty()) << rows[i].note;
        // only accelerations besides its own measure: solved one after another
        for (const ex& x : rows[i].additional_unknowns) EXPECT_FALSE(holds(R, x)) << x;
    }
}

TEST(JointReactions, MoreMeasuresThanCoordinatesArePlanned) {
    // 3 spatial links: 6 coordinates, 6 motor torques and 12 reaction measures
    SampleModel m = make_n_link_pendulum(3, ChainKind::spatial);
    std::vector<ex> R = test::declare_chain_reactions(m, true);
    std::vector<ex> unknowns = m.unknowns;
    unknowns.insert(unknowns.end(), R.begin(), R.end());
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, unknowns);
    ASSERT_EQ(rows.size(), 6u + 12u);
    for (const RoadmapRow& r : rows) {
        EXPECT_TRUE(r.additional_unknowns.empty()) << r.variable;
        EXPECT_TRUE(r.note.empty()) << r.variable << ": " << r.note;
    }
}

TEST(JointReactions, TorqueRowKeepsItsMeasureAndDropsTheForceAtTheJoint) {
    SampleModel m = make_n_link_pendulum(2, ChainKind::spatial);
    std::vector<ex> R = test::declare_chain_reactions(m, true);
    ex M2 = m.system.symbols().symbol("M_B2");
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, {M2}, Analysis::statics);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].motion, Motion::rotate);
    EXPECT_EQ(rows[0].about->name(), "B2_o");
    EXPECT_EQ(body_names(rows[0].system), std::vector<std::string>{"B2"});
    // the FBD marks what the row keeps: the torque, not the forces through B2_o
    std::string fbd;
    for (const std::string& l : rows[0].fbd) fbd += l + "\n";
    EXPECT_NE(fbd.find("M_B2 on B2 from B1 (unknown)\n"), std::string::npos) << fbd;
    EXPECT_NE(fbd.find("R_B2_x at B2_o from B1 (unknown, drops out)"), std::string::npos) << fbd;
}

TEST(JointReactions, RodPendulumPinForceIsWeightPlusCentripetalByHand) {
    // a uniform rod hanging at q = 0 turning at q' = w: the pin force along By> (up the rod)
    // is m g + m (L/2) w^2 and along Bx> it is m (L/2) q'' (tangential), by hand
    test::Model p = test::make_rod_pendulum();
    System& sys = p.sys;
    SymbolTable& s = sys.symbols();
    RigidBody& B = sys.rigid_body("B");
    ex Rx = s.add_unknown("R_x"), Ry = s.add_unknown("R_y");
    sys.add_joint_reaction("pin", nullptr, B, sys.point("B_o"),
                           {{Rx, B.body_frame().x()}, {Ry, B.body_frame().y()}});
    std::vector<RoadmapRow> rows = plan_roadmap(sys, p.q, {p.loads[0], Rx, Ry});
    ASSERT_EQ(rows.size(), 3u);
    const ex& q = p.q[0].symbol();
    const double w = 1.7, acc = -0.6, mass = 1.3, L = 0.8, g = 9.81;
    exmap at{{q, 0}, {p.q[0].d(1), w}, {p.q[0].d(2), acc}};
    std::vector<ex> E{rows[1].equation, rows[2].equation};
    LinearSystem ls = form_linear_system(E, {Rx, Ry});
    // E = b - A x: x = A^-1 b, here A diagonal
    double Rx_v = s.evaluate(ls.b(0, 0), at) / s.evaluate(ls.A(0, 0), at);
    double Ry_v = s.evaluate(ls.b(1, 0), at) / s.evaluate(ls.A(1, 1), at);
    EXPECT_TRUE(test::near(Ry_v, mass * g + mass * (L / 2) * w * w));
    EXPECT_TRUE(test::near(Rx_v, mass * (L / 2) * acc));
}

TEST(JointReactions, DirectionsThatAreNotOrthogonalAreSolvedTogether) {
    test::Model p = test::make_rod_pendulum();
    System& sys = p.sys;
    SymbolTable& s = sys.symbols();
    RigidBody& B = sys.rigid_body("B");
    const Frame& F = B.body_frame();
    ex R1 = s.add_unknown("R1"), R2 = s.add_unknown("R2");
    sys.add_joint_reaction("pin", nullptr, B, sys.point("B_o"), {{R1, F.x()}, {R2, F.x() + F.y()}});
    std::vector<RoadmapRow> rows = plan_roadmap(sys, p.q, {p.loads[0], R1, R2});
    ASSERT_EQ(rows.size(), 3u);
    // u1 . F = R1 + R2 and u2 . F = R1 + 2 R2 share both measures; the torque's row holds
    // neither (the pin force passes through B_o)
    EXPECT_TRUE(rows[0].variable.is_equal(p.loads[0]));
    EXPECT_TRUE(rows[0].note.empty()) << rows[0].note;
    EXPECT_TRUE(rows[1].variable.is_equal(R1));
    EXPECT_EQ(rows[1].note, "solve together with the rows of R2");
    EXPECT_EQ(rows[2].note, "solve together with the rows of R1");
    EXPECT_NE(format_roadmap_table(sys, rows).find("solve together with the rows of R2"),
              std::string::npos);
}

TEST(JointReactions, SwappedParentAndChildIsAModelErrorNamingTheFix) {
    SampleModel m = make_triple_pendulum();
    SymbolTable& s = m.system.symbols();
    ex R = s.add_unknown("R");
    // the knee's reaction declared as acting on the shank A from the thigh B
    m.system.add_joint_reaction("knee", m.links[1], *m.links[0], m.system.point("B_o"),
                                {{R, m.links[0]->body_frame().y()}});
    EXPECT_THROW_MSG(plan_roadmap(m.system, m.q, {R}), ModelError,
                     "declare the reaction with its parent and child swapped");
}

TEST(JointReactions, DeclarationsAreChecked) {
    SampleModel m = make_triple_pendulum();
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    RigidBody& A = *m.links[0];
    ex R = s.add_unknown("R");
    ex k = s.add_constant("k", 1.0);
    EXPECT_THROW_MSG(
        sys.add_joint_reaction("ankle", nullptr, A, sys.point("A_o"), {{k, A.body_frame().x()}}),
        ArgumentError, "the measure 'k' of 'ankle' is not an unknown");
    EXPECT_THROW_MSG(sys.add_joint_reaction("ankle", nullptr, A, sys.point("A_o"), {{R, Vector()}}),
                     ArgumentError, "the direction of 'R' in 'ankle' is zero");
    EXPECT_THROW_MSG(
        sys.add_joint_reaction("ankle", &A, A, sys.point("A_o"), {{R, A.body_frame().x()}}),
        ArgumentError, "between 'A' and itself");
    sys.add_joint_reaction("ankle", nullptr, A, sys.point("A_o"), {{R, A.body_frame().x()}});
    EXPECT_THROW_MSG(
        sys.add_joint_reaction("ankle2", nullptr, A, sys.point("A_o"), {{R, A.body_frame().y()}}),
        ArgumentError, "belongs to the reaction 'ankle' already");
    EXPECT_EQ(sys.reaction_of(R), &sys.joint_reactions().front());
}

TEST(JointReactions, TriplePendulumReactionsMatchNewtonEuler) {
    SampleModel m = make_triple_pendulum();
    std::vector<ex> R = test::declare_chain_reactions(m, false);
    ReactionComparison c = compare_reactions(m.system, m.q, 4);
    ASSERT_EQ(c.measures.size(), 6u);
    EXPECT_LT(c.max_difference, kAgree);
    std::printf("triple pendulum: 6 reaction measures, largest difference %.2g\n",
                c.max_difference);
}

TEST(JointReactions, PlanarChainReactionsMatchNewtonEuler) {
    for (int n = 1; n <= 8; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::planar);
        test::declare_chain_reactions(m, false);
        ReactionComparison c = compare_reactions(m.system, m.q, 2);
        EXPECT_EQ(c.measures.size(), 2u * static_cast<std::size_t>(n));
        EXPECT_LT(c.max_difference, kAgree) << n << " links";
    }
}

TEST(JointReactions, SpatialChainReactionsMatchNewtonEuler) {
    for (int n = 1; n <= 8; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::spatial);
        test::declare_chain_reactions(m, true);
        ReactionComparison c = compare_reactions(m.system, m.q, 2);
        EXPECT_EQ(c.measures.size(), 4u * static_cast<std::size_t>(n));
        EXPECT_LT(c.max_difference, kAgree) << n << " links";
        std::printf("spatial chain of %d links: %zu reaction measures, largest difference %.2g\n",
                    n, c.measures.size(), c.max_difference);
    }
}

TEST(JointReactions, FourBarCrankPinRowComesAfterTheLoopItNeeds) {
    // statics of the four-bar with the crank-coupler pin's force along Nx> as an unknown too:
    // its row (S = {B}, what lies beyond the pin, along Nx>) holds the loop's pin force F_x
    // and the loop's angles, so it is solved after the block that gives them
    SampleModel m = make_four_bar();
    System& sys = m.system;
    ex R = sys.symbols().add_unknown("R_AB_x");
    sys.add_joint_reaction("crank pin", m.links[0], *m.links[1], sys.point("B_o"),
                           {{R, sys.newtonian().x()}});
    ex T = m.unknowns[0], Fx = m.unknowns[1], Fy = m.unknowns[2];
    std::vector<ex> unknowns{R, T, Fx, Fy, m.q[1].symbol(), m.q[2].symbol()};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns, Analysis::statics);
    ASSERT_EQ(rows.size(), 6u);
    auto position = [&](const ex& x) {
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (rows[i].variable.is_equal(x)) return i;
        ADD_FAILURE() << "no row for " << x;
        return rows.size();
    };
    const std::size_t r = position(R);
    for (const ex& x : {Fx, Fy, m.q[1].symbol(), m.q[2].symbol()}) EXPECT_LT(position(x), r) << x;
    const RoadmapRow& row = rows[r];
    EXPECT_EQ(row.motion, Motion::translate);
    EXPECT_EQ(body_names(row.system), std::vector<std::string>{"B"});
    EXPECT_TRUE(holds(row.additional_unknowns, Fx));
    EXPECT_FALSE(holds(row.additional_unknowns, Fy));  // along Ny>, normal to the row's Nx>
    EXPECT_FALSE(holds(row.additional_unknowns, T));
    // solved after the block it needs: no note
    EXPECT_TRUE(row.note.empty()) << row.note;
}

// A closed loop: the four-bar's three pins to the ground and the crank as declared reactions,
// the loop's pin force F_x, F_y held by the loop constraints. The road-map (coordinate rows
// and the loop's constraint rows) and brute-force Newton–Euler (9 body equations and the
// loop at the acceleration level, in 11 unknowns) are solved at random states that close the
// loop (qB, qC by Newton's method, their rates from the loop's velocity level).
TEST(JointReactions, FourBarReactionsMatchNewtonEuler) {
    SampleModel m = make_four_bar();
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    const Frame& N = sys.newtonian();
    auto declare = [&](const std::string& name, const Body* parent, const Body& child,
                       const std::string& at) {
        sys.add_joint_reaction(name, parent, child, sys.point(at),
                               {{s.add_unknown("R_" + child.name() + "_x"), N.x()},
                                {s.add_unknown("R_" + child.name() + "_y"), N.y()}});
    };
    declare("crank bearing", nullptr, *m.links[0], "A_o");
    declare("crank pin", m.links[0], *m.links[1], "B_o");
    declare("rocker bearing", nullptr, *m.links[2], "C_o");
    const ex Fx = m.unknowns[1], Fy = m.unknowns[2];
    ReactionComparison c = compare_reactions(sys, m.q, 4, 1, {}, {Fx, Fy});
    ASSERT_EQ(c.measures.size(), 8u);
    EXPECT_TRUE(c.measures[0].is_equal(Fx));
    EXPECT_TRUE(c.measures[1].is_equal(Fy));
    EXPECT_LT(c.max_difference, kAgree);
    std::printf("four-bar: the loop's pin force and 6 reaction measures, largest difference %.2g\n",
                c.max_difference);
}

TEST(JointReactions, ConstraintForceThatIsAReactionMeasureIsAnArgumentError) {
    SampleModel m = make_triple_pendulum();
    std::vector<ex> R = test::declare_chain_reactions(m, false);
    EXPECT_THROW_MSG(compare_reactions(m.system, m.q, 1, 1, {}, {R[0]}), ArgumentError,
                     "is a measure of a declared joint reaction");
}

// Rolling: the ground's force on the disk at the contact, friction F_x, F_y and normal F_z,
// held by the no-slip motion constraints and the height constraint. The road-map's rows (6
// coordinate rows and the 3 constraint rows) and brute-force Newton–Euler (6 body equations
// and the 3 constraints at the acceleration level) give the same contact force at random
// states that satisfy the constraints.
TEST(JointReactions, RollingDiskContactForceMatchesNewtonEuler) {
    test::Model d = test::make_rolling_disk_with_contact();
    ReactionComparison c = compare_reactions(d.sys, d.q, 4, 1, {}, d.loads);
    ASSERT_EQ(c.measures.size(), 3u);
    EXPECT_LT(c.max_difference, kAgree);
    std::printf("rolling disk: contact force (3 measures), largest difference %.2g\n",
                c.max_difference);
    // by hand: released at rest with lean q2, the disk pivots about the contact line,
    // (m r^2/4 + m r^2) q2'' = +-m g r sin q2, so the centre's vertical acceleration is
    // -r sin q2 |q2''| and the ground pushes F_z = m g (1 - 4/5 sin^2 q2) up, and horizontally
    // m r cos q2 |q2''| = 4/5 m g sin q2 cos q2
    const SymbolTable& st = d.sys.symbols();
    std::vector<ex> x = test::accelerations(d.q);
    x.insert(x.end(), d.loads.begin(), d.loads.end());
    std::vector<ex> E;
    for (const RoadmapRow& r : plan_roadmap(d.sys, d.q, x)) E.push_back(r.equation);
    LinearSystem L = form_linear_system(E, x);
    const double m = 2.0, r = 0.3, g = 9.81;
    for (double lean : {0.0, 0.4, -1.1}) {
        exmap state{{d.q[0].symbol(), 0.3}, {d.q[1].symbol(), lean}, {d.q[2].symbol(), 0.2},
                    {d.q[3].symbol(), 0.1}, {d.q[4].symbol(), -0.2},
                    {d.q[5].symbol(), r * std::cos(lean)}};
        for (const TimeVariable& qi : d.q) state[qi.d(1)] = 0;
        Eigen::VectorXd v = solve_numeric(st, L, state);
        EXPECT_NEAR(v(8), m * g * (1 - 0.8 * std::sin(lean) * std::sin(lean)), 1e-12 * m * g);
        EXPECT_NEAR(std::hypot(v(6), v(7)), 0.8 * m * g * std::abs(std::sin(lean) * std::cos(lean)),
                    1e-12 * m * g);
    }
}
