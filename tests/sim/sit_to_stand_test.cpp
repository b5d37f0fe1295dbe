// SPDX-License-Identifier: MIT
// The sit-to-stand example's checks: torques at the upright pose, static holding torques at the
// ends of the motion from first principles, and sampled data filtered and differentiated
// against the exact formulas.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "alembert/mech/sample_models.hpp"
#include "alembert/sim/inverse_analysis.hpp"
#include "support/constants.hpp"

namespace alembert {
namespace {

using test::kDeg;
constexpr double kL[3] = {0.4182, 0.4165, 0.4896}, kMass[3] = {6.51, 14.00, 47.46},
                 kD[3] = {0.2371, 0.2362, 0.3065}, kG = 9.81;

// holding torques of a still pose from first principles: joint j carries the weights of the
// segments above it, T_j = sum_{k >= j} m_k g (x_cm_k - x_joint_j), since a_y turned by theta
// about z points along (-sin theta, cos theta)
std::array<double, 3> holding_torques(const double q[3]) {
    double theta = 0, x = 0, joint_x[3], cm_x[3];
    for (int k = 0; k < 3; ++k) {
        theta += q[k];
        joint_x[k] = x;
        cm_x[k] = x - kD[k] * std::sin(theta);
        x -= kL[k] * std::sin(theta);
    }
    std::array<double, 3> T{};
    for (int j = 0; j < 3; ++j)
        for (int k = j; k < 3; ++k)
            T[static_cast<std::size_t>(j)] += kMass[k] * kG * (cm_x[k] - joint_x[j]);
    return T;
}

class SitToStand : public ::testing::Test {
protected:
    SampleModel model = make_triple_pendulum();
    InverseDynamics id =
        compile_inverse_dynamics(model.system, model.q, model.unknowns, "sit_to_stand");
    // the minimum-jerk motion: knee and hip over [0, 1.5] s, ankle over [0.15, 1.5] s
    PrescribedMotion motion{
        model.system.symbols(),
        model.q,
        {(-25 + 20 * minimum_jerk(model.system.symbols().time(), 0.15, 1.5)) * kDeg,
         (105 - 95 * minimum_jerk(model.system.symbols().time(), 0.0, 1.5)) * kDeg,
         (-130 + 120 * minimum_jerk(model.system.symbols().time(), 0.0, 1.5)) * kDeg}};
};

TEST_F(SitToStand, UprightAtRestNeedsNoTorque) {
    const double zero[3] = {0, 0, 0};
    double T[3];
    id.calc_loads(0, zero, zero, zero, T);
    for (double Ti : T) EXPECT_NEAR(Ti, 0.0, 1e-12);
}

TEST_F(SitToStand, SeatOffAndStandingNeedTheStaticHoldingTorques) {
    // minimum jerk starts and ends with zero rate and acceleration: only weights are held
    for (double t : {0.0, 1.5}) {
        double q[3], qd[3], qdd[3], T[3];
        motion.calc_state(t, q, qd, qdd);
        id.calc_loads(t, q, qd, qdd, T);
        const std::array<double, 3> hold = holding_torques(q);
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(T[j], hold[static_cast<std::size_t>(j)], 1e-9)
                << "t = " << t << ", joint " << j;
    }
    // the poses are the issue's: seat-off (-25, 105, -130) deg, standing (-5, 10, -10) deg
    double q[3], qd[3], qdd[3];
    motion.calc_state(0, q, qd, qdd);
    EXPECT_NEAR(q[1], 105 * kDeg, 1e-14);
    motion.calc_state(1.5, q, qd, qdd);
    EXPECT_NEAR(q[2], -10 * kDeg, 1e-14);
}

TEST_F(SitToStand, SeatOffAndStandingJointForcesCarryTheWeightAbove) {
    // the example's joint reactions: ankle on A from N, knee on B from A (both in the shank
    // frame A), hip on C from B (in the thigh frame B); compressive along y, shear along x
    System& sys = model.system;
    SymbolTable& s = sys.symbols();
    RigidBody &A = *model.links[0], &B = *model.links[1], &C = *model.links[2];
    const Frame &FA = A.body_frame(), &FB = B.body_frame();
    std::vector<ex> R;
    for (const char* n : {"F_Ac", "F_As", "F_Kc", "F_Ks", "F_Hc", "F_Hs"})
        R.push_back(s.add_unknown(n));
    sys.add_joint_reaction("ankle", nullptr, A, sys.point("A_o"), {{R[0], FA.y()}, {R[1], FA.x()}});
    sys.add_joint_reaction("knee", &A, B, sys.point("B_o"), {{R[2], FA.y()}, {R[3], FA.x()}});
    sys.add_joint_reaction("hip", &B, C, sys.point("C_o"), {{R[4], FB.y()}, {R[5], FB.x()}});
    std::vector<ex> unknowns = model.unknowns;
    unknowns.insert(unknowns.end(), R.begin(), R.end());
    InverseDynamics with_forces = compile_inverse_dynamics(sys, model.q, unknowns, "sit_to_stand");
    // hand statics at the poses at rest: a joint pushes up with the weight W above it, W Ny>;
    // Ny> . Fy> = cos a and Ny> . Fx> = sin a for a frame F turned by a about Nz
    for (double t : {0.0, 1.5}) {
        double q[3], qd[3], qdd[3], L[9];
        motion.calc_state(t, q, qd, qdd);
        with_forces.calc_loads(t, q, qd, qdd, L);
        const std::array<double, 3> hold = holding_torques(q);
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(L[j], hold[static_cast<std::size_t>(j)], 1e-9) << "t = " << t;
        const double W[3] = {(kMass[0] + kMass[1] + kMass[2]) * kG, (kMass[1] + kMass[2]) * kG,
                             kMass[2] * kG};
        const double angle[3] = {q[0], q[0], q[0] + q[1]};  // of A, A, B
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(L[3 + 2 * j], W[j] * std::cos(angle[j]), 1e-9)
                << "t = " << t << ", joint " << j;
            EXPECT_NEAR(L[4 + 2 * j], W[j] * std::sin(angle[j]), 1e-9)
                << "t = " << t << ", joint " << j;
        }
        std::printf("t = %.1f s: knee compressive %.2f N, shear %.2f N; hip %.2f N, %.2f N\n", t,
                    L[5], L[6], L[7], L[8]);
    }
}

TEST_F(SitToStand, FilteredSampledDataReproduceTheExactTorquesAwayFromTheEnds) {
    // the motion sampled at 100 Hz into a CSV in degrees (6 decimals, as the example ships it),
    // read back, filtered at 6 Hz and differentiated; compared with the exact formulas over
    // [0.2, 1.3] s. Stated tolerance: 3 % of each torque's peak magnitude.
    namespace fs = std::filesystem;
    const fs::path csv =
        fs::temp_directory_path() / ("alembert_sts_" + std::to_string(::getpid()) + ".csv");
    {
        std::FILE* f = std::fopen(csv.c_str(), "w");
        std::fprintf(f, "t [s],qA [deg],qB [deg],qC [deg]\n");
        for (int i = 0; i <= 150; ++i) {
            double q[3], qd[3], qdd[3];
            motion.calc_state(i / 100.0, q, qd, qdd);
            std::fprintf(f, "%.2f,%.6f,%.6f,%.6f\n", i / 100.0, q[0] / kDeg, q[1] / kDeg,
                         q[2] / kDeg);
        }
        std::fclose(f);
    }
    MotionSamples sampled = read_motion(csv, {"qA", "qB", "qC"}, {.cutoff_hz = 6});
    fs::remove(csv);
    Table from_data = calc_inverse_dynamics(id, sampled);
    Table exact = calc_inverse_dynamics(id, motion.sample(sampled.t));
    ASSERT_EQ(from_data.names, (std::vector<std::string>{"t", "T_A", "T_B", "T_C"}));
    for (std::size_t j = 1; j <= 3; ++j) {
        double peak = 0, worst = 0;
        for (double v : exact.columns[j]) peak = std::max(peak, std::abs(v));
        for (std::size_t r = 0; r < exact.row_count(); ++r) {
            const double t = exact.columns[0][r];
            if (t < 0.2 - 1e-9 || t > 1.3 + 1e-9) continue;
            worst = std::max(worst, std::abs(from_data.columns[j][r] - exact.columns[j][r]));
        }
        EXPECT_LT(worst, 0.03 * peak) << exact.names[j] << ": peak " << peak << " N m";
        std::printf("%s: peak %.2f N m, largest difference over [0.2, 1.3] s %.3f N m (%.2f %%)\n",
                    exact.names[j].c_str(), peak, worst, 100 * worst / peak);
    }
}

}  // namespace
}  // namespace alembert
