// SPDX-License-Identifier: MIT
// The `marker` statement: a script's model driven by a .trc trial, and a model whose markers
// disagree with the file named at the inverse statement with its coordinate.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace marker_statement_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

// model_lab.alb with `from` replaced by `to` in its text, run into a temporary directory
struct LabScript {
    fs::path dir = fs::temp_directory_path() / ("alembert_marker_" + std::to_string(::getpid()));
    std::ostringstream out, err;
    ~LabScript() { fs::remove_all(dir); }
    RunStatus run(const std::string& from, const std::string& to) {
        const fs::path path = fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/model_lab.alb";
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        const std::size_t at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) s.replace(at, from.size(), to);
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        return interp.run(s, path.string());
    }
};

TEST(MarkerStatement, AMarkerAtTheWrongPointOfTheModelIsAnErrorNamingItsCoordinate) {
    // the thigh's knee marker declared at the thigh's centre of mass, 23.62 cm from the knee (21.1
    // cm after the lab's origin is fitted to all the markers)
    LabScript lab;
    EXPECT_EQ(lab.run("marker LFE on B at B_o", "marker LFE on B at Bcm"), RunStatus::script_error);
    const std::string e = lab.err.str();
    EXPECT_NE(e.find("model_lab.alb:45:1: error"), std::string::npos) << e;
    EXPECT_NE(e.find("marker 'LFE' (on B) is 21.1 cm from where the model puts it"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("check the sign and offset of 'qB'"), std::string::npos) << e;
}

TEST(MarkerStatement, AScriptWithoutMarkersCannotReadATrcTrial) {
    LabScript lab;
    EXPECT_EQ(lab.run("marker LMAL on A at A_o\n", "# no ankle marker\n"), RunStatus::script_error);
    EXPECT_NE(lab.err.str().find(
                  "'qA', 'qB' can change together without turning a segment with two markers"),
              std::string::npos)
        << lab.err.str();
}

// A spatial two-body arm (a universal joint at the base: qz about Nz, then qx about the frame
// F's x; an elbow qe about Ax), its markers written to a .trc from positions derived by hand:
// Ay = (-cos qx sin qz, cos qx cos qz, sin qx), By the same with qx + qe; Acm = L/2 Ay,
// B_o = L Ay, Bcm = L Ay + L/2 By. `inverse ... from "arm.trc"` finds the coordinates by
// inverse kinematics and gives the torques the prescribed motion gives.
TEST(MarkerStatement, ASpatialModelsTrialIsReadByInverseKinematics) {
    const fs::path dir = fs::temp_directory_path() / ("alembert_spatial_marker_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const double L = 0.5, w = 2 * std::numbers::pi * 0.5;
    auto qz = [&](double t) { return 0.3 * std::sin(w * t); };
    auto qx = [&](double t) { return 0.2 + 0.4 * std::sin(w * t); };
    auto qe = [&](double t) { return 0.5 + 0.3 * std::cos(w * t); };
    const int frames = 301;  // 0 to 3 s at 100 Hz
    {
        std::ofstream out(dir / "arm.trc");
        out << "PathFileType\t4\t(X/Y/Z)\tarm.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\t"
               "OrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n100\t100\t" << frames << "\t3\tm\t100\t1\t"
            << frames << "\nFrame#\tTime\tAM\t\t\tKN\t\t\tBM\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\n\n";
        char cell[64];
        for (int k = 0; k < frames; ++k) {
            const double t = k / 100.0, z = qz(t), x = qx(t), e = qe(t);
            const double Ay[3] = {-std::cos(x) * std::sin(z), std::cos(x) * std::cos(z), std::sin(x)};
            const double By[3] = {-std::cos(x + e) * std::sin(z), std::cos(x + e) * std::cos(z), std::sin(x + e)};
            out << k + 1 << "\t" << t;
            for (double f : {0.5, 1.0}) {
                for (int i = 0; i < 3; ++i) {
                    std::snprintf(cell, sizeof cell, "%.17g", f * L * Ay[i]);
                    out << "\t" << cell;
                }
            }
            for (int i = 0; i < 3; ++i) {
                std::snprintf(cell, sizeof cell, "%.17g", L * Ay[i] + L / 2 * By[i]);
                out << "\t" << cell;
            }
            out << "\n";
        }
    }
    const std::string model = R"(newtonian N
frame F
body A, B
variable qz'', qx'', qe''
constant L = 0.5 m, g = 9.81 m/s^2
unknown Tz N*m, Tx N*m, Te N*m
rotate F from N about z by qz
rotate A from F about x by qx
rotate B from A about x by qe
translate A_o from N_o by 0>
translate Acm from A_o by L/2*Ay>
translate B_o from A_o by L*Ay>
translate Bcm from B_o by L/2*By>
mass A = 2 kg; inertia A = 0.05 kg*m^2, 0.01 kg*m^2, 0.05 kg*m^2
mass B = 1.5 kg; inertia B = 0.03 kg*m^2, 0.005 kg*m^2, 0.03 kg*m^2
gravity -g*Nz>
torque Tz on A from N = Tz*Nz>
torque Tx on A from N = Tx*Ax>
torque Te on B from A = Te*Ax>
marker AM on A at Acm
marker KN on B at B_o
marker BM on B at Bcm
)";
    auto run = [&](const std::string& tail, std::ostringstream& out, std::ostringstream& err) {
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        return interp.run(model + tail, (dir / "arm.alb").string());
    };
    std::ostringstream out1, err1, out2, err2;
    // f = 0.5 Hz = 0.5 rev/s = pi rad/s: the arguments f*t turn once every 2 s
    ASSERT_EQ(run("constant f = 0.5 Hz\n"
                  "motion qz = 0.3*sin(f*t), qx = 0.2 + 0.4*sin(f*t), qe = 0.5 + 0.3*cos(f*t)\n"
                  "final time 3 s\noutput step 0.01 s\ninverse for Tz, Tx, Te to \"formula\"\n",
                  out1, err1),
              RunStatus::ok)
        << err1.str();
    ASSERT_EQ(run("inverse for Tz, Tx, Te from \"" + (dir / "arm.trc").string() + "\" cutoff 6 Hz to \"lab\"\n",
                  out2, err2),
              RunStatus::ok)
        << err2.str();
    const std::string transcript = out2.str();
    EXPECT_NE(transcript.find("inverse kinematics in three dimensions"), std::string::npos) << transcript;
    const alembert::Table a = alembert::read_csv((dir / "formula" / "torques.csv").string());
    const alembert::Table b = alembert::read_csv((dir / "lab" / "torques.csv").string());
    ASSERT_EQ(a.row_count(), b.row_count());
    // Away from the ends (the filter's start-up), the zero-lag Butterworth at 6 Hz passes the
    // 0.5 Hz motion with a gain of 1/(1 + (0.5/6)^4) = 1 - 4.8e-5 and central differences at
    // 10 ms err by (w h)^2/12 = 8.2e-5 of q'' (w = pi/s): together 1.3e-4 of the inertial part
    // of the torques, which is below their scale, so they agree to 2e-4 of it; the markers are
    // exact, so inverse kinematics adds only rounding.
    double scale = 0, worst = 0;
    for (std::size_t c = 1; c < a.columns.size(); ++c)
        for (std::size_t r = 0; r < a.row_count(); ++r) scale = std::max(scale, std::abs(a.columns[c][r]));
    for (std::size_t c = 1; c < a.columns.size(); ++c)
        for (std::size_t r = a.row_count() / 4; r < 3 * a.row_count() / 4; ++r)
            worst = std::max(worst, std::abs(a.columns[c][r] - b.columns[c][r]));
    std::printf("spatial marker trial: torques within %.3g N*m of the prescribed motion's (scale %.3g N*m)\n",
                worst, scale);
    EXPECT_GT(scale, 1.0);
    EXPECT_LT(worst, 2e-4 * scale);
    fs::remove_all(dir);
}

// A marker's weight multiplies its squared distance in the inverse-kinematics fit. A slider
// (one translation x) carries two markers at one point of it; the file has them 1 m apart,
// at x = 0 and x = 1, so the fit minimises w1 x^2 + w2 (x - 1)^2: x = w2 / (w1 + w2), the
// weighted mean, 1/2 unweighted and 3/4 with w2 = 3.
TEST(MarkerStatement, AMarkersWeightPullsTheFitByItsShareOfTheWeights) {
    const fs::path dir = fs::temp_directory_path() / ("alembert_marker_weight_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        std::ofstream out(dir / "slide.trc");
        out << "PathFileType\t4\t(X/Y/Z)\tslide.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\t"
               "OrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n100\t100\t21\t2\tm\t100\t1\t21\n"
               "Frame#\tTime\tM1\t\t\tM2\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n";
        for (int k = 0; k < 21; ++k) out << k + 1 << "\t" << k / 100.0 << "\t0\t0\t0\t1\t0\t0\n";
    }
    auto fitted = [&](const std::string& weight) {
        const std::string model = "newtonian N\nbody A\nvariable x''\nunknown F N\n"
                                  "rotate A from N about z by 0\ntranslate A_o from N_o by x*Nx>\ntranslate Acm from A_o by 0>\n"
                                  "mass A = 2 kg; inertia A = 0, 0, 0.1 kg*m^2\nforce F on A_o = F*Nx>\n"
                                  "marker M1 on A at A_o\nmarker M2 on A at A_o" + weight + "\n"
                                  "inverse for F from \"" + (dir / "slide.trc").string() + "\" cutoff 6 Hz to \"fit\"\n";
        std::ostringstream out, err;
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        EXPECT_EQ(interp.run(model, (dir / "slide.alb").string()), RunStatus::ok) << err.str();
        const alembert::Table kin = alembert::read_csv((dir / "fit" / "kinematics.csv").string());
        const alembert::Table loads = alembert::read_csv((dir / "fit" / "forces.csv").string());
        double x = kin.columns[kin.column_index("x")][10];
        for (std::size_t k = 0; k < kin.row_count(); ++k) {
            EXPECT_NEAR(kin.columns[kin.column_index("x")][k], x, 1e-9);
            EXPECT_NEAR(loads.columns[loads.column_index("F")][k], 0.0, 1e-6);  // at rest: no force
        }
        return x;
    };
    EXPECT_NEAR(fitted(""), 0.5, 1e-9);
    EXPECT_NEAR(fitted(" weight 3"), 0.75, 1e-9);
    EXPECT_NEAR(fitted(" weight 0.25"), 0.2, 1e-9);
    fs::remove_all(dir);
}

TEST(MarkerStatement, AWeightThatIsNotAPositiveNumberOrDiffersBetweenAJointsTwoStatementsIsAnError) {
    LabScript zero;
    EXPECT_EQ(zero.run("marker LMAL on A at A_o", "marker LMAL on A at A_o weight 0"), RunStatus::script_error);
    EXPECT_NE(zero.err.str().find("the marker 'LMAL' has weight 0; a weight multiplies the marker's squared distance"),
              std::string::npos)
        << zero.err.str();
    LabScript unit;
    EXPECT_EQ(unit.run("marker LMAL on A at A_o", "marker LMAL on A at A_o weight 2 m"), RunStatus::script_error);
    EXPECT_NE(unit.err.str().find("weight"), std::string::npos) << unit.err.str();
    LabScript joint;
    EXPECT_EQ(joint.run("marker LFE on B at B_o", "marker LFE on B at B_o weight 2"), RunStatus::script_error);
    EXPECT_NE(joint.err.str().find("the marker 'LFE' has weight 2 here but 1 on A"), std::string::npos)
        << joint.err.str();
    // a model read from segment angles has no fit to weigh: the transcript says the weights
    // are not used
    LabScript angles;
    ASSERT_EQ(angles.run("marker LMAL on A at A_o", "marker LMAL on A at A_o weight 3"), RunStatus::ok)
        << angles.err.str();
    EXPECT_NE(angles.out.str().find("marker weights not used ('LMAL'): this model's coordinates come from its "
                                    "segments' angles"),
              std::string::npos)
        << angles.out.str();
}

}  // namespace marker_statement_test
