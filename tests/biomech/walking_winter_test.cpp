// SPDX-License-Identifier: MIT
// Winter's walking trial (Table A.1): the library's swing-phase knee and hip moments against
// an independent bottom-up calculation written here, about each segment's proximal joint.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/link_segment.hpp"
#include "alembert/biomech/segment_parameters.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/filter.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {
namespace {

struct Planar {
    std::vector<double> h, v;
};

TEST(WalkingWinter, SwingMomentsAgreeWithAnIndependentBottomUpCalculation) {
    MarkerTable m = read_trc(std::string(ALEMBERT_SOURCE_DIR) + "/examples/walking_winter/winter_table_a1.trc");
    const double rate = m.data_rate_hz, dt = 1 / rate, mass = 55.7, g = 9.81;
    ASSERT_NEAR(rate, 69.93, 1e-9);
    // markers filtered at Winter's 6 Hz
    auto marker = [&](const char* name) {
        return Planar{filter_lowpass(m.table.columns[m.column(name, 0)], rate, 6.0),
                      filter_lowpass(m.table.columns[m.column(name, 1)], rate, 6.0)};
    };
    const Planar hip = marker("HIP"), knee = marker("KNEE"), ankle = marker("ANKLE"), mt5 = marker("MT5");
    const std::size_t n = hip.h.size();
    // segments: Winter's table, lengths from the first frame
    struct Seg {
        const Planar *P, *D;
        double m, c, I;
    };
    auto seg = [&](const char* name, const Planar& P, const Planar& D) {
        const double L = std::hypot(P.h[0] - D.h[0], P.v[0] - D.v[0]);
        SegmentParameters p = calc_segment_parameters(segment_table("winter"), name, mass, L);
        return Seg{&P, &D, p.mass, p.com_distance / L, p.inertia_flexion};
    };
    const Seg segs[3] = {seg("foot", ankle, mt5), seg("leg", knee, ankle), seg("thigh", hip, knee)};

    // the library
    std::vector<ChainSegment> chain;
    for (const Seg& s : segs) {
        ChainSegment c;
        c.mass = s.m, c.com_fraction = s.c, c.inertia = s.I;
        c.p_h = s.P->h, c.p_v = s.P->v, c.d_h = s.D->h, c.d_v = s.D->v;
        chain.push_back(c);
    }
    std::vector<JointLoads> lib = calc_inverse_dynamics_bottom_up(chain, dt, nullptr, g);

    // independent: moments about the proximal joint P of each segment, from the foot up,
    //   M_P = I alpha + (r_G - r_P) x m a_G - (r_G - r_P) x m g - (r_D - r_P) x F_D - M_D,
    //   F_P = m a_G - m g - F_D, with F_D, M_D the reversed loads of the segment below
    auto pos = [](const Seg& s, std::size_t k) {
        return std::array<double, 2>{s.P->h[k] + s.c * (s.D->h[k] - s.P->h[k]), s.P->v[k] + s.c * (s.D->v[k] - s.P->v[k])};
    };
    auto angle = [](const Seg& s, std::size_t k) { return std::atan2(s.P->v[k] - s.D->v[k], s.P->h[k] - s.D->h[k]); };
    double worst = 0, peak_knee = 0;
    for (std::size_t k = 69; k <= 96; ++k) {  // the second swing phase, frames 70 to 97
        double FD_h = 0, FD_v = 0, MD = 0;
        for (int j = 0; j < 3; ++j) {
            const Seg& s = segs[j];
            const auto g0 = pos(s, k - 1), g1 = pos(s, k), g2 = pos(s, k + 1);
            const double a_h = (g2[0] - 2 * g1[0] + g0[0]) / (dt * dt), a_v = (g2[1] - 2 * g1[1] + g0[1]) / (dt * dt);
            // differences of angles taken the short way round (the foot's angle may cross 180 deg)
            const double alpha = (std::remainder(angle(s, k + 1) - angle(s, k), 2 * std::numbers::pi) -
                                  std::remainder(angle(s, k) - angle(s, k - 1), 2 * std::numbers::pi)) / (dt * dt);
            const double rG_h = g1[0] - s.P->h[k], rG_v = g1[1] - s.P->v[k];
            const double rD_h = s.D->h[k] - s.P->h[k], rD_v = s.D->v[k] - s.P->v[k];
            const double M = s.I * alpha + s.m * (rG_h * a_v - rG_v * a_h) - (rG_h * (-s.m * g)) -
                             (rD_h * FD_v - rD_v * FD_h) - MD;
            const double F_h = s.m * a_h - FD_h, F_v = s.m * a_v + s.m * g - FD_v;
            worst = std::max(worst, std::fabs(M - lib[j].M[k]));
            worst = std::max(worst, std::hypot(F_h - lib[j].F_h[k], F_v - lib[j].F_v[k]));
            if (j == 1 && std::fabs(M) > std::fabs(peak_knee)) peak_knee = M;
            FD_h = -F_h, FD_v = -F_v, MD = -M;
        }
    }
    EXPECT_LT(worst, 1e-9);
    ASSERT_LT(n, 200u);
    // terminal swing: the knee's flexor moment slows the leg and absorbs energy (Winter's K4)
    EXPECT_LT(peak_knee / mass, -0.15);
    EXPECT_GT(peak_knee / mass, -0.6);
    double absorbed = 0;
    for (std::size_t k = 85; k <= 93; ++k) absorbed += lib[1].power[k] * dt;
    EXPECT_LT(absorbed, 0.0);
}

// examples/walking_winter/model.alb, the same trial as a script: its hip translates, so its
// coordinates are fitted to the markers, filtered at 6 Hz and differentiated, and the hip's
// force and moment and the knee's and ankle's moments solved from the model's equations. Its
// swing-phase knee and hip moments against the bottom-up calculation above, frame by frame,
// with the script's segment lengths and markers filtered at the same 6 Hz.
TEST(WalkingWinter, TheScriptGivesTheSwingMomentsOfAnIndependentBottomUpCalculation) {
    namespace fs = std::filesystem;
    const fs::path example = fs::path(ALEMBERT_SOURCE_DIR) / "examples/walking_winter/model.alb";
    const fs::path out = fs::temp_directory_path() / ("alembert_walking_" + std::to_string(::getpid()));
    fs::create_directories(out);
    std::ifstream in(example);
    std::stringstream text;
    text << in.rdbuf();
    std::ostringstream o, e;
    lang::Interpreter interp(o, e, false);
    interp.set_output_dir(out.string());
    ASSERT_EQ(interp.run(text.str(), example.string()), lang::RunStatus::ok) << e.str();
    const Table loads = read_csv((out / "loads.csv").string()), powers = read_csv((out / "powers.csv").string());
    const Table kin = read_csv((out / "kinematics.csv").string());
    const Table residuals = read_csv((out / "marker_residuals.csv").string());
    fs::remove_all(out);
    // each marker's distance from the fitted model per frame: a few mm (skin on bone, markers
    // whose distances change by up to 1.5 cm against rigid segments)
    ASSERT_EQ(residuals.names, (std::vector<std::string>{"time", "HIP", "KNEE", "ANKLE", "MT5", "rms", "max"}));
    ASSERT_EQ(residuals.row_count(), 106u);
    for (std::size_t k = 0; k < 106; ++k) {
        EXPECT_LT(residuals.columns[6][k], 0.02);
        EXPECT_LE(residuals.columns[5][k], residuals.columns[6][k]);
    }
    const double mass = 55.7, g = 9.81;
    ASSERT_EQ(loads.units[loads.column_index("T_K")], "N m/kg");

    // the independent calculation, with the script's lengths and Winter's table
    MarkerTable m = read_trc(std::string(ALEMBERT_SOURCE_DIR) + "/examples/walking_winter/winter_table_a1.trc");
    const double rate = m.data_rate_hz, dt = 1 / rate;
    auto marker = [&](const char* name) {
        return Planar{filter_lowpass(m.table.columns[m.column(name, 0)], rate, 6.0),
                      filter_lowpass(m.table.columns[m.column(name, 1)], rate, 6.0)};
    };
    const Planar hip = marker("HIP"), knee = marker("KNEE"), ankle = marker("ANKLE"), mt5 = marker("MT5");
    struct Seg {
        const Planar *P, *D;
        double m, c, I;
    };
    auto seg = [&](const char* name, const Planar& P, const Planar& D, double L) {
        SegmentParameters p = calc_segment_parameters(segment_table("winter"), name, mass, L);
        return Seg{&P, &D, p.mass, p.com_distance / L, p.inertia_flexion};
    };
    const Seg segs[3] = {seg("foot", ankle, mt5, 0.1211), seg("leg", knee, ankle, 0.4169),
                         seg("thigh", hip, knee, 0.3136)};
    auto pos = [](const Seg& s, std::size_t k) {
        return std::array<double, 2>{s.P->h[k] + s.c * (s.D->h[k] - s.P->h[k]), s.P->v[k] + s.c * (s.D->v[k] - s.P->v[k])};
    };
    auto angle = [](const Seg& s, std::size_t k) { return std::atan2(s.P->v[k] - s.D->v[k], s.P->h[k] - s.D->h[k]); };
    double ss_knee = 0, ss_hip = 0, worst_knee = 0, worst_hip = 0;
    const std::size_t iK = loads.column_index("T_K"), iH = loads.column_index("T_H");
    const std::size_t iP = powers.column_index("P_T_K"), iw = kin.column_index("qK'");
    int frames = 0;
    for (std::size_t k = 69; k <= 96; ++k) {  // the second swing phase, frames 70 to 97
        double FD_h = 0, FD_v = 0, MD = 0, M_knee = 0, M_hip = 0;
        for (int j = 0; j < 3; ++j) {
            const Seg& s = segs[j];
            const auto g0 = pos(s, k - 1), g1 = pos(s, k), g2 = pos(s, k + 1);
            const double a_h = (g2[0] - 2 * g1[0] + g0[0]) / (dt * dt), a_v = (g2[1] - 2 * g1[1] + g0[1]) / (dt * dt);
            const double alpha = (std::remainder(angle(s, k + 1) - angle(s, k), 2 * std::numbers::pi) -
                                  std::remainder(angle(s, k) - angle(s, k - 1), 2 * std::numbers::pi)) / (dt * dt);
            const double rG_h = g1[0] - s.P->h[k], rG_v = g1[1] - s.P->v[k];
            const double rD_h = s.D->h[k] - s.P->h[k], rD_v = s.D->v[k] - s.P->v[k];
            const double M = s.I * alpha + s.m * (rG_h * a_v - rG_v * a_h) - (rG_h * (-s.m * g)) -
                             (rD_h * FD_v - rD_v * FD_h) - MD;
            const double F_h = s.m * a_h - FD_h, F_v = s.m * a_v + s.m * g - FD_v;
            if (j == 1) M_knee = M;
            if (j == 2) M_hip = M;
            FD_h = -F_h, FD_v = -F_v, MD = -M;
        }
        // the script's row of this frame (the same times)
        ASSERT_NEAR(loads.columns[0][k], m.table.columns[0][k], 1e-9);
        const double dK = mass * loads.columns[iK][k] - M_knee, dH = mass * loads.columns[iH][k] - M_hip;
        ss_knee += dK * dK, ss_hip += dH * dH;
        worst_knee = std::max(worst_knee, std::fabs(dK)), worst_hip = std::max(worst_hip, std::fabs(dH));
        ++frames;
        // the knee's power is its moment times the knee's angular velocity
        EXPECT_NEAR(powers.columns[iP][k], loads.columns[iK][k] * kin.columns[iw][k], 1e-12);
    }
    const double rms_knee = std::sqrt(ss_knee / frames), rms_hip = std::sqrt(ss_hip / frames);
    std::printf("script vs bottom-up over the swing: knee %.3f N m RMS (largest %.3f), hip %.3f N m RMS (largest %.3f)\n",
                rms_knee, worst_knee, rms_hip, worst_hip);
    EXPECT_LT(rms_knee, 1.5);
    EXPECT_LT(rms_hip, 1.5);
}

}  // namespace
}  // namespace alembert
