// SPDX-License-Identifier: MIT
// Winter's walking trial (Table A.1): the library's swing-phase knee and hip moments against
// an independent bottom-up calculation written here, about each segment's proximal joint.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/link_segment.hpp"
#include "alembert/biomech/segment_parameters.hpp"
#include "alembert/sim/filter.hpp"

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

}  // namespace
}  // namespace alembert
