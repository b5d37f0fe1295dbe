// SPDX-License-Identifier: MIT
// Contact loads solved with the accelerations (run_simulation, find_contact_loads) and the
// block-by-block numeric solve, against hand derivations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sim/block_solve.hpp"
#include "alembert/sim/contact_loads.hpp"
#include "alembert/sim/simulation.hpp"
#include "support/expect.hpp"

using namespace alembert;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace contact_loads_test {

namespace {

// A block (mass m, no inertia) sliding by x along Sx> of an incline S turned by -beta about Nz,
// pressed by Fn Sy> and braked by Coulomb friction -mu |Fn| csgn(x') Sx>. By hand (F = m a along
// Sy> and Sx>, with Sx> = cos(beta) Nx> - sin(beta) Ny>):
//   Fn = m g cos(beta),   x'' = g (sin(beta) - mu cos(beta) csgn(x')).
struct Block {
    static constexpr double m = 2, g = 9.81, mu = 0.3, beta = std::numbers::pi / 6;
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x");
    ex Fn = s.add_unknown("Fn"), P = s.add_unknown("P");
    // side = -1 declares the normal force as -Fn Sy> (Fn < 0 in contact); a pull P Sy> is
    // given by an input when a test needs one (zero otherwise: an applied load)
    explicit Block(int side = 1) {
        const Frame& N = sys.newtonian();
        Frame& S = sys.add_frame("S");
        S.orient_axis(N, Axis::z, -s.add_constant("beta", beta));
        RigidBody& B = sys.add_rigid_body("B");
        B.body_frame().orient_axis(S, Axis::z, 0);
        sys.point("B_o").set_pos(sys.origin(), x.symbol() * S.x());
        B.cm().set_pos(sys.point("B_o"), Vector{});
        B.set_mass(s.add_constant("m", m));
        B.set_inertia(B.cm(), 0, 0, 0);
        sys.set_gravity(-s.add_constant("g", g) * N.y());
        sys.add_force(sys.point("B_o"), side * Fn * S.y(), "normal");
        sys.add_force(sys.point("B_o"), P * S.y(), "pull");
        sys.add_coulomb_friction(sys.point("B_o"), sys.origin(), s.add_constant("mu", mu), Fn,
                                 S.x(), "f");
    }
};

}  // namespace

TEST(ContactLoads, AFrictionsNormalForceIsFoundAndSolvedWithTheAcceleration) {
    Block b;
    const ContactLoads found = find_contact_loads(b.sys, {b.x}, {}, {}, {}, "test: ");
    ASSERT_EQ(found.measures.size(), 1u);
    EXPECT_TRUE(found.measures[0].is_equal(b.Fn));
    ASSERT_EQ(found.abs_arguments.size(), 1u);
    EXPECT_TRUE(found.abs_arguments[0].is_equal(b.Fn));
    // given by an input, it is not solved for
    EXPECT_TRUE(find_contact_loads(b.sys, {b.x}, {}, {{b.Fn, ex(3)}}, {}, "test: ").measures.empty());

    SimulationRequest r;
    r.model = "block";
    r.coordinates = {b.x};
    r.initial_values = {{b.x.d(1), 0.5}};
    r.outputs = {{"Fn", b.Fn, "N"}, {"x", b.x.symbol(), "m"}};
    r.options = {.t_final = 0.4, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12,
                 .progress = false};
    const SimulationResult res = run_simulation(b.sys, r);
    EXPECT_FALSE(res.recursive);
    EXPECT_TRUE(res.contact_lost.empty());
    const double a = Block::g * (std::sin(Block::beta) - Block::mu * std::cos(Block::beta));
    ASSERT_EQ(res.table.row_count(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        const double t = res.table.columns[0][k];
        EXPECT_NEAR(res.table.columns[1][k], Block::m * Block::g * std::cos(Block::beta), 1e-9);
        EXPECT_NEAR(res.table.columns[2][k], 0.5 * t + a * t * t / 2, 1e-9);
    }
}

TEST(ContactLoads, ANormalForceDeclaredTheOtherWayIsSolvedWithItsSignAssumedNegative) {
    // -Fn Sy> presses the block: along Sy> -Fn - m g cos(beta) = 0, Fn = -m g cos(beta); the
    // friction -mu |Fn| csgn(x') is the same, so x'' = g (sin(beta) - mu cos(beta)) for x' > 0
    Block b(-1);
    SimulationRequest r;
    r.model = "block";
    r.coordinates = {b.x};
    r.initial_values = {{b.x.d(1), 0.5}};
    r.outputs = {{"Fn", b.Fn, "N"}, {"x", b.x.symbol(), "m"}};
    r.options = {.t_final = 0.4, .output_step = 0.1, .abs_tol = 1e-12, .rel_tol = 1e-12,
                 .progress = false};
    const SimulationResult res = run_simulation(b.sys, r);
    const double a = Block::g * (std::sin(Block::beta) - Block::mu * std::cos(Block::beta));
    ASSERT_EQ(res.table.row_count(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        const double t = res.table.columns[0][k];
        EXPECT_NEAR(res.table.columns[1][k], -Block::m * Block::g * std::cos(Block::beta), 1e-9);
        EXPECT_NEAR(res.table.columns[2][k], 0.5 * t + a * t * t / 2, 1e-9);
    }
}

TEST(ContactLoads, APullThatLiftsTheBlockOffTheInclineEndsTheRunWhereFnReachesZero) {
    // a pull P = k t along Sy>: Fn = m g cos(beta) - k t, zero at t* = m g cos(beta) / k;
    // before it, x'' = g sin(beta) - mu (g cos(beta) - k t / m) (x' > 0), so
    //   x = v0 t + g (sin(beta) - mu cos(beta)) t^2 / 2 + mu k t^3 / (6 m)
    Block b;
    const double k = 40, v0 = 0.5, m = Block::m, g = Block::g, mu = Block::mu, be = Block::beta;
    SimulationRequest r;
    r.model = "lifted";
    r.coordinates = {b.x};
    r.inputs = {{b.P, k * b.s.time()}};
    r.initial_values = {{b.x.d(1), v0}};
    r.outputs = {{"Fn", b.Fn, "N"}, {"x", b.x.symbol(), "m"}};
    r.options = {.t_final = 1.0, .output_step = 0.05, .abs_tol = 1e-12, .rel_tol = 1e-12,
                 .progress = false};
    const SimulationResult res = run_simulation(b.sys, r);
    const double ts = m * g * std::cos(be) / k;
    EXPECT_NEAR(res.t_end, ts, 1e-9);
    EXPECT_NE(res.contact_lost.find("'Fn' changes sign at t = "), std::string::npos) << res.contact_lost;
    for (std::size_t row = 0; row < res.table.row_count(); ++row) {
        const double t = res.table.columns[0][row];
        EXPECT_NEAR(res.table.columns[1][row], m * g * std::cos(be) - k * t, 1e-9);
        EXPECT_NEAR(res.table.columns[2][row],
                    v0 * t + g * (std::sin(be) - mu * std::cos(be)) * t * t / 2 + mu * k * t * t * t / (6 * m),
                    1e-9);
    }
}

TEST(ContactLoads, IdleMotorsReadByAnOutputKeepTheTreeRecursion) {
    // the triple pendulum's joint torques are given no law: applied loads (they do work), zero,
    // not contact loads; the run stays on the articulated-body recursion
    SampleModel m = make_triple_pendulum();
    SimulationRequest r;
    r.model = "idle";
    r.coordinates = m.q;
    r.initial_values = {{m.q[0].symbol(), 0.3}};
    r.outputs = {{"T_A", m.unknowns[0], "N*m"}};
    r.options = {.t_final = 0.2, .output_step = 0.1, .progress = false};
    const SimulationResult res = run_simulation(m.system, r);
    EXPECT_TRUE(res.recursive);
    for (double v : res.table.columns[1]) EXPECT_EQ(v, 0.0);
}

TEST(ContactLoads, BlocksSolvedOneAfterAnother) {
    // a - 2 = 0 gives a = 2; then b |a| csgn(c) - 6 = 0 at c = 1 gives b = 3: not linear in
    // (a, b) together, linear in b once a is a number; the order of the residuals is free
    SymbolTable s;
    const ex a = s.add_unknown("a"), b = s.add_unknown("b"), c = s.add_constant("c");
    const std::vector<ex> residuals{b * GiNaC::abs(a) * GiNaC::csgn(c) - 6, a - 2};
    const Eigen::VectorXd x = solve_numeric_in_blocks(s, residuals, {a, b}, {{c, 1}});
    EXPECT_NEAR(x(0), 2, 1e-15);
    EXPECT_NEAR(x(1), 3, 1e-15);
    // a b - 1 = 0, a + b - 3 = 0 hold both unknowns each: no block of one, and not linear
    EXPECT_THROW_MSG(solve_numeric_in_blocks(s, {a * b - 1, a + b - 3}, {a, b}, {}), SolveError,
                     "not linear in '");
}

}  // namespace contact_loads_test
