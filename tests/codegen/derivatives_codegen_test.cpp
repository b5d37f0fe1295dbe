// SPDX-License-Identifier: MIT
// The generated derivatives of inverse and forward dynamics (add_dynamics_derivatives),
// compiled by the system C compiler: against central finite differences of the generated
// inverse and forward dynamics at random states (the KUKA iiwa arm by the recursive formation,
// a double pendulum by Kane's method and by the recursive formation, the triple pendulum by
// its road-map, whose loads enter with coefficients other than -I), one entry of the double
// pendulum against its hand derivation, and the same file from run to run.
#include <cstdlib>

#include "alembert/codegen/codegen.hpp"
#include "alembert/error.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "drivers.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// per state (t, q, qp, qpp, u): d u/d q, d u/d qp, then their central differences of
// inverse_dynamics; qpp, d qpp/d q, d qpp/d qp of forward_dynamics_derivatives, then qpp of
// forward_dynamics and the central differences of forward_dynamics
std::string derivatives_driver(const std::string& name) {
    return c_driver_frame(name, R"(        enum { N = NAME_NQ };
        double t, q[N], qp[N], qpp[N], u[N], Dq[N * N], Dqp[N * N], a[N], b[N], x[N];
        double fq[N * N], fqp[N * N], fqpp[N], fDq[N * N], fDqp[N * N];
        if (!read(&t, 1) || !read(q, N) || !read(qp, N) || !read(qpp, N) || !read(u, N)) return 1;
        NAME_inverse_dynamics_derivatives(&c, t, q, qp, qpp, Dq, Dqp);
        print(Dq, N * N);
        print(Dqp, N * N);
        for (int s = 0; s < 2; ++s) {
            double* y = s == 0 ? q : qp;
            for (int j = 0; j < N; ++j) {
                const double y0 = y[j], h = 1e-5 * (1.0 + (y0 < 0 ? -y0 : y0));
                y[j] = y0 + h;
                NAME_inverse_dynamics(&c, t, q, qp, qpp, a);
                y[j] = y0 - h;
                NAME_inverse_dynamics(&c, t, q, qp, qpp, b);
                y[j] = y0;
                for (int i = 0; i < N; ++i) (s == 0 ? fq : fqp)[i * N + j] = (a[i] - b[i]) / (2 * h);
            }
        }
        print(fq, N * N);
        print(fqp, N * N);
        if (NAME_forward_dynamics_derivatives(&c, t, q, qp, u, x, fDq, fDqp) != 0) return 2;
        print(x, N);
        print(fDq, N * N);
        print(fDqp, N * N);
        if (NAME_forward_dynamics(&c, t, q, qp, u, fqpp) != 0) return 2;
        print(fqpp, N);
        for (int s = 0; s < 2; ++s) {
            double* y = s == 0 ? q : qp;
            for (int j = 0; j < N; ++j) {
                const double y0 = y[j], h = 1e-5 * (1.0 + (y0 < 0 ? -y0 : y0));
                y[j] = y0 + h;
                if (NAME_forward_dynamics(&c, t, q, qp, u, a) != 0) return 2;
                y[j] = y0 - h;
                if (NAME_forward_dynamics(&c, t, q, qp, u, b) != 0) return 2;
                y[j] = y0;
                for (int i = 0; i < N; ++i) (s == 0 ? fq : fqp)[i * N + j] = (a[i] - b[i]) / (2 * h);
            }
        }
        print(fq, N * N);
        print(fqp, N * N);
)");
}

// the case's equations with the derivatives added
CodegenCase with_derivatives(CodegenCase c) {
    add_dynamics_derivatives(c.model->system.symbols(), c.equations);
    return c;
}

CodegenCase arm_case() {
    CodegenCase c;
    c.name = "arm";
    c.model = std::make_unique<SampleModel>(make_kuka_iiwa14());
    TreeEquations tree =
        form_tree_equations(c.model->system, c.model->q, TreeOptions{.mass_matrix = true});
    c.equations = {c.model->q, tree.residuals, c.model->unknowns, std::nullopt, tree.accelerations};
    c.equations.mass_matrix = tree.mass_matrix;
    c.equations.bias_forces = tree.bias_forces;
    return c;
}

// the matrices of one state as the driver prints them
struct Printed {
    std::vector<double> Dq, Dqp, fd_Dq, fd_Dqp, qpp, Fq, Fqp, fd_qpp, fd_Fq, fd_Fqp;
};

std::vector<Printed> split_printed(const std::vector<double>& v, std::size_t n, std::size_t count) {
    const std::size_t nn = n * n;
    std::vector<Printed> out;
    std::size_t at = 0;
    auto take = [&](std::size_t k) {
        std::vector<double> x(v.begin() + static_cast<long>(at), v.begin() + static_cast<long>(at + k));
        at += k;
        return x;
    };
    for (std::size_t s = 0; s < count; ++s) {
        Printed p;
        p.Dq = take(nn);
        p.Dqp = take(nn);
        p.fd_Dq = take(nn);
        p.fd_Dqp = take(nn);
        p.qpp = take(n);
        p.Fq = take(nn);
        p.Fqp = take(nn);
        p.fd_qpp = take(n);
        p.fd_Fq = take(nn);
        p.fd_Fqp = take(nn);
        out.push_back(std::move(p));
    }
    return out;
}

// |got - want| <= tol * max(1, max |want|), entry by entry
void expect_close(const std::vector<double>& got, const std::vector<double>& want, double tol,
                  const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    double scale = 1;
    for (double w : want) scale = std::max(scale, std::fabs(w));
    for (std::size_t i = 0; i < got.size(); ++i)
        EXPECT_NEAR(got[i], want[i], tol * scale) << what << " entry " << i;
}

// generates the case with derivatives in C, compiles it with the driver, runs it at `count`
// random states; the printed values per state
std::vector<Printed> run_derivatives(const CodegenCase& c, const std::vector<State>& states,
                                     const std::string& tag, std::string* source = nullptr) {
    ScratchDir dir(tag);
    generate_case(c, Language::c, dir.path());
    if (source) *source = file_text(dir.path() / (c.name + ".c"));
    const std::optional<std::vector<double>> v =
        compile_and_run_c_driver(dir.path(), c.name, derivatives_driver(c.name), driver_input(states));
    if (!v) return {};
    const std::size_t n = c.n();
    if (v->size() != states.size() * (8 * n * n + 2 * n)) {
        ADD_FAILURE() << "the driver printed " << v->size() << " numbers";
        return {};
    }
    return split_printed(*v, n, states.size());
}

// the derivatives against central differences of the generated dynamics, to 1e-7 relative;
// `expected` are lines the generated file holds (the path taken: factorization, load map)
void expect_derivatives_match_differences(const CodegenCase& c, int count, const std::string& tag,
                                          const std::vector<std::string>& expected) {
    const std::vector<State> states = random_states(c, count, 11);
    std::string source;
    const std::vector<Printed> got = run_derivatives(c, states, tag, &source);
    for (const std::string& line : expected)
        EXPECT_NE(source.find(line), std::string::npos) << "no '" << line << "' in " << c.name;
    ASSERT_EQ(got.size(), states.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        const std::string at = c.name + " state " + std::to_string(k) + ": ";
        expect_close(got[k].Dq, got[k].fd_Dq, 1e-7, at + "d u/d q");
        expect_close(got[k].Dqp, got[k].fd_Dqp, 1e-7, at + "d u/d qp");
        expect_close(got[k].qpp, got[k].fd_qpp, 1e-12, at + "qpp");
        expect_close(got[k].Fq, got[k].fd_Fq, 1e-7, at + "d qpp/d q");
        expect_close(got[k].Fqp, got[k].fd_Fqp, 1e-7, at + "d qpp/d qp");
    }
}

}  // namespace

TEST(DerivativesCodegen, ArmDerivativesMatchCentralDifferencesOfTheGeneratedDynamics) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    // the articulated-body recursion for qpp, M alone factored by Cholesky
    expect_derivatives_match_differences(with_derivatives(arm_case()), 4, "c-derivatives-arm",
                                         {"if (arm_cholesky_factor(arm_NQ, M) != 0) return -1;"});
}

TEST(DerivativesCodegen, DoublePendulumByKaneMatchesDifferencesAndHandDerivation) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    const CodegenCase c = with_derivatives(planar_chain_case(2));
    // M and f of Kane's method, M factored by Cholesky for qpp and the derivatives
    expect_derivatives_match_differences(c, 5, "c-derivatives-chain2",
                                         {"chain2_cholesky_back(chain2_NQ, 1, M, qpp);"});
    // two uniform rods (L = 1 m, m = 1 kg, mass centre at L/2), relative angles, hanging:
    // u1 = M11 q1'' + M12 q2'' - m2 L1 d2 sin(q2) (2 q1' q2' + q2'^2) + g1(q), so
    // d u1/d q2' = -2 m2 L1 d2 sin(q2) (q1' + q2') = -sin(q2) (q1' + q2'); and
    // u2 = M21 q1'' + M22 q2'' + m2 L1 d2 sin(q2) q1'^2 + m2 g d2 sin(q1 + q2), with M21 and M22
    // free of q1, so d u2/d q1 = m2 g d2 cos(q1 + q2) = 4.905 cos(q1 + q2)
    const std::vector<State> states = random_states(c, 3, 23);
    const std::vector<Printed> got = run_derivatives(c, states, "c-derivatives-hand");
    ASSERT_EQ(got.size(), states.size());
    for (std::size_t k = 0; k < states.size(); ++k) {
        const State& s = states[k];
        const double du1_dqp2 = -std::sin(s.q[1]) * (s.qp[0] + s.qp[1]);
        const double du2_dq1 = 9.81 * 0.5 * std::cos(s.q[0] + s.q[1]);
        EXPECT_NEAR(got[k].Dqp[0 * 2 + 1], du1_dqp2, 1e-12) << "state " << k;
        EXPECT_NEAR(got[k].Dq[1 * 2 + 0], du2_dq1, 1e-12) << "state " << k;
    }
}

TEST(DerivativesCodegen, DoublePendulumByTheRecursiveFormationMatchesDifferences) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    expect_derivatives_match_differences(with_derivatives(tree_chain_case(2, ChainKind::planar)), 5,
                                         "c-derivatives-tree2", {"tree2_mass_matrix(c, t, q, M);"});
}

TEST(DerivativesCodegen, TriplePendulumRoadmapMatchesDifferences) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    // the road-map rows about the joints, M split from them (symmetric: Cholesky)
    expect_derivatives_match_differences(
        with_derivatives(triple_pendulum_case()), 5, "c-derivatives-triple",
        {"triple_pendulum_cholesky_back(triple_pendulum_NQ, 1, M, qpp);"});
}

TEST(DerivativesCodegen, MixedRowsWhoseLoadsEnterWithOtherCoefficientsMatchDifferences) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    // Kane's rows of the double pendulum mixed, E1 + E2 and 2 E2 (as equations in absolute
    // angles mix the joint torques): the loads' coefficients are no longer -I, M not symmetric
    CodegenCase c = planar_chain_case(2);
    c.name = "mixed2";
    const std::vector<ex> E = c.equations.residuals;
    c.equations.residuals = {E[0] + E[1], 2 * E[1]};
    c.equations.mass_forcing = std::nullopt;
    expect_derivatives_match_differences(
        with_derivatives(std::move(c)), 5, "c-derivatives-mixed",
        {"static const double A[mixed2_NQ * mixed2_NQ] = {", "mixed2_lu_back(mixed2_NQ, mixed2_NQ, M, p, D);"});
}

TEST(DerivativesCodegen, RowsThatLuPivotsAfterItsFirstStepMatchDifferences) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler found (set CC or install gcc)";
    // Kane's rows of a 4-link chain with the second scaled by 1/100: LU's second step takes
    // a lower row as its pivot, after the first step's multipliers were stored, so the solve
    // must apply the factorization's swaps to the right sides as P A = L U has them
    CodegenCase c = planar_chain_case(4);
    c.name = "pivoted4";
    std::vector<ex> E = c.equations.residuals;
    E[1] = E[1] / 100;
    c.equations.residuals = E;
    c.equations.mass_forcing = std::nullopt;
    expect_derivatives_match_differences(with_derivatives(std::move(c)), 5, "c-derivatives-pivoted",
                                         {"pivoted4_lu_back(pivoted4_NQ, pivoted4_NQ, M, p, D);"});
}

TEST(DerivativesCodegen, CppAndPythonHaveTheDerivatives) {
    const CodegenCase c = with_derivatives(arm_case());
    ScratchDir dir("derivatives-languages");
    GeneratedCode g = generate_case(c, Language::cpp, dir.path());
    EXPECT_GT(g.inverse_dynamics_derivatives_operations, g.inverse_dynamics_operations);
    const std::string hpp = file_text(dir.path() / "arm.hpp");
    EXPECT_NE(hpp.find("void inverse_dynamics_derivatives(double t, const double* q, const double* "
                       "qp, const double* qpp, double* dtau_dq, double* dtau_dqp) const;"),
              std::string::npos)
        << hpp;
    EXPECT_NE(hpp.find("bool forward_dynamics_derivatives("), std::string::npos);
    std::string out;
    const char* cxx_env = std::getenv("CXX");
    const std::string cxx = cxx_env && *cxx_env ? cxx_env : "c++";
    if (run(cxx + " --version", out) == 0) {
        // the C++ derivatives agree with the C ones (checked above against differences)
        write(dir.path() / "driver.cpp", cpp_driver_frame("arm", R"(        double t, q[nq], qp[nq], qpp[nq], u[nq], Dq[nq * nq], Dqp[nq * nq], x[nq];
        double Fq[nq * nq], Fqp[nq * nq];
        if (!read(&t, 1) || !read(q, nq) || !read(qp, nq) || !read(qpp, nq) || !read(u, nq)) return 1;
        model.inverse_dynamics_derivatives(t, q, qp, qpp, Dq, Dqp);
        if (!model.forward_dynamics_derivatives(t, q, qp, u, x, Fq, Fqp)) return 2;
        print(Dq, nq * nq);
        print(Dqp, nq * nq);
        print(x, nq);
        print(Fq, nq * nq);
        print(Fqp, nq * nq);
)"));
        ASSERT_EQ(run("cd " + dir.path().string() + " && " + cxx +
                          " -std=c++17 -Wall -Wextra -Werror -O2 arm.cpp driver.cpp -o driver",
                      out),
                  0)
            << out;
        const std::vector<State> states = random_states(c, 2, 11);
        write(dir.path() / "states.txt", driver_input(states));
        ASSERT_EQ(run("cd " + dir.path().string() + " && ./driver < states.txt", out), 0) << out;
        const std::vector<double> v = numbers(out);
        const std::size_t n = c.n();
        ASSERT_EQ(v.size(), states.size() * (4 * n * n + n)) << out;
        if (have_c_compiler()) {
            const std::vector<Printed> cv = run_derivatives(c, states, "derivatives-c-for-cpp");
            ASSERT_EQ(cv.size(), states.size());
            std::size_t at = 0;
            for (std::size_t k = 0; k < states.size(); ++k)
                for (const auto* x : {&cv[k].Dq, &cv[k].Dqp, &cv[k].qpp, &cv[k].Fq, &cv[k].Fqp})
                    for (double w : *x) {
                        EXPECT_NEAR(v[at], w, 1e-12 * std::max(1.0, std::fabs(w))) << "value " << at;
                        ++at;
                    }
        }
    }
    generate_case(c, Language::python, dir.path());
    const std::string py = file_text(dir.path() / "arm.py");
    EXPECT_NE(py.find("def inverse_dynamics_derivatives(t, q, qp, qpp, ctx):"), std::string::npos);
    EXPECT_NE(py.find("def forward_dynamics_derivatives(t, q, qp, u, ctx):"), std::string::npos);
    EXPECT_EQ(run("python3 -m py_compile " + (dir.path() / "arm.py").string(), out), 0) << out;
    generate_case(c, Language::matlab, dir.path());
    EXPECT_TRUE(fs::exists(dir.path() / "arm_forward_dynamics_derivatives.m"));
    EXPECT_TRUE(fs::exists(dir.path() / "arm_inverse_dynamics_derivatives.m"));
}

TEST(DerivativesCodegen, ModelsThatDoNotFitAreRefusedByName) {
    CodegenCase c = triple_pendulum_reactions_case();
    try {
        add_dynamics_derivatives(c.model->system.symbols(), c.equations);
        FAIL() << "derivatives with joint-reaction measures among the loads were formed";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("9 loads for 3 coordinates"), std::string::npos)
            << e.what();
    }
}

// Run by the next test in a process of its own: generates the arm into $ALEMBERT_TEST_OUT.
TEST(DerivativesCodegen, DISABLED_GenerateArmIntoTestOut) {
    const char* dir = std::getenv("ALEMBERT_TEST_OUT");
    ASSERT_TRUE(dir && *dir) << "set ALEMBERT_TEST_OUT to the output directory";
    generate_case(with_derivatives(arm_case()), Language::c, dir);
}

// Two processes generate the same bytes.
TEST(DerivativesCodegen, GeneratedDerivativesAreTheSameFromRunToRun) {
    ScratchDir dir("c-derivatives-repeat");
    std::string texts[2], out;
    for (int k = 0; k < 2; ++k) {
        const fs::path sub = dir.path() / std::to_string(k);
        fs::create_directories(sub);
        ASSERT_EQ(run("ALEMBERT_TEST_OUT=" + sub.string() + " " +
                          this_program_for("DerivativesCodegen.DISABLED_GenerateArmIntoTestOut"),
                      out),
                  0)
            << out;
        texts[k] = file_text(sub / "arm.c");
    }
    EXPECT_NE(texts[0].find("void arm_inverse_dynamics_derivatives("), std::string::npos);
    EXPECT_NE(texts[0].find("int arm_forward_dynamics_derivatives("), std::string::npos);
    EXPECT_TRUE(texts[0] == texts[1]) << "arm.c differs between two runs";
}
