// SPDX-License-Identifier: MIT
// The linearize statement against hand derivations: the rolling disk's critical spin rate
// sqrt(g/(3 r)) found by a sweep, the inverted pendulum on a cart's eigenvalues
// +-sqrt((M + m) g/(M l)), a pole-placing gain that holds it upright in simulation (and it
// falls without), and the errors that name the user's objects.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace linearize_lang_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

std::string read_example(const std::string& name) {
    std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples" / name / "model.alb");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Dir {
    fs::path path;
    Dir() {
        std::string t = (fs::temp_directory_path() / "alembert-linearize-XXXXXX").string();
        path = ::mkdtemp(t.data());
    }
    ~Dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

struct ScriptRun {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    explicit ScriptRun(const fs::path& dir) { interp.set_output_dir(dir.string()); }
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

// the number after `prefix` on the first line holding it
double number_after(const std::string& text, const std::string& prefix) {
    std::size_t p = text.find(prefix);
    if (p == std::string::npos) {
        ADD_FAILURE() << "no '" << prefix << "' in:\n" << text;
        return NAN;
    }
    return std::stod(text.substr(p + prefix.size()));
}

// the cart-pendulum example's model statements (up to its first linearize)
std::string cart_model() {
    std::string s = read_example("inverted_pendulum_cart");
    return s.substr(0, s.find("\n# upright")) + "\n";
}

TEST(LinearizeStatement, RollingDiskSweepFindsTheCriticalSpinRate) {
    // hand (tests/eom/linearize_test.cpp): upright rolling at spin Omega is stable iff
    // Omega^2 > g/(3 r); r = 0.3 m, g = 9.81 m/s^2 in the example
    Dir d;
    ScriptRun r(d.path);
    std::string out = r.ok("digits 12\n" + read_example("rolling_disk"));
    const double critical = std::sqrt(9.81 / (3 * 0.3));
    EXPECT_NEAR(number_after(out, "a real part crosses zero at Omega = "), critical, 1e-9);
    EXPECT_NE(out.find("unstable below, marginally stable above"), std::string::npos) << out;
    // the CSV: 21 rows from 0 to 10 rad/s; at Omega = 0 the lean falls at
    // lambda = sqrt((4/5) g/r) (lambda^2 = (4/5)(g/r - 3 Omega^2))
    alembert::Table t = alembert::read_csv((d.path / "spin_sweep" / "eigenvalues.csv").string());
    ASSERT_EQ(t.row_count(), 21u);
    EXPECT_EQ(t.names[0], "Omega");
    EXPECT_NEAR(t.columns[t.column_index("re_1")][0], std::sqrt(0.8 * 9.81 / 0.3), 1e-9);
    // at Omega = 10 rad/s every real part is zero and the lean oscillates at sqrt(-lambda^2)
    EXPECT_NEAR(t.columns[t.column_index("re_1")][20], 0, 1e-9);
    EXPECT_NEAR(t.columns[t.column_index("im_1")][20], std::sqrt(0.8 * (3 * 100 - 9.81 / 0.3)), 1e-9);
}

TEST(LinearizeStatement, CartPendulumEigenvaluesAndSecondOrderFormMatchHandDerivation) {
    // point mass m on a massless rod l, cart M: M l th'' = (M + m) g th + F, so
    // lambda = +-sqrt((M + m) g/(M l)); M = 1 kg, m = 0.1 kg, l = 0.5 m
    Dir d;
    ScriptRun r(d.path);
    std::string out = r.ok("digits 12\n" + cart_model() +
                           "linearize K at x = 0, th = 0, x' = 0, th' = 0 inputs F second order\n");
    const double lambda = std::sqrt(1.1 * 9.81 / 0.5);
    EXPECT_NEAR(number_after(out, "lambda1 = "), lambda, 1e-10);
    EXPECT_NEAR(number_after(out, "lambda4 = "), -lambda, 1e-10);
    EXPECT_NEAR(number_after(out, "lambda2 = "), 0, 1e-12);
    EXPECT_NE(out.find("unstable: lambda1"), std::string::npos) << out;
    // A and B by hand: x'' = (F - m g th)/M, th'' = ((M + m) g th + F)/(M l)
    EXPECT_NE(out.find("  [0, g*m/M, 0, 0]\n  [0, g*(M + m)/(l*M), 0, 0]"), std::string::npos) << out;
    EXPECT_NE(out.find("  [0]\n  [0]\n  [1/M]\n  [1/(l*M)]"), std::string::npos) << out;
    // M q'' + K q = H F: M = [[M + m, -m l], [-m l, m l^2]], K = diag(0, -m g l), H = (1, 0)
    EXPECT_NE(out.find("M (mass) =\n  [M + m, -l*m]\n  [-l*m, l^2*m]"), std::string::npos) << out;
    EXPECT_NE(out.find("K (stiffness) =\n  [0, 0]\n  [0, -g*l*m]"), std::string::npos) << out;
    EXPECT_NE(out.find("H (input) =\n  [1]\n  [0]"), std::string::npos) << out;
}

TEST(LinearizeStatement, PlacedGainHoldsTheCartPendulumUprightAndWithoutItItFalls) {
    Dir d;
    ScriptRun r(d.path);
    std::string out = r.ok("digits 12\n" + read_example("inverted_pendulum_cart"));
    // the closed-loop eigenvalues are the poles asked for
    std::size_t closed = out.find("closed-loop eigenvalues");
    ASSERT_NE(closed, std::string::npos) << out;
    const std::string tail = out.substr(closed);
    for (int k = 1; k <= 4; ++k)
        EXPECT_NEAR(number_after(tail, "lambda" + std::to_string(k) + " = "), -1.0 - k, 1e-8);
    // open loop: from 5 deg it passes 90 deg within a second
    alembert::Table open = alembert::read_csv((d.path / "open_loop" / "simulation.csv").string());
    const auto& t_open = open.columns[0];
    const auto& th_open = open.columns[open.column_index("th")];
    EXPECT_NEAR(th_open.back(), 90, 1e-6);
    EXPECT_LT(t_open.back(), 1.0);
    // closed loop: back to upright; the tilt never grows past its start by much, and at 6 s
    // both the tilt and the cart's drift are small
    alembert::Table shut = alembert::read_csv((d.path / "closed_loop" / "simulation.csv").string());
    const auto& th = shut.columns[shut.column_index("th")];
    const auto& x = shut.columns[shut.column_index("x")];
    EXPECT_NEAR(shut.columns[0].back(), 6, 1e-12);
    double worst = 0;
    for (double v : th) worst = std::max(worst, std::abs(v));
    EXPECT_LE(worst, 5 + 1e-9);
    EXPECT_LT(std::abs(th.back()), 1e-2);
    EXPECT_LT(std::abs(x.back()), 1e-3);
    // the simulation's law uses the printed gains' array
    EXPECT_NE(out.find("G = ["), std::string::npos);
}

TEST(LinearizeStatement, ErrorsNameTheEquationsStatesAndTheFix) {
    Dir d;
    ScriptRun r(d.path);
    r.ok(cart_model());
    EXPECT_NE(r.fails("linearize Z at x = 0").find("'Z' holds no equations of motion"), std::string::npos);
    r.ok("Z = [th - 1]");
    EXPECT_NE(r.fails("linearize Z at x = 0").find("hint: form them first: kane Z for q1, q2"), std::string::npos);
    EXPECT_NE(r.fails("linearize K at g = 0").find("'g' is not a state of K"), std::string::npos);
    EXPECT_NE(r.fails("linearize K at th = 0 inputs F poles -1, -2 gains G").find("2 poles for 4 states"),
              std::string::npos);
    EXPECT_NE(r.fails("linearize K at th = 0 poles -1, -2, -3, -4 gains G")
                  .find("pole placement needs exactly one input"),
              std::string::npos);
    EXPECT_NE(r.fails("linearize K at th = 0 for x = 0 to 1 step 0.1").find("'x' is not a constant"),
              std::string::npos);
    EXPECT_NE(r.fails("linearize K at th = 0 for g = 1 to 0 step 0.1").find("a sweep goes up"),
              std::string::npos);
    // a constant without a value: the eigenvalues need it
    r.ok("constant k N/m");
    r.ok("spring s1 between Cart and N_o stiffness k length 0");
    r.ok("kane K2 for x, th");
    EXPECT_NE(r.fails("linearize K2 at th = 0").find("'k' has no value"), std::string::npos);
}

TEST(LinearizeStatement, LagrangeEquationsLinearizeLikeKanesAndChosenSpeedsHaveNoSecondOrderForm) {
    // Lagrange's equations of the cart-pendulum give the same eigenvalues as Kane's
    Dir d;
    ScriptRun r(d.path);
    std::string out = r.ok("digits 12\n" + cart_model() + "lagrange Lg for x, th\nlinearize Lg at th = 0\n");
    EXPECT_NEAR(number_after(out, "lambda1 = "), std::sqrt(1.1 * 9.81 / 0.5), 1e-10);
    // the rolling disk's equations have chosen speeds: no M, C, K form
    ScriptRun disk(d.path);
    std::string model = read_example("rolling_disk");
    disk.ok(model.substr(0, model.find("# Upright rolling")));
    std::string err = disk.fails("linearize K at q2 = 0 second order");
    EXPECT_NE(err.find("the second-order form needs equations in the coordinates' second derivatives; K has chosen speeds"),
              std::string::npos) << err;
    EXPECT_NE(err.find(":1:23:"), std::string::npos) << err;  // at 'second'
}

}  // namespace linearize_lang_test
