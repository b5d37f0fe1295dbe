// SPDX-License-Identifier: MIT
// coef(), replace(), taylor(), factor(), floor(), exclude(), include() and `solve ... as`
// against hand results, compared by meaning: each result evaluated at random points beside the
// hand formula; their errors named at the argument; and arguments of 10,000 terms without deep
// recursion.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"
#include "support/script_dir.hpp"

namespace algebra_functions_test {

using namespace alembert::lang;

using AlgebraRun = alembert::test::ScriptSession;
using alembert::test::digits17;
using alembert::test::has;

void expect_close(double got, double want, const std::string& what) {
    EXPECT_NEAR(got, want, 1e-11 * std::max(1.0, std::abs(want))) << what;
}

const char* kHead =
    "newtonian N\n"
    "constant A, B, L\n"
    "variable q'', x'', p''\n"
    "digits 17\n"
    "e = (A + B*q)^2*x + L*q^3 + sin(p)*q\n";

// e = (A + Bq)^2 x + L q^3 + sin(p) q = A^2 x + (2ABx + sin p) q + B^2 x q^2 + L q^3
TEST(AlgebraFunctions, CoefIsTheCoefficientOfAPowerInAPolynomial) {
    AlgebraRun r;
    r.ok(kHead);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng), l = u(rng), q = u(rng), x = u(rng), p = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b) + ", L = " + digits17(l) + ", q = " + digits17(q) +
                               ", x = " + digits17(x) + ", p = " + digits17(p);
        expect_close(r.at("coef(e, q)", at), 2 * a * b * x + std::sin(p), "coef(e, q)");
        expect_close(r.at("coef(e, q^2)", at), b * b * x, "coef(e, q^2)");
        expect_close(r.at("coef(e, q, 2)", at), b * b * x, "coef(e, q, 2)");
        expect_close(r.at("coef(e, q, 3)", at), l, "coef(e, q, 3)");
        expect_close(r.at("coef(e, q, 0)", at), a * a * x, "coef(e, q, 0)");
        expect_close(r.at("coef(e, q, 4)", at), 0, "coef(e, q, 4)");
        expect_close(r.at("coef(e, x)", at), (a + b * q) * (a + b * q), "coef(e, x)");
        // a list by a list: the coefficient matrix, M[i, j] the coefficient of the j-th symbol
        r.ok("M = coef([e, A*q - 3*x], [q, x])\n");
        expect_close(r.at("M[1, 1]", at), 2 * a * b * x + std::sin(p), "M[1, 1]");
        expect_close(r.at("M[1, 2]", at), (a + b * q) * (a + b * q), "M[1, 2]");
        expect_close(r.at("M[2, 1]", at), a, "M[2, 1]");
        expect_close(r.at("M[2, 2]", at), -3, "M[2, 2]");
    }
}

// A particle of mass m on a massless rod of length L: 0 = -m g L sin q - m L^2 q'', so the
// coefficient of q'' is -m L^2 and the rest, its power 0, is -m g L sin q.
TEST(AlgebraFunctions, CoefOfAnAccelerationInKanesEquationIsTheMassTerm) {
    AlgebraRun r;
    r.ok("newtonian N\nframe A\nparticle P\nconstant m, g, L\nvariable q''\nrotate A from N about z by q\n"
         "translate P from N_o by -L*Ay>\nmass P = m\ngravity -g*Ny>\nkane K for q\ndigits 17\n");
    for (double m : {0.7, 2.5})
        for (double l : {0.3, 1.9}) {
            const std::string at = "m = " + digits17(m) + ", L = " + digits17(l) + ", q = 0.4, g = 9.81";
            expect_close(r.at("coef(K[1], q'')", at), -m * l * l, "coef(K[1], q'')");
            expect_close(r.at("coef(K[1], q'', 0)", at), -m * 9.81 * l * std::sin(0.4), "coef(K[1], q'', 0)");
        }
}

TEST(AlgebraFunctions, CoefRefusesWhatIsNotAPolynomialCoefficient) {
    AlgebraRun r;
    r.ok(kHead);
    std::string e = r.fails("coef(sin(q)*x, q)\n");
    EXPECT_TRUE(has(e, "coef(): the expression is not a polynomial in 'q': it holds q inside a function")) << e;
    EXPECT_TRUE(has(e, "test.alb:1:6:")) << e;  // at the expression, with its caret
    EXPECT_TRUE(has(e, "|      ^")) << e;
    e = r.fails("coef(e, 2)\n");
    EXPECT_TRUE(has(e, "coef(): the second argument must be a declared symbol")) << e;
    EXPECT_TRUE(has(e, "test.alb:1:9:")) << e;
    e = r.fails("coef(e, q^-1)\n");
    EXPECT_TRUE(has(e, "coef(): the power of x^n must be a whole number from 0 to 64")) << e;
    e = r.fails("coef(e, q, 65)\n");
    EXPECT_TRUE(has(e, "coef(): the power n must be a whole number from 0 to 64")) << e;
    e = r.fails("coef([e, sin(q)], q)\n");
    EXPECT_TRUE(has(e, "coef(): element 2 of the list is not a polynomial in 'q'")) << e;
    e = r.fails("coef(q*Nx>, q)\n");
    EXPECT_TRUE(has(e, "coef() takes a scalar or a list of scalars first")) << e;
    e = r.fails("coef(e)\n");
    EXPECT_TRUE(has(e, "coef() takes 2 or 3 arguments, not 1")) << e;
    e = r.fails("coef(e, [q, q])\n");
    EXPECT_TRUE(has(e, "coef(): 'q' is listed twice")) << e;
    e = r.fails("coef(e, q = 1)\n");
    EXPECT_TRUE(has(e, "coef() takes no 'x = v' here")) << e;
}

TEST(AlgebraFunctions, ReplaceSubstitutesEverySymbolAtOnce) {
    AlgebraRun r;
    r.ok(kHead);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng), l = u(rng), q = u(rng), x = u(rng), p = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b) + ", L = " + digits17(l) + ", q = " + digits17(q) +
                               ", x = " + digits17(x) + ", p = " + digits17(p);
        // q = 1, x = L: (A + B)^2 L + L + sin(p)
        expect_close(r.at("replace(e, q = 1, x = L)", at), (a + b) * (a + b) * l + l + std::sin(p), "q = 1, x = L");
        // at once: q and x swapped, so q - 2x becomes x - 2q
        expect_close(r.at("replace(q - 2*x, q = x, x = q)", at), x - 2 * q, "swap");
        // an expression for a symbol: q = x + p
        const double s = x + p;
        expect_close(r.at("replace(e, q = x + p)", at),
                     (a + b * s) * (a + b * s) * x + l * s * s * s + std::sin(p) * s, "q = x + p");
        // a vector's measures
        expect_close(r.at("dot(replace(q*Nx> + x*Ny>, q = A), Nx> + Ny>)", at), a + x, "vector");
        // q' is a symbol of its own: replacing q leaves it
        expect_close(r.at("replace(q*q', q = 2)", at + ", q' = 3"), 6, "q'");
    }
}

TEST(AlgebraFunctions, ReplaceChecksItsSubstitutions) {
    AlgebraRun r;
    r.ok(kHead);
    r.ok("variable z'' m\n");
    std::string e = r.fails("replace(z, z = 2 s)\n");
    EXPECT_TRUE(has(e, "the value of 'z' in replace() must be a length")) << e;
    EXPECT_TRUE(has(e, "test.alb:1:16:")) << e;
    e = r.fails("replace(e, 2 = q)\n");
    EXPECT_TRUE(has(e, "replace(): the left side of 'x = v' must be a declared symbol")) << e;
    e = r.fails("replace(e, q = 1, q = 2)\n");
    EXPECT_TRUE(has(e, "replace(): 'q' is given twice")) << e;
    e = r.fails("replace(e, q)\n");
    EXPECT_TRUE(has(e, "replace() takes 'x = v' after the expression")) << e;
    e = r.fails("replace(e)\n");
    EXPECT_TRUE(has(e, "replace() takes the expression and at least one 'x = v'")) << e;
    e = r.fails("sin(q = 1)\n");
    EXPECT_TRUE(has(e, "'x = v' stands only among the arguments of replace() and taylor()")) << e;
}

TEST(AlgebraFunctions, TaylorIsTheTaylorPolynomialAboutThePoint) {
    AlgebraRun r;
    r.ok(kHead);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    const double pi = std::numbers::pi;
    for (int trial = 0; trial < 3; ++trial) {
        const double q = u(rng), x = u(rng), a = u(rng);
        const std::string at = "q = " + digits17(q) + ", x = " + digits17(x) + ", A = " + digits17(a);
        expect_close(r.at("taylor(sin(q), q = 0, 5)", at), q - q * q * q / 6 + std::pow(q, 5) / 120, "sin");
        // cos about pi: -1 + (q - pi)^2/2; the positional form
        const double d = q - pi;
        expect_close(r.at("taylor(cos(q)*x, q, pi, 3)", at), x * (-1 + d * d / 2), "cos about pi");
        // about a symbolic point A: exp(q) = exp(A) (1 + (q - A) + (q - A)^2/2)
        const double h = q - a;
        expect_close(r.at("taylor(exp(q), q = A, 2)", at), std::exp(a) * (1 + h + h * h / 2), "exp about A");
        // two variables, total order 2: exp(q + x) = 1 + (q + x) + (q + x)^2/2
        const double s = q + x;
        expect_close(r.at("taylor(exp(q + x), q = 0, x = 0, 2)", at), 1 + s + s * s / 2, "two variables");
        // a removable singularity: sin(q)/q = 1 - q^2/6 + ...
        expect_close(r.at("taylor(sin(q)/q, q = 0, 3)", at), 1 - q * q / 6, "sin(q)/q");
        // order 0: the value at the point
        expect_close(r.at("taylor(exp(q + x), q = 0, 0)", at), std::exp(x), "order 0");
        // a polynomial of lower degree is itself
        expect_close(r.at("taylor(e, q = 0, 5)", at + ", B = 0.5, L = 2, p = 0.3"),
                     (a + 0.5 * q) * (a + 0.5 * q) * x + 2 * q * q * q + std::sin(0.3) * q, "polynomial");
    }
}

TEST(AlgebraFunctions, TaylorRefusesSingularPointsAndBadOrders) {
    AlgebraRun r;
    r.ok(kHead);
    std::string e = r.fails("taylor(1/q, q = 0, 3)\n");
    EXPECT_TRUE(has(e, "taylor(): the expression is singular at this point")) << e;
    EXPECT_TRUE(has(e, "test.alb:1:8:")) << e;
    e = r.fails("taylor(sqrt(q), q = 0, 2)\n");
    EXPECT_TRUE(has(e, "taylor(): the expression has no Taylor series about this point")) << e;
    e = r.fails("taylor(sin(q), q = 0, -1)\n");
    EXPECT_TRUE(has(e, "taylor(): the order must be a whole number from 0 to 64")) << e;
    e = r.fails("taylor(sin(q), q = 0, A)\n");
    EXPECT_TRUE(has(e, "taylor(): the order must be a whole number")) << e;
    e = r.fails("taylor(sin(q), q = 0)\n");
    EXPECT_TRUE(has(e, "taylor() takes 3 or more arguments, not 2")) << e;
    e = r.fails("taylor(sin(q), 2, 0, 3)\n");
    EXPECT_TRUE(has(e, "taylor(): the variable must be a declared symbol")) << e;
    e = r.fails("taylor(sin(q), q = 0, q = 1, 3)\n");
    EXPECT_TRUE(has(e, "taylor(): 'q' is given twice")) << e;
}

TEST(AlgebraFunctions, FactorKeepsTheValueAndFloorRoundsNumbersDown) {
    AlgebraRun r;
    r.ok(kHead);
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng), q = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b) + ", q = " + digits17(q);
        expect_close(r.at("factor(A^2*q^2 - B^2)", at), (a * q - b) * (a * q + b), "factor");
    }
    // the factors are GiNaC's: (A*q - B) and (A*q + B) divide the result exactly
    expect_close(r.at("replace(factor(A^2*q^2 - B^2), q = B/A)", "A = 1.5, B = 0.7"), 0, "a root of the factor");
    EXPECT_EQ(r.ok("floor(7/2)\n"), "= 3\n");
    EXPECT_EQ(r.ok("floor(-7/2)\n"), "= -4\n");
    EXPECT_EQ(r.ok("floor(-3)\n"), "= -3\n");
    EXPECT_EQ(r.ok("floor(2*pi)\n"), "= 6\n");
    EXPECT_EQ(r.ok("floor(-sqrt(2))\n"), "= -2\n");
    std::string e = r.fails("floor(q)\n");
    EXPECT_TRUE(has(e, "floor() takes a number, but this holds q\n")) << e;
    e = r.fails("floor(x*sin(q) + A)\n");
    EXPECT_TRUE(has(e, "floor() takes a number, but this holds A, q, x\n")) << e;
    e = r.fails("floor(2 m)\n");
    EXPECT_TRUE(has(e, "the argument of floor() must be")) << e;
}

// e expanded is A^2 x + 2AB x q + B^2 x q^2 + L q^3 + sin(p) q: the terms without q are A^2 x;
// with q, the other four; with p (inside sin), sin(p) q; without x and L, sin(p) q alone.
TEST(AlgebraFunctions, ExcludeAndIncludeChooseTermsOfTheExpandedSum) {
    AlgebraRun r;
    r.ok(kHead);
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng), l = u(rng), q = u(rng), x = u(rng), p = u(rng), qd = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b) + ", L = " + digits17(l) + ", q = " + digits17(q) +
                               ", x = " + digits17(x) + ", p = " + digits17(p) + ", q' = " + digits17(qd);
        const double with_q = 2 * a * b * x * q + b * b * x * q * q + l * q * q * q + std::sin(p) * q;
        expect_close(r.at("exclude(e, q)", at), a * a * x, "exclude(e, q)");
        expect_close(r.at("include(e, q)", at), with_q, "include(e, q)");
        expect_close(r.at("include(e, p)", at), std::sin(p) * q, "include(e, p): p inside a function");
        expect_close(r.at("exclude(e, p)", at), a * a * x + with_q - std::sin(p) * q, "exclude(e, p)");
        expect_close(r.at("exclude(e, x, L)", at), std::sin(p) * q, "exclude(e, x, L)");
        expect_close(r.at("include(e, x, L)", at), a * a * x + with_q - std::sin(p) * q, "include(e, x, L)");
        // a denominator and a root hold their symbols; q' is a symbol of its own
        expect_close(r.at("exclude(A/(1 + q^2) + B + sqrt(L^2 + q^2), q)", at), b, "a denominator and a root");
        expect_close(r.at("include(q*q' + q' + A, q)", at), q * qd, "q and q'");
        expect_close(r.at("exclude(q*q' + q' + A, q)", at), qd + a, "q' without q");
        // each measure of a vector, each element of a matrix
        expect_close(r.at("dot(exclude((A + q)*Nx> + q*B*Ny>, q), Nx> + Ny>)", at), a, "a vector's measures");
        r.ok("M = include([e, A; B*p, q*L], p, q)\n");
        expect_close(r.at("M[1, 1]", at), with_q, "M[1, 1]");
        expect_close(r.at("M[1, 2]", at), 0, "M[1, 2]");
        expect_close(r.at("M[2, 1]", at), b * p, "M[2, 1]");
        expect_close(r.at("M[2, 2]", at), q * l, "M[2, 2]");
    }
    // none is left (0), or the whole of a term that is not a sum
    EXPECT_EQ(r.ok("exclude(e, A, L, q)\ninclude(A*B, q)\nexclude(A*B, q)\n"), "= 0\n= 0\n= A*B\n");
    EXPECT_EQ(r.ok("diff(exclude(e, q), q)\n"), "= 0\n");
}

TEST(AlgebraFunctions, ExcludeAndIncludeRefuseWhatIsNoSymbol) {
    AlgebraRun r;
    r.ok(kHead);
    std::string e = r.fails("exclude(e)\n");
    EXPECT_TRUE(has(e, "test.alb:1:1: error: exclude() takes the expression and at least one symbol")) << e;
    e = r.fails("include(e, 2)\n");
    EXPECT_TRUE(has(e, "test.alb:1:12: error: include(): each symbol after the expression must be a declared symbol")) << e;
    e = r.fails("exclude(e, q, x, q)\n");
    EXPECT_TRUE(has(e, "test.alb:1:18: error: exclude(): 'q' is listed twice")) << e;
    e = r.fails("include(e, q = 1)\n");
    EXPECT_TRUE(has(e, "include() takes no 'x = v' here")) << e;
    // the expansion is bounded like expand()'s: (6 symbols)^60 has C(65, 5) = 8259888 terms
    e = r.fails("exclude((A + B + L + q + x + p)^60, q)\n");
    EXPECT_TRUE(has(e, "exclude(): expanding the expression into its terms would form up to 8.26e+06 terms, more than "
                       "the limit of 100000")) << e;
}

// E: A q + x = 1, q - B x = 0, so q = B/(1 + AB), x = 1/(1 + AB); kept as values, they
// satisfy E.
TEST(AlgebraFunctions, SolveAsKeepsTheSolutionsAsValues) {
    AlgebraRun r;
    r.ok(kHead);
    r.ok("E = [A*q + x - 1, q - B*x]\nsolve E for q, x as qs, xs\nsolve E for q, x as S\n");
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(0.1, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b);
        expect_close(r.at("qs", at), b / (1 + a * b), "qs");
        expect_close(r.at("xs", at), 1 / (1 + a * b), "xs");
        expect_close(r.at("S[1]", at), b / (1 + a * b), "S[1]");
        expect_close(r.at("S[2]", at), 1 / (1 + a * b), "S[2]");
        expect_close(r.at("replace(E[1], q = qs, x = xs)", at), 0, "E[1] at the solution");
        expect_close(r.at("replace(E[2], q = S[1], x = S[2])", at), 0, "E[2] at the solution");
    }
    // numbers: after `at`, in SI, in the unknown's dimension
    r.ok("solve E for q, x at A = 2, B = 3 as qn, xn\n");
    expect_close(r.at("qn", ""), 3.0 / 7, "qn");
    expect_close(r.at("xn", ""), 1.0 / 7, "xn");
    // a matrix of one column holds equations too
    r.ok("C = [q - 2*x; q + x - 3]\nsolve C for q, x as qc, xc\n");
    expect_close(r.at("qc", ""), 2, "qc");
    expect_close(r.at("xc", ""), 1, "xc");
}

TEST(AlgebraFunctions, SolveAsRefusesSingularSystemsAndTakenNames) {
    AlgebraRun r;
    r.ok(kHead);
    r.ok("E = [A*q + x - 1, q - B*x]\nF = [q + x - 1, 2*q + 2*x - 5]\n");
    std::string e = r.fails("solve F for q, x as qf, xf\n");
    EXPECT_TRUE(has(e, "singular")) << e;
    e = r.fails("qf\n");
    EXPECT_TRUE(has(e, "'qf' is not declared")) << e;  // nothing kept from a refused solve
    e = r.fails("solve E for q, x as q1, q2, q3\n");
    EXPECT_TRUE(has(e, "3 names for 2 unknowns")) << e;
    e = r.fails("solve E for q, x as A, q2\n");
    EXPECT_TRUE(has(e, "'A' is already declared")) << e;
    e = r.fails("solve E for q, x as sin, q2\n");
    EXPECT_TRUE(has(e, "'sin' is a word of the language")) << e;
    e = r.fails("solve E for q, x as q2, q2\n");
    EXPECT_TRUE(has(e, "listed twice")) << e;
}

// 10,000 distinct terms sin(k p) q, k = 1 ... 10000, in one argument (over 20 lines inside
// the brackets): each function runs without deep recursion and keeps every term.
TEST(AlgebraFunctions, ArgumentsOfTenThousandTermsRunWithoutDeepRecursion) {
    std::string sum = "(0";
    for (int line = 0; line < 20; ++line) {
        sum += "\n";
        for (int i = 1; i <= 500; ++i) sum += " + sin(" + std::to_string(line * 500 + i) + "*p)*q";
    }
    sum += ")";
    AlgebraRun r;
    r.ok(std::string(kHead) + "c = coef(" + sum + ", q)\nd = replace(" + sum + ", q = 2)\nts = taylor(" + sum +
         ", q = 0, 2)\n");
    const double p = 0.37;
    double s = 0;
    for (int k = 1; k <= 10000; ++k) s += std::sin(k * p);
    EXPECT_NEAR(r.at("c", "p = 0.37"), s, 1e-9);
    EXPECT_NEAR(r.at("d", "p = 0.37"), 2 * s, 2e-9);
    EXPECT_NEAR(r.at("ts", "p = 0.37, q = 1.5"), 1.5 * s, 2e-9);
}

}  // namespace algebra_functions_test
