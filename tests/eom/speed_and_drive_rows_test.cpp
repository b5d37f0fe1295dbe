// SPDX-License-Identifier: MIT
// Speeds and the loads that drive specified motions as road-map unknowns: a top's steady
// precession rate, the motor torque of a tube turned at a prescribed rate, the force that
// drives a pendulum's pivot; each row's S, O, u and numbers checked against a hand derivation.
#include <cmath>
#include <numbers>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace speed_and_drive_rows {

namespace {

std::string body_names(const BodySet& S) {
    std::string s;
    for (const Body* b : S) s += (s.empty() ? "" : ",") + b->name();
    return s;
}

// the row whose variable is x
const RoadmapRow& row_for(const std::vector<RoadmapRow>& rows, const ex& x) {
    for (const RoadmapRow& r : rows)
        if (r.variable.is_equal(x)) return r;
    throw std::runtime_error("no row for " + to_string(x));
}

// u is the unit vector e (same direction), checked by meaning
::testing::AssertionResult along(const Vector& u, const Vector& e) { return test::same(dot(u, e), 1); }

// the about point of a row lies on the line through N_o along u (a fixed axis)
::testing::AssertionResult on_axis_through_origin(const System& sys, const RoadmapRow& r) {
    if (!r.about) return ::testing::AssertionFailure() << "no about point";
    const Vector p = r.about->pos_from(sys.origin());
    const Col3 c = cross(p, r.direction).components_in(sys.newtonian());
    for (int i = 0; i < 3; ++i)
        if (!test::same(c[i], 0)) return ::testing::AssertionFailure() << r.about->name() << " is off the axis";
    return ::testing::AssertionSuccess();
}

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

// the rows solved numerically at the values given, in the order of `xs`
std::vector<double> solve_rows(const System& sys, const std::vector<RoadmapRow>& rows,
                               const std::vector<ex>& xs, const exmap& values) {
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    Eigen::VectorXd v = solve_numeric(sys.symbols(), form_linear_system(E, xs), values);
    return {v.data(), v.data() + v.size()};
}

// A heavy symmetric top: A oriented from N by body-fixed z-x-z angles psi, theta, phi, its tip
// fixed at N_o, its mass centre at r Az> from the tip, central inertia I1, I1, I3; gravity
// -g Nz>; motor torques T_psi Nz> and T_phi Az> on A from N.
struct Top {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable psi = s.add_variable("psi"), theta = s.add_variable("theta"), phi = s.add_variable("phi");
    ex m = s.add_constant("m", 0.5), r = s.add_constant("r", 0.05), g = s.add_constant("g", 9.81),
       I1 = s.add_constant("I1", 0.001), I3 = s.add_constant("I3", 0.0005);
    ex T_psi = s.add_unknown("T_psi"), T_phi = s.add_unknown("T_phi");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    explicit Top(bool motors) {
        A.body_frame().orient_body_fixed(N, RotationSequence::ZXZ, psi.symbol(), theta.symbol(), phi.symbol());
        A.cm().set_pos(sys.origin(), r * A.body_frame().z());
        A.set_mass(m);
        A.set_inertia(A.cm(), I1, I1, I3);
        sys.set_gravity(-g * N.z());
        if (motors) {
            sys.add_torque(A, T_psi * N.z(), "Tpsi");
            sys.add_torque(A, T_phi * A.body_frame().z(), "Tphi");
        }
    }
    // the nodal axis: N's x axis turned by psi about Nz>
    Vector nodal() const { return GiNaC::cos(psi.symbol()) * N.x() + GiNaC::sin(psi.symbol()) * N.y(); }
    double val(const ex& c) const { return *s.value(c); }
};

}  // namespace

// (0) The test the speed rows use: e = z + c with the intermediate z = a b (a speed times a
// speed). e changes with a, but not with b held at 0 (inside the intermediate, where a
// substitution would not reach); c changes it either way; and e = a^2 b still changes with
// b when a is not held.
TEST(SpeedRows, ChangesWithOthersZeroSeesInsideIntermediates) {
    SymbolTable s;
    TimeVariable a = s.add_variable("a"), b = s.add_variable("b"), c = s.add_variable("c");
    const ex z = s.add_intermediate(a.symbol() * b.symbol(), "z");
    const ex e = z + c.symbol();
    EXPECT_TRUE(calc_changes_with_others_zero_at_random_states(s, e, a.symbol(), {}));
    EXPECT_FALSE(calc_changes_with_others_zero_at_random_states(s, e, a.symbol(), {b.symbol()}));
    EXPECT_TRUE(calc_changes_with_others_zero_at_random_states(s, e, c.symbol(), {b.symbol()}));
    EXPECT_TRUE(calc_changes_with_others_zero_at_random_states(s, a.symbol() * a.symbol() * b.symbol(), b.symbol(), {c.symbol()}));
    EXPECT_FALSE(calc_changes_with_others_zero_at_random_states(s, e, b.symbol(), {a.symbol()}));
}

// (1) The steady precession rate of a top. By hand, with I1' = I1 + m r^2 (about the tip) and
// the nodal axis x1, y2 = Az> x x1, Nz> = cos(theta) Az> + sin(theta) y2: with theta' = 0,
//   w = psi' Nz> + phi' Az> = psi' sin(theta) y2 + w3 Az>,   w3 = phi' + psi' cos(theta),
//   H^{A/N_o} = I1' psi' sin(theta) y2 + I3 w3 Az>, turning with psi' Nz>:
//   dH/dt = psi' Nz> x H = psi' sin(theta) (I3 w3 - I1' psi' cos(theta)) x1,
//   M^{N_o} = r Az> x (-m g Nz>) = m g r sin(theta) x1.
// So m g r = psi' (I3 w3 - I1' psi' cos(theta)): a (psi')^2 + b psi' + c = 0 with
//   a = (I3 - I1') cos(theta),  b = I3 phi',  c = -m g r,
// the moment about the nodal axis at the tip: theta's row. psi's row (about Nz>) and phi's
// (about Az>) hold psi' only times theta' (0 here), so they cannot give it.
TEST(SpeedRows, SteadyPrecessionRateComesFromTheNodalAxisRowAtTheTip) {
    Top t(false);
    const ex psid = t.psi.d(1);
    std::vector<RoadmapRow> rows = plan_roadmap(t.sys, {t.psi, t.theta, t.phi}, {psid});
    ASSERT_EQ(rows.size(), 1u);
    const RoadmapRow& R = rows[0];
    EXPECT_TRUE(R.variable.is_equal(psid));
    EXPECT_EQ(R.motion, Motion::rotate);
    EXPECT_TRUE(along(R.direction, t.nodal()));
    EXPECT_EQ(body_names(R.system), "A");
    ASSERT_NE(R.about, nullptr);
    EXPECT_EQ(R.about->name(), "N_o");  // the tip
    EXPECT_TRUE(R.note.empty()) << R.note;

    // solved from a guess at theta = 30 deg, phi' = 200 rad/s (speeds and accelerations not
    // given are 0: a steady motion); D = b^2 - 4 a c > 0, so both roots are real
    const double th = std::numbers::pi / 6, phid = 200;
    const double I1p = t.val(t.I1) + t.val(t.m) * t.val(t.r) * t.val(t.r);
    const double a = (t.val(t.I3) - I1p) * std::cos(th), b = t.val(t.I3) * phid,
                 c = -t.val(t.m) * t.val(t.g) * t.val(t.r);
    const double D = b * b - 4 * a * c;
    ASSERT_GT(D, 0);
    const double slow = 2 * c / (-b - std::sqrt(D));  // the root near m g r / (I3 phi')
    const double fast = (-b - std::sqrt(D)) / (2 * a);  // near I3 phi' / (I1' cos(theta))
    const exmap at{{t.theta.symbol(), th}, {t.phi.d(1), phid}, {t.psi.symbol(), 0.4}, {t.phi.symbol(), -1.1}};
    StaticsOptions o{.require_determined = true};
    // a guess of 2 rad/s picks the slow precession, 60 rad/s the fast one
    Equilibrium e = solve_equilibrium(t.s, residuals_of(rows), {psid}, {{psid, 2.0}}, at, o);
    expect_close(e.value(psid), slow, "slow precession");
    e = solve_equilibrium(t.s, residuals_of(rows), {psid}, {{psid, 60.0}}, at, o);
    expect_close(e.value(psid), fast, "fast precession");
}

// (2) With the motor torques, by hand (Euler's equations about the tip; the spin axis of a
// symmetric body: I3 w3' = M.Az>; about the fixed Nz>: M.Nz> = d/dt (H.Nz>)):
//   psi's row (Nz> at N_o):    T_psi + T_phi cos(theta) = d/dt [I1' psi' sin^2(theta) + I3 w3 cos(theta)]
//   phi's row (Az> through the tip): T_phi + T_psi cos(theta) = I3 w3',
//       w3' = phi'' + psi'' cos(theta) - psi' theta' sin(theta)
//   theta's row (x1 at N_o):   m g r sin(theta) = I1' (theta'' - psi'^2 sin cos) + I3 w3 psi' sin(theta)
// So T_psi goes to psi's row, T_phi to phi's, and psi' to theta's, the only row that holds it
// with the other speeds and the accelerations 0.
TEST(SpeedRows, MotorTorquesTakeTheirAxesRowsAndThePrecessionRateTheNodalRow) {
    Top t(true);
    const ex psid = t.psi.d(1);
    std::vector<RoadmapRow> rows = plan_roadmap(t.sys, {t.psi, t.theta, t.phi}, {psid, t.T_psi, t.T_phi});
    ASSERT_EQ(rows.size(), 3u);
    const RoadmapRow &Rs = row_for(rows, psid), &Rp = row_for(rows, t.T_psi), &Rf = row_for(rows, t.T_phi);
    EXPECT_TRUE(along(Rs.direction, t.nodal()));
    EXPECT_TRUE(along(Rp.direction, t.N.z()));
    EXPECT_TRUE(along(Rf.direction, t.A.body_frame().z()));
    for (const RoadmapRow* R : {&Rs, &Rp, &Rf}) {
        EXPECT_EQ(R->motion, Motion::rotate);
        EXPECT_EQ(body_names(R->system), "A");
        EXPECT_TRUE(on_axis_through_origin(t.sys, *R)) << to_string(R->variable);
    }
    EXPECT_EQ(Rs.about->name(), "N_o");
    EXPECT_EQ(Rp.about->name(), "N_o");

    // the numbers at a general state (not steady)
    const double th = 0.7, thd = -0.8, psd = 1.3, phd = 25.0, psdd = 0.6, thdd = -1.9, phdd = 2.4;
    const exmap at{{t.psi.symbol(), 0.3},  {t.theta.symbol(), th}, {t.phi.symbol(), -0.5},
                   {t.theta.d(1), thd},    {t.phi.d(1), phd},      {t.psi.d(2), psdd},
                   {t.theta.d(2), thdd},   {t.phi.d(2), phdd},     {psid, psd}};
    const double m = t.val(t.m), r = t.val(t.r), g = t.val(t.g), I3 = t.val(t.I3);
    const double I1p = t.val(t.I1) + m * r * r, s = std::sin(th), c = std::cos(th);
    const double w3 = phd + psd * c, w3d = phdd + psdd * c - psd * thd * s;
    const double dHz = I1p * (psdd * s * s + 2 * psd * thd * s * c) + I3 * (w3d * c - w3 * thd * s);
    // T_psi + c T_phi = dHz, c T_psi + T_phi = I3 w3'
    const double Tp = (dHz - c * I3 * w3d) / (1 - c * c), Tf = I3 * w3d - c * Tp;
    std::vector<double> T = solve_rows(t.sys, {Rp, Rf}, {t.T_psi, t.T_phi}, at);
    expect_close(T[0], Tp, "T_psi");
    expect_close(T[1], Tf, "T_phi");
    // theta's row: its residual is the nodal balance above (in either sign)
    const double nodal = m * g * r * s - I1p * (thdd - psd * psd * s * c) - I3 * w3 * psd * s;
    const double E = t.s.evaluate(Rs.equation, at);
    EXPECT_NEAR(std::fabs(E), std::fabs(nodal), 1e-12 * (1 + std::fabs(nodal)));
    EXPECT_GT(std::fabs(nodal), 1e-3);
    exmap moved = at;
    moved[t.theta.d(2)] = thdd + 1;  // the sign: E changes with theta'' as the balance does
    EXPECT_NEAR(t.s.evaluate(Rs.equation, moved) - E, (E / nodal) * -I1p, 1e-12);
}

// (3) Refusals: a speed no row holds (a pendulum's rows never hold q'), and a solve from a
// guess for a speed the chosen row holds only times speeds that are 0 (psi's own row at
// theta' = 0 reads 0 = 0 in psi'): refused naming the unknown and the row, not the guess back.
TEST(SpeedRows, SpeedNoRowHoldsAndUndeterminedSolveAreRefused) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m"), L = s.add_constant("L"), g = s.add_constant("g");
    RigidBody& A = sys.add_rigid_body("A");
    A.body_frame().orient_axis(sys.newtonian(), Axis::z, q.symbol());
    A.cm().set_pos(sys.origin(), -L * A.body_frame().y());
    A.set_mass(m);
    A.set_inertia(A.cm(), 0, 0, 0);
    sys.set_gravity(-g * sys.newtonian().y());
    EXPECT_THROW_MSG(plan_roadmap(sys, {q}, {q.d(1)}), ModelError, "no road-map row holds the speed 'q''");

    Top t(true);
    const ex psid = t.psi.d(1);
    std::vector<RoadmapRow> rows = plan_roadmap(t.sys, {t.psi, t.theta, t.phi}, {psid, t.T_psi, t.T_phi});
    const RoadmapRow& own = row_for(rows, t.T_psi);  // psi's row
    StaticsOptions o{.require_determined = true, .residual_names = {"E_T_psi"}};
    const exmap at{{t.psi.symbol(), 0.1}, {t.theta.symbol(), 0.5}, {t.phi.symbol(), 0.2},
                   {t.phi.d(1), 200.0}, {t.T_psi, 0.0}, {t.T_phi, 0.0}};
    EXPECT_THROW_MSG(solve_equilibrium(t.s, {own.equation}, {psid}, {{psid, 2.0}}, at, o), SolveError,
                     "the equations do not fix 'psi'' at the solution found (psi' = 2, after 0 "
                     "iterations): the Jacobian dE/dx is singular there (rank 0 of 1), and E_T_psi "
                     "does not change with it");
    // without the check, the guess came back as the answer
    EXPECT_EQ(solve_equilibrium(t.s, {own.equation}, {psid}, {{psid, 2.0}}, at).value(psid), 2.0);
}

// (4) A tube A turned about Nz> at a prescribed angle theta (a specified quantity), a bead P
// of mass mP sliding in it at r Ax>, the motor torque T Nz> on A. By hand, with theta free:
//   what moves when only theta changes: A and P, turning about Nz> at N_o;
//   about N_o along Nz>: T = d/dt [(IA + mP r^2) theta'] = (IA + mP r^2) theta'' + 2 mP r r' theta'
//   along Ax> for P alone: 0 = mP (r'' - r theta'^2)  =>  r'' = r theta'^2;
// with theta = w t: T = 2 mP r r' w and r'' = w^2 r.
TEST(DriveRows, MotorTorqueOfAPrescribedRotationComesFromTheSpecifiedQuantitysRow) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable r = s.add_variable("r"), th = s.add_specified("theta");
    ex mP = s.add_constant("mP", 0.3), IA = s.add_constant("IA", 0.1), T = s.add_unknown("T");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    Particle& P = sys.add_particle("P");
    A.body_frame().orient_axis(N, Axis::z, th.symbol());
    P.point().set_pos(sys.origin(), r.symbol() * A.body_frame().x());
    A.cm().set_pos(sys.origin(), Vector());
    A.set_mass(1);
    A.set_inertia(A.cm(), 0, 0, IA);
    P.set_mass(mP);
    sys.add_torque(A, T * N.z(), "motor");

    std::vector<RoadmapRow> rows = plan_roadmap(sys, {r}, {r.d(2), T});
    ASSERT_EQ(rows.size(), 2u);
    const RoadmapRow &Rr = row_for(rows, r.d(2)), &RT = row_for(rows, T);
    EXPECT_EQ(Rr.motion, Motion::translate);
    EXPECT_TRUE(along(Rr.direction, A.body_frame().x()));
    EXPECT_EQ(body_names(Rr.system), "P");
    EXPECT_EQ(RT.motion, Motion::rotate);
    EXPECT_TRUE(along(RT.direction, N.z()));
    EXPECT_EQ(body_names(RT.system), "A,P");
    ASSERT_NE(RT.about, nullptr);
    EXPECT_TRUE(test::same(RT.about->pos_from(sys.origin()), Vector(), N));  // at N_o
    EXPECT_TRUE(RT.additional_unknowns.empty());

    // at a state with theta'' too (the general formula), then at theta = w t
    for (double thdd : {0.0, 0.7}) {
        const double rv = 0.2, rd = -0.15, w = 2.0, mp = 0.3, ia = 0.1;
        const exmap at{{r.symbol(), rv}, {r.d(1), rd}, {th.symbol(), 0.9}, {th.d(1), w}, {th.d(2), thdd}};
        std::vector<double> x = solve_rows(sys, rows, {r.d(2), T}, at);
        expect_close(x[0], w * w * rv, "r''");
        expect_close(x[1], (ia + mp * rv * rv) * thdd + 2 * mp * rv * rd * w, "T");
    }
    // its row is for loads only: the specified quantity's acceleration is never solved for
    EXPECT_THROW(plan_roadmap(sys, {r}, {r.d(2), th.d(2)}), ModelError);
}

// (4b) The same tube with the motor left out and the tube's push on the bead an unknown N_y
// along Ay>: theta's row would need the motor, so it takes no other load; N_y comes from the
// bead's own free-body row along Ay>. By hand, P's acceleration along Ay> is
// r theta'' + 2 r' theta', so N_y = mP (r theta'' + 2 r' theta').
TEST(DriveRows, SpecifiedMotionsRowTakesOnlyTheLoadThatDrivesIt) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable r = s.add_variable("r"), th = s.add_specified("theta");
    ex mP = s.add_constant("mP", 0.3), IA = s.add_constant("IA", 0.1), N_y = s.add_unknown("N_y");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    Particle& P = sys.add_particle("P");
    A.body_frame().orient_axis(N, Axis::z, th.symbol());
    P.point().set_pos(sys.origin(), r.symbol() * A.body_frame().x());
    A.cm().set_pos(sys.origin(), Vector());
    A.set_mass(1);
    A.set_inertia(A.cm(), 0, 0, IA);
    P.set_mass(mP);
    sys.add_force(P.point(), N_y * A.body_frame().y(), "push");

    std::vector<RoadmapRow> rows = plan_roadmap(sys, {r}, {r.d(2), N_y});
    const RoadmapRow& RN = row_for(rows, N_y);
    EXPECT_EQ(RN.motion, Motion::translate);
    EXPECT_TRUE(along(RN.direction, A.body_frame().y()));
    EXPECT_EQ(body_names(RN.system), "P");
    const double rv = 0.2, rd = -0.15, w = 2.0, al = 0.7;
    const exmap at{{r.symbol(), rv}, {r.d(1), rd}, {th.symbol(), 0.9}, {th.d(1), w}, {th.d(2), al}};
    std::vector<double> x = solve_rows(sys, rows, {r.d(2), N_y}, at);
    expect_close(x[0], w * w * rv, "r''");
    expect_close(x[1], 0.3 * (rv * al + 2 * rd * w), "N_y");
}

// (5) A pendulum whose pivot is driven: a cart B of mass M at the specified x(t) along Nx>, a
// pendulum A (a point mass m at L from the pivot B_o, angle theta from the downward vertical,
// Ay> = -sin(theta) Nx> + cos(theta) Ny>, the mass at B_o - L Ay>), gravity -g Ny>, the
// driving force F Nx> on the cart. The mass is at (x + L sin(theta), -L cos(theta)), so
//   a_x = x'' + L (theta'' cos(theta) - theta'^2 sin(theta)).
// By hand:
//   the specified x's row (A and B move when only x changes; translate along Nx>):
//       F = M x'' + m a_x = (M + m) x'' + m L (theta'' cos(theta) - theta'^2 sin(theta))
//   theta's row (A alone about the pivot B_o, along Nz>):
//       -m g L sin(theta) = m L^2 theta'' + m L cos(theta) x''
//       =>  theta'' = -(g sin(theta) + x'' cos(theta)) / L.
TEST(DriveRows, ForceDrivingAPendulumsPivotComesFromTheCartsRow) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_specified("x"), th = s.add_variable("theta");
    ex M = s.add_constant("M", 2.0), m = s.add_constant("m", 0.7), L = s.add_constant("L", 0.4),
       g = s.add_constant("g", 9.81), F = s.add_unknown("F");
    const Frame& N = sys.newtonian();
    Particle& B = sys.add_particle("B");
    RigidBody& A = sys.add_rigid_body("A");
    B.point().set_pos(sys.origin(), x.symbol() * N.x());
    Point& B_o = sys.add_point("B_o", &A);
    B_o.set_pos(B.point(), Vector());
    A.body_frame().orient_axis(N, Axis::z, th.symbol());
    A.cm().set_pos(B_o, -L * A.body_frame().y());
    B.set_mass(M);
    A.set_mass(m);
    A.set_inertia(A.cm(), 0, 0, 0);
    sys.set_gravity(-g * N.y());
    sys.add_force(B.point(), F * N.x(), "drive");

    std::vector<RoadmapRow> rows = plan_roadmap(sys, {th}, {th.d(2), F});
    ASSERT_EQ(rows.size(), 2u);
    const RoadmapRow &Rt = row_for(rows, th.d(2)), &RF = row_for(rows, F);
    EXPECT_EQ(Rt.motion, Motion::rotate);
    EXPECT_TRUE(along(Rt.direction, N.z()));
    EXPECT_EQ(body_names(Rt.system), "A");
    ASSERT_NE(Rt.about, nullptr);
    EXPECT_TRUE(test::same(Rt.about->pos_from(B.point()), Vector(), N));  // the pivot
    EXPECT_EQ(RF.motion, Motion::translate);
    EXPECT_TRUE(along(RF.direction, N.x()));
    EXPECT_EQ(body_names(RF.system), "B,A");

    const double Mv = 2.0, mv = 0.7, Lv = 0.4, gv = 9.81;
    for (double q : {0.3, -2.2}) {
        const double qd = 1.7, xdd = -3.1;
        const exmap at{{x.symbol(), 0.25}, {x.d(1), 0.4}, {x.d(2), xdd}, {th.symbol(), q}, {th.d(1), qd}};
        std::vector<double> sol = solve_rows(sys, rows, {th.d(2), F}, at);
        const double qdd = -(gv * std::sin(q) + xdd * std::cos(q)) / Lv;
        expect_close(sol[0], qdd, "theta''");
        expect_close(sol[1], (Mv + mv) * xdd + mv * Lv * (qdd * std::cos(q) - qd * qd * std::sin(q)), "F");
    }
}

}  // namespace speed_and_drive_rows
