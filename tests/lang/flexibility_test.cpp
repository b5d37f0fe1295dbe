// SPDX-License-Identifier: MIT
// The language's flexibility against hand results: numbers with units inside expressions,
// time inside functions, positive constants, US customary units on a textbook case, specified
// quantities driven in simulate (a base-excited oscillator against its closed-form response),
// declarations before newtonian, angular velocity given in any frame (addition theorem), and
// constants given a new value in a session.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <unistd.h>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace flexibility_lang_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

struct Dir {
    fs::path path;
    Dir() {
        std::string t = (fs::temp_directory_path() / "alembert-flex-XXXXXX").string();
        path = ::mkdtemp(t.data());
    }
    ~Dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

struct ScriptSession {
    Dir dir;
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    ScriptSession() { interp.set_output_dir(dir.path.string()); }
    std::string ok(const std::string& text) {
        out.str("");
        EXPECT_EQ(interp.run(text, "test.alb"), RunStatus::ok) << err.str();
        return out.str();
    }
    std::string fails(const std::string& text) {
        err.str("");
        EXPECT_EQ(interp.run(text, "test.alb"), RunStatus::script_error) << out.str();
        return err.str();
    }
};

// the number printed after `prefix` (the first line holding it)
double number_after(const std::string& text, const std::string& prefix) {
    std::size_t p = text.find(prefix);
    if (p == std::string::npos) {
        ADD_FAILURE() << "no '" << prefix << "' in:\n" << text;
        return NAN;
    }
    return std::stod(text.substr(p + prefix.size()));
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- numbers with units ------------------------------------------------------------------

TEST(UnitsInExpressions, NumbersCarryTheirUnitIntoTheWholeExpression) {
    ScriptSession r;
    r.ok("digits 12\nnewtonian N\nbody B\n");
    // 2 kg * 9.81 m/s^2 is a weight of 19.62 N; the sum of lengths converts each to metres
    EXPECT_NEAR(number_after(r.ok("W = 2 kg * 9.81 m/s^2"), "W = "), 19.62, 1e-12);
    EXPECT_NEAR(number_after(r.ok("d = 15 cm + 2 mm"), "d = "), 0.152, 1e-12);
    // a position vector written with a length: pos() returns it in metres
    r.ok("translate Bcm from N_o by 0.1575 m * Nz> + 30 cm * Nx>\n");
    EXPECT_NEAR(number_after(r.ok("evaluate dot(pos(Bcm, N_o), Nz>)"), "= "), 0.1575, 1e-12);
    EXPECT_NEAR(number_after(r.ok("evaluate dot(pos(Bcm, N_o), Nx>)"), "= "), 0.3, 1e-12);
    // mass B = 1 kg and an inertia in g*cm^2 (1e-7 kg*m^2 each)
    r.ok("mass B = 1500 g\ninertia B = 2e4 g*cm^2, 2e4 g*cm^2, 1e4 g*cm^2\n");
    EXPECT_NEAR(number_after(r.ok("evaluate mass(B)"), "= "), 1.5, 1e-12);
    // a constant's dimension comes from the units inside its value: W is a force
    r.ok("constant Wc = 2 kg * 9.81 m/s^2\n");
    std::string e = r.fails("mass B = Wc");
    EXPECT_TRUE(has(e, "must be a mass (kg), but this is a force (N)")) << e;
}

TEST(UnitsInExpressions, DimensionsOfTheWholeExpressionAreChecked) {
    ScriptSession r;
    r.ok("newtonian N\nbody B\nconstant g = 9.81 m/s^2\n");
    std::string e = r.fails("x = 2 kg + 3 m");
    EXPECT_TRUE(has(e, "test.alb:1:12: error: cannot add a length (m) to a mass (kg)")) << e;
    e = r.fails("mass B = 1 m");
    EXPECT_TRUE(has(e, "the mass of B must be a mass (kg), but this is a length (m)")) << e;
    e = r.fails("translate Bcm from N_o by 2 s * Nx>");
    EXPECT_TRUE(has(e, "must be a length (m), but this is a time (s)")) << e;
    // a unit name that is also the script's name is refused, with both readings' fixes
    e = r.fails("F = 2 kg*g");
    EXPECT_TRUE(has(e, "test.alb:1:10: error: 'g' after the number 2 reads as the unit g")) << e;
    EXPECT_TRUE(has(e, "(2 kg)*g")) << e;
    EXPECT_NEAR(number_after(r.ok("digits 12\nW = (2 kg)*g\nevaluate W"), "\n= "), 19.62, 1e-12);
}

// ---- time in functions ---------------------------------------------------------------------

TEST(TimeInFunctions, PeriodsAndFrequenciesMakeTimeAnAngle) {
    ScriptSession r;
    r.ok("digits 12\nnewtonian N\nframe A\nconstant T = 4 s, f = 0.25 Hz\nvariable q'' deg\n"
         "rotate A from N about z by q\n");
    // at t = 1 s: sin(2 pi t/T) = sin(pi/2) = 1, and with f = 0.25 Hz = 0.25 rev/s,
    // sin(f t) = sin(pi/2) = 1 too: a rate in Hz already counts the 2 pi of a cycle
    EXPECT_NEAR(number_after(r.ok("evaluate sin(2*pi*t/T) at t = 1 s"), "= "), 1.0, 1e-12);
    EXPECT_NEAR(number_after(r.ok("evaluate sin(f*t) at t = 1 s"), "= "), 1.0, 1e-12);
    r.ok("motion q = 30*sin(f*t) deg\n");
    // t alone in sin() shows the fix
    std::string e = r.fails("x = sin(t)");
    EXPECT_TRUE(has(e, "test.alb:1:9: error: the argument of sin() must be an angle or a number, but this is a time (s)"))
        << e;
    EXPECT_TRUE(has(e, "sin(w*t) with constant w = 1 Hz (one cycle per second)")) << e;
}

// ---- positive constants and US customary units ----------------------------------------------

TEST(PositiveConstants, SquareRootOfASquareIsTheConstant) {
    ScriptSession r;
    r.ok("newtonian N\npositive L = 2 m\nconstant c\n");
    EXPECT_EQ(r.ok("sqrt(L^2)"), "= L\n");
    EXPECT_EQ(r.ok("abs(L)"), "= L\n");
    EXPECT_EQ(r.ok("sqrt(c^2)"), "= sqrt(c^2)\n");  // a real constant of either sign
    std::string e = r.fails("positive k = -3 N/m");
    EXPECT_TRUE(has(e, "'k' is declared positive, but its value is -3")) << e;
}

TEST(ImperialUnits, TextbookBlockOnASpringConvertsToSI) {
    // a 20 lbf block hung on a 50 lbf/in spring stretches it W/k = 0.4 in = 0.01016 m; a
    // 1 lbf push on 1 slug accelerates it at 1 ft/s^2 = 0.3048 m/s^2 (definitions: 1 in =
    // 0.0254 m, 1 ft = 0.3048 m, 1 lbf = 0.45359237 kg * 9.80665 m/s^2, 1 slug = 1 lbf*s^2/ft)
    ScriptSession r;
    r.ok("digits 12\nnewtonian N\nparticle P\nconstant W = 20 lbf, k = 50 lbf/in\nvariable x'' m\nunknown F N\n"
         "translate P from N_o by x*Nx>\nmass P = 1 slug\nforce push on P = F*Nx>\n");
    EXPECT_NEAR(number_after(r.ok("evaluate W/k"), "= "), 0.4 * 0.0254, 1e-14);
    std::string out = r.ok("kane K for x\nsolve K for x'' at F = 1 lbf");
    EXPECT_NEAR(number_after(out, "x'' = "), 0.3048, 1e-12) << out;
    EXPECT_NEAR(number_after(r.ok("evaluate 1 lbm"), "= "), 0.45359237, 1e-15);
    EXPECT_NEAR(number_after(r.ok("evaluate 1 ft/(12 in)"), "= "), 1.0, 1e-15);
}

// ---- specified quantities driven ------------------------------------------------------------

TEST(SpecifiedQuantities, BaseExcitedOscillatorFollowsItsClosedFormResponse) {
    // a mass on a spring to a base moved xb = A sin(w t) (specified, its second derivative in
    // the dynamics): x'' + w0^2 x = A w^2 sin(w t) for the stretch x, so from rest
    // x(t) = A w^2/(w0^2 - w^2) (sin(w t) - (w/w0) sin(w0 t))
    ScriptSession r;
    r.ok("newtonian N\npoint B\nparticle P\nconstant m = 2 kg, k = 50 N/m, A = 0.01 m, w = 3 rad/s\n"
         "variable x'' m\nspecified xb'' m\ntranslate B from N_o by xb*Nx>\n"
         "translate P from B by x*Nx>\nmass P = m\nforce spring on P = -k*x*Nx>\n"
         "motion xb = A*sin(w*t)\nfinal time 3 s\ntolerance abs 1e-11 rel 1e-11\noutput x\n"
         "simulate to \"base\"\n");
    alembert::Table tab = alembert::read_csv((r.dir.path / "base" / "simulation.csv").string());
    const double A = 0.01, w = 3, w0 = std::sqrt(50.0 / 2);
    const auto& t = tab.columns[0];
    const auto& x = tab.columns[tab.column_index("x")];
    double worst = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        double exact = A * w * w / (w0 * w0 - w * w) * (std::sin(w * t[i]) - w / w0 * std::sin(w0 * t[i]));
        worst = std::max(worst, std::abs(x[i] - exact));
    }
    EXPECT_NEAR(t.back(), 3, 1e-12);
    EXPECT_LT(worst, 1e-8);
    EXPECT_GT(*std::max_element(x.begin(), x.end()), 1e-3);  // it moved
}

TEST(SpecifiedQuantities, InputGivesASpecifiedForceALaw) {
    // a specified force F = -k x on a free mass is a spring: x(t) = x0 cos(sqrt(k/m) t)
    ScriptSession r;
    r.ok("newtonian N\nparticle P\nconstant m = 1 kg, k = 4 N/m\nvariable x'' m\nspecified F N\n"
         "translate P from N_o by x*Nx>\nmass P = m\nforce push on P = F*Nx>\n"
         "input F = -k*x\ninitial x = 0.1 m\nfinal time 2 s\ntolerance abs 1e-11 rel 1e-11\n"
         "output x\nsimulate to \"spring\"\n");
    alembert::Table tab = alembert::read_csv((r.dir.path / "spring" / "simulation.csv").string());
    const auto& t = tab.columns[0];
    const auto& x = tab.columns[tab.column_index("x")];
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(x[i], 0.1 * std::cos(2 * t[i]), 1e-8);
    // a law of the state for a quantity whose derivative is declared is refused
    std::string e = r.fails("specified G' N\ninput G = -k*x");
    EXPECT_TRUE(has(e, "'G' is declared with derivatives, so its law must be a formula of time")) << e;
}

// ---- order and flexibility ---------------------------------------------------------------

TEST(Flexibility, ConstantsAndSymbolsMayComeBeforeNewtonian) {
    ScriptSession r;
    std::string out = r.ok("digits 12\nconstant g = 9.81 m/s^2, L = 2 m\npositive m = 1 kg\nvariable q''\n"
                           "unknown T N*m\nnewtonian N\nbody A\nrotate A from N about z by q\n"
                           "translate Acm from N_o by L*Ax>\nmass A = m\ninertia A = 0, 0, 0\n"
                           "gravity -g*Ny>\ntorque motor on A = T*Nz>\nkane K for q\n"
                           "solve K for T at q = 0, q' = 0, q'' = 0");
    // holding a point mass level at q = 0 takes T = m g L
    EXPECT_NEAR(number_after(out, "T = "), 9.81 * 2, 1e-9) << out;
    // a name used before newtonian other than as a declaration says what is missing
    ScriptSession r2;
    std::string e = r2.fails("constant a = 1\nframe A");
    EXPECT_TRUE(has(e, "there is no model yet")) << e;
}

TEST(Flexibility, AngularVelocityMayBeGivenInAnyFrame) {
    // B is oriented relative to A, A relative to N; giving w_B_N sets w_B_A = w_B_N - w_A_N
    // (addition theorem), and alf_B_A = alf_B_N - alf_A_N - w_A_N x w_B_A
    ScriptSession r;
    r.ok("newtonian N\nframe A, B\nvariable q'', u1', u2', u3'\nrotate A from N about z by q\n"
         "rotate B from A about x by q\nangvel B in N = u1*Bx> + u2*By> + u3*Bz>\n");
    EXPECT_EQ(r.ok("simplify(express(angvel(B, N) - (u1*Bx> + u2*By> + u3*Bz>), B))"), "= 0>\n");
    EXPECT_EQ(r.ok("simplify(express(angvel(B, A) + angvel(A, N) - angvel(B, N), B))"), "= 0>\n");
    EXPECT_EQ(r.ok("simplify(express(angacc(B, N) - (u1'*Bx> + u2'*By> + u3'*Bz>), B))"), "= 0>\n");
    r.ok("angacc B in N = u1'*Bx> + u2'*By> + u3'*Bz>\n");
    EXPECT_EQ(r.ok("simplify(express(angacc(B, N) - (u1'*Bx> + u2'*By> + u3'*Bz>), B))"), "= 0>\n");
    // a frame oriented relative to B cannot carry B's rate
    std::string e = r.fails("frame C\nrotate C from B about y by q\nangvel B in C = u1*Bx>");
    EXPECT_TRUE(has(e, "'C' is oriented relative to 'B'")) << e;
}

TEST(Flexibility, AStatementWordBeforeParenthesesStartsItsStatement) {
    ScriptSession r;
    r.ok("newtonian N\nconstant a = 2\nvariable q\n");
    EXPECT_NEAR(number_after(r.ok("evaluate (a + q) at q = 1"), "= "), 3.0, 1e-12);
    EXPECT_NEAR(number_after(r.ok("evaluate (a + q)*(a - q) at q = 1"), "= "), 3.0, 1e-12);
    EXPECT_NEAR(number_after(r.ok("evaluate (a)"), "= "), 2.0, 1e-12);
    // digits (n) sets the digits as digits n does: 1/3 printed with 4 significant digits
    r.ok("digits (3 + 1)");
    EXPECT_EQ(r.ok("evaluate 1/3"), "= 0.3333\n");
    // a word that is both a statement and a function stays a call before '('
    EXPECT_EQ(r.ok("simplify(sin(q)^2 + cos(q)^2)"), "= 1\n");
}

TEST(Flexibility, ASessionMayGiveAConstantANewValue) {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_session(true);
    ASSERT_EQ(interp.run("digits 12\nnewtonian N\nconstant L = 1 m\nx = 2*L\n", "<stdin>"), RunStatus::ok);
    ASSERT_EQ(interp.run("constant L = 3 m\n", "<stdin>"), RunStatus::ok) << err.str();
    EXPECT_TRUE(has(out.str(), "L = 3 m (was 1 m); expressions, equations and road-maps keep the symbol L")) << out.str();
    out.str("");
    ASSERT_EQ(interp.run("evaluate x\n", "<stdin>"), RunStatus::ok);
    EXPECT_NEAR(number_after(out.str(), "= "), 6, 1e-12);
    EXPECT_EQ(interp.run("constant L = 3 kg\n", "<stdin>"), RunStatus::script_error);
    EXPECT_TRUE(has(err.str(), "'L' is a length (m), but the new value is a mass (kg)")) << err.str();
    // a script declares each name once
    std::ostringstream o2, e2;
    Interpreter script(o2, e2, false);
    EXPECT_EQ(script.run("newtonian N\nconstant L = 1 m\nconstant L = 3 m\n", "s.alb"), RunStatus::script_error);
    EXPECT_TRUE(has(e2.str(), "'L' is already declared")) << e2.str();
}

// ---- matrices ------------------------------------------------------------------------------

// a double pendulum of point masses m: A's at L along Ax>, B's at 2L Ax> + L Bx>
const char* kTwoLinks =
    "newtonian N\nbody A, B\nconstant L = 1 m, m = 2 kg\nvariable q1'', q2''\n"
    "rotate A from N about z by q1\nrotate B from A about z by q2\ntranslate A_o from N_o by 0>\n"
    "translate Acm from A_o by L*Ax>\ntranslate B_o from Acm by L*Ax>\ntranslate Bcm from B_o by L*Bx>\n"
    "mass A = m; mass B = m\ninertia A = 0, 0, 0\ninertia B = 0, 0, 0\n";

TEST(Matrices, MassMatrixAndJacobianAreTheHandDerivedOnes) {
    // T = m/2 |v_Acm|^2 + m/2 |v_Bcm|^2 gives M = m L^2 [6 + 4 cos q2, 1 + 2 cos q2; 1 + 2 cos q2, 1]
    // (the second point at 2L Ax> + L Bx>: |.|^2 = 5 L^2 + 4 L^2 cos q2 for q1' alone)
    for (const char* method : {"kane", "lagrange"}) {
        ScriptSession r;
        r.ok(std::string(kTwoLinks) + method + " K for q1, q2\nM = massmatrix(K)\n");
        EXPECT_EQ(r.ok("simplify(M[1, 1] - m*L^2*(6 + 4*cos(q2)))"), "= 0\n") << method;
        EXPECT_EQ(r.ok("simplify(M[1, 2] - m*L^2*(1 + 2*cos(q2)))"), "= 0\n") << method;
        EXPECT_EQ(r.ok("simplify(M[2, 1] - M[1, 2])"), "= 0\n") << method;
        EXPECT_EQ(r.ok("simplify(M[2, 2] - m*L^2)"), "= 0\n") << method;
    }
    // the Jacobian of Bcm's position in N: d/dq of (2L cos q1 + L cos(q1 + q2), 2L sin q1 + L sin(q1 + q2), 0)
    ScriptSession r;
    r.ok(std::string(kTwoLinks) + "J = jacobian(pos(Bcm, N_o), [q1, q2], N)\n");
    EXPECT_EQ(r.ok("simplify(J[1, 1] + 2*L*sin(q1) + L*sin(q1 + q2))"), "= 0\n");
    EXPECT_EQ(r.ok("simplify(J[1, 2] + L*sin(q1 + q2))"), "= 0\n");
    EXPECT_EQ(r.ok("simplify(J[2, 1] - 2*L*cos(q1) - L*cos(q1 + q2))"), "= 0\n");
    EXPECT_EQ(r.ok("J[3, 2]"), "J[3, 2] = 0\n");
    // J q' is the velocity: compare with vel(Bcm, N) along Nx>
    EXPECT_EQ(r.ok("simplify(J[1, 1]*q1' + J[1, 2]*q2' - dot(vel(Bcm, N), Nx>))"), "= 0\n");
    // a literal matrix, the rotation matrix, and the errors
    EXPECT_EQ(r.ok("X = [1, 2, 3; 4, 5, 6]"), "X = [1, 2, 3; 4, 5, 6]\n");
    EXPECT_EQ(r.ok("X[2, 3]"), "X[2, 3] = 6\n");
    r.ok("R = rotation(N, B)");
    EXPECT_EQ(r.ok("simplify(R[1, 1] - cos(q1 + q2))"), "= 0\n");
    EXPECT_EQ(r.ok("simplify(R[2, 1] - sin(q1 + q2))"), "= 0\n");
    std::string e = r.fails("X[3, 1]");
    EXPECT_TRUE(has(e, "index 3 is out of range: X has 2 rows")) << e;
    e = r.fails("X[1]");
    EXPECT_TRUE(has(e, "'X' is a matrix: give its row and column")) << e;
    e = r.fails("frame C\nrotate C from N dcm X");
    EXPECT_TRUE(has(e, "must be 3 by 3")) << e;
}

// diff(s, x): Bcm's x coordinate 2L cos q1 + L cos(q1 + q2) by q2 is -L sin(q1 + q2); its
// velocity along Nx>, -(2L sin q1 + L sin(q1 + q2)) q1' - L sin(q1 + q2) q2', by q1' is
// -2L sin q1 - L sin(q1 + q2) (q1' a symbol of its own); L = 1 m.
TEST(Functions, DiffIsThePartialDerivativeBySymbol) {
    ScriptSession r;
    r.ok(std::string(kTwoLinks) + "digits 15\nx = dot(pos(Bcm, N_o), Nx>)\n");
    for (auto [q1, q2] : {std::pair{0.3, -1.1}, std::pair{-2.4, 0.7}}) {
        const std::string at = " at q1 = " + std::to_string(q1) + ", q2 = " + std::to_string(q2);
        const double a = std::stod(std::to_string(q1)), b = std::stod(std::to_string(q2));
        EXPECT_NEAR(number_after(r.ok("evaluate diff(x, q2)" + at), "= "), -std::sin(a + b), 1e-12);
        EXPECT_NEAR(number_after(r.ok("evaluate diff(dot(vel(Bcm, N), Nx>), q1')" + at), "= "),
                    -2 * std::sin(a) - std::sin(a + b), 1e-12);
    }
    EXPECT_TRUE(has(r.fails("diff(x, 2)"), "diff() differentiates by a declared symbol"));
    EXPECT_TRUE(has(r.fails("diff(Nx>, q1)"), "diff() takes a scalar"));
}

TEST(Matrices, MatricesAreOutputsAColumnPerEntry) {
    // released at q1 = 30 deg, q2 = 0 with no loads it stays there: R = rotation(N, B) holds
    // cos, sin of 30 deg and M its values at q2 = 0 (m L^2 (10, 3; 3, 1))
    ScriptSession r;
    r.ok(std::string(kTwoLinks) + "kane K for q1, q2\ninitial q1 = 30 deg\noutput M = massmatrix(K), R = rotation(N, B)\n"
                                  "final time 0.1 s\nsimulate to \"m\"\n");
    alembert::Table t = alembert::read_csv((r.dir.path / "m" / "simulation.csv").string());
    const double c = std::cos(std::numbers::pi / 6), sn = std::sin(std::numbers::pi / 6);
    EXPECT_NEAR(t.columns[t.column_index("M_11")].back(), 2 * 10, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("M_12")].back(), 2 * 3, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("M_22")].back(), 2, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("R_11")].back(), c, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("R_12")].back(), -sn, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("R_21")].back(), sn, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("R_33")].back(), 1, 1e-12);
}

// ---- the linear-quadratic regulator ----------------------------------------------------

TEST(LqrStatement, DoubleIntegratorGainIsTheHandSolution) {
    // x'' = F/m with m = 1 kg, weights 1, 1 on (x, x') and 1 on F: the Riccati equation's
    // entries give p12 = 1, p22 = sqrt 3, so K = (1, sqrt 3) and the closed loop
    // s^2 + sqrt(3) s + 1 has the eigenvalues (-sqrt 3 +- i)/2
    ScriptSession r;
    std::string out = r.ok("digits 12\nnewtonian N\nparticle P\nvariable x'' m\nunknown F N\n"
                           "translate P from N_o by x*Nx>\nmass P = 1 kg\nforce push on P = F*Nx>\nkane K for x\n"
                           "linearize K at x = 0, x' = 0 inputs F lqr 1, 1 and 1 gains L\nL[1]\nL[2]");
    std::size_t gains = out.find("L = [");
    ASSERT_NE(gains, std::string::npos) << out;
    EXPECT_NEAR(number_after(out.substr(gains), "L = ["), 1, 1e-10);
    EXPECT_NEAR(number_after(out.substr(gains), ", "), std::sqrt(3.0), 1e-10);
    EXPECT_TRUE(has(out, "F = -(L[1]*x + L[2]*x')")) << out;
    std::size_t closed = out.find("closed-loop eigenvalues");
    ASSERT_NE(closed, std::string::npos);
    EXPECT_NEAR(number_after(out.substr(closed), "lambda1 = "), -std::sqrt(3.0) / 2, 1e-10);
    // errors name the fix
    std::string e = r.fails("linearize K at x = 0, x' = 0 inputs F lqr 1 and 1 gains L2");
    EXPECT_TRUE(has(e, "1 state weights for 2 states")) << e;
    e = r.fails("linearize K at x = 0, x' = 0 inputs F lqr 1, 1 and 0 gains L2");
    EXPECT_TRUE(has(e, "a weight on an input must be greater than 0")) << e;
    e = r.fails("linearize K at x = 0, x' = 0 inputs F lqr 0, 1 and 1 gains L2");
    EXPECT_TRUE(has(e, "imaginary axis")) << e;  // x unweighted: its integrator mode sits at 0
}

TEST(LqrStatement, RegulatedCartPendulumReturnsUpright) {
    // the example's regulator: from a 5 degree tilt the closed loop returns upright and the
    // cart back near x = 0; the gain on the cart's position is -sqrt(q_x/r) = -10 (for the
    // cart's free position the Riccati equation's first entry gives K_x^2 = q_x/r)
    ScriptSession r;
    std::string out = r.ok("digits 12\n" + [] {
        std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples" / "inverted_pendulum_cart" / "model.alb");
        std::ostringstream t;
        t << in.rdbuf();
        return t.str();
    }());
    std::size_t gains = out.find("L = [");
    ASSERT_NE(gains, std::string::npos) << out;
    EXPECT_NEAR(number_after(out.substr(gains), "L = ["), -10, 1e-8);
    EXPECT_TRUE(has(out, "holds to 1e-1")) << out;  // a relative residual of 1e-10 or less
    alembert::Table t = alembert::read_csv((r.dir.path / "lqr" / "simulation.csv").string());
    const auto& th = t.columns[t.column_index("th")];
    const auto& x = t.columns[t.column_index("x")];
    EXPECT_NEAR(t.columns[0].back(), 6, 1e-12);
    double worst = 0;
    for (double v : th) worst = std::max(worst, std::abs(v));
    EXPECT_LE(worst, 5 + 1e-9);
    EXPECT_LT(std::abs(th.back()), 1e-2);
    EXPECT_LT(std::abs(x.back()), 1e-3);
}

}  // namespace flexibility_lang_test
