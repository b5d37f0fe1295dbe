// SPDX-License-Identifier: MIT
// The benchmarks' hand-written planar-chain dynamics checked against a hand derivation and
// against Kane's equations of the same chain.
#include "planar_chain_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "alembert/eom/kane.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"

namespace alembert {
namespace {

using bench::PlanarChainReference;

TEST(PlanarChainReference, OneLinkIsARodAboutItsEnd) {
    // T = (m L^2/3) q'' - m g (L/2) sin q for a rod standing on its joint
    PlanarChainReference rod(1);
    const double q = 0.7, qd = -1.3, qdd = 2.1;
    double tau = 0;
    rod.inverse_dynamics(&q, &qd, &qdd, &tau);
    const double expected = qdd / 3.0 - 9.81 * 0.5 * std::sin(q);
    EXPECT_NEAR(tau, expected, 1e-14);
    double back = 0;
    rod.forward_dynamics(&q, &qd, &tau, &back);
    EXPECT_NEAR(back, qdd, 1e-13);
}

TEST(PlanarChainReference, UprightChainAtRestNeedsNoTorque) {
    PlanarChainReference chain(5);
    std::vector<double> zero(5, 0.0), tau(5, 1.0), qdd(5, 1.0);
    chain.inverse_dynamics(zero.data(), zero.data(), zero.data(), tau.data());
    chain.forward_dynamics(zero.data(), zero.data(), zero.data(), qdd.data());
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(tau[static_cast<std::size_t>(i)], 0.0) << "joint " << i + 1;
        EXPECT_EQ(qdd[static_cast<std::size_t>(i)], 0.0) << "joint " << i + 1;
    }
}

TEST(PlanarChainReference, HorizontalChainHoldsItsWeightAtEveryJoint) {
    // chain laid along -x (q1 = pi/2, the rest 0), at rest: gravity on links i..n, whose mass
    // centres lie d_k = (k - i + 1/2) m beyond joint i along -x, turns them about +z by
    // (-d_k)(-m g) each, so the torque holding them is T_i = -m g sum_k d_k
    const int n = 4;
    PlanarChainReference chain(n);
    std::vector<double> q(n, 0.0), zero(n, 0.0), tau(n);
    q[0] = M_PI / 2;
    chain.inverse_dynamics(q.data(), zero.data(), zero.data(), tau.data());
    for (int i = 0; i < n; ++i) {
        double d = 0;
        for (int k = i; k < n; ++k) d += (k - i) + 0.5;
        EXPECT_NEAR(tau[static_cast<std::size_t>(i)], -9.81 * d, 1e-12) << "joint " << i + 1;
    }
}

// Kane's equations of make_planar_chain(n), compiled with inputs q, q', q'', T
struct KaneChain {
    explicit KaneChain(int n) : model(make_planar_chain(n)) {
        std::vector<ex> residuals = form_kane_equations(model.system, model.q);
        std::vector<ex> inputs;
        for (int k = 0; k <= 2; ++k)
            for (const TimeVariable& q : model.q) inputs.push_back(q.d(k));
        inputs.insert(inputs.end(), model.unknowns.begin(), model.unknowns.end());
        tape = CompiledExpressions(model.system.symbols(), inputs, residuals);
    }
    // largest |residual| at (q, q', q'', T)
    double residual(const std::vector<double>& q, const std::vector<double>& qd,
                    const std::vector<double>& qdd, const std::vector<double>& tau) const {
        std::vector<double> in = q;
        in.insert(in.end(), qd.begin(), qd.end());
        in.insert(in.end(), qdd.begin(), qdd.end());
        in.insert(in.end(), tau.begin(), tau.end());
        std::vector<double> r = tape.evaluate(in);
        double worst = 0;
        for (double x : r) worst = std::max(worst, std::abs(x));
        return worst;
    }
    SampleModel model;
    CompiledExpressions tape;
};

class PlanarChainReferenceVsKane : public ::testing::TestWithParam<int> {};

TEST_P(PlanarChainReferenceVsKane, InverseAndForwardDynamicsSatisfyKanesEquations) {
    const int n = GetParam();
    const auto un = static_cast<std::size_t>(n);
    KaneChain kane(n);
    PlanarChainReference chain(n);
    std::mt19937 rng(1234u + static_cast<unsigned>(n));
    std::uniform_real_distribution<double> angle(-M_PI, M_PI), rate(-2.0, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> q(un), qd(un), qdd(un), tau(un), qdd_back(un);
        for (std::size_t i = 0; i < un; ++i) q[i] = angle(rng), qd[i] = rate(rng), qdd[i] = rate(rng);
        chain.inverse_dynamics(q.data(), qd.data(), qdd.data(), tau.data());
        double scale = 1.0;
        for (double t : tau) scale = std::max(scale, std::abs(t));
        EXPECT_LT(kane.residual(q, qd, qdd, tau), 1e-12 * scale) << "inverse, trial " << trial;

        // forward dynamics at other torques: Kane's residual vanishes at the accelerations
        for (std::size_t i = 0; i < un; ++i) tau[i] = 20.0 * rate(rng);
        chain.forward_dynamics(q.data(), qd.data(), tau.data(), qdd_back.data());
        EXPECT_LT(kane.residual(q, qd, qdd_back, tau), 1e-12 * std::max(scale, 40.0 * n))
            << "forward, trial " << trial;
    }
}

INSTANTIATE_TEST_SUITE_P(Links, PlanarChainReferenceVsKane, ::testing::Values(1, 2, 3, 5, 8));

}  // namespace
}  // namespace alembert
