// SPDX-License-Identifier: MIT
// Printers spell numbers, names and instructions as each target language reads them.
#include "alembert/codegen/code_printer.hpp"

#include <sstream>

#include "alembert/sym/evaluator.hpp"
#include "support/expect.hpp"

using namespace alembert;

TEST(CodePrinter, NumbersReadBackAsTheSameDouble) {
    CPrinter c;
    for (double x : {0.1, 1.0 / 3.0, 2.0, -7.25e-300, 6.02214076e23}) {
        std::string s = c.number(x);
        EXPECT_EQ(std::stod(s), x) << s;
        EXPECT_NE(s.find_first_of(".e"), std::string::npos) << s;  // never an integer literal
    }
    EXPECT_EQ(c.number(2.0), "2.0");
    EXPECT_EQ(MatlabPrinter().number(1.0 / 0.0), "Inf");
    EXPECT_EQ(PythonPrinter().number(-1.0 / 0.0), "-math.inf");
}

TEST(CodePrinter, IdentifiersAreValidUniqueAndClearOfReservedWords) {
    std::set<std::string> taken;
    CPrinter c;
    EXPECT_EQ(c.identifier("qA''", taken), "qApp");
    EXPECT_EQ(c.identifier("qA'", taken), "qAp");
    EXPECT_EQ(c.identifier("qAp", taken), "qAp_");  // a user's qAp stays distinct
    EXPECT_EQ(c.identifier("double", taken), "double_");
    EXPECT_EQ(c.identifier("z3", taken), "z3_");  // numbered intermediates are ours
    EXPECT_EQ(c.identifier("sin", taken), "sin_");
    std::set<std::string> py;
    EXPECT_EQ(PythonPrinter().identifier("lambda", py), "lambda_");
    std::set<std::string> m;
    EXPECT_EQ(MatlabPrinter().identifier("end", m), "end_");
    std::set<std::string> cpp;
    EXPECT_EQ(CppPrinter().identifier("class", cpp), "class_");
}

TEST(CodePrinter, ProgramsPrintAsStatementsOfEachLanguage) {
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    CompiledExpressions f(s, {x, y}, {3 * x - y + 2 * GiNaC::pow(x, y) + 1, GiNaC::cos(x) * GiNaC::sin(x)});
    StraightLineProgram p = f.calc_program();
    ValueSpelling names{{"x", "y"}, {}, {}, "z"};
    auto text = [&](const CodePrinter& pr) {
        std::ostringstream os;
        pr.print(os, p, p.body, names, "");
        return os.str();
    };
    std::string c = text(CPrinter()), py = text(PythonPrinter()), m = text(MatlabPrinter()),
                cpp = text(CppPrinter());
    EXPECT_NE(c.find("const double z1 = pow(x, y);"), std::string::npos) << c;
    // the sum is one linear combination: unit coefficients bare, numbers folded, signs inline
    std::string sum = c.substr(c.find("const double z2 = "));
    sum = sum.substr(0, sum.find('\n'));
    for (const char* term : {"3.0*x", "2.0*z1", "1.0;"})
        EXPECT_NE(sum.find(term), std::string::npos) << sum;
    // -y first or - y later: the order of the terms is GiNaC's
    EXPECT_TRUE(sum.find("= -y + ") != std::string::npos || sum.find(" - y") != std::string::npos)
        << sum;
    EXPECT_NE(cpp.find("std::pow(x, y)"), std::string::npos) << cpp;
    EXPECT_NE(py.find("z1 = x**y\n"), std::string::npos) << py;
    EXPECT_NE(py.find("math.sin(x)"), std::string::npos) << py;
    EXPECT_NE(m.find("z1 = x^y;"), std::string::npos) << m;
    EXPECT_EQ(MatlabPrinter().element("q", 0), "q(1)");
    EXPECT_EQ(CPrinter().element("q", 0), "q[0]");
}
