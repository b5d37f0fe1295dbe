// SPDX-License-Identifier: MIT
// The numeric statements against physics: simulate conserves a conservative model's energy and
// stops where the event crosses; inverse dynamics of a prescribed motion gives the static holding
// torques where the motion is at rest; generated code simulates as Alembert does.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>

#include "support/script_dir.hpp"
#include "alembert/error.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/integrator.hpp"
#include "alembert/sim/table.hpp"
#include "support/constants.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

using alembert::test::kDeg;

// Winter's segment data of the sit-to-stand example (examples/sit_to_stand/model.alb)
constexpr double g = 9.81, LA = 0.4182, LB = 0.4165, dA = 0.2371, dB = 0.2362, dC = 0.3065;
constexpr double mA = 6.51, mB = 14.00, mC = 47.46;

// the model statements of the sit-to-stand example (everything before its road-map)
std::string sit_to_stand_model() {
    std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/model.alb");
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.rfind("angvel", 0) == 0) break;
        out += line + "\n";
    }
    return out;
}

// a temporary directory named alembert-lang-...
struct TempDir : alembert::test::TempDir {
    TempDir() : alembert::test::TempDir("alembert-lang") {}
};

struct Script {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    explicit Script(const fs::path& dir) { interp.set_output_dir(dir.string()); }
    void run(const std::string& text) {
        ASSERT_EQ(interp.run(text, "test.alb"), RunStatus::ok) << err.str();
    }
};

// potential energy of the triple pendulum at rest (angles from n_y, right-handed about n_z)
double potential(double qA, double qB, double qC) {
    double yA = dA * std::cos(qA), yB = LA * std::cos(qA) + dB * std::cos(qA + qB),
           yC = LA * std::cos(qA) + LB * std::cos(qA + qB) + dC * std::cos(qA + qB + qC);
    return g * (mA * yA + mB * yB + mC * yC);
}

// the torques that hold the pendulum still against gravity (moments about each joint)
std::array<double, 3> holding(double qA, double qB, double qC) {
    double sA = std::sin(qA), sAB = std::sin(qA + qB), sABC = std::sin(qA + qB + qC);
    double TC = -g * mC * dC * sABC;
    double TB = -g * (mB * dB * sAB + mC * (LB * sAB + dC * sABC));
    double TA = -g * (mA * dA * sA + mB * (LA * sA + dB * sAB) + mC * (LA * sA + LB * sAB + dC * sABC));
    return {TA, TB, TC};
}

const std::string kFall =
    "initial qA = 20 deg, qB = -70 deg, qC = 60 deg\n"
    "final time 5 s\n"
    "output step 0.05 s\n"
    "tolerance abs 1e-12 rel 1e-12\n"
    "output qA in deg, height = dot(pos(Ccm, N_o), Ny>) in m\n";

}  // namespace

TEST(Simulate, TheTriplePendulumReleasedFromRestConservesItsEnergyOverFiveSeconds) {
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() + kFall + "simulate to \"fall\"\n");
    alembert::Table t = alembert::read_csv((dir.path / "fall/simulation.csv").string());
    ASSERT_EQ(t.row_count(), 101u);
    EXPECT_NEAR(t.columns[0].back(), 5.0, 1e-12);
    const std::vector<double>& E = t.columns[t.column_index("energy")];
    // at rest: all potential, computed here from the heights of the mass centres
    EXPECT_NEAR(E.front(), potential(20 * kDeg, -70 * kDeg, 60 * kDeg), 1e-9 * std::abs(E.front()));
    for (double e : E) EXPECT_NEAR(e, E.front(), 1e-9 * std::abs(E.front()));
    // the angle column is in degrees, the height in metres
    EXPECT_NEAR(t.columns[t.column_index("qA")].front(), 20.0, 1e-12);
    EXPECT_NEAR(t.columns[t.column_index("height")].front(),
                LA * std::cos(20 * kDeg) + LB * std::cos(-50 * kDeg) + dC * std::cos(10 * kDeg), 1e-12);
    EXPECT_NE(r.out.str().find("energy: 537.196 J at the start"), std::string::npos) << r.out.str();
}

TEST(Simulate, StopWhenEndsTheRunWhereTheExpressionCrossesAndCompiledCodeAgreesWithTheTape) {
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() + kFall + "stop when dot(pos(Ccm, N_o), Ny>) = 50 cm falling\n" +
          "simulate tape to \"tape\"\nsimulate to \"native\"\n");
    alembert::Table a = alembert::read_csv((dir.path / "tape/simulation.csv").string());
    alembert::Table b = alembert::read_csv((dir.path / "native/simulation.csv").string());
    const std::size_t h = a.column_index("height");
    EXPECT_NEAR(a.columns[h].back(), 0.5, 1e-9);
    EXPECT_LT(a.columns[0].back(), 5.0);
    // the height falls through 0.5 m once before the stop: every earlier row is above it
    for (std::size_t k = 0; k + 1 < a.row_count(); ++k) EXPECT_GT(a.columns[h][k], 0.5);
    ASSERT_EQ(a.row_count(), b.row_count());
    for (std::size_t c = 0; c < a.names.size(); ++c)
        for (std::size_t k = 0; k < a.row_count(); ++k)
            EXPECT_NEAR(a.columns[c][k], b.columns[c][k], 1e-9 * (1 + std::abs(a.columns[c][k])));
    EXPECT_NE(r.out.str().find("stopped when dot(pos(Ccm, N_o), Ny>) = 50 cm"), std::string::npos) << r.out.str();
}

// The environment variable `name` set to `value` for one scope, then restored.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

std::size_t libraries_in(const fs::path& dir) {
    std::size_t n = 0;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) n += e.path().extension() == ".so";
    return n;
}

TEST(Simulate, CompiledCodeIsTheDefaultTapeRunsNoCompilerAndEitherGivesTheSameMotion) {
    TempDir dir;
    const fs::path cache = dir.path / "tmp" / "alembert-native";
    fs::create_directories(dir.path / "tmp");
    ScopedEnv tmpdir("TMPDIR", (dir.path / "tmp").string());
    const std::string model = sit_to_stand_model() + kFall + "final time 1 s\n";
    {
        Script r(dir.path);
        r.run(model + "simulate tape to \"tape\"\n");
        EXPECT_EQ(libraries_in(cache), 0u) << "the tape ran a compiler";
    }
    Script r(dir.path);
    r.run(model + "simulate to \"default\"\n");
    EXPECT_GT(libraries_in(cache), 0u) << "the default compiled nothing";
    EXPECT_EQ(r.out.str().find("evaluated"), std::string::npos) << "compiled by default goes unsaid: " << r.out.str();
    alembert::Table a = alembert::read_csv((dir.path / "tape/simulation.csv").string());
    alembert::Table b = alembert::read_csv((dir.path / "default/simulation.csv").string());
    ASSERT_EQ(a.row_count(), b.row_count());
    for (std::size_t c = 0; c < a.names.size(); ++c)
        for (std::size_t k = 0; k < a.row_count(); ++k)
            EXPECT_NEAR(a.columns[c][k], b.columns[c][k], 1e-9 * (1 + std::abs(a.columns[c][k])));
    // (that a second run loads the cached library instead of compiling is for separate
    // processes: tests/lang/determinism_test.sh; a second model built in this process has new
    // symbols, so its code may differ in the order of terms)
    {
        // no compiler: the tape, and the transcript says why
        ScopedEnv cc("CC", "alembert-no-such-compiler");
        Script none(dir.path);
        none.run(model + "simulate to \"none\"\n");
        EXPECT_NE(none.out.str().find("evaluated on the tape, not compiled: NativeExpressions: no C compiler "
                                      "'alembert-no-such-compiler' found"),
                  std::string::npos)
            << none.out.str();
    }
    {
        // the run's default is the tape (alembert run --tape): a statement's `compiled` still compiles
        Script tape(dir.path);
        tape.interp.set_evaluation(Evaluation::tape);
        tape.run(model + "simulate to \"run_tape\"\nsimulate compiled to \"said\"\n");
        EXPECT_NE(tape.out.str().find("evaluated by compiled C code"), std::string::npos) << tape.out.str();
        EXPECT_EQ(tape.out.str().find("evaluated by compiled C code"), tape.out.str().rfind("evaluated by compiled C code"));
    }
    {
        // past the compile limit the default is the tape, and the transcript says how to compile
        Script big(dir.path);
        big.interp.set_compile_limit(10);
        big.run(model + "simulate to \"limit\"\n");
        EXPECT_NE(big.out.str().find("evaluated on the tape, not compiled: "), std::string::npos) << big.out.str();
        EXPECT_NE(big.out.str().find("operations take the C compiler tens of seconds (past 10 only on request): "
                                     "write 'compiled' to compile them once"),
                  std::string::npos)
            << big.out.str();
        alembert::Table c = alembert::read_csv((dir.path / "limit/simulation.csv").string());
        ASSERT_EQ(c.row_count(), a.row_count());
        for (std::size_t k = 0; k < a.row_count(); ++k)
            EXPECT_NEAR(c.columns[1][k], a.columns[1][k], 1e-9 * (1 + std::abs(a.columns[1][k])));
    }
    Script both(dir.path);
    EXPECT_EQ(both.interp.run(model + "simulate compiled tape\n", "test.alb"), RunStatus::script_error);
    EXPECT_NE(both.err.str().find("'compiled' and 'tape' both given"), std::string::npos) << both.err.str();
}

TEST(Simulate, TheIntegratorStatementChoosesTheMethodAndEachFindsTheSameStop) {
    if (!alembert::integrator_available(alembert::Integrator::bdf))
        GTEST_SKIP() << "built without SUNDIALS CVODE (the bdf integrator)";
    // the fall of the sit-to-stand model stopped where the head-arms-trunk centre passes 50 cm:
    // Dormand-Prince, Fehlberg 7(8) and BDF at tight tolerances find one stop and one path
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() + kFall + "stop when dot(pos(Ccm, N_o), Ny>) = 50 cm falling\n" +
          "simulate to \"dopri5\"\nintegrator rkf78\nsimulate to \"rkf78\"\n" +
          "integrator bdf\ntolerance abs 1e-11 rel 1e-11\nsimulate to \"bdf\"\n");
    alembert::Table a = alembert::read_csv((dir.path / "dopri5/simulation.csv").string());
    for (const char* method : {"rkf78", "bdf"}) {
        alembert::Table b = alembert::read_csv((dir.path / method / "simulation.csv").string());
        ASSERT_EQ(a.row_count(), b.row_count()) << method;
        const double tol = std::string(method) == "bdf" ? 1e-6 : 1e-9;
        EXPECT_NEAR(a.columns[0].back(), b.columns[0].back(), tol) << method;
        const std::size_t E = b.column_index("energy");
        for (std::size_t k = 0; k < b.row_count(); ++k)
            EXPECT_NEAR(b.columns[E][k], b.columns[E].front(), 10 * tol * std::abs(b.columns[E].front())) << method;
        for (std::size_t c = 0; c < a.names.size(); ++c)
            for (std::size_t k = 0; k < a.row_count(); ++k)
                EXPECT_NEAR(a.columns[c][k], b.columns[c][k], tol * (1 + std::abs(a.columns[c][k]))) << method;
    }
    EXPECT_NE(r.out.str().find("integrated by rkf78 in "), std::string::npos) << r.out.str();
    EXPECT_NE(r.out.str().find("integrated by bdf in "), std::string::npos) << r.out.str();
}

TEST(Simulate, AMotorLawActsAsTheScriptWritesIt) {
    // a mass on a spring driven by F = -k x (input) is the same oscillator as k alone:
    // x(t) = x0 cos(w t), w = sqrt(2 k / m) with both the spring and the law
    TempDir dir;
    Script r(dir.path);
    r.run("newtonian N\nparticle Q\nvariable x'' m\nconstant k = 10 N/m, m = 2 kg\nunknown F N\n"
          "mass Q = m\ntranslate Q from N_o by x*Nx>\nforce push on Q = F*Nx>\n"
          "spring s between Q and N_o stiffness k length 0\n"
          "input F = -k*x\ninitial x = 10 cm\nfinal time 3 s\noutput step 0.5 s\n"
          "tolerance abs 1e-12 rel 1e-12\noutput x in mm, F in N\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    const double w = std::sqrt(2 * 10.0 / 2.0);
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        double time = t.columns[0][k], x = 0.1 * std::cos(w * time);
        EXPECT_NEAR(t.columns[1][k], 1000 * x, 1e-6) << "t = " << time;
        EXPECT_NEAR(t.columns[2][k], -10.0 * x, 1e-8) << "t = " << time;
    }
    // the input makes the model non-conservative as the checks see it: no energy column
    EXPECT_THROW(t.column_index("energy"), alembert::ArgumentError);
}

TEST(Simulate, AConstraintsDriftIsReportedInTheUnitOfItsResidual) {
    // a pendulum as a particle held on the circle x^2 + y^2 = L^2 by a rod force F
    TempDir dir;
    Script r(dir.path);
    r.run("newtonian N\nparticle P\nconstant L = 0.5 m, m = 1 kg, g = 9.81 m/s^2\n"
          "variable x'' m, y'' m\nunknown F N\nmass P = m\ntranslate P from N_o by x*Nx> + y*Ny>\n"
          "gravity -g*Ny>\nforce rod on P = F*(x*Nx> + y*Ny>)/L\n"
          "constraint configuration circle = x^2 + y^2 - L^2\n"
          "initial x = 0.5 m, y = 0 m\ntolerance abs 1e-12 rel 1e-12\nfinal time 1 s\n"
          "output step 0.1 s\nsimulate\n");
    alembert::Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    const std::size_t c = t.column_index("drift_circle");
    EXPECT_EQ(t.units[c], "m^2");
    for (double v : t.columns[c]) EXPECT_LT(std::abs(v), 1e-8);
    EXPECT_NE(r.out.str().find("constraint circle: largest residual below 1e-"), std::string::npos) << r.out.str();
    EXPECT_NE(r.out.str().find(" m^2\n"), std::string::npos) << r.out.str();
    // its energy stays near zero: the change is stated in J, not as "below 1e1 of its largest value"
    EXPECT_NE(r.out.str().find("energy: 0 J at the start; its largest change is below 1e-"), std::string::npos)
        << r.out.str();
    EXPECT_EQ(r.out.str().find("of its largest value"), std::string::npos) << r.out.str();
}

TEST(Inverse, APrescribedMotionNeedsTheStaticHoldingTorquesWhereItIsAtRest) {
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() +
          "motion qA = (-25 + 20*minimum_jerk(t, 0.15, 1.5)) deg, "
          "qB = (105 - 95*minimum_jerk(t, 0, 1.5)) deg, qC = (-130 + 120*minimum_jerk(t, 0, 1.5)) deg\n"
          "final time 1.5 s\noutput step 0.01 s\ninverse for T_A, T_B, T_C\n");
    alembert::Table t = alembert::read_csv((dir.path / "torques.csv").string());
    ASSERT_EQ(t.row_count(), 151u);
    EXPECT_EQ(t.names, (std::vector<std::string>{"t", "T_A", "T_B", "T_C"}));
    EXPECT_EQ(t.units[1], "N*m");
    auto seat = holding(-25 * kDeg, 105 * kDeg, -130 * kDeg), stand = holding(-5 * kDeg, 10 * kDeg, -10 * kDeg);
    for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(t.columns[static_cast<std::size_t>(j + 1)].front(), seat[static_cast<std::size_t>(j)], 1e-9);
        EXPECT_NEAR(t.columns[static_cast<std::size_t>(j + 1)].back(), stand[static_cast<std::size_t>(j)], 1e-9);
    }
    EXPECT_TRUE(fs::exists(dir.path / "torques.png"));
    EXPECT_NE(r.out.str().find("inverse dynamics over the prescribed motion"), std::string::npos);
}

TEST(Inverse, ForcesGoToForcesCsvUnderTheirOwnNames) {
    // a 2 kg particle moved as x = A sin(w t) needs F_x = m x'' = -m A w^2 sin(w t)
    TempDir dir;
    Script r(dir.path);
    r.run("newtonian N\nparticle Q\nvariable x'' m\nconstant m = 2 kg, A = 0.1 m, w = 3 rad/s\n"
          "unknown F_x N\nmass Q = m\ntranslate Q from N_o by x*Nx>\nforce push on Q = F_x*Nx>\n"
          "motion x = A*sin(w*t)\nfinal time 1 s\noutput step 0.1 s\ninverse for F_x\n");
    EXPECT_FALSE(fs::exists(dir.path / "torques.csv"));
    alembert::Table t = alembert::read_csv((dir.path / "forces.csv").string());
    EXPECT_EQ(t.names, (std::vector<std::string>{"t", "F_x"}));
    EXPECT_EQ(t.units[1], "N");
    for (std::size_t k = 0; k < t.row_count(); ++k)
        EXPECT_NEAR(t.columns[1][k], -2 * 0.1 * 9 * std::sin(3 * t.columns[0][k]), 1e-10);  // 12 digits in the CSV
    EXPECT_NE(r.out.str().find("wrote forces.csv"), std::string::npos) << r.out.str();
}

TEST(Inverse, SampledMotionDataReproduceTheFormulaTorquesAwayFromTheEnds) {
    // the shipped 100 Hz table of the same motion, filtered at 6 Hz and differentiated: within
    // 3 % of each torque's peak on [0.2, 1.3] s (the tolerance of the sim layer's own check)
    TempDir dir;
    Script r(dir.path);
    std::string data = (fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand_inverse/motion.csv").string();
    r.run(sit_to_stand_model() +
          "motion qA = (-25 + 20*minimum_jerk(t, 0.15, 1.5)) deg, "
          "qB = (105 - 95*minimum_jerk(t, 0, 1.5)) deg, qC = (-130 + 120*minimum_jerk(t, 0, 1.5)) deg\n"
          "final time 1.5 s\noutput step 0.01 s\ninverse for T_A, T_B, T_C to \"exact\"\n"
          "inverse for T_A, T_B, T_C from \"" + data + "\" cutoff 6 Hz compiled to \"data\"\n");
    alembert::Table exact = alembert::read_csv((dir.path / "exact/torques.csv").string());
    alembert::Table data_t = alembert::read_csv((dir.path / "data/torques.csv").string());
    ASSERT_EQ(exact.row_count(), data_t.row_count());
    for (std::size_t c = 1; c < 4; ++c) {
        double peak = 0;
        for (double x : exact.columns[c]) peak = std::max(peak, std::abs(x));
        for (std::size_t k = 0; k < exact.row_count(); ++k) {
            double time = exact.columns[0][k];
            if (time < 0.2 || time > 1.3) continue;
            EXPECT_NEAR(data_t.columns[c][k], exact.columns[c][k], 0.03 * peak) << exact.names[c] << " at " << time;
        }
    }
}

TEST(Codegen, JointReactionsAreLoadsOfTheGeneratedInverseDynamics) {
    // 3 torques and the 6 joint forces of the sit-to-stand model for 3 coordinates: inverse
    // dynamics from the road-map rows (tests/codegen checks its numbers against the evaluator)
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() +
          "codegen c name sts for T_A, T_B, T_C, F_Ac, F_As, F_Kc, F_Ks, F_Hc, F_Hs to \"gen\"\n");
    EXPECT_NE(r.out.str().find(", inverse dynamics"), std::string::npos) << r.out.str();
    std::ifstream h(dir.path / "gen" / "sts.h");
    std::string header((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
    EXPECT_NE(header.find("sts_inverse_dynamics"), std::string::npos) << header;
    EXPECT_NE(header.find("F_Kc"), std::string::npos) << header;
}

TEST(Codegen, TheStatementWritesCodeWhoseSimulationProgramFollowsAlembertsSimulation) {
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() + kFall + "codegen c name fall to \"gen\"\nsimulate to \"sim\"\n");
    for (const char* f : {"fall.h", "fall.c", "fall_main.c"}) EXPECT_TRUE(fs::exists(dir.path / "gen" / f)) << f;
    // compile and run the generated simulation program; it writes its CSV to the path given
    const fs::path exe = dir.path / "fall_sim", csv = dir.path / "gen.csv";
    std::string cc = "cc -O1 -std=c99 -o '" + exe.string() + "' '" + (dir.path / "gen/fall.c").string() + "' '" +
                     (dir.path / "gen/fall_main.c").string() + "' -lm";
    ASSERT_EQ(std::system(cc.c_str()), 0) << cc;
    ASSERT_EQ(std::system(("'" + exe.string() + "' '" + csv.string() + "'").c_str()), 0);
    alembert::Table ours = alembert::read_csv((dir.path / "sim/simulation.csv").string());
    alembert::Table gen = alembert::read_csv(csv.string());
    ASSERT_EQ(gen.row_count(), ours.row_count());
    // both integrate at tolerance 1e-12 from the script's initial values (Dormand-Prince each,
    // with different step-size controllers). The released triple pendulum is chaotic: nearby
    // solutions separate by orders of magnitude within seconds, so they are compared over the
    // first two seconds, where both are accurate far below 1e-6 rad
    const std::size_t qa = gen.column_index("qA");
    for (std::size_t k = 0; k <= 40; k += 5)
        EXPECT_NEAR(gen.columns[qa][k], ours.columns[ours.column_index("qA")][k] * kDeg, 1e-6) << "row " << k;
}

TEST(Digits, SolvePrintsTheDigitsAskedForAndSeventeenReadBackAsTheHoldingTorque) {
    TempDir dir;
    Script s(dir.path);
    const std::string at =
        " at qA = 20 deg, qB = -70 deg, qC = 60 deg, qA' = 0, qB' = 0, qC' = 0, qA'' = 0, "
        "qB'' = 0, qC'' = 0\n";
    const std::string solve = "solve E for T_A, T_B, T_C";
    s.run(sit_to_stand_model() + "roadmap E for T_A, T_B, T_C\n" + solve + at + "digits 12\n" +
          solve + at + "digits 17\n" + solve + at);
    // the three answers, in order, as printed: "T_A = <number> N*m"
    std::vector<std::string> printed;
    std::istringstream lines(s.out.str());
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("T_A = ", 0) == 0) printed.push_back(line.substr(6, line.find(' ', 6) - 6));
    ASSERT_EQ(printed.size(), 3u) << s.out.str();
    auto significant = [](const std::string& t) {
        std::string d;
        for (char c : t) if (std::isdigit(static_cast<unsigned char>(c))) d += c;
        return d.size() - std::min(d.find_first_not_of('0'), d.size());
    };
    EXPECT_EQ(significant(printed[0]), 6u) << printed[0];
    EXPECT_EQ(significant(printed[1]), 12u) << printed[1];
    EXPECT_GE(significant(printed[2]), 16u) << printed[2];
    // each agrees with the hand statics to the digits it shows
    const double T_A = holding(20 * kDeg, -70 * kDeg, 60 * kDeg)[0];
    EXPECT_NEAR(std::stod(printed[0]), T_A, 1e-5 * std::fabs(T_A));
    EXPECT_NEAR(std::stod(printed[1]), T_A, 1e-11 * std::fabs(T_A));
    EXPECT_NEAR(std::stod(printed[2]), T_A, 1e-13 * std::fabs(T_A));
}

TEST(Digits, OnlyWholeNumbersFromOneToSeventeen) {
    for (const char* bad : {"digits 0", "digits 18", "digits 2.5", "digits 6 m"}) {
        std::ostringstream out, err;
        Interpreter interp(out, err, false);
        EXPECT_EQ(interp.run(std::string(bad) + "\n", "t.alb"), RunStatus::script_error) << bad;
    }
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    EXPECT_THROW(interp.set_digits(18), alembert::ArgumentError);
    interp.set_digits(3);
    ASSERT_EQ(interp.run("newtonian N\nconstant a = 2\nevaluate sqrt(a)\n", "t.alb"), RunStatus::ok);
    EXPECT_EQ(out.str(), "= 1.41\n");
}

TEST(Report, TheStatementDrawsTheRoadmapAtTheGivenConfigurationAndAnimatesTheSimulation) {
    TempDir dir;
    Script r(dir.path);
    const std::string before = sit_to_stand_model() + "roadmap E for T_A, T_B, T_C\n"
          "initial qA = 20 deg, qB = -70 deg, qC = 60 deg\nfinal time 0.2 s\noutput step 0.05 s\n";
    const std::string simulate_line = std::to_string(std::count(before.begin(), before.end(), '\n') + 1);
    r.run(before + "simulate to \"fall\"\nreport at qA = 10 deg to \"rep\"\n");
    EXPECT_NE(r.out.str().find("wrote rep/index.html"), std::string::npos) << r.out.str();
    std::ifstream in(dir.path / "rep" / "index.html");
    std::stringstream page;
    page << in.rdbuf();
    const std::string html = page.str();
    // qA as given, qB and qC from the first sample of the motion (SI), shown in degrees (the
    // coordinates have no declared unit and turn frames: angles), and the page says where
    // that is from
    EXPECT_NE(html.find("\"configuration\":[{\"name\":\"qA\",\"value\":0.174533,\"shown\":10,\"unit\":\"deg\"},"
                        "{\"name\":\"qB\",\"value\":-1.22173,\"shown\":-70,\"unit\":\"deg\"},"
                        "{\"name\":\"qC\",\"value\":1.0472,\"shown\":60,\"unit\":\"deg\"}],"
                        "\"configuration_source\":\"given with report at, the other coordinates from the first sample of "
                        "simulate at line " + simulate_line + " (fall/simulation.csv)\""),
              std::string::npos) << html.substr(html.find("\"configuration\":"), 400);
    EXPECT_NE(html.find("\"animation\":{\"source\":\"simulate at line " + simulate_line + " (fall/simulation.csv)\""),
              std::string::npos);
    EXPECT_NE(html.find("{\"variable\":\"T_B\""), std::string::npos);
}

// Three runs of one script are told apart on the page: each history's title names its
// statement, the statement's line (counted here from the script's text) and the table it wrote
// relative to the output directory; inverse's table is named by its loads' kind (torques.csv).
TEST(Report, EachHistoryIsTitledByItsStatementLineAndTable) {
    TempDir dir;
    Script r(dir.path);
    const std::string model = sit_to_stand_model();
    const int first = static_cast<int>(std::count(model.begin(), model.end(), '\n')) + 1;
    r.run(model +
          "initial qA = 20 deg, qB = -70 deg, qC = 60 deg\nfinal time 0.1 s\noutput step 0.05 s\n"  // first..first+2
          "simulate to \"a\"\n"                                                                  // first+3
          "initial qA = 10 deg\nsimulate to \"b/c\"\n"                                           // first+5
          "simulate\n"                                                                           // first+6
          "motion qA = 10 deg, qB = -70 deg, qC = 60 deg\ninverse for T_A, T_B, T_C to \"inv\"\n"  // first+8
          "report to \"rep\"\n");
    std::ifstream in(dir.path / "rep" / "index.html");
    std::stringstream page;
    page << in.rdbuf();
    const std::string html = page.str();
    const auto title = [&](const std::string& statement, int line, const std::string& file) {
        return "\"title\":\"" + statement + " at line " + std::to_string(line) + " (" + file + ")\",\"line\":" +
               std::to_string(line) + ",\"file\":\"" + file + "\"";
    };
    EXPECT_NE(html.find(title("simulate", first + 3, "a/simulation.csv")), std::string::npos);
    EXPECT_NE(html.find(title("simulate", first + 5, "b/c/simulation.csv")), std::string::npos);
    EXPECT_NE(html.find(title("simulate", first + 6, "simulation.csv")), std::string::npos);
    EXPECT_NE(html.find(title("inverse", first + 8, "inv/torques.csv")), std::string::npos)
        << html.substr(html.find("\"histories\":"), 300);
    // the page's <title> is the model's name: a script given as text, not read from a file,
    // is named "model"
    EXPECT_NE(html.find("<title>model</title>"), std::string::npos);
}

TEST(Report, AtNamesCoordinatesOnly) {
    TempDir dir;
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(dir.path.string());
    EXPECT_EQ(interp.run(sit_to_stand_model() + "report at T_A = 1 N*m\n", "test.alb"), RunStatus::script_error);
    EXPECT_NE(err.str().find("'T_A' is not a coordinate or rate"), std::string::npos) << err.str();
    EXPECT_NE(err.str().find("report at qA = 20 deg"), std::string::npos) << err.str();
}

TEST(Report, AModelThePlannerCannotPlanGetsANoteInsteadOfARoadmap) {
    TempDir dir;
    Script r(dir.path);
    // a body on a helix (turning about Nz> while its centre rises along it): no point of A is
    // fixed, and its motion is a screw, so it has no instantaneous centre either
    r.run("newtonian N\nbody A\nvariable q'\nconstant L = 1 m, m = 1 kg, I = 1 kg*m^2, g = 9.81 m/s^2\n"
          "rotate A from N about z by q\ntranslate Acm from N_o by L*Ay> + q*L*Nz>\nmass A = m\ninertia A = 0, 0, I\n"
          "gravity -g*Ny>\nreport\n");
    std::ifstream in(dir.path / "index.html");
    std::stringstream page;
    page << in.rdbuf();
    EXPECT_NE(page.str().find("\"notes\":[\"No road-map: the script forms none and planning one failed: "),
              std::string::npos);
    EXPECT_EQ(page.str().find("plan_roadmap()"), std::string::npos) << "a C++ name in a script's report";
    EXPECT_NE(page.str().find("; form one in the script (roadmap E for ...) to see it here.\"]"), std::string::npos);
    EXPECT_NE(page.str().find("\"roadmap\":[]"), std::string::npos);
}

TEST(Codegen, JacobianClauseGeneratesAPointsAndABodysJacobians) {
    // a body's frame Jacobian at its origin (C_o) and a point's Jacobian, three functions each;
    // the sit-to-stand model is a tree, so M alone and the bias forces come too
    TempDir dir;
    Script r(dir.path);
    r.run(sit_to_stand_model() + "codegen c name sts jacobian C, C_o to \"gen\"\n");
    std::ifstream h(dir.path / "gen" / "sts.h");
    std::string header((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
    for (const char* f : {"sts_C_position(", "sts_C_jacobian(", "sts_C_jacobian_dot_rates(",
                          "sts_C_o_jacobian(", "sts_mass_matrix(", "sts_bias_forces("})
        EXPECT_NE(header.find(f), std::string::npos) << f << " in\n" << header;
}

namespace {

// the falling triple pendulum's model (torques T_A, T_B, T_C, no joint reactions)
std::string falling_triple_pendulum_model() {
    std::ifstream in(fs::path(ALEMBERT_SOURCE_DIR) / "examples/triple_pendulum_fall/model.alb");
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.rfind("# released", 0) == 0) break;
        out += line + "\n";
    }
    return out;
}

}  // namespace

TEST(Codegen, DerivativesClauseGeneratesInverseAndForwardDynamicsDerivatives) {
    TempDir dir;
    Script r(dir.path);
    r.run(falling_triple_pendulum_model() + "codegen c name sts derivatives to \"gen\"\n");
    std::ifstream h(dir.path / "gen" / "sts.h");
    std::string header((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
    for (const char* f : {"void sts_inverse_dynamics_derivatives(const sts_context* c, double t, "
                          "const double* q, const double* qp, const double* qpp, double* dtau_dq, "
                          "double* dtau_dqp);",
                          "int sts_forward_dynamics_derivatives(const sts_context* c, double t, "
                          "const double* q, const double* qp, const double* u,\n    double* qpp, "
                          "double* dqpp_dq, double* dqpp_dqp);"})
        EXPECT_NE(header.find(f), std::string::npos) << f << " in\n" << header;
    EXPECT_NE(r.out.str().find("derivatives of inverse and forward dynamics"), std::string::npos)
        << r.out.str();
}

TEST(Codegen, DerivativesClauseNamesTheLoadsThatDoNotFit) {
    // the joint reactions among the loads: 9 loads for 3 coordinates
    TempDir dir;
    Script r(dir.path);
    EXPECT_NE(r.interp.run(sit_to_stand_model() + "codegen c name sts derivatives to \"gen\"\n",
                           "test.alb"),
              RunStatus::ok);
    EXPECT_NE(r.err.str().find("derivatives need one load per coordinate (9 loads for 3 coordinates)"),
              std::string::npos)
        << r.err.str();
}

TEST(Codegen, JacobianClauseNamesWhatIsNeitherAPointNorABody) {
    TempDir dir;
    Script r(dir.path);
    EXPECT_NE(r.interp.run(sit_to_stand_model() + "codegen c name sts jacobian nowhere to \"gen\"\n",
                           "test.alb"),
              RunStatus::ok);
    EXPECT_NE(r.err.str().find("'nowhere' is neither a point nor a rigid body"), std::string::npos)
        << r.err.str();
}
