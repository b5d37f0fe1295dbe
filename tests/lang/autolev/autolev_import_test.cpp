// SPDX-License-Identifier: MIT
// alembert import: names without regard to case, indexed and implicit declarations,
// reordering, expressions, and the messages for what cannot be translated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

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

// the translated script runs; returns the numbers it printed as `name = value`
std::map<std::string, double> run(const std::string& script, const std::string& extra = "") {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(::testing::TempDir());
    EXPECT_EQ(interp.run(script + "digits 17\n" + extra + "\n", "imported.alb"), RunStatus::ok) << err.str() << script;
    std::map<std::string, double> values;
    std::istringstream lines(out.str());
    std::string line;
    std::smatch m;
    static const std::regex assignment(R"(^(\S*) ?= (\S+)$)");
    int evaluations = 0;
    while (std::getline(lines, line))
        if (std::regex_match(line, m, assignment)) {
            // `evaluate` prints "= value": the n-th is keyed "=#n" (the first also "=")
            std::string key = m[1].str().empty() ? (++evaluations == 1 ? "=" : "=#" + std::to_string(evaluations))
                                                 : m[1].str();
            try {
                values[key] = std::stod(m[2]);
            } catch (const std::exception&) {
                // symbolic
            }
        }
    return values;
}

const char* const kPendulum = R"(% a rod on a pin, Q from the downward vertical
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
)";

TEST(AutolevImport, NamesMatchWithoutRegardToCaseAndKeepTheirDeclaredSpelling) {
    AutolevTranslation t = translate_autolev(R"(newtonian n
Bodies Rod
constants Len, g
variables q''
simprot(N, ROD, 3, Q)
p_no_rodo> = -LEN*rod2>
v_RODO_n> = dt(P_NO_RODO>, n)
mass ROD = 2
inertia rod, 0, 0, 1
gravity(-G*N2>)
zero = fr() + frstar()
kane()
input LEN = 0.5, G = 9.81
)",
                                             "mixed.al");
    ASSERT_TRUE(t.ok()) << t.script;
    EXPECT_TRUE(t.diagnostics.empty());
    EXPECT_TRUE(contains(t.script, "rotate Rod from n about z by q\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "translate Rodcm from n_o by -Len*Rody>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "constant Len = 0.5, g = 9.81\n")) << t.script;
    // m L^2 q'' + I q'' = -m g L sin(q): q'' = -2*9.81*0.5 sin(q) / (2*0.25 + 1)
    auto v = run(t.script, "solve K for q'' at q = 0.7, q' = 0");
    EXPECT_NEAR(v["q''"], -2 * 9.81 * 0.5 * std::sin(0.7) / 1.5, 1e-12);
}

TEST(AutolevImport, IndexedDeclarationsExpand) {
    AutolevTranslation t = translate_autolev("NEWTONIAN N\nCONSTANTS L{3}, K{2:4}\nVARIABLES Q{2}'\n"
                                             "MOTIONVARIABLES' U{3:4}\n",
                                             "indexed.al");
    ASSERT_TRUE(t.ok());
    EXPECT_TRUE(contains(t.script, "constant L1, L2, L3, K2, K3, K4\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "variable Q1'', Q2'', U3'', U4''\n")) << t.script;
    run(t.script);
}

TEST(AutolevImport, DeclarationsAndInputValuesMoveFirst) {
    // Autolev's order: variables and constants before NEWTONIAN, values at the end
    AutolevTranslation t = translate_autolev(R"(MOTIONVARIABLES' Q', U'
CONSTANTS M, G
NEWTONIAN N
PARTICLES P
P_NO_P> = Q*N1>
V_P_N> = U*N1>
MASS P = M
Q' = U
GRAVITY(-G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 3, G = 10
INPUT Q = 0.25, U = -1
INPUT TFINAL = 2, INTEGSTP = 0.05, ABSERR = 1e-9, RELERR = 1e-10
)",
                                             "order.al");
    ASSERT_TRUE(t.ok());
    std::istringstream lines(t.script);
    std::string first, second;
    std::getline(lines, first);  // the comment naming the source
    std::getline(lines, second);
    EXPECT_EQ(second, "newtonian N");
    EXPECT_TRUE(contains(t.script, "constant M = 3, G = 10\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "initial Q = 0.25, Q' = -1\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "final time 2\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "output step 0.05\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "tolerance abs 1e-9 rel 1e-10\n")) << t.script;
    // free fall along -N1>: U' = Q'' = -G (U, the rate of Q, is written Q')
    auto v = run(t.script, "solve K for Q'' at Q = 0, Q' = 0");
    EXPECT_NEAR(v["Q''"], -10, 1e-12);
}

TEST(AutolevImport, DirectionCosineMatrixEqualsSimpleRotation) {
    std::string dcm = kPendulum;
    dcm.replace(dcm.find("SIMPROT(N, A, 3, Q)"), 19, "N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]");
    AutolevTranslation a = translate_autolev(kPendulum, "simprot.al");
    AutolevTranslation b = translate_autolev(dcm, "dcm.al");
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_TRUE(contains(b.script, "rotate A from N dcm [cos(Q), -sin(Q), 0; sin(Q), cos(Q), 0; 0, 0, 1]\n")) << b.script;
    // the matrix's columns are A1>, A2>, A3> in N: A1> turns toward N2> as Q grows
    EXPECT_NEAR(run(b.script, "evaluate dot(Ax>, Ny>) at Q = 0.3")["="], std::sin(0.3), 1e-15);
    EXPECT_NEAR(run(a.script, "evaluate dot(Ax>, Ny>) at Q = 0.3")["="], std::sin(0.3), 1e-15);
    for (double q : {-2.0, 0.3, 1.9}) {
        std::string at = "solve K for Q'' at Q = " + std::to_string(q) + ", Q' = 0.4";
        EXPECT_NEAR(run(a.script, at)["Q''"], run(b.script, at)["Q''"], 1e-12);
        EXPECT_NEAR(run(a.script, at)["Q''"], -3 * 9.81 * std::sin(q) / (2 * 0.8), 1e-12);
    }
}

// Autolev reads an angle written with numbers alone in degrees unless the file says DEGREES
// OFF (DEGREES ON is its default); an angle holding a name is radians. Checked by the rotation
// and the sines the script computes, against the angles in radians.
TEST(AutolevImport, NumbersAsAnglesAreDegreesUnlessDegreesOff) {
    const std::string body = "NEWTONIAN N\nFRAMES A, B\nCONSTANTS L\nSIMPROT(N, A, 3, 30)\nSIMPROT(N, B, 3, PI/5)\n"
                             "X = SIN(30) + COS(-2*45) + TAN(L)\nINPUT L = 0.25\n";
    for (const std::string& head : {std::string(""), std::string("DEGREES ON\n")}) {
        AutolevTranslation t = translate_autolev(head + body, "degrees.al");
        ASSERT_TRUE(t.ok()) << messages(t);
        int notes = 0;
        for (const auto& d : t.diagnostics)
            if (d.severity == Severity::note && contains(d.message, "in degrees (DEGREES ON, its default)")) ++notes;
        EXPECT_EQ(notes, 3) << messages(t);  // 30 in SIMPROT, 30 and -2*45 in SIN and COS
        auto v = run(t.script, "evaluate dot(Ax>, Ny>)\nevaluate dot(Bx>, Ny>)\nevaluate X");
        const double pi = std::acos(-1.0);
        EXPECT_NEAR(v["="], 0.5, 1e-15) << t.script;
        EXPECT_NEAR(v["=#2"], std::sin(pi / 5), 1e-15) << t.script;
        EXPECT_NEAR(v["=#3"], 0.5 + std::cos(-pi / 2) + std::tan(0.25), 1e-15) << t.script;
    }
    AutolevTranslation off = translate_autolev("DEGREES OFF\n" + body, "radians.al");
    ASSERT_TRUE(off.ok()) << messages(off);
    auto v = run(off.script, "evaluate dot(Ax>, Ny>)\nevaluate X");
    EXPECT_NEAR(v["="], std::sin(30.0), 1e-14) << off.script;
    EXPECT_NEAR(v["=#2"], std::sin(30.0) + std::cos(-90.0) + std::tan(0.25), 1e-14) << off.script;
}

// A direction cosine matrix used as a value (R = N_A): element (i, j) is Ni> . Aj>, the matrix
// that N_A = [...] would orient A by. Checked against the rotation about N3> by Q, by hand.
TEST(AutolevImport, DirectionCosineMatrixAsAValue) {
    AutolevTranslation t = translate_autolev("DEGREES OFF\nNEWTONIAN N\nFRAMES A, B\nVARIABLES Q\nSIMPROT(N, A, 3, Q)\n"
                                             "SIMPROT(A, B, 1, 2*Q)\nR = N_A\nS = B_N*N_A\nX = R[1, 2] + 10*S[3, 2]\n",
                                             "dcm_value.al");
    ASSERT_TRUE(t.ok()) << messages(t);
    for (double q : {0.3, -1.2}) {
        auto v = run(t.script, "evaluate X at Q = " + std::to_string(q));
        // N1> . A2> = -sin Q; (B_N N_A)[3, 2] = B3> . A2> = -sin 2Q (B turned from A about A1> by 2Q)
        EXPECT_NEAR(v["="], -std::sin(q) - 10 * std::sin(2 * q), 1e-12) << t.script;
    }
}

TEST(AutolevImport, ExpressionsKeepTheirMeaning) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
FRAMES A
CONSTANTS A1, B, C, D, E
VARIABLES Q'
SIMPROT(N, A, 3, Q)
Z = -(A1 + B)^2/(C*D) - -E + 2^-1
W = A1/B/C - A1/(B/C) + .5
R> = 3*A1> - 4*A2>
S = MAG(R>) + DOT(EXPRESS(R>, N), N1>) + DOT(CROSS(N1>, N2>), N3>)
INPUT A1 = 1.5, B = 0.5, C = 2, D = 4, E = 3
)",
                                             "expr.al");
    ASSERT_TRUE(t.ok()) << t.diagnostics.front().message;
    auto v = run(t.script, "evaluate Z at Q = 0\nevaluate W at Q = 0\nevaluate S at Q = 0.5");
    EXPECT_NEAR(v["="], -4.0 / 8 + 3 + 0.5, 1e-14);
    EXPECT_NEAR(v["=#2"], 1.5 / 0.5 / 2 - 1.5 / 0.25 + 0.5, 1e-14);
    EXPECT_NEAR(v["=#3"], 5 + 3 * std::cos(0.5) + 4 * std::sin(0.5) + 1, 1e-14);
}

TEST(AutolevImport, ForcesTorquesAndPairsBecomeLoads) {
    AutolevTranslation t = translate_autolev(R"(NEWTONIAN N
BODIES A, B
POINTS P
CONSTANTS F, T
VARIABLES Q{2}''
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
P_NO_P> = N1>
V2PTS(N, A, NO, P)
FORCE(P, F*N2>)
FORCE(NO/P, F*N1>)
FORCE_P> = F*N3>
TORQUE(A, T*N3>)
TORQUE(A/B, T*A3>)
TORQUE_B> = -T*N3>
)",
                                             "loads.al");
    ASSERT_TRUE(t.ok());
    EXPECT_TRUE(contains(t.script, "force F_P on P = F*Ny>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "force F_P_2 on P from N_o = F*Nx>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "force F_P_3 on P = F*Nz>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "torque T_A on A = T*Nz>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "torque T_B on B from A = T*Az>\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "torque T_B_2 on B = -T*Nz>\n")) << t.script;
    run(t.script);
}

TEST(AutolevImport, StatementsWithoutCounterpartAreLeftOutWithAWarning) {
    std::string src = std::string("UNITSYSTEM KG, METER, SEC\nAUTOZ ON\n") + kPendulum + "PAUSE\n";
    AutolevTranslation t = translate_autolev(src, "extra.al");
    EXPECT_TRUE(t.ok());
    ASSERT_EQ(t.diagnostics.size(), 3u);
    EXPECT_EQ(t.diagnostics[0].severity, Severity::warning);
    EXPECT_EQ(t.diagnostics[0].location.line, 1);
    EXPECT_TRUE(contains(t.diagnostics[0].message, "UNITSYSTEM is not translated"));
    EXPECT_EQ(t.diagnostics[1].location.line, 2);
    EXPECT_EQ(t.diagnostics[2].location.line, 17);
    EXPECT_TRUE(contains(t.diagnostics[2].message, "PAUSE"));
    run(t.script);
}

TEST(AutolevImport, CodeDynamicsOfSpeedsIsGeneratedInCCppAndPython) {
    AutolevTranslation a = translate_autolev(std::string(kPendulum) + "CODE DYNAMICS() pendulum.m\n", "a.al");
    EXPECT_TRUE(a.ok());
    EXPECT_TRUE(contains(a.script, "codegen matlab name pendulum\n")) << a.script;
    // speeds of its own (Q' = 2 U): code in the speeds, in C, C++ and Python
    const std::string spring = R"(NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' Q', U'
P_NO_P> = Q*N1>
V_P_N> = 2*U*N1>
MASS P = 1
FORCE_P> = -Q*N1>
Q' = 2*U
ZERO = FR() + FRSTAR()
KANE()
)";
    AutolevTranslation b = translate_autolev(spring + "CODE DYNAMICS() spring.c\n", "b.al");
    EXPECT_TRUE(b.ok());
    EXPECT_TRUE(b.diagnostics.empty());
    EXPECT_TRUE(contains(b.script, "codegen c name spring\n")) << b.script;
    run(b.script);
    // MATLAB has no code for equations in speeds: left out, with a warning at its line
    AutolevTranslation c = translate_autolev(spring + "CODE DYNAMICS() spring.m\n", "c.al");
    EXPECT_TRUE(c.ok());
    ASSERT_EQ(c.diagnostics.size(), 1u);
    EXPECT_EQ(c.diagnostics[0].severity, Severity::warning);
    EXPECT_EQ(c.diagnostics[0].location.line, 11);
    EXPECT_TRUE(contains(c.diagnostics[0].message, "CODE DYNAMICS() to a MATLAB file")) << c.diagnostics[0].message;
    EXPECT_FALSE(contains(c.script, "codegen"));
}

// POLYNOMIAL(P, X) of an expression that is no polynomial in X translates (whether it is one
// shows when the script runs, as P may be any expression) and is refused there, naming P; the
// statement EIG(M, VALUES, VECTORS) of a complex or defective matrix likewise.
TEST(AutolevImport, PolynomialAndEigenvectorsOfTheWrongKindAreRefusedWhenTheScriptRuns) {
    auto runtime_error = [](const std::string& src) {
        AutolevTranslation t = translate_autolev(src, "runs.al");
        EXPECT_TRUE(t.ok()) << t.script;
        std::ostringstream out, err;
        Interpreter interp(out, err, false);
        EXPECT_EQ(interp.run(t.script, "runs.alb"), RunStatus::script_error) << out.str();
        return err.str();
    };
    std::string e = runtime_error("NEWTONIAN N\nCONSTANTS A\nVARIABLES Q\nP = A*SIN(Q)\nC = POLYNOMIAL(P, Q)\n");
    EXPECT_TRUE(contains(e, "polynomial(): 'P' is not a polynomial in 'Q'")) << e;
    e = runtime_error("NEWTONIAN N\nM = [0, -1; 1, 0]\nEIG(M, V, W)\n");
    EXPECT_TRUE(contains(e, "eig(): the eigenvalues of 'M' are complex: 0 - 1i, 0 + 1i")) << e;
    e = runtime_error("NEWTONIAN N\nM = [2, 1; 0, 2]\nEIG(M, V, W)\n");
    EXPECT_TRUE(contains(e, "eigvec(): 'M' is defective: its eigenvalue 2, repeated 2 times")) << e;
}

// Malformed or untranslatable input: each gives an error at the statement's line and column,
// and the translation is not ok (the command writes no script).
struct BadInput {
    const char* name;
    std::string source;
    int line, column;
    const char* fragment;
};

class AutolevErrors : public ::testing::TestWithParam<BadInput> {};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

TEST_P(AutolevErrors, NamesTheLineColumnAndTheProblem) {
    const BadInput& b = GetParam();
    AutolevTranslation t = translate_autolev(b.source, "bad.al");
    EXPECT_FALSE(t.ok()) << t.script;
    bool found = false;
    for (const auto& d : t.diagnostics)
        if (d.severity == Severity::error && d.location.line == b.line && d.location.column == b.column &&
            contains(d.message, b.fragment)) {
            found = true;
            EXPECT_FALSE(d.hint.empty() && std::string(b.fragment) != "unexpected character") << d.message;
        }
    std::string all;
    for (const auto& d : t.diagnostics)
        all += std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message + "\n";
    EXPECT_TRUE(found) << "expected " << b.line << ":" << b.column << " '" << b.fragment << "', got\n" << all;
}

const std::string kHead = "NEWTONIAN N\nBODIES A\nPOINTS P\nCONSTANTS L\nVARIABLES Q'', U'\n";  // 5 lines

INSTANTIATE_TEST_SUITE_P(
    Malformed, AutolevErrors,
    ::testing::Values(
        BadInput{"undeclared_name", kHead + "SIMPROT(N, A, 3, QQ)\n", 6, 18, "'QQ' is not declared"},
        BadInput{"unclosed_bracket", kHead + "SIMPROT(N, A, 3, Q\n", 6, 19, "expected ')'"},
        BadInput{"dangling_operator", kHead + "X = L +\n", 6, 8, "expected a value but found the end"},
        BadInput{"argument_count", kHead + "SIMPROT(N, A, 3)\n", 6, 1, "takes 4 arguments, not 3"},
        BadInput{"unknown_function", kHead + "X = BESSEL(Q)\n", 6, 5, "function 'BESSEL' is not translated"},
        BadInput{"unknown_statement", kHead + "FROBNICATE ALL\n", 6, 1, "not an Autolev statement"},
        BadInput{"vector_plus_scalar", kHead + "R> = N1> + L\n", 6, 10, "between a vector and a scalar"},
        BadInput{"dyad_as_vector", kHead + "R> = N1>*N2>\n", 6, 9, "a dyadic where a vector is expected"},
        BadInput{"vector_as_dyadic", kHead + "D>> = N1>\n", 6, 7, "a vector where a dyadic is expected"},
        BadInput{"undefined_dyadic", kHead + "R> = DOT(D>>, N1>)\n", 6, 10, "the dyadic 'D>>' is not defined"},
        BadInput{"dot_of_dyadics_as_vector", kHead + "D>> = 1>>\nR> = DOT(D>>, D>>)\n", 7, 6, "a dyadic where a vector is expected"},
        BadInput{"dot_dyadic_scalar", kHead + "D>> = 1>>\nR> = DOT(D>>, L)\n", 7, 15, "takes a vector beside a dyadic"},
        BadInput{"dyadic_in_sin", kHead + "D>> = 1>>\nX = SIN(D>>)\n", 7, 9, "a dyadic where a scalar is expected"},
        BadInput{"dyadic_times_vector", kHead + "D>> = 1>>\nR> = D>>*N1>\n", 7, 9, "'*' between a dyadic and a vector"},
        BadInput{"dyadic_plus_scalar", kHead + "D>> = 1>>\nX = D>> + L\n", 7, 9, "'+' between a dyadic and a scalar"},
        BadInput{"dyadic_to_scalar_name", kHead + "D>> = 1>>\nX = D>>\n", 7, 5, "without '>>'"},
        BadInput{"dt_of_dyadic_no_frame", kHead + "D>> = 1>>\nX>> = DT(D>>)\n", 7, 7, "DT of a dyadic needs the frame"},
        BadInput{"dt_of_dyadic_as_scalar", kHead + "D>> = 1>>\nX = DT(D>>, N)\n", 7, 5, "without '>>'"},
        BadInput{"matrix_of_scalar", kHead + "M = MATRIX(N, L)\n", 6, 15, "MATRIX() takes a vector or a dyadic"},
        BadInput{"inertia_of_a_frame", kHead + "D>> = INERTIA(P, N)\n", 6, 18, "INERTIA() takes bodies and particles"},
        BadInput{"vector_of_two", kHead + "R> = VECTOR(N, [L, L])\n", 6, 16, "not a 1 by 2 matrix"},
        BadInput{"same_name_other_case", "NEWTONIAN N\nCONSTANTS L, l\n", 2, 14, "'l' is already declared"},
        BadInput{"assign_a_constant", kHead + "L = 3\n", 6, 1, "'L' is a constant and cannot be assigned"},
        BadInput{"no_newtonian", "CONSTANTS L\nBODIES A\n", 1, 1, "no NEWTONIAN frame"},
        BadInput{"no_newtonian_with_mass", "FRAMES A\nPARTICLES P\nMASS P = 1\n", 1, 1, "no NEWTONIAN frame"},
        BadInput{"second_newtonian", "NEWTONIAN N\nNEWTONIAN M\n", 2, 1, "a second NEWTONIAN"},
        BadInput{"input_undeclared", kHead + "INPUT LL = 3\n", 6, 7, "'LL' in INPUT is not declared"},
        BadInput{"input_not_a_number", kHead + "INPUT L = 2*Q\n", 6, 12, "must be a number"},
        BadInput{"unknown_unit", kHead + "INPUT L = 3 FURLONG\n", 6, 7, "the unit 'FURLONG' is not translated"},
        BadInput{"fr_alone", kHead + "X = FR()\n", 6, 5, "FR() is translated only in ZERO"},
        BadInput{"zero_other", kHead + "ZERO = FR()\n", 6, 8, "ZERO is translated only as"},
        BadInput{"undeclared_point_in_position", kHead + "P_NO_PP> = L*N1>\n", 6, 1, "has the form of a position"},
        BadInput{"undefined_vector", kHead + "R> = S1>\n", 6, 6, "the vector 'S1>' is not defined"},
        BadInput{"mass_of_a_point", kHead + "MASS P = 2\n", 6, 6, "MASS takes a body or a particle"},
        BadInput{"inertia_count", kHead + "INERTIA A, 1, 2\n", 6, 1, "3 or 6 measures, not 2"},
        BadInput{"dependent_count", kHead + "DEPENDENT[1] = U\nCONSTRAIN(DEPENDENT[U, Q])\n", 7, 1,
                 "2 dependent speeds for 1 constraints"},
        BadInput{"kinematics_of_constant", kHead + "L' = U\n", 6, 1, "'L' is not a variable"},
        BadInput{"auxiliary_count", kHead + "AUXILIARY[1] = U\nCONSTRAIN(AUXILIARY[U, Q])\n", 7, 1,
                 "2 auxiliary speeds for 1 auxiliary constraints"},
        BadInput{"auxiliary_of_constant", kHead + "AUXILIARY[1] = U\nCONSTRAIN(AUXILIARY[L])\n", 7, 21,
                 "AUXILIARY[...] lists speeds"},
        BadInput{"kane_force_without_auxiliary", kHead + "SPECIFIED F\nKANE(F)\n", 7, 6,
                 "the file has no auxiliary speeds to bring them out"},
        BadInput{"kane_force_a_constant", kHead + "AUXILIARY[1] = U\nCONSTRAIN(AUXILIARY[U])\nKANE(L)\n", 8, 6,
                 "KANE(...) names the load measures the auxiliary equations determine"},
        BadInput{"constrain_other", kHead + "CONSTRAIN(U)\n", 6, 11, "CONSTRAIN() takes DEPENDENT[U3, ...] or AUXILIARY"},
        BadInput{"point_not_body", kHead + "V2PTS(N, A, P, A)\n", 6, 16, "expected a point"},
        BadInput{"simprot_axis", kHead + "SIMPROT(N, A, 4, Q)\n", 6, 15, "SIMPROT about this axis"},
        BadInput{"too_many_indexed", "NEWTONIAN N\nCONSTANTS I{99999}\n", 2, 13, "more than 1000"},
        BadInput{"too_many_indexed_2d", "NEWTONIAN N\nCONSTANTS I{40,40}\n", 2, 13, "more than 1000"},
        // algebra functions: what they take, those without a counterpart, and DEGREES
        BadInput{"coef_of_vector", kHead + "X = COEF(L*N1>, Q)\n", 6, 11, "COEF() takes a scalar here"},
        BadInput{"taylor_no_point", kHead + "X = TAYLOR(SIN(Q), 0:3)\n", 6, 5, "TAYLOR() takes the expression, the orders"},
        BadInput{"taylor_orders", kHead + "X = TAYLOR(SIN(Q), 3:1, Q = 0)\n", 6, 21, "run from the lower to the higher"},
        BadInput{"taylor_order_symbol", kHead + "X = TAYLOR(SIN(Q), 0:L, Q = 0)\n", 6, 22, "must be whole numbers"},
        BadInput{"solve_in_expression", kHead + "X = SOLVE(L*Q - 1, Q)\n", 6, 5, "SOLVE() is translated as a statement"},
        BadInput{"solve_count", kHead + "SOLVE(L*Q - 1, Q, L)\n", 6, 16, "1 equation for 2 unknowns"},
        BadInput{"solve_zero", kHead + "SOLVE(ZERO, Q'')\n", 6, 7, "SOLVE(ZERO, ...) needs ZERO = FR() + FRSTAR()"},
        BadInput{"solve_twice", kHead + "SOLVE(L*Q - 1, Q)\nSOLVE(L*Q - 2, Q)\n", 7, 16, "'Q' is solved for already"},
        BadInput{"solve_by_vector", kHead + "SOLVE(L*Q - 1, N1>)\n", 6, 16, "SOLVE() solves for constants, variables"},
        BadInput{"evaluate_alone", kHead + "X = EVALUATE(L*Q)\n", 6, 5, "EVALUATE() without substitutions"},
        BadInput{"replace_by_number", kHead + "X = REPLACE(L*Q, 2 = Q)\n", 6, 18, "REPLACE() substitutes for a constant"},
        BadInput{"replace_no_equals", kHead + "X = REPLACE(L*Q, Q)\n", 6, 18, "REPLACE() takes substitutions X = v"},
        BadInput{"substitution_elsewhere", kHead + "X = SIN(Q = 1)\n", 6, 11, "a substitution 'x = v' stands only"},
        BadInput{"expand_range", kHead + "X = EXPAND(L*Q, 2)\n", 6, 5, "EXPAND() with a range of terms"},
        BadInput{"d_by_time", kHead + "X = D(L*Q, T)\n", 6, 12, "D() by time is not translated"},
        BadInput{"d_of_vector", kHead + "X = D(L*N1>, Q)\n", 6, 8, "D() of a vector is not translated"},
        BadInput{"d_by_number", kHead + "X = D(L*Q, 2)\n", 6, 12, "D() differentiates by a constant"},
        BadInput{"rhs_of_variable", kHead + "X = RHS(Q)\n", 6, 9, "RHS() is translated for a name the file assigns"},
        BadInput{"dt_of_matrix_in_frame", kHead + "M = [Q, L]\nX = DT(M, N)\n", 7, 11, "DT of a matrix takes no frame"},
        BadInput{"degrees_unknown", "DEGREES HALF\n" + kHead, 1, 1, "DEGREES HALF is not an Autolev setting"},
        BadInput{"asin_of_number_in_degrees", kHead + "X = ASIN(1/2)\n", 6, 5, "ASIN() of a number is an angle in degrees"},
        BadInput{"atan_of_number_by_default", "DEGREES OFF\nDEGREES ON\n" + kHead + "X = L*ATAN(1)\n", 8, 7,
                 "ATAN() of a number is an angle in degrees"},
        // matrices: their sizes, and what the matrix functions take
        BadInput{"matrix_ragged", kHead + "M = [1, 2; 3]\n", 6, 12, "the rows of matrix 'M' have different lengths"},
        BadInput{"matrix_arithmetic", kHead + "M = [1, 2]\nX = M + 1\n", 7, 7, "'+' between a matrix and a scalar"},
        BadInput{"matrix_sizes", kHead + "M = [1, 2]\nX = M*M\n", 7, 6, "'*' between a 1 by 2 and a 1 by 2 matrix"},
        BadInput{"matrix_as_scalar", kHead + "M = [1, 2]\nX = SIN(M)\n", 7, 9, "SIN() takes a scalar here, not a matrix"},
        BadInput{"matrix_to_scalar", kHead + "X = L\nX = DIAGMAT(2, L)\n", 7, 5, "'X' is a scalar and is assigned only a scalar"},
        BadInput{"inv_not_square", kHead + "X = INV([1, 2])\n", 6, 9, "INV() takes a square matrix, and this is 1 by 2"},
        BadInput{"det_of_scalar", kHead + "X = DET(L)\n", 6, 9, "DET() takes a matrix here, not a scalar"},
        BadInput{"diagmat_size", kHead + "X = DIAGMAT(L, 1)\n", 6, 13, "the number of rows of DIAGMAT() must be a whole number"},
        BadInput{"element_outside", kHead + "X = ELEMENT([1, 2], 2, 1)\n", 6, 5, "[2, 1] is outside the 1 by 2 matrix"},
        BadInput{"rows_outside", kHead + "M = [1, 2]\nX = ROWS(M, 2)\n", 7, 13, "row 2 is outside the 1 by 2 matrix"},
        BadInput{"eig_vectors", kHead + "X = EIG([1, 0; 0, 1], V, W)\n", 6, 5, "EIG() with names for the eigenvalues"},
        BadInput{"eig_statement_count", kHead + "EIG([1, 0; 0, 1], V, W, X)\n", 6, 1, "EIG() as a statement takes the matrix"},
        BadInput{"eig_values_into_constant", kHead + "EIG([1, 0; 0, 1], L)\n", 6, 19, "'L' is a constant and cannot be assigned the eigenvalues"},
        BadInput{"eig_values_own_matrix", kHead + "M = [1, 0; 0, 1]\nEIG(M, M)\n", 7, 8, "EIG() would assign 'M', its own matrix"},
        BadInput{"eig_names_alike", kHead + "EIG([1, 0; 0, 1], V, V)\n", 6, 22, "EIG() names its eigenvalues and eigenvectors alike"},
        BadInput{"eig_into_constant", kHead + "EIG([1, 0; 0, 1], L, W)\n", 6, 19, "'L' is a constant and cannot be assigned the eigenvalues"},
        BadInput{"eig_not_square", kHead + "EIG([1, 2], V, W)\n", 6, 5, "EIG() takes a square matrix, and this is 1 by 2"},
        BadInput{"eig_own_matrix", kHead + "M = [1, 0; 0, 1]\nEIG(M, M, W)\n", 7, 8, "EIG() would assign 'M', its own matrix"},
        BadInput{"polynomial_of_vector", kHead + "X = POLYNOMIAL(N1>, Q)\n", 6, 16, "POLYNOMIAL() takes a polynomial or a row or column"},
        BadInput{"polynomial_of_matrix", kHead + "X = POLYNOMIAL([1, 2; 3, 4], Q)\n", 6, 16, "and this is 2 by 2"},
        BadInput{"exclude_no_symbol", kHead + "X = EXCLUDE(L*Q)\n", 6, 5, "EXCLUDE() takes the expression and at least one symbol"},
        BadInput{"include_by_number", kHead + "X = INCLUDE(L*Q, 2)\n", 6, 18, "INCLUDE() takes constants, variables or specified"},
        BadInput{"exclude_solved", kHead + "SOLVE(L*Q - 1, Q)\nX = EXCLUDE(L*Q, Q)\n", 7, 18, "'Q' stands for its solution after SOLVE"},
        BadInput{"roots_by_number", kHead + "X = ROOTS(Q^2 - 1, 2)\n", 6, 20, "ROOTS() takes a constant, variable"},
        BadInput{"mass_of_point", kHead + "X = MASS(P)\n", 6, 10, "MASS() takes bodies and particles here"},
        BadInput{"cm_count", kHead + "X> = CM()\n", 6, 6, "CM() takes 1 argument, not 0"},
        BadInput{"angvel_count", kHead + "X> = ANGVEL(N)\n", 6, 6, "ANGVEL() takes 2 arguments, not 1"},
        BadInput{"matrix_outside", kHead + "M = [1, 2]\nX = M[3]\n", 7, 5, "[1, 3] is outside matrix 'M'"},
        BadInput{"matrix_element_assigned", kHead + "M = [1, 2]\nM[1] = 2\n", 7, 1, "an element of matrix 'M'"},
        // arrays assigned by element: every element there when used whole, indices as assigned
        BadInput{"array_gap", kHead + "Z[1] = L*Q\nZ[3] = L\nSOLVE(Z, Q, U)\n", 8, 7,
                 "array 'Z' is used whole, and its element 'Z[2]' is not assigned"},
        BadInput{"array_element_unassigned", kHead + "Z[1] = L\nX = Z[2]\n", 7, 5, "'Z[2]' is not assigned"},
        BadInput{"array_index_count", kHead + "Z[1] = L\nX = Z[1, 1]\n", 7, 5, "array 'Z' is assigned with one index"},
        BadInput{"array_index_symbol", kHead + "Z[L] = 1\n", 6, 3, "the index of array 'Z' must be a whole number"},
        BadInput{"array_of_constant", kHead + "L[1] = 2\n", 6, 1, "'L' is a constant and cannot be assigned as an array"},
        BadInput{"array_element_matrix", kHead + "Z[1] = [1, 2]\n", 6, 8, "an element of array 'Z' is a scalar, not a matrix"},
        BadInput{"array_element_vector", kHead + "Z[1] = N1>\n", 6, 8, "a vector where a scalar is expected"},
        BadInput{"array_compound_unassigned", kHead + "Z[1] += L\n", 6, 1, "the array 'Z' is not assigned"},
        BadInput{"array_of_another_kind", kHead + "X = Q[1]\n", 6, 5, "'Q' is a variable, not an array"},
        BadInput{"zero_element_after_kane", kHead + "ZERO = FR() + FRSTAR()\nZERO[1] = L\n", 7, 1,
                 "ZERO holds Kane's equations here"},
        BadInput{"zero_element_of_kane", kHead + "ZERO = FR() + FRSTAR()\nX = ZERO[Q]\n", 7, 5,
                 "an element of Kane's equations is ZERO[i], i a whole number from 1"},
        BadInput{"kane_after_zero_elements", kHead + "ZERO[1] = L*Q''\nKANE()\n", 7, 1,
                 "KANE() forms Kane's equations from the bodies and loads"},
        // inertia about another point than the mass centre
        BadInput{"inertia_about_without_mass", kHead + "INERTIA A(P), 1, 1, 1\n", 6, 9, "'A' has no MASS"},
        BadInput{"inertia_about_without_position", kHead + "MASS A = L\nINERTIA A(P), 1, 1, 1\n", 7, 9,
                 "the file gives no position of A's mass centre from that point"},
        BadInput{"kane_before_inertia_placed", kHead + "MASS A = L\nINERTIA A(P), 1, 1, 1\nKANE()\nP_P_AO> = L*A1>\n", 8, 1,
                 "KANE() needs the inertia of INERTIA A(P) at line 7"},
        BadInput{"inertia_dyadic_before_placed", kHead + "INERTIA A(P), 1, 1, 1\nD>> = I_A_AO>>\n", 7, 7,
                 "the inertia of 'A' needs the inertia of INERTIA A(P) at line 6"},
        BadInput{"a1pt_count", kHead + "A1PT(N, A, P)\n", 6, 1, "takes 4 arguments, not 3"},
        BadInput{"a1pt_point_not_frame", kHead + "A1PT(N, P, P, P)\n", 6, 9, "expected a frame or body"},
        BadInput{"inertia_about_two_points", kHead + "INERTIA A(P, P), 1, 1, 1\n", 6, 9, "takes one point"},
        BadInput{"inertia_about_a_frame", kHead + "INERTIA A(N), 1, 1, 1\n", 6, 11, "expected a point"},
        BadInput{"non_ascii", kHead + "X = 2\xC2\xB7L\n", 6, 6, "unexpected character"},
        BadInput{"nesting", kHead + "X = " + std::string(80, '(') + "L" + std::string(80, ')') + "\n", 6, 69,
                 "nested more than 64 levels"},
        BadInput{"force_on_a_loose_point", kHead + "FORCE(P, L*N1>)\n", 6, 1, "acts on no body"},
        BadInput{"code_without_kane", kHead + "CODE DYNAMICS() x.c\n", 6, 1, "CODE DYNAMICS() without KANE()"},
        BadInput{"code_fortran", kHead + "CODE DYNAMICS() x.for\n", 6, 1, "'.for' file is not translated"},
        BadInput{"trailing_tokens", kHead + "KANE() KANE()\n", 6, 8, "after the statement"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

// Statements with no counterpart in the script (as opposed to input that cannot be read or
// cannot mean anything): each is left out with a warning at its line and column, a comment
// at its place in the script and its line in left_out_lines; the translation is ok and the
// script runs.
class AutolevLeftOut : public ::testing::TestWithParam<BadInput> {};

TEST_P(AutolevLeftOut, WarnsAtTheLineColumnAndTheScriptRuns) {
    const BadInput& b = GetParam();
    AutolevTranslation t = translate_autolev(b.source, "out.al");
    EXPECT_TRUE(t.ok()) << messages(t);
    bool found = false;
    for (const auto& d : t.diagnostics)
        if (d.severity == Severity::warning && d.location.line == b.line && d.location.column == b.column &&
            contains(d.message, b.fragment)) {
            found = true;
            EXPECT_EQ(d.message.rfind("left out", 0), 0u) << d.message;
            EXPECT_FALSE(d.hint.empty()) << d.message;
        }
    EXPECT_TRUE(found) << "expected " << b.line << ":" << b.column << " '" << b.fragment << "', got\n" << messages(t);
    EXPECT_TRUE(contains(t.script, "# left out (out.al:" + std::to_string(b.line) + "): ")) << t.script;
    EXPECT_NE(std::find(t.left_out_lines.begin(), t.left_out_lines.end(), b.line), t.left_out_lines.end());
    run(t.script);
}

INSTANTIATE_TEST_SUITE_P(
    NoCounterpart, AutolevLeftOut,
    ::testing::Values(
        BadInput{"dyadic_times_dyadic", kHead + "D>> = 1>>\nE>> = D>>*D>>\n", 7, 10, "'*' between two dyadics has no counterpart"},
        BadInput{"inertia_assigned", kHead + "I_A_AO>> = 1>>\n", 6, 1, "is an inertia dyadic"},
        BadInput{"gravity_on_some", kHead + "GRAVITY(-L*N2>, A)\n", 6, 17, "GRAVITY on some bodies only has no counterpart"},
        BadInput{"three_dimensional_index", "NEWTONIAN N\nCONSTANTS K, I{3,3,3}, J\n", 2, 14,
                 "'I{...}' has 3 indices, and the script's indexed names have at most two (I111, ..., I333"},
        BadInput{"factor", kHead + "X = FACTOR(L*Q + L, L)\n", 6, 5, "FACTOR() has no translation: FACTOR(e) is factor(e)"},
        BadInput{"sqr", kHead + "X = SQR(L)\n", 6, 5, "SQR() has no translation: whether it is read as the square"},
        BadInput{"kinetic_energy", kHead + "X = KE()\n", 6, 5, "KE() has no translation: write the sum"},
        BadInput{"complex_on", kHead + "COMPLEX ON\n", 6, 1, "COMPLEX ON has no counterpart: the script's numbers are real"},
        BadInput{"imaginary", kHead + "IMAGINARY J\n", 6, 11, "IMAGINARY J has no counterpart"},
        BadInput{"definition", kHead + "SPECIFIED F = SQR(L)\nX = F\n", 6, 15, "SQR() has no translation"},
        BadInput{"array_three_indices", kHead + "Z[1, 1, 1] = 1\n", 6, 1, "an array of 3 indices ('Z[...]') has no counterpart"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return p.param.name; });

// A statement that uses what a left-out statement defined is left out too, naming it and its
// line, and so on down the chain; a name assigned again means the new value.
TEST(AutolevImport, StatementsUsingALeftOutNameAreLeftOut) {
    AutolevTranslation t = translate_autolev(
        kHead + "X = SQR(L)\nY = 2*X\nZ = Y + L\nW = L\nX = 3*L\nV = X + W\n", "chain.al");
    EXPECT_TRUE(t.ok()) << messages(t);
    const std::string all = messages(t);
    EXPECT_TRUE(contains(all, "6:5: left out: the Autolev function SQR() has no translation")) << all;
    EXPECT_TRUE(contains(all, "7:7: left out: uses X, which line 6 left out")) << all;
    EXPECT_TRUE(contains(all, "8:5: left out: uses Y, which line 7 left out")) << all;
    EXPECT_EQ(t.left_out_lines, (std::vector<int>{6, 7, 8}));
    EXPECT_TRUE(contains(t.script, "# left out (chain.al:7): uses X, which line 6 left out\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "W = L\nX = 3*L\nV = X + W\n")) << t.script;
    std::map<std::string, double> v = run(t.script, "evaluate V at L = 2");
    ASSERT_TRUE(v.count("=")) << t.script;
    EXPECT_DOUBLE_EQ(v["="], 8.0);  // X = 3 L and W = L at L = 2
}

// A rotation left out leaves its frame unoriented: what uses the frame or its unit vectors is
// left out with it.
TEST(AutolevImport, AFrameLeftUnorientedTakesItsUsesWithIt) {
    AutolevTranslation t = translate_autolev(
        kHead + "SIMPROT(N, A, 3, SQR(Q))\nR> = L*A1>\nX = DOT(R>, N1>)\nY = L*Q\n", "frame.al");
    EXPECT_TRUE(t.ok()) << messages(t);
    const std::string all = messages(t);
    EXPECT_TRUE(contains(all, "6:18: left out: the Autolev function SQR() has no translation")) << all;
    EXPECT_TRUE(contains(all, "7:8: left out: uses A1>, which line 6 left out")) << all;
    EXPECT_TRUE(contains(all, "8:9: left out: uses R>, which line 7 left out")) << all;
    EXPECT_EQ(t.left_out_lines, (std::vector<int>{6, 7, 8}));
    EXPECT_TRUE(contains(t.script, "Y = L*Q\n")) << t.script;
    run(t.script);
}

// A model given by its differential equations whose every equation is left out forms no model,
// and says so; CODE DYNAMICS() is left out with it; what is left runs.
TEST(AutolevImport, EquationsOfMotionLeftOutLeaveNoModelAndSaySo) {
    AutolevTranslation t = translate_autolev(
        "NEWTONIAN N\nCONSTANTS K\nVARIABLES X''\nX'' = -K*SQR(X)\nCODE DYNAMICS() osc.c\nINPUT K = 2, X = 1\n",
        "none.al");
    EXPECT_TRUE(t.ok()) << messages(t);
    const std::string all = messages(t);
    EXPECT_TRUE(contains(all, "4:1: the file's equations of motion (line 4) are left out, so the script forms no model"))
        << all;
    EXPECT_TRUE(contains(all, "4:10: left out: the Autolev function SQR() has no translation")) << all;
    EXPECT_TRUE(contains(all, "5:1: left out: CODE DYNAMICS() needs the equations of motion, which line 4 left out"))
        << all;
    EXPECT_EQ(t.left_out_lines, (std::vector<int>{4, 5}));
    EXPECT_FALSE(contains(t.script, "kane ")) << t.script;
    EXPECT_FALSE(contains(t.script, "codegen")) << t.script;
    EXPECT_TRUE(contains(t.script, "# left out (none.al:5): CODE DYNAMICS() needs the equations")) << t.script;
    run(t.script);
}

// One message per bad statement, and the good statements around them still translated.
TEST(AutolevImport, EveryBadStatementIsReportedInFileOrder) {
    AutolevTranslation t = translate_autolev(kHead + "X = BESSEL(Q)\nR> = L*N1>\nY = L +\nZ = UNDECLARED\n", "three.al");
    ASSERT_EQ(t.diagnostics.size(), 3u);
    EXPECT_EQ(t.diagnostics[0].location.line, 6);
    EXPECT_EQ(t.diagnostics[1].location.line, 8);
    EXPECT_EQ(t.diagnostics[2].location.line, 9);
    EXPECT_TRUE(contains(t.script, "R> = L*Nx>\n"));
}

// ZERO = FR() + FRSTAR() after ZERO[i] = ...: Kane's equations replace the file's own array, as
// an assignment replaces a value, and SOLVE(ZERO, ...) then solves Kane's equations.
TEST(AutolevImport, KanesEquationsReplaceAnArrayZero) {
    AutolevTranslation t = translate_autolev(
        kHead + "ZERO[1] = L*Q''\nX = ZERO[1]\nZERO = FR() + FRSTAR()\nKANE()\nSOLVE(ZERO, Q'')\n", "zero.al");
    EXPECT_TRUE(t.ok()) << t.script;
    EXPECT_TRUE(contains(t.script, "ZERO_1 = L*Q''\nX = ZERO_1\n")) << t.script;
    EXPECT_TRUE(contains(t.script, "solve K for Q'' as Qdd_solved")) << t.script;
}

TEST(AutolevImport, EmptyFileGivesAnEmptyScript) {
    AutolevTranslation t = translate_autolev("% nothing but a comment\n\n", "empty.al");
    EXPECT_TRUE(t.ok());
    EXPECT_TRUE(t.diagnostics.empty());
    run(t.script);
}

// Damaged models (characters deleted, repeated or replaced at random, from a fixed seed)
// never make the translator throw or crash: each gives a script or says what is wrong where.
TEST(AutolevImport, DamagedModelsGiveMessagesNotCrashes) {
    std::ifstream f(std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/models/rolling_disk.al");
    std::ostringstream buf;
    buf << f.rdbuf();
    const std::string model = buf.str();
    ASSERT_FALSE(model.empty());
    const std::string alphabet = "%'>()[]{},;=+-*/^:0123456789._ABNQUXYZ \n\x01\xC3";
    std::mt19937 rng(7);
    int failures = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::string s = model;
        int edits = 1 + static_cast<int>(rng() % 4);
        for (int k = 0; k < edits && !s.empty(); ++k) {
            std::size_t at = rng() % s.size();
            switch (rng() % 3) {
                case 0: s.erase(at, 1 + rng() % 8); break;
                case 1: s.insert(at, s.substr(rng() % s.size(), 1 + rng() % 30)); break;
                default: s[at] = alphabet[rng() % alphabet.size()]; break;
            }
        }
        AutolevTranslation t;
        EXPECT_NO_THROW(t = translate_autolev(s, "damaged.al"));
        for (const auto& d : t.diagnostics) {
            EXPECT_GE(d.location.line, 1);
            EXPECT_GE(d.location.column, 1);
            EXPECT_FALSE(d.message.empty());
        }
        if (!t.ok()) ++failures;
    }
    EXPECT_GT(failures, 100);  // the damage was noticed, not translated silently
}

}  // namespace
