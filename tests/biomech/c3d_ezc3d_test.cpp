// SPDX-License-Identifier: MIT
// read_c3d and calc_c3d_ground_forces on two public C3D files of ezc3d's test suite (an
// Optotrak trial and a Qualisys trial with two AMTI plates), checked against the values
// ezc3d's own tests state for them (see NOTICE for the files' source and licence).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "alembert/biomech/c3d_file.hpp"
#include "biomech_data.hpp"

namespace alembert {
namespace {

using Vec3 = std::array<double, 3>;

bool any_note_has(const std::vector<std::string>& notes, const std::string& text) {
    for (const std::string& n : notes)
        if (n.find(text) != std::string::npos) return true;
    return false;
}

// ---- Optotrak.c3d: ezc3d's test/test_ezc3d.cpp, TEST(c3dFileIO, readOptotrakC3D) ------------

TEST(ReadC3dEzc3dFiles, OptotrakPointsRateAndFramesAsEzc3dStatesThem) {
    // ezc3d: 54 points, frame rate 30, scale factor -7.8661418 (float data), no analog channels,
    // FORCE_PLATFORM:USED 0; frames 0 to 28 counted from 0, 29 frames. This copy of the file
    // gives 1149 frames in its header and in POINT:FRAMES but holds 29 whole frames that end
    // with the file: ezc3d reads them to the file's end, and so does read_c3d, with a note.
    const std::string path = test::biomech_data("ezc3d/Optotrak.c3d");
    const C3dFile f = read_c3d(path);
    EXPECT_EQ(f.markers.markers.size(), 54u);
    EXPECT_EQ(f.markers.data_rate_hz, 30);
    EXPECT_TRUE(f.float_data);
    EXPECT_EQ(f.processor, "Intel");
    EXPECT_EQ(f.markers.file_unit, "mm");
    ASSERT_EQ(f.markers.table.row_count(), 29u);
    ASSERT_EQ(f.markers.table.columns.size(), 1 + 3 * 54u);
    // the first frame is frame 1 (ezc3d's 0): t = 0, then 1/30 s apart
    EXPECT_EQ(f.markers.table.columns[0][0], 0.0);
    EXPECT_NEAR(f.markers.table.columns[0][28], 28.0 / 30, 1e-15);
    EXPECT_EQ(f.analog.names.size(), 1u);  // the time column only
    EXPECT_EQ(f.analog.row_count(), 0u);
    EXPECT_TRUE(f.plates.empty());
    EXPECT_TRUE(any_note_has(f.notes, "the header gives 1149 frames (1 to 1149) and POINT:FRAMES 1149, but the file "
                                      "ends after 29 whole frames; these are read, frames 1 to 29"));
}

// ---- Qualisys.c3d: ezc3d's TEST(c3dFileIO, readQualisysC3D), TEST(ForcePlatForm, Type2) and
// test/python3/test_binder_python.py test_force_platform_filter -----------------------------

class Ezc3dQualisys : public ::testing::Test {
protected:
    static void SetUpTestSuite() { file_ = new C3dFile(read_c3d(test::biomech_data("ezc3d/Qualisys.c3d"))); }
    static void TearDownTestSuite() { delete file_, file_ = nullptr; }
    static C3dFile* file_;
};
C3dFile* Ezc3dQualisys::file_ = nullptr;

TEST_F(Ezc3dQualisys, HeaderPointsAndAnalogChannelsAsEzc3dStatesThem) {
    // ezc3d: 55 points, frame rate 200, scale -0.0762322545 (float data), frames 704 to 1043
    // counted from 0 (340 frames), 69 analog channels at 2000 Hz, 10 samples per frame
    const C3dFile& f = *file_;
    EXPECT_EQ(f.markers.markers.size(), 55u);
    EXPECT_EQ(f.markers.data_rate_hz, 200);
    EXPECT_TRUE(f.float_data);
    EXPECT_EQ(f.markers.file_unit, "mm");  // ezc3d's position unit
    ASSERT_EQ(f.markers.table.row_count(), 340u);
    // frame 705 counted from 1: t = 704 / 200 s; the last, 1044: 1043 / 200 s
    EXPECT_NEAR(f.markers.table.columns[0].front(), 704.0 / 200, 1e-15);
    EXPECT_NEAR(f.markers.table.columns[0].back(), 1043.0 / 200, 1e-15);
    EXPECT_EQ(f.analog.names.size(), 1 + 69u);
    EXPECT_EQ(f.analog_rate_hz, 2000);
    EXPECT_EQ(f.analog_per_frame, 10u);
    ASSERT_EQ(f.analog.row_count(), 3400u);
    EXPECT_NEAR(f.analog.columns[0][1], 704.0 / 200 + 1.0 / 2000, 1e-15);
}

TEST_F(Ezc3dQualisys, PlateGeometryAsEzc3dStatesIt) {
    // ezc3d: 2 plates of type 2, ZERO (0, 0); origins (1.524, -0.762, -34.036) and
    // (1.016, 0, -36.322) mm (the file stores them with z > 0: ezc3d negates them, as read_c3d
    // does with a note); corners (columns) [[508, 508, 0, 0], [464, 0, 0, 464], [0, 0, 0, 0]]
    // and [[1017, 1017, 509, 509], [464, 0, 0, 464], [0, 0, 0, 0]] mm. C3dForcePlate keeps the
    // ORIGIN as stored, in m; calc_c3d_ground_forces negates it.
    const C3dFile& f = *file_;
    ASSERT_EQ(f.plates.size(), 2u);
    const double origin[2][3] = {{1.524, -0.762, -34.036}, {1.016, 0, -36.322}};
    const double corners[2][4][3] = {{{508, 464, 0}, {508, 0, 0}, {0, 0, 0}, {0, 464, 0}},
                                     {{1017, 464, 0}, {1017, 0, 0}, {509, 0, 0}, {509, 464, 0}}};
    for (std::size_t i = 0; i < 2; ++i) {
        const C3dForcePlate& p = f.plates[i];
        EXPECT_EQ(p.type, 2);
        EXPECT_EQ(p.zero[0], 0);
        EXPECT_EQ(p.zero[1], 0);
        EXPECT_EQ(p.channels.size(), 6u);
        EXPECT_TRUE(p.cal_matrix.empty());  // ezc3d: zeros, not used for type 2
        // the file's floats to ezc3d's decimal=3: |a - b| < 1.5e-3 mm
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(-p.origin[a] * 1000, origin[i][a], 1.5e-3) << i << " " << a;
        for (int c = 0; c < 4; ++c)
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.corners[c][a] * 1000, corners[i][c][a], 1.5e-3) << i << c << a;
    }
    EXPECT_TRUE(any_note_has(f.notes, "force plate 1's FORCE_PLATFORM:ORIGIN has z > 0"));
    EXPECT_TRUE(any_note_has(f.notes, "force plate 2's FORCE_PLATFORM:ORIGIN has z > 0"));
}

// The loads at each analog sample rather than at the marker frames: the same file with one
// "frame" per analog sample (analog_per_frame 1), so that calc_c3d_ground_forces averages
// each channel over a single sample, which is ezc3d's per-sample computation.
Table ground_forces_per_sample(const C3dFile& f) {
    C3dFile s = f;
    s.markers.table = Table{};
    s.markers.table.add_column("time", "s");
    s.markers.table.columns[0] = f.analog.columns[0];
    s.analog_per_frame = 1;
    std::vector<std::string> notes;
    return calc_c3d_ground_forces(s, "Qualisys.c3d", notes);
}

// What ezc3d states at one analog sample for one plate, in its units (N, N mm, mm, lab axes).
struct Ezc3dPlateSample {
    std::size_t sample;
    Vec3 force, moment, cop, tz;
};

// ezc3d (src/modules/ForcePlatforms.cpp) reads a type 2 plate's channels F_c, M_c (in the
// plate's axes, the moment about its origin O) and, with R the plate's axes in the lab
// (columns x, y, z from the corners, as read_c3d takes them), S the corners' mean and o the
// ORIGIN (from O to S, z < 0), gives in the lab:
//   force  = R F_c                                        (N)
//   moment = R (M_c + F_c x o)     the moment about S:   M_S = M_O + (O - S) x F, O - S = -o (N mm)
//   cop    = S + R c, c = (-M_S,y / F_c,z, M_S,x / F_c,z, 0): where the force's line meets the
//            surface                                      (mm)
//   Tz     = R (M_S - c x F_c), the free moment, along the plate's z   (N mm)
// calc_c3d_ground_forces gives the reaction on the body, which is what the channels are:
//   ground_force_v = R F_c = force                        (N)
//   ground_force_p = S + R (px - ox, py - oy, 0) = cop / 1000 (m), px, py from O
//   ground_torque  = R T, T = M_O,z - (px F_y - py F_x) = Tz / 1000 (N m): the same moment,
//            as M_S,z - (c x F)_z = M_O,z + (F x o)_z - (px - ox) F_y + (py - oy) F_x
// and ezc3d's moment is the moment of that load about S: moment / 1000 = (p - S) x v + torque.
// Each value within tol_abs + tol_rel |expected|.
void expect_ezc3d_sample(const Table& t, const std::string& plate, const C3dForcePlate& fp, const Ezc3dPlateSample& e,
                         double tol_abs, double tol_rel) {
    auto tol = [&](double expected) { return tol_abs + tol_rel * std::abs(expected); };
    const std::string torque = plate.substr(0, plate.find("force")) + "torque";
    Vec3 v{}, p{}, tau{};
    for (std::size_t a = 0; a < 3; ++a) {
        const std::string axis(1, "xyz"[a]);
        v[a] = t.columns[t.column_index(plate + "_v" + axis)][e.sample];
        p[a] = t.columns[t.column_index(plate + "_p" + axis)][e.sample];
        tau[a] = t.columns[t.column_index(torque + "_" + axis)][e.sample];
    }
    // S as the file stores the corners (floats near whole millimetres: 508 is stored as 508.0000305)
    Vec3 S{};
    for (std::size_t a = 0; a < 3; ++a)
        S[a] = (fp.corners[0][a] + fp.corners[1][a] + fp.corners[2][a] + fp.corners[3][a]) / 4;
    const Vec3 r{p[0] - S[0], p[1] - S[1], p[2] - S[2]};
    const Vec3 M_S{r[1] * v[2] - r[2] * v[1] + tau[0], r[2] * v[0] - r[0] * v[2] + tau[1],
                   r[0] * v[1] - r[1] * v[0] + tau[2]};
    for (std::size_t a = 0; a < 3; ++a) {
        SCOPED_TRACE(plate + " sample " + std::to_string(e.sample) + " axis " + std::to_string(a));
        EXPECT_NEAR(v[a], e.force[a], tol(e.force[a]));
        EXPECT_NEAR(p[a] * 1000, e.cop[a], tol(e.cop[a]));
        EXPECT_NEAR(tau[a] * 1000, e.tz[a], tol(e.tz[a]));
        EXPECT_NEAR(M_S[a] * 1000, e.moment[a], tol(e.moment[a]));
    }
}

TEST_F(Ezc3dQualisys, GroundForcesAtAnalogSamplesMatchEzc3dsStatedValues) {
    // test_force_platform_filter: samples 0, 1000 and the last (3399), each printed to three
    // decimals and compared at decimal=3 (|a - b| < 1.5e-3 in N, N mm, mm), the tolerance used
    // here. Sample 1000 of plate 1 is mid-stance: the ground pushes the body up by 764 N (the
    // lab's Z is up: the markers stand at Z > 0 above the plates at Z = 0).
    const Table t = ground_forces_per_sample(*file_);
    ASSERT_EQ(t.row_count(), 3400u);
    const Ezc3dPlateSample plate1[] = {
        {0, {0.140, 0.046, -0.184}, {20.868, -4.623, -29.393}, {228.813, 118.296, 0}, {0, 0, -44.141}},
        {1000, {106.480, -66.407, 763.647}, {54768.655, -24103.676, -12229.124}, {285.564, 303.720, 0}, {0, 0, -2496.299}},
        {3399, {-0.140, -0.138, 0.367}, {51.780, 4.483, -29.960}, {241.787, 373.071, 0}, {0, 0, -51.390}},
    };
    const Ezc3dPlateSample plate2[] = {
        {0, {0.046, -0.185, 0.723}, {49.366, -96.907, 0.047}, {897.0422, 300.283, 0}, {0, 0, 27.944}},
        {1000, {0.232, -0.184, 0.361}, {68.671, -46.501, -19.720}, {891.673, 422.019, 0}, {0, 0, 48.016}},
        {3399, {0.185, -0.046, 0.542}, {16.708, 50.403, 30.122}, {670.044, 262.813, 0}, {0, 0, 31.545}},
    };
    for (const Ezc3dPlateSample& e : plate1) expect_ezc3d_sample(t, "ground_force", file_->plates[0], e, 1.5e-3, 0);
    for (const Ezc3dPlateSample& e : plate2) expect_ezc3d_sample(t, "1_ground_force", file_->plates[1], e, 1.5e-3, 0);
}

TEST_F(Ezc3dQualisys, PlateOneAtSampleZeroMatchesEzc3dToDoublePrecision) {
    // TEST(ForcePlatForm, Type2) states sample 0 of plate 1 with EXPECT_DOUBLE_EQ; the same
    // float channels in double arithmetic, in metres here, agree to a few units in the 15th
    // digit: within 1e-12 of each value's size (and 1e-12 where ezc3d's value is 0)
    const Table t = ground_forces_per_sample(*file_);
    const Ezc3dPlateSample e{0,
                             {0.13992118835449219, 0.046148300170898438, -0.18352508544921872},
                             {20.867615272954936, -4.622511359985765, -29.393223381101276},
                             {228.81266090518048, 118.29556977523387, 0.0},
                             {0.0, 0.0, -44.140528790099872}};
    expect_ezc3d_sample(t, "ground_force", file_->plates[0], e, 1e-12, 1e-12);
}

}  // namespace
}  // namespace alembert
