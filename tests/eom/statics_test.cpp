// SPDX-License-Identifier: MIT
// Nonlinear statics against hand results: a torsional-spring pendulum (bisection), a two-bar
// mechanism's equilibria picked by bounds, a mix of coordinate and load unknowns, and the
// failures (no equilibrium, singular Jacobian, wrong branch).
#include "alembert/eom/statics.hpp"

#include <cmath>
#include <functional>
#include <numbers>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

constexpr double kPi = std::numbers::pi;

// a root of f in [a, b], where f changes sign, by bisection
double bisect(const std::function<double(double)>& f, double a, double b) {
    double fa = f(a);
    for (int k = 0; k < 200 && b - a > 1e-15; ++k) {
        double c = (a + b) / 2, fc = f(c);
        if ((fc < 0) == (fa < 0)) a = c, fa = fc;
        else b = c;
    }
    return (a + b) / 2;
}

// two uniform bars (mass m, length L): B1 pinned at N_o turning about Nz by q1 from the
// downward vertical, B2 pinned at B1's end turning by q2 relative to B1; a horizontal force
// P Nx> at B2's tip; gravity -g Ny
struct TwoBar {
    System sys{"N"};
    TimeVariable q1, q2;
    ex P, m, L, g;
    TwoBar() {
        SymbolTable& s = sys.symbols();
        Frame& N = sys.newtonian();
        q1 = s.add_variable("q1");
        q2 = s.add_variable("q2");
        m = s.add_constant("m", 1.5);
        L = s.add_constant("L", 0.9);
        g = s.add_constant("g", 9.81);
        P = s.add_unknown("P");
        RigidBody& B1 = sys.add_rigid_body("B1");
        RigidBody& B2 = sys.add_rigid_body("B2");
        B1.body_frame().orient_axis(N, Axis::z, q1);
        B2.body_frame().orient_axis(B1.body_frame(), Axis::z, q2);
        sys.point("B1_o").set_pos(sys.origin(), Vector());
        sys.point("B2_o").set_pos(sys.point("B1_o"), -L * B1.body_frame().y());
        B1.cm().set_pos(sys.point("B1_o"), -(L / 2) * B1.body_frame().y());
        B2.cm().set_pos(sys.point("B2_o"), -(L / 2) * B2.body_frame().y());
        Point& tip = sys.add_point("tip", &B2);
        tip.set_pos(sys.point("B2_o"), -L * B2.body_frame().y());
        for (RigidBody* B : {&B1, &B2}) {
            B->set_mass(m);
            B->set_inertia(B->cm(), m * L * L / 12, 0, m * L * L / 12);
        }
        sys.add_force(tip, P * N.x(), "P");
        sys.set_gravity(-g * N.y());
    }
    double value(const ex& c) const { return *sys.symbols().value(c); }
    // statics road-map rows for the two coordinates' rows, solving for `unknowns`
    std::vector<ex> residuals(const std::vector<ex>& unknowns) const {
        return residuals_of(plan_roadmap(sys, {q1, q2}, unknowns, Analysis::statics));
    }
};

}  // namespace

TEST(Statics, TorsionalSpringPendulumMatchesBisection) {
    // a hanging rod with a torsional spring -k q and a torque T: T - k q - m g (L/2) sin q = 0,
    // a transcendental equation solved here by bisection
    test::Model p = test::make_rod_pendulum();
    SymbolTable& s = p.sys.symbols();
    const Frame& N = p.sys.newtonian();
    ex k = s.add_constant("k", 2.0);
    p.sys.add_torque_pair(p.sys.rigid_body("B"), N, -k * p.q[0] * N.z(), "spring");
    double m = *s.value(s.symbol("m")), L = *s.value(s.symbol("L")), g = *s.value(s.symbol("g"));
    const double T = 3.0;
    double q_hand = bisect([&](double q) { return T - 2.0 * q - m * g * (L / 2) * std::sin(q); },
                           0, kPi / 2);

    StaticsOptions tight{.tolerance = 1e-13};
    const ex& q = p.q[0];
    std::vector<ex> roadmap = residuals_of(plan_roadmap(p.sys, p.q, {q}, Analysis::statics));
    Equilibrium a = solve_equilibrium(s, roadmap, {q}, {{q, 0.0}}, {{p.loads[0], T}}, tight);
    EXPECT_NEAR(a.value(q), q_hand, 1e-12);
    EXPECT_LE(a.residual, 1e-13);
    // Kane's generalized active force F_q = 0 gives the same configuration
    std::vector<ex> kane = form_generalized_active_forces(p.sys, p.q);
    Equilibrium b = solve_equilibrium(s, kane, {q}, {{q, 1.0}}, {{p.loads[0], T}}, tight);
    EXPECT_NEAR(b.value(q), q_hand, 1e-12);
}

TEST(Statics, TwoBarBoundsPickTheHangingOrTheInvertedEquilibrium) {
    // with phi1 = q1, phi2 = q1 + q2 the absolute angles, equilibrium needs
    // tan phi1 = 2P/(3 m g) and tan phi2 = 2P/(m g): hanging (both atan), or inverted (both + pi)
    TwoBar t;
    const double P = 2.0, mg = t.value(t.m) * t.value(t.g);
    double phi1 = std::atan(2 * P / (3 * mg)), phi2 = std::atan(2 * P / mg);
    std::vector<ex> E = t.residuals({t.q1, t.q2});
    exmap guess{{t.q1, 1.6}, {t.q2, 0.1}};
    StaticsOptions hanging{.tolerance = 1e-12,
                           .bounds = {{t.q1, -1.5, 1.5}, {t.q2, -1.5, 1.5}}};
    Equilibrium a = solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2}, guess, {{t.P, P}}, hanging);
    EXPECT_NEAR(a.value(t.q1), phi1, 1e-10);
    EXPECT_NEAR(a.value(t.q2), phi2 - phi1, 1e-10);

    StaticsOptions inverted{.tolerance = 1e-12,
                            .bounds = {{t.q1, 1.7, 4.6}, {t.q2, -1.5, 1.5}}};
    Equilibrium b = solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2}, guess, {{t.P, P}}, inverted);
    EXPECT_NEAR(b.value(t.q1), phi1 + kPi, 1e-10);
    EXPECT_NEAR(b.value(t.q2), phi2 - phi1, 1e-10);
}

TEST(Statics, TwoBarWithLockedKneeHasTwoEquilibriaInAngleAndForce) {
    // q2 = 0.3 given, q1 and P unknown: tan(phi1 + q2) = 3 tan phi1, so with a = tan q2,
    // t = tan phi1 = (1 -+ sqrt(1 - 3 a^2)) / (3 a), and P = 3 m g t / 2
    TwoBar t;
    const double q2 = 0.3, a = std::tan(q2), mg = t.value(t.m) * t.value(t.g);
    double r = std::sqrt(1 - 3 * a * a);
    double t_low = (1 - r) / (3 * a), t_high = (1 + r) / (3 * a);
    std::vector<ex> E = t.residuals({t.q1, t.P});
    exmap guess{{t.q1, 0.7}, {t.P, 1.0}};
    StaticsOptions low{.tolerance = 1e-12, .bounds = {{t.q1, 0.0, 0.6}}};
    Equilibrium s1 = solve_equilibrium(t.sys.symbols(), E, {t.q1, t.P}, guess, {{t.q2, q2}}, low);
    EXPECT_NEAR(s1.value(t.q1), std::atan(t_low), 1e-10);
    EXPECT_NEAR(s1.value(t.P), 1.5 * mg * t_low, 1e-9);

    StaticsOptions high{.tolerance = 1e-12, .bounds = {{t.q1, 0.8, 1.5}}};
    Equilibrium s2 = solve_equilibrium(t.sys.symbols(), E, {t.q1, t.P}, guess, {{t.q2, q2}}, high);
    EXPECT_NEAR(s2.value(t.q1), std::atan(t_high), 1e-10);
    EXPECT_NEAR(s2.value(t.P), 1.5 * mg * t_high, 1e-9);
}

TEST(Statics, SignConditionRefusesTheOtherBranch) {
    // the tip above the pivot (y_tip = -L cos phi1 - L cos phi2 > 0) excludes the hanging
    // equilibrium that a guess near it converges to, and accepts the inverted one
    TwoBar t;
    ex y_tip = -t.L * GiNaC::cos(t.q1.symbol()) - t.L * GiNaC::cos(t.q1 + t.q2);
    StaticsOptions up{.tolerance = 1e-12, .conditions = {{y_tip, true, "tip above the pivot"}}};
    std::vector<ex> E = t.residuals({t.q1, t.q2});
    EXPECT_THROW_MSG(solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2}, {{t.q1, 0.2}, {t.q2, 0.1}},
                                       {{t.P, 2.0}}, up),
                     SolveError, "outside the requested branch: condition 'tip above the pivot'");
    Equilibrium b = solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2},
                                      {{t.q1, 3.0}, {t.q2, 0.2}}, {{t.P, 2.0}}, up);
    EXPECT_GT(t.sys.symbols().evaluate(y_tip, b.as_map()), 0);
}

TEST(Statics, NoEquilibriumIsASolveErrorNamingTheLastIterate) {
    // a motor torque larger than the largest gravity moment m g L/2 can hold
    test::Model p = test::make_rod_pendulum();
    const SymbolTable& s = p.sys.symbols();
    const ex& q = p.q[0];
    double mgL2 = *s.value(s.symbol("m")) * *s.value(s.symbol("g")) * *s.value(s.symbol("L")) / 2;
    std::vector<ex> E = residuals_of(plan_roadmap(p.sys, p.q, {q}, Analysis::statics));
    try {
        solve_equilibrium(s, E, {q}, {{q, 0.1}}, {{p.loads[0], 2 * mgL2}});
        ADD_FAILURE() << "expected a SolveError";
    } catch (const SolveError& e) {
        std::string msg = e.what();
        for (const char* part : {"no equilibrium found", "iterations", "last residual", "q = ",
                                 "change the guess"})
            EXPECT_NE(msg.find(part), std::string::npos) << part << " not in: " << msg;
        // the iteration ends where |E| = T - m g (L/2) sin q is least, at q = pi/2
        auto at = msg.find("max|E| = ");
        ASSERT_NE(at, std::string::npos);
        EXPECT_NEAR(std::stod(msg.substr(at + 9)), 2 * mgL2 - mgL2, 1e-4) << msg;
    }
}

TEST(Statics, SingularJacobianIsReported) {
    // at q = pi/2 the gravity moment m g (L/2) sin q is at its peak: dE/dq = 0
    test::Model p = test::make_rod_pendulum();
    const SymbolTable& s = p.sys.symbols();
    const ex& q = p.q[0];
    std::vector<ex> E = residuals_of(plan_roadmap(p.sys, p.q, {q}, Analysis::statics));
    StaticsOptions strict{.least_squares = false};
    EXPECT_THROW_MSG(solve_equilibrium(s, E, {q}, {{q, kPi / 2}}, {{p.loads[0], 1.0}}, strict),
                     SolveError, "singular at iteration 0");
    // from an ordinary guess the same equation solves: sin q = T / (m g L/2)
    Equilibrium e = solve_equilibrium(s, E, {q}, {{q, 0.2}}, {{p.loads[0], 1.0}}, strict);
    double mgL2 = *s.value(s.symbol("m")) * *s.value(s.symbol("g")) * *s.value(s.symbol("L")) / 2;
    EXPECT_NEAR(e.value(q), std::asin(1.0 / mgL2), 1e-10);
}

TEST(Statics, RepeatedBalanceConvergesByLeastSquaresSteps) {
    // the same balance stated twice (x + y = 2 and 2 (x + y) = 2 * 2): the Jacobian is singular
    // everywhere; the minimum-norm step from (0, 0) lands on (1, 1)
    SymbolTable s;
    ex x = s.add_unknown("x"), y = s.add_unknown("y");
    std::vector<ex> E{x + y - 2, 2 * (x + y - 2)};
    Equilibrium e = solve_equilibrium(s, E, {x, y}, {{x, 0.0}, {y, 0.0}});
    EXPECT_GE(e.least_squares_steps, 1);
    EXPECT_NEAR(e.value(x), 1.0, 1e-12);
    EXPECT_NEAR(e.value(y), 1.0, 1e-12);
    EXPECT_THROW_MSG(solve_equilibrium(s, E, {x, y}, {{x, 0.0}, {y, 0.0}}, {},
                                       {.least_squares = false}),
                     SolveError, "rank 1 of 2");
}

TEST(Statics, MissingValueAndBadBoundAreArgumentErrors) {
    TwoBar t;
    std::vector<ex> E = t.residuals({t.q1, t.q2});
    EXPECT_THROW_MSG(solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2}, {}), ArgumentError,
                     "'P' has no value");
    EXPECT_THROW_MSG(solve_equilibrium(t.sys.symbols(), E, {t.q1, t.q2}, {}, {{t.P, 1.0}},
                                       {.bounds = {{t.P, 0, 1}}}),
                     ArgumentError, "names no unknown");
}
