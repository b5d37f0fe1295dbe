// SPDX-License-Identifier: MIT
// Joint reactions in generated simulation programs (issue 24): the programs a script's
// `codegen` writes compute each declared reaction measure at every sample from its road-map
// rows, checked row by row against Newton's law written out by hand; the library function
// NAME_reactions at chosen states; each CSV column once; the same files from run to run.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../codegen/drivers.hpp"
#include "../codegen/harness.hpp"
#include "alembert/lang/interpreter.hpp"

// a named namespace: the unity build joins this file with others that have their own helpers
namespace codegen_reactions {

namespace {

using alembert::test::csv_rows;
using alembert::test::numbers;
using alembert::test::run;
using alembert::test::ScratchDir;
namespace fs = std::filesystem;

// Debian's interpreter (a pyenv shim may come first on PATH without NumPy)
const char* kPython = "/usr/bin/python3";

std::string c_compiler() {
    const char* cc = std::getenv("CC");
    return cc && *cc ? cc : "cc";
}

bool has_program(const std::string& command) {
    std::string out;
    return run(command, out) == 0;
}

// runs `script` with its files written under `dir`
void run_script(const std::string& script, const fs::path& dir) {
    std::ostringstream out, err;
    alembert::lang::Interpreter interp(out, err, false);
    interp.set_output_dir(dir.string());
    ASSERT_EQ(interp.run(script, "reactions.alb"), alembert::lang::RunStatus::ok) << err.str();
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// compiles NAME.c (or .cpp) and NAME_main in `dir` and runs the program, which writes NAME.csv
void compile_and_simulate(const fs::path& dir, const std::string& name, bool cpp) {
    const std::string command =
        cpp ? "c++ -std=c++17 -Wall -Wextra -Werror -O2 " + name + ".cpp " + name + "_main.cpp"
            : c_compiler() + " -std=c99 -pedantic -Wall -Wextra -Werror -O2 " + name + ".c " + name +
                  "_main.c -lm";
    std::string out;
    ASSERT_EQ(run("cd " + dir.string() + " && " + command + " -o sim && ./sim", out), 0)
        << "compiling or running the generated program failed:\n" << out;
}

// ---- the pendulum -----------------------------------------------------------------------
// A particle of mass m at distance L below a pin at N_o on a massless rod A turned by q about
// Nz; the pin's force on A is declared as the reaction R = Rx Nx + Ry Ny. By hand: the
// particle at r = L sin q Nx - L cos q Ny has
//   a = L q'' (cos q Nx + sin q Ny) + L q'^2 (-sin q Nx + cos q Ny),
// the moment about the pin gives q'' = -(g/L) sin q, and Newton's law R - m g Ny = m a gives
//   Rx = m L (q'' cos q - q'^2 sin q),  Ry = m L (q'' sin q + q'^2 cos q) + m g.
constexpr double m = 2, L = 1, g = 9.81;
const std::string kPendulum =
    "newtonian N\nbody A\nvariable q''\nconstant m = 2 kg, L = 1 m, g = 9.81 m/s^2\n"
    "coordinates q\nunknown Rx N, Ry N\nrotate A from N about z by q\n"
    "translate A_o from N_o by 0>\ntranslate Acm from A_o by -L*Ay>\nmass A = m\n"
    "inertia A = 0, 0, 0\ngravity -g*Ny>\n"
    "reaction pin between N and A at A_o force Rx along Nx>, Ry along Ny>\n"
    "initial q = 60 deg\nfinal time 2 s\noutput step 0.1 s\noutput q, Rx, Ry\n";

double pendulum_Rx(double q, double w, double a) { return m * L * (a * std::cos(q) - w * w * std::sin(q)); }
double pendulum_Ry(double q, double w, double a) {
    return m * L * (a * std::sin(q) + w * w * std::cos(q)) + m * g;
}

// |got - want| within 1e-12 of the larger of 1 and |want|
void expect_close(double got, double want, const char* what) {
    EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::fabs(want))) << what;
}

// every row of a pendulum CSV (t, q, q', Rx, Ry) against the hand formulas at its q and q'
void expect_pendulum_rows(const fs::path& csv) {
    std::string header;
    const std::vector<std::vector<double>> rows = csv_rows(csv, &header);
    // each column once: the loads are columns, so the outputs naming them add none
    EXPECT_EQ(header, "t [s],q,q',Rx [N],Ry [N]");
    ASSERT_EQ(rows.size(), 21u);
    double largest_speed = 0;
    for (const std::vector<double>& r : rows) {
        ASSERT_EQ(r.size(), 5u);
        SCOPED_TRACE("t = " + std::to_string(r[0]));
        const double q = r[1], w = r[2], a = -(g / L) * std::sin(q);
        expect_close(r[3], pendulum_Rx(q, w, a), "Rx");
        expect_close(r[4], pendulum_Ry(q, w, a), "Ry");
        largest_speed = std::max(largest_speed, std::fabs(w));
    }
    EXPECT_GT(largest_speed, 2.0);  // it swings: the q'^2 terms are tested, not only the weight
}

// ---- the two-link arm -------------------------------------------------------------------
// Link A turned by q1 about Nz at the shoulder N_o, mass centre a1 down A (-Ay), link B turned
// by q2 relative to A at the elbow B_o = L1 down A, mass centre b down B; central inertias IA,
// IB about z; a motor at the elbow, T = T0 cos(w t) on B from A; the pins' forces declared as
// reactions S (on A from N) and E (on B from A). By hand, with th2 = q1 + q2:
//   p_Acm = a1 (sin q1, -cos q1),  p_Bcm = L1 (sin q1, -cos q1) + b (sin th2, -cos th2),
// and a point at l (sin th, -cos th) accelerates at l th'' (cos th, sin th) + l th'^2 (-sin th,
// cos th). Lagrange's equations, h = mB L1 b sin q2:
//   M11 = IA + mA a1^2 + IB + mB (L1^2 + b^2 + 2 L1 b cos q2),  M12 = IB + mB (b^2 + L1 b cos q2),
//   M22 = IB + mB b^2,
//   f1 = h (2 q1' q2' + q2'^2) - (mA a1 + mB L1) g sin q1 - mB b g sin th2,
//   f2 = -h q1'^2 - mB b g sin th2 + T  (the motor's torque pair does no work through q1),
// M q'' = f; then Newton's law for B alone and for A and B together:
//   E = mB a_Bcm + mB g Ny,  S = mA a_Acm + mB a_Bcm + (mA + mB) g Ny.
constexpr double mA = 1.5, mB = 0.8, L1 = 0.7, a1 = 0.3, b = 0.4, IA = 0.05, IB = 0.02, T0 = 0.5,
                 w_T = 3;
const std::string kArm =
    "newtonian N\nbody A\nbody B\nvariable q1'', q2''\n"
    "constant mA = 1.5 kg, mB = 0.8 kg, L1 = 0.7 m, a1 = 0.3 m, b = 0.4 m\n"
    "constant IA = 0.05 kg*m^2, IB = 0.02 kg*m^2, g = 9.81 m/s^2, T0 = 0.5 N*m, w = 3 rad/s\n"
    "unknown Sx N, Sy N, Ex N, Ey N, T N*m\n"
    "rotate A from N about z by q1\nrotate B from A about z by q2\n"
    "translate A_o from N_o by 0>\ntranslate Acm from A_o by -a1*Ay>\n"
    "translate B_o from A_o by -L1*Ay>\ntranslate Bcm from B_o by -b*By>\n"
    "mass A = mA\nmass B = mB\ninertia A = 0, 0, IA\ninertia B = 0, 0, IB\ngravity -g*Ny>\n"
    "torque motor on B from A = T*Nz>\n"
    "reaction shoulder between N and A at A_o force Sx along Nx>, Sy along Ny>\n"
    "reaction elbow between A and B at B_o force Ex along Nx>, Ey along Ny>\n"
    "input T = T0*cos(w*t)\n"
    "initial q1 = 70 deg, q2 = -40 deg, q1' = 1 rad/s\nfinal time 2 s\noutput step 0.1 s\n"
    "output q1, Ex, Ey, Sx, Sy\n";

// The same arm with B turned by q2 from N (absolute angles, not a tree in relative
// coordinates: Kane's equations with their mass matrix, not the recursion). With th2 = q2 and
// c = mB L1 b, the same Lagrangian gives
//   (IA + mA a1^2 + mB L1^2) q1'' + c cos(q1 - q2) q2'' = -c sin(q1 - q2) q2'^2
//                                                         - (mA a1 + mB L1) g sin q1 - T,
//   c cos(q1 - q2) q1'' + (IB + mB b^2) q2'' = c sin(q1 - q2) q1'^2 - mB b g sin q2 + T
// (the motor's pair, T on B and -T on A, works through q2' - q1'), and the same Newton's law.
const std::string kArmAbsolute = [] {
    std::string s = kArm;
    s.replace(s.find("rotate B from A"), 15, "rotate B from N");
    s.replace(s.find("q2 = -40 deg"), 12, "q2 = 30 deg");
    return s;
}();

struct ArmForces {
    double Sx, Sy, Ex, Ey;
};

// the hand formulas above at (q1, q2, q1', q2') with the motor's torque T
ArmForces arm_forces(double q1, double q2, double d1, double d2, double T, bool absolute) {
    double th2, d_th2, dd1, dd2;
    if (!absolute) {
        const double h = mB * L1 * b * std::sin(q2);
        th2 = q1 + q2;
        const double M11 = IA + mA * a1 * a1 + IB + mB * (L1 * L1 + b * b + 2 * L1 * b * std::cos(q2));
        const double M12 = IB + mB * (b * b + L1 * b * std::cos(q2)), M22 = IB + mB * b * b;
        const double f1 = h * (2 * d1 * d2 + d2 * d2) - (mA * a1 + mB * L1) * g * std::sin(q1) -
                          mB * b * g * std::sin(th2);
        const double f2 = -h * d1 * d1 - mB * b * g * std::sin(th2) + T;
        const double det = M11 * M22 - M12 * M12;
        dd1 = (M22 * f1 - M12 * f2) / det, dd2 = (M11 * f2 - M12 * f1) / det;
        d_th2 = d1 + d2;
    } else {
        const double c = mB * L1 * b;
        th2 = q2;
        const double M11 = IA + mA * a1 * a1 + mB * L1 * L1, M12 = c * std::cos(q1 - q2),
                     M22 = IB + mB * b * b;
        const double f1 = -c * std::sin(q1 - q2) * d2 * d2 - (mA * a1 + mB * L1) * g * std::sin(q1) - T;
        const double f2 = c * std::sin(q1 - q2) * d1 * d1 - mB * b * g * std::sin(q2) + T;
        const double det = M11 * M22 - M12 * M12;
        dd1 = (M22 * f1 - M12 * f2) / det, dd2 = (M11 * f2 - M12 * f1) / det;
        d_th2 = d2;
    }
    const double dd_th2 = absolute ? dd2 : dd1 + dd2;
    // l th'' (cos th, sin th) + l th'^2 (-sin th, cos th)
    auto ax = [](double l, double th, double d, double dd) {
        return l * dd * std::cos(th) - l * d * d * std::sin(th);
    };
    auto ay = [](double l, double th, double d, double dd) {
        return l * dd * std::sin(th) + l * d * d * std::cos(th);
    };
    const double aAx = ax(a1, q1, d1, dd1), aAy = ay(a1, q1, d1, dd1);
    const double aBx = ax(L1, q1, d1, dd1) + ax(b, th2, d_th2, dd_th2);
    const double aBy = ay(L1, q1, d1, dd1) + ay(b, th2, d_th2, dd_th2);
    return {mA * aAx + mB * aBx, mA * aAy + mB * aBy + (mA + mB) * g, mB * aBx, mB * aBy + mB * g};
}

// ---- sit-to-stand ------------------------------------------------------------------------
// examples/sit_to_stand: shank A, thigh B and trunk C in the plane, turned by qA about Nz at
// the ankle A_o (fixed), qB at the knee B_o, qC at the hip C_o, each segment along its y axis;
// joint reactions declared at the three joints. With absolute angles thA = qA, thB = thA + qB,
// thC = thB + qC and e(th) = (-sin th, cos th) (a body's y axis):
//   p_Acm = d_A e(thA),  p_Bcm = L_A e(thA) + d_B e(thB),  p_Ccm = L_A e(thA) + L_B e(thB) + d_C e(thC),
// and l e(th) accelerates at l (th'' (-cos th, -sin th) - th'^2 e(th)). Moments about each
// joint O of the bodies beyond it (the joint's reaction force acts at O, gravity -g Ny):
//   T_O = sum over those bodies of I alpha + ((p - p_O) x m (a + g Ny)) . Nz,
// the knee's and hip's points moving (the moment equation about any point with the mass
// centres' accelerations).
struct Segment {
    double m, I;
};
constexpr Segment kShank{6.51, 0.1038}, kThigh{14.00, 0.2534}, kTrunk{47.46, 2.799};
constexpr double kLA = 0.4182, kLB = 0.4165, kdA = 0.2371, kdB = 0.2362, kdC = 0.3065, kg = 9.81;

std::array<double, 3> sit_to_stand_torques(const std::array<double, 9>& x) {
    const double th[3] = {x[0], x[0] + x[1], x[0] + x[1] + x[2]};
    const double w[3] = {x[3], x[3] + x[4], x[3] + x[4] + x[5]};
    const double al[3] = {x[6], x[6] + x[7], x[6] + x[7] + x[8]};
    struct Planar {
        double x, y;
    };
    // l e(th) and its acceleration, summed over the segments' lengths l[k] from the ankle
    auto at = [&](const double* l, int count, Planar& p, Planar& a) {
        p = {0, 0}, a = {0, 0};
        for (int k = 0; k < count; ++k) {
            const double s = std::sin(th[k]), c = std::cos(th[k]);
            p.x += -l[k] * s, p.y += l[k] * c;
            a.x += l[k] * (-al[k] * c + w[k] * w[k] * s);
            a.y += l[k] * (-al[k] * s - w[k] * w[k] * c);
        }
    };
    const double lA[] = {kdA}, lB[] = {kLA, kdB}, lC[] = {kLA, kLB, kdC}, lKnee[] = {kLA},
                 lHip[] = {kLA, kLB};
    Planar p[3], a[3], knee, hip, unused;
    at(lA, 1, p[0], a[0]);
    at(lB, 2, p[1], a[1]);
    at(lC, 3, p[2], a[2]);
    at(lKnee, 1, knee, unused);
    at(lHip, 2, hip, unused);
    const Segment seg[3] = {kShank, kThigh, kTrunk};
    // the moment about O of the segments from `first` on
    auto moment = [&](Planar O, int first) {
        double T = 0;
        for (int k = first; k < 3; ++k) {
            const double Fx = seg[k].m * a[k].x, Fy = seg[k].m * (a[k].y + kg);
            T += seg[k].I * al[k] + (p[k].x - O.x) * Fy - (p[k].y - O.y) * Fx;
        }
        return T;
    };
    return {moment({0, 0}, 0), moment(knee, 1), moment(hip, 2)};
}

// the example's model statements (up to its road-map)
std::string sit_to_stand_model() {
    const std::string text = read_text(fs::path(ALEMBERT_SOURCE_DIR) / "examples" / "sit_to_stand" / "model.alb");
    const std::size_t end = text.find("\nroadmap E");
    EXPECT_NE(end, std::string::npos) << "examples/sit_to_stand/model.alb has no road-map";
    return text.substr(0, end + 1);
}

}  // namespace

TEST(CodegenReactions, APendulumsGeneratedProgramWritesThePinForceOfNewtonsLawAtEveryRow) {
    if (!has_program(c_compiler() + " --version"))
        GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    ScratchDir dir("reactions-pendulum");
    run_script(kPendulum + "tolerance abs 1e-12 rel 1e-12\ncodegen c name pend to \"c\"\n"
                           "codegen cpp name pend to \"cpp\"\n",
               dir.path());
    for (const char* language : {"c", "cpp"}) {
        SCOPED_TRACE(language);
        const fs::path at = dir.path() / language;
        compile_and_simulate(at, "pend", std::string(language) == "cpp");
        expect_pendulum_rows(at / "pend.csv");
    }
}

TEST(CodegenReactions, OneForceGivenByMeasuresAlongObliqueDirectionsIsSolvedForBoth) {
    // the pin's force as R = P Nx + Q (Nx + Ny): each measure's row (along Nx, along Nx + Ny)
    // holds both, so the two are solved together; R = Rx Nx + Ry Ny of Newton's law above gives
    //   Q = Ry,  P = Rx - Ry
    if (!has_program(c_compiler() + " --version"))
        GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    std::string script = kPendulum;
    auto replace = [&](const std::string& a, const std::string& b) {
        const std::size_t at = script.find(a);
        ASSERT_NE(at, std::string::npos) << a;
        script.replace(at, a.size(), b);
    };
    replace("unknown Rx N, Ry N", "unknown P N, Q N");
    replace("force Rx along Nx>, Ry along Ny>", "force P along Nx>, Q along Nx> + Ny>");
    replace("output q, Rx, Ry", "output q, P, Q");
    ScratchDir dir("reactions-oblique");
    run_script(script + "tolerance abs 1e-12 rel 1e-12\ncodegen c name pend to \"c\"\n", dir.path());
    const fs::path at = dir.path() / "c";
    compile_and_simulate(at, "pend", false);
    std::string header;
    const std::vector<std::vector<double>> rows = csv_rows(at / "pend.csv", &header);
    EXPECT_EQ(header, "t [s],q,q',P [N],Q [N]");
    ASSERT_EQ(rows.size(), 21u);
    for (const std::vector<double>& r : rows) {
        ASSERT_EQ(r.size(), 5u);
        SCOPED_TRACE("t = " + std::to_string(r[0]));
        const double q = r[1], w = r[2], a = -(g / L) * std::sin(q);
        const double Rx = pendulum_Rx(q, w, a), Ry = pendulum_Ry(q, w, a);
        expect_close(r[3], Rx - Ry, "P");
        expect_close(r[4], Ry, "Q");
    }
}

TEST(CodegenReactions, TheGeneratedReactionsFunctionGivesThePinForceAtAnyStateAndAcceleration) {
    // the rows hold q'' as given: R - m g Ny = m a for any q, q', q'' (not only the motion's)
    if (!has_program(c_compiler() + " --version"))
        GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    ScratchDir dir("reactions-function");
    run_script(kPendulum + "codegen c name pend to \"c\"\n", dir.path());
    const fs::path at = dir.path() / "c";
    const std::string header = read_text(at / "pend.h");
    EXPECT_NE(header.find("void pend_reactions(const pend_context* c, double t, const double* q, "
                          "const double* qp, const double* qpp, const double* u, double* reaction);"),
              std::string::npos)
        << header;
    EXPECT_NE(header.find("The joint-reaction measures reaction[] = (Rx, Ry)"), std::string::npos);
    alembert::test::write(at / "driver.c", alembert::test::c_driver_frame("pend", R"(        double q[1], qp[1], qpp[1], u[2] = {1e300, -1e300}, r[2];
        if (!read(q, 1) || !read(qp, 1) || !read(qpp, 1)) return 1;
        pend_reactions(&c, 0.0, q, qp, qpp, u, r);
        print(r, 2);
)"));
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> draw(-3, 3);
    std::vector<std::array<double, 3>> states;
    std::ostringstream in;
    in.precision(17);
    in << 8 << "\n";
    for (int k = 0; k < 8; ++k) {
        states.push_back({draw(rng), draw(rng), draw(rng)});
        in << states.back()[0] << ' ' << states.back()[1] << ' ' << states.back()[2] << "\n";
    }
    alembert::test::write(at / "states.txt", in.str());
    std::string out;
    ASSERT_EQ(run("cd " + at.string() + " && " + c_compiler() +
                      " -std=c99 -pedantic -Wall -Wextra -Werror -O2 pend.c driver.c -lm -o driver"
                      " && ./driver < states.txt",
                  out),
              0)
        << out;
    const std::vector<double> r = numbers(out);
    ASSERT_EQ(r.size(), 2 * states.size()) << out;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const auto [q, w, a] = states[k];
        expect_close(r[2 * k], pendulum_Rx(q, w, a), "Rx");
        expect_close(r[2 * k + 1], pendulum_Ry(q, w, a), "Ry");
    }
}

TEST(CodegenReactions, ATwoLinkArmsProgramWritesTheElbowAndShoulderForcesAtEveryRow) {
    if (!has_program(c_compiler() + " --version"))
        GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    for (bool absolute : {false, true}) {
        SCOPED_TRACE(absolute ? "absolute angles (Kane's equations)" : "relative angles (a tree)");
        ScratchDir dir(absolute ? "reactions-arm-absolute" : "reactions-arm");
        run_script((absolute ? kArmAbsolute : kArm) +
                       "tolerance abs 1e-12 rel 1e-12\ncodegen c name arm to \"c\"\n",
                   dir.path());
        const fs::path at = dir.path() / "c";
        // the recursion's accelerations for the tree, M q'' = f solved for the other
        EXPECT_EQ(read_text(at / "arm.h").find("arm_accelerations") == std::string::npos, absolute);
        compile_and_simulate(at, "arm", false);
        std::string header;
        const std::vector<std::vector<double>> rows = csv_rows(at / "arm.csv", &header);
        EXPECT_EQ(header, "t [s],q1,q2,q1',q2',Sx [N],Sy [N],Ex [N],Ey [N],T [N*m]");
        ASSERT_EQ(rows.size(), 21u);
        double largest_elbow_rate = 0;
        for (const std::vector<double>& r : rows) {
            ASSERT_EQ(r.size(), 10u);
            SCOPED_TRACE("t = " + std::to_string(r[0]));
            const double T = T0 * std::cos(w_T * r[0]);
            expect_close(r[9], T, "T, the motor's law");
            const ArmForces f = arm_forces(r[1], r[2], r[3], r[4], T, absolute);
            expect_close(r[5], f.Sx, "Sx");
            expect_close(r[6], f.Sy, "Sy");
            expect_close(r[7], f.Ex, "Ex");
            expect_close(r[8], f.Ey, "Ey");
            largest_elbow_rate = std::max(largest_elbow_rate, std::fabs(r[4] - (absolute ? r[3] : 0)));
        }
        EXPECT_GT(largest_elbow_rate, 1.0);  // the elbow moves: its centripetal terms are tested
    }
}

TEST(CodegenReactions, GeneratedPythonWritesThePinForceOfNewtonsLawAtEveryRow) {
    if (!has_program(std::string(kPython) + " -c 'import numpy, scipy'"))
        GTEST_SKIP() << kPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    ScratchDir dir("reactions-python");
    run_script(kPendulum + "tolerance abs 1e-12 rel 1e-12\ncodegen python name pend to \"py\"\n",
               dir.path());
    const fs::path at = dir.path() / "py";
    std::string out;
    ASSERT_EQ(run("cd " + at.string() + " && " + kPython + " pend.py pend.csv", out), 0) << out;
    expect_pendulum_rows(at / "pend.csv");
}

TEST(CodegenReactions, GeneratedMatlabWritesThePinForceOfNewtonsLawAtEveryRowUnderOctave) {
    if (!has_program("command -v octave")) GTEST_SKIP() << "octave is not installed";
    ScratchDir dir("reactions-octave");
    run_script(kPendulum + "tolerance abs 1e-12 rel 1e-12\ncodegen matlab name pend to \"m\"\n",
               dir.path());
    const fs::path at = dir.path() / "m";
    std::string out;
    ASSERT_EQ(run("cd " + at.string() + " && octave --no-gui --quiet --eval \"pend_simulate('pend.csv')\"", out),
              0)
        << out;
    expect_pendulum_rows(at / "pend.csv");
}

TEST(CodegenReactions, TheGeneratedFilesAreTheSameFromRunToRun) {
    // two runs of the command, each its own process (its own addresses and symbol serials)
    ScratchDir dir("reactions-same");
    alembert::test::write(dir.path() / "arm.alb",
                          kArm + "codegen c name arm to \"c\"\ncodegen python name arm to \"c\"\n");
    for (const char* run_name : {"first", "second"}) {
        std::string out;
        ASSERT_EQ(run("cd " + dir.path().string() + " && " + ALEMBERT_CLI + " run arm.alb --out " +
                          run_name,
                      out),
                  0)
            << out;
    }
    for (const char* file : {"arm.h", "arm.c", "arm_main.c", "arm.py"}) {
        const std::string a = read_text(dir.path() / "first" / "c" / file);
        EXPECT_NE(a.find("reactions"), std::string::npos) << file;
        EXPECT_EQ(a, read_text(dir.path() / "second" / "c" / file)) << file;
    }
}

TEST(CodegenReactions, TorquesOfAModelThatDeclaresJointReactionsNeedNoReactionValues) {
    // the sit-to-stand model declares reactions at all three joints; code for its torques alone
    // (with or without the derivatives) takes the torques as its only loads: the reactions do
    // no work, so neither inverse nor forward dynamics reads them
    if (!has_program(c_compiler() + " --version"))
        GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    ScratchDir dir("reactions-sit-to-stand");
    run_script(sit_to_stand_model() + "codegen c name sts for T_A, T_B, T_C to \"c\"\n" +
                   "codegen c name sts for T_A, T_B, T_C derivatives to \"d\"\n",
               dir.path());
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3);
    std::vector<std::array<double, 9>> states(6);
    std::ostringstream in;
    in.precision(17);
    in << states.size() << "\n";
    for (std::array<double, 9>& x : states) {
        for (double& v : x) v = angle(rng);
        for (std::size_t i = 3; i < 9; ++i) x[i] = rate(rng);
        for (double v : x) in << v << ' ';
        in << "\n";
    }
    for (const char* sub : {"c", "d"}) {
        SCOPED_TRACE(sub);
        const fs::path at = dir.path() / sub;
        EXPECT_NE(read_text(at / "sts.h").find("#define sts_NU 3"), std::string::npos) << read_text(at / "sts.h");
        // per state: the torques of inverse dynamics, then q'' of forward dynamics with them
        const std::optional<std::vector<double>> got = alembert::test::compile_and_run_c_driver(
            at, "sts", alembert::test::c_driver_frame("sts", R"(        double q[3], qp[3], qpp[3], u[3], a[3];
        if (!read(q, 3) || !read(qp, 3) || !read(qpp, 3)) return 1;
        sts_inverse_dynamics(&c, 0.0, q, qp, qpp, u);
        if (sts_forward_dynamics(&c, 0.0, q, qp, u, a) != 0) return 2;
        print(u, 3);
        print(a, 3);
)"),
            in.str());
        ASSERT_TRUE(got);
        ASSERT_EQ(got->size(), 6 * states.size());
        for (std::size_t k = 0; k < states.size(); ++k) {
            SCOPED_TRACE("state " + std::to_string(k));
            const std::array<double, 3> T = sit_to_stand_torques(states[k]);
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR((*got)[6 * k + i], T[i], 1e-11 * std::max(1.0, std::fabs(T[i]))) << "torque " << i;
                EXPECT_NEAR((*got)[6 * k + 3 + i], states[k][6 + i], 1e-9 * std::max(1.0, std::fabs(states[k][6 + i])))
                    << "q'' " << i;
            }
        }
    }
}

}  // namespace codegen_reactions
