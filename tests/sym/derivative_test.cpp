// SPDX-License-Identifier: MIT
// Partial derivatives through a memo: the chain rule by hand, central differences, and GiNaC's diff.
#include "alembert/sym/derivative.hpp"

#include <cmath>
#include <random>

#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {

// e at q = at (a map of the symbols' values), as a double
double value_at(const ex& e, const GiNaC::exmap& at) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

// d e/d s by a central difference at `at`
double central_difference(const ex& e, const GiNaC::symbol& s, GiNaC::exmap at) {
    const double h = 1e-5, x = GiNaC::ex_to<GiNaC::numeric>(at[s]).to_double();
    at[s] = x + h;
    const double up = value_at(e, at);
    at[s] = x - h;
    return (up - value_at(e, at)) / (2 * h);
}

// A random expression in q1, q2, L of sums, products, powers, sines and cosines of the
// coordinates, reusing earlier sub-expressions (a DAG, as the equations of motion are)
ex random_expression(std::mt19937& rng, const std::vector<ex>& leaves, int steps) {
    std::vector<ex> pool = leaves;
    std::uniform_int_distribution<int> kind(0, 5), coeff(-3, 3);
    for (int k = 0; k < steps; ++k) {
        std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
        const ex a = pool[pick(rng)], b = pool[pick(rng)];
        int c = coeff(rng);
        if (c == 0) c = 2;
        switch (kind(rng)) {
            case 0: pool.push_back(a + c * b); break;
            case 1: pool.push_back(c * a * b); break;
            case 2: pool.push_back(pow(a, 2) - b); break;
            case 3: pool.push_back(sin(a) * b); break;
            case 4: pool.push_back(cos(a + c) + b / 2); break;
            default:
                if (!a.is_zero()) pool.push_back(pow(a, -1) * b + c);
                break;
        }
    }
    return pool.back() + pool[pool.size() / 2];
}

}  // namespace

TEST(DerivativeMemo, ChainRuleOfSinesAndCosinesByHand) {
    GiNaC::symbol q("q"), L("L");
    // f = L sin(q)^2 cos(2q):  f' = L (2 sin q cos q cos 2q - 2 sin(q)^2 sin 2q)
    const ex f = L * pow(sin(q), 2) * cos(2 * q);
    const ex by_hand = L * (2 * sin(q) * cos(q) * cos(2 * q) - 2 * pow(sin(q), 2) * sin(2 * q));
    EXPECT_TRUE(same(calc_derivative(f, q), by_hand));
    // by L: sin(q)^2 cos(2q); by a symbol it does not hold: 0
    EXPECT_TRUE(same(calc_derivative(f, L), pow(sin(q), 2) * cos(2 * q)));
    GiNaC::symbol r("r");
    EXPECT_TRUE(calc_derivative(f, r).is_zero());
    // a realsymbol (as the symbol table's) is told apart by identity, not copied as a symbol
    GiNaC::realsymbol x("x");
    EXPECT_TRUE(same(calc_derivative(L * x * sin(x), x), L * sin(x) + L * x * cos(x)));
    // sqrt(L^2 + q^2)' = q / sqrt(L^2 + q^2)
    EXPECT_TRUE(same(calc_derivative(sqrt(pow(L, 2) + pow(q, 2)), q), q / sqrt(pow(L, 2) + pow(q, 2))));
}

TEST(DerivativeMemo, AgreesWithCentralDifferencesAndGinacOnRandomExpressions) {
    GiNaC::symbol q1("q1"), q2("q2"), L("L");
    const std::vector<ex> leaves{q1, q2, L, sin(q1), cos(q2), sin(q1 - q2)};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> value(0.3, 1.2);
    for (int trial = 0; trial < 40; ++trial) {
        const ex e = random_expression(rng, leaves, 12);
        for (const GiNaC::symbol& s : {q1, q2, L}) {
            const ex d = calc_derivative(e, s);
            // the same expression GiNaC's diff forms, not only an equal one
            EXPECT_TRUE(d.is_equal(e.diff(s))) << to_string(e) << " by " << s;
            const GiNaC::exmap at{{q1, value(rng)}, {q2, value(rng)}, {L, value(rng)}};
            const double fd = central_difference(e, s, at), exact = value_at(d, at);
            if (!std::isfinite(fd) || std::abs(fd) > 1e6) continue;  // near a pole of 1/a
            EXPECT_NEAR(exact, fd, 1e-5 * (1 + std::abs(fd))) << to_string(e) << " by " << s;
        }
    }
}

TEST(DerivativeMemo, DifferentiatesASharedSubexpressionOnce) {
    GiNaC::symbol q("q"), L("L");
    const ex shared = L * sin(q) * cos(q) + pow(sin(q), 2);
    DerivativeMemo d(q);
    const ex a = d(shared * L);
    const std::size_t after_first = d.size();
    const ex b = d(shared + cos(q));
    // the second expression adds only its own sum, product and cos(q) nodes, not shared's
    EXPECT_LE(d.size(), after_first + 2);
    EXPECT_TRUE(same(a, L * (L * (pow(cos(q), 2) - pow(sin(q), 2)) + 2 * sin(q) * cos(q))));
    EXPECT_TRUE(same(b, L * (pow(cos(q), 2) - pow(sin(q), 2)) + 2 * sin(q) * cos(q) - sin(q)));
    // a memo of one symbol differentiates a long chain of shared products once per link:
    // x_{k+1} = x_k^2 + sin(x_k) doubles the tree's size at each link
    ex x = q;
    for (int k = 0; k < 6; ++k) x = pow(x, 2) + sin(x);
    DerivativeMemo chain(q);
    const ex dx = chain(x);
    EXPECT_TRUE(dx.is_equal(x.diff(q)));
    EXPECT_LE(chain.size(), 6u * 4u);
}

TEST(DerivativeMemo, OtherFunctionsAreDifferentiatedByGinac) {
    GiNaC::symbol q("q"), L("L");
    const ex e = exp(L * q) + atan2(q, L) + pow(q, L);
    EXPECT_TRUE(calc_derivative(e, q).is_equal(e.diff(q)));
    EXPECT_TRUE(same(calc_derivative(e, q),
                     L * exp(L * q) + L / (pow(L, 2) + pow(q, 2)) + L * pow(q, L - 1)));
}
