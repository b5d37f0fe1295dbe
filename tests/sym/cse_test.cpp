// SPDX-License-Identifier: MIT
// Naming repeated subexpressions keeps meaning and cuts operation counts.
#include "alembert/sym/cse.hpp"

#include "alembert/sym/simplify.hpp"
#include "support/expect.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

TEST(IntroduceIntermediates, KeepsMeaningAndReducesOperations) {
    SymbolTable s;
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2");
    ex L = s.add_constant("L"), m = s.add_constant("m");
    ex shared = L * cos(q1) * sin(q2) + m * q1.d(1);
    std::vector<ex> exprs{pow(shared, 2) + q2, sin(shared) * m, shared * q2.d(1)};
    const std::vector<ex> original = exprs;
    std::size_t before = count_ops(original[0]) + count_ops(original[1]) + count_ops(original[2]);

    auto created = introduce_intermediates(s, exprs);
    ASSERT_FALSE(created.empty());
    for (std::size_t i = 0; i < exprs.size(); ++i)
        EXPECT_TRUE(alembert::test::same(s.expand_intermediates(exprs[i]), original[i]));
    EXPECT_LT(count_ops_with_intermediates(s, exprs), before);
    // every intermediate uses only earlier ones
    for (std::size_t i = 0; i < created.size(); ++i)
        for (std::size_t j = i; j < created.size(); ++j)
            EXPECT_FALSE(s.definition(created[i]).has(created[j]));
}

TEST(IntroduceIntermediates, LeavesUniqueSubexpressionsAlone) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    std::vector<ex> exprs{sin(q) + 1, cos(q) * 2};
    auto created = introduce_intermediates(s, exprs);
    EXPECT_TRUE(created.empty());
    EXPECT_TRUE(s.intermediates().empty());
}

TEST(IntroduceIntermediates, TimeDerivativeOfResultMatchesOriginal) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q", 2);
    ex L = s.add_constant("L");
    ex shared = L * sin(q) * cos(q);
    std::vector<ex> exprs{shared * q.d(1), shared + pow(shared, 2)};
    const std::vector<ex> original = exprs;
    introduce_intermediates(s, exprs);
    for (std::size_t i = 0; i < exprs.size(); ++i)
        EXPECT_TRUE(alembert::test::same(s.expand_intermediates(s.dt(exprs[i])),
                                         s.dt(original[i])));
}
