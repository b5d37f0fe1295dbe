// SPDX-License-Identifier: MIT
// Equations as a person reads them: angle shifts by multiples of Pi/2, common factors,
// intermediates written out where short and defined before use where long.
#include <gtest/gtest.h>

#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/sym/symbol_table.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::Pi;
using GiNaC::pow;
using GiNaC::sin;
using GiNaC::tan;

namespace {
struct Model {
    SymbolTable s;
    TimeVariable qA = s.add_variable("qA"), qB = s.add_variable("qB");
    ex L = s.add_constant("L"), m = s.add_constant("m"), g = s.add_constant("g");
};

bool has_pi(const ex& e) { return e.has(Pi); }
}  // namespace

TEST(AngleShifts, SinAndCosOfAnAngleShiftedByQuarterTurnsLoseTheShift) {
    Model x;
    const ex q = x.qB;
    // every quarter turn from -3 to 4, both functions: equal in meaning, no Pi left
    for (int k = -3; k <= 4; ++k) {
        for (const ex& f : std::vector<ex>{sin(q + k * Pi / 2), cos(q + k * Pi / 2), sin(x.L * q - k * Pi / 2)}) {
            ex r = fold_angle_shifts(f);
            EXPECT_FALSE(has_pi(r)) << to_string(f) << " -> " << to_string(r);
            EXPECT_LE(max_numeric_difference(r, f), 1e-14) << to_string(f) << " -> " << to_string(r);
        }
    }
    // the textbook cases, exactly
    EXPECT_TRUE((fold_angle_shifts(sin(q + Pi)) + sin(q)).is_zero());
    EXPECT_TRUE((fold_angle_shifts(cos(q + Pi)) + cos(q)).is_zero());
    EXPECT_TRUE((fold_angle_shifts(sin(q + Pi / 2)) - cos(q)).is_zero());
    EXPECT_TRUE((fold_angle_shifts(cos(q - Pi / 2)) - sin(q)).is_zero());
    EXPECT_TRUE((fold_angle_shifts(tan(q + Pi)) - tan(q)).is_zero());
    EXPECT_EQ(to_string(simplify(x.m * sin(q + Pi))), "-m*sin(qB)");
}

TEST(AngleShifts, AShiftWrittenInDegreesCountsAndOtherNumbersDoNot) {
    Model x;
    const ex q = x.qA;
    // 180 deg arrives as a decimal number
    ex r = fold_angle_shifts(cos(q + GiNaC::numeric(180 * std::numbers::pi / 180)));
    EXPECT_TRUE((r + cos(q)).is_zero()) << to_string(r);
    ex one = cos(q + 1.0);
    EXPECT_TRUE(fold_angle_shifts(one).is_equal(one));
    ex third = sin(q + Pi / 3);
    EXPECT_TRUE(fold_angle_shifts(third).is_equal(third));
    // tan shifted by a quarter turn is not shorter and stays
    ex t = tan(q + Pi / 2);
    EXPECT_LE(max_numeric_difference(fold_angle_shifts(t), t), 1e-12);
}

TEST(FactorCommon, FactorsCommonToEveryTermComeOut) {
    Model x;
    const ex a = x.qA, b = x.qB;
    ex e = x.L * x.m * a + x.L * x.m * pow(b, 2);
    ex f = factor_common(e);
    EXPECT_TRUE(GiNaC::is_a<GiNaC::mul>(f)) << to_string(f);
    EXPECT_TRUE((expand(f) - e).is_zero());
    EXPECT_EQ(to_string(f), "L*m*(qA + qB^2)");
    // every term negative: the sign comes out too; powers to the lowest
    ex n = -x.g * pow(x.L, 2) * sin(a) - x.g * x.L * cos(b);
    ex fn = factor_common(n);
    EXPECT_TRUE((expand(fn) - n).is_zero());
    EXPECT_EQ(to_string(fn), "-g*L*(L*sin(qA) + cos(qB))");
    // nothing common: unchanged
    ex none = x.L * a + x.m * b;
    EXPECT_TRUE(factor_common(none).is_equal(none));
    // inside a product (a coefficient of an acceleration)
    ex acc = x.qA.d(2) * (x.m * x.L * cos(b) + x.m * x.L) + x.g;
    ex fa = factor_common(acc);
    EXPECT_TRUE((expand(fa) - expand(acc)).is_zero());
    EXPECT_LT(count_ops(fa), count_ops(acc)) << to_string(fa);
}

namespace {
// a model whose equation holds one long and one short intermediate
struct WithIntermediates : Model {
    ex z_long = s.name_subexpression(x_long());
    ex z_short = s.name_subexpression(L * sin(qA) + L * cos(qB));
    ex equation = m * z_long * qA.d(2) + m * z_short * qB.d(2) + g * z_short * sin(qA + Pi);

    ex x_long() {
        ex e = 0;
        for (int k = 1; k <= 8; ++k) e += k * L * sin(k * ex(qA)) * cos(ex(qB) + k * ex(qA));
        return e;
    }
};
}  // namespace

TEST(Readable, ShortIntermediatesAreWrittenOutAndLongOnesDefinedFirst) {
    WithIntermediates x;
    ex r = calc_readable(x.s, x.equation);
    // equal in meaning, once every intermediate is written out
    EXPECT_LE(max_numeric_difference(x.s.expand_intermediates(r), x.s.expand_intermediates(x.equation)),
              1e-12);
    GiNaC::exset syms = symbols_of(r);
    EXPECT_FALSE(syms.count(x.z_short)) << to_string(r);
    EXPECT_TRUE(syms.count(x.z_long)) << to_string(r);
    EXPECT_FALSE(has_pi(r)) << to_string(r);
    // the long one is defined, by its definition
    auto used = calc_used_intermediates(x.s, {r});
    ASSERT_EQ(used.size(), 1u);
    EXPECT_TRUE(used[0].first.is_equal(x.z_long));
    EXPECT_LE(max_numeric_difference(used[0].second, x.x_long()), 1e-12);
    std::string defs = format_intermediates(x.s, {r});
    EXPECT_EQ(defs.rfind(to_string(x.z_long) + " = ", 0), 0u) << defs;
    // collected in the accelerations: each appears once
    std::string text = to_string(r);
    for (const char* a : {"qA''", "qB''"}) {
        std::size_t first = text.find(a);
        ASSERT_NE(first, std::string::npos) << text;
        EXPECT_EQ(text.find(a, first + 1), std::string::npos) << text;
    }
}

TEST(Readable, DefinitionsComeInDependencyOrderAndNameOnlyEarlierOnes) {
    Model x;
    // a chain of long intermediates, each built on the one before
    ex prev = 0;
    std::vector<ex> chain;
    for (int k = 1; k <= 4; ++k) {
        ex d = prev;
        for (int j = 1; j <= 10; ++j) d += j * k * x.L * sin(j * ex(x.qA) + k * ex(x.qB));
        prev = x.s.name_subexpression(d);
        chain.push_back(prev);
    }
    ex e = x.m * prev * x.qA.d(2) + x.g;
    ex r = calc_readable(x.s, e);
    std::string text = format_intermediates(x.s, {r}) + "E: 0 = " + to_string(r) + "\n";
    // every intermediate named is defined on an earlier line
    std::set<std::string> defined;
    std::istringstream in(text);
    std::string line;
    const std::regex name(R"(\bz[0-9]+'*)");
    while (std::getline(in, line)) {
        std::string lhs = line.substr(0, line.find(" = "));
        std::string rhs = line.substr(line.find(" = ") + 3);
        for (auto it = std::sregex_iterator(rhs.begin(), rhs.end(), name); it != std::sregex_iterator(); ++it)
            EXPECT_TRUE(defined.count(it->str())) << it->str() << " used before its definition in:\n" << text;
        if (lhs.rfind('z', 0) == 0) defined.insert(lhs);
    }
    EXPECT_EQ(defined.size(), chain.size()) << text;
    // the printed definitions mean what the table's do
    for (const auto& [z, d] : calc_used_intermediates(x.s, {r}))
        EXPECT_LE(max_numeric_difference(x.s.expand_intermediates(d), x.s.expand_intermediates(z)), 1e-12);
}

TEST(Readable, FactoredFormIsEqualAndShorter) {
    Model x;
    const ex a = x.qA, b = x.qB;
    // a double pendulum's first equation as Kane's method forms it (unsimplified)
    ex e = -x.L * (x.L * x.m * x.qB.d(2) * cos(a - b) + x.L * x.m * pow(x.qB.d(1), 2) * sin(a - b)) -
           x.g * x.L * x.m * sin(a) - x.g * x.L * x.m * sin(a) - pow(x.L, 2) * x.m * x.qA.d(2) -
           pow(x.L, 2) * x.m * x.qA.d(2) * (pow(sin(b), 2) + pow(cos(b), 2));
    ex r = calc_readable(x.s, e, true);
    EXPECT_TRUE(alembert::equal(r, e)) << to_string(r);
    EXPECT_LT(count_ops(r), count_ops(e)) << to_string(r);
    EXPECT_TRUE(GiNaC::is_a<GiNaC::mul>(r)) << to_string(r);  // -L*m*(...)
}
