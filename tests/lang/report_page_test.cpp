// SPDX-License-Identifier: MIT
// The report of a script: its diagrams drawn at a configuration the model takes (where solve
// puts it, or with its loops closed), every result the script printed on the page, values in
// the units the script declared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/script_dir.hpp"

namespace report_page {

namespace {

using alembert::test::read_text;
using alembert::test::ScriptInDir;
using alembert::test::TempDir;

// The four-bar of examples/four_bar_linkage: crank A (0.4 m) from N_o, coupler B (1.2 m),
// rocker C (0.8 m) from N_c = 1 m along Nx>, the loop closed where B's tip meets C's
const std::string kFourBar = R"(newtonian N
body A, B, C
point N_c
point A_tip on A; point B_tip on B; point C_tip on C
constant L_N = 1 m, L_A = 0.4 m, L_B = 1.2 m, L_C = 0.8 m, g = 9.81 m/s^2
constant m_A = 1 kg, m_B = 2 kg, m_C = 1.5 kg
variable qA'' rad, qB'' rad, qC'' rad
unknown T N*m, F_x N, F_y N
rotate A from N about z by qA
rotate B from A about z by qB
rotate C from N about z by qC
translate A_o from N_o by 0>; translate N_c from N_o by L_N*Nx>; translate C_o from N_c by 0>
translate A_tip from A_o by L_A*Ax>; translate B_o from A_tip by 0>
translate B_tip from B_o by L_B*Bx>; translate C_tip from C_o by L_C*Cx>
translate Acm from A_o by L_A/2*Ax>
translate Bcm from B_o by L_B/2*Bx>
translate Ccm from C_o by L_C/2*Cx>
mass A = m_A; mass B = m_B; mass C = m_C
inertia A = 0, 0, m_A*L_A^2/12; inertia B = 0, 0, m_B*L_B^2/12; inertia C = 0, 0, m_C*L_C^2/12
gravity -g*Ny>
torque T on A from N = T*Nz>
force F_BC on B_tip from C_tip = F_x*Nx> + F_y*Ny>
constraint configuration loop = pos(B_tip, C_tip) in N
)";

struct Xy {
    double x = NAN, y = NAN;
};

// where the page's geometry puts point `name` (printed to 6 significant digits)
Xy point_at(const std::string& page, const std::string& name) {
    std::smatch m;
    const std::regex re("\\{\"name\":\"" + name + "\",\"at\":\\[([-0-9.e+]+),([-0-9.e+]+),([-0-9.e+]+)\\]\\}");
    if (!std::regex_search(page, m, re)) {
        ADD_FAILURE() << "no point " << name << " in the page's geometry";
        return {};
    }
    return {std::stod(m[1]), std::stod(m[2])};
}

double distance(Xy a, Xy b) { return std::hypot(a.x - b.x, a.y - b.y); }

// the loop drawn closed: the coupler's tip on the rocker's, each link its own length, the
// crank at 60 degrees; to the 6 digits the page prints
void expect_drawn_closed_at_60_degrees(const std::string& page) {
    const Xy A_tip = point_at(page, "A_tip"), B_o = point_at(page, "B_o"), B_tip = point_at(page, "B_tip"),
             C_tip = point_at(page, "C_tip"), N_c = point_at(page, "N_c");
    EXPECT_NEAR(A_tip.x, 0.4 * std::cos(M_PI / 3), 1e-6);
    EXPECT_NEAR(A_tip.y, 0.4 * std::sin(M_PI / 3), 1e-6);
    EXPECT_NEAR(distance(B_o, A_tip), 0, 1e-6);
    EXPECT_NEAR(distance(B_tip, C_tip), 0, 1e-5) << "the loop is torn open";
    EXPECT_NEAR(distance(B_o, B_tip), 1.2, 1e-5);
    EXPECT_NEAR(distance(N_c, C_tip), 0.8, 1e-5);
    // each of the loop's equations met at the drawn configuration
    std::smatch m;
    std::string rest = page;
    int residuals = 0;
    const std::regex re("\\{\"name\":\"loop_[xyz]\",\"residual\":([-0-9.e+]+)\\}");
    while (std::regex_search(rest, m, re)) {
        EXPECT_LE(std::abs(std::stod(m[1])), 1e-9) << m[0];
        ++residuals;
        rest = m.suffix();
    }
    EXPECT_GE(residuals, 2);
}

}  // namespace

TEST(ReportPage, AFourBarIsDrawnWhereSolvePutsIt) {
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run(kFourBar +
          "roadmap S for T, F_x, F_y, qB, qC statics\n"
          "solve S for T, F_x, F_y, qB, qC guess qB = -30 deg, qC = 85 deg at qA = 60 deg\n"
          "report to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    expect_drawn_closed_at_60_degrees(page);
    EXPECT_NE(page.find("\"configuration_source\":\"where solve at line 25 puts it\""), std::string::npos);
    const std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    EXPECT_NE(tex.find("Drawn at qA = 1.0472 rad, "), std::string::npos);
    EXPECT_NE(tex.find("(where solve at line 25 puts it)."), std::string::npos);
}

TEST(ReportPage, ALoopIsClosedFromTheInitialValuesWhenNothingWasSolved) {
    // only the crank's angle given: qB and qC are solved for from 0 until the loop closes
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run(kFourBar + "initial qA = 60 deg\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    expect_drawn_closed_at_60_degrees(page);
    EXPECT_NE(page.find("\"configuration_source\":\"the initial values, with qB, qC solved to close the loops\""),
              std::string::npos);
}

TEST(ReportPage, WhatSolveEvaluateAndLinearizePrintedIsOnThePageUnderItsStatement) {
    TempDir dir;
    ScriptInDir r(dir.path);
    // a mass on a spring: x'' = (F - k x)/m; at rest under F the spring stretches F/k
    r.run("newtonian N\nparticle P\nconstant m = 2 kg, k = 50 N/m\nvariable x''\nunknown F N\n"
          "translate P from N_o by x*Nx>\nmass P = m\nforce push on P = F*Nx>\n"
          "spring s between P and N_o stiffness k length 0\n"
          "kane K for x\n"
          "solve K for x guess x = 0.1 m at x' = 0, x'' = 0, F = 10 N\n"
          "evaluate k/m\n"
          "evaluate 2*k/m \\\n    - k/m\n"
          "report to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    const std::string printed = r.out.str();
    // x = F/k = 0.2 m, k/m = 25 per s^2
    EXPECT_NE(printed.find("x = 0.2\n"), std::string::npos) << printed;
    EXPECT_NE(page.find("{\"line\":11,\"statement\":\"solve K for x guess x = 0.1 m at x' = 0, x'' = 0, F = 10 N\","
                        "\"text\":\"x = 0.2\\n\"}"),
              std::string::npos);
    EXPECT_NE(page.find("{\"line\":12,\"statement\":\"evaluate k/m\",\"text\":\"= 25"), std::string::npos);
    // a statement continued over two lines is shown on one
    EXPECT_NE(page.find("{\"line\":13,\"statement\":\"evaluate 2*k/m - k/m\",\"text\":\"= 25"), std::string::npos);
    const std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    EXPECT_NE(tex.find("\\subsection*{Results}\nLine 11:\n\\begin{verbatim}\n> solve K for x guess x = 0.1 m at x' = 0, "
                       "x'' = 0, F = 10 N\nx = 0.2\n\\end{verbatim}"),
              std::string::npos)
        << tex.substr(tex.find("Results") == std::string::npos ? 0 : tex.find("Results"));
}

TEST(ReportPage, ConstantsAndTheConfigurationAreShownInTheUnitsTheScriptDeclared) {
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nbody A\nconstant L = 41.82 cm, m = 6.5 kg, g = 9.81 m/s^2\nvariable q'' deg\n"
          "rotate A from N about z by q\ntranslate A_o from N_o by 0>\ntranslate Acm from A_o by L*Ay>\n"
          "mass A = m\ninertia A = 0, 0, 0\ngravity -g*Ny>\ninitial q = 30 deg\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    // 41.82 cm, not its SI value beside the unit cm
    EXPECT_NE(page.find("{\"name\":\"L\",\"value\":41.82,\"unit\":\"cm\"}"), std::string::npos);
    EXPECT_NE(page.find("{\"name\":\"q\",\"value\":0.523599,\"shown\":30,\"unit\":\"deg\"}"), std::string::npos);
    EXPECT_NE(page.find("\"configuration_source\":\"the initial values\""), std::string::npos);
}

TEST(ReportPage, ACoordinateWithoutAUnitIsShownInMetresOnlyWherePositionsMakeItALength) {
    // x places P along Nx> (x Nx>, L + x Ny> for P2): a length, in m; s enters only as L s,
    // a number times the length L; q only inside sin and cos (a particle's swing, turning no
    // frame): neither is given a unit
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nparticle P, P2, Q, R\nconstant m = 1 kg, L = 2 m, g = 9.81 m/s^2\nvariable x'', s'', q''\n"
          "translate P from N_o by x*Nx>\ntranslate P2 from N_o by (L + x)*Ny>\n"
          "translate Q from N_o by L*s*Ny>\ntranslate R from N_o by L*sin(q)*Nx> - L*cos(q)*Ny>\n"
          "mass P = m; mass P2 = m; mass Q = m; mass R = m\ngravity -g*Ny>\n"
          "initial x = 0.3, s = 0.5, q = 0.25, x' = 2\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("{\"name\":\"x\",\"value\":0.3,\"shown\":0.3,\"unit\":\"m\"}"), std::string::npos);
    EXPECT_NE(page.find("{\"name\":\"x'\",\"value\":2,\"shown\":2,\"unit\":\"m/s\"}"), std::string::npos);
    EXPECT_NE(page.find("{\"name\":\"s\",\"value\":0.5,\"shown\":0.5,\"unit\":\"\"}"), std::string::npos);
    EXPECT_NE(page.find("{\"name\":\"q\",\"value\":0.25,\"shown\":0.25,\"unit\":\"\"}"), std::string::npos);
}

TEST(ReportPage, TheLoadsAreDrawnWithTheValuesTheSolveTookAndNoneItDidNot) {
    // a block on a spring (k = 50 N/m, L0 = 0.4 m) and a damper, pushed by F: solve takes
    // x' = 0 and F = 10 N, and finds x = L0 + F/k = 0.6 m; there the spring pulls back with
    // k (x - L0) = 10 N, the push is 10 N along Nx, the damper's c x' = 0
    const std::string model =
        "newtonian N\nparticle Q\nconstant m = 2 kg, k = 50 N/m, c = 3 N*s/m, L0 = 0.4 m\n"
        "variable x'' m\nspecified F N\ntranslate Q from N_o by x*Nx>\nmass Q = m\n"
        "spring k1 between Q and N_o stiffness k length L0\ndamper c1 between Q and N_o coefficient c\n"
        "force push on Q = F*Nx>\nkane K for x\n"
        "solve K for x guess x = 0.5 m at x' = 0, x'' = 0, F = 10 N\n";
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run(model + "report to \"rep\"\n");
    std::string page = read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"label\":\"push\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[10,0,0],"), std::string::npos);
    EXPECT_NE(page.find("\"label\":\"k1\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[-10,0,0],"), std::string::npos);
    EXPECT_NE(page.find("\"label\":\"c1\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[0,0,0],"), std::string::npos);
    EXPECT_EQ(page.find("\"given\":false"), std::string::npos);
    EXPECT_NE(page.find("\"configuration_data\":[{\"name\":\"x'\",\"value\":0,\"shown\":0,\"unit\":\"m/s\"},"
                        "{\"name\":\"x''\",\"value\":0,\"shown\":0,\"unit\":\"m/s^2\"},"
                        "{\"name\":\"F\",\"value\":10,\"shown\":10,\"unit\":\"N\"}]"),
              std::string::npos);
    std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    EXPECT_NE(tex.find("Drawn at x = 0.6 m, with x' = 0 m/s, x'' = 0 m/s\\textasciicircum{}2, F = 10 N (where solve at "
                       "line 12 puts it)."),
              std::string::npos);
    // drawn at a chosen x, at no state of the run: neither F nor x' is given there, so the
    // push and the damper have no value (not the 0 they would be evaluated at)
    TempDir other;
    ScriptInDir at(other.path);
    at.run(model + "report at x = 0.5 m to \"rep\"\n");
    page = read_text(other.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"label\":\"push\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[],"), std::string::npos);
    EXPECT_NE(page.find("\"label\":\"c1\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[],"), std::string::npos);
    EXPECT_NE(page.find("\"label\":\"k1\",\"at\":\"Q\",\"on\":\"Q\",\"vector\":[-5,0,0],"), std::string::npos);
    EXPECT_NE(page.find("\"configuration_data\":[]"), std::string::npos);
    tex = read_text(other.path / "rep" / "roadmap.tex");
    EXPECT_EQ(tex.find("$= 0$"), std::string::npos);
    EXPECT_NE(tex.find("Value not given at this configuration, drawn in its positive sense: c1, push."), std::string::npos);
}

TEST(ReportPage, LongResultLinesAreBrokenInTheLatexDocument) {
    // a result line longer than the page is continued on indented lines of at most 80
    // characters, so the verbatim block stays inside the margins
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nconstant a_rather_long_name_for_a_constant = 1, another_rather_long_name = 2\n"
          "evaluate a_rather_long_name_for_a_constant + another_rather_long_name + a_rather_long_name_for_a_constant*"
          "another_rather_long_name + a_rather_long_name_for_a_constant/another_rather_long_name\n"
          "latex to \"rep\"\n");
    const std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    const std::size_t begin = tex.find("\\begin{verbatim}"), end = tex.find("\\end{verbatim}");
    ASSERT_NE(begin, std::string::npos);
    ASSERT_NE(end, std::string::npos);
    std::istringstream lines(tex.substr(begin, end - begin));
    std::string line;
    int count = 0;
    while (std::getline(lines, line)) {
        EXPECT_LE(line.size(), 80u) << line;
        ++count;
    }
    EXPECT_GE(count, 4);  // \begin, the statement over two lines at least, the result
}

TEST(ReportPage, TheEquationsKaneAndLagrangeFormedAreOnThePageAndInTheLatex) {
    // a mass on a spring: Kane's and Lagrange's one equation each, 0 = -k x - m x''
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nparticle P\nconstant m = 2 kg, k = 50 N/m\nvariable x''\n"
          "translate P from N_o by x*Nx>\nmass P = m\nspring s between P and N_o stiffness k length 0\n"
          "kane K for x\nlagrange L for x\nkane K for x\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    // in run order, a name formed again in its later place, each with its line
    const std::size_t L = page.find("{\"name\":\"L\",\"method\":\"Lagrange's method\",\"line\":9,\"equations\":[\"");
    const std::size_t K = page.find("{\"name\":\"K\",\"method\":\"Kane's method\",\"line\":10,\"equations\":[\"");
    ASSERT_NE(L, std::string::npos);
    ASSERT_NE(K, std::string::npos);
    EXPECT_LT(L, K);
    EXPECT_EQ(page.find("\"line\":8,\"equations\""), std::string::npos) << "K's first forming is replaced";
    // each equation holds the spring's k x and the inertia m x''
    for (std::size_t at : {L, K}) {
        const std::string set = page.substr(at, page.find("]}", at) - at);
        EXPECT_NE(set.find("k"), std::string::npos) << set;
        EXPECT_NE(set.find("{x}''"), std::string::npos) << set;
    }
    const std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    EXPECT_NE(tex.find("\\subsection*{Lagrange's method: L (line 9)}"), std::string::npos);
    EXPECT_NE(tex.find("\\subsection*{Kane's method: K (line 10)}"), std::string::npos);
    EXPECT_NE(tex.find("\\eqline{\\mathrm{K}[1]\\colon\\ "), std::string::npos);
}

TEST(ReportPage, APositionIsNoStickAndASlidingConnectionNoJointForce) {
    // a cart C on a rail at x Nx> from the origin, a rod A pinned to it at C_o: the vector from
    // N_o to C_o is where the cart is, not a body, and the rail lets C slide along Nx> (no
    // joint force there); the pin at C_o is a joint (A's row about C_o draws its force)
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nbody C, A\nconstant M = 2 kg, m = 1 kg, L = 0.5 m, g = 9.81 m/s^2\n"
          "variable x'', th''\nunknown F N\nrotate C from N about z by 0\nrotate A from N about z by th\n"
          "translate C_o from N_o by x*Nx>\ntranslate Ccm from C_o by 0>\ntranslate A_o from C_o by 0>\n"
          "translate Acm from A_o by L*Ay>\nmass C = M; mass A = m\ninertia C = 0, 0, 0; inertia A = 0, 0, m*L^2/12\n"
          "gravity -g*Ny>\nforce push on C_o = F*Nx>\nroadmap E for F, th''\ninitial x = 0.3, th = 20 deg\n"
          "report to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"segments\":[{\"body\":\"A\",\"from\":\"A_o\",\"to\":\"Acm\"}]"), std::string::npos)
        << page.substr(page.find("\"segments\""), 200);
    const std::size_t F = page.find("{\"variable\":\"F\""), th = page.find("{\"variable\":\"th''\"");
    ASSERT_NE(F, std::string::npos);
    ASSERT_NE(th, std::string::npos);
    const std::string F_row = page.substr(F, th - F), th_row = page.substr(th);
    EXPECT_EQ(F_row.find("\"kind\":\"joint\""), std::string::npos) << F_row;
    EXPECT_NE(th_row.find("\"kind\":\"joint\",\"label\":\"from C\""), std::string::npos);
}

TEST(ReportPage, AParticleOnAStringOfFixedLengthIsDrawnWithItsString) {
    // a simple pendulum written in N's axes: P at L (sin q Nx> - cos q Ny>) from the pivot; the
    // distance stays L, so the line from N_o to P is drawn as P's string; a bead placed at a
    // changing distance (r Nx>) is not joined to the origin by a stick
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run("newtonian N\nparticle P, Q\nconstant m = 1 kg, L = 2 m, g = 9.81 m/s^2\nvariable q'', r''\n"
          "translate P from N_o by L*sin(q)*Nx> - L*cos(q)*Ny>\ntranslate Q from N_o by r*Nx>\n"
          "mass P = m; mass Q = m\ngravity -g*Ny>\ninitial q = 30 deg, r = 1\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"segments\":[{\"body\":\"P\",\"from\":\"N_o\",\"to\":\"P\"}]"), std::string::npos)
        << page.substr(page.find("\"segments\""), 200);
}

// The numbers of the JSON array that follows `key` at or after `from` in `page` (null: NAN)
std::vector<double> numbers_after(const std::string& page, const std::string& key, std::size_t from) {
    std::vector<double> out;
    const std::size_t at = page.find(key, from);
    if (at == std::string::npos) {
        ADD_FAILURE() << "no " << key << " in the page after " << from;
        return out;
    }
    std::size_t i = page.find('[', at) + 1;
    const std::size_t end = page.find(']', i);
    while (i < end) {
        std::size_t next = std::min(page.find(',', i), end);
        const std::string item = page.substr(i, next - i);
        out.push_back(item == "null" ? NAN : std::stod(item));
        i = next + 1;
    }
    return out;
}

TEST(ReportPage, ASweepsEigenvaluesArePlottedUnderItsResultAndCrossZeroAtTheDisksCriticalSpin) {
    // examples/rolling_disk: a thin disk (radius r, A = m r^2/4 about a diameter, C = m r^2/2
    // about its axle) rolling upright at spin Omega. By hand, linearized (Routh): lean th and
    // heading psi obey (A + m r^2) th'' + (C + m r^2) Omega psi' - m g r th = 0 and
    // A psi'' = C Omega th', so (A + m r^2) th'' = (m g r - (C + m r^2) C Omega^2 / A) th:
    // lambda^2 = 4 (g - 3 r Omega^2) / (5 r), and every other eigenvalue is 0. The real parts
    // cross zero at Omega^2 = g/(3 r).
    TempDir dir;
    ScriptInDir r(dir.path);
    const std::string script =
        read_text(std::filesystem::path(ALEMBERT_SOURCE_DIR) / "examples" / "rolling_disk" / "model.alb");
    r.run(script + "report to \"rep\"\nreport plot none to \"bare\"\n");
    const double g = 9.81, radius = 0.3;
    const std::string page = read_text(dir.path / "rep" / "index.html");
    // the result of the linearize at line 29, its sweep under it, named by statement and file
    const std::size_t result = page.find("{\"line\":29,\"statement\":\"linearize K at q2 = 0");
    ASSERT_NE(result, std::string::npos);
    const std::size_t sweep =
        page.find("\"sweep\":{\"title\":\"linearize at line 29 (spin_sweep/eigenvalues.csv)\"", result);
    ASSERT_NE(sweep, std::string::npos) << page.substr(result, 600);
    EXPECT_EQ(page.find("\"sweep\":", result), sweep);
    EXPECT_NE(page.find("\"parameter\":\"Omega\",\"unit\":\"rad/s\"", sweep), std::string::npos);
    const std::vector<double> omega = numbers_after(page, "\"values\":", sweep);
    ASSERT_EQ(omega.size(), 21u);  // 0 to 10 rad/s in steps of 0.5
    for (std::size_t i = 0; i < omega.size(); ++i) EXPECT_DOUBLE_EQ(omega[i], 0.5 * static_cast<double>(i));
    // the 8 states' real parts, then their imaginary parts, each on its axis in 1/s
    std::vector<std::vector<double>> re, im;
    for (int k = 1; k <= 8; ++k) {
        const std::string n = std::to_string(k);
        const std::size_t a = page.find("{\"name\":\"re_" + n + "\",\"axis\":\"real part\",\"unit\":\"1/s\"", sweep);
        const std::size_t b = page.find("{\"name\":\"im_" + n + "\",\"axis\":\"imaginary part\",\"unit\":\"1/s\"", sweep);
        ASSERT_NE(a, std::string::npos) << "re_" << n;
        ASSERT_NE(b, std::string::npos) << "im_" << n;
        re.push_back(numbers_after(page, "\"values\":", a));
        im.push_back(numbers_after(page, "\"values\":", b));
        ASSERT_EQ(re.back().size(), omega.size());
        ASSERT_EQ(im.back().size(), omega.size());
    }
    EXPECT_EQ(page.find("{\"name\":\"re_9\"", sweep), std::string::npos);
    // at each spin: the largest real part and the largest imaginary part are the lean's
    // sqrt(|lambda^2|) by hand (the page prints 6 significant digits), the rest of the real
    // parts are not above it
    double last_unstable = -1, first_stable = -1;
    for (std::size_t i = 0; i < omega.size(); ++i) {
        const double l2 = 4 * (g - 3 * radius * omega[i] * omega[i]) / (5 * radius);
        double top_re = -INFINITY, top_im = -INFINITY;
        for (std::size_t k = 0; k < re.size(); ++k) {
            top_re = std::max(top_re, re[k][i]);
            top_im = std::max(top_im, im[k][i]);
        }
        SCOPED_TRACE("Omega = " + std::to_string(omega[i]));
        EXPECT_NEAR(top_re, std::sqrt(std::max(0.0, l2)), 1e-5 * std::max(1.0, std::sqrt(std::abs(l2))));
        EXPECT_NEAR(top_im, std::sqrt(std::max(0.0, -l2)), 1e-5 * std::max(1.0, std::sqrt(std::abs(l2))));
        if (top_re > 1e-3) last_unstable = omega[i];
        if (top_re <= 1e-3 && first_stable < 0) first_stable = omega[i];
    }
    // the real parts cross zero between the samples either side of Omega = sqrt(g/(3 r))
    const double critical = std::sqrt(g / (3 * radius));  // 3.30151 rad/s
    EXPECT_DOUBLE_EQ(last_unstable, 3.0);
    EXPECT_DOUBLE_EQ(first_stable, 3.5);
    EXPECT_LT(last_unstable, critical);
    EXPECT_GT(first_stable, critical);
    // and the crossing the statement printed beside it, found by bisection, is the hand value
    const std::size_t crosses = page.find("a real part crosses zero at Omega = ", result);
    ASSERT_LT(crosses, sweep);
    EXPECT_NEAR(std::stod(page.substr(crosses + std::string("a real part crosses zero at Omega = ").size())), critical,
                1e-4);
    // with the plots turned off the result stays and its sweep goes
    const std::string bare = read_text(dir.path / "bare" / "index.html");
    EXPECT_NE(bare.find("{\"line\":29,\"statement\":\"linearize K at q2 = 0"), std::string::npos);
    EXPECT_EQ(bare.find("\"sweep\":"), std::string::npos);
}

namespace {

// A number as roadmap.tex writes it in a table's cell or a plot's coordinate: 5.11468,
// $-5.11468$, $1.5\cdot 10^{-5}$, 1.5e-5
double tex_number(const std::string& text) {
    std::smatch m;
    static const std::regex re(
        "\\s*\\$?(-?[0-9.]+(?:e-?[0-9]+)?)(?:\\\\cdot 10\\^\\{(-?[0-9]+)\\})?\\$?\\s*");
    if (!std::regex_match(text, m, re)) {
        ADD_FAILURE() << "not a number: '" << text << "'";
        return NAN;
    }
    return std::stod(m[1]) * (m[2].matched ? std::pow(10.0, std::stoi(m[2])) : 1.0);
}

// The columns of the tables in `tex`, by their names (the first row of each; "re\_1 [1/s]"
// read as re_1), each a map from the swept value (a row's first number) to the row's number
std::map<std::string, std::map<double, double>> tex_table_columns(const std::string& tex) {
    std::map<std::string, std::map<double, double>> out;
    for (std::size_t at = tex.find("\\begin{tabular}"); at != std::string::npos;
         at = tex.find("\\begin{tabular}", at + 1)) {
        const std::size_t begin = tex.find('\n', at) + 1, end = tex.find("\\end{tabular}", at);
        std::vector<std::vector<std::string>> rows;
        for (std::size_t i = begin; i < end;) {
            std::size_t stop = std::min(tex.find("\\\\\n", i), end);
            std::string line = tex.substr(i, stop - i);
            for (std::size_t h; (h = line.find("\\hline")) != std::string::npos;) line.erase(h, 6);
            std::vector<std::string> cells;
            std::stringstream ss(line);
            for (std::string c; std::getline(ss, c, '&');) cells.push_back(c);
            if (line.find_first_not_of(" \n") != std::string::npos) rows.push_back(cells);
            i = stop + 3;
        }
        if (rows.empty()) continue;
        std::vector<std::string> names;
        for (std::string n : rows[0]) {
            n = std::regex_replace(n, std::regex("\\s*\\[.*\\]\\s*$|^\\s+|\\s+$"), "");
            names.push_back(std::regex_replace(n, std::regex("\\\\_"), "_"));
        }
        for (std::size_t r = 1; r < rows.size(); ++r) {
            const double x = tex_number(rows[r][0]);
            for (std::size_t k = 0; k < rows[r].size() && k < names.size(); ++k)
                out[names[k]][x] = tex_number(rows[r][k]);
        }
    }
    return out;
}

// The series of the plots in `tex`, by their legend entries: each (x, y) of its coordinates
std::map<std::string, std::vector<std::pair<double, double>>> tex_plot_series(
    const std::string& tex) {
    std::map<std::string, std::vector<std::pair<double, double>>> out;
    for (std::size_t at = tex.find("\\addplot["); at != std::string::npos;
         at = tex.find("\\addplot[", at + 1)) {
        const std::size_t begin = tex.find("coordinates {", at) + 13, end = tex.find("};", begin);
        const std::size_t legend = tex.find("\\addlegendentry{", end) + 16;
        const std::string name = std::regex_replace(
            tex.substr(legend, tex.find("}\n", legend) - legend), std::regex("\\\\_"), "_");
        const std::string coordinates = tex.substr(begin, end - begin);
        static const std::regex pair("\\(([^,()]+),([^,()]+)\\)");
        for (auto it = std::sregex_iterator(coordinates.begin(), coordinates.end(), pair);
             it != std::sregex_iterator(); ++it)
            out[name].emplace_back(tex_number((*it)[1]), tex_number((*it)[2]));
    }
    return out;
}

}  // namespace

// roadmap.tex holds the sweep too, under the linearize's printed text: the numbers of its
// table and of its plots are the disk's hand result at every sample they show
TEST(ReportPage, ASweepsEigenvaluesInRoadmapTexAreTheHandResultAndCrossZeroAtTheDisksCriticalSpin) {
    // by hand (see the test above): lambda^2 = 4 (g - 3 r Omega^2) / (5 r), every other
    // eigenvalue 0; the real parts cross zero at Omega^2 = g/(3 r)
    TempDir dir;
    ScriptInDir r(dir.path);
    const std::string script = read_text(std::filesystem::path(ALEMBERT_SOURCE_DIR) / "examples" /
                                         "rolling_disk" / "model.alb");
    r.run(script + "report to \"rep\"\nreport plot none to \"bare\"\n");
    const double g = 9.81, radius = 0.3;
    const auto lambda2 = [&](double omega) {
        return 4 * (g - 3 * radius * omega * omega) / (5 * radius);
    };
    const std::string tex = read_text(dir.path / "rep" / "roadmap.tex");
    // the linearize's result at line 29, its sweep under its text
    const std::size_t result = tex.find("Line 29:\n\\begin{verbatim}\n> linearize K at q2 = 0");
    ASSERT_NE(result, std::string::npos);
    const std::size_t after = tex.find("\\end{verbatim}", result);
    ASSERT_NE(after, std::string::npos);
    const std::string sweep = tex.substr(after, tex.find("\\end{document}", after) - after);
    // the table: the spins and each eigenvalue it lists (the rest are 0 at every spin)
    const auto columns = tex_table_columns(sweep);
    ASSERT_TRUE(columns.count("Omega")) << sweep.substr(0, 3000);
    std::vector<double> omega;
    for (const auto& [x, v] : columns.at("Omega")) omega.push_back(v);
    ASSERT_EQ(omega.size(), 21u);  // 0 to 10 rad/s in steps of 0.5: all 21, no more than 25
    for (std::size_t i = 0; i < omega.size(); ++i)
        EXPECT_DOUBLE_EQ(omega[i], 0.5 * static_cast<double>(i));
    std::size_t re_columns = 0, im_columns = 0;
    double last_unstable = -1, first_stable = -1;
    for (double w : omega) {
        SCOPED_TRACE("Omega = " + std::to_string(w));
        const double l2 = lambda2(w), tol = 1e-5 * std::max(1.0, std::sqrt(std::abs(l2)));
        const double re = std::sqrt(std::max(0.0, l2)), im = std::sqrt(std::max(0.0, -l2));
        double top_re = 0, low_re = 0, top_im = 0, low_im = 0;  // the series left out are 0
        re_columns = im_columns = 0;
        for (const auto& [name, values] : columns) {
            if (name == "Omega") continue;
            ASSERT_TRUE(values.count(w)) << name;
            const double v = values.at(w);
            const bool real = name.rfind("re_", 0) == 0;
            ASSERT_TRUE(real || name.rfind("im_", 0) == 0) << name;
            (real ? re_columns : im_columns) += 1;
            // each listed value is the lean's pair or 0
            EXPECT_TRUE(std::abs(v) < tol || std::abs(std::abs(v) - (real ? re : im)) < tol)
                << name << " = " << v;
            (real ? top_re : top_im) = std::max(real ? top_re : top_im, v);
            (real ? low_re : low_im) = std::min(real ? low_re : low_im, v);
        }
        EXPECT_NEAR(top_re, re, tol);
        EXPECT_NEAR(low_re, -re, tol);
        EXPECT_NEAR(top_im, im, tol);
        EXPECT_NEAR(low_im, -im, tol);
        if (top_re > 1e-3) last_unstable = w;
        if (top_re <= 1e-3 && first_stable < 0) first_stable = w;
    }
    EXPECT_GE(re_columns, 2u);
    EXPECT_GE(im_columns, 2u);
    // the zero crossing the table shows is where the hand result puts it, and so is the one
    // the statement printed above it
    const double critical = std::sqrt(g / (3 * radius));  // 3.30151 rad/s
    EXPECT_DOUBLE_EQ(last_unstable, 3.0);
    EXPECT_DOUBLE_EQ(first_stable, 3.5);
    EXPECT_LT(last_unstable, critical);
    EXPECT_GT(first_stable, critical);
    const std::string crosses = "a real part crosses zero at Omega = ";
    const std::size_t said = tex.find(crosses, result);
    ASSERT_LT(said, after);
    EXPECT_NEAR(std::stod(tex.substr(said + crosses.size())), critical, 1e-4);
    // the plots: each series' points are the hand result at its spins (a series 0 at every
    // spin drawn as one line at 0), the lean's pair leaving the real axis between 3 and 3.5
    const auto series = tex_plot_series(sweep);
    EXPECT_GE(series.size(), 4u);
    std::map<double, double> top_re, top_im;
    for (const auto& [name, points] : series) {
        const bool real = name.rfind("re_", 0) == 0;
        ASSERT_TRUE(real || name.rfind("im_", 0) == 0) << name;
        ASSERT_GE(points.size(), 2u) << name;
        for (const auto& [x, y] : points) {
            const double l2 = lambda2(x), tol = 1e-5 * std::max(1.0, std::sqrt(std::abs(l2)));
            const double pair = std::sqrt(std::max(0.0, real ? l2 : -l2));
            EXPECT_TRUE(std::abs(y) < tol || std::abs(std::abs(y) - pair) < tol)
                << name << " at " << x << ": " << y;
            auto& top = real ? top_re : top_im;
            top[x] = top.count(x) ? std::max(top[x], y) : y;
        }
    }
    ASSERT_EQ(top_re.size(), 21u);
    for (const auto& [x, y] : top_re) {
        EXPECT_NEAR(y, std::sqrt(std::max(0.0, lambda2(x))),
                    1e-5 * std::max(1.0, std::sqrt(std::abs(lambda2(x)))));
        EXPECT_NEAR(top_im.at(x), std::sqrt(std::max(0.0, -lambda2(x))),
                    1e-5 * std::max(1.0, std::sqrt(std::abs(lambda2(x)))));
    }
    EXPECT_GT(top_re.at(3.0), 1e-3);
    EXPECT_LT(top_re.at(3.5), 1e-3);
    // with the plots turned off: the table stays, the plots go
    const std::string bare = read_text(dir.path / "bare" / "roadmap.tex");
    EXPECT_EQ(bare.find("\\begin{axis}"), std::string::npos);
    EXPECT_EQ(bare.find("pgfplots"), std::string::npos);
    EXPECT_EQ(tex_table_columns(bare.substr(bare.find("Line 29:"))).at("Omega").size(), 21u);
}

}  // namespace report_page
