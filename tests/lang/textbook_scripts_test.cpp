// SPDX-License-Identifier: MIT
// Textbook problems written as scripts: the road-map table a textbook would draw and the
// numbers against hand derivations (tests/eom/textbook_problems_test.cpp derives the
// slider-crank in full; the derivations used here are repeated in each comment).
#include <gtest/gtest.h>

#include <cmath>
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
namespace textbook_scripts {

namespace {

// a temporary directory named alembert-textbook-...
struct TempDir : alembert::test::TempDir {
    TempDir() : alembert::test::TempDir("alembert-textbook") {}
};

struct ScriptRun {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    ScriptRun(const std::string& text, const fs::path& dir) {
        interp.set_output_dir(dir.string());
        EXPECT_EQ(interp.run(text, "textbook.alb"), RunStatus::ok) << err.str() << out.str();
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

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// A slider-crank held still: crank A (a = 0.3 m, 1.4 kg) at qA = 50 deg about N_o, rod B
// (b = 1.1 m, 2.3 kg) pinned at the crank's tip and at the slider C (3.1 kg) on a frictionless
// horizontal guide, a load P = -200 N Nx> on the slider; the model keeps qA, qB and x with the
// loop declared and the pin's force on the slider declared as a force pair. By virtual work
// (phi = qA + qB the rod's angle, sin phi = -(a/b) sin qA):
//   T = (m_A + m_B) g (a/2) cos qA + P a sin(qA - phi) / cos phi;
// the slider along Nx>: F_x = -P; the rod about the crank's tip: F_y = F_x tan phi - m_B g / 2;
// the slider along Ny>: N_n = m_C g - F_y = m_C g + m_B g / 2 + P tan phi.
TEST(TextbookScripts, SliderCrankHeldStillWithALoadOnTheSlider) {
    TempDir dir;
    ScriptRun r(R"(newtonian N
body A, B
particle C
point A_t on A; point B_t on B
constant a = 0.3 m, b = 1.1 m, g = 9.81 m/s^2
constant m_A = 1.4 kg, m_B = 2.3 kg, m_C = 3.1 kg, P = -200 N
variable qA'' rad, qB'' rad, x'' m
unknown T N*m, N_n N, F_x N, F_y N
rotate A from N about z by qA
rotate B from A about z by qB
translate A_o from N_o by 0>
translate Acm from A_o by a/2*Ax>
translate A_t from A_o by a*Ax>
translate B_o from A_t by 0>
translate Bcm from B_o by b/2*Bx>
translate B_t from B_o by b*Bx>
translate C from N_o by x*Nx>
mass A = m_A; mass B = m_B; mass C = m_C
inertia A = 0, 0, m_A*a^2/12; inertia B = 0, 0, m_B*b^2/12
gravity -g*Ny>
torque T on A from N = T*Nz>
force load on C = P*Nx>
force Nn on C = N_n*Ny>
force pin on C from B_t = F_x*Nx> + F_y*Ny>
constraint configuration loop = pos(B_t, C) in N
roadmap S for T, N_n, F_x, F_y, qB, x statics
digits 17
solve S for T, N_n, F_x, F_y, qB, x guess qB = -40 deg, x = 1.3 m at qA = 50 deg
)",
                dir.path);
    const std::string t = r.out.str();
    // the slider alone along the guide's normal for N_n; what turns with the crank about the
    // fixed pin for T
    EXPECT_TRUE(has(t, "| N_n      | translate        | Ny>       | {C}      |")) << t;
    EXPECT_TRUE(has(t, "| T        | rotate           | Nz>       | {A, B}   |")) << t;
    EXPECT_TRUE(std::regex_search(t, std::regex("\\| T +\\|.*\\| A_o +\\|"))) << t;
    const double a = 0.3, b = 1.1, g = 9.81, mA = 1.4, mB = 2.3, mC = 3.1, P = -200;
    const double th = 50 * std::numbers::pi / 180, phi = std::asin(-a / b * std::sin(th));
    expect_close(r.value("T"), (mA + mB) * g * a / 2 * std::cos(th) + P * a * std::sin(th - phi) / std::cos(phi), "T");
    expect_close(r.value("N_n"), mC * g + mB * g / 2 + P * std::tan(phi), "N_n");
    expect_close(r.value("F_x"), -P, "F_x");
    expect_close(r.value("F_y"), -P * std::tan(phi) - mB * g / 2, "F_y");
    expect_close(r.value("qB"), phi - th, "qB");
    expect_close(r.value("x"), a * std::cos(th) + b * std::cos(phi), "x");
}

// The same slider-crank in its crank angle alone: the rod turned from the crank by
// asin(-(a/b) sin qA) - qA, the slider pinned at the rod's tip. Rod and slider about the crank
// pin B_o give N_n, the whole linkage about N_o gives T: the same two numbers as above.
TEST(TextbookScripts, SliderCrankInItsCrankAngleAlone) {
    TempDir dir;
    ScriptRun r(R"(newtonian N
body A, B
particle C
point A_t on A; point B_t on B
constant a = 0.3 m, b = 1.1 m, g = 9.81 m/s^2
constant m_A = 1.4 kg, m_B = 2.3 kg, m_C = 3.1 kg, P = -200 N
variable qA'' rad
unknown T N*m, N_n N
rotate A from N about z by qA
rotate B from A about z by -asin(a/b*sin(qA)) - qA
translate A_o from N_o by 0>
translate Acm from A_o by a/2*Ax>
translate A_t from A_o by a*Ax>
translate B_o from A_t by 0>
translate Bcm from B_o by b/2*Bx>
translate B_t from B_o by b*Bx>
translate C from B_t by 0>
mass A = m_A; mass B = m_B; mass C = m_C
inertia A = 0, 0, m_A*a^2/12; inertia B = 0, 0, m_B*b^2/12
gravity -g*Ny>
torque T on A from N = T*Nz>
force load on C = P*Nx>
force Nn on C = N_n*Ny>
roadmap S for T, N_n statics
digits 17
solve S for T, N_n at qA = 50 deg
)",
                dir.path);
    const std::string t = r.out.str();
    EXPECT_TRUE(std::regex_search(t, std::regex("\\| N_n +\\| rotate +\\| Nz> +\\| \\{B, C\\} +\\|.*\\| B_o +\\|"))) << t;
    EXPECT_TRUE(std::regex_search(t, std::regex("\\| T +\\| rotate +\\| Nz> +\\| \\{A, B, C\\} +\\|.*\\| A_o +\\|"))) << t;
    const double a = 0.3, b = 1.1, g = 9.81, mA = 1.4, mB = 2.3, mC = 3.1, P = -200;
    const double th = 50 * std::numbers::pi / 180, phi = std::asin(-a / b * std::sin(th));
    expect_close(r.value("T"), (mA + mB) * g * a / 2 * std::cos(th) + P * a * std::sin(th - phi) / std::cos(phi), "T");
    expect_close(r.value("N_n"), mC * g + mB * g / 2 + P * std::tan(phi), "N_n");
}

// A cart C (M = 2 kg) on Nx> pushed by F, with an inverted pendulum R (mr = 0.5 kg, Lr = 1 m,
// uniform) pinned on it, th from the upright (Ry> = -sin th Nx> + cos th Ny>). Kane's
// equation for th: (mr Lr/2)(g sin th + x'' cos th) - (mr Lr^2/3) th'' = 0, so a motion with
// th given must have x'' = (2 Lr/3) th'' / cos th - g tan th. With th = atan(b t) (s = b t,
// D = 1 + s^2: th' = b/D, th'' = -2 b^2 s/D^2, cos th = D^(-1/2)), th''/cos th =
// -2 b^3 t D^(-3/2), whose second integral is 2 asinh(b t) (d/dt 2b D^(-1/2) = -2 b^3 t D^(-3/2)),
// and -g tan th = -g b t integrates twice to -g b t^3/6:
//   x = (4 Lr/3) asinh(b t) - g b t^3/6   (asinh(s) = log(s + sqrt(1 + s^2))).
// The push: F = (M + mr) x'' - (mr Lr/2)(th'' cos th - th'^2 sin th), at each sample.
TEST(TextbookScripts, CartWithInvertedPendulumPushForAFallingRod) {
    TempDir dir;
    ScriptRun r(R"(newtonian N
particle C
body R
constant M = 2 kg, mr = 0.5 kg, Lr = 1 m, g = 9.81 m/s^2
constant b = 0.5 rad/s
variable x'' m, th''
unknown F N
translate C from N_o by x*Nx>
rotate R from N about z by th
translate R_o from C by 0>
translate Rcm from R_o by Lr/2*Ry>
mass C = M
mass R = mr
inertia R = 0, 0, mr*Lr^2/12
gravity -g*Ny>
force push on C = F*Nx>
final time 1 s
output step 0.125 s
motion x = 4*Lr/3*log(b*t + sqrt(1 + (b*t)^2)) - g*b*t^3/6, th = atan(b*t)
inverse for F
)",
                dir.path);
    alembert::Table tab = alembert::read_csv((dir.path / "forces.csv").string());
    ASSERT_EQ(tab.row_count(), 9u);
    const double M = 2, mr = 0.5, Lr = 1, g = 9.81, b = 0.5;
    for (std::size_t k = 0; k < tab.row_count(); ++k) {
        const double t = tab.columns[0][k], s = b * t, D = 1 + s * s;
        const double thd = b / D, thdd = -2 * b * b * s / (D * D);
        const double c = 1 / std::sqrt(D), sn = s / std::sqrt(D);
        const double xdd = 2 * Lr / 3 * (-2 * b * b * b * t) / std::pow(D, 1.5) - g * b * t;
        expect_close(tab.columns[1][k], (M + mr) * xdd - mr * Lr / 2 * (thdd * c - thd * thd * sn), "F");
    }
}

}  // namespace textbook_scripts
