// SPDX-License-Identifier: MIT
// The planner reproduces the seed's road-map and solves inverse dynamics and statics.
#include "alembert/eom/planner.hpp"

#include "alembert/eom/equations.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::sin;

namespace {
std::vector<std::string> names(const BodySet& S) {
    std::vector<std::string> n;
    for (const Body* b : S) n.push_back(b->name());
    return n;
}
}  // namespace

TEST(Planner, TriplePendulumGivesTheSeedsThreeRows) {
    SampleModel m = make_triple_pendulum();
    System& sys = m.system;
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, m.unknowns);
    ASSERT_EQ(rows.size(), 3u);
    const std::vector<std::vector<std::string>> S{{"A", "B", "C"}, {"B", "C"}, {"C"}};
    const char* about[] = {"A_o", "B_o", "C_o"};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(rows[i].variable.is_equal(m.unknowns[i]));
        EXPECT_EQ(rows[i].motion, Motion::rotate);
        EXPECT_TRUE(same(dot(rows[i].direction, sys.newtonian().z()), 1));  // u = Nz>
        EXPECT_EQ(names(rows[i].system), S[i]);
        ASSERT_NE(rows[i].about, nullptr);
        EXPECT_EQ(rows[i].about->name(), about[i]);
        EXPECT_TRUE(rows[i].note.empty()) << rows[i].note;
        EXPECT_TRUE(rows[i].additional_unknowns.empty());
        // the row's own torque is the only torque in it
        for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(rows[i].equation.has(m.unknowns[j]), i == j);
    }
    std::string table = format_roadmap_table(sys, rows);
    EXPECT_NE(table.find("| T_B      | rotate"), std::string::npos) << table;
    EXPECT_NE(table.find("{B, C}"), std::string::npos);
    EXPECT_NE(table.find("Nz>"), std::string::npos);
    std::string json = format_roadmap_json(sys, rows);
    EXPECT_NE(json.find("\"system\": [\"A\", \"B\", \"C\"]"), std::string::npos) << json;
    EXPECT_NE(json.find("\"about\": \"C_o\""), std::string::npos);
}

TEST(Planner, InverseDynamicsTorquesSatisfyEveryRow) {
    SampleModel m = make_triple_pendulum();
    System& sys = m.system;
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, m.unknowns);
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    std::vector<ex> T = solve_symbolic(form_linear_system(E, m.unknowns));
    // substituting the solved torques back makes each equation vanish
    exmap sol;
    for (std::size_t i = 0; i < 3; ++i) sol[m.unknowns[i]] = T[i];
    for (const ex& e : E) EXPECT_TRUE(same(e.subs(sol), 0));
}

TEST(Planner, StaticsTorquesAreTheGravityMomentsByHand) {
    SampleModel m = make_triple_pendulum();
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, m.unknowns, Analysis::statics);
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) {
        EXPECT_FALSE(r.equation.has(m.q[0].d(2)));
        E.push_back(r.equation);
    }
    std::vector<ex> T = solve_symbolic(form_linear_system(E, m.unknowns));
    ex g = s.symbol("g"), L_A = s.symbol("L_A"), L_B = s.symbol("L_B");
    ex d_A = s.symbol("d_A"), d_B = s.symbol("d_B"), d_C = s.symbol("d_C");
    ex m_A = s.symbol("m_A"), m_B = s.symbol("m_B"), m_C = s.symbol("m_C");
    ex qA = m.q[0], qB = m.q[1], qC = m.q[2];
    ex phi = qA + qB, theta = qA + qB + qC;
    // each motor holds the gravity moment of what is above its joint
    ex T_C = -g * m_C * d_C * sin(theta);
    ex T_B = -g * (m_B * d_B * sin(phi) + m_C * (L_B * sin(phi) + d_C * sin(theta)));
    ex T_A = -g * (m_A * d_A * sin(qA) + m_B * (L_A * sin(qA) + d_B * sin(phi)) +
                   m_C * (L_A * sin(qA) + L_B * sin(phi) + d_C * sin(theta)));
    EXPECT_TRUE(same(T[0], T_A));
    EXPECT_TRUE(same(T[1], T_B));
    EXPECT_TRUE(same(T[2], T_C));
    // upright standing needs no torque
    exmap upright{{qA, 0}, {qB, 0}, {qC, 0}};
    for (const ex& Ti : T) EXPECT_NEAR(s.evaluate(Ti, upright), 0.0, 1e-15);
    // seat-off pose (-25, 105, -130 deg): compare the numbers too
    const double deg = M_PI / 180;
    exmap seat{{qA, -25 * deg}, {qB, 105 * deg}, {qC, -130 * deg}};
    EXPECT_NEAR(s.evaluate(T[2], seat), s.evaluate(T_C, seat), 1e-12);
}

TEST(Planner, SlidingMassGetsATranslateRow) {
    SampleModel m = make_mass_spring_damper();
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, {m.q[0].d(2)});
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].motion, Motion::translate);
    EXPECT_TRUE(same(dot(rows[0].direction, m.system.newtonian().x()), 1));
    EXPECT_EQ(rows[0].about, nullptr);
    EXPECT_EQ(names(rows[0].system), std::vector<std::string>{"Q"});
}

TEST(Planner, ForwardDynamicsRowsListTheCoupledAccelerations) {
    SampleModel m = make_triple_pendulum();
    std::vector<ex> acc{m.q[0].d(2), m.q[1].d(2), m.q[2].d(2)};
    std::vector<RoadmapRow> rows = plan_roadmap(m.system, m.q, acc);
    // the hip row holds all three accelerations: its additional unknowns are qA'', qB''
    ASSERT_EQ(rows[2].additional_unknowns.size(), 2u);
    EXPECT_TRUE(rows[2].additional_unknowns[0].is_equal(acc[0]));
    EXPECT_TRUE(rows[2].additional_unknowns[1].is_equal(acc[1]));
}

TEST(Planner, RejectsUnknownsNoRowHolds) {
    SampleModel m = make_triple_pendulum();
    ex F = m.system.symbols().add_unknown("F_x");
    EXPECT_THROW_MSG(plan_roadmap(m.system, m.q, {m.unknowns[0], m.unknowns[1], F}), ModelError,
                     "no road-map row holds the unknown 'F_x'");
    EXPECT_THROW_MSG(plan_roadmap(m.system, m.q, {m.unknowns[0], m.unknowns[1], m.unknowns[2], F}),
                     ModelError, "4 unknowns but only 3 coordinates");
}

namespace {
// the rows' notes that claim S does not move as one body
std::string rigidity_notes(const System& sys, const std::vector<TimeVariable>& q) {
    std::vector<ex> acc;
    for (const TimeVariable& qi : q) acc.push_back(qi.d(2));
    std::string out;
    for (const RoadmapRow& r : plan_roadmap(sys, q, acc))
        if (r.note.find("as one body") != std::string::npos)
            out += to_string(r.variable) + ": " + r.note + "\n";
    return out;
}
}  // namespace

// The rigidity checks decide their zeros at random states through the named intermediates,
// so no tree model of the cross-check gets a false "does not turn as one body" note: not the
// deep chains, not a payload particle on the last link.
TEST(Planner, TreeModelsOfTheCrossCheckHaveNoRigidityNote) {
    {
        SampleModel m = make_triple_pendulum();
        EXPECT_EQ(rigidity_notes(m.system, m.q), "");
    }
    for (ChainKind kind : {ChainKind::planar, ChainKind::spatial})
        for (int n = 1; n <= 8; ++n) {
            SampleModel m = make_n_link_pendulum(n, kind);
            EXPECT_EQ(rigidity_notes(m.system, m.q), "") << n << " links";
        }
    for (int n : {4, 8}) {
        SampleModel m = make_planar_chain(n);
        EXPECT_EQ(rigidity_notes(m.system, m.q), "") << n << " links";
    }
    {
        SampleModel m = make_mass_spring_damper();
        EXPECT_EQ(rigidity_notes(m.system, m.q), "");
    }
    for (test::Model (*make)() :
         {&test::make_rod_pendulum, &test::make_particle_double_pendulum,
          &test::make_free_rigid_body, &test::make_gimbal, &test::make_rod_and_plate}) {
        test::Model m = make();
        EXPECT_EQ(rigidity_notes(m.sys, m.q), "");
    }
    {
        test::Model m = test::make_spinning_tube(false);
        EXPECT_EQ(rigidity_notes(m.sys, m.q), "");
    }
    // a payload particle at the tip of the last of five planar links
    SampleModel m = make_n_link_pendulum(5, ChainKind::planar);
    SymbolTable& s = m.system.symbols();
    Particle& P = m.system.add_particle("P");
    P.set_mass(s.add_constant("mP", 2.0));
    P.point().set_pos(m.system.point("B5_o"), -s.symbol("L5") * m.links[4]->body_frame().y());
    EXPECT_EQ(rigidity_notes(m.system, m.q), "");
}

// the check still says so where S really does not turn as one body about O: a rod B oriented
// by an absolute angle and hung from the tip of rod A translates when A turns
TEST(Planner, AbsoluteAngleOfAHungRodKeepsItsNote) {
    System sys("N");
    SymbolTable& s = sys.symbols();
    const Frame& N = sys.newtonian();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    ex L = s.add_constant("L", 1.0), mass = s.add_constant("m", 1.0);
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    A.body_frame().orient_axis(N, Axis::z, q1);
    B.body_frame().orient_axis(N, Axis::z, q2);
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), -(L / 2) * A.body_frame().y());
    sys.point("B_o").set_pos(sys.point("A_o"), -L * A.body_frame().y());
    B.cm().set_pos(sys.point("B_o"), -(L / 2) * B.body_frame().y());
    for (RigidBody* b : {&A, &B}) {
        b->set_mass(mass);
        b->set_inertia(b->cm(), 0, 0, mass * L * L / 12);
    }
    sys.set_gravity(-s.add_constant("g", 9.81) * N.y());
    EXPECT_EQ(rigidity_notes(sys, {q1, q2}),
              "q1'': S does not turn as one body about A_o when only q1 changes; constraint "
              "forces may remain\n");
}
