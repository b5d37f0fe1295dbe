// SPDX-License-Identifier: MIT
// Point and frame Jacobians of the KUKA iiwa arm's flange against central finite differences
// of the positions and rotations they come with, and J' q' against differences of J along q'.
#include "alembert/eom/jacobians.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"

using namespace alembert;

namespace {

// the arm with its flange E, 0.126 m along B7z from B7_o
struct ArmWithFlange {
    SampleModel m = make_kuka_iiwa14();
    Point* E = nullptr;
    ArmWithFlange() {
        RigidBody& B7 = *m.links.back();
        E = &m.system.add_point("E", &B7);
        E->set_pos(m.system.point("B7_o"), ex(0.126) * B7.body_frame().z());
    }
    std::vector<ex> q() const {
        std::vector<ex> out;
        for (const TimeVariable& v : m.q) out.push_back(v.d(0));
        return out;
    }
    std::vector<ex> q_qp() const {
        std::vector<ex> out = q();
        for (const TimeVariable& v : m.q) out.push_back(v.d(1));
        return out;
    }
};

using Vec = std::vector<double>;

Vec along(const Vec& x, const Vec& d, double h) {
    Vec y = x;
    for (std::size_t i = 0; i < x.size(); ++i) y[i] += h * d[i];
    return y;
}

double largest(const Vec& v) {
    double s = 0;
    for (double x : v) s = std::max(s, std::abs(x));
    return s;
}

// J' q' against (J(q + h q') - J(q - h q')) / 2h times q'
void expect_jacobian_dot_rates_match(const CompiledExpressions& J, const CompiledExpressions& Jdq,
                                     const Vec& q, const Vec& qp, std::size_t rows) {
    const std::size_t n = q.size();
    const double h = 1e-5;
    const Vec Jp = J.evaluate(along(q, qp, h)), Jm = J.evaluate(along(q, qp, -h));
    Vec x = q;
    x.insert(x.end(), qp.begin(), qp.end());
    const Vec got = Jdq.evaluate(x);
    ASSERT_EQ(got.size(), rows);
    Vec want(rows, 0.0);
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < n; ++j)
            want[i] += (Jp[i * n + j] - Jm[i * n + j]) / (2 * h) * qp[j];
    const double scale = std::max(1.0, largest(want));
    for (std::size_t i = 0; i < rows; ++i)
        EXPECT_NEAR(got[i], want[i], 1e-7 * scale) << "J' q' row " << i;
}

}  // namespace

TEST(Jacobians, PointJacobianOfTheFlangeMatchesDifferencesOfItsPosition) {
    ArmWithFlange a;
    KinematicJacobian k = form_point_jacobian(a.m.system, a.m.q, *a.E);
    const std::size_t n = a.m.q.size();
    ASSERT_EQ(k.position.size(), 3u);
    ASSERT_EQ(k.jacobian.size(), 3 * n);
    const SymbolTable& st = a.m.system.symbols();
    CompiledExpressions p(st, a.q(), k.position), J(st, a.q(), k.jacobian),
        Jdq(st, a.q_qp(), k.jacobian_dot_rates);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        Vec q(n), qp(n);
        for (std::size_t i = 0; i < n; ++i) q[i] = d(rng), qp[i] = d(rng);
        const Vec got = J.evaluate(q);
        const double h = 1e-6, scale = std::max(1.0, largest(got));
        for (std::size_t j = 0; j < n; ++j) {
            Vec e(n, 0.0);
            e[j] = 1;
            const Vec pp = p.evaluate(along(q, e, h)), pm = p.evaluate(along(q, e, -h));
            for (std::size_t i = 0; i < 3; ++i)
                EXPECT_NEAR(got[i * n + j], (pp[i] - pm[i]) / (2 * h), 1e-7 * scale)
                    << "J(" << i << ", " << j << ")";
        }
        expect_jacobian_dot_rates_match(J, Jdq, q, qp, 3);
    }
}

TEST(Jacobians, FrameJacobianOfTheLastLinkMatchesDifferencesOfItsRotationAndOrigin) {
    ArmWithFlange a;
    const Frame& B7 = a.m.links.back()->body_frame();
    KinematicJacobian k = form_frame_jacobian(a.m.system, a.m.q, B7, *a.E);
    const std::size_t n = a.m.q.size();
    ASSERT_EQ(k.position.size(), 12u);
    ASSERT_EQ(k.jacobian.size(), 6 * n);
    const SymbolTable& st = a.m.system.symbols();
    CompiledExpressions x(st, a.q(), k.position), J(st, a.q(), k.jacobian),
        Jdq(st, a.q_qp(), k.jacobian_dot_rates);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> d(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        Vec q(n), qp(n);
        for (std::size_t i = 0; i < n; ++i) q[i] = d(rng), qp[i] = d(rng);
        const Vec got = J.evaluate(q), x0 = x.evaluate(q);
        const double h = 1e-6, scale = std::max(1.0, largest(got));
        for (std::size_t j = 0; j < n; ++j) {
            Vec e(n, 0.0);
            e[j] = 1;
            const Vec xp = x.evaluate(along(q, e, h)), xm = x.evaluate(along(q, e, -h));
            // dR/dq_j R^T = [w_j x]
            double S[3][3] = {};
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    for (int l = 0; l < 3; ++l)
                        S[r][c] += (xp[3 * r + l] - xm[3 * r + l]) / (2 * h) * x0[3 * c + l];
            const double w[3] = {S[2][1], S[0][2], S[1][0]};
            for (std::size_t i = 0; i < 3; ++i)
                EXPECT_NEAR(got[i * n + j], w[i], 1e-7 * scale) << "J_w(" << i << ", " << j << ")";
            for (std::size_t i = 0; i < 3; ++i)
                EXPECT_NEAR(got[(3 + i) * n + j], (xp[9 + i] - xm[9 + i]) / (2 * h), 1e-7 * scale)
                    << "J_v(" << i << ", " << j << ")";
        }
        expect_jacobian_dot_rates_match(J, Jdq, q, qp, 6);
    }
}
