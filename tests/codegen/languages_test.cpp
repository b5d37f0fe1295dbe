// SPDX-License-Identifier: MIT
// Generated Python (NumPy, SciPy) and MATLAB/Octave run and agree with Alembert's evaluator.
#include "alembert/codegen/codegen.hpp"

#include "drivers.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// Debian's interpreter (a pyenv shim may come first on PATH without NumPy)
const char* kPython = "/usr/bin/python3";

bool python_with_numpy_and_scipy() {
    std::string out;
    return run(std::string(kPython) + " -c 'import numpy, scipy'", out) == 0;
}

bool octave_present() {
    std::string out;
    return run("command -v octave", out) == 0;
}

}  // namespace

TEST(GeneratedPython, AgreesWithTheEvaluatorAtRandomStates) {
    if (!python_with_numpy_and_scipy())
        GTEST_SKIP() << kPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    std::vector<CodegenCase> cases;
    cases.push_back(triple_pendulum_case());
    cases.push_back(planar_chain_case(5));
    cases.push_back(tree_chain_case(3, ChainKind::spatial));
    for (const CodegenCase& c : cases) {
        ScratchDir dir("py-" + c.name);
        generate_case(c, Language::python, dir.path());
        std::vector<State> states = random_states(c, 5, 13);
        write(dir.path() / "driver.py", python_driver(c.name, dir.path().string()));
        write(dir.path() / "states.txt", driver_input(states));
        std::string out;
        ASSERT_EQ(run("cd " + dir.path().string() + " && " + kPython +
                          " driver.py < states.txt",
                      out),
                  0)
            << out;
        expect_agreement(c, states, numbers(out), 1e-12, "Python, " + c.name);
    }
}

TEST(GeneratedPython, SimulationBySolveIvpConservesEnergy) {
    if (!python_with_numpy_and_scipy())
        GTEST_SKIP() << kPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    CodegenCase c = triple_pendulum_case();
    ScratchDir dir("py-sim");
    CodegenOptions o{.name = c.name, .simulation = true};
    o.outputs = c.outputs;
    o.simulation_spec = {.final_time = 0.5,
                         .output_step = 0.1,
                         .absolute_tolerance = 1e-10,
                         .relative_tolerance = 1e-10,
                         .initial_q = {0.3, -0.5, 0.8},
                         .initial_qp = {},
                         .load_laws = {}};
    generate_code(c.table(), c.equations, Language::python, dir.path(), o);
    std::string out;
    ASSERT_EQ(run("cd " + dir.path().string() + " && " + kPython + " " + c.name + ".py run.csv",
                  out),
              0)
        << out;
    std::string header;
    auto rows = csv_rows(dir.path() / "run.csv", &header);
    EXPECT_EQ(header, "t [s],qA,qB,qC,qA',qB',qC',T_A,T_B,T_C,E [J],PE [J]");
    ASSERT_EQ(rows.size(), 6u);
    for (const auto& r : rows) EXPECT_NEAR(r[10], rows[0][10], 1e-7 * std::fabs(rows[0][10]));
    EXPECT_GT(std::fabs(rows.back()[11] - rows[0][11]), 1.0);  // it moved
}

TEST(GeneratedMatlab, AgreesWithTheEvaluatorUnderOctave) {
    if (!octave_present()) GTEST_SKIP() << "octave is not installed";
    std::vector<CodegenCase> cases;
    cases.push_back(triple_pendulum_case());
    cases.push_back(tree_chain_case(3, ChainKind::spatial));
    for (const CodegenCase& c : cases) {
        ScratchDir dir("m-" + c.name);
        generate_case(c, Language::matlab, dir.path());
        std::vector<State> states = random_states(c, 4, 17);
        std::string rows;
        for (const State& s : states) {
            std::ostringstream os;
            os.precision(17);
            os << s.t;
            for (const auto* v : {&s.q, &s.qp, &s.qpp, &s.u})
                for (double x : *v) os << ' ' << x;
            rows += os.str() + "\n";
        }
        write(dir.path() / "states.txt", rows);
        write(dir.path() / "driver.m", octave_driver(c.name, c.n(), c.m(), true));
        std::string out;
        ASSERT_EQ(run("cd " + dir.path().string() + " && octave --no-gui --quiet driver.m", out),
                  0)
            << out;
        expect_agreement(c, states, numbers(out), 1e-12, "Octave, " + c.name);
    }
}

TEST(GeneratedMatlab, FilesAreFunctionsWithQuotedStrings) {
    // checked without Octave: one function per file, named as the file, closed by end;
    // primes in the CSV header doubled inside MATLAB's single-quoted string
    CodegenCase c = triple_pendulum_case();
    ScratchDir dir("m-text");
    CodegenOptions o{.name = "tp", .simulation = true};
    o.units = {{"qA", "rad"}};
    GeneratedCode g = generate_code(c.table(), c.equations, Language::matlab, dir.path(), o);
    ASSERT_EQ(g.files.size(), 8u);  // parameters, context, M and f, ID, load laws, FD, rhs, simulate
    for (const fs::path& f : g.files) {
        std::ifstream in(f);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string stem = f.stem().string();
        EXPECT_EQ(text.rfind("function ", 0), 0u) << f;
        EXPECT_NE(text.find(stem + "("), std::string::npos) << f;
        EXPECT_EQ(text.substr(text.size() - 4), "end\n") << f;
        if (stem == "tp_simulate") {
            EXPECT_NE(text.find("'t [s],qA [rad],qB,qC,qA'' [rad/s],qB'',qC'',T_A,T_B,T_C'"),
                      std::string::npos)
                << text;
        }
    }
}
