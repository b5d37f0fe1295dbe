// SPDX-License-Identifier: MIT
// Linear systems from residuals: mass matrix and forcing, symbolic and numeric solves.
#include "alembert/eom/equations.hpp"

#include "alembert/error.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;

TEST(LinearSystem, SplitsResidualIntoMassMatrixAndForcing) {
    SymbolTable s;
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y");
    ex m = s.add_constant("m"), k = s.add_constant("k");
    // E1 = -k x - m x'' - y'' ; E2 = -2 m y'' + k
    std::vector<ex> E{-k * x - m * x.d(2) - y.d(2), -2 * m * y.d(2) + k};
    LinearSystem L = form_linear_system(E, {x.d(2), y.d(2)});
    EXPECT_TRUE(same(L.A(0, 0), m));
    EXPECT_TRUE(same(L.A(0, 1), 1));
    EXPECT_TRUE(same(L.A(1, 0), 0));
    EXPECT_TRUE(same(L.A(1, 1), 2 * m));
    EXPECT_TRUE(same(L.b(0, 0), -k * x));
    EXPECT_TRUE(same(L.b(1, 0), k));
    std::vector<ex> sol = solve_symbolic(L);
    EXPECT_TRUE(same(sol[1], k / (2 * m)));
    EXPECT_TRUE(same(sol[0], (-k * x - k / (2 * m)) / m));
}

TEST(LinearSystem, NonlinearUnknownIsASolveErrorNamingIt) {
    SymbolTable s;
    TimeVariable x = s.add_variable("x");
    EXPECT_THROW_MSG(form_linear_system({x.d(2) * x.d(2) + 1}, {x.d(2)}), SolveError,
                     "not linear in 'x'''");
    EXPECT_THROW_MSG(form_linear_system({x.d(2)}, {x.d(2), x.d(1)}), ArgumentError,
                     "1 equations for 2 unknowns");
}

TEST(LinearSystem, NumericSolveReportsSingularMatrices) {
    SymbolTable s;
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y");
    ex c = s.add_constant("c", 2.0);
    std::vector<ex> E{x.d(2) + y.d(2) - 1, c * x.d(2) + c * y.d(2) - 2};
    LinearSystem L = form_linear_system(E, {x.d(2), y.d(2)});
    EXPECT_THROW_MSG(solve_numeric(s, L, {}), SolveError, "singular");
    std::vector<ex> F{x.d(2) + y.d(2) - 1, x.d(2) - c * y.d(2) - 4};
    Eigen::VectorXd v = solve_numeric(s, form_linear_system(F, {x.d(2), y.d(2)}), {});
    EXPECT_NEAR(v(0), 2.0, 1e-14);
    EXPECT_NEAR(v(1), -1.0, 1e-14);
}
