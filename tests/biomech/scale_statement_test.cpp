// SPDX-License-Identifier: MIT
// The `scale` statement: a model's lengths from a static trial written with known lengths, a
// segment table scaled by them, and the mistakes it names.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/lang/interpreter.hpp"
#include "alembert/mech/system.hpp"

namespace {

using namespace alembert::lang;
namespace fs = std::filesystem;

struct ScaleSession {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    RunStatus run(const std::string& text) {
        out.str("");
        err.str("");
        return interp.run(text, "scale.alb");
    }
};

// A subject standing 2 s at 100 Hz, swaying as a rigid chain: the hip 3 mm back and forth, the
// thigh (HIP to KNEE, 0.40 m, the knee's marker 5 cm lateral) and the leg (KNEE to ANKLE,
// 0.43 m) leaning by a few degrees. Coordinates in mm to 1e-9 mm. With `thigh_marker`, a
// fourth marker THI rides on the thigh at thi_along down the line from HIP to KNEE (in the X-Y
// plane) and thi_across forward of it, 3 cm lateral.
struct StaticTrc {
    static constexpr double thi_along = 0.182, thi_across = 0.061;  // m
    fs::path dir = fs::temp_directory_path() / ("alembert_scale_" + std::to_string(::getpid()));
    fs::path path = dir / "static.trc";
    // the hip and the thigh's angle (rad, from -Ny> counterclockwise) at frame k; mm
    static void pose(int k, double hip[3], double& a) {
        const double t = k / 100.0;
        a = 0.04 * std::sin(1.7 * t);
        hip[0] = 3 * std::sin(2.3 * t), hip[1] = 930, hip[2] = 100;
    }
    explicit StaticTrc(bool thigh_marker = false) {
        fs::create_directories(dir);
        std::ofstream out(path);
        const int frames = 200;
        out << "PathFileType\t4\t(X/Y/Z)\tstatic.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n100\t100\t"
            << frames << (thigh_marker ? "\t4" : "\t3") << "\tmm\nFrame#\tTime\tHIP\t\t\tKNEE\t\t\tANKLE\t\t"
            << (thigh_marker ? "\tTHI\t\t" : "") << "\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3"
            << (thigh_marker ? "\tX4\tY4\tZ4" : "") << "\n\n";
        const double T = 400, L = 430, lateral = 50, Ts = std::sqrt(T * T - lateral * lateral);
        char cell[64];
        for (int k = 0; k < frames; ++k) {
            const double t = k / 100.0, b = -0.03 * std::sin(1.1 * t + 0.5);
            double hip[3], a;
            pose(k, hip, a);
            const double knee[3] = {hip[0] + Ts * std::sin(a), hip[1] - Ts * std::cos(a), hip[2] + lateral};
            const double ankle[3] = {knee[0] + L * std::sin(b), knee[1] - L * std::cos(b), knee[2]};
            // u = (sin a, -cos a) from HIP to KNEE, n = (cos a, sin a) a quarter turn counterclockwise
            const double A = thi_along * 1000, C = thi_across * 1000;
            const double thi[3] = {hip[0] + A * std::sin(a) + C * std::cos(a), hip[1] - A * std::cos(a) + C * std::sin(a),
                                   hip[2] + 30};
            out << k + 1 << "\t" << t;
            std::vector<const double*> rows = {hip, knee, ankle};
            if (thigh_marker) rows.push_back(thi);
            for (const double* p : rows)
                for (int i = 0; i < 3; ++i) {
                    std::snprintf(cell, sizeof cell, "%.9f", p[i]);
                    out << "\t" << cell;
                }
            out << "\n";
        }
    }
    ~StaticTrc() { fs::remove_all(dir); }
};

TEST(ScaleStatement, DeclaresTheLengthsOfAStaticTrialAndScalesASegmentTableByThem) {
    StaticTrc trc;
    ScaleSession s;
    const std::string file = trc.path.string();
    ASSERT_EQ(s.run("newtonian N\nbody Thigh, Leg\n"
                    "scale L_T from \"" + file + "\" between HIP and KNEE\n"
                    "scale L_L from \"" + file + "\" between KNEE and ANKLE within 5 mm\n"
                    "segment m_T, d_T, I_T from winter thigh mass 56.7 kg length L_T\n"),
              RunStatus::ok)
        << s.err.str();
    const std::string text = s.out.str();
    // the lengths written, 0.40 and 0.43 m, to the transcript's six digits; a rigid sway: the
    // SD only the rounding of the file's coordinates (1e-9 mm)
    const std::string said = "L_T = 0.4 m: the mean distance from HIP to KNEE over 200 frames of " + file + " (SD ";
    const std::size_t at = text.find(said);
    ASSERT_NE(at, std::string::npos) << text;
    EXPECT_LT(std::stod(text.substr(at + said.size())), 1e-8) << text;
    EXPECT_NE(text.find("L_L = 0.43 m: the mean distance from KNEE to ANKLE over 200 frames"), std::string::npos) << text;
    // Winter's thigh for 56.7 kg and 0.40 m, as segment_statement_test.cpp works it by hand:
    // 0.100 * 56.7 kg; 0.433 * 0.40 m; 5.67 (0.323 * 0.40)^2 kg m^2
    EXPECT_NE(text.find("m_T = 5.67 kg, d_T = 0.1732 m, I_T = 0.0946473 kg*m^2"), std::string::npos) << text;
    // the lengths are constants of the model, in metres: the leg hanging from the thigh
    ASSERT_EQ(s.run("variable q\nevaluate L_T*cos(q) + L_L at q = 0\n"), RunStatus::ok) << s.err.str();
    EXPECT_NE(s.out.str().find("0.83 m"), std::string::npos) << s.out.str();
}

TEST(ScaleStatement, MistakesNameTheMarkerTheFileOrTheDeviation) {
    StaticTrc trc;
    ScaleSession s;
    const std::string file = trc.path.string();
    ASSERT_EQ(s.run("newtonian N\nbody Thigh\n"), RunStatus::ok);
    EXPECT_EQ(s.run("scale L_T from \"" + file + "\" between HIP and TOE\n"), RunStatus::script_error);
    EXPECT_NE(s.err.str().find("no marker 'TOE' in the marker file; its markers are: HIP, KNEE, ANKLE"),
              std::string::npos)
        << s.err.str();
    // HIP to ANKLE spans the knee, which bends by up to 0.07 rad: their distance is not steady
    EXPECT_EQ(s.run("scale L_X from \"" + file + "\" between HIP and ANKLE within 0.1 mm\n"), RunStatus::script_error);
    EXPECT_NE(s.err.str().find("the distance between 'HIP' and 'ANKLE' is "), std::string::npos) << s.err.str();
    EXPECT_EQ(s.run("scale L_T from \"" + (trc.dir / "none.trc").string() + "\" between HIP and KNEE\n"),
              RunStatus::script_error);
    EXPECT_NE(s.err.str().find("none.trc"), std::string::npos) << s.err.str();
    // a segment's length that has no value
    EXPECT_EQ(s.run("constant L\nsegment m, d, I from winter thigh mass 60 kg length L\n"), RunStatus::script_error);
    EXPECT_NE(s.err.str().find("the segment's length L has no value"), std::string::npos) << s.err.str();
}

TEST(PlaceStatement, DeclaresAMarkersPlaceOnTheThighAndAModelPointFromItMatchesTheTrial) {
    StaticTrc trc(true);
    ScaleSession s;
    const std::string file = trc.path.string();
    ASSERT_EQ(s.run("newtonian N\nbody T\nvariable qT\n"
                    "place A_K, C_K from \"" + file + "\" marker THI between HIP and KNEE\n"),
              RunStatus::ok)
        << s.err.str();
    EXPECT_NE(s.out.str().find("A_K = 0.182 m, C_K = 0.061 m: the mean place of THI along the line from HIP to KNEE "
                               "and across it"),
              std::string::npos)
        << s.out.str();
    EXPECT_NE(s.out.str().find(" over 200 frames of " + file), std::string::npos) << s.out.str();
    // the constants are the place written, up to the file's rounding (1e-9 mm = 1e-12 m per
    // coordinate, averaged over 200 frames)
    const alembert::SymbolTable& table = s.interp.system()->symbols();
    EXPECT_NEAR(*table.value(table.symbol("A_K")), StaticTrc::thi_along, 1e-12);
    EXPECT_NEAR(*table.value(table.symbol("C_K")), StaticTrc::thi_across, 1e-12);
    // a thigh hanging along -Ty> from the hip, Tx> forward, turned by qT about Nz: its marker
    // point at C_K*Tx> - A_K*Ty> from the hip is the trial's THI at the pose of frame 90
    double hip[3], a;
    StaticTrc::pose(90, hip, a);
    s.interp.set_digits(15);
    char setup[256];
    std::snprintf(setup, sizeof setup,
                  "rotate T from N about z by qT\npoint HIP_P, THI_M\ntranslate HIP_P from N_o by %.17g m*Nx> + %.17g m*Ny>\n",
                  hip[0] / 1000, hip[1] / 1000);
    ASSERT_EQ(s.run(std::string(setup) + "translate THI_M from HIP_P by C_K*Tx> - A_K*Ty>\n"), RunStatus::ok)
        << s.err.str();
    const double want[2] = {
        (hip[0] + 1000 * (StaticTrc::thi_along * std::sin(a) + StaticTrc::thi_across * std::cos(a))) / 1000,
        (hip[1] + 1000 * (-StaticTrc::thi_along * std::cos(a) + StaticTrc::thi_across * std::sin(a))) / 1000};
    const char* axes[2] = {"Nx>", "Ny>"};
    for (int i = 0; i < 2; ++i) {
        char line[128];
        std::snprintf(line, sizeof line, "evaluate dot(pos(THI_M, N_o), %s) at qT = %.17g\n", axes[i], a);
        ASSERT_EQ(s.run(line), RunStatus::ok) << s.err.str();
        const std::string out = s.out.str();
        const std::size_t eq = out.rfind("= ");
        ASSERT_NE(eq, std::string::npos) << out;
        EXPECT_NEAR(std::stod(out.substr(eq + 2)), want[i], 2e-12) << axes[i] << ": " << out;
    }
}

TEST(PlaceStatement, AMissingMarkerIsNamedAtItsPlaceInTheScript) {
    StaticTrc trc(true);
    ScaleSession s;
    const std::string file = trc.path.string();
    ASSERT_EQ(s.run("newtonian N\nbody T\n"), RunStatus::ok);
    EXPECT_EQ(s.run("place A_K, C_K from \"" + file + "\" marker LKNE between HIP and KNEE\n"), RunStatus::script_error);
    EXPECT_NE(s.err.str().find("scale.alb:1:"), std::string::npos) << s.err.str();
    EXPECT_NE(s.err.str().find("no marker 'LKNE' in the marker file; its markers are: HIP, KNEE, ANKLE, THI"),
              std::string::npos)
        << s.err.str();
    // nothing declared: the names are free for the corrected statement
    EXPECT_EQ(s.run("place A_K, C_K from \"" + file + "\" marker THI between HIP and KNEE\n"), RunStatus::ok)
        << s.err.str();
}

}  // namespace
