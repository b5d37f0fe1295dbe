// SPDX-License-Identifier: MIT
// Simplification for mechanics and equality by meaning.
#include "alembert/sym/simplify.hpp"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "alembert/sym/symbol_table.hpp"
#include "support/expect.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {
struct Symbols {
    SymbolTable s;
    ex a = s.add_variable("a"), b = s.add_variable("b"), c = s.add_variable("c");
    ex k = s.add_constant("k"), m = s.add_constant("m");
};
}  // namespace

TEST(Simplify, PythagoreanIdentityCollapses) {
    Symbols x;
    EXPECT_TRUE((simplify(x.k * pow(sin(x.a), 2) + x.k * pow(cos(x.a), 2)) - x.k).is_zero());
    // m (1 - cos^2 a) -> m sin^2 a is shorter
    ex r = simplify(x.m - x.m * pow(cos(x.a), 2));
    EXPECT_TRUE((r - x.m * pow(sin(x.a), 2)).is_zero());
}

namespace {
// r equals `expected` in meaning and is as short (up to a sign flip of the argument)
::testing::AssertionResult folds_to(const ex& r, const ex& expected) {
    if (!alembert::equal(r, expected)) return ::testing::AssertionFailure() << "not equal";
    if (count_ops(r) > count_ops(expected) + 1)
        return ::testing::AssertionFailure() << to_string(r) << " is longer than "
                                             << to_string(expected);
    return ::testing::AssertionSuccess();
}
}  // namespace

TEST(Simplify, AngleSumsFoldIntoOneTerm) {
    Symbols x;
    const ex &a = x.a, &b = x.b, &c = x.c, &k = x.k;
    EXPECT_TRUE(folds_to(simplify(k * sin(a) * cos(b) + k * cos(a) * sin(b)), k * sin(a + b)));
    EXPECT_TRUE(folds_to(simplify(sin(a) * cos(b) - cos(a) * sin(b)), sin(a - b)));
    EXPECT_TRUE(folds_to(simplify(cos(a) * cos(b) - sin(a) * sin(b)), cos(a + b)));
    EXPECT_TRUE(folds_to(simplify(cos(a) * cos(b) + sin(a) * sin(b)), cos(a - b)));
    // sin(a + b + c) written out in four products folds back to one
    ex expanded = GiNaC::expand(
        (sin(a) * cos(b) + cos(a) * sin(b)) * cos(c) + (cos(a) * cos(b) - sin(a) * sin(b)) * sin(c));
    EXPECT_TRUE(folds_to(simplify(-k * expanded), -k * sin(a + b + c)));
}

TEST(Simplify, FoldsInsideProductsAndKeepsUnrelatedTerms) {
    Symbols x;
    const ex &a = x.a, &b = x.b, &k = x.k, &m = x.m;
    ex e = m * (cos(a) * cos(b) - sin(a) * sin(b)) * (k + a) + k * sin(a);
    ex r = simplify(e);
    EXPECT_TRUE(alembert::equal(r, e));
    EXPECT_LT(count_ops(r), count_ops(e));
    EXPECT_TRUE(r.has(cos(a + b)));
}

TEST(Simplify, NeverLengthens) {
    Symbols x;
    ex e = (x.k + x.m) * (x.a + x.b) * (x.a - x.c);
    EXPECT_LE(count_ops(simplify(e)), count_ops(e));
    EXPECT_LE(count_ops(trig_simplify(e)), count_ops(e));
}

TEST(Simplify, RationalExpressionsAreNormalised) {
    Symbols x;
    ex e = x.k / (x.m + x.a) + x.a * x.k / (x.m + x.a);
    ex r = simplify(e);
    EXPECT_TRUE(alembert::equal(r, e));
    EXPECT_LT(count_ops(r), count_ops(e));
}

TEST(Equal, RecognisesIdentitiesByMeaning) {
    Symbols x;
    const ex &a = x.a, &b = x.b;
    EXPECT_TRUE(alembert::equal(sin(2 * a), 2 * sin(a) * cos(a)));  // numeric fallback
    EXPECT_TRUE(alembert::equal(pow(sin(a + b), 2) + pow(cos(a + b), 2), 1));
    EXPECT_TRUE(alembert::equal((a + b) * (a - b), a * a - b * b));
    EXPECT_FALSE(alembert::equal(sin(2 * a), 2 * sin(a)));
    EXPECT_FALSE(alembert::equal(a, a + 1e-6));
    EXPECT_GT(max_numeric_difference(cos(a), sin(a)), 0.01);
}

TEST(CollectIn, GroupsByTheListedSymbols) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m"), L = s.add_constant("L");
    ex e = m * L * q.d(2) + L * L * m * q.d(2) + m * L * pow(q.d(1), 2) + 3;
    ex c = collect_in(e, {q.d(2), q.d(1)});
    EXPECT_TRUE(alembert::equal(c, e));
    EXPECT_TRUE(alembert::equal(c.coeff(q.d(2), 1), m * L + L * L * m));
    EXPECT_TRUE(alembert::equal(c.coeff(q.d(1), 2), m * L));
}

TEST(CountOps, CountsArithmeticOfATree) {
    Symbols x;
    EXPECT_EQ(count_ops(x.a), 0u);
    EXPECT_EQ(count_ops(x.a + x.b + x.c), 2u);           // two additions
    EXPECT_EQ(count_ops(x.a * x.b), 1u);                 // one product
    EXPECT_EQ(count_ops(sin(x.a) * x.k + x.m), 3u);      // sin, *, +
    EXPECT_EQ(count_ops(pow(x.a, 2)), 1u);
}

TEST(Equal, SymbolsThatCancelInTheDifferenceStillGetValues) {
    // y cancels from a - b; the numeric fallback must still give it a value
    Symbols x;
    EXPECT_TRUE(alembert::equal(x.k + GiNaC::tan(x.a), x.k + sin(x.a) / cos(x.a)));
    EXPECT_LT(max_numeric_difference(x.k + GiNaC::tan(x.a), x.k + sin(x.a) / cos(x.a)), 1e-12);
}

TEST(CountOps, NegationCostsOneOperation) {
    Symbols x;
    EXPECT_EQ(count_ops(-x.a), 1u);
    EXPECT_EQ(count_ops(-x.a * x.b), 2u);
}

TEST(Simplify, AQuotientWithTrigonometryKeepsItsSignWhateverTheTermOrder) {
    // r = w sin(l) (x - w) / (b cos(l) - 2 a sin(l)) once cos(l) cancels. GiNaC's numer() and
    // denom() each normalise anew and may return (p, q) from one and (-p, -q) from the other;
    // taking them from two calls flipped the sign in about 4 of 10 term orders (a Whipple
    // bicycle linearised through a script came out unstable at every speed). Fresh symbols
    // each round give GiNaC new term orders.
    for (int round = 0; round < 40; ++round) {
        const std::string k = std::to_string(round);
        GiNaC::symbol a("a" + k), b("b" + k), l("l" + k), x("x" + k), w("w" + k);
        const ex r = (-pow(w, 2) * cos(l) * sin(l) + w * x * cos(l) * sin(l)) /
                     (-2 * a * cos(l) * sin(l) + b * pow(cos(l), 2));
        const GiNaC::exmap at{{a, 2}, {b, 3}, {l, 0.3}, {x, 0.9}, {w, 1.02}};
        const double expected = 1.02 * std::sin(0.3) * (0.9 - 1.02) / (3 * std::cos(0.3) - 4 * std::sin(0.3));
        const ex s = simplify(r);
        const double got = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(s.subs(at))).to_double();
        ASSERT_NEAR(got, expected, 1e-14) << "round " << round << ": " << s;
    }
}

namespace {
// the operation count of a tree as documented, walked through op(i) with no memory: the
// reference for the DAG walk that reads sums' and products' pairs where GiNaC keeps them
std::size_t tree_ops(const ex& e) {
    using namespace GiNaC;
    if (is_a<symbol>(e)) return 0;
    if (is_a<numeric>(e)) {
        const numeric& n = ex_to<numeric>(e);
        return (n.is_negative() ? 1 : 0) + (n.is_rational() && !n.is_integer() ? 1 : 0);
    }
    std::size_t n = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) n += tree_ops(e.op(i));
    if (is_a<add>(e) || is_a<mul>(e)) {
        const ex& last = e.op(e.nops() - 1);
        const bool negation = is_a<mul>(e) && is_a<numeric>(last) && last.is_equal(-1);
        return n + e.nops() - (negation ? 2 : 1);
    }
    return n + 1;
}
}  // namespace

TEST(CountOps, AgreesWithTheTreeWalkOnRandomExpressions) {
    Symbols x;
    std::mt19937 rng(7);
    std::vector<ex> pool{x.a, x.b, x.k, ex(2), ex(-1), GiNaC::numeric(1, 2), ex(-3), ex(1.5)};
    int compared = 0;
    for (int i = 0; i < 3000; ++i) {
        const ex p = pool[rng() % pool.size()], q = pool[rng() % pool.size()];
        ex r;
        try {
            switch (rng() % 7) {
                case 0: r = p + q; break;
                case 1: r = p * q; break;
                case 2: r = p - q; break;
                case 3: r = pow(p, static_cast<int>(rng() % 5) - 2); break;
                case 4: r = sin(p); break;
                case 5: r = p / q; break;
                default: r = -p * q + 3 * p; break;
            }
        } catch (const std::exception&) {
            continue;  // 1/0
        }
        if (tree_ops(r) > 5000) continue;  // the reference walks the tree
        ASSERT_EQ(count_ops(r), tree_ops(r)) << to_string(r);
        ++compared;
        if (pool.size() < 300) pool.push_back(r);
        else pool[rng() % pool.size()] = r;
    }
    EXPECT_GT(compared, 2000);
}

TEST(Simplifier, RemembersAcrossExpressionsAndKeepsTheirMeaning) {
    // rows sharing their kinematics, as a road-map's rows do: one simplifier for all of them
    Symbols x;
    const ex s2 = pow(sin(x.a), 2) + pow(cos(x.a), 2);
    const ex fold = sin(x.a) * cos(x.b) + cos(x.a) * sin(x.b);
    const std::vector<ex> rows{x.k * s2 * fold + x.m, (x.m + x.k) * fold * s2 - x.c * s2,
                               x.m * s2 / (x.k + s2), fold * fold + x.k * s2};
    Simplifier once;
    for (const ex& e : rows) {
        const ex shared = once(e), alone = simplify(e);
        EXPECT_LT(max_numeric_difference(shared, e), 1e-12) << to_string(shared);
        EXPECT_LE(count_ops(shared), count_ops(e));
        EXPECT_LE(count_ops(shared), count_ops(alone) + 1) << to_string(shared);
        const ex col = once.collected(shared, {x.c, x.m});
        EXPECT_LT(max_numeric_difference(col, e), 1e-12) << to_string(col);
    }
    EXPECT_TRUE(alembert::equal(once(x.k * s2 * fold + x.m), x.k * sin(x.a + x.b) + x.m));
}
