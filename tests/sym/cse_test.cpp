// SPDX-License-Identifier: MIT
// Naming repeated subexpressions keeps meaning and cuts operation counts.
#include "alembert/sym/cse.hpp"

#include <map>

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

namespace {
// a chain of k links' worth of shared kinematics: each level's sines and cosines of the angle
// sums so far, every level holding the whole level below (a deep DAG whose tree is huge),
// some of it named as intermediates, and one equation per level over all of it
struct SharedChain {
    SymbolTable table;
    std::vector<ex> equations;
    explicit SharedChain(int k) {
        ex L = table.add_constant("L"), angle = 0, x = 0, y = 0;
        for (int i = 1; i <= k; ++i) {
            TimeVariable q = table.add_variable("q" + std::to_string(i));
            angle += q.symbol();
            x = x + L * cos(angle) + y * sin(q.symbol());
            y = y - L * sin(angle) + x * cos(q.symbol());
            if (i % 3 == 0) {
                x = table.add_intermediate(x);
                y = table.add_intermediate(y);
            }
            equations.push_back(x * q.d(2) + y * q.d(1));
        }
    }
};

// the intermediates each expression reaches on its own, merged: the walk of one expression
// at a time that the shared walk replaces
std::vector<ex> reached_one_by_one(const SymbolTable& table, const std::vector<ex>& exprs) {
    std::map<std::size_t, ex> by_position;
    std::map<ex, std::size_t, GiNaC::ex_is_less> position;
    for (std::size_t i = 0; i < table.intermediates().size(); ++i)
        position.emplace(table.intermediates()[i], i);
    std::vector<ex> work(exprs.begin(), exprs.end());
    while (!work.empty()) {
        const ex e = work.back();
        work.pop_back();
        for (const ex& s : symbols_of(e)) {
            auto it = position.find(s);
            if (it != position.end() && by_position.emplace(it->second, s).second)
                work.push_back(table.definition(s));
        }
    }
    std::vector<ex> out;
    for (const auto& [i, z] : by_position) out.push_back(z);
    return out;
}
}  // namespace

TEST(CountOpsWithIntermediates, OneWalkOverSharedEquationsCountsWhatEachWalkedAloneCounts) {
    // 40 equations sharing one deep DAG, larger than any example's: the shared walk must
    // find the same intermediates in the same (dependency) order and the same count as
    // measuring each equation and each definition on its own
    SharedChain c(40);
    const std::vector<ex> reached = calc_reached_intermediates(c.table, c.equations);
    const std::vector<ex> expected = reached_one_by_one(c.table, c.equations);
    ASSERT_EQ(reached.size(), expected.size());
    for (std::size_t i = 0; i < reached.size(); ++i) EXPECT_TRUE(reached[i].is_equal(expected[i]));
    ASSERT_FALSE(reached.empty());
    // dependency order: each definition uses only intermediates listed before it
    for (std::size_t i = 0; i < reached.size(); ++i)
        for (std::size_t j = i; j < reached.size(); ++j)
            EXPECT_FALSE(c.table.definition(reached[i]).has(reached[j]));
    std::size_t one_by_one = 0;
    for (const ex& e : c.equations) one_by_one += count_ops(e);
    for (const ex& z : expected) one_by_one += count_ops(c.table.definition(z));
    EXPECT_EQ(count_ops_with_intermediates(c.table, c.equations), one_by_one);
    std::vector<ex> all = c.equations;
    for (const ex& z : expected) all.push_back(c.table.definition(z));
    EXPECT_EQ(count_ops(all), one_by_one);
    // only what is reached: the first equations reach none of the later intermediates
    const std::vector<ex> first(c.equations.begin(), c.equations.begin() + 4);
    EXPECT_EQ(calc_reached_intermediates(c.table, first).size(), 2u);
}
