// SPDX-License-Identifier: MIT
// Unknown load measures that the motion determines, in simulate and in solve ... at (issue 24):
// a block with Coulomb friction on an incline whose normal force is unknown, and a rod sliding
// on a frictionless wall and floor with the contact forces unknown in minimal coordinates.
// Every number is checked against a hand derivation written out below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>

#include "support/script_dir.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace unknown_loads_simulate {

namespace {

// a temporary directory named alembert-loads-...
struct TempDir : alembert::test::TempDir {
    TempDir() : alembert::test::TempDir("alembert-loads") {}
};

struct Script {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    explicit Script(const fs::path& dir) { interp.set_output_dir(dir.string()); }
    void run(const std::string& text) {
        ASSERT_EQ(interp.run(text, "test.alb"), RunStatus::ok) << err.str();
    }
    std::string fails(const std::string& text) {
        EXPECT_EQ(interp.run(text, "test.alb"), RunStatus::script_error) << out.str();
        return interp.last_error() ? interp.last_error()->message : "";
    }
    // the value printed as "name = value ..." (the last one)
    double value(const std::string& name) const {
        std::regex re("(^|\\n)" + name + " = (-?[0-9.]+(e[-+]?[0-9]+)?)");
        const std::string text = out.str();
        double v = NAN;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), re);
             it != std::sregex_iterator(); ++it)
            v = std::stod((*it)[2]);
        return v;
    }
};

// The block B (a particle: no inertia) slides along Sx> on an incline S turned by -beta about
// Nz, pressed on it by the unknown normal force Fn Sy> and braked by Coulomb friction
// -mu |Fn| csgn(x') Sx>. Gravity -m g Ny> has Sx> part m g sin(beta) (down the slope is +x,
// since Sx> = cos(beta) Nx> - sin(beta) Ny>) and Sy> part -m g cos(beta). By hand:
//   along Sy> (no motion): Fn - m g cos(beta) = 0           =>  Fn = m g cos(beta)
//   along Sx>:  m g sin(beta) - mu |Fn| csgn(x') = m x''    =>  x'' = g (sin(beta) - mu cos(beta) csgn(x'))
const std::string kBlock =
    "newtonian N\nbody B\nframe S\nvariable x''\n"
    "constant m = 2 kg, g = 9.81 m/s^2, mu = 0.3, beta = 30 deg\nunknown Fn N\ncoordinates x\n"
    "rotate S from N about z by -beta\nrotate B from S about z by 0\n"
    "translate B_o from N_o by x*Sx>\ntranslate Bcm from B_o by 0>\nmass B = m\n"
    "inertia B = 0, 0, 0\ngravity -g*Ny>\nforce normal on B_o = Fn*Sy>\n"
    "friction f on B_o from N_o coefficient mu normal Fn along Sx>\nroadmap V for x'', Fn\n"
    "tolerance abs 1e-12 rel 1e-12\n";
constexpr double m = 2, g = 9.81, mu = 0.3;
const double beta = 30 * std::numbers::pi / 180;

// The rod A of length L slides with its foot A_o on the floor (Ny> up) and its top A_w on the
// wall, turned by q from the upright; only q is a coordinate, the wall and floor forces N_w Nx>
// and N_f Ny> are unknowns (tests/eom/contact_rows_test.cpp derives the rows). By hand:
//   about the instantaneous centre: q'' = 3 g sin(q) / (2 L)
//   Acm = (L/2 sin q, L/2 cos q): a_x = L/2 (q'' cos q - q'^2 sin q), a_y = -L/2 (q'' sin q + q'^2 cos q)
//   F = m a: N_w = m a_x,  N_f = m g + m a_y.
// From rest at q0, energy: (m L^2/6) q'^2 = m g L/2 (cos q0 - cos q), q'^2 = 3 g (cos q0 - cos q) / L,
// so N_w = (3 m g / 4) sin q (3 cos q - 2 cos q0): the rod leaves the wall where
// cos q = (2/3) cos q0, the wall force having to pull beyond it.
const std::string kRod =
    "newtonian N\nbody A\npoint A_w on A\nvariable q''\n"
    "constant m = 2.5 kg, L = 1.3 m, g = 9.81 m/s^2\nunknown N_w N, N_f N\ncoordinates q\n"
    "rotate A from N about z by q\ntranslate A_o from N_o by L*sin(q)*Nx>\n"
    "translate Acm from A_o by L/2*Ay>\ntranslate A_w from A_o by L*Ay>\nmass A = m\n"
    "inertia A = 0, 0, m*L^2/12\ngravity -g*Ny>\nforce Nw on A_w = N_w*Nx>\n"
    "force Nf on A_o = N_f*Ny>\ntolerance abs 1e-12 rel 1e-12\n";
constexpr double m_rod = 2.5, L = 1.3;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// ---- the block on the incline ----------------------------------------------------------

TEST(UnknownLoadsSimulate, ABlockSlidingDownBrakesByFrictionFromItsSolvedNormalForce) {
    // x' > 0 throughout: x(t) = v0 t + a t^2 / 2, x' = v0 + a t, a = g (sin(beta) - mu cos(beta));
    // before, Fn was set to 0 and the block slid at g sin(beta) with Fn = 0 written
    TempDir dir;
    Script r(dir.path);
    r.run(kBlock + "initial x = 0, x' = 1\noutput x, x', Fn\nfinal time 0.5 s\n"
                   "output step 0.1 s\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_EQ(t.row_count(), 6u);
    const double v0 = 1, a = g * (std::sin(beta) - mu * std::cos(beta));
    const std::size_t cx = t.column_index("x"), cv = t.column_index("x'"), cf = t.column_index("Fn");
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double tk = t.columns[0][k];
        EXPECT_NEAR(t.columns[cx][k], v0 * tk + a * tk * tk / 2, 1e-9) << "t = " << tk;
        EXPECT_NEAR(t.columns[cv][k], v0 + a * tk, 1e-9) << "t = " << tk;
        EXPECT_NEAR(t.columns[cf][k], m * g * std::cos(beta), 1e-9) << "t = " << tk;
    }
    // friction does work: no energy column claims the model conservative
    EXPECT_FALSE(std::count(t.names.begin(), t.names.end(), "energy"));
}

TEST(UnknownLoadsSimulate, SolveAtTakesTheRowOfFnFirstThenTheRowOfXdd) {
    // the rows are not linear together (|Fn|) but each is once the one before is solved:
    // Fn = m g cos(beta), then x'' = g (sin(beta) - mu cos(beta) csgn(x'))
    TempDir dir;
    Script r(dir.path);
    r.run(kBlock + "digits 17\nsolve V for x'', Fn at x = 0, x' = 1\n");
    const double Fn = m * g * std::cos(beta);
    EXPECT_NEAR(r.value("Fn"), Fn, 1e-12 * Fn);
    const double down = g * (std::sin(beta) - mu * std::cos(beta));
    EXPECT_NEAR(r.value("x''"), down, 1e-12 * std::abs(down));
    Script up(dir.path);
    up.run(kBlock + "digits 17\nsolve V for Fn, x'' at x = 0, x' = -1\n");
    const double rising = g * (std::sin(beta) + mu * std::cos(beta));
    EXPECT_NEAR(up.value("x''"), rising, 1e-12 * rising);
    EXPECT_NEAR(up.value("Fn"), Fn, 1e-12 * Fn);
}

TEST(UnknownLoadsSimulate, ABlockPushedUpDeceleratesByGravityAndFrictionUntilItStops) {
    // x' = -v0 < 0 (up the slope): friction acts down the slope with gravity,
    // a = g (sin(beta) + mu cos(beta)); x' = -v0 + a t reaches 0 at t* = v0 / a,
    // where x = -v0^2 / (2 a); the run is stopped there by the stop condition
    TempDir dir;
    Script r(dir.path);
    const double v0 = 1.5, a = g * (std::sin(beta) + mu * std::cos(beta)), ts = v0 / a;
    r.run(kBlock + "initial x = 0, x' = -1.5\noutput x, x', Fn\nfinal time 1 s\n"
                   "output step 0.05 s\nstop when x' = 0 m/s rising\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    const std::size_t cx = t.column_index("x"), cv = t.column_index("x'"), cf = t.column_index("Fn");
    ASSERT_GE(t.row_count(), 5u);
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double tk = t.columns[0][k];
        EXPECT_LE(tk, ts + 1e-9);
        EXPECT_NEAR(t.columns[cx][k], -v0 * tk + a * tk * tk / 2, 1e-9) << "t = " << tk;
        EXPECT_NEAR(t.columns[cv][k], -v0 + a * tk, 1e-9) << "t = " << tk;
        EXPECT_NEAR(t.columns[cf][k], m * g * std::cos(beta), 1e-9) << "t = " << tk;
    }
    EXPECT_NEAR(t.columns[0].back(), ts, 1e-9);
    EXPECT_NEAR(t.columns[cx].back(), -v0 * v0 / (2 * a), 1e-9);
}

// ---- the rod on the wall and the floor ---------------------------------------------------

TEST(UnknownLoadsSimulate, ARodsWallAndFloorForcesFollowNewtonsLawAtEveryRowUntilItLeavesTheWall) {
    TempDir dir;
    Script r(dir.path);
    const double q0 = 0.2;
    const std::string message =
        r.fails(kRod + "initial q = 0.2 rad\nfinal time 3 s\noutput step 0.02 s\n"
                       "output q, q', N_w, N_f\nsimulate\n");
    // the run stops where N_w changes sign, naming it and the time
    EXPECT_TRUE(has(message, "'N_w' changes sign at t = ")) << message;
    EXPECT_TRUE(has(message, "the contact is lost")) << message;
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_GE(t.row_count(), 10u);
    const std::size_t cq = t.column_index("q"), cv = t.column_index("q'"),
                      cw = t.column_index("N_w"), cf = t.column_index("N_f");
    const double scale = m_rod * g;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double q = t.columns[cq][k], qd = t.columns[cv][k];
        const double qdd = 3 * g * std::sin(q) / (2 * L);
        const double Nw = m_rod * L / 2 * (qdd * std::cos(q) - qd * qd * std::sin(q));
        const double Nf = m_rod * g - m_rod * L / 2 * (qdd * std::sin(q) + qd * qd * std::cos(q));
        EXPECT_NEAR(t.columns[cw][k], Nw, 1e-10 * std::max(std::abs(Nw), scale)) << "q = " << q;
        EXPECT_NEAR(t.columns[cf][k], Nf, 1e-10 * std::max(std::abs(Nf), scale)) << "q = " << q;
        // the state itself, from the energy: q'^2 = 3 g (cos q0 - cos q) / L
        EXPECT_NEAR(qd * qd, 3 * g * (std::cos(q0) - std::cos(q)) / L, 1e-9) << "q = " << q;
        if (k + 1 < t.row_count()) {
            EXPECT_GT(t.columns[cw][k], 0.0) << "q = " << q;
        }
    }
    // the last row is where the rod leaves the wall: cos q = (2/3) cos q0, N_w = 0
    EXPECT_NEAR(std::cos(t.columns[cq].back()), 2.0 / 3.0 * std::cos(q0), 1e-9);
    EXPECT_NEAR(t.columns[cw].back(), 0.0, 1e-9 * scale);
}

TEST(UnknownLoadsSimulate, AnIdleMotorTorqueStaysZeroAndAWorklessUndeterminedLoadIsRefused) {
    // a motor torque that is given no input does work: it is an applied load, 0 by default,
    // and the pendulum keeps its energy; a push P at the fixed pin does no work and no row
    // determines it, so an output of it is refused rather than written as 0
    const std::string pendulum =
        "newtonian N\nbody A\nconstant L = 0.5 m, m = 2 kg, g = 9.81 m/s^2\nvariable q''\n"
        "unknown T_A N*m, P N\nrotate A from N about z by q\ntranslate A_o from N_o by 0>\n"
        "translate Acm from A_o by -L*Ay>\nmass A = m\ninertia A = 0, 0, m*L^2/12\n"
        "gravity -g*Ny>\ntorque T_A on A from N = T_A*Nz>\nforce push on A_o = P*Nx>\n"
        "initial q = 0.3\nfinal time 0.2 s\noutput step 0.1 s\n";
    TempDir dir;
    Script idle(dir.path);
    idle.run(pendulum + "output q, T_A\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    for (double v : t.columns[t.column_index("T_A")]) EXPECT_EQ(v, 0.0);
    Script push(dir.path);
    const std::string message = push.fails(pendulum + "output q, P\nsimulate\n");
    EXPECT_TRUE(has(message, "'P' is read by an output or a stop condition, but it does no work"))
        << message;
}

}  // namespace unknown_loads_simulate
