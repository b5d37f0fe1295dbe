// SPDX-License-Identifier: MIT
// Generated point and frame Jacobians of the KUKA iiwa arm's flange, compiled by the system C
// compiler, against central finite differences of the generated positions and rotations, and
// J' q' against differences of the generated J along q'.
#include <cstdlib>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/jacobians.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "drivers.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

using Vec = std::vector<double>;

// per state q, q': the frame's position (12), J (6 x 7), J' q' (6)
std::string jacobian_driver(const std::string& name) {
    return c_driver_frame(
        name, R"(        double q[NAME_NQ], qp[NAME_NQ], pos[12], J[6 * NAME_NQ], Jdqp[6];
        if (!read(q, NAME_NQ) || !read(qp, NAME_NQ)) return 1;
        NAME_flange_position(&c, 0, q, pos);
        NAME_flange_jacobian(&c, 0, q, J);
        NAME_flange_jacobian_dot_rates(&c, 0, q, qp, Jdqp);
        print(pos, 12);
        print(J, 6 * NAME_NQ);
        print(Jdqp, 6);
)");
}

}  // namespace

TEST(JacobianCodegen, GeneratedFrameJacobianMatchesDifferencesOfGeneratedPositions) {
    const char* cc_env = std::getenv("CC");
    const std::string cc = cc_env && *cc_env ? cc_env : "cc";
    std::string out;
    if (run(cc + " --version", out) != 0)
        GTEST_SKIP() << "no C compiler '" << cc << "' found (set CC or install gcc)";

    SampleModel m = make_kuka_iiwa14();
    RigidBody& B7 = *m.links.back();
    Point& E = m.system.add_point("E", &B7);
    E.set_pos(m.system.point("B7_o"), ex(0.126) * B7.body_frame().z());
    TreeEquations tree = form_tree_equations(m.system, m.q);
    DynamicsEquations eq{m.q, tree.residuals, m.unknowns, std::nullopt, tree.accelerations};
    CodegenOptions options;
    options.name = "arm";
    options.jacobians = {{"flange", form_frame_jacobian(m.system, m.q, B7.body_frame(), E)}};
    ScratchDir dir("c-jacobian");
    generate_code(m.system.symbols(), eq, Language::c, dir.path(), options);
    write(dir.path() / "driver.c", jacobian_driver(options.name));
    ASSERT_EQ(run("cd " + dir.path().string() + " && " + cc +
                      " -std=c99 -pedantic -Wall -Wextra -Werror -O2 arm.c driver.c -lm -o driver",
                  out),
              0)
        << "compiling the generated C failed:\n"
        << out;

    // per trial: the state, then q +- h e_j (j = 1..n), then q +- h q'
    const std::size_t n = m.q.size();
    const double h = 1e-6, hd = 1e-5;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> d(-2, 2);
    const int trials = 3;
    std::vector<std::pair<Vec, Vec>> states;
    for (int k = 0; k < trials; ++k) {
        Vec q(n), qp(n);
        for (std::size_t i = 0; i < n; ++i) q[i] = d(rng), qp[i] = d(rng);
        states.push_back({q, qp});
        for (std::size_t j = 0; j < n; ++j)
            for (double s : {h, -h}) {
                Vec x = q;
                x[j] += s;
                states.push_back({x, qp});
            }
        for (double s : {hd, -hd}) {
            Vec x = q;
            for (std::size_t i = 0; i < n; ++i) x[i] += s * qp[i];
            states.push_back({x, qp});
        }
    }
    std::ostringstream input;
    input.precision(17);
    input << states.size() << '\n';
    for (const auto& [q, qp] : states) {
        for (double x : q) input << x << ' ';
        for (double x : qp) input << x << ' ';
        input << '\n';
    }
    write(dir.path() / "states.txt", input.str());
    ASSERT_EQ(run("cd " + dir.path().string() + " && ./driver < states.txt", out), 0) << out;
    const Vec got = numbers(out);
    const std::size_t per = 12 + 6 * n + 6, per_trial = 2 * n + 3;
    ASSERT_EQ(got.size(), states.size() * per);
    auto at = [&](std::size_t state) { return &got[state * per]; };

    for (int k = 0; k < trials; ++k) {
        const std::size_t base = static_cast<std::size_t>(k) * per_trial;
        const double* x0 = at(base);
        const double* J = x0 + 12;
        const double* Jdqp = J + 6 * n;
        double scale = 1;
        for (std::size_t i = 0; i < 6 * n; ++i) scale = std::max(scale, std::abs(J[i]));
        for (std::size_t j = 0; j < n; ++j) {
            const double* xp = at(base + 1 + 2 * j);
            const double* xm = at(base + 2 + 2 * j);
            // dR/dq_j R^T = [w_j x]; the origin's position by central differences
            double S[3][3] = {};
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    for (int l = 0; l < 3; ++l)
                        S[r][c] += (xp[3 * r + l] - xm[3 * r + l]) / (2 * h) * x0[3 * c + l];
            const double w[3] = {S[2][1], S[0][2], S[1][0]};
            for (std::size_t i = 0; i < 3; ++i) {
                EXPECT_NEAR(J[i * n + j], w[i], 1e-7 * scale) << "J_w(" << i << ", " << j << ")";
                EXPECT_NEAR(J[(3 + i) * n + j], (xp[9 + i] - xm[9 + i]) / (2 * h), 1e-7 * scale)
                    << "J_v(" << i << ", " << j << ")";
            }
        }
        // J' q' = (J(q + hd q') - J(q - hd q')) / 2 hd q'
        const double* Jp = at(base + 1 + 2 * n) + 12;
        const double* Jm = at(base + 2 + 2 * n) + 12;
        const Vec& qp = states[base].second;
        for (std::size_t i = 0; i < 6; ++i) {
            double want = 0;
            for (std::size_t j = 0; j < n; ++j)
                want += (Jp[i * n + j] - Jm[i * n + j]) / (2 * hd) * qp[j];
            EXPECT_NEAR(Jdqp[i], want, 1e-7 * std::max(1.0, std::abs(want) + scale))
                << "J' q' row " << i;
        }
    }
}
