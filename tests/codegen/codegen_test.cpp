// SPDX-License-Identifier: MIT
// Generated C and C++ compile warning-free, run, and agree with Alembert's evaluator; the
// simulation programs conserve energy; bad requests fail with clear messages.
#include "alembert/codegen/codegen.hpp"

#include "alembert/error.hpp"
#include "drivers.hpp"
#include "harness.hpp"
#include "support/expect.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// generates `lang` for the case into dir, compiles it with the driver, runs it on the states
std::vector<double> run_generated(const CodegenCase& c, Language lang, const fs::path& dir,
                                  const std::vector<State>& states,
                                  const CodegenOptions& extra = {}, const std::string& setup = "") {
    GeneratedCode g = generate_case(c, lang, dir, extra);
    EXPECT_TRUE(g.inverse_dynamics);
    std::string out;
    std::string cmd;
    if (lang == Language::c) {
        write(dir / "driver.c", c_driver(c.name));
        cmd = "cd " + dir.string() + " && cc -std=c99 -pedantic -Wall -Wextra -Werror -O0 " +
              c.name + ".c driver.c -lm -o driver";
    } else {
        write(dir / "driver.cpp", cpp_driver(c.name, setup));
        cmd = "cd " + dir.string() + " && c++ -std=c++17 -pedantic -Wall -Wextra -Werror -O0 " +
              c.name + ".cpp driver.cpp -o driver";
    }
    EXPECT_EQ(run(cmd, out), 0) << "compiling the generated code failed:\n" << out;
    write(dir / "states.txt", driver_input(states));
    EXPECT_EQ(run("cd " + dir.string() + " && ./driver < states.txt", out), 0) << out;
    return numbers(out);
}

// a road-map, Kane's equations with M given, and the recursive formation (rows and the
// articulated-body accelerations) of planar and spatial chains (two-axis joints)
std::vector<CodegenCase> cases() {
    std::vector<CodegenCase> v;
    v.push_back(triple_pendulum_case());
    v.push_back(planar_chain_case(5));
    v.push_back(tree_chain_case(5, ChainKind::planar));
    v.push_back(tree_chain_case(3, ChainKind::spatial));
    return v;
}

}  // namespace

TEST(GenerateCode, CAgreesWithTheEvaluatorAtRandomStates) {
    for (const CodegenCase& c : cases()) {
        ScratchDir dir("c-" + c.name);
        std::vector<State> states = random_states(c, 6);
        expect_agreement(c, states, run_generated(c, Language::c, dir.path(), states), 1e-12,
                         "C, " + c.name);
    }
}

TEST(GenerateCode, CppAgreesWithTheEvaluatorAtRandomStates) {
    for (const CodegenCase& c : cases()) {
        ScratchDir dir("cpp-" + c.name);
        std::vector<State> states = random_states(c, 6, 11);
        expect_agreement(c, states, run_generated(c, Language::cpp, dir.path(), states), 1e-12,
                         "C++, " + c.name);
    }
}

TEST(GenerateCode, ParametersChangedInTheGeneratedCodeActLikeNewConstants) {
    // the generated model on the Moon against the evaluator with the table's g changed
    CodegenCase c = triple_pendulum_case();
    ScratchDir dir("cpp-moon");
    std::vector<State> states = random_states(c, 3, 5);
    std::vector<double> got =
        run_generated(c, Language::cpp, dir.path(), states, {}, "p.g = 1.62; p.m_C = 50.0;");
    SymbolTable& T = c.model->system.symbols();
    T.set_value(T.symbol("g"), 1.62);
    T.set_value(T.symbol("m_C"), 50.0);
    expect_agreement(c, states, got, 1e-12, "C++ with changed parameters");
}

TEST(GenerateCode, JointReactionsOfInverseDynamicsAgreeWithTheEvaluator) {
    // 3 torques and 6 joint-reaction measures for 3 coordinates: inverse dynamics from the
    // road-map rows, at full precision
    CodegenCase c = triple_pendulum_reactions_case();
    ScratchDir dir("c-reactions");
    GeneratedCode g = generate_case(c, Language::c, dir.path());
    EXPECT_TRUE(g.inverse_dynamics);
    std::vector<State> states = random_states(c, 4);
    std::vector<double> got = run_generated(c, Language::c, dir.path(), states);
    expect_agreement(c, states, got, 1e-12, "C with joint reactions");
}

TEST(GenerateCode, InverseThenForwardDynamicsGivesBackTheAccelerations) {
    // a round trip through the generated C alone: the torques inverse dynamics computes for
    // q'', fed to forward dynamics, give back q''
    CodegenCase c = planar_chain_case(4);
    ScratchDir dir("c-roundtrip");
    std::vector<State> states = random_states(c, 4, 3);
    std::vector<double> first = run_generated(c, Language::c, dir.path(), states);
    const std::size_t n = c.n(), per = n * n + 3 * n + c.outputs.size();
    ASSERT_EQ(first.size(), per * states.size());
    std::vector<State> fed = states;
    for (std::size_t k = 0; k < states.size(); ++k)
        for (std::size_t i = 0; i < n; ++i) fed[k].u[i] = first[k * per + n * n + 2 * n + i];
    write(dir.path() / "states.txt", driver_input(fed));
    std::string out;
    ASSERT_EQ(run("cd " + dir.path().string() + " && ./driver < states.txt", out), 0) << out;
    std::vector<double> second = numbers(out);
    for (std::size_t k = 0; k < states.size(); ++k)
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_NEAR(second[k * per + n * n + n + i], states[k].qpp[i], 1e-12)
                << "state " << k << ", coordinate " << i;
}

TEST(GenerateCode, SimulationProgramsConserveEnergyAndWriteLabelledColumns) {
    // the triple pendulum released with zero torques: E = KE + PE stays constant
    CodegenCase c = triple_pendulum_case();
    for (Language lang : {Language::c, Language::cpp}) {
        ScratchDir dir(std::string("sim-") + to_string(lang));
        CodegenOptions o{.name = c.name, .source = "triple_pendulum_case()"};
        o.outputs = c.outputs;
        o.units = {{"qA", "rad"}, {"qB", "rad"}, {"qC", "rad"}, {"T_A", "N*m"}};
        o.simulation = true;
        o.simulation_spec = {.final_time = 1.0,
                             .output_step = 0.05,
                             .absolute_tolerance = 1e-11,
                             .relative_tolerance = 1e-11,
                             .initial_q = {0.3, -0.5, 0.8},
                             .initial_qp = {0.0, 1.0, 0.0},
                             .load_laws = {}};
        generate_code(c.table(), c.equations, lang, dir.path(), o);
        const bool cpp = lang == Language::cpp;
        std::string out;
        std::string cmd = "cd " + dir.path().string() + " && " +
                          (cpp ? "c++ -std=c++17" : "cc -std=c99") +
                          " -pedantic -Wall -Wextra -Werror -O1 " + c.name +
                          (cpp ? ".cpp " : ".c ") + c.name + (cpp ? "_main.cpp" : "_main.c") +
                          " -lm -o sim && ./sim run.csv";
        ASSERT_EQ(run(cmd, out), 0) << out;
        std::string header;
        auto rows = csv_rows(dir.path() / "run.csv", &header);
        EXPECT_EQ(header,
                  "t [s],qA [rad],qB [rad],qC [rad],qA' [rad/s],qB' [rad/s],qC' [rad/s],"
                  "T_A [N*m],T_B,T_C,E [J],PE [J]");
        ASSERT_EQ(rows.size(), 21u);
        const double E0 = rows[0][10];
        for (std::size_t k = 0; k < rows.size(); ++k) {
            EXPECT_NEAR(rows[k][0], 0.05 * static_cast<double>(k), 1e-15);
            EXPECT_NEAR(rows[k][10], E0, 1e-8 * std::fabs(E0)) << "t = " << rows[k][0];
        }
        EXPECT_NEAR(rows[0][1], 0.3, 0);
        EXPECT_NEAR(rows[0][5], 1.0, 0);
        // it moved: the kinetic energy at the end is not that at the start
        EXPECT_GT(std::fabs(rows.back()[11] - rows[0][11]), 1.0);
    }
}

TEST(GenerateCode, FilesOpenWithTheGeneratorAndReadableNames) {
    CodegenCase c = triple_pendulum_case();
    ScratchDir dir("header");
    CodegenOptions o{.name = "tp", .source = "examples/triple_pendulum/model.alb"};
    o.units = {{"L_A", "m"}};
    GeneratedCode g = generate_code(c.table(), c.equations, Language::c, dir.path(), o);
    ASSERT_EQ(g.files.size(), 2u);
    EXPECT_TRUE(g.symmetric_mass_matrix);
    EXPECT_GT(g.mass_forcing_operations, 0u);
    EXPECT_GT(g.prelude_operations, 0u);
    std::ifstream in(g.files[1]);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Generated by Alembert " + std::string(generator_version())),
              std::string::npos);
    EXPECT_NE(text.find("from examples/triple_pendulum/model.alb"), std::string::npos);
    EXPECT_NE(text.find("do not edit"), std::string::npos);
    EXPECT_NE(text.find("p->L_A = 0.4182; /* [m] */"), std::string::npos);
    EXPECT_NE(text.find("const double qAp = qp[0];"), std::string::npos);
    EXPECT_NE(text.find("const double z1 = "), std::string::npos);
    // nothing left behind by the atomic writes, and a second run replaces the files
    generate_code(c.table(), c.equations, Language::c, dir.path(), o);
    std::size_t count = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) {
        EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
        ++count;
    }
    EXPECT_EQ(count, 2u);
}

TEST(GenerateCode, BadRequestsFailWithClearMessages) {
    CodegenCase c = triple_pendulum_case();
    ScratchDir dir("errors");
    const SymbolTable& T = c.table();
    EXPECT_THROW_MSG(generate_code(T, c.equations, Language::c, dir.path(), {.name = "2link"}),
                     ArgumentError, "the name '2link' is not an identifier");
    write(dir.path() / "file", "x");
    EXPECT_THROW_MSG(generate_code(T, c.equations, Language::c, dir.path() / "file"),
                     ArgumentError, "exists and is not a directory");
    EXPECT_THROW_MSG(generate_code(T, c.equations, Language::c, dir.path() / "file" / "sub"),
                     ArgumentError, "cannot create the output directory");
    DynamicsEquations short_eq = c.equations;
    short_eq.residuals.pop_back();
    EXPECT_THROW_MSG(generate_code(T, short_eq, Language::c, dir.path()), ArgumentError,
                     "2 residuals for 3 coordinates");
    // a load left out of the list is a symbol the generated functions cannot take
    DynamicsEquations missing = c.equations;
    missing.loads.pop_back();
    EXPECT_THROW_MSG(generate_code(T, missing, Language::c, dir.path()), ArgumentError,
                     "the unknown 'T_C'");
    // a mass matrix for other unknowns than the accelerations
    CodegenCase e = planar_chain_case(2);
    std::swap(e.equations.mass_forcing->unknowns[0], e.equations.mass_forcing->unknowns[1]);
    EXPECT_THROW_MSG(generate_code(e.table(), e.equations, Language::c, dir.path()),
                     ArgumentError, "its unknowns differ at position 1");
    // a parameter needs a default
    CodegenCase d = planar_chain_case(2);
    SymbolTable& S = d.model->system.symbols();
    ex k = S.add_constant("k");
    d.equations.residuals[0] = d.equations.residuals[0] - k * d.model->q[0].symbol();
    d.equations.mass_forcing.reset();
    EXPECT_THROW_MSG(generate_code(S, d.equations, Language::c, dir.path()), ArgumentError,
                     "the constant 'k' has no value");
    EXPECT_THROW_MSG(parse_language("fortran"), ArgumentError,
                     "unknown language 'fortran'; use c, cpp, matlab or python");
    EXPECT_EQ(parse_language("C++"), Language::cpp);
    EXPECT_EQ(parse_language("octave"), Language::matlab);
}
