// SPDX-License-Identifier: MIT
// Linearization against hand derivations; the rolling disk acceptance test (Kane's method with
// chosen speeds and no-slip constraints, checked against Newton-Euler and energy, linearized
// about steady rolling).
#include "alembert/eom/linearize.hpp"

#include "alembert/error.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <random>

#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;
using GiNaC::tan;

namespace {

// a bob of mass m at -L By> on frame B turning about Nz by th, gravity -g Ny>, and an input
// force F Bx> on the bob (perpendicular to the rod)
struct SimplePendulum {
    System sys;
    TimeVariable th;
    ex mass, g, L, F;
    SimplePendulum() {
        SymbolTable& s = sys.symbols();
        Frame& N = sys.newtonian();
        th = s.add_variable("th");
        mass = s.add_constant("m"), g = s.add_constant("g"), L = s.add_constant("L");
        F = s.add_unknown("F");
        Frame& B = sys.add_frame("B");
        B.orient_axis(N, Axis::z, th);
        Particle& P = sys.add_particle("P");
        P.set_mass(mass);
        P.point().set_pos(sys.origin(), -L * B.y());
        sys.set_gravity(-g * N.y());
        sys.add_force(P.point(), F * B.x(), "F");
    }
};

GiNaC::matrix block(const GiNaC::matrix& A, const std::vector<unsigned>& idx) {
    const unsigned n = static_cast<unsigned>(idx.size());
    GiNaC::matrix out(n, n);
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) out(i, j) = A(idx[i], idx[j]);
    return out;
}

}  // namespace

TEST(Linearize, SimplePendulumInSecondOrderFormMatchesHandDerivation) {
    // m L^2 th'' = F L - m g L sin(th): about th = 0, x = (th, th'):
    //   A = [[0, 1], [-g/L, 0]] (omega^2 = g/L), B = [[0], [1/(m L)]]; about th = pi, +g/L
    SimplePendulum p;
    std::vector<ex> E = form_kane_equations(p.sys, {p.th});
    FirstOrderEquations f = to_first_order(E, {p.th});
    LinearizedEquations down = linearize(p.sys.symbols(), f,
                                         {.operating_point = {{p.th, 0}}, .inputs = {p.F}});
    ASSERT_EQ(down.A.rows(), 2u);
    ASSERT_EQ(down.B.cols(), 1u);
    EXPECT_TRUE(same(down.A(0, 0), 0));
    EXPECT_TRUE(same(down.A(0, 1), 1));
    EXPECT_TRUE(same(down.A(1, 0), -p.g / p.L));
    EXPECT_TRUE(same(down.A(1, 1), 0));
    EXPECT_TRUE(same(down.B(0, 0), 0));
    EXPECT_TRUE(same(down.B(1, 0), 1 / (p.mass * p.L)));
    // the operating point leaves th' and F out, so they stay symbols: the rates there are
    // th' and th'' = F/(m L)
    EXPECT_TRUE(same(down.operating_rates[0], p.th.d(1)));
    EXPECT_TRUE(same(down.operating_rates[1], p.F / (p.mass * p.L)));

    LinearizedEquations up = linearize(
        p.sys.symbols(), f,
        {.operating_point = {{p.th, GiNaC::Pi}, {p.th.d(1), 0}, {p.F, 0}}, .inputs = {p.F}});
    EXPECT_TRUE(same(up.A(1, 0), p.g / p.L));
    EXPECT_TRUE(same(up.B(1, 0), 1 / (p.mass * p.L)));
    // omega^2 = g/L: det(A - lambda 1) = lambda^2 + g/L about th = 0
    GiNaC::symbol lambda("lambda");
    EXPECT_TRUE(same(down.A.charpoly(lambda), pow(lambda, 2) + p.g / p.L));
}

TEST(Linearize, ChosenSpeedFirstOrderFormMatchesHandDerivation) {
    // speed u = L th' (the bob's speed): th' = u/L, m u' = F - m g sin(th); about th = u = 0
    //   A = [[0, 1/L], [-g, 0]], B = [[0], [1/m]]; eigenvalues lambda^2 = -g/L
    SimplePendulum p;
    TimeVariable u = p.sys.symbols().add_variable("u", 1);
    KaneEquations k = form_kane_equations(
        p.sys, KaneOptions{.coordinates = {p.th},
                           .speeds = {u},
                           .kinematic_equations = {u - p.L * p.th.d(1)}});
    FirstOrderEquations f = to_first_order(k);
    ASSERT_EQ(f.states.size(), 2u);
    ASSERT_EQ(f.residuals.size(), 2u);
    LinearizedEquations lin = linearize(p.sys.symbols(), f,
                                        {.operating_point = {{p.th, 0}, {u, 0}}, .inputs = {p.F}});
    EXPECT_TRUE(same(lin.A(0, 0), 0));
    EXPECT_TRUE(same(lin.A(0, 1), 1 / p.L));
    EXPECT_TRUE(same(lin.A(1, 0), -p.g));
    EXPECT_TRUE(same(lin.A(1, 1), 0));
    EXPECT_TRUE(same(lin.B(0, 0), 0));
    EXPECT_TRUE(same(lin.B(1, 0), 1 / p.mass));
    GiNaC::symbol lambda("lambda");
    EXPECT_TRUE(same(lin.A.charpoly(lambda), pow(lambda, 2) + p.g / p.L));
}

TEST(Linearize, ErrorsNameTheObjectAndTheFix) {
    SimplePendulum p;
    const SymbolTable& s = p.sys.symbols();
    FirstOrderEquations f = to_first_order(form_kane_equations(p.sys, {p.th}), {p.th});
    EXPECT_THROW_MSG(linearize(s, f, {.operating_point = {{p.th.d(2), 0}}}), ArgumentError,
                     "gives a value for the rate 'th'''");
    EXPECT_THROW_MSG(linearize(s, f, {.inputs = {p.th}}), ArgumentError,
                     "input 'th' is a state or a rate");
    FirstOrderEquations bad = f;
    bad.residuals.push_back(0);
    EXPECT_THROW_MSG(linearize(s, bad), ArgumentError, "2 residuals for 1 rates");
    bad = f;
    bad.residuals[0] = pow(p.th.d(2), 2) - sin(p.th);
    EXPECT_THROW_MSG(linearize(s, bad), SolveError, "not linear in the rate 'th'''");
    // cos(th) th'' = sin(th) is singular at th = pi/2
    bad.residuals[0] = cos(p.th) * p.th.d(2) - sin(p.th);
    EXPECT_THROW_MSG(linearize(s, bad, {.operating_point = {{p.th, GiNaC::Pi / 2}}}), SolveError,
                     "singular mass matrix there");
    EXPECT_THROW_MSG(to_first_order(std::vector<ex>{}, {p.th}), ArgumentError,
                     "0 equations for 1 coordinates");
}

// ============================================================================================
// Rolling disk acceptance test
// ============================================================================================
//
// A thin uniform disk D (mass m, radius r) rolls without slip on the horizontal plane of N
// (Nz up). Yaw frame Y: about Nz by q1; lean frame L: about Yx> by q2; D: about Ly> (the disk
// axis) by q3. The contact point P (on the plane) is at x Nx> + y Ny>; the centre Dcm at
// r Lz> from it. Central inertia Ia = m r^2/2 about Ly>, Id = m r^2/4 about Lx>, Lz>.
// Speeds: u1, u2, u3 = w_ND . Lx>, Ly>, Lz> (so u1 = q2', u2 = q3' + q1' sin q2,
// u3 = q1' cos q2) and u4 = x', u5 = y'. No slip at the disk's point D_P in contact:
// v_ND_P . Nx> = v_ND_P . Ny> = 0, solved for the dependent u4, u5.
//
// Newton-Euler by hand (independent of Kane's method). Write s = sin q2, t = tan q2.
// With rolling, v_Dcm = w_ND x r Lz> = r (u2 Lx> - u1 Ly>); L turns with
// w_NL = u1 Lx> + u3 t Ly> + u3 Lz>, so
//   a_Dcm = r [(u2' + u1 u3) Lx> + (-u1' + u2 u3) Ly> + (-u1^2 - t u2 u3) Lz>],
//   H = Id u1 Lx> + Ia u2 Ly> + Id u3 Lz> (about Dcm),
//   dH/dt = (Id u1' + Id t u3^2 - Ia u2 u3) Lx> + Ia u2' Ly> + (Id u3' + Ia u1 u2 - Id t u1 u3) Lz>.
// Moments about the contact point P eliminate the contact force:
//   M_P = r Lz> x (-m g Nz>) = m g r s Lx> = dH/dt + r Lz> x m a_Dcm, which gives
//   (Id + m r^2) u1' = m g r s - Id t u3^2 + (Ia + m r^2) u2 u3
//   (Ia + m r^2) u2' = -m r^2 u1 u3
//   Id u3'           = -Ia u1 u2 + Id t u1 u3
//
// Upright steady rolling: q2 = 0, u1 = u3 = 0, u2 = Omega (q3' = Omega, rolling at r Omega).
// Linearized: q2' = u1, (Id + m r^2) u1' = m g r q2 + (Ia + m r^2) Omega u3,
// Id u3' = -Ia Omega u1, u2' = 0. For the lean states (q2, u1, u3),
//   det(lambda 1 - A_lean) = lambda (lambda^2 - a + b c),
//   a = m g r/(Id + m r^2), b = (Ia + m r^2) Omega/(Id + m r^2), c = Ia Omega/Id,
// stable (lambda purely imaginary) iff (Ia + m r^2) Ia Omega^2/Id > m g r. For the thin disk
// b c = (12/5) Omega^2 and a = (4/5) g/r, so lambda^2 = (4/5)(g/r - 3 Omega^2):
// stable iff Omega^2 > g/(3 r).

namespace {

struct RollingDisk {
    System sys;
    std::vector<TimeVariable> q, u;
    ex mass, r, g, Omega, Ia, Id;
    KaneOptions options;
    RollingDisk() {
        SymbolTable& s = sys.symbols();
        Frame& N = sys.newtonian();
        for (const char* n : {"q1", "q2", "q3", "x", "y"}) q.push_back(s.add_variable(n, 1));
        for (const char* n : {"u1", "u2", "u3", "u4", "u5"}) u.push_back(s.add_variable(n, 1));
        mass = s.add_constant("m"), r = s.add_constant("r"), g = s.add_constant("g");
        Omega = s.add_constant("Omega");
        Ia = mass * r * r / 2, Id = mass * r * r / 4;
        Frame& Y = sys.add_frame("Y");
        Y.orient_axis(N, Axis::z, q[0]);
        Frame& L = sys.add_frame("L");
        L.orient_axis(Y, Axis::x, q[1]);
        RigidBody& D = sys.add_rigid_body("D");
        Frame& Df = D.body_frame();
        Df.orient_axis(L, Axis::y, q[2]);
        Point& P = sys.add_point("P");
        P.set_pos(sys.origin(), q[3] * N.x() + q[4] * N.y());
        D.cm().set_pos(P, r * L.z());
        D.set_mass(mass);
        // axisymmetric about Ly> = Dy>, so the central inertia reads the same in L
        Mat3 I;
        I(0, 0) = Id, I(1, 1) = Ia, I(2, 2) = Id;
        D.set_inertia(D.cm(), Dyadic(L, L, I));
        sys.set_gravity(-g * N.z());
        // the disk's own point at the contact, for the no-slip constraints
        Point& DP = sys.add_point("D_P", &D);
        DP.set_pos(D.cm(), -r * L.z());
        DP.set_vel_two_point(N, D.cm(), Df);
        Vector w = Df.ang_vel_in(N);
        options = {.coordinates = q,
                   .speeds = {u[0], u[1], u[2], u[3], u[4]},
                   .kinematic_equations = {u[0] - dot(w, L.x()), u[1] - dot(w, L.y()),
                                           u[2] - dot(w, L.z()), u[3] - q[3].d(1),
                                           u[4] - q[4].d(1)},
                   .motion_constraints = {dot(DP.vel_in(N), N.x()), dot(DP.vel_in(N), N.y())},
                   .dependent_speeds = {u[3], u[4]}};
    }
    // u1', u2', u3' by Newton-Euler (see the derivation above)
    std::vector<ex> newton_euler_rates() const {
        ex s = sin(q[1]), t = tan(q[1]);
        ex u1 = u[0], u2 = u[1], u3 = u[2];
        return {(mass * g * r * s - Id * t * u3 * u3 + (Ia + mass * r * r) * u2 * u3) /
                    (Id + mass * r * r),
                -mass * r * r * u1 * u3 / (Ia + mass * r * r),
                (-Ia * u1 * u2 + Id * t * u1 * u3) / Id};
    }
};

}  // namespace

namespace {

void expect_newton_euler(RollingDisk& d, bool simplified) {
    SCOPED_TRACE(simplified ? "simplified" : "not simplified");
    d.options.simplify = simplified;
    KaneEquations k = form_kane_equations(d.sys, d.options);
    ASSERT_EQ(k.residuals.size(), 3u);
    ASSERT_EQ(k.independent_speeds.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(k.independent_speeds[i].is_equal(d.u[i]));
        EXPECT_TRUE(k.dynamics.unknowns[i].is_equal(d.u[i].d(1)));
    }
    // the dependent speeds by hand: the contact point moves at r (u2 - u3 t) along Lx>
    ex roll = d.r * (d.u[1] - d.u[2] * tan(d.q[1]));
    EXPECT_TRUE(same(k.dependent_speed_values[0], roll * cos(d.q[0])));
    EXPECT_TRUE(same(k.dependent_speed_values[1], roll * sin(d.q[0])));
    // the kinematic equations solved, by hand
    EXPECT_TRUE(same(k.coordinate_rates[0], d.u[2] / cos(d.q[1])));
    EXPECT_TRUE(same(k.coordinate_rates[1], d.u[0]));
    EXPECT_TRUE(same(k.coordinate_rates[2], d.u[1] - d.u[2] * tan(d.q[1])));
    EXPECT_TRUE(same(k.coordinate_rates[3], roll * cos(d.q[0])));
    EXPECT_TRUE(same(k.coordinate_rates[4], roll * sin(d.q[0])));
    // the Newton-Euler rates satisfy Kane's equations, whose mass matrix is invertible, so
    // they are its solution
    EXPECT_FALSE(equal(k.dynamics.A.determinant(), 0));
    std::vector<ex> ne = d.newton_euler_rates();
    exmap at_ne;
    for (std::size_t i = 0; i < 3; ++i) at_ne[d.u[i].d(1)] = ne[i];
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_TRUE(same(k.residuals[i].subs(at_ne), 0)) << "equation " << i;
    // and the mass-matrix form rebuilds the residuals
    for (unsigned i = 0; i < 3; ++i) {
        ex rebuilt = k.dynamics.b(i, 0);
        for (unsigned j = 0; j < 3; ++j) rebuilt -= k.dynamics.A(i, j) * d.u[j].d(1);
        EXPECT_TRUE(same(rebuilt, k.residuals[i]));
    }
}

}  // namespace

TEST(RollingDisk, KaneWithDependentSpeedsMatchesNewtonEuler) {
    RollingDisk d;
    expect_newton_euler(d, true);
    expect_newton_euler(d, false);
}

TEST(RollingDisk, EnergyIsConservedAlongKanesEquations) {
    // T + V with T from the model's velocities (System::calc_kinetic_energy) and
    // V = m g r cos(q2); along the motion d/dt (T + V) = sum dE/dq q' + dE/du u' = 0, with q'
    // from the kinematic equations and u' solved from Kane's equations at random states
    RollingDisk d;
    KaneEquations k = form_kane_equations(d.sys, d.options);
    const SymbolTable& st = d.sys.symbols();
    exmap qd;
    for (std::size_t i = 0; i < 5; ++i) qd[d.q[i].d(1)] = k.coordinate_rates[i];
    ex energy = (d.sys.calc_kinetic_energy(d.sys.bodies()) + d.mass * d.g * d.r * cos(d.q[1]))
                    .subs(qd);
    ex energy_rate = 0;
    for (std::size_t i = 0; i < 5; ++i)
        energy_rate += energy.diff(GiNaC::ex_to<GiNaC::symbol>(d.q[i].symbol())) *
                       k.coordinate_rates[i];
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
    for (int trial = 0; trial < 4; ++trial) {
        exmap values{{d.mass, positive(rng)}, {d.r, positive(rng)}, {d.g, 9.81}};
        for (std::size_t i = 0; i < 5; ++i) values[d.q[i]] = unit(rng);
        for (std::size_t i = 0; i < 3; ++i) values[d.u[i]] = 3 * unit(rng);
        Eigen::VectorXd ud = solve_numeric(st, k.dynamics, values);
        double rate = st.evaluate(energy_rate, values);
        double scale = std::abs(st.evaluate(energy, values));
        for (std::size_t i = 0; i < 3; ++i) {
            double dE_du = st.evaluate(energy.diff(GiNaC::ex_to<GiNaC::symbol>(d.u[i].symbol())),
                                       values);
            rate += dE_du * ud(static_cast<int>(i));
        }
        EXPECT_LT(std::abs(rate), 1e-12 * std::max(1.0, scale)) << "trial " << trial;
    }
}

TEST(RollingDisk, UprightRollingIsStableAboveTheClassicalSpinRate) {
    RollingDisk d;
    KaneEquations k = form_kane_equations(d.sys, d.options);
    FirstOrderEquations f = to_first_order(k);
    // states (q1, q2, q3, x, y, u1, u2, u3); q1, q3, x, y left symbolic (ignorable)
    ASSERT_EQ(f.states.size(), 8u);
    LinearizedEquations lin = linearize(
        d.sys.symbols(), f,
        {.operating_point = {{d.q[1], 0}, {d.u[0], 0}, {d.u[1], d.Omega}, {d.u[2], 0}}});
    // a steady motion: the rates there are q3' = Omega, x' = r Omega cos q1,
    // y' = r Omega sin q1, the rest zero
    std::vector<ex> rates0 = {0, 0, d.Omega, d.r * d.Omega * cos(d.q[0]),
                              d.r * d.Omega * sin(d.q[0]), 0, 0, 0};
    for (std::size_t i = 0; i < 8; ++i) EXPECT_TRUE(same(lin.operating_rates[i], rates0[i])) << i;

    // the lean states (q2, u1, u3) = indices (1, 5, 7) form a closed block
    const std::vector<unsigned> lean = {1, 5, 7};
    for (unsigned i : lean)
        for (unsigned j = 0; j < 8; ++j)
            if (j != 1 && j != 5 && j != 7) {
                EXPECT_TRUE(same(lin.A(i, j), 0)) << i << "," << j;
            }
    GiNaC::matrix A_lean = block(lin.A, lean);
    // by hand: q2' = u1, u1' = (4/5)(g/r) q2 + (6/5) Omega u3, u3' = -2 Omega u1
    EXPECT_TRUE(same(A_lean(0, 1), 1));
    EXPECT_TRUE(same(A_lean(1, 0), ex(4) / 5 * d.g / d.r));
    EXPECT_TRUE(same(A_lean(1, 2), ex(6) / 5 * d.Omega));
    EXPECT_TRUE(same(A_lean(2, 1), -2 * d.Omega));
    // the characteristic polynomial and the stability condition Omega^2 > g/(3 r)
    GiNaC::symbol lambda("lambda");
    ex lambda2 = ex(4) / 5 * (d.g / d.r - 3 * pow(d.Omega, 2));
    EXPECT_TRUE(same(A_lean.charpoly(lambda), -(pow(lambda, 3) - lambda2 * lambda)));
    EXPECT_TRUE(same(lambda2.subs(d.Omega == GiNaC::sqrt(d.g / (3 * d.r))), 0));
    // the whole linearization: five more zero roots (yaw, spin, position, spin rate)
    EXPECT_TRUE(same(lin.A.charpoly(lambda), pow(lambda, 6) * (pow(lambda, 2) - lambda2)));

    // numerically, across the threshold: purely imaginary above it, a positive real root below
    const SymbolTable& st = d.sys.symbols();
    const double r = 0.3, g = 9.81, threshold = g / (3 * r);
    for (double factor : {1.1, 0.9}) {
        exmap values{{d.mass, 1.7}, {d.r, r}, {d.g, g}, {d.Omega, std::sqrt(factor * threshold)}};
        Eigen::Matrix3d A;
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j) A(i, j) = st.evaluate(A_lean(i, j), values);
        Eigen::Vector3cd ev = Eigen::EigenSolver<Eigen::Matrix3d>(A).eigenvalues();
        double max_real = -1e300, max_imag = 0;
        for (int i = 0; i < 3; ++i) {
            max_real = std::max(max_real, ev(i).real());
            max_imag = std::max(max_imag, std::abs(ev(i).imag()));
        }
        // the nonzero pair is +-sqrt(lambda^2) with lambda^2 = (4/5)(g/r)(1 - factor)
        double expected = std::sqrt(std::abs(0.8 * g / r * (1 - factor)));
        if (factor > 1) {
            EXPECT_LT(std::abs(max_real), 1e-12 * expected) << "stable above the threshold";
            EXPECT_NEAR(max_imag, expected, 1e-12 * expected);
        } else {
            EXPECT_NEAR(max_real, expected, 1e-12 * expected) << "unstable below the threshold";
            EXPECT_LT(max_imag, 1e-12 * expected);
        }
    }
}

TEST(Linearize, SecondOrderFormOfThePendulumMatchesHandDerivation) {
    // m L^2 th'' + m g L sin(th) = F L: about th = 0, M = m L^2, C = 0, K = m g L, H = L;
    // about th = pi (inverted) K = -m g L, the unstable direction
    SimplePendulum p;
    std::vector<ex> E = form_kane_equations(p.sys, {p.th});
    SecondOrderLinearization down = linearize_second_order(
        p.sys.symbols(), E, {p.th}, {.operating_point = {{p.th, 0}, {p.th.d(1), 0}}, .inputs = {p.F}});
    ASSERT_EQ(down.M.rows(), 1u);
    EXPECT_TRUE(same(down.M(0, 0), p.mass * pow(p.L, 2)));
    EXPECT_TRUE(same(down.C(0, 0), 0));
    EXPECT_TRUE(same(down.K(0, 0), p.mass * p.g * p.L));
    EXPECT_TRUE(same(down.H(0, 0), p.L));
    SecondOrderLinearization up = linearize_second_order(
        p.sys.symbols(), E, {p.th},
        {.operating_point = {{p.th, GiNaC::Pi}, {p.th.d(1), 0}, {p.F, 0}}, .inputs = {p.F}});
    EXPECT_TRUE(same(up.K(0, 0), -p.mass * p.g * p.L));
    // away from equilibrium (horizontal, th = pi/2, th0'' = -g/L): K = m g L cos(pi/2) = 0
    SecondOrderLinearization side = linearize_second_order(
        p.sys.symbols(), E, {p.th}, {.operating_point = {{p.th, GiNaC::Pi / 2}, {p.F, 0}}});
    EXPECT_TRUE(same(side.K(0, 0), 0));
    EXPECT_TRUE(same(side.M(0, 0), p.mass * pow(p.L, 2)));
}

TEST(Linearize, CoulombFrictionLinearizesAwayFromRestAndIsRefusedAtRest) {
    // m x'' = F - mu m g csgn(x'): at x' = 1 the friction force is constant, so A = [[0, 1],
    // [0, 0]] and B = [[0], [1/m]]; at x' = 0 it switches and has no derivative
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x");
    ex mass = s.add_constant("m"), mu = s.add_constant("mu"), g = s.add_constant("g");
    ex F = s.add_unknown("F");
    std::vector<ex> E = {F - mu * mass * g * GiNaC::csgn(x.d(1)) - mass * x.d(2)};
    FirstOrderEquations f = to_first_order(E, {x});
    LinearizedEquations lin =
        linearize(s, f, {.operating_point = {{x, 0}, {x.d(1), 1}, {F, 0}}, .inputs = {F}});
    EXPECT_TRUE(same(lin.A(1, 1), 0));
    EXPECT_TRUE(same(lin.B(1, 0), 1 / mass));
    EXPECT_TRUE(same(lin.operating_rates[1], -mu * g));
    EXPECT_THROW_MSG(linearize(s, f, {.operating_point = {{x, 0}, {x.d(1), 0}}, .inputs = {F}}),
                     SolveError, "a sign function (Coulomb friction, a one-sided contact) switches there");
}
