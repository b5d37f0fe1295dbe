// SPDX-License-Identifier: MIT
// A row's equation checked term by term in the units a script declares.
#include "alembert/lang/equation_units.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "alembert/sym/symbol_table.hpp"
#include "support/script_dir.hpp"

using namespace alembert;
using alembert::lang::Dimension;
using alembert::lang::EquationUnitChecker;

namespace equation_units_test {

namespace {

// a pendulum's rotate row, T - m g d sin(q) - (I + m d^2) q'' (N*m), its symbols' dimensions
// given by name; `T_unit` is T's
struct Pendulum {
    SymbolTable st;
    ex g = st.add_constant("g", 9.81), m = st.add_constant("m", 2), d = st.add_constant("d", 0.5),
       I = st.add_constant("I", 0.1), T = st.add_unknown("T");
    TimeVariable q = st.add_variable("q", 2);
    std::map<std::string, Dimension> dims{
        {"g", Dimension::length() / pow(Dimension::time(), 2)}, {"m", Dimension::mass()},
        {"d", Dimension::length()}, {"I", Dimension::mass() * pow(Dimension::length(), 2)},
        {"q", Dimension::none()}, {"q'", pow(Dimension::time(), -1)}, {"q''", pow(Dimension::time(), -2)},
        {"T", Dimension::torque()}};
    EquationUnitChecker checker() {
        return EquationUnitChecker(st, [this](const ex& s) {
            auto it = dims.find(st.name(s));
            return it == dims.end() ? Dimension::open() : it->second;
        });
    }
    ex equation() const {
        return T - m * g * d * GiNaC::sin(q) - (I + m * d * d) * q.d(2);
    }
};

}  // namespace

TEST(EquationUnits, APendulumsRotateRowIsInNewtonMetres) {
    Pendulum p;
    const ReportUnitCheck c = p.checker().check(p.equation(), Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::consistent);
    EXPECT_EQ(c.unit, "N*m");
    EXPECT_EQ(c.summary, "units: N\u00b7m");
}

TEST(EquationUnits, ATorqueDeclaredInNewtonsIsNamed) {
    Pendulum p;
    p.dims["T"] = Dimension::force();
    const ReportUnitCheck c = p.checker().check(p.equation(), Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::inconsistent);
    ASSERT_EQ(c.terms.size(), 1u);
    EXPECT_EQ(c.terms[0], "T is in N");
    EXPECT_EQ(c.summary, "units: the term T is in N, not N\u00b7m");
}

TEST(EquationUnits, ASumInsideATermWhoseTermsDifferIsNamed) {
    // (I + m d) q'': I in kg*m^2 but m d in kg*m
    Pendulum p;
    const ex e = p.T - (p.I + p.m * p.d) * p.q.d(2);
    const ReportUnitCheck c = p.checker().check(e, Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::inconsistent);
    EXPECT_NE(c.summary.find("in a sum, "), std::string::npos) << c.summary;
    // each term of the sum named with its unit, in whichever order the sum keeps its terms
    EXPECT_TRUE(std::regex_search(c.summary, std::regex(R"(\bI (is )?in kg\*m\^2)"))) << c.summary;
    EXPECT_TRUE(std::regex_search(c.summary, std::regex(R"(\bd\*m (is )?in kg\*m\b(?!\^))"))) << c.summary;
}

TEST(EquationUnits, IntermediatesCarryTheirDefinitionsDimension) {
    // z = m g d sin(q), a torque, named once and used in the row
    Pendulum p;
    const ex z = p.st.add_intermediate(p.m * p.g * p.d * GiNaC::sin(p.q));
    EXPECT_EQ(p.checker().check(p.T - z, Dimension::torque()).verdict, ReportUnitCheck::Verdict::consistent);
    p.dims["d"] = Dimension::none();  // z is then a force
    const ReportUnitCheck c = p.checker().check(p.T - z, Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::inconsistent);
    EXPECT_EQ(c.terms.at(0), "-z1 is in N");
}

TEST(EquationUnits, ALengthWrittenAsADecimalNumberLeavesTheRowUncheckedNotWrong) {
    // the pendulum with its length written `0.35 m` in the model: the equation holds 0.35,
    // its metre gone, so the weight's moment m g 0.35 sin(q) reads as a force
    Pendulum p;
    const ex d = GiNaC::numeric(0.35);
    const ex row = p.T - p.m * p.g * d * GiNaC::sin(p.q.symbol()) - (p.I + p.m * d * d) * p.q.d(2);
    const ReportUnitCheck c = p.checker().check(row, Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::unchecked) << c.summary;
    EXPECT_NE(c.summary.find("not checked (a decimal number"), std::string::npos) << c.summary;
    // a term off without a decimal number in it is still named
    p.dims["T"] = Dimension::force();
    const ReportUnitCheck wrong = p.checker().check(row, Dimension::torque());
    EXPECT_EQ(wrong.verdict, ReportUnitCheck::Verdict::inconsistent) << wrong.summary;
    ASSERT_FALSE(wrong.terms.empty());
    EXPECT_EQ(wrong.terms[0], "T is in N");
    // a decimal number without a unit in a term that is right leaves the row checked:
    // I + 0.5 m d^2 (0.5 a pure number)
    p.dims["T"] = Dimension::torque();
    const ex half = GiNaC::numeric(0.5);
    const ex right = p.T - p.m * p.g * p.d * GiNaC::sin(p.q.symbol()) - (p.I + half * p.m * p.d * p.d) * p.q.d(2);
    const ReportUnitCheck ok = p.checker().check(right, Dimension::torque());
    EXPECT_EQ(ok.verdict, ReportUnitCheck::Verdict::consistent) << ok.summary;
    // inside a sum: (0.35 + d) adds a bare number to a length, unchecked rather than wrong
    const ex nested = p.T - p.m * p.g * (d + p.d) * GiNaC::sin(p.q.symbol());
    EXPECT_EQ(p.checker().check(nested, Dimension::torque()).verdict, ReportUnitCheck::Verdict::unchecked);
}

TEST(EquationUnits, SymbolsWithoutUnitsLeaveTheRowUnchecked) {
    Pendulum p;
    p.dims.erase("I");
    const ReportUnitCheck c = p.checker().check(p.equation(), Dimension::torque());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::unchecked);
    EXPECT_EQ(c.summary, "units: not checked (no units declared for I)");
    p.dims.clear();
    EXPECT_EQ(p.checker().check(p.equation(), Dimension::torque()).summary,
              "units: not checked (no units declared for I, T, d, g, m, q, q'')");
}

TEST(EquationUnits, ConstraintRowsTermsAgreeWithOneAnother) {
    Pendulum p;
    const ex e = p.d * GiNaC::cos(p.q) - p.d;  // lengths
    EXPECT_EQ(p.checker().check(e, Dimension::open()).verdict, ReportUnitCheck::Verdict::consistent);
    const ReportUnitCheck c = p.checker().check(p.d * GiNaC::cos(p.q) - p.m, Dimension::open());
    EXPECT_EQ(c.verdict, ReportUnitCheck::Verdict::inconsistent);
}

TEST(EquationUnits, TheReportOfAScriptShowsEachRowsUnits) {
    // the sit-to-stand's rows: torques in N*m, joint forces in N; qA declared without a unit
    // turns a frame, so it is an angle
    test::TempDir dir;
    test::ScriptInDir r(dir.path);
    r.run(test::read_text(std::filesystem::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/model.alb")
              .substr(0, test::read_text(std::filesystem::path(ALEMBERT_SOURCE_DIR) /
                                         "examples/sit_to_stand/model.alb")
                             .find("roadmap E for")) +
          "roadmap E for T_A, T_B, T_C, F_Ac, F_As, F_Kc, F_Ks, F_Hc, F_Hs\n"
          "report at qA = 20 deg, qB = -70 deg, qC = 60 deg to \"rep\"\n");
    const std::string page = test::read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"units\":{\"verdict\":\"consistent\",\"unit\":\"N*m\",\"summary\":\"units: N\u00b7m\""),
              std::string::npos);
    EXPECT_NE(page.find("\"units\":{\"verdict\":\"consistent\",\"unit\":\"N\",\"summary\":\"units: N\""),
              std::string::npos);
    EXPECT_EQ(page.find("\"verdict\":\"inconsistent\""), std::string::npos);
    EXPECT_EQ(page.find("\"verdict\":\"unchecked\""), std::string::npos);
    // free-body diagrams of each body: 9 equations in 9 unknowns, beside the torques' 3 rows
    EXPECT_NE(page.find("\"brute_force\":{\"formed\":true,\"planar\":true,\"equations\":9,\"unknowns\":9,"
                        "\"reactions\":6,\"asked\":3,\"rows\":3"),
              std::string::npos);
}

TEST(EquationUnits, TheBruteForceCountOfOneBodyIsASentence) {
    // one particle in the plane: its two equations of motion, said of the one body
    test::TempDir dir;
    test::ScriptInDir r(dir.path);
    r.run("newtonian N\nparticle P\nconstant m = 2 kg\nvariable x'' m\nunknown F N\n"
          "translate P from N_o by x*Nx>\nmass P = m\nforce push on P = F*Nx>\n"
          "roadmap E for x''\nreport to \"rep\"\n");
    const std::string page = test::read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("(brute-force Newton\u2013Euler, planar): 1 particle gives 2 equations (2 per particle)"),
              std::string::npos);
}

TEST(EquationUnits, AScriptWithoutUnitsSaysNotChecked) {
    test::TempDir dir;
    test::ScriptInDir r(dir.path);
    r.run("newtonian N\nparticle P\nconstant m = 2, k = 50\nvariable x''\nunknown F\n"
          "translate P from N_o by x*Nx>\nmass P = m\nforce push on P = F*Nx>\n"
          "roadmap E for x''\nreport to \"rep\"\n");
    const std::string page = test::read_text(dir.path / "rep" / "index.html");
    EXPECT_NE(page.find("\"verdict\":\"unchecked\""), std::string::npos);
    EXPECT_NE(page.find("units: not checked (no units declared for "), std::string::npos);
    EXPECT_EQ(page.find("\"verdict\":\"consistent\""), std::string::npos);
}

}  // namespace equation_units_test
