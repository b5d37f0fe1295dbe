// SPDX-License-Identifier: MIT
// The generated mass matrix alone and bias forces alone (composite-rigid-body recursion) of
// the KUKA iiwa arm, compiled by the system C compiler, against the generated mass matrix and
// forcing at random states; the generated file is the same from run to run.
#include <cstdlib>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "drivers.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// per state: M and f of mass_forcing (loads zero), then M alone, then the bias forces
std::string mass_matrix_driver(const std::string& name) {
    return c_driver_frame(name, R"(        double t, q[NAME_NQ], qp[NAME_NQ], u[NAME_NU] = {0};
        double M[NAME_NQ * NAME_NQ], f[NAME_NQ], M_alone[NAME_NQ * NAME_NQ], bias[NAME_NQ];
        if (!read(&t, 1) || !read(q, NAME_NQ) || !read(qp, NAME_NQ)) return 1;
        NAME_mass_forcing(&c, t, q, qp, u, M, f);
        NAME_mass_matrix(&c, t, q, M_alone);
        NAME_bias_forces(&c, t, q, qp, bias);
        print(M, NAME_NQ * NAME_NQ);
        print(f, NAME_NQ);
        print(M_alone, NAME_NQ * NAME_NQ);
        print(bias, NAME_NQ);
)");
}

DynamicsEquations arm_equations(const SampleModel& m) {
    TreeEquations tree = form_tree_equations(m.system, m.q, TreeOptions{.mass_matrix = true});
    DynamicsEquations eq{m.q, tree.residuals, m.unknowns, std::nullopt, tree.accelerations};
    eq.mass_matrix = tree.mass_matrix;
    eq.bias_forces = tree.bias_forces;
    return eq;
}

}  // namespace

TEST(MassMatrixCodegen, GeneratedMassMatrixAndBiasOfTheArmMatchMassAndForcing) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";

    SampleModel m = make_kuka_iiwa14();
    const DynamicsEquations eq = arm_equations(m);
    ScratchDir dir("c-mass-matrix");
    CodegenOptions options;
    options.name = "arm";
    GeneratedCode g = generate_code(m.system.symbols(), eq, Language::c, dir.path(), options);
    EXPECT_GT(g.mass_matrix_operations, 0u);
    EXPECT_GT(g.bias_forces_operations, 0u);
    // M alone costs less than M with the forcing
    EXPECT_LT(g.mass_matrix_operations, g.mass_forcing_operations);

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(-2.5, 2.5), rate(-2, 2);
    const int count = 5;
    const std::size_t n = m.q.size();
    std::ostringstream input;
    input.precision(17);
    input << count << '\n';
    for (int k = 0; k < count; ++k) {
        input << 0.0;
        for (std::size_t i = 0; i < n; ++i) input << ' ' << angle(rng);
        for (std::size_t i = 0; i < n; ++i) input << ' ' << rate(rng);
        input << '\n';
    }
    const std::optional<std::vector<double>> printed =
        compile_and_run_c_driver(dir.path(), options.name, mass_matrix_driver(options.name), input.str());
    ASSERT_TRUE(printed);
    const std::vector<double>& got = *printed;
    const std::size_t per = 2 * (n * n + n);
    ASSERT_EQ(got.size(), count * per);
    for (int k = 0; k < count; ++k) {
        const double* M = &got[k * per];
        const double* f = M + n * n;
        const double* M_alone = f + n;
        const double* bias = M_alone + n * n;
        double scale = 1;
        for (std::size_t i = 0; i < n * n; ++i) scale = std::max(scale, std::abs(M[i]));
        for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(f[i]));
        for (std::size_t i = 0; i < n * n; ++i)
            EXPECT_NEAR(M_alone[i], M[i], 1e-12 * scale) << "M entry " << i << ", state " << k;
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_NEAR(bias[i], -f[i], 1e-12 * scale) << "bias " << i << ", state " << k;
    }
}

// Run by the next test in a process of its own: generates the arm into $ALEMBERT_TEST_OUT.
TEST(MassMatrixCodegen, DISABLED_GenerateArmIntoTestOut) {
    const char* dir = std::getenv("ALEMBERT_TEST_OUT");
    ASSERT_TRUE(dir && *dir) << "set ALEMBERT_TEST_OUT to the output directory";
    SampleModel m = make_kuka_iiwa14();
    CodegenOptions options;
    options.name = "arm";
    generate_code(m.system.symbols(), arm_equations(m), Language::c, dir, options);
}

// Two processes generate the same bytes (GiNaC's term order may differ between two models
// built in one process, not between runs).
TEST(MassMatrixCodegen, GeneratedMassMatrixFileIsTheSameFromRunToRun) {
    ScratchDir dir("c-mass-matrix-repeat");
    std::string texts[2], out;
    for (int k = 0; k < 2; ++k) {
        const fs::path sub = dir.path() / std::to_string(k);
        fs::create_directories(sub);
        ASSERT_EQ(run("ALEMBERT_TEST_OUT=" + sub.string() + " " +
                          this_program_for("MassMatrixCodegen.DISABLED_GenerateArmIntoTestOut"),
                      out),
                  0)
            << out;
        texts[k] = file_text(sub / "arm.c");
    }
    EXPECT_NE(texts[0].find("void arm_mass_matrix("), std::string::npos);
    EXPECT_NE(texts[0].find("void arm_bias_forces("), std::string::npos);
    EXPECT_TRUE(texts[0] == texts[1]) << "arm.c differs between two runs";
}
