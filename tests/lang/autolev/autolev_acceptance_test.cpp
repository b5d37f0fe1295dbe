// SPDX-License-Identifier: MIT
// alembert import on the Autolev files of tests/lang/autolev/acceptance/, one or more for each
// family of statements: each file is imported unchanged, its equations of motion are solved at
// random states and compared with the hand derivation written below (to 1e-12), and each
// dynamics model is simulated and its end state compared with a fourth-order Runge-Kutta
// integration of the hand-derived equations, its energy checked where it is conserved. The
// kinematics file is checked against the arm's hand-derived positions and velocities. The
// classic models of tests/lang/autolev/models/ are simulated too, each checked against its
// hand-derived energy, energy balance, constraints or closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/interpreter.hpp"

namespace autolev_acceptance_test {

using alembert::lang::AutolevTranslation;
using alembert::lang::Interpreter;
using alembert::lang::RunStatus;
using alembert::lang::Severity;
using alembert::lang::translate_autolev;

const std::string kDir = std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/acceptance/";
constexpr double kG = 9.81;
constexpr double kDeg = std::numbers::pi / 180;

std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    EXPECT_TRUE(f.good()) << path;
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

struct ScriptRun {
    RunStatus status = RunStatus::ok;
    std::string out, err;
    std::vector<double> values;  // the numbers printed as `name = value` or `= value`, in order
    std::map<std::string, double> named;
};

ScriptRun run(const std::string& script, const std::string& extra) {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(::testing::TempDir());
    ScriptRun r;
    r.status = interp.run(script + "\ndigits 17\n" + extra + "\n", "imported.alb");
    r.out = out.str();
    r.err = err.str();
    std::istringstream lines(r.out);
    std::string line;
    std::smatch m;
    static const std::regex assignment(R"(^(\S*) ?= (\S+)( .*)?$)");
    while (std::getline(lines, line))
        if (std::regex_match(line, m, assignment)) {
            try {
                double v = std::stod(m[2]);
                r.values.push_back(v);
                if (!m[1].str().empty()) r.named[m[1]] = v;
            } catch (const std::exception&) {
                // a symbolic line
            }
        }
    return r;
}

// the file imported: no message but notes, except warnings on the lines `left_out` names
// (statements left out, and the line that says the equations lack them), which are then
// exactly the lines left out
AutolevTranslation import(const std::string& file, const std::vector<int>& left_out = {}, int model_warning = 0) {
    AutolevTranslation t = translate_autolev(read_file(kDir + file), file);
    for (const auto& d : t.diagnostics) {
        const int line = d.location.line;
        const bool expected = d.severity == Severity::warning &&
                              (line == model_warning || std::find(left_out.begin(), left_out.end(), line) != left_out.end());
        if (d.severity != Severity::note && !expected)  // notes tell of names declared or renamed
            ADD_FAILURE() << file << ":" << line << ":" << d.location.column << ": " << d.message;
    }
    EXPECT_EQ(t.left_out_lines, left_out) << file;
    return t;
}

std::string kane_name(const std::string& script) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(script, m, std::regex(R"(\bkane (\w+) for)"))) << script;
    return m.size() > 1 ? m[1].str() : "K";
}

using Vec = std::vector<double>;
// the accelerations q'' at time t and state (q, q'), by hand
using Accelerations = std::function<Vec(double t, const Vec& q, const Vec& qd)>;
// the energy at (q, q'), by hand; empty where it is not conserved
using Energy = std::function<double(const Vec& q, const Vec& qd)>;

struct Case {
    std::string file;
    std::vector<std::string> q;  // the coordinates as the imported script names them
    Accelerations accelerations;
    Vec q0, qd0;  // the file's initial values, in SI
    Energy energy{};
    std::string given{};  // values of given quantities for `solve ... at`
    std::vector<int> left_out{};  // the lines the import leaves out (each with a warning)
    int model_warning = 0;        // the line that says the equations lack what was left out
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }

Vec solve2(double a11, double a12, double a21, double a22, double b1, double b2) {
    double det = a11 * a22 - a12 * a21;
    return {(b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // X'' = -K/M X with K = 4, M = 1
    c.push_back({"ode_oscillator.al", {"X"}, [](double, const Vec& q, const Vec&) { return Vec{-4 * q[0]}; },
                 {1}, {0}, [](const Vec& q, const Vec& qd) { return qd[0] * qd[0] / 2 + 4 * q[0] * q[0] / 2; }});
    // X'' = -W^2 X + A sin(t), W = 2, A = 0.5 (V is X')
    c.push_back({"ode_first_order_pair.al", {"X"},
                 [](double t, const Vec& q, const Vec&) { return Vec{-4 * q[0] + 0.5 * std::sin(t)}; }, {0.5}, {0}});
    // two masses of 1 between three springs K = 3: V = K (x1^2 - x1 x2 + x2^2)
    c.push_back({"ode_coupled.al", {"X1", "X2"},
                 [](double, const Vec& q, const Vec&) {
                     return Vec{-6 * q[0] + 3 * q[1], 3 * q[0] - 6 * q[1]};
                 },
                 {0.2, -0.1}, {0, 0.4},
                 [](const Vec& q, const Vec& qd) {
                     return (qd[0] * qd[0] + qd[1] * qd[1]) / 2 + 3 * (q[0] * q[0] - q[0] * q[1] + q[1] * q[1]);
                 }});
    // Y'' = MU (1 - Y^2) Y' - Y, MU = 1.5
    c.push_back({"ode_van_der_pol.al", {"Y"},
                 [](double, const Vec& q, const Vec& qd) { return Vec{1.5 * (1 - q[0] * q[0]) * qd[0] - q[0]}; }, {2},
                 {0}});
    // TH'' = -G/L sin(TH), L = 0.6: E = TH'^2/2 - G/L cos(TH)
    c.push_back({"ode_pendulum.al", {"TH"}, [](double, const Vec& q, const Vec&) { return Vec{-kG / 0.6 * std::sin(q[0])}; },
                 {40 * kDeg}, {0}, [](const Vec& q, const Vec& qd) { return qd[0] * qd[0] / 2 - kG / 0.6 * std::cos(q[0]); }});
    // a particle m at L on a massless rod: Q'' = -G/L sin(Q), L = 0.9, M = 0.5
    c.push_back({"continuation.al", {"Q"}, [](double, const Vec& q, const Vec&) { return Vec{-kG / 0.9 * std::sin(q[0])}; },
                 {25 * kDeg}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (0.5 * 0.81 * qd[0] * qd[0]) - 0.5 * kG * 0.9 * std::cos(q[0]);
                 }});
    // a uniform rod of length LEN = L0 + D = 0.8 and mass MA = 2 M = 1.5 about its end:
    // (MA LEN^2/3) Q'' = -MA G LEN/2 sin(Q)
    c.push_back({"compound_assignment.al", {"Q"},
                 [](double, const Vec& q, const Vec&) { return Vec{-3 * kG * std::sin(q[0]) / (2 * 0.8)}; }, {1}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (1.5 * 0.64 / 3) * qd[0] * qd[0] - 1.5 * kG * 0.4 * std::cos(q[0]);
                 }});
    // a compound pendulum: (I3 + MB H^2) Q'' = -MB G H sin(Q), MB = 3, H = 0.4, I3 = 0.05
    c.push_back({"implicit_constants.al", {"Q"},
                 [](double, const Vec& q, const Vec&) { return Vec{-3 * kG * 0.4 * std::sin(q[0]) / (0.05 + 3 * 0.16)}; },
                 {0.5}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (0.05 + 3 * 0.16) * qd[0] * qd[0] - 3 * kG * 0.4 * std::cos(q[0]);
                 }});
    // a rod (M, L) and a particle M at its end: (M L^2/3 + M L^2) A'' = -(M G L/2 + M G L) sin(A),
    // A'' = -9 G sin(A) / (8 L), L = 0.8, M = 1.1; the variable A is A_var in the script
    c.push_back({"kind_clash.al", {"A_var"},
                 [](double, const Vec& q, const Vec&) { return Vec{-9 * kG * std::sin(q[0]) / (8 * 0.8)}; }, {0.3}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (4.0 / 3 * 1.1 * 0.64) * qd[0] * qd[0] - 1.5 * 1.1 * kG * 0.8 * std::cos(q[0]);
                 }});
    // a particle pendulum, OMEGA = THETA' written as the rate: THETA'' = -G/L sin(THETA), L = 1.3
    c.push_back({"speed_as_assignment.al", {"THETA"},
                 [](double, const Vec& q, const Vec&) { return Vec{-kG / 1.3 * std::sin(q[0])}; }, {60 * kDeg}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * 0.2 * 1.69 * qd[0] * qd[0] - 0.2 * kG * 1.3 * std::cos(q[0]);
                 }});
    // M X'' = -K (X - L0) - C X', M = 2, K = 30, C = 0.5, L0 = 0.4
    c.push_back({"specified_definition.al", {"X"},
                 [](double, const Vec& q, const Vec& qd) { return Vec{(-30 * (q[0] - 0.4) - 0.5 * qd[0]) / 2}; }, {0.6},
                 {0}});
    // M X'' = O cos(2 t) - C X', M = 3, C = 0.2, O = 1.5 (given)
    c.push_back({"given_variable.al", {"X"},
                 [](double t, const Vec&, const Vec& qd) { return Vec{(1.5 * std::cos(2 * t) - 0.2 * qd[0]) / 3}; }, {0},
                 {0.1}, {}, ", O = 1.5"});
    // M X'' = -K X - C X' - F0 + F0/2, M = 1.5, K = 20, C = 0.7, F0 = 2
    c.push_back({"force_added.al", {"X"},
                 [](double, const Vec& q, const Vec& qd) { return Vec{(-20 * q[0] - 0.7 * qd[0] - 1) / 1.5}; }, {0.1}, {0}});
    // a uniform rod about its end, L = 1.1, M = 2: Q'' = -3 G sin(Q) / (2 L)
    // a uniform rod (L = 0.8, M = 1.5) whose inertia is given about its pivot, M L^2/3 about A3>:
    // (M L^2/3) Q'' = -M G (L/2) sin(Q), as its central M L^2/12 moved by M (L/2)^2
    c.push_back({"inertia_about_point.al", {"Q"},
                 [](double, const Vec& q, const Vec&) { return Vec{-3 * kG * std::sin(q[0]) / (2 * 0.8)}; },
                 {20 * kDeg}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (1.5 * 0.64 / 3) * qd[0] * qd[0] - 1.5 * kG * 0.4 * std::cos(q[0]);
                 }});
    c.push_back({"dcm_pendulum.al", {"Q"},
                 [](double, const Vec& q, const Vec&) { return Vec{-3 * kG * std::sin(q[0]) / (2 * 1.1)}; }, {0.7}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (2 * 1.21 / 3) * qd[0] * qd[0] - 2 * kG * 0.55 * std::cos(q[0]);
                 }});
    // the point-mass double pendulum (L1 = 1, L2 = 0.8, M1 = 1.2, M2 = 0.7), d = Q1 - Q2:
    //   (M1 + M2) L1 Q1'' + M2 L2 cos(d) Q2'' = -M2 L2 Q2'^2 sin(d) - (M1 + M2) G sin(Q1)
    //   L1 cos(d) Q1'' + L2 Q2'' = L1 Q1'^2 sin(d) - G sin(Q2)
    c.push_back({"particle_double_pendulum.al", {"Q1", "Q2"},
                 [](double, const Vec& q, const Vec& qd) {
                     const double L1 = 1, L2 = 0.8, M1 = 1.2, M2 = 0.7, d = q[0] - q[1];
                     return solve2((M1 + M2) * L1, M2 * L2 * std::cos(d), L1 * std::cos(d), L2,
                                   -M2 * L2 * qd[1] * qd[1] * std::sin(d) - (M1 + M2) * kG * std::sin(q[0]),
                                   L1 * qd[0] * qd[0] * std::sin(d) - kG * std::sin(q[1]));
                 },
                 {40 * kDeg, -20 * kDeg}, {0, 1},
                 [](const Vec& q, const Vec& qd) {
                     const double L1 = 1, L2 = 0.8, M1 = 1.2, M2 = 0.7;
                     double T = 0.5 * (M1 + M2) * L1 * L1 * qd[0] * qd[0] + 0.5 * M2 * L2 * L2 * qd[1] * qd[1] +
                                M2 * L1 * L2 * qd[0] * qd[1] * std::cos(q[0] - q[1]);
                     return T - (M1 + M2) * kG * L1 * std::cos(q[0]) - M2 * kG * L2 * std::cos(q[1]);
                 }});
    // IA Q'' = TM - B Q', IA = 0.02, TM = 0.3, B = 0.05
    c.push_back({"motor_torque.al", {"Q"},
                 [](double, const Vec&, const Vec& qd) { return Vec{(0.3 - 0.05 * qd[0]) / 0.02}; }, {0}, {0}});
    // a rod about its end pushed by F N1> at its tip (L sin Q, -L cos Q): moment F L cos(Q);
    // (M L^2/3) Q'' = F L cos(Q) - M G L/2 sin(Q), L = 1, M = 1.5, F = 2; the constant force's
    // potential is -F L sin(Q)
    c.push_back({"two_points.al", {"Q"},
                 [](double, const Vec& q, const Vec&) {
                     return Vec{(2 * std::cos(q[0]) - 1.5 * kG * 0.5 * std::sin(q[0])) / (1.5 / 3)};
                 },
                 {0}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.5 * (1.5 / 3) * qd[0] * qd[0] - 1.5 * kG * 0.5 * std::cos(q[0]) - 2 * std::sin(q[0]);
                 }});
    // a particle pendulum, L = 0.7, M = 1: Q'' = -G/L sin(Q) (OUTPUT gives Q in degrees)
    c.push_back({"sign_and_units.al", {"Q"}, [](double, const Vec& q, const Vec&) { return Vec{-kG / 0.7 * std::sin(q[0])}; },
                 {30 * kDeg}, {0},
                 [](const Vec& q, const Vec& qd) { return 0.5 * 0.49 * qd[0] * qd[0] - kG * 0.7 * std::cos(q[0]); }});
    // a rod about its end driven by T0 sin(W t): (M L^2/3) Q'' = T0 sin(W t) - M G L/2 sin(Q),
    // L = 0.6, M = 1, T0 = 0.4, W = 3
    c.push_back({"time_forcing.al", {"Q"},
                 [](double t, const Vec& q, const Vec&) {
                     return Vec{(0.4 * std::sin(3 * t) - kG * 0.3 * std::sin(q[0])) / (0.36 / 3)};
                 },
                 {0}, {0}});
    // X'' = -K X with the symmetric K = [5, -2; -2, 3]: V = (5 X1^2 - 4 X1 X2 + 3 X2^2) / 2
    c.push_back({"indexed_2d.al", {"X1", "X2"},
                 [](double, const Vec& q, const Vec&) {
                     return Vec{-5 * q[0] + 2 * q[1], 2 * q[0] - 3 * q[1]};
                 },
                 {0.1, 0}, {0, 0.2},
                 [](const Vec& q, const Vec& qd) {
                     return (qd[0] * qd[0] + qd[1] * qd[1]) / 2 + (5 * q[0] * q[0] - 4 * q[0] * q[1] + 3 * q[1] * q[1]) / 2;
                 }});
    // V = K X^2/2 + C X^4/4, the force -dV/dX: M X'' = -K X - C X^3, M = 0.5, K = 2, C = 8
    c.push_back({"potential_force.al", {"X"},
                 [](double, const Vec& q, const Vec&) { return Vec{(-2 * q[0] - 8 * q[0] * q[0] * q[0]) / 0.5}; },
                 {0.4}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 0.25 * qd[0] * qd[0] + q[0] * q[0] + 2 * q[0] * q[0] * q[0] * q[0];
                 }});
    // two carts on springs: M1 X1'' = -K1 X1 + K2 (X2 - X1), M2 X2'' = -K2 (X2 - X1), M1 = 1,
    // M2 = 2, K1 = 30, K2 = 20 (ZERO[i] by element: KaneRowsAreFrPlusFrStarOfEachSpeed)
    c.push_back({"kane_rows.al", {"X1", "X2"},
                 [](double, const Vec& q, const Vec&) {
                     return Vec{-30 * q[0] + 20 * (q[1] - q[0]), -20 * (q[1] - q[0]) / 2};
                 },
                 {0.1, -0.05}, {0, 0},
                 [](const Vec& q, const Vec& qd) {
                     return (qd[0] * qd[0] + 2 * qd[1] * qd[1]) / 2 + 15 * q[0] * q[0] + 10 * (q[1] - q[0]) * (q[1] - q[0]);
                 }});
    // the pendulum whose equation SOLVE(ZERO, U') solves: Q'' = -G/L sin Q, L = 0.8, M = 1.5;
    // the energy M L^2 Q'^2/2 - M G L cos Q
    c.push_back({"solve_zero_pendulum.al", {"Q"},
                 [](double, const Vec& q, const Vec&) { return Vec{-kG / 0.8 * std::sin(q[0])}; }, {0.6}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 1.5 * 0.64 * qd[0] * qd[0] / 2 - 1.5 * kG * 0.8 * std::cos(q[0]);
                 }});
    // on a slope at 30 degrees (DEGREES ON by default): M X'' = -K X - M G sin 30 + F cos 60,
    // M = 2, K = 20, G = 9.81, F = 3; the energy M X'^2/2 + K X^2/2 + M G X sin 30 - F X cos 60
    c.push_back({"degrees_incline.al", {"X"},
                 [](double, const Vec& q, const Vec&) { return Vec{(-20 * q[0] - 2 * kG * 0.5 + 3 * 0.5) / 2}; },
                 {0.3}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return qd[0] * qd[0] + 10 * q[0] * q[0] + 2 * kG * 0.5 * q[0] - 1.5 * q[0];
                 }});
    // statements with no counterpart left out (COMPLEX ON, C{2,2,2}, SQR(), E[1, 2, 1]), the
    // model kept: the mass centre at L A1> with A1> = cos Q N1> + sin Q N2>, the spring's torque
    // -K Q: M L^2 Q'' = -M G L cos Q - K Q, L = 0.9, M = 1.2, K = 3; the energy
    // M L^2 Q'^2/2 + M G L sin Q + K Q^2/2
    c.push_back({"left_out_no_counterpart.al", {"Q"},
                 [](double, const Vec& q, const Vec&) {
                     return Vec{(-1.2 * kG * 0.9 * std::cos(q[0]) - 3 * q[0]) / (1.2 * 0.81)};
                 },
                 {40 * kDeg}, {0},
                 [](const Vec& q, const Vec& qd) {
                     return 1.2 * 0.81 * qd[0] * qd[0] / 2 + 1.2 * kG * 0.9 * std::sin(q[0]) + 1.5 * q[0] * q[0];
                 },
                 "", {4, 8, 16, 17}});
    // the friction force (SIGN()) left out, and said to be: the equations are the spring's
    // alone, M X'' = -K X, M = 2, K = 8; the energy M X'^2/2 + K X^2/2
    c.push_back({"left_out_chain.al", {"X"}, [](double, const Vec& q, const Vec&) { return Vec{-4 * q[0]}; },
                 {0.3}, {0}, [](const Vec& q, const Vec& qd) { return qd[0] * qd[0] + 4 * q[0] * q[0]; }, "",
                 {13, 14, 15, 16}, 19});
    return c;
}

// A fourth-order Runge-Kutta integration of the hand-derived equations to t_end.
std::pair<Vec, Vec> integrate(const Accelerations& f, Vec q, Vec qd, double t_end) {
    const int n = static_cast<int>(std::lround(t_end / 1e-4));
    const double h = t_end / n;
    const std::size_t m = q.size();
    auto add = [m](const Vec& a, const Vec& b, double s) {
        Vec r(m);
        for (std::size_t i = 0; i < m; ++i) r[i] = a[i] + s * b[i];
        return r;
    };
    for (int k = 0; k < n; ++k) {
        double t = k * h;
        Vec k1q = qd, k1v = f(t, q, qd);
        Vec k2q = add(qd, k1v, h / 2), k2v = f(t + h / 2, add(q, k1q, h / 2), add(qd, k1v, h / 2));
        Vec k3q = add(qd, k2v, h / 2), k3v = f(t + h / 2, add(q, k2q, h / 2), add(qd, k2v, h / 2));
        Vec k4q = add(qd, k3v, h), k4v = f(t + h, add(q, k3q, h), add(qd, k3v, h));
        for (std::size_t i = 0; i < m; ++i) {
            q[i] += h / 6 * (k1q[i] + 2 * k2q[i] + 2 * k3q[i] + k4q[i]);
            qd[i] += h / 6 * (k1v[i] + 2 * k2v[i] + 2 * k3v[i] + k4v[i]);
        }
    }
    return {q, qd};
}

// simulation.csv: the columns by name (units dropped, degrees turned into radians)
std::map<std::string, Vec> read_table(const std::string& path) {
    std::istringstream in(read_file(path));
    std::string header, line;
    std::getline(in, header);
    std::vector<std::string> names;
    std::vector<double> scale;
    std::istringstream h(header);
    for (std::string cell; std::getline(h, cell, ',');) {
        std::string unit;
        if (auto b = cell.find(" ["); b != std::string::npos) {
            unit = cell.substr(b + 2, cell.size() - b - 3);
            cell = cell.substr(0, b);
        }
        names.push_back(cell);
        scale.push_back(unit == "deg" || unit == "deg/s" ? kDeg : 1.0);
    }
    std::map<std::string, Vec> table;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::size_t i = 0;
        for (std::string cell; std::getline(l, cell, ',') && i < names.size(); ++i)
            table[names[i]].push_back(std::stod(cell) * scale[i]);
    }
    return table;
}

// A quantity of one row of a table, from the row's values by column name.
using Row = std::function<double(const std::string& column)>;

// The largest change of f over the rows of a table from its value in the first row, that
// first value and the largest magnitude f takes (the scales of a relative tolerance).
struct Change {
    double largest = 0, first = 0, scale = 0;
};

Change change_over_rows(const std::map<std::string, Vec>& table, const std::function<double(const Row&)>& f) {
    Change c;
    const std::size_t rows = table.count("t") ? table.at("t").size() : 0;
    for (std::size_t row = 0; row < rows; ++row) {
        double v = f([&table, row](const std::string& column) {
            auto it = table.find(column);
            if (it == table.end()) {
                ADD_FAILURE() << "no column " << column;
                return std::nan("");
            }
            return it->second.at(row);
        });
        if (row == 0) c.first = v;
        c.largest = std::max(c.largest, std::abs(v - c.first));
        if (std::isnan(v)) c.largest = v;
        c.scale = std::max(c.scale, std::abs(v));
    }
    return c;
}

class AutolevAcceptance : public ::testing::TestWithParam<Case> {};

// The equations of the imported file, solved for the accelerations at random states, equal
// the hand derivation.
TEST_P(AutolevAcceptance, EquationsAgreeWithTheHandDerivation) {
    const Case& c = GetParam();
    AutolevTranslation t = import(c.file, c.left_out, c.model_warning);
    ASSERT_TRUE(t.ok());
    const std::string k = kane_name(t.script);
    std::mt19937 rng(20261127);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        Vec q, qd;
        std::string at, unknowns;
        double time = uniform(0, 5);
        for (const std::string& n : c.q) {
            q.push_back(uniform(-2, 2));
            qd.push_back(uniform(-3, 3));
            at += n + " = " + num(q.back()) + ", " + n + "' = " + num(qd.back()) + ", ";
            unknowns += (unknowns.empty() ? "" : ", ") + n + "''";
        }
        ScriptRun r = run(t.script, "solve " + k + " for " + unknowns + " at " + at + "t = " + num(time) + c.given);
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        Vec expected = c.accelerations(time, q, qd);
        for (std::size_t i = 0; i < c.q.size(); ++i) {
            ASSERT_TRUE(r.named.count(c.q[i] + "''")) << r.out;
            EXPECT_NEAR(r.named[c.q[i] + "''"], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i])))
                << c.file << " " << c.q[i] << "'' at " << at << "t = " << time;
        }
    }
}

// The imported file simulates: its end state equals the hand-derived equations integrated
// alike, and the energy is kept where it is conserved.
TEST_P(AutolevAcceptance, SimulatesAsTheHandDerivation) {
    const Case& c = GetParam();
    AutolevTranslation t = import(c.file, c.left_out, c.model_warning);
    ASSERT_TRUE(t.ok());
    const std::string dir = "acceptance_" + c.file.substr(0, c.file.size() - 3);
    // the file's OUTPUT lists some columns: the rates the energy needs are added
    std::string rates;
    if (t.script.find("\noutput ") != std::string::npos)
        for (const std::string& n : c.q) rates += "output " + n + "'\n";
    ScriptRun r = run(t.script, rates + "tolerance abs 1e-12 rel 1e-12\nintegrator rkf78\nsimulate plot none to \"" + dir + "\"");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    auto table = read_table((std::filesystem::path(::testing::TempDir()) / dir / "simulation.csv").string());
    ASSERT_TRUE(table.count("t")) << t.script;
    const Vec& time = table["t"];
    ASSERT_GE(time.size(), 2u);
    auto [q, qd] = integrate(c.accelerations, c.q0, c.qd0, time.back());
    int compared = 0;
    for (std::size_t i = 0; i < c.q.size(); ++i) {
        if (table.count(c.q[i])) {
            EXPECT_NEAR(table[c.q[i]].back(), q[i], 1e-8 * std::max(1.0, std::abs(q[i]))) << c.file << " " << c.q[i];
            ++compared;
        }
        if (table.count(c.q[i] + "'")) {
            EXPECT_NEAR(table[c.q[i] + "'"].back(), qd[i], 1e-8 * std::max(1.0, std::abs(qd[i]))) << c.file;
            ++compared;
        }
    }
    EXPECT_GT(compared, 0) << c.file << ": no coordinate among the columns";
    if (!c.energy) return;
    Change e = change_over_rows(table, [&c](const Row& at) {
        Vec qs, qds;
        for (const std::string& n : c.q) {
            qs.push_back(at(n));
            qds.push_back(at(n + "'"));
        }
        return c.energy(qs, qds);
    });
    EXPECT_LE(e.largest, 1e-9 * std::max(1.0, std::abs(e.first))) << c.file;
}

INSTANTIATE_TEST_SUITE_P(Files, AutolevAcceptance, ::testing::ValuesIn(cases()), [](const auto& p) {
    return p.param.file.substr(0, p.param.file.size() - 3);
});

// Every file of the folder has a case (the kinematics file its own test below), and there are
// at least twenty.
TEST(AutolevAcceptanceFiles, EveryFileIsChecked) {
    std::vector<std::string> checked{"vector_algebra.al", "no_newtonian_kinematics.al", "algebra_functions.al",
                                     "matrix_values.al", "series_and_solve.al",
                                     "solve_zero_pendulum.al", "matrix_operations.al", "mass_functions.al",
                                     "terms_and_coefficients.al", "normal_modes.al", "chaplygin_sled.al",
                                     "arrays_by_element.al", "eig_values.al", "dyadic_products.al",
                                     "one_point_acceleration.al", "matrix_rates.al", "rate_dependent.al",
                                     "auxiliary_rod_tension.al", "auxiliary_cartesian_rod.al"};
    for (const Case& c : cases()) checked.push_back(c.file);
    for (const char* f : {"dyadic_inertia.al", "dyadic_algebra.al"}) checked.push_back(f);
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(kDir)) {
        if (e.path().extension() != ".al") continue;
        ++files;
        const std::string name = e.path().filename().string();
        EXPECT_NE(std::find(checked.begin(), checked.end(), name), checked.end()) << name << " has no test";
    }
    EXPECT_GE(files, 20);
}

// A file without dynamics: the two-link arm's tip R> = L1 A1> + L2 B1>, its measures, velocity
// and angular momentum measure against the hand derivation (s1 = sin Q1, s12 = sin(Q1 + Q2)):
//   X = L1 c1 + L2 c12, Y = L1 s1 + L2 s12, D = sqrt(L1^2 + L2^2 + 2 L1 L2 c2),
//   VX = -L1 s1 Q1' - L2 s12 (Q1' + Q2'), VY = L1 c1 Q1' + L2 c12 (Q1' + Q2'),
//   H = X VY - Y VX, C = R>.A1> / D = (L1 + L2 c2) / D.
TEST(AutolevAcceptanceFiles, KinematicsAgreeWithTheHandDerivation) {
    AutolevTranslation t = import("vector_algebra.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(27);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double q1 = uniform(-3, 3), q2 = uniform(-3, 3), u1 = uniform(-4, 4), u2 = uniform(-4, 4);
        double l1 = uniform(0.2, 2), l2 = uniform(0.2, 2);
        std::string at = " at Q1 = " + num(q1) + ", Q2 = " + num(q2) + ", Q1' = " + num(u1) + ", Q2' = " + num(u2) +
                         ", L1 = " + num(l1) + ", L2 = " + num(l2);
        std::string extra;
        for (const char* n : {"X", "Y", "D", "VX", "H", "C"}) extra += std::string("evaluate ") + n + at + "\n";
        ScriptRun r = run(t.script, extra);
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        ASSERT_GE(r.values.size(), 6u) << r.out;
        Vec v(r.values.end() - 6, r.values.end());
        double c1 = std::cos(q1), s1 = std::sin(q1), c12 = std::cos(q1 + q2), s12 = std::sin(q1 + q2);
        double x = l1 * c1 + l2 * c12, y = l1 * s1 + l2 * s12;
        double d = std::sqrt(l1 * l1 + l2 * l2 + 2 * l1 * l2 * std::cos(q2));
        double vx = -l1 * s1 * u1 - l2 * s12 * (u1 + u2), vy = l1 * c1 * u1 + l2 * c12 * (u1 + u2);
        Vec expected{x, y, d, vx, x * vy - y * vx, (l1 + l2 * std::cos(q2)) / d};
        for (std::size_t i = 0; i < 6; ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << at << "\n" << r.out;
    }
}

// The values `evaluate` prints for each name of `names` at `at`, in order.
Vec evaluate(const AutolevTranslation& t, const std::vector<std::string>& names, const std::string& at) {
    std::string extra;
    for (const std::string& n : names) extra += "evaluate " + n + " at " + at + "\n";
    ScriptRun r = run(t.script, extra);
    EXPECT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    if (r.values.size() < names.size()) {
        ADD_FAILURE() << r.out;
        return Vec(names.size(), NAN);
    }
    return Vec(r.values.end() - static_cast<std::ptrdiff_t>(names.size()), r.values.end());
}

// A file without NEWTONIAN: the slider at R B1> on the arm B turning by Q in A has
//   v = R' B1> + R Q' B2>,  a = (R'' - R Q'^2) B1> + (2 R' Q' + R Q'') B2>,
// and a.A1> = (R'' - R Q'^2) cos Q - (2 R' Q' + R Q'') sin Q.
TEST(AutolevAcceptanceFiles, KinematicsWithoutNewtonianAgreeWithTheHandDerivation) {
    AutolevTranslation t = import("no_newtonian_kinematics.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2027);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double q = uniform(-3, 3), r = uniform(-2, 2), qd = uniform(-3, 3), rd = uniform(-3, 3);
        double qdd = uniform(-5, 5), rdd = uniform(-5, 5);
        std::string at = "Q = " + num(q) + ", R = " + num(r) + ", Q' = " + num(qd) + ", R' = " + num(rd) +
                         ", Q'' = " + num(qdd) + ", R'' = " + num(rdd);
        Vec v = evaluate(t, {"VR", "VT", "AR", "AT", "AX"}, at);
        double ar = rdd - r * qd * qd, at_ = 2 * rd * qd + r * qdd;
        Vec expected{rd, r * qd, ar, at_, ar * std::cos(q) - at_ * std::sin(q)};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Algebra: E1 = (A + B Q)^2 expanded, E2 = E1 + (A + B) Q, E3 = dE1/dQ + d(A U^2)/dU =
// 2 B (A + B Q) + 2 A U (U is Q'), E4 = E2 sin Q.
TEST(AutolevAcceptanceFiles, AlgebraFunctionsAgreeWithTheHandResults) {
    AutolevTranslation t = import("algebra_functions.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2028);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double a = uniform(-2, 2), b = uniform(-2, 2), q = uniform(-3, 3), u = uniform(-3, 3);
        std::string at = "A = " + num(a) + ", B = " + num(b) + ", Q = " + num(q) + ", Q' = " + num(u);
        Vec v = evaluate(t, {"E1", "E2", "E3", "E4"}, at);
        double e1 = (a + b * q) * (a + b * q), e2 = e1 + (a + b) * q;
        Vec expected{e1, e2, 2 * b * (a + b * q) + 2 * a * u, e2 * std::sin(q)};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// A direction cosine matrix as a value and its rate: for A turned about N3> by Q, R = N_A is
// [cos Q, -sin Q, 0; sin Q, cos Q, 0; 0, 0, 1] and R^T R' = Q' [0, -1, 0; 1, 0, 0; 0, 0, 0], so
// EQN[1] = Q' and EQN[2] = -Q' + Q' = 0; FACTOR keeps the value W^2 (Q^2 - 1).
TEST(AutolevAcceptanceFiles, MatrixRatesAgreeWithTheHandResults) {
    AutolevTranslation t = import("matrix_rates.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2031);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double w = uniform(-2, 2), q = uniform(-3, 3), qd = uniform(-3, 3);
        std::string at = "W = " + num(w) + ", Q = " + num(q) + ", Q' = " + num(qd);
        Vec v = evaluate(t, {"EQN_1", "EQN_2", "F", "R[2, 1]"}, at);
        Vec expected{qd, 0, w * w * (q * q - 1), std::sin(q)};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// ZERO[i] after ZERO = FR() + FRSTAR() is Fr + Fr* of the i-th speed, by hand:
// ZERO[1] = -K1 X1 + K2 (X2 - X1) - M1 X1'', ZERO[2] = -K2 (X2 - X1) - M2 X2''.
TEST(AutolevAcceptanceFiles, KaneRowsAreFrPlusFrStarOfEachSpeed) {
    AutolevTranslation t = import("kane_rows.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2033);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double x1 = uniform(-1, 1), x2 = uniform(-1, 1), a1 = uniform(-5, 5), a2 = uniform(-5, 5);
        std::string at = "X1 = " + num(x1) + ", X2 = " + num(x2) + ", X1'' = " + num(a1) + ", X2'' = " + num(a2);
        Vec v = evaluate(t, {"E1", "E2", "S"}, at);
        double e1 = -30 * x1 + 20 * (x2 - x1) - a1, e2 = -20 * (x2 - x1) - 2 * a2;
        Vec expected{e1, e2, e1 + 2 * e2};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Matrices as values: M = [cos Q, -sin Q; sin Q, cos Q] times the column [A; B] by elements,
// X = A cos Q - B sin Q, Y = A sin Q + B cos Q, and R = X^2 + Y^2 = A^2 + B^2.
TEST(AutolevAcceptanceFiles, MatrixElementsAgreeWithTheHandResults) {
    AutolevTranslation t = import("matrix_values.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2029);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double a = uniform(-2, 2), b = uniform(-2, 2), q = uniform(-3, 3);
        std::string at = "A = " + num(a) + ", B = " + num(b) + ", Q = " + num(q);
        Vec v = evaluate(t, {"X", "Y", "R"}, at);
        Vec expected{a * std::cos(q) - b * std::sin(q), a * std::sin(q) + b * std::cos(q), a * a + b * b};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Series, coefficients, substitutions and SOLVE, by hand: with m = -M G L,
//   MOM = m sin Q, LIN = m Q, CUBIC = -m Q^3/6, STIFF = m, SQUARE = 3 L^2 ((1 + LQ)^3),
//   SLOPE = m cos 0 = m, SIDE = -M G (2L) sin(pi/6) = -M G L, TURNS = floor(19/3) = 6;
// the springs: K1 X1 = K2 (X2 - X1) = M G, so X1 = M G/K1, X2 = M G/K1 + M G/K2 and
// STRETCH = M G/K2; after SOLVE, X1 and X2 are their solutions (P1, P2).
TEST(AutolevAcceptanceFiles, SeriesCoefficientsAndSolveAgreeWithTheHandResults) {
    AutolevTranslation t = import("series_and_solve.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2030);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double k1 = uniform(10, 100), k2 = uniform(10, 100), mass = uniform(0.5, 3), g = uniform(9, 10);
        double l = uniform(0.2, 2), q = uniform(-1, 1);
        std::string at = "K1 = " + num(k1) + ", K2 = " + num(k2) + ", M = " + num(mass) + ", G = " + num(g) +
                         ", L = " + num(l) + ", Q = " + num(q);
        Vec v = evaluate(t, {"LIN", "CUBIC", "STIFF", "SQUARE", "SLOPE", "SIDE", "TURNS", "STRETCH", "P1", "P2"}, at);
        const double m = -mass * g * l;
        Vec expected{m * q,
                     -m * q * q * q / 6,
                     m,
                     3 * l * l,
                     m,
                     -mass * g * l,
                     6,
                     mass * g / k2,
                     mass * g / k1,
                     mass * g / k1 + mass * g / k2};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// SOLVE(ZERO, U'): the particle at -L A2> on the arm turned by Q has M L^2 U' = -M G L sin Q, so
// ACC = U' = -(G/L) sin Q, its series to order 1 is -(G/L) Q, and PERIOD = 2 pi sqrt(L/G).
TEST(AutolevAcceptanceFiles, SolveOfKanesEquationsAgreesWithTheHandResults) {
    AutolevTranslation t = import("solve_zero_pendulum.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2031);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        double l = uniform(0.2, 2), mass = uniform(0.5, 3), g = uniform(9, 10), q = uniform(-3, 3);
        std::string at = "L = " + num(l) + ", M = " + num(mass) + ", G = " + num(g) + ", Q = " + num(q);
        Vec v = evaluate(t, {"ACC", "PERIOD"}, at);
        Vec expected{-g / l * std::sin(q), 2 * std::numbers::pi * std::sqrt(l / g)};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Matrix operations, by hand: with R the rotation by Q and J = diag(A, A + B),
//   R J R^T = A 1 + B r r^T, r = (-sin Q, cos Q): JXX = A + B sin^2 Q, JXY = -B sin Q cos Q,
//   its trace 2A + B and determinant A (A + B); K = [A, B; B, C] has
//   K^-1 = [C, -B; -B, A]/(AC - B^2), so K^-1 [1; 2] = [C - 2B; 2A - B]/(AC - B^2);
//   ROWS(K) + COLS of a 1 by 3 = 5, K's first row's second element B, J's second column's
//   second element A + B; [2, 1; 1, 2] has eigenvalues 1 and 3; POLYNOMIAL([1, -6, 11, -6], Q)
//   is (Q - 1)(Q - 2)(Q - 3), whose roots add up to 6; 2x - 3 has the root 1.5; the row
//   [DET(K), ELEMENT(K, 1, 2)] has B second.
TEST(AutolevAcceptanceFiles, MatrixOperationsAgreeWithTheHandResults) {
    AutolevTranslation t = import("matrix_operations.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2032);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double a = uniform(0.5, 3), b = uniform(-2, 2), c = uniform(0.5, 3), q = uniform(-3, 3);
        std::string at = "A = " + num(a) + ", B = " + num(b) + ", C = " + num(c) + ", Q = " + num(q);
        Vec v = evaluate(t, {"JXX", "JXY", "TR", "DJ", "X1", "X2", "NR", "T12", "S22", "E1", "E2", "P", "RSUM", "R1", "RB", "R3C", "KM12"}, at);
        const double s = std::sin(q), co = std::cos(q), d = a * c - b * b;
        Vec expected{a + b * s * s,
                     -b * s * co,
                     2 * a + b,
                     a * (a + b),
                     (c - 2 * b) / d,
                     (2 * a - b) / d,
                     5,
                     b,
                     a + b,
                     1,
                     3,
                     (q - 1) * (q - 2) * (q - 3),
                     6,
                     1.5,
                     b,
                     std::cos(3 * q),
                     -b / d};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Inertia dyadics, by hand: B turned by Q1 about N3> then Q2 about A1> has w = (Q2', Q1' sin Q2,
// Q1' cos Q2) in B's unit vectors (A3> = sin Q2 B2> + cos Q2 B3>), so about BO H = I w =
// (I1 Q2', I2 Q1' sin Q2, I3 Q1' cos Q2) and KE = w.I.w/2; about NO, L from BO along B3>, the
// transfer M (L^2 U - L^2 B3> B3>) adds M L^2 about B1> and B2> only: J1 = I1 + M L^2, J3 = I3,
// and H about the fixed point NO has B2> measure (I2 + M L^2) Q1' sin Q2; the trace of the
// central inertia in N is I1 + I2 + I3 in any frame; the particle at R A1> has about NO
// MP (R^2 U - R^2 A1> A1>): 0 along A1>, MP R^2 across, no products. INERTIA(NO), both about
// NO, has I1 + M L^2 along A1> = B1> and, A2> = cos Q2 B2> - sin Q2 B3>, (I2 + M L^2) cos^2 Q2
// + I3 sin^2 Q2 + MP R^2 along A2>; INERTIA(BO, B) is the central inertia, I3 along B3>.
TEST(AutolevAcceptanceFiles, InertiaDyadicsAgreeWithTheHandResults) {
    AutolevTranslation t = import("dyadic_inertia.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2034);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double l = uniform(0.2, 2), r = uniform(0.2, 2), m = uniform(0.5, 3), mp = uniform(0.5, 3);
        const double i1 = uniform(0.1, 2), i2 = uniform(0.1, 2), i3 = uniform(0.1, 2);
        const double q1 = uniform(-3, 3), q2 = uniform(-3, 3), u1 = uniform(-4, 4), u2 = uniform(-4, 4);
        std::string at = "L = " + num(l) + ", R = " + num(r) + ", M = " + num(m) + ", MP = " + num(mp) +
                         ", I1 = " + num(i1) + ", I2 = " + num(i2) + ", I3 = " + num(i3) + ", Q1 = " + num(q1) +
                         ", Q2 = " + num(q2) + ", Q1' = " + num(u1) + ", Q2' = " + num(u2);
        Vec v = evaluate(t, {"H1", "H2", "H3", "KE", "J1", "J3", "HO2", "TRACE", "P11", "P22", "P12", "IS11", "IS22", "IB33"},
                         at);
        const double w1 = u2, w2 = u1 * std::sin(q2), w3 = u1 * std::cos(q2);
        Vec expected{i1 * w1,
                     i2 * w2,
                     i3 * w3,
                     (i1 * w1 * w1 + i2 * w2 * w2 + i3 * w3 * w3) / 2,
                     i1 + m * l * l,
                     i3,
                     (i2 + m * l * l) * w2,
                     i1 + i2 + i3,
                     0,
                     mp * r * r,
                     0,
                     i1 + m * l * l,
                     (i2 + m * l * l) * std::cos(q2) * std::cos(q2) + i3 * std::sin(q2) * std::sin(q2) + mp * r * r,
                     i3};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Dyadics as values, by hand (c = cos Q, s = sin Q, B1> = c N1> + s N2>, B2> = -s N1> + c N2>):
// D = diag(3, 1, 2) in N has in B [3c^2 + s^2, -2sc, 0; -2sc, 3s^2 + c^2, 0; 0, 0, 2]; V =
// X1 B1> + X2 B2> + X3 B3> is (X1 c - X2 s, X1 s + X2 c, X3) in N, so D.V = (3(X1 c - X2 s),
// X1 s + X2 c, 2 X3) = V.D (D symmetric); 1>>.V = V; F = N1> B2>/2 - B2> N1>/4 has
// N1>.F.B2> = 1/2 - (N1>.B2>)^2/4 = 1/2 - s^2/4; D less itself in B is 0; VECTOR(N, [1, 2, 3])
// has 2 along N2>, and VECTOR(N, MATRIX(N, V>)) is V.
TEST(AutolevAcceptanceFiles, DyadicValuesAgreeWithTheHandResults) {
    AutolevTranslation t = import("dyadic_algebra.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2035);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double x1 = uniform(-2, 2), x2 = uniform(-2, 2), x3 = uniform(-2, 2), q = uniform(-3, 3);
        std::string at = "X1 = " + num(x1) + ", X2 = " + num(x2) + ", X3 = " + num(x3) + ", Q = " + num(q);
        Vec v = evaluate(t, {"B11", "B12", "B22", "B33", "E12", "W1", "W2", "W3", "VD1", "U1", "S", "Z11", "R2", "BACK1"},
                         at);
        const double c = std::cos(q), s = std::sin(q);
        Vec expected{3 * c * c + s * s,
                     -2 * s * c,
                     3 * s * s + c * c,
                     2,
                     -2 * s * c,
                     3 * (x1 * c - x2 * s),
                     x1 * s + x2 * c,
                     2 * x3,
                     3 * (x1 * c - x2 * s),
                     x1,
                     0.5 - s * s / 4,
                     0,
                     2,
                     0};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Mass functions, by hand: the rod's mass centre at (L/2)(cos Q, sin Q), P1 at L (cos Q, sin Q),
// P2 at (0, 2L); MASS() = MASS(A, P1, P2) = MA + M1 + M2 = m; CM(NO) = (MA L/2 + M1 L)(cos Q,
// sin Q)/m + (0, 2 L M2/m); CM(P2, A, P1) = (MA L/2 + M1 L)(cos Q, sin Q)/(MA + M1) - (0, 2L);
// ANGVEL(N, A) = Q' N3>.
TEST(AutolevAcceptanceFiles, MassFunctionsAgreeWithTheHandResults) {
    AutolevTranslation t = import("mass_functions.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2033);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double l = uniform(0.2, 2), m1 = uniform(0.5, 3), m2 = uniform(0.5, 3), ma = uniform(0.5, 3);
        const double q = uniform(-3, 3), u = uniform(-4, 4);
        std::string at = "L = " + num(l) + ", M1 = " + num(m1) + ", M2 = " + num(m2) + ", MA = " + num(ma) +
                         ", Q = " + num(q) + ", Q' = " + num(u);
        Vec v = evaluate(t, {"MT", "MALL", "RX", "RY", "SX", "SY", "WZ"}, at);
        const double m = ma + m1 + m2, arm = ma * l / 2 + m1 * l;
        Vec expected{m,
                     m,
                     arm * std::cos(q) / m,
                     arm * std::sin(q) / m + 2 * l * m2 / m,
                     arm * std::cos(q) / (ma + m1),
                     arm * std::sin(q) / (ma + m1) - 2 * l,
                     u};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Terms and coefficients, by hand: E = M L^2 U^2/2 - M G L cos Q + K Q^2/2 (U is Q') has the
// kinetic term KE = M L^2 U^2/2, the rest PE = -M G L cos Q + K Q^2/2, of which the term with G
// is -M G L cos Q and the term with neither U nor G is K Q^2/2; the terms of [E; K Q + G] with
// Q are [PE; K Q] (cos Q holds Q). (Q - 1)(Q - 2)(K Q + M) = K Q^3 + (M - 3K) Q^2 +
// (2K - 3M) Q + 2M; Q^2 - 5Q + 6 has the roots 2 and 3; the polynomial of the coefficients
// less P is 0.
TEST(AutolevAcceptanceFiles, TermsAndCoefficientsAgreeWithTheHandResults) {
    AutolevTranslation t = import("terms_and_coefficients.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2034);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double m = uniform(0.5, 3), g = uniform(9, 10), l = uniform(0.2, 2), k = uniform(1, 20);
        const double q = uniform(-3, 3), u = uniform(-4, 4);
        std::string at = "M = " + num(m) + ", G = " + num(g) + ", L = " + num(l) + ", K = " + num(k) + ", Q = " + num(q) +
                         ", Q' = " + num(u);
        Vec v = evaluate(t, {"KE", "PE", "GRAV", "SPRING", "T1", "T2", "C1", "C2", "C3", "C4", "R2", "BACK"}, at);
        const double pe = -m * g * l * std::cos(q) + k * q * q / 2;
        Vec expected{m * l * l * u * u / 2,
                     pe,
                     -m * g * l * std::cos(q),
                     k * q * q / 2,
                     pe,
                     k * q,
                     k,
                     m - 3 * k,
                     2 * k - 3 * m,
                     2 * m,
                     3,
                     0};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// Normal modes, by hand: for a 2 by 2 matrix [a, b; c, d], lambda = ((a + d) -+ sqrt((a - d)^2
// + 4 b c))/2 with the eigenvector (-b, a - lambda), over its length, its largest component
// positive. M^-1 K = [2K/M1, -K/M1; -K/M2, K/M2] (K = 3, M1 = 1.5, M2 = 0.5, the file's values)
// gives the squared frequencies and the mode shapes; K alone, [2K, -K; -K, K], is symmetric.
TEST(AutolevAcceptanceFiles, NormalModesAgreeWithTheHandResults) {
    AutolevTranslation t = import("normal_modes.al");
    ASSERT_TRUE(t.ok());
    const double k = 3, m1 = 1.5, m2 = 0.5;
    // the eigenvalues, then the eigenvectors by columns
    auto eigen2 = [](double a, double b, double c, double d) {
        const double root = std::sqrt((a - d) * (a - d) + 4 * b * c);
        Vec out{((a + d) - root) / 2, ((a + d) + root) / 2};
        for (int j = 0; j < 2; ++j) {
            double x = -b, y = a - out[static_cast<std::size_t>(j)];
            const double length = std::hypot(x, y);
            const double sign = (std::abs(x) >= std::abs(y) ? x : y) < 0 ? -1 : 1;
            out.push_back(sign * x / length);
            out.push_back(sign * y / length);
        }
        return out;
    };
    const Vec modes = eigen2(2 * k / m1, -k / m1, -k / m2, k / m2), stiff = eigen2(2 * k, -k, -k, k);
    std::string extra;
    const std::vector<std::string> names{"W1SQ", "W2SQ", "OMEGA1", "X11", "X21", "X12", "X22",
                                         "KV1",  "KV2",  "S11",    "S21", "S12", "S22"};
    for (const std::string& n : names) extra += "evaluate " + n + "\n";
    ScriptRun r = run(t.script, extra);
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    ASSERT_GE(r.values.size(), names.size()) << r.out;
    Vec v(r.values.end() - static_cast<std::ptrdiff_t>(names.size()), r.values.end());
    Vec expected{modes[0], modes[1], std::sqrt(modes[0]), modes[2], modes[3], modes[4], modes[5],
                 stiff[0], stiff[1], stiff[2],              stiff[3], stiff[4], stiff[5]};
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << names[i] << "\n" << r.out;
    // the symmetric matrix's eigenvectors are orthogonal
    EXPECT_NEAR(v[9] * v[11] + v[10] * v[12], 0, 1e-15);
}

// Arrays assigned by element, by hand: the masses between springs have
//   M1 X1'' = -K1 X1 + K2 (X2 - X1),  M2 X2'' = -K2 (X2 - X1) - C X2';
// the stiffness matrix [K1 + K2, -K2; -K2, K2] has determinant K1 K2, and with its last element
// K2 + C, (K1 + K2)(K2 + C) - K2^2 and trace K1 + 2 K2 + C; P1 + P2 = L and P1 - P2 = H give
// P1 = (L + H)/2, P2 = (L - H)/2; the particle M at L A1> on the arm turned by Q under gravity
// -G N2> has, along A2>, -M G cos Q = M L Q'', so Q'' = -G cos Q / L.
TEST(AutolevAcceptanceFiles, ArraysByElementAgreeWithTheHandResults) {
    AutolevTranslation t = import("arrays_by_element.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2035);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double m1 = uniform(0.5, 3), m2 = uniform(0.5, 3), k1 = uniform(1, 50), k2 = uniform(1, 50);
        const double c = uniform(0.1, 5), l = uniform(0.2, 2), h = uniform(-1, 1), m = uniform(0.5, 3);
        const double g = uniform(9, 10), x1 = uniform(-1, 1), x2 = uniform(-1, 1), x2d = uniform(-3, 3);
        const double q = uniform(-3, 3);
        std::string at = "M1 = " + num(m1) + ", M2 = " + num(m2) + ", K1 = " + num(k1) + ", K2 = " + num(k2) +
                         ", C = " + num(c) + ", L = " + num(l) + ", H = " + num(h) + ", M = " + num(m) +
                         ", G = " + num(g) + ", X1 = " + num(x1) + ", X2 = " + num(x2) + ", X2' = " + num(x2d) +
                         ", Q = " + num(q);
        Vec v = evaluate(t, {"A1", "A2", "DK", "DK2", "TK", "S1", "S2", "QDD"}, at);
        Vec expected{(-k1 * x1 + k2 * (x2 - x1)) / m1,
                     (-k2 * (x2 - x1) - c * x2d) / m2,
                     k1 * k2,
                     (k1 + k2) * (k2 + c) - k2 * k2,
                     k1 + 2 * k2 + c,
                     (l + h) / 2,
                     (l - h) / 2,
                     -g * std::cos(q) / l};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// EIG(M, VALUES), by hand: [3, -1; -1, 1] has the characteristic polynomial x^2 - 4x + 2, so
// the eigenvalues 2 - sqrt 2 and 2 + sqrt 2; [4, 1; 2, 3] has x^2 - 7x + 10, so 2 and 5.
TEST(AutolevAcceptanceFiles, EigenvaluesAloneAgreeWithTheHandResults) {
    AutolevTranslation t = import("eig_values.al");
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t.script.find("eigvec"), std::string::npos) << t.script;
    const std::vector<std::string> names{"W2A", "W2B", "E1", "E2"};
    std::string extra;
    for (const std::string& n : names) extra += "evaluate " + n + "\n";
    ScriptRun r = run(t.script, extra);
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    ASSERT_GE(r.values.size(), names.size()) << r.out;
    Vec v(r.values.end() - static_cast<std::ptrdiff_t>(names.size()), r.values.end());
    Vec expected{2 - std::sqrt(2.0), 2 + std::sqrt(2.0), 2, 5};
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << names[i] << "\n" << r.out;
}

// Products and rates of dyadics, by hand, with B turned from N by Q about N3> (N1>.B1> = cos Q,
// N1>.B2> = -sin Q, N3> = B3>): (A N1> B1> + B2> N3>) . (K B1> N2> + N3> B3>) = A K N1> N2> +
// B2> B3> (B1>.B1> = N3>.N3> = 1, B1>.N3> = 0), so N1>.F.N2> = A K, B2>.F.B3> = 1 and
// N1>.F.N1> = 0; in N, B1> has the rate Q' B2>, so d/dt (B1> B1>) = Q' (B2> B1> + B1> B2>), whose
// B1>, B2> measure is Q' and N1>, N1> measure d/dt cos^2 Q = -2 sin Q cos Q Q'; in B, N1> has the
// rate -Q' N2> and B1>, B2>, N3> none, so d/dt D = -A Q' N2> B1>.
TEST(AutolevAcceptanceFiles, DyadicProductsAndRatesAgreeWithTheHandResults) {
    AutolevTranslation t = import("dyadic_products.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2036);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double a = uniform(-2, 2), k = uniform(-2, 2), q = uniform(-3, 3), u = uniform(-3, 3);
        std::string at = "A = " + num(a) + ", K = " + num(k) + ", Q = " + num(q) + ", Q' = " + num(u);
        Vec v = evaluate(t, {"F12", "F23", "F11", "G12", "G11", "H21", "H23"}, at);
        Vec expected{a * k, 1, 0, u, -2 * std::sin(q) * std::cos(q) * u, -a * u, 0};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// A1PT, by hand: the cart's point O at X N1> accelerates by X'' N1> = X'' (cos Q B1> - sin Q B2>),
// and the slider P at R B1> on the arm B turning by Q adds (R'' - R Q'^2) B1> + (2 R' Q' + R Q'')
// B2>, so along B1> X'' cos Q + R'' - R Q'^2, along B2> -X'' sin Q + 2 R' Q' + R Q'', along N3> 0.
TEST(AutolevAcceptanceFiles, OnePointAccelerationAgreesWithTheHandDerivation) {
    AutolevTranslation t = import("one_point_acceleration.al");
    ASSERT_TRUE(t.ok());
    std::mt19937 rng(2037);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 3; ++trial) {
        const double q = uniform(-3, 3), r = uniform(-2, 2), qd = uniform(-3, 3), rd = uniform(-3, 3);
        const double qdd = uniform(-5, 5), rdd = uniform(-5, 5), xdd = uniform(-5, 5), x = uniform(-2, 2);
        std::string at = "X = " + num(x) + ", Q = " + num(q) + ", R = " + num(r) + ", Q' = " + num(qd) +
                         ", R' = " + num(rd) + ", X'' = " + num(xdd) + ", Q'' = " + num(qdd) + ", R'' = " + num(rdd);
        Vec v = evaluate(t, {"AR", "AT", "AZ"}, at);
        Vec expected{xdd * std::cos(q) + rdd - r * qd * qd, -xdd * std::sin(q) + 2 * rd * qd + r * qdd, 0};
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(v[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << i << " at " << at;
    }
}

// A model with a motion constraint (DEPENDENT[1], CONSTRAIN) and speeds of its own: the
// Chaplygin sled, a body on a knife edge at P that cannot slide sideways, its mass centre a
// ahead of P. By hand, with v = U1 (P's forward speed), w = U2 (the turn rate) and
// J = IZ + M A^2: along B1> M (v' - A w^2) = 0, and about the mass centre IZ w' = -A lambda with
// lambda = M (v w + A w') the knife's force, so
//   v' = A w^2,  J w' = -M A v w.
// The energy (M v^2 + J w^2)/2 is kept, so v' = k (V^2 - v^2) with k = M A / J and
// V^2 = v0^2 + J w0^2 / M:
//   v = V tanh(k V t + c0), c0 = atanh(v0 / V),  w = w0 cosh(c0) / cosh(k V t + c0).
// The imported file simulates in its speeds, follows that closed form at every row and keeps
// its constraint; its CODE DYNAMICS() generates C for the same equations.
TEST(AutolevAcceptanceFiles, ConstrainedSledSimulatesAsItsClosedForm) {
    AutolevTranslation t = import("chaplygin_sled.al");
    ASSERT_TRUE(t.ok());
    EXPECT_NE(t.script.find("constraints [dot(vel(P, N), By>)] dependent U3"), std::string::npos) << t.script;
    EXPECT_NE(t.script.find("codegen c name sled"), std::string::npos) << t.script;
    const std::string dir = "acceptance_chaplygin_sled";
    ScriptRun r = run(t.script, "tolerance abs 1e-12 rel 1e-12\nsimulate plot none to \"" + dir + "\"");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    EXPECT_NE(r.out.find("generated C for 'sled'"), std::string::npos) << r.out;
    auto table = read_table((std::filesystem::path(::testing::TempDir()) / dir / "simulation.csv").string());
    ASSERT_TRUE(table.count("U1") && table.count("U2") && table.count("energy") && table.count("drift_motion_1"))
        << t.script;
    const double m = 3, iz = 0.2, a = 0.4, v0 = -0.5, w0 = 2;
    const double J = iz + m * a * a, V = std::sqrt(v0 * v0 + J * w0 * w0 / m), k = m * a / J;
    const double c0 = std::atanh(v0 / V);
    const Vec& time = table["t"];
    ASSERT_EQ(time.size(), 31u);
    EXPECT_DOUBLE_EQ(time.back(), 3.0);
    const double e0 = (m * v0 * v0 + J * w0 * w0) / 2;
    for (std::size_t i = 0; i < time.size(); ++i) {
        const double ti = time[i];
        EXPECT_NEAR(table["U1"][i], V * std::tanh(k * V * ti + c0), 1e-9) << "t = " << ti;
        EXPECT_NEAR(table["U2"][i], w0 * std::cosh(c0) / std::cosh(k * V * ti + c0), 1e-9) << "t = " << ti;
        EXPECT_NEAR(table["energy"][i], e0, 1e-10) << "t = " << ti;
        EXPECT_LE(std::abs(table["drift_motion_1"][i]), 1e-14) << "t = " << ti;
    }
}

// Auxiliary speeds and KANE(T): the rod's tension of a pendulum, brought out by an auxiliary
// speed along the rod (AUXILIARY[1] = U2, the speed itself) or by the rod's constraint written
// as an auxiliary one (AUXILIARY[1] = DOT(V_P_N>, P_NO_P>), solved for U2). By hand, with e
// the unit vector from the pin to P: m a.e = -T - m g e.N2> and a.e = -v^2 / L, so
// T = m v^2 / L - m g e.N2> at every row.
// The imported file simulates, T is a column of its own, and the energy is kept.
TEST(AutolevAcceptanceFiles, AuxiliarySpeedsGiveTheRodsTensionAsDerivedByHand) {
    struct File {
        const char* name;
        const char* aux;  // what the kane statement must say
        double L, m;
    };
    for (const File& f : {File{"auxiliary_rod_tension.al", "auxiliary U2", 1.5, 2},
                          File{"auxiliary_cartesian_rod.al", "dependent U2 \\\n  auxiliary UA_U2", 1.2, 0.5}}) {
        SCOPED_TRACE(f.name);
        AutolevTranslation t = import(f.name);
        ASSERT_TRUE(t.ok());
        EXPECT_NE(t.script.find(f.aux), std::string::npos) << t.script;
        EXPECT_NE(t.script.find("unknown T\n"), std::string::npos) << t.script;
        const std::string dir = std::string("acceptance_") + f.name;
        ScriptRun r = run(t.script, "final time 3\noutput step 0.1\ntolerance abs 1e-12 rel 1e-12\n"
                                    "simulate plot none to \"" + dir + "\"");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        auto table = read_table((std::filesystem::path(::testing::TempDir()) / dir / "simulation.csv").string());
        ASSERT_TRUE(table.count("T") && table.count("energy")) << t.script;
        const Vec& time = table["t"];
        ASSERT_EQ(time.size(), 31u);
        double lowest = 1e9, highest = -1e9;
        for (std::size_t i = 0; i < time.size(); ++i) {
            double v2 = 0, up = 0;  // v^2 and e.N2>
            if (table.count("Q")) {
                const double q = table["Q"][i], u = table["U1"][i];
                v2 = f.L * f.L * u * u;
                up = std::sin(q);
            } else {
                const double u1 = table["U1"][i], u2 = table["U2"][i];
                v2 = u1 * u1 + u2 * u2;
                up = table["Y"][i] / f.L;
            }
            const double T = f.m * v2 / f.L - f.m * kG * up;
            EXPECT_NEAR(table["T"][i], T, 1e-9 * std::max(1.0, std::abs(T))) << "t = " << time[i];
            EXPECT_NEAR(table["energy"][i], table["energy"][0], 1e-9 * std::max(1.0, std::abs(table["energy"][0])));
            lowest = std::min(lowest, table["T"][i]);
            highest = std::max(highest, table["T"][i]);
        }
        EXPECT_GT(highest - lowest, 0.1 * f.m * kG) << "it swung";
    }
    // files that bring out forces often name them in ZEE_NOT (keep them out of Autolev's Z
    // intermediates): left out with a warning at its line, the script otherwise the same
    std::string source = read_file(kDir + "auxiliary_rod_tension.al");
    const std::size_t zero = source.find("ZERO = FR()");
    ASSERT_NE(zero, std::string::npos);
    source.insert(zero, "ZEE_NOT = [T]\n");
    AutolevTranslation with = translate_autolev(source, "zee.al");
    AutolevTranslation without = translate_autolev(read_file(kDir + "auxiliary_rod_tension.al"), "zee.al");
    ASSERT_TRUE(with.ok());
    int warnings = 0;
    for (const auto& d : with.diagnostics)
        if (d.severity == Severity::warning) {
            ++warnings;
            EXPECT_EQ(d.location.line, 18);
            EXPECT_NE(d.message.find("ZEE_NOT is not translated"), std::string::npos) << d.message;
        }
    EXPECT_EQ(warnings, 1);
    EXPECT_EQ(with.script, without.script);
}

// Statements left out: each at its line and column with its reason, a comment at its place in
// the script, the statements that use what it defined left out in turn (naming the line), and
// the equations of motion said to lack a force that was left out.
TEST(AutolevAcceptanceFiles, LeftOutStatementsAreSaidLineByLine) {
    auto says = [](const AutolevTranslation& t, int line, int column, const std::string& part) {
        for (const auto& d : t.diagnostics)
            if (d.severity == Severity::warning && d.location.line == line && d.location.column == column &&
                d.message.find(part) != std::string::npos)
                return true;
        return false;
    };
    AutolevTranslation a = import("left_out_no_counterpart.al", {4, 8, 16, 17});
    EXPECT_TRUE(says(a, 4, 1, "left out: COMPLEX ON has no counterpart"));
    EXPECT_TRUE(says(a, 8, 23, "left out in part: 'C{...}' has 3 indices"));
    EXPECT_TRUE(says(a, 16, 5, "left out: the Autolev function SQR() has no translation"));
    EXPECT_TRUE(says(a, 17, 1, "left out: an array of 3 indices ('E[...]')"));
    for (int line : {4, 8, 16, 17})
        EXPECT_NE(a.script.find("# left out (left_out_no_counterpart.al:" + std::to_string(line) + "): "),
                  std::string::npos)
            << a.script;
    EXPECT_NE(a.script.find("constant L = 0.9, M = 1.2, G = 9.81, K = 3\n"), std::string::npos) << a.script;
    EXPECT_EQ(a.script.find("lack"), std::string::npos) << a.script;  // the model is whole
    // H, worked out from the model's names, is kept: M L^2 Q'^2/2 + M G L sin Q + K Q^2/2
    ScriptRun h = run(a.script, "evaluate H at Q = 0.5, Q' = 2");
    ASSERT_EQ(h.status, RunStatus::ok) << h.err;
    ASSERT_FALSE(h.values.empty()) << h.out;
    EXPECT_NEAR(h.values.back(), 1.2 * 0.81 * 2 + 1.2 * kG * 0.9 * std::sin(0.5) + 1.5 * 0.25, 1e-12);

    AutolevTranslation b = import("left_out_chain.al", {13, 14, 15, 16}, 19);
    EXPECT_TRUE(says(b, 13, 21, "left out: the Autolev function SIGN() has no translation"));
    EXPECT_TRUE(says(b, 14, 5, "left out: the Autolev function KE() has no translation"));
    EXPECT_TRUE(says(b, 15, 5, "left out: uses E, which line 14 left out"));
    EXPECT_TRUE(says(b, 16, 14, "left out in part: uses H, which line 15 left out"));  // OUTPUT keeps T, X
    EXPECT_NE(b.script.find("\noutput X\n"), std::string::npos) << b.script;
    EXPECT_TRUE(says(b, 19, 1,
                     "the equations of motion are formed without what line 13 (FORCE_P> += ...) left out, so they "
                     "are not the Autolev file's equations"));
    EXPECT_NE(b.script.find("# left out (left_out_chain.al:15): uses E, which line 14 left out\n"
                            "# left out (left_out_chain.al:16): uses H, which line 15 left out\nS = K*X^2/2\n"),
              std::string::npos)
        << b.script;
    EXPECT_NE(b.script.find("# the equations below lack what line 13 (FORCE_P> += ...) left out"), std::string::npos)
        << b.script;
    // what is left runs: S, which uses no left-out name, is the spring's energy
    ScriptRun s = run(b.script, "evaluate S at X = 0.5");
    ASSERT_EQ(s.status, RunStatus::ok) << s.err;
    ASSERT_FALSE(s.values.empty()) << s.out;
    EXPECT_NEAR(s.values.back(), 8 * 0.25 / 2, 1e-12);
}

// CONSTRAIN(DEPENDENT[Y']) in a model without speeds: each coordinate gets a speed u = q' and
// Y's is dependent. By hand, with Y' = -X X'/Y, the partial velocity of P for X' is
// N1> - X/Y N2>, and Kane's equation M G X/Y - M (X'' - X/Y Y'') = 0 gives
// X'' = (G X Y^3 - X X'^2 (X^2 + Y^2)) / (Y^2 (X^2 + Y^2)); at random states to 1e-12. Simulated,
// the energy M (X'^2 + Y'^2)/2 + M G Y is kept to 1e-9, and so are the rod's length and the
// velocity across it.
TEST(AutolevAcceptanceFiles, DependentRateWithoutSpeedsAgreesWithTheHandDerivation) {
    AutolevTranslation t = translate_autolev(read_file(kDir + "rate_dependent.al"), "rate_dependent.al");
    ASSERT_TRUE(t.ok());
    bool noted = false;
    for (const auto& d : t.diagnostics) {
        EXPECT_EQ(d.severity, Severity::note) << d.message;
        noted = noted || d.message.find("each coordinate is given one equal to its rate (X_u = X', Y_u = Y')") !=
                             std::string::npos;
    }
    EXPECT_TRUE(noted);
    EXPECT_NE(t.script.find("kane K for X, Y speeds X_u, Y_u \\\n  kinematics [X' - X_u, Y' - Y_u] \\\n"
                            "  constraints [X*X' + Y*Y'] dependent Y_u\n"),
              std::string::npos)
        << t.script;
    const double m = 0.7;
    std::mt19937 rng(20261128);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (int trial = 0; trial < 4; ++trial) {
        const double x = uniform(-2, 2), y = uniform(0.3, 2) * (trial % 2 ? 1 : -1), u = uniform(-3, 3);
        ScriptRun r = run(t.script, "solve K for X_u' at X = " + num(x) + ", Y = " + num(y) + ", X_u = " + num(u));
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        ASSERT_TRUE(r.named.count("X_u'")) << r.out;
        const double r2 = x * x + y * y;
        const double expected = (kG * x * y * y * y - x * u * u * r2) / (y * y * r2);
        EXPECT_NEAR(r.named["X_u'"], expected, 1e-12 * std::max(1.0, std::abs(expected))) << x << " " << y << " " << u;
    }
    const std::string dir = "acceptance_rate_dependent";
    ScriptRun r = run(t.script, "final time 5\ntolerance abs 1e-12 rel 1e-12\nintegrator rkf78\nsimulate plot none to \"" +
                                    dir + "\"");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    auto table = read_table((std::filesystem::path(::testing::TempDir()) / dir / "simulation.csv").string());
    ASSERT_TRUE(table.count("X_u") && table.count("Y_u") && table.count("t")) << t.script;
    EXPECT_NEAR(table["t"].back(), 5, 1e-12);
    Change e = change_over_rows(table, [&](const Row& at) {
        return m * (at("X_u") * at("X_u") + at("Y_u") * at("Y_u")) / 2 + m * kG * at("Y");
    });
    EXPECT_NEAR(e.first, m * (1.44 + 0.81) / 2 - m * kG * 0.8, 1e-12);
    EXPECT_LE(e.largest, 1e-9 * e.scale);
    Change across = change_over_rows(table, [](const Row& at) { return at("X") * at("X_u") + at("Y") * at("Y_u"); });
    EXPECT_LE(std::abs(across.first), 1e-12);
    EXPECT_LE(across.largest, 1e-9);
    Change length = change_over_rows(table, [](const Row& at) { return std::hypot(at("X"), at("Y")); });
    EXPECT_NEAR(length.first, 1.0, 1e-12);
    EXPECT_LE(length.largest, 1e-9);
    // it swings: X changes sign
    Change x = change_over_rows(table, [](const Row& at) { return at("X"); });
    EXPECT_GT(x.largest, 0.6);
}

// ---- the classic models of tests/lang/autolev/models/, simulated ------------------------
// Each file is imported unchanged; the lines added after it give what the file leaves open
// (an assembled initial state, a specified load's value) and a tight tolerance. Over five
// seconds the energy, worked out by hand from the columns, is kept where no load does work;
// otherwise the motion is checked against a balance or a closed form.

const std::string kModels = std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/models/";

std::map<std::string, Vec> simulate_model(const std::string& model, const std::string& extra) {
    AutolevTranslation t = translate_autolev(read_file(kModels + model + ".al"), model + ".al");
    for (const auto& d : t.diagnostics)
        if (d.severity != Severity::note)
            ADD_FAILURE() << model << ".al:" << d.location.line << ":" << d.location.column << ": " << d.message;
    if (!t.ok()) return {};
    const std::string dir = "models_" + model;
    ScriptRun r = run(t.script, extra + "\ntolerance abs 1e-12 rel 1e-12\nintegrator rkf78\nfinal time 5\n" +
                                    "simulate plot none to \"" + dir + "\"");
    EXPECT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    if (r.status != RunStatus::ok) return {};
    auto table = read_table((std::filesystem::path(::testing::TempDir()) / dir / "simulation.csv").string());
    EXPECT_TRUE(table.count("t")) << t.script;
    if (table.count("t")) {
        EXPECT_GE(table["t"].size(), 2u) << model;
        EXPECT_NEAR(table["t"].back(), 5, 1e-12) << model;
    }
    return table;
}

// A uniform rod (L = 0.8, M = 1.5) about its end from the file's 20 deg at rest:
// E = M L^2 Q'^2 / 6 - M G L cos(Q) / 2.
TEST(AutolevModelsSimulate, SimplePendulumKeepsItsEnergy) {
    auto table = simulate_model("simple_pendulum", "");
    const double L = 0.8, M = 1.5;
    Change e = change_over_rows(table, [&](const Row& at) {
        return M * L * L * at("Q'") * at("Q'") / 6 - M * kG * L * std::cos(at("Q")) / 2;
    });
    EXPECT_NEAR(e.first, -M * kG * L * std::cos(20 * kDeg) / 2, 1e-12);
    EXPECT_LE(e.largest, 1e-9 * e.scale);
    // it swings through the bottom: Q changes sign
    Change q = change_over_rows(table, [](const Row& at) { return at("Q"); });
    EXPECT_GT(q.largest, 30 * kDeg);
}

// The rod A (LA = 0.6, MA = 0.8) about N1> through THETA, the plate B (side S = 0.3,
// MB = 1.3) at LB = 0.45 spinning about A3> through PHI, from THETA = 90 deg, PHI = 1 deg and
// (added) rates 1 and 2 rad/s. With A1> = cos(PHI) B1> - sin(PHI) B2>:
//   T = (MA LA^2/3 + MB LB^2) THETA'^2/2 + (I11 cos^2 PHI + I22 sin^2 PHI) THETA'^2/2 + I33 PHI'^2/2,
//   V = -G (MA LA/2 + MB LB) cos(THETA),   I11 = I33 = MB S^2/12, I22 = MB S^2/6.
TEST(AutolevModelsSimulate, ChaoticPendulumKeepsItsEnergy) {
    auto table = simulate_model("chaotic_pendulum", "initial THETA' = 1, PHI' = 2");
    const double LA = 0.6, LB = 0.45, MA = 0.8, MB = 1.3, S = 0.3;
    const double i11 = MB * S * S / 12, i22 = MB * S * S / 6, i33 = i11;
    Change e = change_over_rows(table, [&](const Row& at) {
        const double th = at("THETA"), ph = at("PHI"), w = at("THETA'"), a = at("PHI'");
        const double c = std::cos(ph), s = std::sin(ph);
        return (MA * LA * LA / 3 + MB * LB * LB + i11 * c * c + i22 * s * s) * w * w / 2 + i33 * a * a / 2 -
               kG * (MA * LA / 2 + MB * LB) * std::cos(th);
    });
    EXPECT_LE(e.largest, 1e-9 * e.scale);
}

// The particle (M = 0.5) on the massless rod of length 1.2 in the coordinates X, Y, its
// speed U2 dependent on U1 through the rod (X U1 + Y U2 = 0), from the file's X = 0.6,
// Y = -1.03923: E = M (U1^2 + U2^2)/2 + M G Y is
// kept, the velocity stays perpendicular to the rod and the rod keeps its length.
TEST(AutolevModelsSimulate, CartesianPendulumKeepsItsEnergyAndItsRod) {
    // moving at U1 = 1 m/s (added); the file's U2 = 0 is replaced by the value the rod gives it
    auto table = simulate_model("nonminimal_pendulum", "initial U1 = 1, U2 = " + num(0.6 / 1.03923));
    const double M = 0.5;
    Change e = change_over_rows(table, [&](const Row& at) {
        return M * (at("U1") * at("U1") + at("U2") * at("U2")) / 2 + M * kG * at("Y");
    });
    EXPECT_LE(e.largest, 1e-9 * e.scale);
    Change along = change_over_rows(table, [](const Row& at) { return at("X") * at("U1") + at("Y") * at("U2"); });
    EXPECT_LE(std::abs(along.first), 1e-12);
    EXPECT_LE(along.largest, 1e-9);
    Change length = change_over_rows(table, [](const Row& at) { return std::hypot(at("X"), at("Y")); });
    EXPECT_NEAR(length.first, 1.2, 1e-5);  // the file's Y = -1.03923 is 1.2 cos(30 deg) to six figures
    EXPECT_LE(length.largest, 1e-8);
}

// The four-bar (crank LA = 0.2, coupler LB = 0.5, rocker LC = 0.4, ground LN = 0.45; masses
// 1, 2, 1.5) driven by a constant TA = 0.3 N m from an assembled state: Q1 = 1 rad turning at
// U1 = 2 rad/s, Q2 and Q3 where the circles about the crank's tip and about D meet. The
// torque's work TA (Q1 - Q1(0)) is the change of the energy; the loop stays closed.
TEST(AutolevModelsSimulate, FourBarBalancesItsEnergyWithTheMotorAndStaysClosed) {
    const double LA = 0.2, LB = 0.5, LC = 0.4, LN = 0.45, MA = 1, MB = 2, MC = 1.5, TA = 0.3;
    const double q1 = 1;
    const double px = LA * std::cos(q1), py = LA * std::sin(q1);
    const double dx = LN - px, dy = -py, d = std::hypot(dx, dy);
    const double a = (LB * LB - LC * LC + d * d) / (2 * d), h = std::sqrt(LB * LB - a * a);
    const double qx = px + a * dx / d - h * dy / d, qy = py + a * dy / d + h * dx / d;
    const double q2 = std::atan2(qy - py, qx - px), q3 = std::atan2(qy, qx - LN);
    auto table = simulate_model("four_bar", "input TA = " + num(TA) + "\ninitial Q1 = " + num(q1) + ", Q2 = " +
                                                num(q2) + ", Q3 = " + num(q3) + ", U1 = 2");
    // the energy less the motor's work
    Change balance = change_over_rows(table, [&](const Row& at) {
        const double c1 = std::cos(at("Q1")), s1 = std::sin(at("Q1")), c2 = std::cos(at("Q2")), s2 = std::sin(at("Q2"));
        const double u1 = at("U1"), u2 = at("U2"), u3 = at("U3");
        // B's mass centre moves at LA U1 a2> + LB/2 U2 b2>, a2> = (-s1, c1), b2> = (-s2, c2)
        const double vx = -LA * u1 * s1 - LB / 2 * u2 * s2, vy = LA * u1 * c1 + LB / 2 * u2 * c2;
        const double t = MA * LA * LA / 3 * u1 * u1 / 2 + MB * (vx * vx + vy * vy) / 2 + MB * LB * LB / 12 * u2 * u2 / 2 +
                         MC * LC * LC / 3 * u3 * u3 / 2;
        const double v = kG * (MA * LA / 2 * s1 + MB * (LA * s1 + LB / 2 * s2) + MC * LC / 2 * std::sin(at("Q3")));
        return t + v - TA * at("Q1");
    });
    EXPECT_LE(balance.largest, 1e-9 * std::max(1.0, balance.scale));
    // the linkage moves a good way: the crank swings through more than a radian
    Change crank = change_over_rows(table, [](const Row& at) { return at("Q1"); });
    EXPECT_GT(crank.largest, 1.0);
    // the loop closes at the coupler-rocker pin: LA a1> + LB b1> = LN n1> + LC c1>
    for (int axis = 0; axis < 2; ++axis) {
        Change gap = change_over_rows(table, [&](const Row& at) {
            auto along = [axis](double q) { return axis == 0 ? std::cos(q) : std::sin(q); };
            return LA * along(at("Q1")) + LB * along(at("Q2")) - (axis == 0 ? LN : 0) - LC * along(at("Q3"));
        });
        EXPECT_LE(std::abs(gap.first), 1e-12) << axis;
        EXPECT_LE(gap.largest, 1e-9) << axis;
    }
}

// The symmetric rotor (L = 0.05, M = 0.3, IT = 4e-4, IS = 6e-4) from the file's 30 deg
// nutation and 200 rad/s spin, precessing at (added) 1 rad/s. In 3-1-3 angles
// w1^2 + w2^2 = Q1'^2 sin^2 Q2 + Q2'^2 and w3 = Q1' cos Q2 + Q3', so
//   E = (IT + M L^2)(Q1'^2 sin^2 Q2 + Q2'^2)/2 + IS w3^2/2 + M G L cos Q2,
// and the spin w3 about the symmetry axis is kept too.
TEST(AutolevModelsSimulate, GyroscopeKeepsItsEnergyAndSpin) {
    auto table = simulate_model("gyroscope", "initial Q1' = 1");
    const double L = 0.05, M = 0.3, IT = 4e-4, IS = 6e-4;
    auto spin = [](const Row& at) { return at("Q1'") * std::cos(at("Q2")) + at("Q3'"); };
    Change e = change_over_rows(table, [&](const Row& at) {
        const double s2 = std::sin(at("Q2")), w3 = spin(at);
        return (IT + M * L * L) * (at("Q1'") * at("Q1'") * s2 * s2 + at("Q2'") * at("Q2'")) / 2 + IS * w3 * w3 / 2 +
               M * kG * L * std::cos(at("Q2"));
    });
    EXPECT_LE(e.largest, 1e-9 * e.scale);
    Change w3 = change_over_rows(table, spin);
    EXPECT_NEAR(w3.first, std::cos(30 * kDeg) + 200, 1e-12);
    EXPECT_LE(w3.largest, 1e-9 * w3.scale);
}

// The block (M = 2, K = 50, C = 3, LN = 0.4) pushed by a constant F = 10 from X = 0.1 at rest
// is damped: its energy is not kept, but it follows the closed form about the equilibrium
// LN + F/K = 0.6, x = 0.6 + exp(-s t)(A cos(wd t) + B sin(wd t)), s = C/(2M),
// wd = sqrt(K/M - s^2), A = 0.1 - 0.6, B = s A / wd.
TEST(AutolevModelsSimulate, MassSpringDamperFollowsItsClosedForm) {
    auto table = simulate_model("mass_spring_damper", "input F = 10\ninitial X = 0.1, X' = 0");
    const double M = 2, K = 50, C = 3, xe = 0.4 + 10 / K;
    const double s = C / (2 * M), wd = std::sqrt(K / M - s * s), A = 0.1 - xe, B = s * A / wd;
    ASSERT_TRUE(table.count("X") && table.count("X'"));
    const Vec& time = table["t"];
    for (std::size_t i = 0; i < time.size(); ++i) {
        const double t = time[i], decay = std::exp(-s * t), c = std::cos(wd * t), sn = std::sin(wd * t);
        EXPECT_NEAR(table["X"][i], xe + decay * (A * c + B * sn), 1e-9) << "t = " << t;
        EXPECT_NEAR(table["X'"][i], decay * ((B * wd - s * A) * c - (A * wd + s * B) * sn), 1e-9) << "t = " << t;
    }
}

// The rolling disk (R = 0.3, M = 2) leaning 10 deg, spinning at U2 = 8 rad/s and turning at
// U3 = 1 rad/s. The contact point is at rest, so DO moves at R w> x B3>, of squared speed
// R^2 (U1^2 + U2^2), and
//   E = M R^2 (U1^2 + U2^2)/2 + M R^2 (U1^2/4 + U2^2/2 + U3^2/4)/2 + M G R cos(Q2).
TEST(AutolevModelsSimulate, RollingDiskKeepsItsEnergy) {
    auto table = simulate_model("rolling_disk", "initial Q2 = 10 deg, U2 = 8, U3 = 1");
    const double R = 0.3, M = 2;
    Change e = change_over_rows(table, [&](const Row& at) {
        const double u1 = at("U1"), u2 = at("U2"), u3 = at("U3");
        return M * R * R * (u1 * u1 + u2 * u2) / 2 + M * R * R * (u1 * u1 / 4 + u2 * u2 / 2 + u3 * u3 / 4) / 2 +
               M * kG * R * std::cos(at("Q2"));
    });
    EXPECT_LE(e.largest, 1e-9 * e.scale);
    // it rolls: the contact moves, at R U2 along the heading
    Change x = change_over_rows(table, [](const Row& at) { return std::hypot(at("X"), at("Y")); });
    EXPECT_GT(x.largest, 0.5);
}

}  // namespace autolev_acceptance_test
