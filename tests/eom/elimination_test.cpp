// SPDX-License-Identifier: MIT
// detail::solve_by_elimination: Gauss elimination with named intermediates and no
// normalisation, checked by substituting the solution back at random points.
#include <cmath>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

// a symbolic 5 x 5 system large enough to be solved with named intermediates: trigonometric
// entries in two coordinates, and a first column that vanishes at the reference
// configuration (q = 0) in every row but the last, so the pivot search must look past it
struct System5 {
    SymbolTable st;
    TimeVariable q1 = st.add_variable("q1", 1), q2 = st.add_variable("q2", 1);
    ex a = st.add_constant("a", 0.7), b = st.add_constant("b");
    GiNaC::matrix A{5, 5}, B{5, 2};
    std::vector<ex> unknowns;
    System5() {
        const ex x1 = q1.symbol(), x2 = q2.symbol();
        ex s1 = sin(x1), c1 = cos(x1), s2 = sin(x2), c2 = cos(x2);
        for (unsigned i = 0; i < 5; ++i) {
            for (unsigned j = 0; j < 5; ++j)
                A(i, j) = (i + 1) * a * c1 * s2 + (j + 2) * b * s1 * c2 + (i == j ? 3 + a * c2 : 0) +
                          (i + j) * s1 * s2;
            A(i, 0) = i == 4 ? a + c2 : (i + 1) * s1 * (a + c2 * b);
            B(i, 0) = (i + 1) * c1 - a * s2;
            B(i, 1) = b * s1 * c2 + i;
        }
        for (int i = 0; i < 5; ++i) unknowns.push_back(st.add_unknown("x" + std::to_string(i)));
    }
};

}  // namespace

TEST(SolveByElimination, SolutionSatisfiesTheSystemAtRandomPoints) {
    System5 s;
    ASSERT_TRUE(detail::is_large(s.A, s.B));
    GiNaC::matrix X = detail::solve_by_elimination(s.st, s.A, s.B, s.unknowns, "test");
    // large systems come out with named intermediates
    bool named = false;
    for (const ex& z : symbols_of(X(0, 0)))
        named = named || s.st.kind(z) == SymbolKind::intermediate;
    EXPECT_TRUE(named);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(-1.5, 1.5);
    for (int trial = 0; trial < 5; ++trial) {
        exmap at{{s.q1.symbol(), d(rng)}, {s.q2.symbol(), d(rng)}, {s.b, d(rng)}};
        for (unsigned i = 0; i < 5; ++i)
            for (unsigned k = 0; k < 2; ++k) {
                double lhs = 0;
                for (unsigned j = 0; j < 5; ++j)
                    lhs += s.st.evaluate(s.A(i, j), at) * s.st.evaluate(X(j, k), at);
                const double rhs = s.st.evaluate(s.B(i, k), at);
                EXPECT_NEAR(lhs, rhs, 1e-11 * std::max(1.0, std::abs(rhs)))
                    << "row " << i << ", column " << k << ", trial " << trial;
            }
    }
}

TEST(SolveByElimination, ASingularSystemIsAnErrorNamingTheUnknowns) {
    System5 s;
    for (unsigned j = 0; j < 5; ++j) s.A(3, j) = 2 * s.A(1, j) - s.A(2, j);  // dependent rows
    EXPECT_THROW_MSG(detail::solve_by_elimination(s.st, s.A, s.B, s.unknowns, "the test system"),
                     SolveError, "the test system: the equations for");
}
