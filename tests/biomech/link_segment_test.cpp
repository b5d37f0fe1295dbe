// SPDX-License-Identifier: MIT
// Planar inverse dynamics: a segment standing on a force plate by hand statics, a pendulum by
// its equation of motion, the plate switched off out of contact, two plates as one.
#include "alembert/biomech/link_segment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

constexpr double kG = 9.81;

// a plate record in OpenSim's column names: force (0, Fy, 0) at (x_cop, 0, 0), no free moment
Table plate_table(const std::vector<double>& Fy, double x_cop) {
    Table t;
    t.add_column("time", "s");
    for (const char* c : {"ground_force_vx", "ground_force_vy", "ground_force_vz", "ground_force_px",
                          "ground_force_py", "ground_force_pz", "ground_torque_x", "ground_torque_y",
                          "ground_torque_z"})
        t.add_column(c, "");
    for (std::size_t k = 0; k < Fy.size(); ++k) {
        t.columns[0].push_back(0.01 * static_cast<double>(k));
        for (std::size_t c = 1; c < t.columns.size(); ++c) t.columns[c].push_back(0.0);
        t.columns[2][k] = Fy[k];
        t.columns[4][k] = x_cop;
    }
    return t;
}

// a rod of 1 m, 10 kg, G at 0.4 from the top joint P, held still at 60 deg with its lower
// end D at the origin
ChainSegment still_rod(std::size_t n) {
    ChainSegment s;
    s.name = "rod";
    s.proximal_joint = "top";
    s.mass = 10;
    s.com_fraction = 0.4;
    s.inertia = 0.8;
    const double phi = std::numbers::pi / 3;
    s.p_h.assign(n, std::cos(phi)), s.p_v.assign(n, std::sin(phi));
    s.d_h.assign(n, 0.0), s.d_v.assign(n, 0.0);
    return s;
}

TEST(LinkSegment, ARodStandingOnAPlateIsInStaticEquilibrium) {
    // the plate pushes up 300 N at x = 0.02 m; the rod weighs 98.1 N with G at
    // P + 0.4 (D - P) = (0.3, 0.3 sqrt 3); the joint at P must hold the rest:
    //   F_P = -(0, 300) + (0, 98.1) = (0, -201.9) N
    //   moments about P: M_P + (r_CoP - r_P) x F + (r_G - r_P) x m g = 0
    //   (r_CoP - r_P) x F = (0.02 - 0.5) * 300 = -144;  (r_G - r_P) x m g = (-0.2)(-98.1) = 19.62
    //   M_P = 144 - 19.62 = 124.38 N m
    const std::size_t n = 8;
    ForcePlate plate = force_plate_from_table(plate_table(std::vector<double>(n, 300.0), 0.02), "ground_force");
    PlanarLoad load = planar_load_from_plate(plate);
    std::vector<JointLoads> j = calc_inverse_dynamics_bottom_up({still_rod(n)}, 0.01, &load, kG);
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0].joint, "top");
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_NEAR(j[0].F_h[k], 0.0, 1e-9);
        EXPECT_NEAR(j[0].F_v[k], -201.9, 1e-9);  // second differences of 1e4/s^2 carry roundoff
        EXPECT_NEAR(j[0].M[k], 124.38, 1e-9);
    }
    EXPECT_TRUE(j[0].power.empty());
}

TEST(LinkSegment, ThePlateSwitchesOffOutOfContact) {
    // 5 N is below the 20 N contact threshold: the rod hangs from P alone,
    // F_P = (0, 98.1), M_P = -(r_G - r_P) x m g = -19.62 N m
    std::vector<double> Fy = {300, 300, 5, 5, 300, 300};
    ForcePlate plate = force_plate_from_table(plate_table(Fy, 0.02), "ground_force");
    EXPECT_FALSE(plate.in_contact(2));
    PlanarLoad load = planar_load_from_plate(plate);
    EXPECT_EQ(load.F_v[3], 0.0);
    std::vector<JointLoads> j = calc_inverse_dynamics_bottom_up({still_rod(6)}, 0.01, &load, kG);
    EXPECT_NEAR(j[0].F_v[2], 98.1, 1e-9);
    EXPECT_NEAR(j[0].M[3], -19.62, 1e-9);
    EXPECT_NEAR(j[0].M[4], 124.38, 1e-9);
}

TEST(LinkSegment, MissingPlateColumnsAreNamed) {
    Table t = plate_table({300}, 0);
    EXPECT_THROW_MSG(force_plate_from_table(t, "1_ground_force"), ArgumentError,
                     "plate '1_ground_force' lacks the columns 1_ground_force_vx, 1_ground_force_px, 1_ground_torque_x");
}

TEST(LinkSegment, TwoPlatesActAsTheirSum) {
    // 200 N at x = 0.1 and 100 N at x = 0.4: 300 N at x = 0.2 (moments 20 + 40 = 60 = 0.2 * 300)
    ForcePlate a = force_plate_from_table(plate_table({200, 200, 200, 200}, 0.1), "ground_force");
    ForcePlate b = force_plate_from_table(plate_table({100, 100, 100, 100}, 0.4), "ground_force");
    PlanarLoad sum = combine_loads({planar_load_from_plate(a), planar_load_from_plate(b)});
    EXPECT_NEAR(sum.F_v[0], 300, 1e-12);
    EXPECT_NEAR(sum.p_h[0], 0.2, 1e-12);
    EXPECT_NEAR(sum.M[0], 0.0, 1e-12);
}

TEST(LinkSegment, APendulumNeedsTheMomentOfItsEquationOfMotion) {
    // a rod hanging from a fixed pivot P swings as phi(t) = -pi/2 + A sin(w t) (phi: the
    // direction P->D); about P: I_P phi'' = M_P + (r_G - r_P) x m g, so
    //   M_P = I_P phi'' + m g c L cos(phi),  I_P = I + m (c L)^2,
    // and F_P = m a_G - m g. Sampled at 1 kHz; central differences are second order.
    const double L = 0.45, c = 0.43, m = 3.5, I = 0.06, A = 0.6, w = 5.0, dt = 1e-3;
    ChainSegment s;
    s.name = "leg";
    s.proximal_joint = "knee";
    s.mass = m, s.com_fraction = c, s.inertia = I;
    const std::size_t n = 801;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = dt * static_cast<double>(k), phi = -std::numbers::pi / 2 + A * std::sin(w * t);
        s.p_h.push_back(0), s.p_v.push_back(0);
        s.d_h.push_back(L * std::cos(phi)), s.d_v.push_back(L * std::sin(phi));
    }
    std::vector<JointLoads> j = calc_inverse_dynamics_bottom_up({s}, dt, nullptr, kG);
    const double I_P = I + m * c * L * c * L;
    double worst_M = 0, worst_F = 0;
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const double t = dt * static_cast<double>(k), phi = -std::numbers::pi / 2 + A * std::sin(w * t);
        const double phid = A * w * std::cos(w * t), phidd = -A * w * w * std::sin(w * t);
        const double M = I_P * phidd + m * kG * c * L * std::cos(phi);
        // a_G of a point at radius cL: tangential phi'' and centripetal phi'^2
        const double a_h = c * L * (-std::sin(phi) * phidd - std::cos(phi) * phid * phid);
        const double a_v = c * L * (std::cos(phi) * phidd - std::sin(phi) * phid * phid);
        worst_M = std::max(worst_M, std::fabs(j[0].M[k] - M));
        worst_F = std::max(worst_F, std::hypot(j[0].F_h[k] - m * a_h, j[0].F_v[k] - (m * a_v + m * kG)));
    }
    // peak moment is about 8 N m; differences of O(dt^2 w^2) ~ 1e-5 relative
    EXPECT_LT(worst_M, 1e-4);
    EXPECT_LT(worst_F, 1e-3);
}

TEST(LinkSegment, TopDownMeetsBottomUpOnConsistentDataAndShowsAPlateError) {
    // two segments moving arbitrarily (smooth), the lower one on a plate: bottom-up from the
    // plate gives the top joint's load; top-down from that load must predict the plate's load
    // back (residual 0). A plate reading 10 N too high shows as a residual of -10 N and its
    // moment about D.
    const std::size_t n = 200;
    const double dt = 0.005;
    ChainSegment leg, thigh;
    leg.name = "leg", leg.proximal_joint = "knee", leg.mass = 3, leg.com_fraction = 0.43, leg.inertia = 0.05;
    thigh.name = "thigh", thigh.proximal_joint = "hip", thigh.mass = 7, thigh.com_fraction = 0.43, thigh.inertia = 0.12;
    PlanarLoad plate;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = dt * static_cast<double>(k);
        const double ah = 0.1 * std::sin(2 * t), kh = 0.2 + 0.05 * std::cos(3 * t), kv = 0.45 + 0.02 * std::sin(t);
        const double hh = 0.1 + 0.1 * std::sin(1.5 * t), hv = 0.9;
        leg.d_h.push_back(ah), leg.d_v.push_back(0.08), leg.p_h.push_back(kh), leg.p_v.push_back(kv);
        thigh.d_h.push_back(kh), thigh.d_v.push_back(kv), thigh.p_h.push_back(hh), thigh.p_v.push_back(hv);
        plate.F_h.push_back(20 * std::sin(t)), plate.F_v.push_back(400 + 50 * std::cos(2 * t));
        plate.p_h.push_back(0.05 + 0.1 * t), plate.p_v.push_back(0.0), plate.M.push_back(1.5);
    }
    const std::vector<ChainSegment> chain = {leg, thigh};
    std::vector<JointLoads> up = calc_inverse_dynamics_bottom_up(chain, dt, &plate, kG);
    PlanarLoad hip;
    hip.F_h = up[1].F_h, hip.F_v = up[1].F_v, hip.M = up[1].M;
    hip.p_h = thigh.p_h, hip.p_v = thigh.p_v;
    std::vector<JointLoads> down = calc_inverse_dynamics_top_down(chain, dt, &hip, kG);
    ASSERT_EQ(down.size(), 3u);
    EXPECT_EQ(down[2].joint, "ground");
    JointLoads r = calc_top_down_residual(down, leg, &plate);
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_NEAR(r.F_h[k], 0, 1e-9);
        EXPECT_NEAR(r.F_v[k], 0, 1e-9);
        EXPECT_NEAR(r.M[k], 0, 1e-9);
        EXPECT_NEAR(down[0].M[k], up[0].M[k], 1e-9);  // the knee from both ends
        EXPECT_NEAR(down[0].power[k], up[0].power[k], 1e-9);
    }
    // the plate 10 N too high
    PlanarLoad wrong = plate;
    for (double& f : wrong.F_v) f += 10;
    JointLoads bad = calc_top_down_residual(down, leg, &wrong);
    for (std::size_t k = 0; k < n; k += 50) {
        EXPECT_NEAR(bad.F_v[k], -10, 1e-9);
        EXPECT_NEAR(bad.M[k], -(plate.p_h[k] - leg.d_h[k]) * 10, 1e-9);
    }
}

TEST(LinkSegment, NormalizingDividesByBodyMass) {
    std::vector<JointLoads> j(1);
    j[0].M = {70}, j[0].F_h = {7}, j[0].F_v = {-14}, j[0].power = {35};
    normalize_by_body_mass(j, 70);
    EXPECT_DOUBLE_EQ(j[0].M[0], 1.0);
    EXPECT_DOUBLE_EQ(j[0].F_v[0], -0.2);
    EXPECT_DOUBLE_EQ(j[0].power[0], 0.5);
    EXPECT_THROW_MSG(normalize_by_body_mass(j, 0), ArgumentError, "must be positive");
}

}  // namespace
}  // namespace alembert
