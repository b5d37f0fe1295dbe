// SPDX-License-Identifier: MIT
// Kane's auxiliary speeds (Kane & Levinson 1985, sec. 5.7) against hand derivations, an MG
// road-map and brute-force Newton–Euler: constraint forces come out right, and the auxiliary
// equations hold no auxiliary speed, no auxiliary rate and no velocity term left over.
#include <algorithm>
#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/inertia.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;

namespace {

// the symbols of an expression that `e` must not hold, by name, for failure messages
::testing::AssertionResult holds_none_of(const ex& e, const std::vector<ex>& xs) {
    for (const ex& x : xs)
        if (e.has(x))
            return ::testing::AssertionFailure() << to_string(e) << "\n  holds " << to_string(x);
    return ::testing::AssertionSuccess();
}

// ---- Kane & Levinson 1985, exercises 8.12 and 8.17 (PyDy's "non-central inertia" test) ----
// A vehicle on a plane P inclined by theta (P: F turned by -theta about Fy). Body A yaws by q1
// about Ax> (the plane's normal); D, the midpoint of the axle Az>, moves with u2 Ay>. Wheels B
// and C (radius R, mass mB, moments K, K, J about B*, C*) turn by q2, q3 about Az> at
// b Az>, -b Az> from D and roll without slip (contact points B^, C^ at -R Ax> from B*, C*).
// A's mass centre A* is at a Ay>; its weight-like load -M g Fx> acts at S* (e Ay>), and the
// contact force Q1 Ax> + Q2 Ay> + Q3 Az> of a third support at Q (f Ay> - R Ax>). The
// auxiliary speed u3 pitches A about the axle: w_FA = u1 Ax> + u3 Az>.
struct RollingVehicle {
    System sys{"F"};
    TimeVariable q1, q2, q3, u1, u2, u3, u4, u5;
    ex theta, R, M, g, e, f, a, b, mA, mB, IA, IA22, IA33, IA23, J, K, Q1, Q2, Q3;
    Point *B_hat = nullptr, *C_hat = nullptr;
    Frame* A = nullptr;

    // `about_D`: the inertias are given about D (not the mass centres), by the parallel-axis
    // theorem by hand; the equations must not change
    explicit RollingVehicle(bool about_D) {
        SymbolTable& s = sys.symbols();
        Frame& F = sys.newtonian();
        q1 = s.add_variable("q1", 1), q2 = s.add_variable("q2", 1), q3 = s.add_variable("q3", 1);
        u1 = s.add_variable("u1", 1), u2 = s.add_variable("u2", 1), u3 = s.add_variable("u3", 1);
        u4 = s.add_variable("u4", 1), u5 = s.add_variable("u5", 1);
        for (auto [x, n] : {std::pair{&theta, "theta"},
                            {&R, "R"},
                            {&M, "M"},
                            {&g, "g"},
                            {&e, "e"},
                            {&f, "f"},
                            {&a, "a"},
                            {&b, "b"},
                            {&mA, "mA"},
                            {&mB, "mB"},
                            {&IA, "IA"},
                            {&IA22, "IA22"},
                            {&IA33, "IA33"},
                            {&IA23, "IA23"},
                            {&J, "J"},
                            {&K, "K"}})
            *x = s.add_constant(n);
        Q1 = s.add_unknown("Q1"), Q2 = s.add_unknown("Q2"), Q3 = s.add_unknown("Q3");

        Frame& P = sys.add_frame("P");
        P.orient_axis(F, Axis::y, -theta);
        RigidBody& rA = sys.add_rigid_body("A");
        RigidBody& rB = sys.add_rigid_body("B");
        RigidBody& rC = sys.add_rigid_body("C");
        A = &rA.body_frame();
        A->orient_axis(P, Axis::x, q1);
        A->set_ang_vel(P, u1 * A->x() + u3 * A->z());
        rB.body_frame().orient_axis(*A, Axis::z, q2);
        rB.body_frame().set_ang_vel(*A, u4 * A->z());
        rC.body_frame().orient_axis(*A, Axis::z, q3);
        rC.body_frame().set_ang_vel(*A, u5 * A->z());

        Point& D = sys.add_point("D", &rA);
        D.set_vel(F, u2 * A->y());
        rA.cm().set_pos(D, a * A->y());
        rB.cm().set_pos(D, b * A->z());
        rC.cm().set_pos(D, -b * A->z());
        Point& S_star = sys.add_point("S_star", &rA);
        S_star.set_pos(D, e * A->y());
        Point& Q = sys.add_point("Q", &rA);
        Q.set_pos(D, f * A->y() - R * A->x());
        B_hat = &sys.add_point("B_hat", &rB);
        B_hat->set_pos(rB.cm(), -R * A->x());
        B_hat->set_vel_two_point(F, rB.cm(), rB.body_frame());
        C_hat = &sys.add_point("C_hat", &rC);
        C_hat->set_pos(rC.cm(), -R * A->x());
        C_hat->set_vel_two_point(F, rC.cm(), rC.body_frame());

        rA.set_mass(mA), rB.set_mass(mB), rC.set_mass(mB);
        Dyadic I_A = inertia_dyadic(*A, IA, IA22, IA33, 0, IA23, 0);
        Dyadic I_B = inertia_dyadic(rB.body_frame(), K, K, J);
        Dyadic I_C = inertia_dyadic(rC.body_frame(), K, K, J);
        if (about_D) {
            rA.set_inertia(D, I_A + point_mass_inertia(mA, a * A->y(), *A));
            rB.set_inertia(D, I_B + point_mass_inertia(mB, b * A->z(), *A));
            rC.set_inertia(D, I_C + point_mass_inertia(mB, -b * A->z(), *A));
        } else {
            rA.set_inertia(rA.cm(), I_A), rB.set_inertia(rB.cm(), I_B);
            rC.set_inertia(rC.cm(), I_C);
        }
        sys.add_force(S_star, -M * g * F.x(), "W");
        sys.add_force(Q, Q1 * A->x() + Q2 * A->y() + Q3 * A->z(), "Q");
    }

    KaneOptions options() const {
        const Frame& F = sys.newtonian();
        return {
            .coordinates = {q1, q2, q3},
            .speeds = {u1, u2, u4, u5},
            .kinematic_equations = {u1 - q1.d(1), u4 - q2.d(1), u5 - q3.d(1)},
            .motion_constraints = {dot(B_hat->vel_in(F), A->y()), dot(C_hat->vel_in(F), A->y())},
            .dependent_speeds = {u4, u5},
            .auxiliary_speeds = {u3}};
    }
};

}  // namespace

TEST(KaneAuxiliary, RollingVehicleWithNonCentralInertiaGivesKaneAndLevinsonsEquations) {
    for (bool about_D : {false, true}) {
        SCOPED_TRACE(about_D ? "inertias about D" : "inertias about the mass centres");
        RollingVehicle v(about_D);
        KaneEquations k = form_kane_equations(v.sys, v.options());
        ASSERT_EQ(k.residuals.size(), 2u);
        ASSERT_EQ(k.auxiliary_equations.size(), 1u);
        using GiNaC::cos, GiNaC::sin, GiNaC::pow;
        const ex &u1 = v.u1, &u2 = v.u2, &q1 = v.q1;
        ex u1d = v.u1.d(1), u2d = v.u2.d(1);

        // rolling of B and C, by hand: v_B* = (u2 - b u1) Ay>, and w_FB = u1 Ax> + (u3 + u4) Az>
        // gives v_B^ . Ay> = u2 - b u1 - R (u3 + u4) = 0, so u4 = (u2 - b u1)/R - u3 and
        // likewise u5 = (u2 + b u1)/R - u3: the wheels do not turn in the auxiliary motion
        EXPECT_TRUE(same(k.dependent_speed_values[0], (u2 - v.b * u1) / v.R));
        EXPECT_TRUE(same(k.dependent_speed_values[1], (u2 + v.b * u1) / v.R));
        ASSERT_EQ(k.auxiliary_constraint_coefficients.rows(), 2u);
        ASSERT_EQ(k.auxiliary_constraint_coefficients.cols(), 1u);
        EXPECT_TRUE(same(k.auxiliary_constraint_coefficients(0, 0), -1));
        EXPECT_TRUE(same(k.auxiliary_constraint_coefficients(1, 0), -1));

        // generalized inertia forces, Kane & Levinson 1985, exercise 8.12 (as PyDy has them)
        EXPECT_TRUE(same(k.inertia_forces[0], -(v.IA + 2 * v.J * v.b * v.b / (v.R * v.R) + 2 * v.K +
                                                v.mA * v.a * v.a + 2 * v.mB * v.b * v.b) *
                                                      u1d -
                                                  v.mA * v.a * u1 * u2));
        EXPECT_TRUE(same(k.inertia_forces[1],
                         -(v.mA + 2 * v.mB + 2 * v.J / (v.R * v.R)) * u2d + v.mA * v.a * u1 * u1));
        // generalized active forces by hand: Az>.Fx> = -sin(theta) cos(q1),
        // Ay>.Fx> = -sin(theta) sin(q1); partial velocities of S*: e Az>, Ay>; of Q: f Az>, Ay>
        EXPECT_TRUE(
            same(k.active_forces[0], v.M * v.g * v.e * sin(v.theta) * cos(q1) + v.f * v.Q3));
        EXPECT_TRUE(same(k.active_forces[1], v.M * v.g * sin(v.theta) * sin(q1) + v.Q2));

        // the auxiliary (third) equation, by hand. In the auxiliary motion A pitches about
        // the axle and the wheels do not turn (C = -1 above), so the partial velocities for
        // u3 are: S* -e Ax>, Q -f Ax> - R Ay>, A* -a Ax>, B* and C* 0; w_FA Az>, w_FB and
        // w_FC 0. Ax>.Fx> = cos(theta). F~3 = M g e cos(theta) - f Q1 - R Q2. F~3* = 0: a_A*
        // lies in the plane of Ay>, Az> (D moves in the plane, A turns about Ax>), and
        // (I.alpha + w x I.w) . Az> = 0 for w = u1 Ax> (no product of inertia with Ax>).
        // With the wheels' spin wrongly kept in the auxiliary motion it would hold
        // -J (u4' + u5') = -2 J u2'/R.
        const ex& E3 = k.auxiliary_equations[0];
        EXPECT_TRUE(same(E3, v.M * v.g * v.e * cos(v.theta) - v.f * v.Q1 - v.R * v.Q2));
        EXPECT_TRUE(holds_none_of(
            E3, {v.u3, v.u3.d(1), u1, u2, u1d, u2d, v.u4, v.u5, v.u4.d(1), v.u5.d(1)}));
        for (const ex& r : k.residuals) EXPECT_TRUE(holds_none_of(r, {v.u3, v.u3.d(1)}));
    }
}

// ---- the four-bar's loop pin force: auxiliary speeds vs a road-map and Newton–Euler ---------

namespace {

// the four-bar's geometry solved by hand (circle intersection), branch +1 or -1; qB is
// relative to the crank, qC absolute (the sample model's values)
struct LoopState {
    double qA, qB, qC, wA, wB, wC;
};

LoopState loop_state(double qA, double wA, int branch) {
    const double LN = 1.0, LA = 0.4, LB = 1.2, LC = 0.8;
    double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
    double dx = LN - ax, dy = -ay, d = std::hypot(dx, dy);
    double along = (LB * LB - LC * LC + d * d) / (2 * d), h = std::sqrt(LB * LB - along * along);
    double px = ax + along * dx / d - branch * h * dy / d,
           py = ay + along * dy / d + branch * h * dx / d;
    double thB = std::atan2(py - ay, px - ax), qC = std::atan2(py, px - LN);
    // the loop's closure differentiated: LA wA e'(qA) + LB (wA + wB) e'(thB) - LC wC e'(qC)
    // = 0 with e'(x) = (-sin x, cos x), solved for wB, wC by Cramer's rule
    double a11 = -LB * std::sin(thB), a12 = LC * std::sin(qC);
    double a21 = LB * std::cos(thB), a22 = -LC * std::cos(qC);
    double r1 = LA * wA * std::sin(qA) + LB * wA * std::sin(thB);
    double r2 = -LA * wA * std::cos(qA) - LB * wA * std::cos(thB);
    double det = a11 * a22 - a12 * a21;
    return {qA, thB - qA, qC, wA, (r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det};
}

}  // namespace

TEST(KaneAuxiliary, FourBarPinForceMatchesARoadmapAndNewtonEulerAtRandomStates) {
    // the pin joining the coupler's tip B_tip to the rocker's tip C_tip is opened by the
    // auxiliary speeds ux, uy: v_NBtip - v_NCtip = ux Nx> + uy Ny>. The loop's motion
    // constraints are solved with them, so the linkage moves with the opening; the pin force
    // F_x Nx> + F_y Ny> (on B at B_tip, its opposite on C) then does work F_x ux + F_y uy.
    SampleModel m = make_four_bar();
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    TimeVariable ux = st.add_variable("ux", 1), uy = st.add_variable("uy", 1);
    ex T = m.unknowns[0], Fx = m.unknowns[1], Fy = m.unknowns[2];
    Vector v_rel = sys.point("B_tip").vel_in(N) - sys.point("C_tip").vel_in(N);
    const TimeVariable &qA = m.q[0], &qB = m.q[1], &qC = m.q[2];
    KaneEquations k = form_kane_equations(
        sys, KaneOptions{.coordinates = m.q,
                         .motion_constraints = {dot(v_rel, N.x()) - ux, dot(v_rel, N.y()) - uy},
                         .dependent_speeds = {qB.d(1), qC.d(1)},
                         .auxiliary_speeds = {ux, uy}});
    ASSERT_EQ(k.residuals.size(), 1u);
    ASSERT_EQ(k.auxiliary_equations.size(), 2u);
    for (const ex& E : k.auxiliary_equations)
        EXPECT_TRUE(holds_none_of(E, {ux, uy, ux.d(1), uy.d(1)}));
    LinearSystem pin = form_linear_system(k.auxiliary_equations, {Fx, Fy});

    // the road-map: 3 balance rows and the loop's 2 constraint rows (acceleration level)
    std::vector<ex> unknowns{qA.d(2), qB.d(2), qC.d(2), Fx, Fy};
    LinearSystem roadmap =
        form_linear_system(residuals_of(plan_roadmap(sys, m.q, unknowns)), unknowns);
    // brute-force Newton–Euler: 9 planar equations with 6 joint reactions, and the loop's
    // closure differentiated twice
    NewtonEulerEquations ne = form_newton_euler_equations(sys, m.q, unknowns);
    std::vector<ex> ne_equations = ne.equations;
    for (const Constraint& c : sys.constraints()) ne_equations.push_back(st.dt(st.dt(c.residual)));
    LinearSystem newton_euler = form_linear_system(ne_equations, ne.unknowns);

    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> angle(-3.1, 3.1), rate(-2.0, 2.0), torque(-5.0, 5.0);
    for (int trial = 0; trial < 6; ++trial) {
        int branch = trial % 2 == 0 ? 1 : -1;
        LoopState x = loop_state(angle(rng), rate(rng), branch);
        exmap at{{qA, x.qA},      {qB, x.qB},      {qC, x.qC},      {qA.d(1), x.wA},
                 {qB.d(1), x.wB}, {qC.d(1), x.wC}, {T, torque(rng)}};
        SCOPED_TRACE("qA = " + std::to_string(x.qA) + ", branch " + std::to_string(branch));
        // Kane: the pin force does no work in the linkage's motion (its coefficients in the
        // dynamical equation vanish, by trigonometric identities), the crank's acceleration
        // from that equation, then the pin force from the auxiliary equations
        for (const ex& F : {Fx, Fy})
            EXPECT_NEAR(st.evaluate(k.residuals[0].diff(GiNaC::ex_to<GiNaC::symbol>(F)), at), 0,
                        1e-12);
        exmap at_dynamics = at;
        at_dynamics[Fx] = at_dynamics[Fy] = 0;
        double qA_dd = solve_numeric(st, k.dynamics, at_dynamics)(0);
        exmap at_kane = at;
        at_kane[qA.d(2)] = qA_dd;
        Eigen::VectorXd F_kane = solve_numeric(st, pin, at_kane);
        Eigen::VectorXd x_roadmap = solve_numeric(st, roadmap, at);
        Eigen::VectorXd x_ne = solve_numeric(st, newton_euler, at);
        auto tol = [](double ref) { return 1e-12 * std::max(1.0, std::abs(ref)); };
        EXPECT_NEAR(qA_dd, x_roadmap(0), tol(x_roadmap(0)));
        EXPECT_NEAR(F_kane(0), x_roadmap(3), tol(x_roadmap(3)));
        EXPECT_NEAR(F_kane(1), x_roadmap(4), tol(x_roadmap(4)));
        EXPECT_NEAR(F_kane(0), x_ne(3), tol(x_ne(3)));
        EXPECT_NEAR(F_kane(1), x_ne(4), tol(x_ne(4)));
        // not trivially zero: the pin carries at least part of the coupler's weight
        EXPECT_GT(std::hypot(F_kane(0), F_kane(1)), 1.0);
    }
}

// ---- a box on the ground: contact forces by auxiliary speeds ----------------------------------

TEST(KaneAuxiliary, BoxOnTheGroundNormalForceIsItsWeightAndTheMomentBalances) {
    // box B (mass m, width w, height h, central inertia I about Nz) slides along Nx> by x on
    // the ground, pushed by P Nx> at height hp on its back face; normal forces N1, N2 at its
    // back and front lower corners, with sliding friction -mu N1 Nx>, -mu N2 Nx> (x' > 0).
    // Auxiliary speeds: uy lifts the box (v_NBcm gains uy Ny>), wz tips it (w_NB = wz Nz>).
    // By hand: along Ny>: N1 + N2 - m g = 0; about Bcm (no inertia torque, alpha = 0):
    //   (w/2)(N2 - N1) - (h/2) mu (N1 + N2) - (hp - h/2) P = 0;  along Nx>: P - mu (N1 + N2)
    //   - m x'' = 0
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable x = s.add_variable("x"), uy = s.add_variable("uy", 1),
                 wz = s.add_variable("wz", 1);
    ex mass = s.add_constant("m"), g = s.add_constant("g"), w = s.add_constant("w"),
       h = s.add_constant("h"), hp = s.add_constant("hp"), mu = s.add_constant("mu"),
       I = s.add_constant("I"), P = s.add_constant("P");
    ex N1 = s.add_unknown("N1"), N2 = s.add_unknown("N2");
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Bf = B.body_frame();
    Bf.orient_axis(N, Axis::z, 0);
    Bf.set_ang_vel(N, wz * N.z());
    B.cm().set_pos(sys.origin(), x * N.x() + h / 2 * N.y());
    B.cm().set_vel(N, x.d(1) * N.x() + uy * N.y());
    B.set_mass(mass);
    B.set_inertia(B.cm(), 0, 0, I);
    Point& back = sys.add_point("back", &B);
    back.set_pos(B.cm(), -w / 2 * Bf.x() - h / 2 * Bf.y());
    Point& front = sys.add_point("front", &B);
    front.set_pos(B.cm(), w / 2 * Bf.x() - h / 2 * Bf.y());
    Point& pushed = sys.add_point("pushed", &B);
    pushed.set_pos(B.cm(), -w / 2 * Bf.x() + (hp - h / 2) * Bf.y());
    sys.set_gravity(-g * N.y());
    sys.add_force(back, N1 * N.y() - mu * N1 * N.x(), "back contact");
    sys.add_force(front, N2 * N.y() - mu * N2 * N.x(), "front contact");
    sys.add_force(pushed, P * N.x(), "push");
    KaneEquations k =
        form_kane_equations(sys, KaneOptions{.coordinates = {x}, .auxiliary_speeds = {uy, wz}});
    ASSERT_EQ(k.auxiliary_equations.size(), 2u);
    EXPECT_TRUE(same(k.residuals[0], P - mu * (N1 + N2) - mass * x.d(2)));
    EXPECT_TRUE(same(k.auxiliary_equations[0], N1 + N2 - mass * g));
    EXPECT_TRUE(same(k.auxiliary_equations[1],
                     w / 2 * (N2 - N1) - h / 2 * mu * (N1 + N2) - (hp - h / 2) * P));
    for (const ex& E : k.auxiliary_equations)
        EXPECT_TRUE(holds_none_of(E, {uy, wz, uy.d(1), wz.d(1), x.d(1), x.d(2), I}));

    // solved: the normal force is m g, shared as the moments say
    std::vector<ex> F = solve_symbolic(form_linear_system(k.auxiliary_equations, {N1, N2}));
    EXPECT_TRUE(same(F[0] + F[1], mass * g));
    EXPECT_TRUE(same(F[1] - F[0], (mu * h * mass * g + (2 * hp - h) * P) / w));
    // resting, unpushed: each corner carries half the weight
    EXPECT_TRUE(same(F[0].subs(exmap{{P, 0}, {mu, 0}}), mass * g / 2));
}

TEST(KaneAuxiliary, AnAuxiliarySpeedThatMovesNothingIsAModelError) {
    // a particle on a line; ua is listed but appears in no velocity and no constraint
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x"), ua = s.add_variable("ua", 1);
    Particle& P = sys.add_particle("P");
    P.set_mass(s.add_constant("m"));
    P.point().set_pos(sys.origin(), x * sys.newtonian().x());
    sys.add_force(P.point(), s.add_unknown("Fn") * sys.newtonian().y(), "normal");
    EXPECT_THROW_MSG(
        form_kane_equations(sys, KaneOptions{.coordinates = {x}, .auxiliary_speeds = {ua}}),
        ModelError, "auxiliary speed 'ua' gives the equation 0 = 0");
}
