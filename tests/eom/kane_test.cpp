// SPDX-License-Identifier: MIT
// Kane's method against equations derived by hand.
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"

#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::pow;
using GiNaC::sin;
using GiNaC::cos;

TEST(Kane, RodPendulumMatchesHandDerivation) {
    // a uniform rod about its end: T1 - (m L^2/3) q'' - m g (L/2) sin q = 0
    SampleModel m = make_n_link_pendulum(1);
    SymbolTable& s = m.system.symbols();
    ex L = s.symbol("L1"), mass = s.symbol("m1"), g = s.symbol("g"), T = s.symbol("T1");
    const TimeVariable& q = m.q[0];
    std::vector<ex> E = form_kane_equations(m.system, m.q);
    ASSERT_EQ(E.size(), 1u);
    EXPECT_TRUE(same(E[0], T - mass * L * L / 3 * q.d(2) - mass * g * L / 2 * sin(q)));
    // F_r alone: the torque and gravity
    EXPECT_TRUE(same(form_generalized_active_forces(m.system, m.q)[0],
                     T - mass * g * L / 2 * sin(q)));
}

TEST(Kane, ParticleInARotatingTubeMatchesHandDerivation) {
    // tube T turns about Nz by theta (inertia J about Nz); particle P of mass m at r along Tx,
    // tied to N_o by a spring (k, natural length L0); motor torque tau on T.
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th = s.add_variable("theta"), r = s.add_variable("r");
    ex J = s.add_constant("J"), mass = s.add_constant("m"), k = s.add_constant("k"),
       L0 = s.add_constant("L0"), tau = s.add_unknown("tau");
    RigidBody& T = sys.add_rigid_body("T");
    T.body_frame().orient_axis(N, Axis::z, th);
    sys.point("T_o").set_pos(sys.origin(), Vector());
    T.cm().set_pos(sys.point("T_o"), Vector());
    T.set_mass(s.add_constant("M"));
    T.set_inertia(T.cm(), 0, 0, J);
    Particle& P = sys.add_particle("P");
    P.set_mass(mass);
    sys.point("P").set_pos(sys.point("T_o"), r * T.body_frame().x());
    sys.add_spring(sys.point("P"), sys.origin(), k, L0);
    sys.add_torque_pair(T, N, tau * N.z());
    std::vector<ex> E = form_kane_equations(sys, {th, r});
    // r > 0: |r| = r.  theta: tau - (J + m r^2) theta'' - 2 m r r' theta' = 0
    //                  r:     -k (r - L0) - m (r'' - r theta'^2) = 0
    exmap abs_r{{pow(pow(r, 2), GiNaC::wild()), pow(r, 2 * GiNaC::wild())}};
    EXPECT_TRUE(same(E[0].subs(abs_r), tau - (J + mass * r * r) * th.d(2) -
                                           2 * mass * r * r.d(1) * th.d(1)));
    EXPECT_TRUE(same(E[1].subs(abs_r),
                     -k * (r - L0) - mass * (r.d(2) - r * pow(th.d(1), 2))));
}

// ---- KaneOptions: the classical case -------------------------------------------------------

TEST(Kane, OptionsWithCoordinatesOnlyGiveTheClassicalEquations) {
    // the triple pendulum: u_r = q_r', no constraints; the mass-matrix form rebuilds E
    SampleModel m = make_triple_pendulum();
    std::vector<ex> classical = form_kane_equations(m.system, m.q);
    KaneEquations k = form_kane_equations(m.system, KaneOptions{.coordinates = m.q});
    ASSERT_EQ(k.residuals.size(), 3u);
    ASSERT_EQ(k.dynamics.unknowns.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(same(k.residuals[i], classical[i])) << "equation " << i;
        EXPECT_TRUE(k.dynamics.unknowns[i].is_equal(m.q[i].d(2)));
        EXPECT_TRUE(same(k.coordinate_rates[i], m.q[i].d(1)));
        // E = f - M q''
        ex rebuilt = k.dynamics.b(i, 0);
        for (unsigned j = 0; j < 3; ++j) rebuilt -= k.dynamics.A(i, j) * m.q[j].d(2);
        EXPECT_TRUE(same(rebuilt, classical[i]));
    }
    // the rod pendulum by hand, through the options: T1 - (m L^2/3) q'' - m g (L/2) sin q
    SampleModel p = make_n_link_pendulum(1);
    SymbolTable& s = p.system.symbols();
    ex L = s.symbol("L1"), mass = s.symbol("m1"), g = s.symbol("g"), T = s.symbol("T1");
    KaneEquations kp = form_kane_equations(p.system, KaneOptions{.coordinates = p.q});
    EXPECT_TRUE(same(kp.dynamics.A(0, 0), mass * L * L / 3));
    EXPECT_TRUE(same(kp.dynamics.b(0, 0), T - mass * g * L / 2 * sin(p.q[0])));
    EXPECT_TRUE(same(kp.active_forces[0], T - mass * g * L / 2 * sin(p.q[0])));
    EXPECT_TRUE(same(kp.inertia_forces[0], -mass * L * L / 3 * p.q[0].d(2)));
}

// ---- chosen generalized speeds -------------------------------------------------------------

namespace {
// a free rigid body: body-fixed XYZ angles q1..q3 and mass-centre position x, y, z in N;
// speeds u1..u3 = w_NB . Bx>, By>, Bz> and u4..u6 = v_NBcm . Bx>, By>, Bz>; principal
// central inertias I1, I2, I3; a torque Tx Bx> + Ty By> + Tz Bz> and a force at Bcm
// Fx Bx> + Fy By> + Fz Bz>.
struct FreeBody {
    System sys;
    std::vector<TimeVariable> q, u;
    ex I1, I2, I3, mass, Tx, Ty, Tz, Fx, Fy, Fz;
    RigidBody* B = nullptr;
    std::vector<ex> kinematics;
    FreeBody() {
        SymbolTable& s = sys.symbols();
        Frame& N = sys.newtonian();
        for (const char* n : {"q1", "q2", "q3", "x", "y", "z"}) q.push_back(s.add_variable(n, 1));
        for (const char* n : {"u1", "u2", "u3", "u4", "u5", "u6"})
            u.push_back(s.add_variable(n, 1));
        I1 = s.add_constant("I1"), I2 = s.add_constant("I2"), I3 = s.add_constant("I3");
        mass = s.add_constant("m");
        Tx = s.add_unknown("Tx"), Ty = s.add_unknown("Ty"), Tz = s.add_unknown("Tz");
        Fx = s.add_unknown("Fx"), Fy = s.add_unknown("Fy"), Fz = s.add_unknown("Fz");
        B = &sys.add_rigid_body("B");
        Frame& F = B->body_frame();
        F.orient_body_fixed(N, RotationSequence::XYZ, q[0], q[1], q[2]);
        B->cm().set_pos(sys.origin(), q[3] * N.x() + q[4] * N.y() + q[5] * N.z());
        // the mass-centre velocity in the chosen speeds
        B->cm().set_vel(N, u[3] * F.x() + u[4] * F.y() + u[5] * F.z());
        B->set_mass(mass);
        B->set_inertia(B->cm(), I1, I2, I3);
        sys.add_torque(*B, Tx * F.x() + Ty * F.y() + Tz * F.z(), "T");
        sys.add_force(B->cm(), Fx * F.x() + Fy * F.y() + Fz * F.z(), "F");
        Vector w = F.ang_vel_in(N);
        Vector rate = q[3].d(1) * N.x() + q[4].d(1) * N.y() + q[5].d(1) * N.z();
        kinematics = {u[0] - dot(w, F.x()),    u[1] - dot(w, F.y()),    u[2] - dot(w, F.z()),
                      u[3] - dot(rate, F.x()), u[4] - dot(rate, F.y()), u[5] - dot(rate, F.z())};
    }
    KaneOptions options() const {
        return {.coordinates = q,
                .speeds = {u[0], u[1], u[2], u[3], u[4], u[5]},
                .kinematic_equations = kinematics};
    }
};
}  // namespace

TEST(Kane, BodyFrameSpeedsOfAFreeBodyGiveEulersEquations) {
    FreeBody b;
    KaneEquations k = form_kane_equations(b.sys, b.options());
    const Frame& N = b.sys.newtonian();
    const Frame& F = b.B->body_frame();
    ASSERT_EQ(k.residuals.size(), 6u);
    ASSERT_EQ(k.coordinate_rates.size(), 6u);

    // the kinematic equations solved: with q' replaced, w_NB = u1 Bx> + u2 By> + u3 Bz> and
    // the rate of the position is u4 Bx> + u5 By> + u6 Bz>
    exmap qd;
    for (std::size_t i = 0; i < 6; ++i) qd[b.q[i].d(1)] = k.coordinate_rates[i];
    Vector w = F.ang_vel_in(N).map([&](const ex& e) { return e.subs(qd); });
    EXPECT_TRUE(same(w, b.u[0] * F.x() + b.u[1] * F.y() + b.u[2] * F.z(), F));
    Vector rate = (b.q[3].d(1) * N.x() + b.q[4].d(1) * N.y() + b.q[5].d(1) * N.z())
                      .map([&](const ex& e) { return e.subs(qd); });
    EXPECT_TRUE(same(rate, b.u[3] * F.x() + b.u[4] * F.y() + b.u[5] * F.z(), F));

    // Euler's equations and Newton's in body axes (Kane 1985, sec. 6.1), by hand:
    //   T1 = I1 u1' - (I2 - I3) u2 u3 (cyclic), F1 = m (u4' + u2 u6 - u3 u5) (cyclic)
    auto d = [&](int i) { return b.u[static_cast<std::size_t>(i)].d(1); };
    auto U = [&](int i) { return ex(b.u[static_cast<std::size_t>(i)]); };
    std::vector<ex> expected = {
        b.Tx - (b.I1 * d(0) - (b.I2 - b.I3) * U(1) * U(2)),
        b.Ty - (b.I2 * d(1) - (b.I3 - b.I1) * U(2) * U(0)),
        b.Tz - (b.I3 * d(2) - (b.I1 - b.I2) * U(0) * U(1)),
        b.Fx - b.mass * (d(3) + U(1) * U(5) - U(2) * U(4)),
        b.Fy - b.mass * (d(4) + U(2) * U(3) - U(0) * U(5)),
        b.Fz - b.mass * (d(5) + U(0) * U(4) - U(1) * U(3))};
    for (std::size_t i = 0; i < 6; ++i) EXPECT_TRUE(same(k.residuals[i], expected[i])) << i;
    // mass matrix diag(I1, I2, I3, m, m, m) in u'
    std::vector<ex> diagonal = {b.I1, b.I2, b.I3, b.mass, b.mass, b.mass};
    for (unsigned i = 0; i < 6; ++i) {
        EXPECT_TRUE(k.dynamics.unknowns[i].is_equal(b.u[i].d(1)));
        for (unsigned j = 0; j < 6; ++j)
            EXPECT_TRUE(same(k.dynamics.A(i, j), i == j ? diagonal[i] : ex(0))) << i << j;
    }
    // no constraints: the constrained forces are the unconstrained ones
    EXPECT_TRUE(same(k.active_forces[0], b.Tx));
    EXPECT_TRUE(same(k.unconstrained_active_forces[3], b.Fx));
}

// ---- motion constraints --------------------------------------------------------------------

TEST(Kane, DerivativeOfAConfigurationConstraintEliminatesADependentSpeed) {
    // a pendulum bob in Cartesian coordinates x, y (u = q'), held at x^2 + y^2 = L^2: the
    // derivative x x' + y y' = 0 is passed as a motion constraint with y' dependent
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y");
    ex mass = s.add_constant("m"), g = s.add_constant("g"), L = s.add_constant("L");
    Particle& P = sys.add_particle("P");
    P.set_mass(mass);
    P.point().set_pos(sys.origin(), x * N.x() + y * N.y());
    sys.set_gravity(-g * N.y());
    KaneEquations k = form_kane_equations(
        sys, KaneOptions{.coordinates = {x, y},
                         .motion_constraints = {x * x.d(1) + y * y.d(1)},
                         .dependent_speeds = {y.d(1)}});
    ASSERT_EQ(k.residuals.size(), 1u);
    ASSERT_EQ(k.independent_speeds.size(), 1u);
    EXPECT_TRUE(k.independent_speeds[0].is_equal(x.d(1)));
    // by hand: y' = -x x'/y, A = -x/y
    EXPECT_TRUE(same(k.dependent_speed_values[0], -x * x.d(1) / y));
    EXPECT_TRUE(same(k.constraint_coefficients(0, 0), -x / y));
    EXPECT_TRUE(same(k.coordinate_rates[1], -x * x.d(1) / y));
    // F~ = F_x + A F_y = 0 + (-x/y)(-m g);  F~* = -m x'' + (-x/y)(-m y'')
    EXPECT_TRUE(same(k.active_forces[0], mass * g * x / y));

    // against the angle form: x = L sin(th), y = -L cos(th), th'' = -(g/L) sin(th)
    GiNaC::realsymbol th("th"), thd("thd");
    ex thdd = -g / L * GiNaC::sin(th);
    exmap on_circle{{x, L * GiNaC::sin(th)},
                    {y, -L * GiNaC::cos(th)},
                    {x.d(1), L * GiNaC::cos(th) * thd},
                    {x.d(2), L * GiNaC::cos(th) * thdd - L * GiNaC::sin(th) * thd * thd}};
    EXPECT_TRUE(same(k.residuals[0].subs(on_circle), 0));
}

// ---- auxiliary speeds ----------------------------------------------------------------------

TEST(Kane, AuxiliarySpeedBringsOutThePendulumTension) {
    // bob P (mass m) at -L By> on frame B turning about Nz by th; the rod's pull T By> on P;
    // auxiliary speed ua along -By> (outward). By hand, along the rod:
    //   T = m g cos(th) + m L th'^2;  about the pivot: -m L^2 th'' - m g L sin(th) = 0
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th = s.add_variable("th"), ua = s.add_variable("ua", 1);
    ex mass = s.add_constant("m"), g = s.add_constant("g"), L = s.add_constant("L"),
       T = s.add_unknown("T");
    Frame& B = sys.add_frame("B");
    B.orient_axis(N, Axis::z, th);
    Particle& P = sys.add_particle("P");
    P.set_mass(mass);
    P.point().set_pos(sys.origin(), -L * B.y());
    P.point().set_vel(N, P.point().vel_in(N) - ua * B.y());
    sys.set_gravity(-g * N.y());
    sys.add_force(P.point(), T * B.y(), "T");
    KaneEquations k =
        form_kane_equations(sys, KaneOptions{.coordinates = {th}, .auxiliary_speeds = {ua}});
    ASSERT_EQ(k.residuals.size(), 1u);
    ASSERT_EQ(k.auxiliary_equations.size(), 1u);
    EXPECT_TRUE(same(k.residuals[0], -mass * L * L * th.d(2) - mass * g * L * sin(th)));
    const ex& Ea = k.auxiliary_equations[0];
    ex T_solved = -Ea.subs(T == 0) / Ea.diff(GiNaC::ex_to<GiNaC::symbol>(T));
    EXPECT_TRUE(same(T_solved, mass * g * GiNaC::cos(th) + mass * L * pow(th.d(1), 2)));
    EXPECT_FALSE(k.residuals[0].has(ua));
}

TEST(Kane, AuxiliarySpeedsBringOutTheForcesOfASpinningTube) {
    // tube T spun about Nz by a specified angle th(t); particle P (mass m) slides in it at r
    // along Tx>; gravity -g Nz>. Constraint forces on P: Fn Ty> from the tube wall and
    // Fv Nz> from the tube floor, brought out by ua along Ty> and ub along Nz>. By hand:
    //   along Tx>: -m (r'' - r th'^2) = 0
    //   along Ty>: Fn - m (r th'' + 2 r' th') = 0;   along Nz>: Fv - m g = 0
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th = s.add_specified("th"), r = s.add_variable("r");
    TimeVariable ua = s.add_variable("ua", 1), ub = s.add_variable("ub", 1);
    ex mass = s.add_constant("m"), g = s.add_constant("g"), Fn = s.add_unknown("Fn"),
       Fv = s.add_unknown("Fv");
    Frame& T = sys.add_frame("T");
    T.orient_axis(N, Axis::z, th);
    Particle& P = sys.add_particle("P");
    P.set_mass(mass);
    P.point().set_pos(sys.origin(), r * T.x());
    P.point().set_vel(N, P.point().vel_in(N) + ua * T.y() + ub * N.z());
    sys.set_gravity(-g * N.z());
    sys.add_force(P.point(), Fn * T.y() + Fv * N.z(), "contact");
    KaneEquations k = form_kane_equations(
        sys, KaneOptions{.coordinates = {r}, .auxiliary_speeds = {ua, ub}});
    ASSERT_EQ(k.auxiliary_equations.size(), 2u);
    EXPECT_TRUE(same(k.residuals[0], -mass * (r.d(2) - r * pow(th.d(1), 2))));
    EXPECT_TRUE(same(k.auxiliary_equations[0], Fn - mass * (r * th.d(2) + 2 * r.d(1) * th.d(1))));
    EXPECT_TRUE(same(k.auxiliary_equations[1], Fv - mass * g));
}

// ---- errors name the user's objects and the fix --------------------------------------------

namespace {
// a particle in the plane with speeds u1 = x', u2 = y'
struct PlanarParticle {
    System sys;
    TimeVariable x, y, u1, u2;
    PlanarParticle() {
        SymbolTable& s = sys.symbols();
        Frame& N = sys.newtonian();
        x = s.add_variable("x"), y = s.add_variable("y");
        u1 = s.add_variable("u1", 1), u2 = s.add_variable("u2", 1);
        Particle& P = sys.add_particle("P");
        P.set_mass(s.add_constant("m"));
        P.point().set_pos(sys.origin(), x * N.x() + y * N.y());
    }
    KaneOptions options() const {
        return {.coordinates = {x, y},
                .speeds = {u1, u2},
                .kinematic_equations = {u1 - x.d(1), u2 - y.d(1)}};
    }
};
}  // namespace

TEST(Kane, ErrorsNameTheObjectAndTheFix) {
    PlanarParticle p;
    SymbolTable& s = p.sys.symbols();
    KaneOptions o = p.options();

    // a dependent speed that the constraints do not hold
    o.motion_constraints = {p.u1 - p.x * p.u1};
    o.dependent_speeds = {p.u2};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, o), ArgumentError,
                     "dependent speed 'u2' appears in no motion constraint");
    // a dependent speed that is not a speed
    o.dependent_speeds = {p.x};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, o), ArgumentError,
                     "dependent speed 'x' is not one of the speeds");
    // a constraint not linear in the speeds
    o.motion_constraints = {p.u1 * p.u2 + p.y};
    o.dependent_speeds = {p.u2};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, o), SolveError,
                     "motion constraint 1 is not linear in 'u1'");
    // constraints that cannot be solved for the dependent speeds named
    o.motion_constraints = {p.u1 + p.u2, 2 * p.u1 + 2 * p.u2};
    o.dependent_speeds = {p.u1, p.u2};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, o), SolveError,
                     "cannot be solved for the dependent speeds");
    // one constraint, two dependent speeds
    o.motion_constraints = {p.u1 + p.u2};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, o), ArgumentError,
                     "1 motion constraints and 2 dependent speeds");

    // kinematic equations: a count off, missing, not linear in q', not solvable
    KaneOptions k = p.options();
    k.kinematic_equations.pop_back();
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), ArgumentError,
                     "1 kinematic equations for 2 coordinates 'x', 'y'");
    k.kinematic_equations.clear();
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), ArgumentError,
                     "without kinematic equations");
    k = p.options();
    k.kinematic_equations[1] = p.u2 - pow(p.y.d(1), 2);
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), SolveError,
                     "kinematic equation 2 is not linear in 'y''");
    k.kinematic_equations = {p.u1 - p.x.d(1) - p.y.d(1), p.u2 - p.x.d(1) - p.y.d(1)};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), SolveError,
                     "cannot be solved for q'");

    // a speed without a declared derivative, a speed that is a coordinate rate
    TimeVariable w = s.add_variable("w", 0);
    k = p.options();
    k.speeds = {p.u1, w};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), ModelError,
                     "time derivative of speed 'w' is not declared");
    k.speeds = {p.u1, p.y.d(1)};
    EXPECT_THROW_MSG(form_kane_equations(p.sys, k), ArgumentError,
                     "speed 'y'' is a coordinate or its rate");

    // a velocity holding the rate of a coordinate left out of the list
    TimeVariable z = s.add_variable("z");
    Particle& Q = p.sys.add_particle("Q");
    Q.set_mass(s.add_constant("mQ"));
    Q.point().set_pos(p.sys.origin(), z * p.sys.newtonian().z());
    EXPECT_THROW_MSG(form_kane_equations(p.sys, p.options()), ModelError,
                     "the velocity of point 'Q' in 'N' holds 'z''");
}

TEST(KaneAndLagrange, ACoordinateListedTwiceIsAnArgumentError) {
    System sys("N");
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q");
    RigidBody& B = sys.add_rigid_body("B");
    B.body_frame().orient_axis(sys.newtonian(), Axis::z, q);
    B.cm().set_pos(sys.origin(), s.add_constant("L") * B.body_frame().x());
    B.set_mass(s.add_constant("m"));
    EXPECT_THROW_MSG(form_kane_equations(sys, {q, q}), ArgumentError,
                     "form_kane_equations(): the coordinate 'q' is listed twice");
    EXPECT_THROW_MSG(form_lagrange_equations(sys, {q, q}), ArgumentError,
                     "form_lagrange_equations(): the coordinate 'q' is listed twice");
}
