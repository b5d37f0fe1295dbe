// SPDX-License-Identifier: MIT
// The composite-rigid-body mass matrix and the bias forces of the recursive formation against
// the rows they come from: E = F - (M u' + h) at random states of the arm and the humanoid.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"

using namespace alembert;

namespace {

// Checks tree.mass_matrix and tree.bias_forces against the residuals, which are linear in the
// speeds' rates u' and the loads: at zero loads, h = -E(u' = 0) and M e_j = E(0) - E(e_j).
void expect_mass_matrix_and_bias_match_rows(SampleModel& m, const TreeEquations& tree,
                                            unsigned seed) {
    SymbolTable& st = m.system.symbols();
    const std::vector<ex>& u = tree.speeds;
    const std::size_t n = u.size(), nq = m.q.size();
    ASSERT_EQ(tree.mass_matrix.size(), n * n);
    ASSERT_EQ(tree.bias_forces.size(), n);
    std::vector<ex> inputs;
    for (const TimeVariable& q : m.q) inputs.push_back(q.d(0));
    inputs.insert(inputs.end(), u.begin(), u.end());
    std::vector<ex> mass_inputs = inputs;
    mass_inputs.resize(nq);  // M depends on q alone
    for (const ex& x : u) inputs.push_back(st.dt(x));
    inputs.insert(inputs.end(), m.unknowns.begin(), m.unknowns.end());
    CompiledExpressions rows(st, inputs, tree.residuals);
    CompiledExpressions mass(st, mass_inputs, tree.mass_matrix);
    std::vector<ex> bias_inputs = inputs;
    bias_inputs.resize(nq + n);
    CompiledExpressions bias(st, bias_inputs, tree.bias_forces);

    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<double> x(inputs.size(), 0.0);
        for (std::size_t i = 0; i < nq + n; ++i) x[i] = d(rng);
        // Euler parameters (e0_<B>..e3_<B>) of unit length: the composite inertias are carried
        // through rotations, which R_PB is only on the unit sphere
        for (std::size_t i = 0; i < nq; ++i) {
            if (m.q[i].name().rfind("e0_", 0) != 0) continue;
            const double norm = std::sqrt(x[i] * x[i] + x[i + 1] * x[i + 1] +
                                          x[i + 2] * x[i + 2] + x[i + 3] * x[i + 3]);
            for (std::size_t l = i; l < i + 4; ++l) x[l] /= norm;
        }
        const std::vector<double> M = mass.evaluate(std::vector<double>(x.begin(), x.begin() + nq));
        const std::vector<double> h =
            bias.evaluate(std::vector<double>(x.begin(), x.begin() + nq + n));
        const std::vector<double> E0 = rows.evaluate(x);
        double scale = 1;
        for (double v : M) scale = std::max(scale, std::abs(v));
        for (double v : E0) scale = std::max(scale, std::abs(v));
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_NEAR(h[i], -E0[i], 1e-12 * scale) << "bias force " << i << ", trial " << trial;
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<double> xj = x;
            xj[nq + n + j] = 1;
            const std::vector<double> Ej = rows.evaluate(xj);
            for (std::size_t i = 0; i < n; ++i) {
                EXPECT_NEAR(M[i * n + j], E0[i] - Ej[i], 1e-12 * scale)
                    << "M(" << i << ", " << j << "), trial " << trial;
                EXPECT_EQ(M[i * n + j], M[j * n + i]) << "M(" << i << ", " << j << ") symmetric";
            }
        }
    }
}

}  // namespace

TEST(TreeMassMatrix, CompositeRigidBodyMassMatrixAndBiasMatchTheArmsRows) {
    SampleModel m = make_kuka_iiwa14();
    TreeEquations tree = form_tree_equations(m.system, m.q, TreeOptions{.mass_matrix = true});
    expect_mass_matrix_and_bias_match_rows(m, tree, 29);
}

TEST(TreeMassMatrix, CompositeRigidBodyMassMatrixAndBiasMatchTheHumanoidsRows) {
    SampleModel m = make_humanoid();
    TreeEquations tree =
        form_tree_equations(m.system, m.q, m.speeds, TreeOptions{.mass_matrix = true});
    expect_mass_matrix_and_bias_match_rows(m, tree, 31);
}

TEST(TreeMassMatrix, MassMatrixIsPositiveDefiniteOnTheHumanoid) {
    SampleModel m = make_humanoid();
    TreeEquations tree =
        form_tree_equations(m.system, m.q, m.speeds, TreeOptions{.mass_matrix = true});
    std::vector<ex> q;
    for (const TimeVariable& v : m.q) q.push_back(v.d(0));
    CompiledExpressions mass(m.system.symbols(), q, tree.mass_matrix);
    std::vector<double> x(q.size(), 0.5);  // every quaternion (0.5, 0.5, 0.5, 0.5): unit
    const std::vector<double> M = mass.evaluate(x);
    // Cholesky without pivoting succeeds
    const std::size_t n = m.speeds.size();
    std::vector<double> L(M);
    for (std::size_t j = 0; j < n; ++j) {
        double s = L[j * n + j];
        for (std::size_t k = 0; k < j; ++k) s -= L[j * n + k] * L[j * n + k];
        ASSERT_GT(s, 0) << "pivot " << j;
        L[j * n + j] = std::sqrt(s);
        for (std::size_t i = j + 1; i < n; ++i) {
            double t = L[i * n + j];
            for (std::size_t k = 0; k < j; ++k) t -= L[i * n + k] * L[j * n + k];
            L[i * n + j] = t / L[j * n + j];
        }
    }
}

TEST(TreeMassMatrix, IsFormedOnlyOnRequest) {
    SampleModel m = make_kuka_iiwa14();
    TreeEquations tree = form_tree_equations(m.system, m.q);
    EXPECT_TRUE(tree.mass_matrix.empty());
    EXPECT_TRUE(tree.bias_forces.empty());
    EXPECT_EQ(tree.residuals.size(), 7u);
}
