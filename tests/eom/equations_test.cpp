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

TEST(LinearSystem, SingularSolvesNameTheUnknownsBehindThem) {
    SymbolTable s;
    TimeVariable q = s.add_variable("q");
    ex I = s.add_constant("I", 0.5), T = s.add_unknown("T"), T2 = s.add_unknown("T2"),
       F = s.add_unknown("F");
    // the same torque declared twice: T and T2 enter both equations as T + T2
    std::vector<ex> E{T + T2 - I * q.d(2), 3 * (T + T2) + GiNaC::sin(q.symbol())};
    LinearSystem L = form_linear_system(E, {T, T2});
    EXPECT_THROW_MSG(solve_symbolic(L), SolveError,
                     "'T' and 'T2' enter every equation in the same proportion");
    EXPECT_THROW_MSG(solve_numeric(s, L, {{q.symbol(), 0.3}, {q.d(2), 1.0}}), SolveError,
                     "'T' and 'T2' enter every equation in the same proportion");
    // an unknown in no equation
    std::vector<ex> G{T - I * q.d(2), 2 * T + 1};
    EXPECT_THROW_MSG(solve_symbolic(form_linear_system(G, {T, F})), SolveError,
                     "'F' appears in no equation");
}
