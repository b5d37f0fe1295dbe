// SPDX-License-Identifier: MIT
// The interpreter against physics: the examples' numbers checked by hand derivations, and the
// language's statements doing what docs/language.md says.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"
#include "support/constants.hpp"
#include "support/script_dir.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

using alembert::test::kDeg;

std::string example(const std::string& name) {
    std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples" / name / "model.alb");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// runs the statements (quietly: results only) and returns what they printed; what they
// write (an example's inverse, a sweep) goes to a temporary directory, not where the test runs
struct Session {
    alembert::test::TempDir dir{"alembert-examples"};
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    Session() { interp.set_output_dir(dir.path.string()); }
    std::string run(const std::string& text) {
        out.str("");
        RunStatus s = interp.run(text, "test.alb");
        EXPECT_EQ(s, RunStatus::ok) << err.str();
        return out.str();
    }
};

// the number printed after "name = " in a transcript (6 significant digits)
double value(const std::string& transcript, const std::string& name) {
    std::istringstream in(transcript);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(name + " = ", 0) == 0) return std::stod(line.substr(name.size() + 3));
    ADD_FAILURE() << "no '" << name << " = ' in:\n" << transcript;
    return NAN;
}

// printed values carry 6 significant digits
void expect_printed(double printed, double exact) {
    EXPECT_NEAR(printed, exact, 5e-6 * std::max(1.0, std::fabs(exact)) + 1e-12);
}

}  // namespace

TEST(Examples, SitToStandHoldingTorquesEqualTheGravityMomentsAboutEachJoint) {
    Session s;
    std::string out = s.run(example("sit_to_stand"));
    // hand: each torque balances the gravity moment, about its joint, of the links above it
    const double g = 9.81, LA = 0.4182, LB = 0.4165, dA = 0.2371, dB = 0.2362, dC = 0.3065;
    const double mA = 6.51, mB = 14.00, mC = 47.46;
    const double qA = 20 * kDeg, qB = -70 * kDeg, qC = 60 * kDeg;
    // the links lean from the vertical by qA, qA + qB, qA + qB + qC; a mass at height along
    // a link's y axis at angle a sits at horizontal -r sin(a) from the joint
    double xA = -dA * std::sin(qA), xKnee = -LA * std::sin(qA);
    double xB = xKnee - dB * std::sin(qA + qB), xHip = xKnee - LB * std::sin(qA + qB);
    double xC = xHip - dC * std::sin(qA + qB + qC);
    // T + (moments about the joint of the weights above it) = 0; a weight -m g Ny> at
    // horizontal offset x from the joint has moment -x m g about Nz>, so T = sum x m g
    double T_C = mC * g * (xC - xHip);
    double T_B = mB * g * (xB - xKnee) + mC * g * (xC - xKnee);
    double T_A = mA * g * xA + mB * g * xB + mC * g * xC;
    expect_printed(value(out, "T_A"), T_A);
    expect_printed(value(out, "T_B"), T_B);
    expect_printed(value(out, "T_C"), T_C);
}

TEST(Examples, SitToStandJointForcesCarryTheWeightAboveEachJoint) {
    Session s;
    std::string out = s.run(example("sit_to_stand"));
    // hand statics of the crouch: each joint pushes up on what lies above it with that weight,
    // W Ny>; compressive along the lower segment's y axis, shear along its x axis, and
    // Ny> . Ay> = cos qA, Ny> . Ax> = sin qA (Ax> = cos qA Nx> + sin qA Ny>)
    const double g = 9.81, mA = 6.51, mB = 14.00, mC = 47.46;
    const double qA = 20 * kDeg, qB = -70 * kDeg;
    const double ankle = (mA + mB + mC) * g, knee = (mB + mC) * g, hip = mC * g;
    expect_printed(value(out, "F_Ac"), ankle * std::cos(qA));
    expect_printed(value(out, "F_As"), ankle * std::sin(qA));
    expect_printed(value(out, "F_Kc"), knee * std::cos(qA));
    expect_printed(value(out, "F_Ks"), knee * std::sin(qA));
    expect_printed(value(out, "F_Hc"), hip * std::cos(qA + qB));
    expect_printed(value(out, "F_Hs"), hip * std::sin(qA + qB));
    // the road-map: each force its own translate row, S what lies beyond the joint
    std::string table = s.interp.roadmap_text(false);
    EXPECT_NE(table.find("| F_Kc     | translate        | Ay>       | {B, C}    |"), std::string::npos) << table;
    EXPECT_NE(table.find("| F_Hs     | translate        | Bx>       | {C}       |"), std::string::npos) << table;
    EXPECT_NE(table.find("F_Kc at B_o from A (unknown, drops out)"), std::string::npos) << table;
}

TEST(Examples, SitToStandRoadmapHasTheSeedsThreeRows) {
    Session s;
    s.run(example("sit_to_stand"));
    std::string table = s.interp.roadmap_text(false);
    EXPECT_NE(table.find("| T_A      | rotate           | Nz>       | {A, B, C} |"), std::string::npos) << table;
    EXPECT_NE(table.find("| T_B      | rotate           | Nz>       | {B, C}    |"), std::string::npos);
    EXPECT_NE(table.find("| T_C      | rotate           | Nz>       | {C}       |"), std::string::npos);
    for (const char* about : {"| A_o ", "| B_o ", "| C_o "}) EXPECT_NE(table.find(about), std::string::npos);
}

TEST(Examples, DoublePendulumAccelerationsMatchTheTextbookEquations) {
    Session s;
    std::string out = s.run(example("double_pendulum"));
    // Kane's and Lagrange's equations agree: both differences print as 0
    std::size_t zeros = 0;
    for (std::size_t at = out.find("\n= 0\n"); at != std::string::npos; at = out.find("\n= 0\n", at + 1)) ++zeros;
    EXPECT_EQ(zeros, 2u) << out;
    // hand (absolute angles from the downward vertical), released from rest:
    //   (m1 + m2) L1 a1 + m2 L2 cos(q1 - q2) a2 = -(m1 + m2) g sin q1
    //   L1 cos(q1 - q2) a1 + L2 a2 = -g sin q2
    const double L1 = 1, L2 = 0.5, m1 = 2, m2 = 1, g = 9.81, q1 = 30 * kDeg, q2 = 45 * kDeg;
    double a11 = (m1 + m2) * L1, a12 = m2 * L2 * std::cos(q1 - q2), b1 = -(m1 + m2) * g * std::sin(q1);
    double a21 = L1 * std::cos(q1 - q2), a22 = L2, b2 = -g * std::sin(q2);
    double det = a11 * a22 - a12 * a21;
    expect_printed(value(out, "q1''"), (b1 * a22 - a12 * b2) / det);
    expect_printed(value(out, "q2''"), (a11 * b2 - a21 * b1) / det);
}

TEST(Examples, SpringMassDamperIsNewtonsSecondLaw) {
    Session s;
    std::string out = s.run(example("mass_spring_damper"));
    expect_printed(value(out, "x"), 0.4 + 10.0 / 50);  // L0 + F/k
    // m x'' = F - k (x - L0) - c x' at a state with x > 0: the residual K[1] = F - k(x - L0) - c x' - m x''
    std::string e = s.run("evaluate K[1] at x = 0.7 m, x' = 0.3 m/s, x'' = 1.1 m/s^2, F = 2 N");
    double x = 0.7, xd = 0.3, xdd = 1.1, F = 2, m = 2, k = 50, c = 3, L0 = 0.4;
    expect_printed(std::stod(e.substr(2)), F - k * (x - L0) - c * xd - m * xdd);
}

TEST(Examples, SpringRestrainedDoublePendulumRestsWhereMomentsBalance) {
    Session s;
    std::string out = s.run(example("statics_double_pendulum"));
    double q1 = value(out, "q1"), q2 = value(out, "q2");
    // hand: rods hang along -Ay>, -By>; A turns by q1, B by q2 about Nz> (absolute angles)
    const double L = 1, mA = 2, mB = 1, g = 9.81, k = 100, L0 = 0.5, h = 1.5, d = 2;
    double Bo_x = L * std::sin(q1), Bo_y = -L * std::cos(q1);
    double tip_x = Bo_x + L * std::sin(q2), tip_y = Bo_y - L * std::cos(q2);
    double rx = tip_x - h, ry = tip_y + d, len = std::hypot(rx, ry);
    double Fx = -k * (len - L0) * rx / len, Fy = -k * (len - L0) * ry / len;  // on the tip
    auto moment = [](double px, double py, double fx, double fy) { return px * fy - py * fx; };
    // about B_o, rod B: spring at the tip, gravity at its middle
    double MB = moment(tip_x - Bo_x, tip_y - Bo_y, Fx, Fy) +
                moment((tip_x - Bo_x) / 2, (tip_y - Bo_y) / 2, 0, -mB * g);
    // about N_o, both rods
    double MA = moment(tip_x, tip_y, Fx, Fy) + moment(Bo_x / 2, Bo_y / 2, 0, -mA * g) +
                moment((Bo_x + tip_x) / 2, (Bo_y + tip_y) / 2, 0, -mB * g);
    // the printed angles carry 6 digits: the moments vanish to that precision (k L ~ 100 N m/rad)
    EXPECT_NEAR(MB, 0, 1e-3);
    EXPECT_NEAR(MA, 0, 1e-3);
    EXPECT_GT(q2, q1);  // the spring pulls the lower rod further out
}

TEST(Examples, RollingDiskRatesMatchNewtonEulerByHand) {
    Session s;
    s.run(example("rolling_disk"));
    // hand (tests/eom/linearize_test.cpp derivation), thin disk Id = m r^2/4, Ia = m r^2/2:
    //   (Id + m r^2) u1' = m g r s - Id t u3^2 + (Ia + m r^2) u2 u3
    //   (Ia + m r^2) u2' = -m r^2 u1 u3
    //   Id u3' = -Ia u1 u2 + Id t u1 u3
    std::string out = s.run("solve K for u1', u2', u3' at q2 = 0.3, u1 = 0.2, u2 = 1.5, u3 = -0.4");
    const double m = 2, r = 0.3, g = 9.81, q2 = 0.3, u1 = 0.2, u2 = 1.5, u3 = -0.4;
    double Id = m * r * r / 4, Ia = m * r * r / 2, sn = std::sin(q2), t = std::tan(q2);
    expect_printed(value(out, "u1'"), (m * g * r * sn - Id * t * u3 * u3 + (Ia + m * r * r) * u2 * u3) / (Id + m * r * r));
    expect_printed(value(out, "u2'"), -m * r * r * u1 * u3 / (Ia + m * r * r));
    expect_printed(value(out, "u3'"), (-Ia * u1 * u2 + Id * t * u1 * u3) / Id);
}

TEST(Examples, FourBarClosesItsLoopAndTheTorqueIsTheVirtualWorkOfGravity) {
    Session s;
    std::string out = s.run(example("four_bar_linkage"));
    const double LN = 1, LA = 0.4, LB = 1.2, LC = 0.8, mA = 1, mB = 2, mC = 1.5, g = 9.81;
    // hand geometry: the rocker's tip is where circles about A_tip (radius L_B) and N_c
    // (radius L_C) meet, on the branch above the line between their centres
    auto pose = [&](double qA, double& qB, double& qC) {
        double ax = LA * std::cos(qA), ay = LA * std::sin(qA);
        double dx = LN - ax, dy = -ay, dd = std::hypot(dx, dy);
        double a = (LB * LB - LC * LC + dd * dd) / (2 * dd), hh = std::sqrt(LB * LB - a * a);
        double px = ax + a * dx / dd - hh * dy / dd, py = ay + a * dy / dd + hh * dx / dd;
        qB = std::atan2(py - ay, px - ax) - qA;
        qC = std::atan2(py, px - LN);
    };
    // potential energy of gravity; virtual work: T = dV/dqA along the constrained motion
    auto V = [&](double qA) {
        double qB, qC;
        pose(qA, qB, qC);
        double yA = LA / 2 * std::sin(qA), yB = LA * std::sin(qA) + LB / 2 * std::sin(qA + qB);
        double yC = LC / 2 * std::sin(qC);
        return g * (mA * yA + mB * yB + mC * yC);
    };
    double qA = 60 * kDeg, qB, qC, h = 1e-5;
    pose(qA, qB, qC);
    expect_printed(value(out, "qB"), qB);
    expect_printed(value(out, "qC"), qC);
    expect_printed(value(out, "T"), (V(qA + h) - V(qA - h)) / (2 * h));
}

TEST(Language, UnitsConvertToSIAndPrintInTheDeclaredUnit) {
    Session s;
    s.run("newtonian N\nconstant L = 40 cm, a = 90 deg\nvariable x'' mm\n");
    expect_printed(std::stod(s.run("evaluate L").substr(2)), 0.4);
    EXPECT_EQ(s.run("evaluate L*sin(a)"), "= 0.4 m\n");
    EXPECT_EQ(s.run("Z = [x - L]\nsolve Z for x"), "Z[1]: 0 = -L + x\nx = L\n");
    EXPECT_EQ(s.run("solve Z for x at x' = 0"), "x = 400 mm\n");
}

TEST(Language, KinematicCallsPrintAndKeepTheirMonogramNames) {
    Session s;
    std::string out = s.run(
        "newtonian N\nbody A\nvariable q'' rad\nconstant L = 2 m\nrotate A from N about z by q\n"
        "translate A_o from N_o by 0>\ntranslate Acm from A_o by L*Ax>\n"
        "angvel(A, N)\nangacc(A, N)\nvel(Acm, N)\npos(Acm, N_o)\nz = dot(v_Acm_N>, Ny>)\n");
    EXPECT_NE(out.find("w_A_N> = q'*Az>\n"), std::string::npos) << out;
    EXPECT_NE(out.find("alf_A_N> = q''*Az>\n"), std::string::npos) << out;
    EXPECT_NE(out.find("v_Acm_N> = L*q'*Ay>\n"), std::string::npos) << out;
    EXPECT_NE(out.find("p_No_Acm> = L*Ax>\n"), std::string::npos) << out;
    EXPECT_NE(out.find("z = L*q'*cos(q)\n"), std::string::npos) << out;
}

TEST(Language, VectorOperationsFollowTheDefinitions) {
    Session s;
    s.run("newtonian N\nframe A\nvariable q'' rad\nrotate A from N about z by q\n");
    EXPECT_EQ(s.run("dot(Ax>, Nx>)"), "= cos(q)\n");
    EXPECT_EQ(s.run("cross(Nx>, Ny>)"), "= Nz>\n");
    EXPECT_EQ(s.run("simplify(express(Ax>, N))"), "= cos(q)*Nx> + sin(q)*Ny>\n");
    // d/dt in N of Ax> is w x Ax> = q' Az> x Ax> = q' Ay>
    EXPECT_EQ(s.run("dt(Ax>, N)"), "= q'*Ay>\n");
    EXPECT_EQ(s.run("dt(sin(q))"), "= q'*cos(q)\n");
}

TEST(Language, StatementsRunAcrossCallsAsInASession) {
    Session s;
    s.run("newtonian N\nvariable q''\n");
    std::ostringstream err;
    // an error leaves what was declared; the next call goes on
    EXPECT_EQ(s.interp.run("z = nothing\n", "<stdin>", 3), RunStatus::script_error);
    EXPECT_EQ(s.interp.last_error()->location.line, 3);
    EXPECT_EQ(s.run("z = 2*q"), "z = 2*q\n");
}

TEST(Language, EchoedTranscriptShowsEachStatementThenItsResult) {
    std::ostringstream out, err;
    Interpreter interp(out, err, true);
    ASSERT_EQ(interp.run("# a comment\nnewtonian N\nframe A; z = 1 + 2  # three\n", "t.alb"), RunStatus::ok);
    EXPECT_EQ(out.str(), "# a comment\n> newtonian N\n> frame A\n> z = 1 + 2  # three\nz = 3\n");
}

TEST(Language, EveryStatementRunsAndTheHandCheckableResultsHold) {
    Session s;
    std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "tests" / "lang" / "every_statement.alb");
    std::ostringstream text;
    text << in.rdbuf();
    std::string out = s.run(text.str());
    // a left-handed rotation about x by q is a right-handed one by -q
    EXPECT_NE(out.find("R_N_H = [1, 0, 0; 0, cos(q), sin(q); 0, -sin(q), cos(q)]\n"), std::string::npos) << out;
    EXPECT_NE(out.find("R_N_G = [cos(q), -sin(q), 0; sin(q), cos(q), 0; 0, 0, 1]\n"), std::string::npos);
    EXPECT_NE(out.find("a_Q_N> = x''*Nx> + y''*Ny>\n"), std::string::npos);
    EXPECT_NE(out.find("L_Q_N> = m*x'*Nx> + m*y'*Ny>\n"), std::string::npos);
    EXPECT_NE(out.find("KE_Q = m*(x'^2 + y'^2)/2\n"), std::string::npos);
    EXPECT_NE(out.find("m_S = 2*m\n"), std::string::npos);
    EXPECT_NE(out.find("= 3/5*Nx> + 4/5*Ny>\n"), std::string::npos);
    EXPECT_NE(out.find("roll: 0 = -L*q' + x'\n"), std::string::npos);
    EXPECT_NE(out.find("c1: 0 = -L*sin(q) + y\n"), std::string::npos);
    EXPECT_NE(out.find("| T        | rotate           | Nz>       | {B}      |"), std::string::npos);
    // linearized quadratic drag c_q |v| v at v = (1, 1) m/s: d/dy' of its x-component is
    // c_q x' y'/|v| = c_q/sqrt(2), divided by the mass
    EXPECT_NE(out.find("-0.5*cq*sqrt(2)/m]"), std::string::npos) << out;
    // potential energy at Q = (3, 4) m, R = (1, 0) m: m g y - G m^2 / |r|
    const double m = 2, g = 9.81, G0 = 6.674e-11, r = std::hypot(3.0 - 1.0, 4.0);
    std::string last = out.substr(out.rfind("= "));
    expect_printed(std::stod(last.substr(2)), m * g * 4 - G0 * m * m / r);
    EXPECT_NE(last.find(" N*m"), std::string::npos) << last;  // energy and torque share N*m
}
