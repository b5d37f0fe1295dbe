// SPDX-License-Identifier: MIT
// Road-map, Kane, Lagrange and brute-force Newton–Euler agree at random states on a range of
// models; Euler's equations and a rotating-tube law checked by hand.
#include "alembert/eom/cross_check.hpp"

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

using alembert::test::kAgree;

// every method agrees with the road-map, Newton–Euler included, and on trees the recursive
// road-map rows and the articulated-body accelerations too
::testing::AssertionResult all_agree(const MethodComparison& c, bool tree = true) {
    const std::size_t expected = tree ? 6 : 4;
    if (c.methods.size() != expected || c.differences.size() != expected)
        return ::testing::AssertionFailure()
               << c.methods.size() << " methods compared, not " << expected;
    for (std::size_t m = 0; m < c.methods.size(); ++m)
        if (!(c.differences[m] < kAgree))
            return ::testing::AssertionFailure()
                   << c.methods[m] << " differs from the road-map by " << c.differences[m];
    return ::testing::AssertionSuccess();
}

MethodComparison compare(const test::Model& m, int states = 3) {
    return compare_methods(m.sys, m.q, states);
}

}  // namespace

TEST(CompareMethods, TriplePendulumAgrees) {
    SampleModel m = make_triple_pendulum();
    MethodComparison c = compare_methods(m.system, m.q, 4);
    ASSERT_EQ(c.methods.size(), 6u);
    EXPECT_EQ(c.methods[3], "Newton–Euler");
    EXPECT_EQ(c.methods[4], "recursive road-map");
    EXPECT_EQ(c.methods[5], "articulated body");
    EXPECT_TRUE(all_agree(c));
}

TEST(CompareMethods, DoublePendulumsAgree) {
    // of rigid rods (the 2-link planar chain) and of particles on massless rods
    SampleModel rods = make_n_link_pendulum(2, ChainKind::planar);
    EXPECT_TRUE(all_agree(compare_methods(rods.system, rods.q, 3)));
    EXPECT_TRUE(all_agree(compare(test::make_particle_double_pendulum())));
}

// The methods are evaluated and solved in extended precision: in double precision the long
// chains' ill-conditioned mass matrices put every method about 1e-12 from a 40-digit solution,
// and agreement to kAgree would no longer tell methods apart. The spatial chain of 5 links
// takes over 10 s to form (bench/README.md).
TEST(CompareMethods, PlanarChainsAgree) {
    for (int n = 1; n <= 8; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::planar);
        EXPECT_TRUE(all_agree(compare_methods(m.system, m.q, 2))) << n << " links";
    }
}

TEST(CompareMethods, SpatialChainsAgree) {
    for (int n = 1; n <= 8; ++n) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::spatial);
        EXPECT_TRUE(all_agree(compare_methods(m.system, m.q, 2))) << n << " links";
    }
}

TEST(CompareMethods, MassSpringDamperAgrees) {
    SampleModel m = make_mass_spring_damper();
    EXPECT_TRUE(all_agree(compare_methods(m.system, m.q, 3)));
}

TEST(CompareMethods, GimbalAgrees) { EXPECT_TRUE(all_agree(compare(test::make_gimbal()))); }

TEST(CompareMethods, RodAndPlateDoublePendulumAgrees) {
    EXPECT_TRUE(all_agree(compare(test::make_rod_and_plate())));
}

TEST(CompareMethods, ParticleInSpinningTubeAgreesAndFollowsTheRadialLaw) {
    // tube at a specified rate th(t), and tube free under a motor torque
    test::Model driven = test::make_spinning_tube(true);
    EXPECT_TRUE(all_agree(compare(driven)));
    EXPECT_TRUE(all_agree(compare(test::make_spinning_tube(false))));
    // by hand, along the tube for x > 0: m (x'' - x th'^2) = -k (x - L0) - m g sin th
    const SymbolTable& st = driven.sys.symbols();
    ex x = driven.q[0], xdd = driven.q[0].d(2);
    TimeVariable th = st.variable("th");
    ex m = st.symbol("mQ"), k = st.symbol("k"), L0 = st.symbol("L0"), g = st.symbol("g");
    ex hand = x * pow(th.d(1), 2) - (k / m) * (x - L0) - g * sin(th.symbol());
    LinearSystem K = form_linear_system(form_kane_equations(driven.sys, driven.q), {xdd});
    std::mt19937 rng(5);
    for (int i = 0; i < 3; ++i) {
        exmap state = test::random_state(st, rng, {xdd});
        state[x] = 0.5 + std::abs(GiNaC::ex_to<GiNaC::numeric>(state[x]).to_double());  // x > 0
        EXPECT_NEAR(solve_numeric(st, K, state)(0), st.evaluate(hand, state), 1e-12);
    }
}

TEST(CompareMethods, FreeRigidBodyAgreesAndSatisfiesNewtonAndEuler) {
    // six coordinates: position of B_o and body-fixed XYZ angles; loads F Nx> at B_o, Tq Bz>
    test::Model f = test::make_free_rigid_body();
    EXPECT_TRUE(all_agree(compare(f)));
    // the solved accelerations satisfy m a_cm = F + m g and, about the mass centre,
    // I.alpha + w x I.w = Tq Bz> + r^{B_o/Bcm} x F Nx>
    const System& sys = f.sys;
    const SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    const RigidBody& B = dynamic_cast<const RigidBody&>(*sys.bodies().front());
    const Frame& Bf = B.body_frame();
    const Point* Bo = nullptr;
    for (const Point* p : sys.points())
        if (p->name() == "B_o") Bo = p;
    ASSERT_NE(Bo, nullptr);
    std::vector<ex> acc = test::accelerations(f.q);
    LinearSystem L = form_linear_system(form_kane_equations(sys, f.q), acc);
    Vector F = st.symbol("Fx") * N.x();
    Vector w = Bf.ang_vel_in(N), alpha = Bf.ang_acc_in(N);
    const Dyadic& I = B.inertia();
    Col3 euler = (dot(I, alpha) + cross(w, dot(I, w)) - st.symbol("Tq") * Bf.z() -
                  cross(Bo->pos_from(B.cm()), F))
                     .components_in(Bf);
    Col3 newton = (B.mass() * B.cm().acc_in(N) - F - B.mass() * sys.gravity()).components_in(N);
    std::mt19937 rng(9);
    for (int k = 0; k < 2; ++k) {
        exmap state = test::random_state(st, rng, acc);
        Eigen::VectorXd qdd = solve_numeric(st, L, state);
        for (std::size_t i = 0; i < acc.size(); ++i) state[acc[i]] = qdd(static_cast<Eigen::Index>(i));
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(st.evaluate(euler[i], state), 0.0, 1e-12);
            EXPECT_NEAR(st.evaluate(newton[i], state), 0.0, 1e-12);
        }
    }
}

TEST(CompareMethods, TorqueFreeBodyAboutItsMassCentreSatisfiesEulersEquations) {
    // a body pivoting about its mass centre (a ball joint there), body-fixed XYZ angles
    System sys;
    SymbolTable& s = sys.symbols();
    std::vector<TimeVariable> q{s.add_variable("q1"), s.add_variable("q2"), s.add_variable("q3")};
    RigidBody& B = sys.add_rigid_body("B");
    B.body_frame().orient_body_fixed(sys.newtonian(), RotationSequence::XYZ, q[0], q[1], q[2]);
    B.cm().set_pos(sys.origin(), Vector());
    B.set_mass(s.add_constant("m", 2.0));
    B.set_inertia(B.cm(), s.add_constant("Ixx", 1.0), s.add_constant("Iyy", 2.0),
                  s.add_constant("Izz", 3.5), s.add_constant("Ixy", 0.1));
    EXPECT_TRUE(all_agree(compare_methods(sys, q, 3)));
    // with no loads, the solved accelerations make I.alpha + w x I.w vanish
    const Frame& N = sys.newtonian();
    const Frame& Bf = B.body_frame();
    std::vector<ex> acc = test::accelerations(q);
    LinearSystem L = form_linear_system(form_kane_equations(sys, q), acc);
    exmap state{{q[0], 0.3}, {q[1], -0.4}, {q[2], 1.2},
                {q[0].d(1), 0.7}, {q[1].d(1), -1.1}, {q[2].d(1), 0.5}};
    Eigen::VectorXd qdd = solve_numeric(s, L, state);
    for (int i = 0; i < 3; ++i) state[acc[static_cast<std::size_t>(i)]] = qdd(i);
    Vector w = Bf.ang_vel_in(N), alpha = Bf.ang_acc_in(N);
    const Dyadic& I = B.inertia();
    Col3 euler = (dot(I, alpha) + cross(w, dot(I, w))).components_in(Bf);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.evaluate(euler[i], state), 0.0, 1e-12);
}

// The planner's "S does not turn as one body about O when only q changes" note is decided by
// numeric tests at random states; on a tree every row's S does turn as one body, so no row of
// any tree model of the cross-check may carry it, for the accelerations (forward dynamics) or
// for the model's unknown loads (inverse dynamics).
TEST(CompareMethods, NoTreeModelRowSaysItsSystemDoesNotTurnAsOneBody) {
    auto check = [](const System& sys, const std::vector<TimeVariable>& q,
                    const std::vector<ex>& loads, const std::string& name) {
        std::vector<std::vector<ex>> unknown_sets{test::accelerations(q)};
        if (loads.size() == q.size()) unknown_sets.push_back(loads);
        std::size_t rows = 0;
        for (const std::vector<ex>& x : unknown_sets)
            for (const RoadmapRow& r : plan_roadmap(sys, q, x)) {
                ++rows;
                EXPECT_EQ(r.note.find("does not turn as one body"), std::string::npos)
                    << name << ", row for " << r.variable << ": " << r.note;
            }
        EXPECT_GE(rows, q.size()) << name;
    };
    SampleModel triple = make_triple_pendulum();
    check(triple.system, triple.q, triple.unknowns, "triple pendulum");
    for (int n = 1; n <= 8; ++n)
        for (ChainKind kind : {ChainKind::planar, ChainKind::spatial}) {
            SampleModel m = make_n_link_pendulum(n, kind);
            check(m.system, m.q, m.unknowns,
                  std::to_string(n) + (kind == ChainKind::planar ? " planar" : " spatial") +
                      " links");
        }
    SampleModel msd = make_mass_spring_damper();
    check(msd.system, msd.q, msd.unknowns, "mass-spring-damper");
    for (auto [make, name] :
         std::vector<std::pair<test::Model (*)(), std::string>>{
             {test::make_particle_double_pendulum, "particle double pendulum"},
             {test::make_gimbal, "gimbal"},
             {test::make_rod_and_plate, "rod and plate"},
             {test::make_free_rigid_body, "free rigid body"},
             {test::make_rod_pendulum, "rod pendulum"}}) {
        test::Model m = make();
        check(m.sys, m.q, m.loads, name);
    }
    for (bool driven : {true, false}) {
        test::Model m = test::make_spinning_tube(driven);
        check(m.sys, m.q, m.loads, driven ? "driven spinning tube" : "free spinning tube");
    }
}
