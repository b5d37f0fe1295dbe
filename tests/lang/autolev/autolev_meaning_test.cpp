// SPDX-License-Identifier: MIT
// alembert import keeps every meaning or says why not: definitions in declarations, sign
// qualifiers, line continuation, compound assignments, implicit declarations, names that
// differ only by kind, kinematical equations written as assignments, and imported models
// that simulate. Each translated script is run and its values checked against a hand
// derivation at random points.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/interpreter.hpp"

namespace {

using alembert::lang::AutolevTranslation;
using alembert::lang::Interpreter;
using alembert::lang::RunStatus;
using alembert::lang::Severity;
using alembert::lang::translate_autolev;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string messages(const AutolevTranslation& t) {
    std::string all;
    for (const auto& d : t.diagnostics)
        all += std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message + "\n";
    return all;
}

// Runs `script` and then `extra`; the numbers printed as `name = value` (`evaluate` prints
// `= value`: the n-th is keyed "#n").
struct ScriptRun {
    RunStatus status = RunStatus::ok;
    std::string out, err;
    std::map<std::string, double> values;
};
ScriptRun run(const std::string& script, const std::string& extra = "") {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(::testing::TempDir());
    ScriptRun r;
    r.status = interp.run(script + "digits 17\n" + extra + "\n", "imported.alb");
    r.out = out.str();
    r.err = err.str();
    std::istringstream lines(r.out);
    std::string line;
    std::smatch m;
    static const std::regex assignment(R"(^(\S*) ?= (\S+)( .*)?$)");
    int evaluations = 0;
    while (std::getline(lines, line))
        if (std::regex_match(line, m, assignment)) {
            std::string key = m[1].str().empty() ? "#" + std::to_string(++evaluations) : m[1].str();
            try {
                r.values[key] = std::stod(m[2]);
            } catch (const std::exception&) {
                // symbolic
            }
        }
    return r;
}

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// the name the translation gave Kane's equations (K, or K2 if the model has a K)
std::string kane_name(const std::string& script) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(script, m, std::regex(R"(\bkane (\w+) for)"))) << script;
    return m.size() > 1 ? m[1].str() : "K";
}

double uniform(std::mt19937& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

// ---- definitions in declarations ------------------------------------------------------------

// A spring force given as a specified quantity's definition: m x'' = -k x, not FS - m x''.
const char* const kSpecifiedSpring = R"(NEWTONIAN N
PARTICLES P
CONSTANTS M, K
VARIABLES X''
SPECIFIED FS = -K*X
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = FS*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 50
)";

TEST(AutolevMeaning, SpecifiedDefinitionEntersKanesEquation) {
    AutolevTranslation t = translate_autolev(kSpecifiedSpring, "spring.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_FALSE(contains(t.script, "specified")) << t.script;
    std::mt19937 rng(27);
    for (int k = 0; k < 4; ++k) {
        double x = uniform(rng, -1, 1), xd = uniform(rng, -2, 2);
        ScriptRun r = run(t.script, "solve " + kane_name(t.script) + " for X'' at X = " + num(x) + ", X' = " + num(xd));
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["X''"], -50 * x / 2, 1e-12) << t.script;
    }
}

TEST(AutolevMeaning, VariableAndSpecifiedDefinitionsAreTheirExpressions) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
VARIABLES X1, X2, X'
SPECIFIED F1 = X1*X2 + 3*X1^2
VARIABLES Z = 2*X
Y = Z'
)",
                                             "defs.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    std::mt19937 rng(28);
    for (int k = 0; k < 3; ++k) {
        double x1 = uniform(rng, -2, 2), x2 = uniform(rng, -2, 2), x = uniform(rng, -2, 2), xd = uniform(rng, -2, 2);
        ScriptRun r = run(t.script, "evaluate F1 at X1 = " + num(x1) + ", X2 = " + num(x2) + "\nevaluate Z at X = " + num(x) +
                                  "\nevaluate Y at X' = " + num(xd));
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["#1"], x1 * x2 + 3 * x1 * x1, 1e-12) << t.script;
        EXPECT_NEAR(r.values["#2"], 2 * x, 1e-12) << t.script;
        EXPECT_NEAR(r.values["#3"], 2 * xd, 1e-12) << t.script;
    }
}

TEST(AutolevMeaning, SignQualifiersAreTranslatedOrReported) {
    AutolevTranslation t = translate_autolev("NEWTONIAN N\nCONSTANTS L+, M-, C~, D\nINPUT L = 2\n", "signs.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "positive L = 2\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "constant M, C, D\n")) << t.script;
    ASSERT_EQ(t.diagnostics.size(), 2u) << messages(t);
    EXPECT_EQ(t.diagnostics[0].severity, Severity::warning);
    EXPECT_EQ(t.diagnostics[0].location.line, 2);
    EXPECT_EQ(t.diagnostics[0].location.column, 16);
    EXPECT_TRUE(contains(t.diagnostics[0].message, "'-' (negative) of 'M' is not translated")) << messages(t);
    EXPECT_EQ(t.diagnostics[1].location.column, 20);
    EXPECT_TRUE(contains(t.diagnostics[1].message, "'~' (nonzero) of 'C'")) << messages(t);
    ScriptRun r = run(t.script, "evaluate sqrt(L^2)");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    EXPECT_NEAR(r.values["#1"], 2, 1e-15);
}

TEST(AutolevMeaning, ConstantUnitsAreKept) {
    AutolevTranslation t = translate_autolev("NEWTONIAN N\nCONSTANTS G = 9.81 M/S^2, L = 30 CM\n", "units.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "constant G = 9.81 m/s^2, L = 30 cm\n")) << t.script;
    ScriptRun r = run(t.script, "evaluate G*L");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    EXPECT_NEAR(r.values["#1"], 9.81 * 0.3, 1e-12);
}

// ---- whole-file features --------------------------------------------------------------------

TEST(AutolevMeaning, AmpersandContinuesTheLine) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
BODIES A
CONSTANTS L, &   % the length,
  M, G           % the mass and gravity
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2 &
  *A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, &
      G = 9.81
X = UNDECLARED
)",
                                             "amp.al");
    ASSERT_FALSE(t.ok());
    ASSERT_EQ(t.diagnostics.size(), 1u) << messages(t);
    EXPECT_EQ(t.diagnostics[0].location.line, 17);  // lines are counted across continuations
    EXPECT_EQ(t.diagnostics[0].location.column, 5);
    AutolevTranslation good = translate_autolev(std::string(kSpecifiedSpring) + "R> = X*N1> + &\n  X*N2>\n", "amp2.al");
    ASSERT_TRUE(good.ok()) << messages(good);
    EXPECT_TRUE(contains(good.script, "R> = X*Nx> + X*Ny>\n")) << good.script;
    // the pendulum above without its bad last line: Q'' = -3 g sin(Q) / (2 L)
    std::string src = R"(NEWTONIAN N
BODIES A
CONSTANTS L, &
  M, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2 &
  *A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, &
      G = 9.81
)";
    AutolevTranslation p = translate_autolev(src, "amp3.al");
    ASSERT_TRUE(p.ok()) << messages(p);
    for (double q : {-1.3, 0.4, 2.2}) {
        ScriptRun r = run(p.script, "solve K for Q'' at Q = " + num(q) + ", Q' = 0.5");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << p.script;
        EXPECT_NEAR(r.values["Q''"], -3 * 9.81 * std::sin(q) / (2 * 0.8), 1e-12);
    }
}

TEST(AutolevMeaning, CompoundAssignmentsAddToTheValue) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
CONSTANTS L, H
X := 2*L
X += H - 1
X *= L + 1
X -= L - H
X /= 2 + H
R> := L*N1>
R> += H*N2>
Y = DOT(R>, N1> + 2*N2>)
)",
                                             "compound.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    std::mt19937 rng(29);
    for (int k = 0; k < 3; ++k) {
        double l = uniform(rng, -2, 2), h = uniform(rng, 0.1, 2);
        std::string at = " at L = " + num(l) + ", H = " + num(h);
        ScriptRun r = run(t.script, "evaluate X" + at + "\nevaluate Y" + at);
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["#1"], ((2 * l + h - 1) * (l + 1) - (l - h)) / (2 + h), 1e-12) << t.script;
        EXPECT_NEAR(r.values["#2"], l + 2 * h, 1e-12) << t.script;
    }
}

// MASS A = MA and INERTIA A, I1, I2, I3 with names never declared: Autolev declares them as
// constants, and so does the translation. A rod of any inertia about its mass centre at L/2
// from the pin: Q'' = -MA g (L/2) sin(Q) / (I3 + MA L^2/4).
TEST(AutolevMeaning, MassAndInertiaDeclareTheirConstants) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
BODIES A
CONSTANTS L, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = MA
INERTIA A, I1, I2, I3
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, G = 9.81, MA = 1.5, I3 = 0.1
)",
                                             "implicit.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "constant MA = 1.5, I1, I2, I3 = 0.1\n")) << t.script;
    ASSERT_EQ(t.diagnostics.size(), 4u) << messages(t);
    EXPECT_EQ(t.diagnostics[0].severity, Severity::note);
    EXPECT_EQ(t.diagnostics[0].location.line, 8);
    EXPECT_TRUE(contains(t.diagnostics[0].message, "'MA' is not declared; MASS declares it as a constant"));
    for (double q : {-2.0, 0.7}) {
        ScriptRun r = run(t.script, "solve K for Q'' at Q = " + num(q) + ", Q' = 1");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["Q''"], -1.5 * 9.81 * 0.4 * std::sin(q) / (0.1 + 1.5 * 0.64 / 4), 1e-12);
    }
}

// A frame A beside a variable A, a constant L beside a particle L: Autolev tells them apart by
// use, the script by name, so the later declaration is renamed, with a note and a comment. A rod
// A of mass MA turned by the angle A, with a particle L of mass M at its tip at distance L:
// A'' = -g sin(A) (MA L/2 + M L) / (MA L^2/3 + M L^2).
TEST(AutolevMeaning, NamesThatDifferOnlyByKindAreRenamed) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
BODIES A
CONSTANTS L, MA, M, G
PARTICLES L
VARIABLES A''
SIMPROT(N, A, 3, A)
P_NO_AO> = -L/2*A2>
P_NO_L> = -L*A2>
V_AO_N> = DT(P_NO_AO>, N)
V_L_N> = DT(P_NO_L>, N)
MASS A = MA, L = M
INERTIA A, 0, 0, MA*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.9, MA = 1.5, M = 0.7, G = 9.81
)",
                                             "kinds.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    ASSERT_EQ(t.diagnostics.size(), 2u) << messages(t);
    EXPECT_EQ(t.diagnostics[0].severity, Severity::note);
    EXPECT_EQ(t.diagnostics[0].location.line, 4);
    EXPECT_TRUE(contains(t.diagnostics[0].message, "'L' is declared as a particle at line 4 and as a constant at line 3; "
                                                   "the particle is called 'L_particle' in the script"))
        << messages(t);
    EXPECT_TRUE(contains(t.diagnostics[1].message, "the variable is called 'A_var'")) << messages(t);
    EXPECT_TRUE(contains(t.script, "# renamed: 'A' is declared as a variable at line 5 and as a body at line 2"))
        << t.script;
    EXPECT_TRUE(contains(t.script, "rotate A from N about z by A_var\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "mass L_particle = M\n")) << t.script;
    const double L = 0.9, MA = 1.5, M = 0.7, g = 9.81;
    for (double a : {-2.1, 0.4, 1.3}) {
        ScriptRun r = run(t.script, "solve K for A_var'' at A_var = " + num(a) + ", A_var' = 0.8");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["A_var''"], -g * std::sin(a) * (MA * L / 2 + M * L) / (MA * L * L / 3 + M * L * L), 1e-12);
    }
}

// Two values (or two frames, bodies, particles, points) of one name are an error that names
// both declarations and their lines.
TEST(AutolevMeaning, NamesDeclaredTwiceNameBothDeclarations) {
    AutolevTranslation a = translate_autolev("NEWTONIAN N\nCONSTANTS L\nVARIABLES L'\n", "twice.al");
    ASSERT_FALSE(a.ok());
    ASSERT_EQ(a.diagnostics.size(), 1u) << messages(a);
    EXPECT_EQ(a.diagnostics[0].location.line, 3);
    EXPECT_EQ(a.diagnostics[0].location.column, 11);
    EXPECT_TRUE(contains(a.diagnostics[0].message,
                         "'L' is declared as a variable at line 3, and 'L' as a constant at line 2"))
        << messages(a);
    EXPECT_FALSE(contains(a.diagnostics[0].hint, "'L' and 'L'")) << a.diagnostics[0].hint;
    AutolevTranslation b = translate_autolev("NEWTONIAN N\nFRAMES A\nPOINTS B, A\n", "twice2.al");
    ASSERT_FALSE(b.ok());
    ASSERT_EQ(b.diagnostics.size(), 1u) << messages(b);
    EXPECT_EQ(b.diagnostics[0].location.column, 11);
    EXPECT_TRUE(contains(b.diagnostics[0].message, "'A' is declared as a point at line 3, and 'A' as a frame at line 2"))
        << messages(b);
}

// Statements read but not translatable whole: an error at the line and column, never a
// partial translation.
TEST(AutolevMeaning, PartsThatCannotBeTranslatedAreErrors) {
    struct Bad {
        std::string source;
        int line, column;
        const char* fragment;
    };
    const std::string head = "NEWTONIAN N\nVARIABLES X'\n";
    for (const Bad& b : {Bad{head + "FRAMES A = 2\n", 3, 12, "'A' is declared in FRAMES with a value"},
                         Bad{head + "POINTS P+\n", 3, 9, "with the sign qualifier '+'"},
                         Bad{head + "SPECIFIED F = 2*X M\n", 3, 19, "a unit after the definition of 'F'"},
                         Bad{head + "CONSTANTS K+-\n", 3, 13, "two sign qualifiers"},
                         Bad{head + "VARIABLES U\nU = 2*X\n", 4, 1, "is assigned only as a coordinate's rate"},
                         Bad{head + "CONSTANTS' K\n", 3, 1, "CONSTANTS is written with primes"},
                         Bad{head + "VARIABLES U\nX' += U\n", 4, 1, "'+=' on a derivative is not translated"},
                         Bad{head + "X''' = -X\n", 3, 1, "an equation for 'X'''' is not translated"},
                         // a differential equation beside bodies, KANE() or a first-order one
                         Bad{head + "BODIES B\nX'' = -X\n", 4, 1, "the model also has a body 'B'"},
                         Bad{head + "X'' = -X\nZERO = FR() + FRSTAR()\nKANE()\n", 3, 1,
                             "the file also forms Kane's equations"},
                         Bad{head + "GRAVITY(-N2>)\nX'' = -X\n", 4, 1, "GRAVITY would act on"},
                         Bad{head + "VARIABLES Y'\nX'' = -X\nY' = -Y\n", 5, 1,
                             "the first-order equation Y' = ... is not translated"},
                         Bad{head + "VARIABLES Y''\nX'' = -X\n", 3, 11, "the variable 'Y' has no equation"},
                         Bad{head + "X'' = -X\nX'' = X\n", 4, 1, "a second equation for X''"}}) {
        AutolevTranslation t = translate_autolev(b.source, "bad.al");
        EXPECT_FALSE(t.ok()) << b.source;
        bool found = false;
        for (const auto& d : t.diagnostics)
            found = found || (d.severity == Severity::error && d.location.line == b.line &&
                              d.location.column == b.column && contains(d.message, b.fragment) && !d.hint.empty());
        EXPECT_TRUE(found) << b.source << "expected " << b.line << ":" << b.column << " " << b.fragment << ", got\n"
                           << messages(t);
    }
}

// ---- kinematical equations written as assignments -------------------------------------------

TEST(AutolevMeaning, SpeedAssignedARateIsAKinematicalEquation) {
    const std::string model = R"(NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES THETA', OMEGA'
SIMPROT(N, A, 3, THETA)
%KIN%
W_A_N> = OMEGA*N3>
P_NO_AO> = -L/2*A2>
V_AO_N> = CROSS(W_A_N>, P_NO_AO>)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
)";
    auto with = [&](const std::string& kin) {
        std::string s = model;
        s.replace(s.find("%KIN%"), 5, kin);
        return translate_autolev(s, "kin.al");
    };
    AutolevTranslation a = with("OMEGA = THETA'"), b = with("THETA' = OMEGA");
    ASSERT_TRUE(a.ok()) << messages(a);
    ASSERT_TRUE(b.ok()) << messages(b);
    // OMEGA is THETA' either way, and written so
    EXPECT_TRUE(contains(a.script, "# OMEGA is THETA'")) << a.script;
    EXPECT_TRUE(contains(a.script, "kane K for THETA\n")) << a.script;
    EXPECT_TRUE(contains(a.script, "angvel A in N = THETA'*Nz>\n")) << a.script;
    for (double q : {-1.1, 0.3, 2.5}) {
        std::string at = "solve K for THETA'' at THETA = " + num(q) + ", THETA' = 0.7";
        ScriptRun ra = run(a.script, at), rb = run(b.script, at);
        ASSERT_EQ(ra.status, RunStatus::ok) << ra.err << a.script;
        EXPECT_NEAR(ra.values["THETA''"], -3 * 9.81 * std::sin(q) / (2 * 0.8), 1e-12);
        EXPECT_NEAR(ra.values["THETA''"], rb.values["THETA''"], 1e-12);
    }
}

// With a kinematical equation of another form in the model, the speeds stay speeds and
// OMEGA = THETA' is the kinematical equation THETA' - OMEGA.
TEST(AutolevMeaning, SpeedAssignedARateBesideOtherSpeeds) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
BODIES A
PARTICLES P
CONSTANTS L, M, G
VARIABLES THETA', OMEGA', X', V'
SIMPROT(N, A, 3, THETA)
OMEGA = THETA'
X' = 2*V
W_A_N> = OMEGA*N3>
P_NO_AO> = -L/2*A2>
V_AO_N> = CROSS(W_A_N>, P_NO_AO>)
P_NO_P> = X*N1>
V_P_N> = 2*V*N1>
MASS A = M, P = 1
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
)",
                                             "speeds.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "speeds OMEGA, V")) << t.script;
    EXPECT_TRUE(contains(t.script, "kinematics [THETA' - OMEGA, X' - 2*V]")) << t.script;
    for (double q : {-1.1, 2.5}) {
        ScriptRun r = run(t.script, "solve K for OMEGA', V' at THETA = " + num(q) + ", OMEGA = 0.7, X = 1, V = 2");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["OMEGA'"], -3 * 9.81 * std::sin(q) / (2 * 0.8), 1e-12);
        EXPECT_NEAR(r.values["V'"], 0, 1e-12);  // the particle moves freely along N1>
    }
}

// Without KANE(): speeds that are rates are still written as the rates; kinematical equations
// of another form, and constraints, which only Kane's equations take, are reported.
TEST(AutolevMeaning, KinematicalEquationsWithoutKaneAreReported) {
    AutolevTranslation a = translate_autolev(R"(NEWTONIAN N
PARTICLES P
VARIABLES Q', U'
Q' = U
V_P_N> = U*N1>
)",
                                             "kinematics.al");
    ASSERT_TRUE(a.ok()) << messages(a);
    EXPECT_TRUE(a.diagnostics.empty()) << messages(a);
    EXPECT_TRUE(contains(a.script, "velocity P in N = Q'*Nx>\n")) << a.script;
    AutolevTranslation b = translate_autolev(R"(NEWTONIAN N
PARTICLES P
VARIABLES Q', U'
Q' = 2*U
DEPENDENT[1] = U - Q
V_P_N> = U*N1>
)",
                                             "kinematics2.al");
    ASSERT_TRUE(b.ok()) << messages(b);
    ASSERT_EQ(b.diagnostics.size(), 2u) << messages(b);
    EXPECT_EQ(b.diagnostics[0].severity, Severity::warning);
    EXPECT_EQ(b.diagnostics[0].location.line, 4);
    EXPECT_TRUE(contains(b.diagnostics[0].message, "the kinematical equation Q' - 2*U = 0 is not translated"))
        << messages(b);
    EXPECT_EQ(b.diagnostics[1].location.line, 5);
    EXPECT_TRUE(contains(b.diagnostics[1].message, "DEPENDENT[...] is not translated")) << messages(b);
    EXPECT_EQ(run(b.script).status, RunStatus::ok);
}

// Beside Q' = U, a variable used with its derivatives (X'' in V_P2_N> = X'*N1>) is a coordinate
// with its rate as speed, not a given quantity: two free particles on springs, Q'' = -k Q / m1,
// X'' = -k X / m2.
TEST(AutolevMeaning, VariableUsedWithItsRateBesideSpeedsIsACoordinate) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
PARTICLES P1, P2
CONSTANTS KS, M1, M2
VARIABLES Q', U', X''
Q' = U
P_NO_P1> = Q*N1>
V_P1_N> = U*N1>
P_NO_P2> = X*N2>
V_P2_N> = X'*N2>
MASS P1 = M1, P2 = M2
FORCE_P1> = -KS*Q*N1>
FORCE_P2> = -KS*X*N2>
ZERO = FR() + FRSTAR()
KANE()
INPUT KS = 40, M1 = 2, M2 = 5
)",
                                             "mixed.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(t.diagnostics.empty()) << messages(t);
    EXPECT_TRUE(contains(t.script, "kane K for Q, X\n")) << t.script;
    ScriptRun r = run(t.script, "solve K for Q'', X'' at Q = 0.3, X = -0.7, Q' = 1, X' = 2");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    EXPECT_NEAR(r.values["Q''"], -40 * 0.3 / 2, 1e-12);
    EXPECT_NEAR(r.values["X''"], 40 * 0.7 / 5, 1e-12);
    // beside a kinematical equation of another form it cannot be told apart: an error
    std::string other = R"(NEWTONIAN N
PARTICLES P1, P2
VARIABLES Q', U', X''
Q' = 2*U
V_P1_N> = 2*U*N1>
V_P2_N> = X'*N2>
MASS P1 = 1, P2 = 1
ZERO = FR() + FRSTAR()
KANE()
)";
    AutolevTranslation e = translate_autolev(other, "mixed2.al");
    ASSERT_FALSE(e.ok());
    ASSERT_EQ(e.diagnostics.size(), 1u) << messages(e);
    EXPECT_EQ(e.diagnostics[0].location.line, 3);
    EXPECT_EQ(e.diagnostics[0].location.column, 19);
    EXPECT_TRUE(contains(e.diagnostics[0].message, "'X' has no kinematical equation, while Q has one")) << messages(e);
}

// ---- what is imported runs --------------------------------------------------------------

std::string read_model(const std::string& name) {
    std::ifstream f(std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/models/" + name, std::ios::binary);
    EXPECT_TRUE(f.good()) << name;
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// The double pendulum's speeds are its angles' rates (Q1' = U1): written as the rates, its
// Kane equations simulate, and the energy of this conservative model is kept.
TEST(AutolevMeaning, ImportedDoublePendulumSimulates) {
    AutolevTranslation t = translate_autolev(read_model("double_pendulum.al"), "double_pendulum.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "kane K for Q1, Q2\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "initial Q1 = 30 deg, Q2 = 10 deg, Q1' = 0, Q2' = 0\n")) << t.script;
    ScriptRun r = run(t.script, "simulate plot none");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(energy: .* its largest change is below (\S+) of)"))) << r.out;
    EXPECT_LE(std::stod(m[1]), 1e-6) << r.out;
    // the hand-written script (Lagrange's equations) run alike ends in the same state
    ScriptRun h = run(read_model("double_pendulum.alb") +
                          "initial Q1 = 30 deg, Q2 = 10 deg\nfinal time 5\noutput step 0.01\n"
                          "output Q1 in deg, Q2 in deg\n",
                      "simulate plot none");
    ASSERT_EQ(h.status, RunStatus::ok) << h.err;
    static const std::regex last(R"(\n\s+5\s+(\S+)\s+(\S+))");
    std::smatch a, b;
    ASSERT_TRUE(std::regex_search(r.out, a, last)) << r.out;
    ASSERT_TRUE(std::regex_search(h.out, b, last)) << h.out;
    EXPECT_NEAR(std::stod(a[1]), std::stod(b[1]), 1e-4) << r.out << h.out;
    EXPECT_NEAR(std::stod(a[2]), std::stod(b[2]), 1e-4) << r.out << h.out;
    // and CODE DYNAMICS() of it translates (it was left out: the speeds were not the rates)
    AutolevTranslation c =
        translate_autolev(read_model("double_pendulum.al") + "CODE DYNAMICS() pendulum2.c\n", "double_pendulum.al");
    ASSERT_TRUE(c.ok()) << messages(c);
    EXPECT_TRUE(c.diagnostics.empty()) << messages(c);
    EXPECT_TRUE(contains(c.script, "codegen c name pendulum2\n")) << c.script;
    ScriptRun g = run(c.script);
    ASSERT_EQ(g.status, RunStatus::ok) << g.err << c.script;
    // OUTPUT of a speed keeps its name for the column: U1 = Q1'
    std::string model = read_model("double_pendulum.al");
    model.replace(model.find("OUTPUT T, Q1 DEG, Q2 DEG"), 24, "OUTPUT T, Q1 DEG, U1, U2 DEG/S");
    AutolevTranslation o = translate_autolev(model, "double_pendulum.al");
    ASSERT_TRUE(o.ok()) << messages(o);
    EXPECT_TRUE(contains(o.script, "output Q1 in deg, U1 = Q1', U2 = Q2' in deg/s\n")) << o.script;
    ScriptRun s = run(o.script, "final time 0.5\nsimulate plot none");
    ASSERT_EQ(s.status, RunStatus::ok) << s.err << o.script;
    EXPECT_TRUE(contains(s.out, "U2 [deg/s]")) << s.out;
}

// A mass-spring-damper forced by O*SIN(T): T is a number of seconds, O (no coordinate, no
// speed) is a given quantity, X' = V makes V the rate of X. m x'' = -k x - c x' + O sin(t).
TEST(AutolevMeaning, ForcedMassSpringDamperImportsAndSimulates) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C
VARIABLES X', V'
VARIABLES O
X' = V
P_NO_P> = X*N1>
V_P_N> = V*N1>
MASS P = M
FORCE_P> = (-K*X - C*V + O*SIN(T))*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 50, C = 3, O = 4
INPUT X = 0.1, V = 0
INPUT TFINAL = 2
)",
                                             "msd.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "specified O\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "input O = 4\n")) << t.script;
    const std::string k = kane_name(t.script);
    EXPECT_TRUE(contains(t.script, "kane " + k + " for X\n")) << t.script;
    std::mt19937 rng(30);
    for (int i = 0; i < 3; ++i) {
        double x = uniform(rng, -1, 1), xd = uniform(rng, -2, 2), o = uniform(rng, -5, 5), tt = uniform(rng, 0, 10);
        ScriptRun r = run(t.script, "solve " + k + " for X'' at X = " + num(x) + ", X' = " + num(xd) + ", O = " +
                                        num(o) + ", t = " + num(tt));
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["X''"], (-50 * x - 3 * xd + o * std::sin(tt)) / 2, 1e-12) << t.script;
    }
    ScriptRun r = run(t.script, "simulate plot none");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
}

// ---- loads assigned more than once; long chains -----------------------------------------

// FORCE_P> = v> then FORCE_P> += w>: the force on P is v> + w>; a second '=' is an error.
TEST(AutolevMeaning, ForceAssignedThenAddedTo) {
    std::string model = R"(NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C
VARIABLES X''
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = -K*X*N1>
%MORE%
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 50, C = 3
)";
    auto with = [&](const std::string& more) {
        std::string s = model;
        s.replace(s.find("%MORE%"), 6, more);
        return translate_autolev(s, "loads.al");
    };
    AutolevTranslation t = with("FORCE_P> += -C*X'*N1>\nFORCE_P> -= 5*N1>");
    ASSERT_TRUE(t.ok()) << messages(t);
    const std::string k = kane_name(t.script);
    for (double x : {-0.4, 0.9}) {
        ScriptRun r = run(t.script, "solve " + k + " for X'' at X = " + num(x) + ", X' = 1.5");
        ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
        EXPECT_NEAR(r.values["X''"], (-50 * x - 3 * 1.5 - 5) / 2, 1e-12) << t.script;
    }
    AutolevTranslation twice = with("FORCE_P> = -C*X'*N1>");
    ASSERT_FALSE(twice.ok());
    ASSERT_EQ(twice.diagnostics.size(), 1u) << messages(twice);
    EXPECT_EQ(twice.diagnostics[0].location.line, 9);
    EXPECT_TRUE(contains(twice.diagnostics[0].message, "assigned a second time")) << messages(twice);
}

// A model given by its differential equation generates code like any other: CODE DYNAMICS()
// becomes codegen, which writes the C files.
TEST(AutolevMeaning, DifferentialEquationsGenerateCode) {
    AutolevTranslation t = translate_autolev("CONSTANTS K\nVARIABLES X''\nX'' = -K*X\nINPUT K = 4, X = 1\n"
                                             "CODE DYNAMICS() oscillator_ode.c\n",
                                             "ode.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "codegen c name oscillator_ode\n")) << t.script;
    ScriptRun r = run(t.script);
    ASSERT_EQ(r.status, RunStatus::ok) << r.err << t.script;
    std::ifstream c(::testing::TempDir() + "/oscillator_ode.c");
    EXPECT_TRUE(c.good()) << r.out;
}

TEST(AutolevMeaning, CodeDynamicsArgumentsAreReported) {
    AutolevTranslation t = translate_autolev(std::string(kSpecifiedSpring) + "CODE DYNAMICS(X) spring.c\n", "code.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    ASSERT_EQ(t.diagnostics.size(), 1u) << messages(t);
    EXPECT_EQ(t.diagnostics[0].severity, Severity::warning);
    EXPECT_TRUE(contains(t.diagnostics[0].message, "arguments of CODE DYNAMICS(X) are not translated"));
    EXPECT_TRUE(contains(t.script, "codegen c name spring\n")) << t.script;
}

// Long chains of operators (10,000 terms, 20,000 factors, a 20,000-term vector sum) are
// translated without a deep stack, in time proportional to their length.
TEST(AutolevMeaning, LongOperatorChainsTranslate) {
    std::string sum = "M", product = "M", vector = "N1>";
    for (int i = 0; i < 10000; ++i) sum += " + 0*M";
    for (int i = 0; i < 20000; ++i) product += "*M";
    for (int i = 0; i < 20000; ++i) vector += " + N2>";
    AutolevTranslation t = translate_autolev("NEWTONIAN N\nBODIES A\nCONSTANTS M\nMASS A = " + sum + "\nX = " + product +
                                                 "\nR> = " + vector + "\n",
                                             "chains.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "mass A = M + 0*M + 0*M")) << t.script.substr(0, 200);
    EXPECT_TRUE(contains(t.script, "X = M*M*M*M")) << t.script.substr(0, 200);
    EXPECT_TRUE(contains(t.script, "R> = Nx> + Ny> + Ny>")) << t.script.substr(0, 200);
}

// A 200,000-factor product: its expression tree, as deep as the chain is long, is read,
// translated and taken apart without a deep stack (Expr's operands are copied and destroyed
// with worklists; the recursive destructor overflowed at 20,000 factors in an unoptimized
// sanitizer build, at 200,000 in any).
TEST(AutolevMeaning, ProductOf200000FactorsTranslates) {
    std::string product = "M";
    for (int i = 0; i < 200000; ++i) product += "*M";
    AutolevTranslation t = translate_autolev("NEWTONIAN N\nCONSTANTS M\nX = " + product + "\nY = X + " + product + "\n",
                                             "deep.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    std::size_t at = t.script.find("X = M*M*M");
    ASSERT_NE(at, std::string::npos) << t.script.substr(0, 200);
    std::size_t end = t.script.find('\n', at);
    EXPECT_EQ(end - at, std::string("X = M").size() + 2 * 200000u) << "every factor is kept";
}

// Arguments of 10,000 terms to COEF, REPLACE, EVALUATE, TAYLOR and SOLVE translate without a
// deep stack (the script's run of such arguments: tests/lang/algebra_functions_test.cpp).
TEST(AutolevMeaning, LongArgumentsOfAlgebraFunctionsTranslate) {
    std::string sum = "M*Q";
    for (int i = 0; i < 10000; ++i) sum += " + M*Q";
    AutolevTranslation t = translate_autolev(
        "NEWTONIAN N\nCONSTANTS M\nVARIABLES Q\nC = COEF(" + sum + ", Q)\nR = REPLACE(" + sum +
            ", Q = 2)\nE = EVALUATE(" + sum + ", Q = 2, M = 1)\nS = TAYLOR(" + sum + ", 1:2, Q = 0)\nSOLVE(" + sum +
            " - 1, Q)\n",
        "long.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    EXPECT_TRUE(contains(t.script, "C = coef(M*Q + M*Q + M*Q")) << t.script.substr(0, 300);
    EXPECT_TRUE(contains(t.script, " + M*Q, Q = 2)\n")) << t.script.substr(0, 300);
    EXPECT_TRUE(contains(t.script, " + M*Q, Q = 2, M = 1)\n")) << t.script.substr(0, 300);
    EXPECT_TRUE(contains(t.script, " + M*Q, Q = 0, 2) - taylor(M*Q + ")) << t.script.substr(0, 300);
    EXPECT_TRUE(contains(t.script, " + M*Q - 1]\nsolve solve_eq for Q as Q_solved\n")) << t.script.substr(0, 300);
}

}  // namespace
