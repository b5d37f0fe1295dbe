// SPDX-License-Identifier: MIT
// to_latex: expressions as TeX for KaTeX, in a deterministic order.
#include <gtest/gtest.h>

#include <cmath>

#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {
namespace {

TEST(Latex, SubscriptsPrimesFunctionsAndFractions) {
    SymbolTable st;
    TimeVariable q = st.add_variable("qA", 2);
    ex T = st.add_unknown("T_A"), m = st.add_constant("m_A"), L = st.add_constant("L");
    EXPECT_EQ(to_latex(T), "T_{A}");
    EXPECT_EQ(to_latex(q.d(2)), "{qA}''");
    EXPECT_EQ(to_latex(GiNaC::sin(q.symbol())), "\\sin\\left(qA\\right)");
    EXPECT_EQ(to_latex(m / L), "\\frac{m_{A}}{L}");
    EXPECT_EQ(to_latex(ex(1) / 2 * m), "\\frac{m_{A}}{2}");
    EXPECT_EQ(to_latex(T - m * L), "-L \\, m_{A} + T_{A}");
    EXPECT_EQ(to_latex(GiNaC::pow(L, 2)), "L^{2}");
    EXPECT_EQ(to_latex(GiNaC::sqrt(L)), "\\sqrt{L}");
    // a name of several words: the first underscore starts the subscript, the others are
    // characters of it (one subscript, not a subscript's subscript)
    EXPECT_EQ(to_latex(st.add_variable("ankle_angle_l", 2).symbol()), "ankle_{angle\\_l}");
    EXPECT_EQ(to_latex(st.add_constant("a_b_c_d")), "a_{b\\_c\\_d}");
    // a name that starts or ends with one has no subscript: every underscore is a character
    EXPECT_EQ(to_latex(st.add_constant("_x")), "\\_x");
}

TEST(Latex, SameExpressionBuiltInAnyOrderPrintsTheSame) {
    SymbolTable st;
    ex a = st.add_constant("a"), b = st.add_constant("b"), c = st.add_constant("c");
    EXPECT_EQ(to_latex(a * b + c - a), to_latex(c - a + b * a));
}

// GiNaC holds -c*(a - b) or c*(b - a) as its term order leaves it: both forms of a product,
// of a power of a sum and of sin or cos of a sum print as the text printer writes them
TEST(Latex, ASumInAProductPrintsInOneSign) {
    SymbolTable st;
    ex a = st.add_constant("a"), b = st.add_constant("b"), c = st.add_constant("c");
    const ex s = a - b, n = b - a;  // n is -s, held as a sum of its own
    const ex flipped[][2] = {{-c * s, c * n},
                             {c * GiNaC::pow(s, 3), -c * GiNaC::pow(n, 3)},
                             {GiNaC::pow(s, 3), -GiNaC::pow(n, 3)},
                             {c * GiNaC::pow(s, -1), -c * GiNaC::pow(n, -1)},
                             {c * GiNaC::sin(s), -c * GiNaC::sin(n)},
                             {GiNaC::sin(s), -GiNaC::sin(n)},
                             {c * GiNaC::cos(s) + a, c * GiNaC::cos(n) + a}};
    for (const auto& pair : flipped) {
        const GiNaC::exmap at{{a, 0.3}, {b, 1.1}, {c, 0.7}};  // equal in meaning
        const ex d = GiNaC::evalf((pair[0] - pair[1]).subs(at));
        ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(d) && std::abs(GiNaC::ex_to<GiNaC::numeric>(d).to_double()) < 1e-12);
        EXPECT_EQ(to_latex(pair[0]), to_latex(pair[1])) << to_string(pair[0]);
        EXPECT_EQ(to_string(pair[0]), to_string(pair[1]));
    }
}

}  // namespace
}  // namespace alembert
