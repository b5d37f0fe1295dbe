// SPDX-License-Identifier: MIT
// Brute-force Newton–Euler: counts, joint reactions against hand derivations, and agreement of
// the solved motion with the road-map and Kane's method.
#include "alembert/eom/newton_euler.hpp"

#include <cmath>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/inertia_forces.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

using alembert::test::kAgree;

// the solved values of `wanted` (a subset of the system's unknowns)
std::vector<double> pick(const LinearSystem& L, const Eigen::VectorXd& x,
                         const std::vector<ex>& wanted) {
    std::vector<double> out;
    for (const ex& w : wanted)
        for (std::size_t i = 0; i < L.unknowns.size(); ++i)
            if (L.unknowns[i].is_equal(w)) out.push_back(x(static_cast<Eigen::Index>(i)));
    return out;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

std::vector<ex> roadmap_equations(const System& sys, const std::vector<TimeVariable>& q,
                                  const std::vector<ex>& unknowns) {
    std::vector<ex> E;
    for (const RoadmapRow& r : plan_roadmap(sys, q, unknowns)) E.push_back(r.equation);
    return E;
}

}  // namespace

TEST(NewtonEuler, TriplePendulumCountsNineInPlaneAndEighteenInSpace) {
    // each hinge: 2 in-plane force components (planar), or 3 forces and the 2 bending torques
    // about axes normal to the hinge (spatial); each body 3 or 6 equations; 3 motor torques
    SampleModel m = make_triple_pendulum();
    NewtonEulerEquations planar = form_newton_euler_equations(m.system, m.q, m.unknowns);
    EXPECT_TRUE(planar.planar);
    EXPECT_EQ(planar.equations.size(), 9u);
    EXPECT_EQ(planar.unknowns.size(), 9u);
    EXPECT_EQ(planar.force_reactions, 6u);
    EXPECT_EQ(planar.torque_reactions, 0u);
    EXPECT_NE(summarize(planar).find("9 equations in 9 unknowns (6 joint reactions"),
              std::string::npos)
        << summarize(planar);
    EXPECT_NE(summarize(planar).find("vs 3 road-map equations"), std::string::npos);

    NewtonEulerEquations spatial = form_newton_euler_equations(
        m.system, m.q, m.unknowns, {.mode = NewtonEulerMode::spatial});
    EXPECT_FALSE(spatial.planar);
    EXPECT_EQ(spatial.equations.size(), 18u);
    EXPECT_EQ(spatial.unknowns.size(), 18u);
    EXPECT_EQ(spatial.force_reactions, 9u);
    EXPECT_EQ(spatial.torque_reactions, 6u);
    EXPECT_NE(summarize(spatial).find("18 equations in 18 unknowns (15 joint reactions"),
              std::string::npos)
        << summarize(spatial);
}

TEST(NewtonEuler, TriplePendulumJointsAreTheHingesOfTheModel) {
    SampleModel m = make_triple_pendulum();
    const System& sys = m.system;
    const Frame& N = sys.newtonian();
    NewtonEulerEquations ne = form_newton_euler_equations(sys, m.q, m.unknowns,
                                                           {.mode = NewtonEulerMode::spatial});
    ASSERT_EQ(ne.joints.size(), 3u);
    const Body* parent[3] = {nullptr, m.links[0], m.links[1]};
    for (std::size_t i = 0; i < 3; ++i) {
        const NewtonEulerJoint& j = ne.joints[i];
        EXPECT_EQ(j.body, m.links[i]);
        EXPECT_EQ(j.parent, parent[i]);
        EXPECT_EQ(j.torque_parent, parent[i]);
        EXPECT_EQ(j.at->name(), m.links[i]->name() + "_o");
        EXPECT_EQ(j.free_rotations, 1);
        EXPECT_EQ(j.free_slides, 0);
        // the reaction torques are normal to the hinge axis Nz, the forces span space
        for (const ReactionComponent& r : j.reactions) {
            if (r.kind == LoadKind::torque) {
                EXPECT_TRUE(test::same(dot(r.direction, N.z()), 0)) << r.direction;
            }
        }
    }
    // names say which body acts on which
    const SymbolTable& st = sys.symbols();
    for (const char* name : {"F_NA_x", "F_NA_y", "F_NA_z", "F_AB_x", "F_BC_y", "M_NA_x", "M_BC_y"})
        EXPECT_TRUE(st.contains(name)) << name;
}

TEST(NewtonEuler, TriplePendulumMatchesRoadmapAndKaneAtRandomStates) {
    SampleModel m = make_triple_pendulum();
    const System& sys = m.system;
    const SymbolTable& st = sys.symbols();
    std::vector<ex> acc = test::accelerations(m.q);
    // inverse dynamics (torques from motion) and forward dynamics (motion from torques)
    LinearSystem rm_inverse = form_linear_system(roadmap_equations(sys, m.q, m.unknowns), m.unknowns);
    LinearSystem kane_forward = form_linear_system(form_kane_equations(sys, m.q), acc);
    std::mt19937 rng(7);
    for (NewtonEulerMode mode : {NewtonEulerMode::planar, NewtonEulerMode::spatial}) {
        NewtonEulerEquations inv = form_newton_euler_equations(sys, m.q, m.unknowns, {.mode = mode});
        NewtonEulerEquations fwd = form_newton_euler_equations(sys, m.q, acc, {.mode = mode});
        LinearSystem ne_inverse = form_linear_system(inv.equations, inv.unknowns);
        LinearSystem ne_forward = form_linear_system(fwd.equations, fwd.unknowns);
        for (int k = 0; k < 3; ++k) {
            exmap state = test::random_state(st, rng, inv.unknowns);
            std::vector<double> T_ne = pick(ne_inverse, solve_numeric(st, ne_inverse, state), m.unknowns);
            Eigen::VectorXd T_rm = solve_numeric(st, rm_inverse, state);
            for (int i = 0; i < 3; ++i) EXPECT_LT(relative(T_ne[static_cast<std::size_t>(i)], T_rm(i)), kAgree);

            state = test::random_state(st, rng, fwd.unknowns);
            std::vector<double> a_ne = pick(ne_forward, solve_numeric(st, ne_forward, state), acc);
            Eigen::VectorXd a_kane = solve_numeric(st, kane_forward, state);
            for (int i = 0; i < 3; ++i) EXPECT_LT(relative(a_ne[static_cast<std::size_t>(i)], a_kane(i)), kAgree);
        }
    }
}

TEST(NewtonEuler, GroundReactionIsTheRateOfMomentumLessGravity) {
    // for the whole chain, F^{N/A} + sum m g = sum m a_cm (the road-map's translate row for S =
    // {A, B, C}): an independent check of the solved reactions
    SampleModel m = make_triple_pendulum();
    const System& sys = m.system;
    const SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    NewtonEulerEquations ne = form_newton_euler_equations(sys, m.q, m.unknowns,
                                                          {.mode = NewtonEulerMode::spatial});
    LinearSystem L = form_linear_system(ne.equations, ne.unknowns);
    BodySet S = sys.bodies();
    Col3 expected = (calc_inertial_force(S, N) - sys.calc_mass(S) * sys.gravity()).components_in(N);
    Col3 reaction = ne.joints.front().force.components_in(N);
    std::mt19937 rng(11);
    for (int k = 0; k < 3; ++k) {
        exmap state = test::random_state(st, rng, ne.unknowns);
        Eigen::VectorXd x = solve_numeric(st, L, state);
        for (std::size_t i = 0; i < ne.unknowns.size(); ++i)
            state[ne.unknowns[i]] = x(static_cast<Eigen::Index>(i));
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(st.evaluate(reaction[i], state), st.evaluate(expected[i], state), 1e-9);
    }
}

TEST(NewtonEuler, SimplePendulumPinReactionMatchesHandDerivation) {
    // rod (m, L) hanging at angle q: (m L^2/3) q'' = -m g (L/2) sin q + T, and the pin force on
    // the rod R = m a_cm - m g with a_cm = (L/2)(q'' cos q - q'^2 sin q, q'' sin q + q'^2 cos q)
    test::Model p = test::make_rod_pendulum();
    const SymbolTable& st = p.sys.symbols();
    const Frame& N = p.sys.newtonian();
    ex q = p.q[0], qd = p.q[0].d(1), qdd = p.q[0].d(2);
    ex m = st.symbol("m"), L = st.symbol("L"), g = st.symbol("g"), T = st.symbol("T");
    ex qdd_hand = (T - m * g * (L / 2) * sin(q)) / (m * L * L / 3);
    ex Rx = m * (L / 2) * (qdd_hand * cos(q) - qd * qd * sin(q));
    ex Ry = m * (L / 2) * (qdd_hand * sin(q) + qd * qd * cos(q)) + m * g;
    for (NewtonEulerMode mode : {NewtonEulerMode::planar, NewtonEulerMode::spatial}) {
        NewtonEulerEquations ne = form_newton_euler_equations(p.sys, p.q, {qdd}, {.mode = mode});
        EXPECT_EQ(ne.equations.size(), mode == NewtonEulerMode::planar ? 3u : 6u);
        std::vector<ex> x = solve_symbolic(form_linear_system(ne.equations, ne.unknowns));
        exmap solved;
        for (std::size_t i = 0; i < x.size(); ++i) solved[ne.unknowns[i]] = x[i];
        EXPECT_TRUE(test::same(x[0], qdd_hand));
        const NewtonEulerJoint& pin = ne.joints.front();
        EXPECT_EQ(pin.parent, nullptr);
        Col3 R = pin.force.components_in(N).map([&](const ex& e) { return e.subs(solved); });
        EXPECT_TRUE(test::same(R[0], Rx));
        EXPECT_TRUE(test::same(R[1], Ry));
        EXPECT_TRUE(test::same(R[2], 0));
        // no bending torque on a hinge of a rod whose inertia has no products
        Col3 M = pin.torque.components_in(N).map([&](const ex& e) { return e.subs(solved); });
        for (int i = 0; i < 3; ++i) EXPECT_TRUE(test::same(M[i], 0));
    }
}

TEST(NewtonEuler, ParticlePendulumRodsCarryOnlyTension) {
    // each massless rod of a particle double pendulum pushes along itself: one in-plane
    // reaction per particle, normal to its free slide
    test::Model p = test::make_particle_double_pendulum();
    const Frame& N = p.sys.newtonian();
    NewtonEulerEquations ne = form_newton_euler_equations(p.sys, p.q, test::accelerations(p.q));
    EXPECT_TRUE(ne.planar);
    EXPECT_EQ(ne.equations.size(), 4u);
    EXPECT_EQ(ne.unknowns.size(), 4u);
    const Frame& A = p.sys.frame("A");
    const Frame& B = p.sys.frame("B");
    ASSERT_EQ(ne.joints.size(), 2u);
    EXPECT_EQ(ne.joints[1].parent, &p.sys.body("Q1"));
    const Frame* rod[2] = {&A, &B};
    for (std::size_t i = 0; i < 2; ++i) {
        ASSERT_EQ(ne.joints[i].reactions.size(), 1u);
        const Vector& d = ne.joints[i].reactions[0].direction;
        EXPECT_TRUE(test::same(dot(d, rod[i]->x()), 0));
        EXPECT_TRUE(test::same(dot(d, N.z()), 0));
    }
    // the solved motion agrees with Kane's
    const SymbolTable& st = p.sys.symbols();
    LinearSystem L = form_linear_system(ne.equations, ne.unknowns);
    LinearSystem K = form_linear_system(form_kane_equations(p.sys, p.q), test::accelerations(p.q));
    std::mt19937 rng(3);
    exmap state = test::random_state(st, rng, ne.unknowns);
    std::vector<double> a = pick(L, solve_numeric(st, L, state), test::accelerations(p.q));
    Eigen::VectorXd a_kane = solve_numeric(st, K, state);
    for (int i = 0; i < 2; ++i) EXPECT_LT(relative(a[static_cast<std::size_t>(i)], a_kane(i)), kAgree);
}

TEST(NewtonEuler, UniversalJointTransmitsOneTorqueNormalToBothAxes) {
    // the spatial chain's joints turn about the parent's z axis and the link's x axis
    SampleModel m = make_n_link_pendulum(2, ChainKind::spatial);
    NewtonEulerEquations ne = form_newton_euler_equations(m.system, m.q, m.unknowns);
    EXPECT_FALSE(ne.planar);
    EXPECT_EQ(ne.equations.size(), 12u);
    EXPECT_EQ(ne.unknowns.size(), 12u);  // 4 torques, 2 x (3 forces + 1 torque)
    const Frame* parent = &m.system.newtonian();
    for (std::size_t i = 0; i < 2; ++i) {
        const NewtonEulerJoint& j = ne.joints[i];
        EXPECT_EQ(j.free_rotations, 2);
        int torques = 0;
        for (const ReactionComponent& r : j.reactions) {
            if (r.kind != LoadKind::torque) continue;
            ++torques;
            EXPECT_TRUE(test::same(dot(r.direction, parent->z()), 0));
            EXPECT_TRUE(test::same(dot(r.direction, m.links[i]->body_frame().x()), 0));
        }
        EXPECT_EQ(torques, 1);
        parent = &m.links[i]->body_frame();
    }
}

TEST(NewtonEuler, FreeBodyHasNoReactions) {
    test::Model f = test::make_free_rigid_body();
    NewtonEulerEquations ne = form_newton_euler_equations(f.sys, f.q, test::accelerations(f.q));
    EXPECT_FALSE(ne.planar);
    EXPECT_TRUE(ne.reactions.empty());
    EXPECT_EQ(ne.equations.size(), 6u);
    EXPECT_EQ(ne.joints.front().free_slides, 3);
    EXPECT_EQ(ne.joints.front().free_rotations, 3);
}

TEST(NewtonEuler, PlanarModeOfASpatialModelIsRefused) {
    SampleModel m = make_n_link_pendulum(2, ChainKind::spatial);
    EXPECT_THROW_MSG(form_newton_euler_equations(m.system, m.q, m.unknowns,
                                                 {.mode = NewtonEulerMode::planar}),
                     ModelError, "not planar");
}

TEST(NewtonEuler, FormingAgainReusesTheReactionUnknowns) {
    SampleModel m = make_triple_pendulum();
    NewtonEulerEquations a = form_newton_euler_equations(m.system, m.q, m.unknowns);
    NewtonEulerEquations b = form_newton_euler_equations(m.system, m.q, m.unknowns);
    ASSERT_EQ(a.reactions.size(), b.reactions.size());
    for (std::size_t i = 0; i < a.reactions.size(); ++i)
        EXPECT_TRUE(a.reactions[i].is_equal(b.reactions[i]));
}

TEST(NewtonEuler, ReactionNameTakenByAConstantIsAModelError) {
    SampleModel m = make_triple_pendulum();
    m.system.symbols().add_constant("F_NA_x", 1.0);
    EXPECT_THROW_MSG(form_newton_euler_equations(m.system, m.q, m.unknowns), ModelError,
                     "'F_NA_x' clashes with the constant");
}

TEST(NewtonEuler, UnlocatedBodyIsAModelError) {
    System sys;
    TimeVariable q = sys.symbols().add_variable("q");
    RigidBody& B = sys.add_rigid_body("B");
    B.body_frame().orient_axis(sys.newtonian(), Axis::z, q);
    B.set_mass(1);
    B.set_inertia(B.cm(), 1, 1, 1);
    EXPECT_THROW_MSG(form_newton_euler_equations(sys, {q}, {q.d(2)}), ModelError,
                     "no point of 'B' is located");
}
