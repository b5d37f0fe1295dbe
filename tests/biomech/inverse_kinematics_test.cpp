// SPDX-License-Identifier: MIT
// Inverse kinematics of a spatial leg and a planar chain against markers made from known
// coordinates by independent rotation matrices.
#include "alembert/biomech/inverse_kinematics.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

#include "alembert/biomech/segment_angles.hpp"
#include "alembert/error.hpp"
#include "spatial_leg.hpp"
#include "support/expect.hpp"

namespace alembert::ik_test {
namespace {

using namespace alembert::test;

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// a marker table of `names` at 100 Hz from positions per frame
MarkerTable marker_table(const std::vector<std::string>& names,
                         const std::vector<std::vector<Eigen::Vector3d>>& p) {
    MarkerTable m;
    m.markers = names;
    m.data_rate_hz = 100;
    m.file_unit = "m";
    m.table.add_column("time", "s");
    for (const auto& n : names)
        for (const char* a : {".X", ".Y", ".Z"}) m.table.add_column(n + a, "m");
    for (std::size_t k = 0; k < p.size(); ++k) {
        m.table.columns[0].push_back(static_cast<double>(k) / 100.0);
        for (std::size_t i = 0; i < names.size(); ++i)
            for (int a = 0; a < 3; ++a) m.table.columns[1 + 3 * i + a].push_back(p[k][i](a));
    }
    return m;
}

// the leg's markers over `frames` frames of leg_motion, and the coordinates that made them
struct Trial {
    MarkerTable markers;
    std::vector<std::vector<double>> q;
};

Trial leg_trial(std::size_t frames) {
    Trial trial;
    std::vector<std::vector<Eigen::Vector3d>> p;
    for (std::size_t k = 0; k < frames; ++k) {
        trial.q.push_back(leg_motion(static_cast<double>(k) / 100.0));
        p.push_back(leg_markers_by_hand(trial.q.back()));
    }
    trial.markers = marker_table(kLegMarkerNames, p);
    return trial;
}

double largest_coordinate_error(const InverseKinematicsResult& r, const Trial& trial) {
    double e = 0;
    for (std::size_t k = 0; k < r.frames.size(); ++k)
        for (std::size_t j = 0; j < trial.q[k].size(); ++j)
            e = std::max(e, std::abs(r.frames[k].q[j] - trial.q[k][j]));
    return e;
}

TEST(InverseKinematics, ModelMarkerPositionsMatchRotationMatricesComposedByHand) {
    auto leg = make_leg();
    InverseKinematics ik(leg->system, leg->q, leg->markers);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<double> q(9);
        for (double& v : q) v = u(random);
        const std::vector<double> p = ik.calc_marker_positions(q);
        const std::vector<Eigen::Vector3d> p_hand = leg_markers_by_hand(q);
        for (std::size_t i = 0; i < 9; ++i)
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(p[3 * i + a], p_hand[i](a), 1e-14);
    }
}

TEST(InverseKinematics, RecoversTheCoordinatesOfASpatialLegFromExactMarkers) {
    auto leg = make_leg();
    const Trial trial = leg_trial(200);
    // the first frame starts from the reference pose (all zero), 0.9 m and 0.6 rad away
    const InverseKinematicsResult r =
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers);
    ASSERT_EQ(r.frames.size(), 200u);
    EXPECT_LT(largest_coordinate_error(r, trial), 1e-9);
    for (const auto& f : r.frames) {
        EXPECT_LT(f.max, 1e-9);
        EXPECT_LE(f.rms, f.max);
        EXPECT_TRUE(f.missing.empty());
    }
    EXPECT_GT(r.frames[0].iterations, r.frames[1].iterations);  // later frames start close
    const std::vector<std::string> units = {"m",   "m",   "m",   "rad", "rad",
                                            "rad", "rad", "rad", "rad"};
    EXPECT_EQ(r.units, units);
    const Table q = r.calc_coordinate_table();
    EXPECT_EQ(q.names[1], "tx");
    EXPECT_EQ(q.units[4], "rad");
    EXPECT_EQ(q.columns[7][10], r.frames[10].q[6]);
    EXPECT_TRUE(r.gaps.empty());
}

TEST(InverseKinematics, MarkerNoiseOfKnownSizeGivesResidualsOfThatSize) {
    // Gaussian noise sigma = 1 mm on each marker coordinate. A linearized least-squares fit of
    // n = 9 coordinates to 3 m = 27 measurements leaves residuals whose sum of squares is
    // sigma^2 chi^2(27 - 9), so the mean over frames of rms^2 = (sum of squares) / m tends to
    // sigma^2 (3 m - n) / m = 2 sigma^2; over 200 frames (3600 degrees of freedom) its relative
    // standard deviation is sqrt(2 / 3600) = 2.4 % (1.2 % for its square root, for which we
    // allow 5 %). The coordinates' errors
    // dq have covariance sigma^2 (J^T J)^-1, so dq^T J^T J dq / sigma^2 averages n = 9 (1800
    // degrees of freedom, 3.3 %; we allow 15 %).
    auto leg = make_leg();
    Trial trial = leg_trial(200);
    const double sigma = 1e-3;
    std::mt19937 random(11);
    std::normal_distribution<double> noise(0, sigma);
    for (std::size_t c = 1; c < trial.markers.table.columns.size(); ++c)
        for (double& v : trial.markers.table.columns[c]) v += noise(random);
    InverseKinematics ik(leg->system, leg->q, leg->markers);
    const InverseKinematicsResult r = ik.solve(trial.markers);
    double rms2 = 0, chi2_q = 0;
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
        const auto& f = r.frames[k];
        rms2 += f.rms * f.rms;
        // J at the true coordinates by central differences of the model's positions
        Eigen::MatrixXd J(27, 9);
        for (int j = 0; j < 9; ++j) {
            std::vector<double> qp = trial.q[k], qm = trial.q[k];
            qp[j] += 1e-6, qm[j] -= 1e-6;
            const std::vector<double> pp = ik.calc_marker_positions(qp),
                                      pm = ik.calc_marker_positions(qm);
            for (int i = 0; i < 27; ++i) J(i, j) = (pp[i] - pm[i]) / 2e-6;
        }
        Eigen::VectorXd dq(9);
        for (int j = 0; j < 9; ++j) dq(j) = f.q[j] - trial.q[k][j];
        chi2_q += dq.dot(J.transpose() * J * dq) / (sigma * sigma);
    }
    const double frames = static_cast<double>(r.frames.size());
    EXPECT_NEAR(std::sqrt(rms2 / frames), sigma * std::sqrt(2.0), 0.05 * sigma * std::sqrt(2.0));
    EXPECT_NEAR(chi2_q / frames, 9.0, 9.0 * 0.15);
    // a residual is a distance of a 3D error: far below 6 sigma everywhere
    for (const auto& f : r.frames) EXPECT_LT(f.max, 6 * sigma);
}

TEST(InverseKinematics, AMissingMarkerStretchIsSkippedNotZeroAndNamed) {
    auto leg = make_leg();
    Trial trial = leg_trial(200);
    // T2 unseen for frames 50-69 (t = 0.5 to 0.69 s), S3 for frames 120-124
    auto hide = [&](const std::string& name, std::size_t from, std::size_t to) {
        for (int a = 0; a < 3; ++a)
            for (std::size_t k = from; k <= to; ++k)
                trial.markers.table.columns[trial.markers.column(name, a)][k] = kNaN;
    };
    hide("T2", 50, 69);
    hide("S3", 120, 124);
    const InverseKinematicsResult r =
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers);
    EXPECT_LT(largest_coordinate_error(r, trial), 1e-9);
    EXPECT_EQ(r.frames[49].missing.size(), 0u);
    ASSERT_EQ(r.frames[50].missing.size(), 1u);
    EXPECT_EQ(r.frames[50].missing[0], "T2");
    EXPECT_TRUE(std::isnan(r.frames[60].residual[1]));
    EXPECT_FALSE(std::isnan(r.frames[60].residual[0]));
    EXPECT_EQ(r.frames[122].missing, std::vector<std::string>{"S3"});
    ASSERT_EQ(r.gaps.size(), 2u);
    EXPECT_EQ(r.gaps[0].name, "T2");
    EXPECT_EQ(r.gaps[0].samples, 20u);
    EXPECT_DOUBLE_EQ(r.gaps[0].t_first, 0.5);
    EXPECT_DOUBLE_EQ(r.gaps[0].t_last, 0.69);
    EXPECT_EQ(r.gaps[1].name, "S3");
    const std::string text = r.describe();
    EXPECT_NE(text.find("'T2' is missing from t = 0.5 s to 0.69 s (20 frames)"), std::string::npos)
        << text;
    EXPECT_NE(text.find("'S3' is missing from t = 1.2 s to 1.24 s (5 frames)"), std::string::npos)
        << text;
    const Table residuals = r.calc_residual_table();
    EXPECT_EQ(residuals.names[2], "T2");
    EXPECT_TRUE(std::isnan(residuals.columns[2][55]));
    EXPECT_EQ(residuals.names.back(), "max");
}

TEST(InverseKinematics, ReadsTheMarkersOfAnOpenSimTrcFileInMillimetres) {
    // the trial written as a lab's .trc (mm, tab-separated, 17 significant digits), one cell
    // of T2 left empty, read back by read_trc: the fit is in metres whatever the file's unit
    auto leg = make_leg();
    const Trial trial = leg_trial(50);
    namespace fs = std::filesystem;
    const fs::path path =
        fs::temp_directory_path() / ("alembert_ik_test_" + std::to_string(::getpid()) + ".trc");
    {
        std::ofstream out(path);
        out << "PathFileType\t4\t(X/Y/Z)\tleg.trc\n"
            << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\t"
               "OrigDataStartFrame\tOrigNumFrames\n"
            << "100\t100\t50\t9\tmm\t100\t1\t50\nFrame#\tTime";
        for (const auto& name : kLegMarkerNames) out << "\t" << name << "\t\t";
        out << "\n\t";
        for (std::size_t i = 1; i <= 9; ++i) out << "\tX" << i << "\tY" << i << "\tZ" << i;
        out << "\n\n";
        char cell[64];
        for (std::size_t k = 0; k < 50; ++k) {
            out << k + 1 << "\t" << static_cast<double>(k) / 100.0;
            for (std::size_t c = 1; c < trial.markers.table.columns.size(); ++c) {
                std::snprintf(cell, sizeof cell, "%.17g", 1000 * trial.markers.table.columns[c][k]);
                out << "\t" << (k == 20 && c >= 4 && c <= 6 ? "" : cell);
            }
            out << "\n";
        }
    }
    const MarkerTable markers = read_trc(path.string());
    fs::remove(path);
    const InverseKinematicsResult r =
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, markers);
    EXPECT_LT(largest_coordinate_error(r, trial), 1e-9);
    EXPECT_EQ(r.frames[20].missing, std::vector<std::string>{"T2"});
}

TEST(InverseKinematics, AWeightCountsAsThatManyCopiesOfTheMarker) {
    // with noisy markers the fit depends on the weights: weight 2 on T1 gives the same
    // coordinates as T1 listed twice (a second model marker "T1b" on the same point, reading a
    // copy of T1's columns), and differs from weight 1
    auto leg = make_leg();
    Trial trial = leg_trial(20);
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0, 2e-3);
    for (std::size_t c = 1; c < trial.markers.table.columns.size(); ++c)
        for (double& v : trial.markers.table.columns[c]) v += noise(random);
    MarkerTable doubled = trial.markers;
    doubled.markers.push_back("T1b");
    for (int a = 0; a < 3; ++a)
        doubled.table.add_column(std::string("T1b.") + "XYZ"[a], "m"),
            doubled.table.columns.back() =
                trial.markers.table.columns[trial.markers.column("T1", a)];
    std::vector<MarkerPoint> weighted = leg->markers, copied = leg->markers;
    weighted[0].weight = 2;
    copied.push_back({"T1b", leg->markers[0].point, 1.0});
    const InverseKinematicsResult r_w =
        calc_inverse_kinematics(leg->system, leg->q, weighted, trial.markers);
    const InverseKinematicsResult r_c =
        calc_inverse_kinematics(leg->system, leg->q, copied, doubled);
    const InverseKinematicsResult r_1 =
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers);
    double same = 0, differ = 0;
    for (std::size_t k = 0; k < 20; ++k)
        for (std::size_t j = 0; j < 9; ++j) {
            same = std::max(same, std::abs(r_w.frames[k].q[j] - r_c.frames[k].q[j]));
            differ = std::max(differ, std::abs(r_w.frames[k].q[j] - r_1.frames[k].q[j]));
        }
    EXPECT_LT(same, 1e-10);
    EXPECT_GT(differ, 1e-5);
    // residuals are distances, not weighted: T1's is the same in both
    EXPECT_NEAR(r_w.frames[5].residual[0], r_c.frames[5].residual[0], 1e-12);
}

TEST(InverseKinematics, PlanarChainAgreesWithTwoMarkerSegmentAngles) {
    // a sagittal thigh and leg: hip H at (x, y); the thigh at absolute angle qT (the line from
    // knee to hip, as Winter measures it), the leg at qK relative to it (the line from ankle
    // to knee at qT + qK); markers at hip, knee and ankle, and one off each segment's line
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y"), qT = s.add_variable("qT"),
                 qK = s.add_variable("qK");
    RigidBody& T = sys.add_rigid_body("T");
    RigidBody& L = sys.add_rigid_body("L");
    T.body_frame().orient_axis(N, Axis::z, qT);
    L.body_frame().orient_axis(T.body_frame(), Axis::z, qK);
    Point& HIP = sys.add_point("HIP", &T);
    HIP.set_pos(sys.origin(), ex(x) * N.x() + ex(y) * N.y());
    Point& KNEE = sys.add_point("KNEE", &L);
    KNEE.set_pos(HIP, ex(-kThigh) * T.body_frame().x());
    Point& ANKLE = sys.add_point("ANKLE", &L);
    ANKLE.set_pos(KNEE, ex(-kShank) * L.body_frame().x());
    Point& THI = sys.add_point("THI", &T);
    THI.set_pos(HIP, ex(-0.2) * T.body_frame().x() + ex(0.05) * T.body_frame().y());
    std::vector<MarkerPoint> markers = {
        {"HIP", &HIP, 1.0}, {"KNEE", &KNEE, 1.0}, {"ANKLE", &ANKLE, 1.0}, {"THI", &THI, 1.0}};
    // a squat-like motion, markers from cosines and sines by hand
    std::vector<std::vector<Eigen::Vector3d>> p;
    for (int k = 0; k < 100; ++k) {
        const double t = 0.01 * k, xh = 0.1 * t, yh = 0.9 - 0.2 * t;
        const double th = kPi / 2 + 1.2 * t, tk = -0.3 - 1.5 * t;  // thigh up, leg turning
        const Eigen::Vector3d hip(xh, yh, 0);
        const Eigen::Vector3d knee = hip - kThigh * Eigen::Vector3d(std::cos(th), std::sin(th), 0);
        const Eigen::Vector3d ankle =
            knee - kShank * Eigen::Vector3d(std::cos(th + tk), std::sin(th + tk), 0);
        const Eigen::Vector3d thi = hip - 0.2 * Eigen::Vector3d(std::cos(th), std::sin(th), 0) +
                                    0.05 * Eigen::Vector3d(-std::sin(th), std::cos(th), 0);
        p.push_back({hip, knee, ankle, thi});
    }
    const MarkerTable table = marker_table({"HIP", "KNEE", "ANKLE", "THI"}, p);
    InverseKinematicsOptions options;
    options.initial = {0, 1, 1.5, 0};  // the thigh upright, near the first frame
    const InverseKinematicsResult r =
        calc_inverse_kinematics(sys, {x, y, qT, qK}, markers, table, options);
    const std::vector<double> theta_thigh = calc_segment_angle(table, "KNEE", "HIP");
    const std::vector<double> theta_leg = calc_segment_angle(table, "ANKLE", "KNEE");
    const std::vector<double> knee = calc_joint_angle(theta_thigh, theta_leg, +1);
    for (std::size_t k = 0; k < 100; ++k) {
        EXPECT_NEAR(r.frames[k].q[2], theta_thigh[k], 1e-9);
        EXPECT_NEAR(r.frames[k].q[3], knee[k], 1e-9);
    }
}

TEST(InverseKinematics, TwoThreadsSolvingWithOneObjectGetTheAnswerOfOne) {
    auto leg = make_leg();
    const Trial trial = leg_trial(100);
    const InverseKinematics ik(leg->system, leg->q, leg->markers);
    const InverseKinematicsResult alone = ik.solve(trial.markers);
    InverseKinematicsResult a, b;
    std::thread ta([&] { a = ik.solve(trial.markers); });
    std::thread tb([&] { b = ik.solve(trial.markers); });
    ta.join();
    tb.join();
    for (std::size_t k = 0; k < alone.frames.size(); ++k) {
        EXPECT_EQ(a.frames[k].q, alone.frames[k].q);
        EXPECT_EQ(b.frames[k].q, alone.frames[k].q);
    }
}

TEST(InverseKinematics, AModelMarkerNotInTheFileIsNamed) {
    auto leg = make_leg();
    Trial trial = leg_trial(3);
    trial.markers.markers[8] = "TOE";
    EXPECT_THROW_MSG(
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers), ArgumentError,
        "model marker 'F3' is not in the marker file (its markers: 'T1', 'T2', 'T3', 'S1'");
}

TEST(InverseKinematics, FewerMarkerCoordinatesThanCoordinatesIsUnderDetermined) {
    auto leg = make_leg();
    std::vector<MarkerPoint> two = {leg->markers[0], leg->markers[1]};
    EXPECT_THROW_MSG(InverseKinematics(leg->system, leg->q, two), ModelError,
                     "under-determined: 2 markers give 6 measured coordinates, fewer than the 9 "
                     "coordinates; the markers do not fix");
}

TEST(InverseKinematics, MarkersThatLeaveTheFootFreeNameItsCoordinates) {
    // thigh and shank markers (18 measured coordinates for 9) cannot fix the ankle's angles
    auto leg = make_leg();
    std::vector<MarkerPoint> no_foot(leg->markers.begin(), leg->markers.begin() + 6);
    EXPECT_THROW_MSG(InverseKinematics(leg->system, leg->q, no_foot), ModelError,
                     "under-determined: the markers' positions do not change along a "
                     "combination of coordinates; the markers do not fix 'qA1', 'qA2'; add "
                     "markers");
}

TEST(InverseKinematics, AFrameWhoseGapsLeaveCoordinatesFreeIsNamed) {
    auto leg = make_leg();
    Trial trial = leg_trial(20);
    for (const char* name : {"F1", "F2", "F3"})
        for (int a = 0; a < 3; ++a)
            trial.markers.table.columns[trial.markers.column(name, a)][10] = kNaN;
    EXPECT_THROW_MSG(
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers), SolveError,
        "at frame 11 (t = 0.1 s) the markers present ('F1', 'F2', 'F3' missing) do not fix "
        "'qA1', 'qA2'; fill the gaps first");
}

TEST(InverseKinematics, AFrameThatDoesNotConvergeIsNamedWithItsTime) {
    auto leg = make_leg();
    const Trial trial = leg_trial(5);
    InverseKinematicsOptions options;
    options.max_iterations = 2;  // the first frame starts 0.9 m away
    EXPECT_THROW_MSG(
        calc_inverse_kinematics(leg->system, leg->q, leg->markers, trial.markers, options),
        SolveError, "frame 1 (t = 0 s) did not converge in 2 iterations");
}

TEST(InverseKinematics, MalformedModelsAreRefusedWithTheirNames) {
    auto leg = make_leg();
    std::vector<ex> eight(leg->q.begin(), leg->q.end() - 1);
    EXPECT_THROW_MSG(InverseKinematics(leg->system, eight, leg->markers), ArgumentError,
                     "model marker 'F1' (point 'F1') uses 'qA2', a variable that is not among "
                     "the coordinates");
    std::vector<ex> twice = leg->q;
    twice.push_back(leg->q[0]);
    EXPECT_THROW_MSG(InverseKinematics(leg->system, twice, leg->markers), ArgumentError,
                     "coordinate 'tx' is listed twice");
    std::vector<MarkerPoint> bad = leg->markers;
    bad[2].weight = 0;
    EXPECT_THROW_MSG(InverseKinematics(leg->system, leg->q, bad), ArgumentError,
                     "model marker 'T3' has weight 0");
    InverseKinematicsOptions options;
    options.initial = {0, 0};
    EXPECT_THROW_MSG(InverseKinematics(leg->system, leg->q, leg->markers, options), ArgumentError,
                     "options.initial has 2 values for 9 coordinates");
}

}  // namespace
}  // namespace alembert::ik_test
