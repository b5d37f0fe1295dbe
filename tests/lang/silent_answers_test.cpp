// SPDX-License-Identifier: MIT
// Answers that once came out wrong without a word (issue 24), each checked against a hand
// derivation: joint reactions in simulate's table, rates in Hz, loads that a motion does not
// determine, and motions that the listed loads cannot make.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>

#include "support/script_dir.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace silent_answers {

namespace {

// a temporary directory named alembert-silent-...
struct TempDir : alembert::test::TempDir {
    TempDir() : alembert::test::TempDir("alembert-silent") {}
};

struct Script {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    explicit Script(const fs::path& dir) { interp.set_output_dir(dir.string()); }
    void run(const std::string& text) {
        ASSERT_EQ(interp.run(text, "test.alb"), RunStatus::ok) << err.str();
    }
    // the error message of a script that must fail
    std::string fails(const std::string& text) {
        EXPECT_EQ(interp.run(text, "test.alb"), RunStatus::script_error) << out.str();
        return interp.last_error() ? interp.last_error()->message : "";
    }
};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// a particle of mass m at distance L below a pin at N_o, on a massless rod A turned by q about
// Nz, with the pin's force on A declared as a reaction R = Rx Nx + Ry Ny
const std::string kPendulum =
    "newtonian N\nbody A\nconstant m = 2 kg, L = 1 m, g = 9.81 m/s^2\nvariable q''\n"
    "unknown Rx N, Ry N\nrotate A from N about z by q\ntranslate A_o from N_o by 0>\n"
    "translate Acm from A_o by -L*Ay>\nmass A = m\ninertia A = 0, 0, 0\ngravity -g*Ny>\n"
    "reaction pin between N and A at A_o force Rx along Nx>, Ry along Ny>\n";
constexpr double m = 2, L = 1, g = 9.81;

}  // namespace

// ---- reactions in simulate's table ------------------------------------------------------

TEST(SilentAnswers, APendulumHangingAtRestWritesItsWeightAsThePinForceInEveryRow) {
    // at rest, R - m g Ny = 0: Rx = 0, Ry = m g = 19.62 N (it used to be written as 0)
    TempDir dir;
    Script r(dir.path);
    r.run(kPendulum + "final time 1 s\noutput step 0.25 s\noutput q, Rx, Ry\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_EQ(t.row_count(), 5u);
    const std::size_t rx = t.column_index("Rx"), ry = t.column_index("Ry");
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        EXPECT_EQ(t.columns[t.column_index("q")][k], 0.0);
        EXPECT_NEAR(t.columns[rx][k], 0.0, 1e-12);
        EXPECT_NEAR(t.columns[ry][k], m * g, 1e-12);
    }
}

TEST(SilentAnswers, ASwingingPendulumWritesThePinForceOfNewtonsLawAtEverySample) {
    // the particle at r = L sin q Nx - L cos q Ny has
    //   a = L q'' (cos q Nx + sin q Ny) + L q'^2 (-sin q Nx + cos q Ny),  q'' = -(g/L) sin q,
    // and R = m a + m g Ny:
    //   Rx = m L (q'' cos q - q'^2 sin q),  Ry = m L (q'' sin q + q'^2 cos q) + m g;
    // along the rod (Ay, towards the pin) R.Ay = m g cos q + m L q'^2, across it R.Ax = 0
    TempDir dir;
    Script r(dir.path);
    r.run(kPendulum +
          "initial q = 60 deg\nfinal time 2 s\noutput step 0.1 s\ntolerance abs 1e-12 rel 1e-12\n"
          "output q, q', Rx, Ry\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_EQ(t.row_count(), 21u);
    const auto& Q = t.columns[t.column_index("q")];
    const auto& W = t.columns[t.column_index("q'")];
    const auto& Rx = t.columns[t.column_index("Rx")];
    const auto& Ry = t.columns[t.column_index("Ry")];
    double largest_speed = 0;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double q = Q[k], w = W[k], a = -(g / L) * std::sin(q);
        SCOPED_TRACE("t = " + std::to_string(t.columns[0][k]));
        EXPECT_NEAR(Rx[k], m * L * (a * std::cos(q) - w * w * std::sin(q)), 1e-12);
        EXPECT_NEAR(Ry[k], m * L * (a * std::sin(q) + w * w * std::cos(q)) + m * g, 1e-12);
        EXPECT_NEAR(-Rx[k] * std::sin(q) + Ry[k] * std::cos(q), m * g * std::cos(q) + m * L * w * w, 1e-12);
        EXPECT_NEAR(Rx[k] * std::cos(q) + Ry[k] * std::sin(q), 0.0, 1e-12);
        largest_speed = std::max(largest_speed, std::abs(w));
    }
    EXPECT_GT(largest_speed, 2.0);  // it swings: the q'^2 term is tested, not only the weight
}

TEST(SilentAnswers, ATubeTurnedAtAPrescribedRateWritesTheWallsPushOnTheBead) {
    // a bead P (mass mP) free in a tube A turned by theta = w t about the vertical Nz>: from
    // rest at r0 along the tube, r = r0 cosh(w t), r' = r0 w sinh(w t); across the tube the
    // wall pushes N_y = mP (r theta'' + 2 r' theta') = 2 mP w r' (Coriolis), and up N_z = mP g
    // (both were written as 0 by simulate)
    TempDir dir;
    Script r(dir.path);
    r.run("newtonian N\nbody A\nparticle P\nvariable r''\nspecified theta''\n"
          "constant mP = 0.3 kg, IA = 0.1 kg*m^2, w = 2 rad/s, g = 9.81 m/s^2\nunknown N_y N, N_z N\n"
          "rotate A from N about z by theta\ntranslate Acm from N_o by 0>\ntranslate P from N_o by r*Ax>\n"
          "mass A = 1 kg\ninertia A = 0, 0, IA\nmass P = mP\ngravity -g*Nz>\n"
          "force wall on P = N_y*Ay> + N_z*Nz>\nmotion theta = w*t\ninitial r = 0.1\nfinal time 1 s\n"
          "output step 0.125 s\ntolerance abs 1e-12 rel 1e-12\noutput r, r', N_y, N_z\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_EQ(t.row_count(), 9u);
    const double mP = 0.3, w = 2, r0 = 0.1;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double time = t.columns[0][k];
        SCOPED_TRACE("t = " + std::to_string(time));
        const double rd = r0 * w * std::sinh(w * time);
        EXPECT_NEAR(t.columns[t.column_index("r")][k], r0 * std::cosh(w * time), 1e-9);
        EXPECT_NEAR(t.columns[t.column_index("r'")][k], rd, 1e-9);
        // the wall's push from the row's own r' (the integrator's, not the exact one)
        EXPECT_NEAR(t.columns[t.column_index("N_y")][k], 2 * mP * w * t.columns[t.column_index("r'")][k], 1e-12);
        EXPECT_NEAR(t.columns[t.column_index("N_z")][k], mP * g, 1e-12);
    }
    EXPECT_GT(t.columns[t.column_index("N_y")].back(), 0.8);  // the Coriolis push is tested, not 0
}

TEST(SilentAnswers, APendulumOnADrivenPivotWritesThePinForceOfNewtonsLaw) {
    // a particle pendulum (mass m, length L) hanging from a cart C whose position x = A sin(W t)
    // is prescribed; with the bob at (x + L sin q, -L cos q):
    //   q'' = -(g sin q + x'' cos q)/L,
    //   R = m a + m g Ny:  Rx = m (x'' + L (q'' cos q - q'^2 sin q)),
    //                      Ry = m L (q'' sin q + q'^2 cos q) + m g
    TempDir dir;
    Script r(dir.path);
    r.run("newtonian N\nbody C, A\nvariable q''\nspecified x''\n"
          "constant m = 2 kg, L = 1 m, g = 9.81 m/s^2, Am = 0.1 m, W = 3 rad/s\nunknown Rx N, Ry N\n"
          "rotate C from N about z by 0\nrotate A from N about z by q\ntranslate C_o from N_o by x*Nx>\n"
          "translate Ccm from C_o by 0>\ntranslate A_o from C_o by 0>\ntranslate Acm from A_o by -L*Ay>\n"
          "mass C = 5 kg; mass A = m\ninertia C = 0, 0, 0; inertia A = 0, 0, 0\ngravity -g*Ny>\n"
          "reaction pin between C and A at A_o force Rx along Nx>, Ry along Ny>\nmotion x = Am*sin(W*t)\n"
          "initial q = 30 deg\nfinal time 2 s\noutput step 0.1 s\noutput q, q', Rx, Ry\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    ASSERT_EQ(t.row_count(), 21u);
    const double Am = 0.1, W = 3;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double time = t.columns[0][k], q = t.columns[t.column_index("q")][k],
                     qd = t.columns[t.column_index("q'")][k];
        SCOPED_TRACE("t = " + std::to_string(time));
        const double xdd = -Am * W * W * std::sin(W * time), qdd = -(g * std::sin(q) + xdd * std::cos(q)) / L;
        EXPECT_NEAR(t.columns[t.column_index("Rx")][k], m * (xdd + L * (qdd * std::cos(q) - qd * qd * std::sin(q))),
                    1e-10);
        EXPECT_NEAR(t.columns[t.column_index("Ry")][k], m * L * (qdd * std::sin(q) + qd * qd * std::cos(q)) + m * g,
                    1e-10);
    }
}

// ---- output columns ---------------------------------------------------------------------

TEST(SilentAnswers, AnOutputNamedLikeACoordinateMustHoldThatCoordinate) {
    TempDir dir;
    Script r(dir.path);
    r.run(kPendulum);
    const std::string e = r.fails("output q = 2*q\n");
    EXPECT_TRUE(has(e, "the output column 'q' would hold 2*q, not q")) << e;
    // the same expression under its own name, and the coordinate under its own, are fine
    r.run("output q_twice = 2*q, q = q in deg\n");
}

// ---- units ------------------------------------------------------------------------------

TEST(SilentAnswers, OneHertzIsOneRevolutionPerSecondAsSixtyRpmIs) {
    TempDir dir;
    Script r(dir.path);
    r.run("digits 17\nnewtonian N\nconstant f = 1 Hz, n = 60 rpm, v = 1 rev/s, w = 2*pi rad/s\n"
          "evaluate f - n\nevaluate f - v\nevaluate f - w\nevaluate f\n");
    const std::string out = r.out.str();
    EXPECT_TRUE(has(out, "= 0 1/s\n= 0 1/s\n= 0 1/s\n= 6.2831853071795862 1/s")) << out;
    // 2*pi beside a rate in Hz would count the cycle twice
    const std::string e = r.fails("x = sin(2*pi*f*t)\n");
    EXPECT_TRUE(has(e, "'f' is a rate in revolutions")) << e;
    r.run("x = sin(f*t)\nevaluate x at t = 0.25 s\n");
    EXPECT_TRUE(has(r.out.str(), "= 1\n")) << r.out.str();  // a quarter turn at one turn per second
}

TEST(SilentAnswers, AFiltersCutoffInHertzCountsCyclesPerSecond) {
    // the same motion table filtered at 6 Hz, at 360 rpm and at a bare 6: the same torques
    TempDir dir;
    Script r(dir.path);
    const std::string data =
        (fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand_inverse/motion.csv").string();
    std::string model;
    {
        std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/model.alb");
        std::string line;
        while (std::getline(in, line) && line.rfind("angvel", 0) != 0) model += line + "\n";
    }
    r.run(model + "inverse for T_A, T_B, T_C from \"" + data + "\" cutoff 6 Hz tape to \"hz\"\n" +
          "inverse for T_A, T_B, T_C from \"" + data + "\" cutoff 360 rpm tape to \"rpm\"\n" +
          "inverse for T_A, T_B, T_C from \"" + data + "\" cutoff 6 tape to \"bare\"\n");
    alembert::Table hz = alembert::read_csv((dir.path / "hz/torques.csv").string());
    alembert::Table rpm = alembert::read_csv((dir.path / "rpm/torques.csv").string());
    alembert::Table bare = alembert::read_csv((dir.path / "bare/torques.csv").string());
    ASSERT_EQ(hz.row_count(), bare.row_count());
    ASSERT_EQ(hz.row_count(), rpm.row_count());
    for (std::size_t k = 0; k < hz.row_count(); ++k) {
        EXPECT_NEAR(hz.columns[1][k], bare.columns[1][k], 1e-9 * (1 + std::abs(bare.columns[1][k])));
        EXPECT_NEAR(rpm.columns[1][k], bare.columns[1][k], 1e-9 * (1 + std::abs(bare.columns[1][k])));
    }
}

// ---- inverse dynamics -------------------------------------------------------------------

namespace {

// a rod A turned by q1 about Nz, its mass centre at L along Ax, driven by a torque T1 cos(q1):
// about the pin, T1 cos q1 - m g L cos q1 - I q1'' = 0 (I = m L^2 about the pin), so at a
// steady rate T1 = m g L = 19.62 N*m, and where cos q1 = 0 nothing determines T1
const std::string kCrank =
    "newtonian N\nbody A\nconstant m = 2 kg, L = 1 m, g = 9.81 m/s^2\nvariable q1''\n"
    "constant w1 = 60 deg/s, w2 = 180 deg/s\nunknown T1 N*m\nrotate A from N about z by q1\ntranslate A_o from N_o by 0>\n"
    "translate Acm from A_o by L*Ax>\nmass A = m\ninertia A = 0, 0, 0\ngravity -g*Ny>\n"
    "torque drive on A from N = T1*cos(q1)*Nz>\n";

}  // namespace

TEST(SilentAnswers, ATorqueWhoseCoefficientVanishesAtASampleIsNotDeterminedThere) {
    TempDir dir;
    Script r(dir.path);
    // away from 90 deg: T1 = m g L at every sample
    r.run(kCrank + "motion q1 = w1*t\nfinal time 1 s\noutput step 0.1 s\ninverse for T1 to \"away\"\n");
    alembert::Table t = alembert::read_csv((dir.path / "away/torques.csv").string());
    ASSERT_EQ(t.row_count(), 11u);
    for (double T : t.columns[1]) EXPECT_NEAR(T, m * g * L, 1e-12);
    // through 90 deg at t = 0.5 s: cos q1 is 6e-17 there, zero against its size 1
    const std::string e = r.fails("motion q1 = w2*t\ninverse for T1 to \"through\"\n");
    EXPECT_TRUE(has(e, "the load measures T1 are not determined at 1 of 11 samples: t = 0.5 s (sample 6)")) << e;
    EXPECT_TRUE(has(e, "T1 is not determined: its coefficient in its equation is")) << e;
    EXPECT_FALSE(fs::exists(dir.path / "through/torques.csv"));
}

namespace {

// a cart C (mass M) on Nx pushed by F, with a rod R (mass mr, length Lr, inertia mr Lr^2/12
// about its centre) pinned at the cart and turned by th from the upright. Kane's equation
// for th: (mr Lr/2) (g sin th + x'' cos th) - (mr Lr^2/3) th'' = 0; for x:
// F = (M + mr) x'' + (mr Lr/2)(-th'' cos th + th'^2 sin th)
const std::string kCart =
    "newtonian N\nparticle C\nbody R\nconstant M = 2 kg, mr = 0.5 kg, Lr = 1 m, g = 9.81 m/s^2\n"
    "constant a = 1 m/s^2\nvariable x'' m, th''\nunknown F N\ntranslate C from N_o by x*Nx>\n"
    "rotate R from N about z by th\ntranslate R_o from C by 0>\ntranslate Rcm from R_o by Lr/2*Ry>\n"
    "mass C = M\nmass R = mr\ninertia R = 0, 0, mr*Lr^2/12\ngravity -g*Ny>\n"
    "force push on C = F*Nx>\nfinal time 1 s\noutput step 0.25 s\n";
constexpr double M = 2, mr = 0.5, Lr = 1, acc = 1;

}  // namespace

TEST(SilentAnswers, AnUnderActuatedMotionThatTheRodsEquationAllowsGivesThePush) {
    // x = a t^2/2 with the rod leaning at tan th = -a/g holds the rod's equation: F = (M + mr) a
    TempDir dir;
    Script r(dir.path);
    r.run(kCart + "motion x = a*t^2/2, th = -atan(a/g)\ninverse for F\n");
    alembert::Table t = alembert::read_csv((dir.path / "forces.csv").string());
    ASSERT_EQ(t.row_count(), 5u);
    for (double F : t.columns[1]) EXPECT_NEAR(F, (M + mr) * acc, 1e-12);
}

TEST(SilentAnswers, AnUnderActuatedMotionThatBreaksTheRodsEquationIsRefusedNamingIt) {
    // held upright (th = 0) while the cart accelerates: the rod's equation is off by
    // mr Lr a / 2 = 0.25 N*m at every sample, and no push F makes that motion
    TempDir dir;
    Script r(dir.path);
    const std::string e = r.fails(kCart + "motion x = a*t^2/2, th = 0\ninverse for F\n");
    EXPECT_TRUE(has(e, "the motion does not satisfy Kane's equation for th, which the loads F were "
                       "not solved from, at 5 of 5 samples")) << e;
    EXPECT_TRUE(has(e, "its largest residual is 0.25 (SI)") || has(e, "its largest residual is -0.25 (SI)")) << e;
    EXPECT_FALSE(fs::exists(dir.path / "forces.csv"));
    EXPECT_EQ(mr * Lr * acc / 2, 0.25);
}

}  // namespace silent_answers
