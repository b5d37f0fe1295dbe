// SPDX-License-Identifier: MIT
// read_c3d on files written by the test from the format description: markers, gaps, units,
// analog scaling, Intel, DEC and MIPS byte orders, integer and float data, force plates of
// types 1-4 against loads worked forward by hand (the moment of a force at a point), and
// truncated or corrupted files refused with a message, never a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "alembert/biomech/c3d_file.hpp"
#include "alembert/biomech/force_plate.hpp"
#include "alembert/error.hpp"
#include "c3d_writer.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;
using test::C3dPlateSpec;
using test::C3dProcessor;
using test::C3dSpec;
using Vec = std::array<double, 3>;

struct C3dScratch {
    fs::path dir = fs::temp_directory_path() / ("alembert_c3d_" + std::to_string(::getpid()));
    C3dScratch() { fs::create_directories(dir); }
    ~C3dScratch() { fs::remove_all(dir); }
    std::string write(const std::string& name, const C3dSpec& s) const {
        const std::string p = (dir / name).string();
        test::write_c3d(p, s);
        return p;
    }
    std::string write_bytes(const std::string& name, const std::string& bytes) const {
        const std::string p = (dir / name).string();
        std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return p;
    }
};

// three markers over 12 frames in mm, multiples of 0.1 mm; RASH not seen at frames 4-6
double marker_mm(std::size_t k, std::size_t i, int a) {
    return std::round(10 * (100.0 * static_cast<double>(i + 1) + (a == 0 ? 3.7 : a == 1 ? -1.3 : 0.9) * static_cast<double>(k) +
                            (a == 2 ? 850.0 : 0.0))) / 10;
}
C3dSpec marker_spec(C3dProcessor p, bool floats) {
    C3dSpec s;
    s.processor = p, s.floats = floats, s.scale = 0.1, s.rate = 120, s.first_frame = 7;
    s.labels = {"LASI", "RASI", "RASH"};
    for (std::size_t k = 0; k < 12; ++k) {
        s.points.emplace_back();
        s.valid.emplace_back();
        for (std::size_t i = 0; i < 3; ++i) {
            s.points.back().push_back({marker_mm(k, i, 0), marker_mm(k, i, 1), marker_mm(k, i, 2)});
            s.valid.back().push_back(!(i == 2 && k >= 3 && k <= 5));
        }
    }
    return s;
}

void expect_markers(const C3dFile& f, bool floats) {
    const MarkerTable& m = f.markers;
    ASSERT_EQ(m.markers, (std::vector<std::string>{"LASI", "RASI", "RASH"}));
    EXPECT_EQ(m.file_unit, "mm");
    EXPECT_EQ(m.data_rate_hz, 120);
    ASSERT_EQ(m.table.row_count(), 12u);
    // the first frame is 7: t = 6/120 s
    EXPECT_NEAR(m.table.columns[0][0], 6.0 / 120, 1e-15);
    EXPECT_NEAR(m.table.columns[0][11], 17.0 / 120, 1e-15);
    for (std::size_t k = 0; k < 12; ++k)
        for (std::size_t i = 0; i < 3; ++i)
            for (int a = 0; a < 3; ++a) {
                const double got = m.table.columns[m.column(m.markers[i], a)][k];
                if (i == 2 && k >= 3 && k <= 5) {
                    EXPECT_TRUE(std::isnan(got)) << k;  // a negative residual: a gap
                    continue;
                }
                const double mm = marker_mm(k, i, a);
                // floats: the stored float, exactly, in metres; integers: words of 0.1 mm
                // (the scale itself stored as a float)
                if (floats) EXPECT_EQ(got, static_cast<double>(static_cast<float>(mm)) * 1e-3);
                else EXPECT_NEAR(got, mm * 1e-3, 1e-7 * std::abs(mm) * 1e-3);
            }
}

TEST(ReadC3d, MarkersFromIntelDecAndMipsFilesFloatAndIntegerWithGapsAsNaN) {
    C3dScratch s;
    for (C3dProcessor p : {C3dProcessor::intel, C3dProcessor::dec, C3dProcessor::mips})
        for (bool floats : {true, false}) {
            SCOPED_TRACE(std::to_string(static_cast<int>(p)) + (floats ? " float" : " integer"));
            const C3dFile f = read_c3d(s.write("m.c3d", marker_spec(p, floats)));
            EXPECT_EQ(f.processor, p == C3dProcessor::intel ? "Intel" : p == C3dProcessor::dec ? "DEC" : "MIPS");
            EXPECT_EQ(f.float_data, floats);
            expect_markers(f, floats);
        }
}

TEST(ReadC3d, MetresStayMetresAndTwiceUsedLabelsAreRenamed) {
    C3dScratch s;
    C3dSpec spec = marker_spec(C3dProcessor::intel, true);
    spec.units = "m";
    spec.labels = {"KNEE", "KNEE", ""};
    const C3dFile f = read_c3d(s.write("m.c3d", spec));
    EXPECT_EQ(f.markers.markers, (std::vector<std::string>{"KNEE", "KNEE_2", "P3"}));
    EXPECT_EQ(f.markers.table.columns[f.markers.column("KNEE_2", 2)][0], static_cast<double>(static_cast<float>(marker_mm(0, 1, 2))));
    ASSERT_FALSE(f.notes.empty());
    EXPECT_NE(f.notes[0].find("the label 'KNEE' is used again by P2, read as 'KNEE_2'"), std::string::npos);
}

TEST(ReadC3d, AnalogChannelsAreOffsetScaledAndGenScaled) {
    // integer data: stored words w, OFFSET o, SCALE s, GEN_SCALE g give (w - o) s g
    C3dScratch s;
    C3dSpec spec = marker_spec(C3dProcessor::intel, false);
    spec.analog_labels = {"EMG1", "EMG2"};
    spec.analog_units = {"V", "V"};
    spec.analog_scale = {0.002, -0.5};
    spec.analog_offset = {100, -20};
    spec.gen_scale = 0.25;
    spec.analog_per_frame = 3;
    for (int j = 0; j < 36; ++j) spec.analog.push_back({static_cast<double>(100 + 7 * j), static_cast<double>(-20 - j)});
    const C3dFile f = read_c3d(s.write("a.c3d", spec));
    ASSERT_EQ(f.analog.names, (std::vector<std::string>{"time", "EMG1", "EMG2"}));
    EXPECT_EQ(f.analog_rate_hz, 360);
    EXPECT_EQ(f.analog_per_frame, 3u);
    ASSERT_EQ(f.analog.row_count(), 36u);
    for (std::size_t j = 0; j < 36; ++j) {
        // the SCALE values are floats in the file
        EXPECT_DOUBLE_EQ(f.analog.columns[1][j], 7.0 * static_cast<double>(j) * static_cast<float>(0.002) * 0.25);
        EXPECT_DOUBLE_EQ(f.analog.columns[2][j], -static_cast<double>(j) * -0.5 * 0.25);
        EXPECT_NEAR(f.analog.columns[0][j], 6.0 / 120 + static_cast<double>(j) / 360, 1e-12);
    }
}

// ---- frame counts ----------------------------------------------------------------------

bool has_note(const C3dFile& f, const std::string& text) {
    for (const std::string& n : f.notes)
        if (n.find(text) != std::string::npos) return true;
    return false;
}

TEST(ReadC3d, AHeaderThatOverstatesTheFramesIsReadByPointFramesOrTheWholeFramesTheFileEndsWith) {
    // the 12 frames of 48 bytes (3 points of 4 floats), from frame 7, unpadded: the data end
    // with the file after frame 18
    C3dScratch s;
    C3dSpec spec = marker_spec(C3dProcessor::intel, true);
    spec.pad_data = false;
    spec.header_frames = 1149, spec.param_frames = 1149;
    const C3dFile whole = read_c3d(s.write("whole.c3d", spec));
    expect_markers(whole, true);
    EXPECT_TRUE(has_note(whole, "the header gives 1149 frames (7 to 1155) and POINT:FRAMES 1149, but the file ends "
                                "after 12 whole frames; these are read, frames 7 to 18"));
    // POINT:FRAMES right, the header wrong: POINT:FRAMES frames, as ezc3d takes them
    spec.param_frames = 10;
    const C3dFile by_param = read_c3d(s.write("param.c3d", spec));
    ASSERT_EQ(by_param.markers.table.row_count(), 10u);
    EXPECT_NEAR(by_param.markers.table.columns[0].back(), 15.0 / 120, 1e-15);
    EXPECT_TRUE(has_note(by_param, "the header gives 1149 frames (7 to 1155), more than the data hold; POINT:FRAMES "
                                   "(10) is read, frames 7 to 16"));
    // padded to 1024 bytes of data: it ends 16 bytes into a 22nd frame, and both counts
    // overstate it: truncated
    spec.pad_data = true, spec.param_frames = 1149;
    EXPECT_THROW_MSG(read_c3d(s.write("cut.c3d", spec)), ArgumentError,
                     "the file holds 1149 frames (7 to 1155) of 48 bytes");
    // the header right, POINT:FRAMES not: the header's count, and a note
    spec.header_frames = 0, spec.param_frames = 30;
    const C3dFile by_header = read_c3d(s.write("header.c3d", spec));
    expect_markers(by_header, true);
    EXPECT_TRUE(has_note(by_header, "POINT:FRAMES is 30 but the header gives 12 frames (7 to 18); the header's count "
                                    "is read"));
}

// ---- force plates ------------------------------------------------------------------------

// A 600 x 400 mm plate in a z-up lab, its surface in the floor Z = 0, centred at S (mm), its
// axes x = X, y = -Y, z = -Z (down, as a plate's z is): corner 1 in its +x +y quadrant.
constexpr double kSx = 250, kSy = 700;
C3dPlateSpec floor_plate(int type, std::array<double, 3> origin, int first_channel) {
    C3dPlateSpec p;
    p.type = type;
    p.corners = {kSx + 300, kSy - 200, 0, kSx - 300, kSy - 200, 0, kSx - 300, kSy + 200, 0, kSx + 300, kSy + 200, 0};
    p.origin = origin;
    for (int c = 0; c < (type == 3 ? 8 : 6); ++c) p.channels.push_back(first_channel + c);
    return p;
}
// the plate's components of a lab vector (R^T v with R = [X, -Y, -Z])
Vec in_plate(const Vec& v) { return {v[0], -v[1], -v[2]}; }
Vec cross3(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// A load on the body: the ground reaction G (N, lab) at the centre of pressure Q (m, on the
// floor) and the free moment tau (N m about Z).
struct BodyLoad {
    Vec G, Q;
    double tau;
};
// What a type 2 plate records of it, in its axes: the reaction on the body, G at Q with the
// couple tau Z (the convention of C3D files: a plate's Fz, along its downward z, is negative
// under a standing subject); its moment about the plate's origin O = S - R ORIGIN is
// (Q - O) x G + tau Z. Forces in N, moments in N mm.
std::array<double, 6> type2_channels(const BodyLoad& b, const std::array<double, 3>& origin_mm) {
    const Vec O{(kSx - origin_mm[0]) / 1000, (kSy + origin_mm[1]) / 1000, origin_mm[2] / 1000};
    const Vec F = b.G;
    Vec M = cross3({b.Q[0] - O[0], b.Q[1] - O[1], b.Q[2] - O[2]}, F);
    M[2] += b.tau;
    const Vec f = in_plate(F), m = in_plate(M);
    return {f[0], f[1], f[2], 1000 * m[0], 1000 * m[1], 1000 * m[2]};
}

C3dSpec plate_spec(int per_frame) {
    C3dSpec s;
    s.rate = 100;
    s.labels = {"HEEL"};
    for (int k = 0; k < 10; ++k) {
        s.points.push_back({{100.0 + k, 200, 30}});
    }
    s.analog_per_frame = per_frame;
    return s;
}
void add_channels(C3dSpec& s, const std::string& stem) {
    for (const char* c : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
        s.analog_labels.push_back(stem + c);
        s.analog_units.push_back(c[0] == 'F' ? "N" : "Nmm");
        s.analog_scale.push_back(1);
        s.analog_offset.push_back(0);
    }
}

void expect_load(const Table& forces, const std::string& prefix, std::size_t row, const BodyLoad& b, double tol_F,
                 double tol_p) {
    const std::string torque = prefix.substr(0, prefix.find("force")) + "torque";
    for (int a = 0; a < 3; ++a) {
        const std::string axis = std::string(1, "xyz"[a]);
        EXPECT_NEAR(forces.columns[forces.column_index(prefix + "_v" + axis)][row], b.G[static_cast<std::size_t>(a)], tol_F)
            << prefix << " v" << axis << " row " << row;
        EXPECT_NEAR(forces.columns[forces.column_index(prefix + "_p" + axis)][row], b.Q[static_cast<std::size_t>(a)], tol_p)
            << prefix << " p" << axis << " row " << row;
        EXPECT_NEAR(forces.columns[forces.column_index(torque + "_" + axis)][row], a == 2 ? b.tau : 0.0, tol_F)
            << torque << axis << " row " << row;
    }
}

TEST(ReadC3dPlates, AType2PlateWorkedByHand) {
    // The plate centred at the lab's origin, ORIGIN (0, 0, -40) mm: the body pushed up by
    // 800 N at (0.1, 0.05, 0) m. The plate records that reaction, (0, 0, 800) N in the lab,
    // (0, 0, -800) N in its axes (its z down); about O = (0, 0, -0.04) m its moment is
    // (0.1, 0.05, 0.04) x (0, 0, 800) = (40, -80, 0) N m in the lab, (40, 80, 0) in its axes.
    // Then px = (oz Fx - My) / Fz = -80 / -800 = 0.1 and py = (Mx + oz Fy) / Fz = 40 / -800 =
    // -0.05 in its axes: (0.1, 0.05) in the lab.
    C3dScratch s;
    C3dSpec spec = plate_spec(1);
    add_channels(spec, "");
    C3dPlateSpec p = floor_plate(2, {0, 0, -40}, 1);
    p.corners = {300, -200, 0, -300, -200, 0, -300, 200, 0, 300, 200, 0};
    spec.plates = {p};
    for (int j = 0; j < 10; ++j) spec.analog.push_back({0, 0, -800, 40000, 80000, 0});
    const C3dFile f = read_c3d(s.write("hand.c3d", spec));
    expect_load(f.forces, "ground_force", 4, {{0, 0, 800}, {0.1, 0.05, 0}, 0}, 1e-9, 1e-12);
}

TEST(ReadC3dPlates, Type2And4PlatesGiveBackTheLoadInIntelDecAndMipsFiles) {
    // plate 1 type 2, plate 2 type 4 with a calibration matrix that is not the identity: its
    // channels are C^-1 (F, M), so that C times them is the plate's load
    const std::array<double, 3> origin1{1.5, -2, -41.3}, origin2{-0.8, 0.6, -38};
    std::array<double, 36> C{};
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) C[static_cast<std::size_t>(r + 6 * c)] = (r == c ? 1.0 + 0.1 * r : 0.0) + 0.02 * (r - c) + 0.01 * ((r * c) % 4);
    auto solve = [&](std::array<double, 6> b) {  // C x = b by Gauss elimination with pivoting
        double A[6][7];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 6; ++c) A[r][c] = C[static_cast<std::size_t>(r + 6 * c)];
            A[r][6] = b[static_cast<std::size_t>(r)];
        }
        for (int c = 0; c < 6; ++c) {
            int piv = c;
            for (int r = c + 1; r < 6; ++r)
                if (std::abs(A[r][c]) > std::abs(A[piv][c])) piv = r;
            std::swap(A[c], A[piv]);
            for (int r = 0; r < 6; ++r)
                if (r != c) {
                    const double m = A[r][c] / A[c][c];
                    for (int k = c; k < 7; ++k) A[r][k] -= m * A[c][k];
                }
        }
        std::array<double, 6> x{};
        for (int r = 0; r < 6; ++r) x[static_cast<std::size_t>(r)] = A[r][6] / A[r][r];
        return x;
    };
    auto load1 = [](double t) { return BodyLoad{{25 + 40 * t, -12, 650 + 100 * t}, {0.31, 0.66, 0}, 1.5 - t}; };
    auto load2 = [](double t) { return BodyLoad{{-8, 30 * t, 420}, {0.2, 0.75, 0}, -0.7}; };
    for (C3dProcessor proc : {C3dProcessor::intel, C3dProcessor::dec, C3dProcessor::mips}) {
        SCOPED_TRACE(static_cast<int>(proc));
        C3dScratch s;
        C3dSpec spec = plate_spec(4);  // analog at 400 Hz
        spec.processor = proc;
        add_channels(spec, "A");
        add_channels(spec, "B");
        C3dPlateSpec p2 = floor_plate(4, origin2, 7);
        p2.cal_matrix.assign(C.begin(), C.end());
        spec.plates = {floor_plate(2, origin1, 1), p2};
        for (int j = 0; j < 40; ++j) {
            const double t = j / 400.0;
            const std::array<double, 6> a = type2_channels(load1(t), origin1);
            const std::array<double, 6> b = solve(type2_channels(load2(t), origin2));
            spec.analog.push_back({a[0], a[1], a[2], a[3], a[4], a[5], b[0], b[1], b[2], b[3], b[4], b[5]});
        }
        const C3dFile f = read_c3d(s.write("plates.c3d", spec));
        ASSERT_EQ(f.plates.size(), 2u);
        EXPECT_EQ(f.plates[1].type, 4);
        // the loads vary linearly in time: a frame's centred average is its value, exact inside
        // the trial; the channels are floats (7 digits): forces to 1e-3 N, centres to 1e-5 m
        for (std::size_t k = 1; k + 1 < 10; ++k) {
            const double t = static_cast<double>(k) / 100;
            expect_load(f.forces, "ground_force", k, load1(t), 2e-3, 2e-5);
            expect_load(f.forces, "1_ground_force", k, load2(t), 2e-3, 2e-5);
        }
        // the first frame averages the samples from its time on only (half a frame of them)
        const double t0 = (0 * 1.0 + 1 * 1.0 + 2 * 0.5) / (1 + 1 + 0.5) / 400;  // samples 0, 1, 2 (half)
        expect_load(f.forces, "ground_force", 0, load1(t0), 2e-3, 2e-5);
        // the table feeds the plates' path as a .mot does
        const ForcePlate fp = force_plate_from_table(f.forces, "1_ground_force", 20, "plates.c3d");
        EXPECT_NEAR(fp.F[2][5], 420, 2e-3);
    }
}

TEST(ReadC3dPlates, Type3SensorsAndType1CentreOfPressureGiveBackTheLoad) {
    C3dScratch s;
    C3dSpec spec = plate_spec(1);
    const std::array<double, 3> o3{210, 160, -45};  // sensors at (±210, ±160) mm, 45 mm below
    const BodyLoad b3{{14, -9, 610}, {0.34, 0.62, 0}, 0.8}, b1{{-6, 11, 380}, {0.18, 0.79, 0}, -1.1};
    // type 3: the reaction about the sensors' centre O = S + 0.045 m down, shared by
    // four sensors 1 (+a, +b), 2 (-a, +b), 3 (-a, -b), 4 (+a, -b): the shear halves in y, the
    // x shear split so the pairs give Mz, the vertical loads so that they give Fz, Mx, My
    const std::array<double, 6> fm = type2_channels(b3, {0, 0, o3[2]});
    const double a = o3[0] / 1000, bb = o3[1] / 1000;
    const double Fx = fm[0], Fy = fm[1], Fz = fm[2], Mx = fm[3] / 1000, My = fm[4] / 1000, Mz = fm[5] / 1000;
    const double fy14 = Fy / 2, fy23 = Fy / 2;
    const double fx34 = (Fx + (Mz - a * (fy14 - fy23)) / bb) / 2, fx12 = Fx - fx34;
    const double u = Mx / bb, v = My / a;
    const std::vector<double> sensors{fx12, fx34, fy14, fy23, (Fz + u - v) / 4, (Fz + u + v) / 4, (Fz - u + v) / 4,
                                      (Fz - u - v) / 4};
    // type 1: Fx, Fy, Fz, the centre of pressure from S in the plate's axes (mm), Tz (N mm)
    const Vec f1 = in_plate(b1.G);
    const Vec p1 = in_plate({b1.Q[0] * 1000 - kSx, b1.Q[1] * 1000 - kSy, 0});
    const std::vector<double> type1{f1[0], f1[1], f1[2], p1[0], p1[1], -1000 * b1.tau};  // tau Z is -tau z
    for (int c = 0; c < 14; ++c) {
        spec.analog_labels.push_back("C" + std::to_string(c + 1));
        spec.analog_units.push_back(c == 11 || c == 12 ? "mm" : c == 13 ? "Nmm" : "N");
        spec.analog_scale.push_back(1), spec.analog_offset.push_back(0);
    }
    spec.plates = {floor_plate(3, o3, 1), floor_plate(1, {0, 0, 0}, 9)};
    for (int j = 0; j < 10; ++j) {
        std::vector<double> row = sensors;
        row.insert(row.end(), type1.begin(), type1.end());
        spec.analog.push_back(row);
    }
    const C3dFile f = read_c3d(s.write("t13.c3d", spec));
    expect_load(f.forces, "ground_force", 3, b3, 2e-3, 2e-5);
    expect_load(f.forces, "1_ground_force", 3, b1, 2e-3, 2e-5);
}

TEST(ReadC3dPlates, TheZeroFramesAreTheBaselineAndSaidSo) {
    // frames 1-3 unloaded read 5 N on Fz and 200 N mm on Mx (drift); the load from frame 4 on
    C3dScratch s;
    C3dSpec spec = plate_spec(2);
    add_channels(spec, "");
    spec.plates = {floor_plate(2, {0, 0, -40}, 1)};
    spec.zero = {1, 3};
    const BodyLoad b{{10, 20, 700}, {0.3, 0.72, 0}, 0.4};
    const std::array<double, 6> c = type2_channels(b, {0, 0, -40});
    for (int j = 0; j < 20; ++j) {
        const bool on = j >= 8;
        spec.analog.push_back({on ? c[0] : 0, on ? c[1] : 0, (on ? c[2] : 0) + 5, (on ? c[3] : 0) + 200, on ? c[4] : 0,
                               on ? c[5] : 0});
    }
    const C3dFile f = read_c3d(s.write("zero.c3d", spec));
    expect_load(f.forces, "ground_force", 6, b, 2e-3, 2e-5);
    ASSERT_FALSE(f.notes.empty());
    EXPECT_NE(f.notes.back().find("force plate 1: each channel's mean over frames 1 to 3 (FORCE_PLATFORM:ZERO) subtracted"),
              std::string::npos);
}

// ---- bad files -----------------------------------------------------------------------------

C3dSpec small_trial() {
    C3dSpec spec = plate_spec(2);
    add_channels(spec, "");
    spec.plates = {floor_plate(2, {0, 0, -40}, 1)};
    for (int j = 0; j < 20; ++j) spec.analog.push_back({1, 2, 700, 3, 4, 5});
    return spec;
}

TEST(ReadC3dErrors, EachNamesTheFileWhatIsWrongAndWhere) {
    C3dScratch s;
    const std::string good = test::c3d_bytes(small_trial());
    // truncated inside the data: the frame and the byte
    const std::string cut = s.write_bytes("cut.c3d", good.substr(0, 1024 + 512 + 100));
    EXPECT_THROW_MSG(read_c3d(cut), ArgumentError, "cut.c3d: the file holds 10 frames (1 to 10)");
    EXPECT_THROW_MSG(read_c3d(cut), ArgumentError, "the file is truncated");
    // the parameter block past the end
    std::string far = good;
    far[0] = static_cast<char>(200);
    EXPECT_THROW_MSG(read_c3d(s.write_bytes("far.c3d", far)), ArgumentError,
                     "far.c3d: the header puts the parameter section at block 200 (byte 101888), past the end of the file");
    // an unknown processor type
    std::string proc = good;
    proc[512 + 3] = 83;
    EXPECT_THROW_MSG(read_c3d(s.write_bytes("proc.c3d", proc)), ArgumentError,
                     "proc.c3d: unknown processor type 83; C3D files are written for 84 (Intel), 85 (DEC) or 86 (MIPS)");
    EXPECT_THROW_MSG(read_c3d(s.write_bytes("proc.c3d", proc)), ArgumentError, "(byte 515)");
    // a plate type not read
    C3dSpec five = small_trial();
    five.plates[0].type = 5;
    EXPECT_THROW_MSG(read_c3d(s.write("five.c3d", five)), ArgumentError,
                     "five.c3d: force plate 1 is of type 5, which this reader does not compute");
    // a text file
    EXPECT_THROW_MSG(read_c3d(s.write_bytes("text.c3d", std::string(600, 'a'))), ArgumentError,
                     "not a C3D file: its second byte is 97");
    EXPECT_THROW_MSG(read_c3d((s.dir / "none.c3d").string()), ArgumentError, "cannot open");
}

TEST(ReadC3dErrors, TruncatedAndCorruptedCopiesAreRefusedOrReadNeverACrash) {
    // every length of the file, and 3000 copies with one to four bytes changed at random
    // (a fixed seed): each is read or refused with an ArgumentError naming the file
    C3dScratch s;
    const std::string good = test::c3d_bytes(small_trial());
    std::size_t refused = 0, read = 0;
    auto attempt = [&](const std::string& bytes) {
        const std::string p = s.write_bytes("bad.c3d", bytes);
        try {
            const C3dFile f = read_c3d(p);
            ++read;
            EXPECT_EQ(f.markers.table.columns.size(), 1 + 3 * f.markers.markers.size());
        } catch (const ArgumentError& e) {
            ++refused;
            EXPECT_EQ(std::string(e.what()).find(p), 0u) << e.what();
        }
    };
    for (std::size_t n = 0; n < good.size(); n += 7) attempt(good.substr(0, n));
    std::mt19937 rng(12345);
    for (int i = 0; i < 3000; ++i) {
        std::string bytes = good;
        const int changes = 1 + static_cast<int>(rng() % 4);
        for (int c = 0; c < changes; ++c) {
            // mostly in the header and parameter section, where the structure is
            const std::size_t at = rng() % 3 == 0 ? rng() % bytes.size() : rng() % 1024;
            bytes[at] = static_cast<char>(rng() & 0xFF);
        }
        attempt(bytes);
    }
    EXPECT_GT(refused, 100u);
    EXPECT_GT(read, 100u);
}

}  // namespace
}  // namespace alembert
