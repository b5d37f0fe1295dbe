// SPDX-License-Identifier: MIT
// Contact forces as unknowns in minimal coordinates, through the script language: the
// road-map table and the numbers against hand derivations (tests/eom/contact_rows_test.cpp
// has the derivations in full).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

using namespace alembert::lang;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace contact_script {

namespace {

struct ScriptRun {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    explicit ScriptRun(const std::string& text) {
        EXPECT_EQ(interp.run(text, "contact.alb"), RunStatus::ok) << err.str() << out.str();
    }
    // the value printed as "name = value ..." (the last one)
    double value(const std::string& name) const {
        std::regex re("(^|\\n)" + std::regex_replace(name, std::regex("'"), "'") +
                      " = (-?[0-9.]+(e[-+]?[0-9]+)?)");
        const std::string text = out.str();
        double v = NAN;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), re);
             it != std::sregex_iterator(); ++it)
            v = std::stod((*it)[2]);
        return v;
    }
};

const char* kRod = R"(newtonian N
body A
point A_w on A
variable q''
constant m = 2.5 kg, L = 1.3 m, g = 9.81 m/s^2
unknown N_w N, N_f N
coordinates q
rotate A from N about z by q
translate A_o from N_o by L*sin(q)*Nx>
translate Acm from A_o by L/2*Ay>
translate A_w from A_o by L*Ay>
mass A = m
inertia A = 0, 0, m*L^2/12
gravity -g*Ny>
force Nw on A_w = N_w*Nx>
force Nf on A_o = N_f*Ny>
digits 17
)";

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

}  // namespace

// The rod sliding on a frictionless wall and floor, angle only: about the instantaneous
// centre for q'' = 3 g sin q / (2 L), then F = m a along Nx> and Ny>.
TEST(ContactScript, RodSlidingOnWallAndFloor) {
    ScriptRun r(std::string(kRod) + "roadmap E for q'', N_w, N_f\n"
                              "solve E for q'', N_w, N_f at q = 0.9 rad, q' = 1.7 rad/s\n");
    const std::string t = r.out.str();
    EXPECT_NE(t.find("| q''      | rotate           | Nz>"), std::string::npos) << t;
    EXPECT_NE(t.find("| IC_q"), std::string::npos) << t;
    EXPECT_NE(t.find("| N_w      | translate        | Nx>"), std::string::npos) << t;
    EXPECT_NE(t.find("| N_f      | translate        | Ny>"), std::string::npos) << t;
    EXPECT_EQ(t.find("joint force"), std::string::npos) << t;
    const double m = 2.5, L = 1.3, g = 9.81, q = 0.9, qd = 1.7;
    const double a = 3 * g * std::sin(q) / (2 * L);
    expect_close(r.value("q''"), a, "q''");
    expect_close(r.value("N_w"), m * L / 2 * (a * std::cos(q) - qd * qd * std::sin(q)), "N_w");
    expect_close(r.value("N_f"), m * g - m * L / 2 * (a * std::sin(q) + qd * qd * std::cos(q)),
                 "N_f");
}

// The ladder at rest against a frictionless wall on a rough floor, one coordinate:
// N_w = (m g / 2) tan q about the foot, N_f = m g along Ny>, F_f = -(m g / 2) tan q about
// where the lines of N_w and N_f meet.
TEST(ContactScript, LadderInStaticEquilibrium) {
    std::string text = kRod;
    text.replace(text.find("unknown N_w N, N_f N"), 20, "unknown N_w N, N_f N, F_f N");
    text += "force Ff on A_o = F_f*Nx>\n"
            "roadmap E for N_w, N_f, F_f statics\n"
            "solve E for N_w, N_f, F_f at q = 0.55 rad\n";
    ScriptRun r(text);
    const std::string t = r.out.str();
    EXPECT_NE(t.find("| N_w      | rotate           | Nz>"), std::string::npos) << t;
    EXPECT_NE(t.find("| A_o "), std::string::npos) << t;
    EXPECT_NE(t.find("| N_f      | translate        | Ny>"), std::string::npos) << t;
    EXPECT_NE(t.find("| F_f      | rotate           | Nz>"), std::string::npos) << t;
    const double m = 2.5, g = 9.81, q = 0.55;
    expect_close(r.value("N_w"), m * g / 2 * std::tan(q), "N_w");
    expect_close(r.value("N_f"), m * g, "N_f");
    expect_close(r.value("F_f"), -m * g / 2 * std::tan(q), "F_f");
}

// The same ladder with its contacts declared as joint reactions (the wall's push at the top,
// the floor's push and friction at the foot). The wall's and the floor's rows translating S =
// {A} along Nx> are the same equation, N_w + F_f = 0; a solve refused them as singular ("the
// same load declared twice?"), and an earlier version printed N_w = x2, F_f = x2. By hand, as
// above: about the foot, N_w L cos q = m g (L/2) sin q; along Ny>, N_f = m g; along Nx>,
// F_f = -N_w.
TEST(ContactScript, LadderWithItsContactsDeclaredAsReactions) {
    std::string text = kRod;
    text.replace(text.find("unknown N_w N, N_f N"), 20, "unknown N_w N, N_f N, F_f N");
    text.replace(text.find("force Nw on A_w = N_w*Nx>\n"), 26, "");
    text.replace(text.find("force Nf on A_o = N_f*Ny>\n"), 26, "");
    text += "reaction wall between N and A at A_w force N_w along Nx>\n"
            "reaction floor between N and A at A_o force N_f along Ny>, F_f along Nx>\n"
            "roadmap E for N_w, N_f, F_f statics\n"
            "solve E for N_w, N_f, F_f at q = 0.55 rad\n";
    ScriptRun r(text);
    const double m = 2.5, g = 9.81, q = 0.55;
    expect_close(r.value("N_w"), m * g / 2 * std::tan(q), "N_w");
    expect_close(r.value("N_f"), m * g, "N_f");
    expect_close(r.value("F_f"), -m * g / 2 * std::tan(q), "F_f");
    // no two rows the same: one of the wall's and the floor's Nx> rows turns about a point
    const std::string t = r.out.str();
    EXPECT_NE(t.find("| rotate           | Nz>"), std::string::npos) << t;
}

// Two unknown forces on one line of action stay refused, in the script's own names.
TEST(ContactScript, ForcesOnOneLineRefused) {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    std::string text = kRod;
    text.replace(text.find("unknown N_w N, N_f N"), 20, "unknown N_w N, N_f N, N_v N");
    text += "force Nv on A_w = N_v*Nx>\nroadmap E for q'', N_w, N_f, N_v\n";
    EXPECT_EQ(interp.run(text, "contact.alb"), RunStatus::script_error);
    ASSERT_TRUE(interp.last_error());
    EXPECT_NE(interp.last_error()->message.find(
                  "no choice of S, direction and about point determines N_w, N_v"),
              std::string::npos)
        << interp.last_error()->message;
}

}  // namespace contact_script
