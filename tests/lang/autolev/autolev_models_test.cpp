// SPDX-License-Identifier: MIT
// alembert import on eight classic models: each Autolev model (tests/lang/autolev/models/*.al)
// is translated and run, and its equations of motion agree with those of a hand-written
// Alembert script of the same system at random states (and with closed forms where known).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/interpreter.hpp"

namespace {

using alembert::lang::Interpreter;
using alembert::lang::RunStatus;

std::string read_model(const std::string& name) {
    std::ifstream f(std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/models/" + name, std::ios::binary);
    EXPECT_TRUE(f.good()) << name;
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Runs `script` and then `extra`; returns the numbers printed as `name = value`.
std::map<std::string, double> run_numbers(const std::string& script, const std::string& extra,
                                          const std::string& what) {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(::testing::TempDir());  // the files of CODE DYNAMICS go there
    RunStatus s = interp.run(script + "\ndigits 17\n" + extra + "\n", what);
    EXPECT_EQ(s, RunStatus::ok) << what << ":\n" << err.str() << "\n" << script;
    std::map<std::string, double> values;
    std::istringstream lines(out.str());
    std::string line;
    static const std::regex assignment(R"(^(\S+) = (\S+)(\s.*)?$)");
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_match(line, m, assignment)) {
            try {
                values[m[1]] = std::stod(m[2]);
            } catch (const std::exception&) {
                // a symbolic line, not a number
            }
        }
    return values;
}

std::string kane_name(const std::string& script) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(script, m, std::regex(R"(\bkane (\w+) for)"))) << script;
    return m.size() > 1 ? m[1].str() : "K";
}

// One random state: the `at` clauses of the imported and of the hand-written script, and
// accelerations known in closed form (by their names in the imported script).
struct State {
    std::string imported_at;
    std::string hand_at;
    std::map<std::string, double> closed_form{};
};

struct Case {
    std::string model;
    std::string hand_equations;                                 // K, E, ...
    std::vector<std::pair<std::string, std::string>> unknowns;  // imported name, hand name
    std::function<State(std::mt19937&)> state;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.model; }

double uniform(std::mt19937& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

std::string at(const std::vector<std::pair<std::string, double>>& values) {
    std::string s;
    for (const auto& [n, v] : values) s += (s.empty() ? "" : ", ") + n + " = " + num(v);
    return s;
}

const double kG = 9.81;

std::vector<Case> cases() {
    std::vector<Case> c;
    c.push_back({"simple_pendulum", "K", {{"Q''", "Q''"}}, [](std::mt19937& rng) {
                     double q = uniform(rng, -2, 2), qd = uniform(rng, -3, 3);
                     std::string a = at({{"Q", q}, {"Q'", qd}});
                     // a uniform rod about its end: Q'' = -3 g sin(Q) / (2 L)
                     return State{a, a, {{"Q''", -3 * kG * std::sin(q) / (2 * 0.8)}}};
                 }});
    // speeds that are a coordinate's rate (Q1' = U1) are written as the rate: U1' is Q1''
    c.push_back({"double_pendulum", "K", {{"Q1''", "Q1''"}, {"Q2''", "Q2''"}}, [](std::mt19937& rng) {
                     double q1 = uniform(rng, -3, 3), q2 = uniform(rng, -3, 3);
                     double u1 = uniform(rng, -4, 4), u2 = uniform(rng, -4, 4);
                     std::string a = at({{"Q1", q1}, {"Q2", q2}, {"Q1'", u1}, {"Q2'", u2}});
                     return State{a, a};
                 }});
    c.push_back({"mass_spring_damper", "E", {{"X''", "X''"}}, [](std::mt19937& rng) {
                     double x = uniform(rng, 0.1, 1), xd = uniform(rng, -2, 2), f = uniform(rng, -20, 20);
                     std::string a = at({{"X", x}, {"X'", xd}, {"F", f}});
                     // m x'' = F - k (x - L0) - c x'
                     return State{a, a, {{"X''", (f - 50 * (x - 0.4) - 3 * xd) / 2}}};
                 }});
    c.push_back({"chaotic_pendulum", "K", {{"THETA''", "THETA''"}, {"PHI''", "PHI''"}}, [](std::mt19937& rng) {
                     double th = uniform(rng, -3, 3), ph = uniform(rng, -3, 3);
                     double w = uniform(rng, -5, 5), a = uniform(rng, -5, 5);
                     std::string s = at({{"THETA", th}, {"PHI", ph}, {"THETA'", w}, {"PHI'", a}});
                     return State{s, s};
                 }});
    c.push_back({"nonminimal_pendulum", "K", {{"U1'", "U1'"}}, [](std::mt19937& rng) {
                     // a state on the rod: X = L sin(th), Y = -L cos(th), rates from th'
                     const double L = 1.2;
                     double th = uniform(rng, -2.5, 2.5), w = uniform(rng, -3, 3);
                     double x = L * std::sin(th), y = -L * std::cos(th);
                     double u1 = L * std::cos(th) * w, u2 = L * std::sin(th) * w;
                     std::string a = at({{"X", x}, {"Y", y}, {"U1", u1}, {"U2", u2}});
                     // the pendulum th'' = -g sin(th) / L, and X'' = L (cos(th) th'' - sin(th) th'^2)
                     double thdd = -kG * std::sin(th) / L;
                     return State{a, a, {{"U1'", L * (std::cos(th) * thdd - std::sin(th) * w * w)}}};
                 }});
    c.push_back({"rolling_disk", "K", {{"U1'", "U1'"}, {"U2'", "U2'"}, {"U3'", "U3'"}}, [](std::mt19937& rng) {
                     std::vector<std::pair<std::string, double>> v{
                         {"Q1", uniform(rng, -3, 3)}, {"Q2", uniform(rng, -1.2, 1.2)}, {"Q3", uniform(rng, -3, 3)},
                         {"X", uniform(rng, -1, 1)},  {"Y", uniform(rng, -1, 1)},      {"U1", uniform(rng, -3, 3)},
                         {"U2", uniform(rng, -8, 8)}, {"U3", uniform(rng, -3, 3)}};
                     std::string a = at(v);
                     return State{a, a};
                 }});
    c.push_back({"four_bar", "K", {{"U1'", "U1'"}}, [](std::mt19937& rng) {
                     // an assembled configuration: the coupler-rocker pin where the circles about
                     // the crank's tip (radius LB) and the ground pivot D (radius LC) meet
                     const double LA = 0.2, LB = 0.5, LC = 0.4, LN = 0.45;
                     double q1 = uniform(rng, -3.1, 3.1), u1 = uniform(rng, -5, 5), ta = uniform(rng, -3, 3);
                     double px = LA * std::cos(q1), py = LA * std::sin(q1);
                     double dx = LN - px, dy = -py, d = std::hypot(dx, dy);
                     double a = (LB * LB - LC * LC + d * d) / (2 * d), h = std::sqrt(LB * LB - a * a);
                     double mx = px + a * dx / d, my = py + a * dy / d;
                     double qx = mx - h * dy / d, qy = my + h * dx / d;
                     double q2 = std::atan2(qy - py, qx - px), q3 = std::atan2(qy, qx - LN);
                     // rates closing the loop: LB u2 b2 - LC u3 c2 = -LA u1 a2 (b2 = B's y direction)
                     double m11 = -LB * std::sin(q2), m12 = LC * std::sin(q3);
                     double m21 = LB * std::cos(q2), m22 = -LC * std::cos(q3);
                     double r1 = LA * u1 * std::sin(q1), r2 = -LA * u1 * std::cos(q1);
                     double det = m11 * m22 - m12 * m21;
                     double u2 = (r1 * m22 - m12 * r2) / det, u3 = (m11 * r2 - r1 * m21) / det;
                     std::string s = at({{"Q1", q1}, {"Q2", q2}, {"Q3", q3}, {"U1", u1}, {"U2", u2}, {"U3", u3}, {"TA", ta}});
                     return State{s, s};
                 }});
    c.push_back({"gyroscope", "K", {{"Q1''", "Q1''"}, {"Q2''", "Q2''"}, {"Q3''", "Q3''"}}, [](std::mt19937& rng) {
                     double q1 = uniform(rng, -3, 3), q2 = uniform(rng, 0.3, 1.3), q3 = uniform(rng, -3, 3);
                     double u1 = uniform(rng, -5, 5), u2 = uniform(rng, -5, 5), u3 = uniform(rng, 50, 200);
                     std::string s = at({{"Q1", q1}, {"Q2", q2}, {"Q3", q3}, {"Q1'", u1}, {"Q2'", u2}, {"Q3'", u3}});
                     return State{s, s};
                 }});
    return c;
}

class AutolevModel : public ::testing::TestWithParam<Case> {};

TEST_P(AutolevModel, ImportedEquationsAgreeWithTheHandWrittenScript) {
    const Case& c = GetParam();
    alembert::lang::AutolevTranslation t = alembert::lang::translate_autolev(read_model(c.model + ".al"), c.model + ".al");
    for (const auto& d : t.diagnostics) ADD_FAILURE() << c.model << ".al:" << d.location.line << ": " << d.message;
    ASSERT_TRUE(t.ok());
    const std::string hand = read_model(c.model + ".alb");
    const std::string k = kane_name(t.script);
    std::string imported_unknowns, hand_unknowns;
    for (const auto& [i, h] : c.unknowns) {
        imported_unknowns += (imported_unknowns.empty() ? "" : ", ") + i;
        hand_unknowns += (hand_unknowns.empty() ? "" : ", ") + h;
    }
    std::mt19937 rng(20261124);
    for (int trial = 0; trial < 4; ++trial) {
        State s = c.state(rng);
        auto imported = run_numbers(t.script, "solve " + k + " for " + imported_unknowns + " at " + s.imported_at,
                                    c.model + " (imported)");
        auto by_hand = run_numbers(hand, "solve " + c.hand_equations + " for " + hand_unknowns + " at " + s.hand_at,
                                   c.model + ".alb");
        for (const auto& [i, h] : c.unknowns) {
            ASSERT_TRUE(imported.count(i)) << c.model << ": no value of " << i;
            ASSERT_TRUE(by_hand.count(h)) << c.model << ": no value of " << h;
            const double scale = std::max(1.0, std::abs(by_hand[h]));
            EXPECT_NEAR(imported[i], by_hand[h], 1e-10 * scale) << c.model << " " << i << " at " << s.imported_at;
            if (s.closed_form.count(i)) {
                EXPECT_NEAR(imported[i], s.closed_form[i], 1e-10 * scale) << c.model << " " << i << " (closed form)";
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Classic, AutolevModel, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& p) { return p.param.model; });

// INPUT's values become the constants' values, the initial values (with their unit) and the
// final time, and the equations at the initial state equal the hand-written script's.
TEST(AutolevModel, InputValuesReachTheScript) {
    alembert::lang::AutolevTranslation t =
        alembert::lang::translate_autolev(read_model("double_pendulum.al"), "double_pendulum.al");
    ASSERT_TRUE(t.ok());
    EXPECT_NE(t.script.find("constant L1 = 1, L2 = 0.7"), std::string::npos) << t.script;
    EXPECT_NE(t.script.find("initial Q1 = 30 deg, Q2 = 10 deg, Q1' = 0, Q2' = 0"), std::string::npos) << t.script;
    EXPECT_NE(t.script.find("final time 5"), std::string::npos) << t.script;
    // at the initial state (30 deg, 10 deg, at rest) the accelerations equal the hand script's
    auto imported = run_numbers(t.script, "solve K for Q1'', Q2'' at Q1 = 30 deg, Q2 = 10 deg, Q1' = 0, Q2' = 0", "dp");
    auto by_hand = run_numbers(read_model("double_pendulum.alb"),
                               "solve K for Q1'', Q2'' at Q1 = 30 deg, Q2 = 10 deg, Q1' = 0, Q2' = 0", "dp.alb");
    EXPECT_NEAR(imported["Q1''"], by_hand["Q1''"], 1e-10);
    EXPECT_NEAR(imported["Q2''"], by_hand["Q2''"], 1e-10);
}

}  // namespace
