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

#include "alembert/lang/interpreter.hpp"

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
// 0.43 m) leaning by a few degrees. Coordinates in mm to 1e-9 mm.
struct StaticTrc {
    fs::path dir = fs::temp_directory_path() / ("alembert_scale_" + std::to_string(::getpid()));
    fs::path path = dir / "static.trc";
    StaticTrc() {
        fs::create_directories(dir);
        std::ofstream out(path);
        const int frames = 200;
        out << "PathFileType\t4\t(X/Y/Z)\tstatic.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n100\t100\t"
            << frames << "\t3\tmm\nFrame#\tTime\tHIP\t\t\tKNEE\t\t\tANKLE\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\n\n";
        const double T = 400, L = 430, lateral = 50, Ts = std::sqrt(T * T - lateral * lateral);
        char cell[64];
        for (int k = 0; k < frames; ++k) {
            const double t = k / 100.0, a = 0.04 * std::sin(1.7 * t), b = -0.03 * std::sin(1.1 * t + 0.5);
            const double hip[3] = {3 * std::sin(2.3 * t), 930, 100};
            const double knee[3] = {hip[0] + Ts * std::sin(a), hip[1] - Ts * std::cos(a), hip[2] + lateral};
            const double ankle[3] = {knee[0] + L * std::sin(b), knee[1] - L * std::cos(b), knee[2]};
            out << k + 1 << "\t" << t;
            for (const double* p : {hip, knee, ankle})
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

}  // namespace
