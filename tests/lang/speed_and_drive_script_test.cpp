// SPDX-License-Identifier: MIT
// Speeds and the loads that drive specified motions as road-map unknowns, through the script
// language: the road-map tables, `solve ... guess` for a top's steady precession rate, `solve ...
// at` and `inverse` for the motor torque of a turned tube, and the force that drives a
// pendulum's pivot, against hand derivations (tests/eom/speed_and_drive_rows_test.cpp has them
// in full).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

using namespace alembert::lang;
namespace fs = std::filesystem;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace speed_drive_script {

namespace {

struct ScriptRun {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    RunStatus status;
    explicit ScriptRun(const std::string& text, const fs::path& dir = {}) {
        if (!dir.empty()) interp.set_output_dir(dir.string());
        status = interp.run(text, "drive.alb");
    }
    // the value printed as "name = value ..." (the last one)
    double value(const std::string& name) const {
        std::regex re("(^|\\n)" + name + " = (-?[0-9.]+(e[-+]?[0-9]+)?)");
        const std::string text = out.str();
        double v = NAN;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
            v = std::stod((*it)[2]);
        return v;
    }
    // the table row of the road-map that starts with "| name"
    std::string row(const std::string& name) const {
        const std::string text = out.str(), head = "\n| " + name + " ";
        const std::size_t at = text.find(head);
        if (at == std::string::npos) return "";
        return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
    }
};

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

const char* kTop = R"(newtonian N
body A
variable psi'', theta'', phi''
unknown T_psi N*m, T_phi N*m
constant m = 0.5 kg, r = 0.05 m, g = 9.81 m/s^2, I1 = 0.001 kg*m^2, I3 = 0.0005 kg*m^2
coordinates psi, theta, phi
rotate A from N body zxz by psi, theta, phi
translate Acm from N_o by r*Az>
mass A = m
inertia A = I1, I1, I3
gravity -g*Nz>
torque Tpsi on A from N = T_psi*Nz>
torque Tphi on A from N = T_phi*Az>
digits 17
)";

const char* kTube = R"(newtonian N
body A
particle P
variable r''
specified theta''
constant mP = 0.3 kg, IA = 0.1 kg*m^2, w = 2 rad/s
unknown T N*m
coordinates r
rotate A from N about z by theta
translate P from N_o by r*Ax>
translate Acm from N_o by 0>
mass A = 1 kg
inertia A = 0, 0, IA
mass P = mP
torque motor on A from N = T*Nz>
digits 17
)";

struct TempDir {
    fs::path path;
    TempDir() {
        std::string t = (fs::temp_directory_path() / "alembert-drive-XXXXXX").string();
        path = ::mkdtemp(t.data());
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

}  // namespace

// The top's steady precession: psi' from theta's row (about the nodal axis at the tip N_o),
// the motor torques from their own axes' rows. By hand (theta' = 0, accelerations 0):
// (I3 - I1') cos(theta) psi'^2 + I3 phi' psi' - m g r = 0, I1' = I1 + m r^2; with the motors
// idle (T = 0: H.Nz> and w3 stay constant). A guess of 2 rad/s gives the slow root.
TEST(SpeedScript, TopsPrecessionRateFromTheNodalRowBySolveGuess) {
    ScriptRun s(std::string(kTop) + "roadmap V for psi', T_psi, T_phi\n"
                                    "solve V for psi', T_psi, T_phi guess psi' = 2 rad/s at theta = 30 deg, "
                                    "phi' = 200 rad/s, psi = 0.4 rad, phi = -1.1 rad\n");
    ASSERT_EQ(s.status, RunStatus::ok) << s.err.str();
    EXPECT_NE(s.row("psi'").find("| rotate           | cos(phi)*Ax> - sin(phi)*Ay> | {A}"), std::string::npos)
        << s.out.str();
    EXPECT_NE(s.row("psi'").find("| N_o "), std::string::npos) << s.row("psi'");
    EXPECT_NE(s.row("T_psi").find("| rotate           | Nz>"), std::string::npos) << s.out.str();
    EXPECT_NE(s.row("T_psi").find("| N_o "), std::string::npos) << s.row("T_psi");
    EXPECT_NE(s.row("T_phi").find("| rotate           | Az>"), std::string::npos) << s.out.str();
    const double m = 0.5, r = 0.05, g = 9.81, I1 = 0.001, I3 = 0.0005, th = std::numbers::pi / 6, phid = 200;
    const double a = (I3 - I1 - m * r * r) * std::cos(th), b = I3 * phid, c = -m * g * r;
    const double slow = 2 * c / (-b - std::sqrt(b * b - 4 * a * c));
    expect_close(s.value("psi'"), slow, "psi'");
    EXPECT_NEAR(s.value("T_psi"), 0, 1e-12);
    EXPECT_NEAR(s.value("T_phi"), 0, 1e-12);
}

// The equations of W (psi's and phi's rows) hold psi' only times theta', 0 here: a solve for
// psi' from them is refused, naming psi' and the rows, instead of printing the guess back.
TEST(SpeedScript, SolveForASpeedTheRowsDoNotHoldIsRefused) {
    ScriptRun s(std::string(kTop) + "roadmap W for T_psi, T_phi\n"
                                    "solve W for psi', T_phi guess psi' = 2 rad/s at theta = 30 deg, "
                                    "phi' = 200 rad/s, psi = 0, phi = 0, T_psi = 0\n");
    EXPECT_EQ(s.status, RunStatus::script_error);
    const std::string e = s.err.str();
    EXPECT_NE(e.find("the equations do not fix 'psi''"), std::string::npos) << e;
    EXPECT_NE(e.find("E_T_psi (the row of W for T_psi), E_T_phi (the row of W for T_phi) do not change with it"),
              std::string::npos)
        << e;
    EXPECT_EQ(s.out.str().find("psi' = 2"), std::string::npos) << s.out.str();
}

// The tube turned by theta: T from theta's row (S = {A, P} about the axle along Nz>), r'' from
// P's row along Ax>. By hand: T = (IA + mP r^2) theta'' + 2 mP r r' theta', r'' = r theta'^2.
TEST(DriveScript, TubesMotorTorqueFromTheSpecifiedRotationsRow) {
    ScriptRun s(std::string(kTube) + "roadmap V for r'', T\n"
                                     "solve V for r'', T at r = 0.2 m, r' = -0.15 m/s, theta = 0.9 rad, "
                                     "theta' = 2 rad/s, theta'' = 0.7 rad/s^2\n");
    ASSERT_EQ(s.status, RunStatus::ok) << s.err.str();
    EXPECT_NE(s.row("T").find("| rotate           | Nz>       | {A, P}"), std::string::npos) << s.out.str();
    EXPECT_NE(s.row("r''").find("| translate        | Ax>       | {P}"), std::string::npos) << s.out.str();
    const double mP = 0.3, IA = 0.1, r = 0.2, rd = -0.15, w = 2, al = 0.7;
    expect_close(s.value("r''"), r * w * w, "r''");
    expect_close(s.value("T"), (IA + mP * r * r) * al + 2 * mP * r * rd * w, "T");
}

// inverse for T with theta's motion given by `motion`: r = r0 cosh(w t) (the motion the bead
// makes: r'' = w^2 r), theta = w t, so T = 2 mP r r' w = 2 mP r0^2 w^2 cosh(w t) sinh(w t).
TEST(DriveScript, InverseGivesTheMotorTorqueOfAPrescribedRotation) {
    TempDir dir;
    ScriptRun s(std::string(kTube) + "motion r = 0.05 m*(exp(w*t) + exp(-w*t)), theta = w*t\n"
                                     "final time 0.5 s\noutput step 0.1 s\ninverse for T\n",
                dir.path);
    ASSERT_EQ(s.status, RunStatus::ok) << s.err.str();
    // the printed table: "t T" rows after the header "t [s] T [N*m]"
    const std::string text = s.out.str();
    const std::size_t head = text.find("t [s]");
    ASSERT_NE(head, std::string::npos) << text;
    std::istringstream rows(text.substr(text.find('\n', head) + 1));
    int n = 0;
    for (double t = 0, T = 0; rows >> t >> T; ++n) {
        const double r0 = 0.1, w = 2, mP = 0.3;
        expect_close(T, 2 * mP * r0 * r0 * w * w * std::cosh(w * t) * std::sinh(w * t), "T");
    }
    EXPECT_EQ(n, 6);
}

// A pendulum whose pivot B is driven along Nx> at the specified x: theta'' from the pendulum's
// row (about the pivot B_o along Nz>), F from x's row (S = {A, B}, along Nx>). By hand:
// theta'' = -(g sin(theta) + x'' cos(theta)) / L, F = (M + m) x'' + m L (theta'' cos - theta'^2 sin).
TEST(DriveScript, ForceDrivingAPendulumsPivot) {
    ScriptRun s(R"(newtonian N
body A
particle B
point B_o on A
specified x'' m
variable theta''
constant M = 2 kg, m = 0.7 kg, L = 0.4 m, g = 9.81 m/s^2
unknown F N
coordinates theta
translate B from N_o by x*Nx>
translate B_o from B by 0>
rotate A from N about z by theta
translate Acm from B_o by -L*Ay>
mass B = M
mass A = m
inertia A = 0, 0, 0
gravity -g*Ny>
force drive on B = F*Nx>
digits 17
roadmap V for theta'', F
solve V for theta'', F at theta = 0.3 rad, theta' = 1.7 rad/s, x = 0.25 m, x' = 0.4 m/s, x'' = -3.1 m/s^2
)");
    ASSERT_EQ(s.status, RunStatus::ok) << s.err.str();
    EXPECT_NE(s.row("theta''").find("| rotate           | Nz>       | {A}"), std::string::npos) << s.out.str();
    EXPECT_NE(s.row("theta''").find("| B_o "), std::string::npos) << s.row("theta''");
    EXPECT_NE(s.row("F").find("| translate        | Nx>       | {A, B}"), std::string::npos) << s.out.str();
    const double M = 2, m = 0.7, L = 0.4, g = 9.81, q = 0.3, qd = 1.7, xdd = -3.1;
    const double qdd = -(g * std::sin(q) + xdd * std::cos(q)) / L;
    expect_close(s.value("theta''"), qdd, "theta''");
    expect_close(s.value("F"), (M + m) * xdd + m * L * (qdd * std::cos(q) - qd * qd * std::sin(q)), "F");
}

}  // namespace speed_drive_script
