// SPDX-License-Identifier: MIT
// Linear systems from residuals: mass matrix and forcing, symbolic and numeric solves.
#include "alembert/eom/equations.hpp"

#include <random>

#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "models.hpp"
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

// The expected size counts the terms of Cramer's rule written out: for a 2 x 2 system
// [[a + b, c], [d, e]] x = [f + g + h, k] that is det = (a + b) e - c d (3 terms) plus the
// larger numerator, (f + g + h) e - c k (4 terms) against (a + b) k - (f + g + h) d (5 terms).
TEST(SymbolicSolve, ExpectedSizeIsCramersRuleWrittenOut) {
    SymbolTable s;
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y");
    ex a = s.add_constant("a"), b = s.add_constant("b"), c = s.add_constant("c"),
       d = s.add_constant("d"), e = s.add_constant("e"), f = s.add_constant("f"),
       g = s.add_constant("g"), h = s.add_constant("h"), k = s.add_constant("k");
    std::vector<ex> E{f + g + h - (a + b) * x.d(2) - c * y.d(2), k - d * x.d(2) - e * y.d(2)};
    LinearSystem L = form_linear_system(E, {x.d(2), y.d(2)});
    EXPECT_EQ(estimate_solution_terms(L), 3.0 + 5.0);
    // a triangular system: zeros keep the count to the diagonal's products
    std::vector<ex> T{f - a * x.d(2), g - b * x.d(2) - c * y.d(2)};
    EXPECT_EQ(estimate_solution_terms(form_linear_system(T, {x.d(2), y.d(2)})), 1.0 + 2.0);
}

TEST(SymbolicSolve, PastTheLimitIsRefusedBeforeAnyWorkAndARaisedLimitSolves) {
    SampleModel m = make_n_link_pendulum(2, ChainKind::planar);
    std::vector<ex> acc = test::accelerations(m.q);
    std::vector<ex> E;
    for (const RoadmapRow& r : plan_roadmap(m.system, m.q, acc)) E.push_back(r.equation);
    LinearSystem L = form_linear_system(E, acc);
    const double expected = estimate_solution_terms(L);
    ASSERT_GT(expected, 10.0);
    SymbolicSolveOptions tight;
    tight.max_terms = expected - 1;
    std::size_t calls = 0;
    tight.progress = [&](std::size_t, std::size_t) { ++calls; };
    EXPECT_THROW_MSG(solve_symbolic(L, tight), SolveError, "solve numerically at given values");
    EXPECT_THROW_MSG(solve_symbolic(L, tight), SolveError, "codegen");
    EXPECT_THROW_MSG(solve_symbolic(L, tight), SolveError, "more than the limit of");
    EXPECT_EQ(calls, 0u);  // refused before the first step
    // at the limit it solves, reporting each step in order, and agrees with the numeric solve
    SymbolicSolveOptions raised;
    raised.max_terms = expected;
    std::vector<std::size_t> steps;
    raised.progress = [&](std::size_t step, std::size_t total) {
        EXPECT_EQ(total, acc.size() + 1);
        steps.push_back(step);
    };
    std::vector<ex> x = solve_symbolic(L, raised);
    EXPECT_EQ(steps, (std::vector<std::size_t>{0, 1, 2, 3}));
    const SymbolTable& st = m.system.symbols();
    std::mt19937 rng(4);
    for (int k = 0; k < 3; ++k) {
        exmap state = test::random_state(st, rng, acc);
        Eigen::VectorXd v = solve_numeric(st, L, state);
        for (std::size_t i = 0; i < x.size(); ++i)
            EXPECT_NEAR(st.evaluate(x[i], state), v(static_cast<Eigen::Index>(i)),
                        1e-10 * std::max(1.0, std::abs(v(static_cast<Eigen::Index>(i)))));
    }
}

// The four-bar's dynamics rows for its accelerations, the loop's pin force and the crank pin's
// force along Nx> (about 20 s of normal() on the solution) are refused at the default limit,
// with the numeric path suggested, and solved numerically instead.
TEST(SymbolicSolve, FourBarWithAJointForceIsRefusedAtTheDefaultLimit) {
    SampleModel m = make_four_bar();
    System& sys = m.system;
    ex R = sys.symbols().add_unknown("R_AB_x");
    sys.add_joint_reaction("crank pin", m.links[0], *m.links[1], sys.point("B_o"),
                           {{R, sys.newtonian().x()}});
    std::vector<ex> x = test::accelerations(m.q);
    x.insert(x.end(), {m.unknowns[1], m.unknowns[2], R});
    std::vector<ex> E;
    for (const RoadmapRow& r : plan_roadmap(sys, m.q, x)) E.push_back(r.equation);
    LinearSystem L = form_linear_system(E, x);
    EXPECT_GT(estimate_solution_terms(L), kDefaultMaxSolveTerms);
    EXPECT_THROW_MSG(solve_symbolic(L), SolveError, "solve numerically at given values");
    std::mt19937 rng(6);
    exmap state = test::random_state(sys.symbols(), rng, x);
    Eigen::VectorXd v = solve_numeric(sys.symbols(), L, state);
    EXPECT_TRUE(v.allFinite());
}
