// SPDX-License-Identifier: MIT
// The sit-to-stand driven by lab files (examples/sit_to_stand/model_lab.alb: markers and the
// chair's force plate, written by generate_lab_files.py) against the formula-driven version
// (model.alb), to a tolerance derived from the files' printed precision and the filter.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "alembert/biomech/force_plate.hpp"
#include "alembert/biomech/lab_files.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/filter.hpp"
#include "alembert/sim/table.hpp"

namespace sit_to_stand_lab_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

constexpr double kDeg = std::numbers::pi / 180;
// model.alb's values
constexpr double g = 9.81, L_A = 0.4182, L_B = 0.4165, d_A = 0.2371, d_B = 0.2362, d_C = 0.3065;
constexpr double m_A = 6.51, m_B = 14.00, m_C = 47.46, I_A = 0.1038, I_B = 0.2534, I_C = 2.799;
// the trial: 100 Hz from -0.5 to 2 s; markers in mm with 3 decimals, plates with 4 decimals
constexpr double kRate = 100, kT0 = -0.5, kCutoff = 6;
constexpr std::size_t kSamples = 251;
constexpr double kMarkerRounding = 0.5e-6;  // m, half the last printed digit (0.001 mm)
constexpr double kPlateRounding = 0.5e-4;   // N and m

// model.alb's motion: minimum-jerk q, q', q'' (rad) of qA, qB, qC at t
struct Coordinate {
    double start, span, t0;
};
constexpr Coordinate kMotion[3] = {{-25, 20, 0.15}, {105, -95, 0}, {-130, 120, 0}};
double q_of(int j, double t, int order) {
    const Coordinate c = kMotion[j];
    const double T = 1.5 - c.t0, u = (t - c.t0) / T;
    if (u <= 0 || u >= 1) return order ? 0 : (c.start + (u >= 1 ? c.span : 0)) * kDeg;
    const double s[3] = {10 * std::pow(u, 3) - 15 * std::pow(u, 4) + 6 * std::pow(u, 5),
                         (30 * u * u - 60 * std::pow(u, 3) + 30 * std::pow(u, 4)) / T,
                         (60 * u - 180 * u * u + 120 * std::pow(u, 3)) / (T * T)};
    return (order ? 0 : c.start * kDeg) + c.span * kDeg * s[order];
}
double time_of(std::size_t k) { return kT0 + static_cast<double>(k) / kRate; }

// runs a script of the example into `out`, returns its loads.csv
alembert::Table run_example(const std::string& script, const fs::path& out,
                            const std::string& dir) {
    const fs::path path = fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand" / script;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::ostringstream o, e;
    Interpreter interp(o, e, false);
    interp.set_output_dir(out.string());
    EXPECT_EQ(interp.run(text.str(), path.string()), RunStatus::ok) << e.str();
    return alembert::read_csv((out / dir / "loads.csv").string());
}

// how far, at most, the lab pipeline's q, q', q'' can be from the exact motion at each sample:
// the filter's bias on the exact samples, plus the rounding of the markers carried through the
// filter and the differences (their worst-case gain, the sum of |impulse response|)
struct MotionError {
    std::vector<double> q[3], qd[3], qdd[3];  // [coordinate][sample]
};
const MotionError& motion_error() {
    static const MotionError e = [] {
        const double h = 1 / kRate;
        // the rounding: each marker coordinate within kMarkerRounding, so a segment's angle
        // within 2 sqrt(2) r / length; qA = theta_A, qB = theta_B - theta_A, qC = theta_C - theta_B
        const double seg[3] = {2 * std::sqrt(2) * kMarkerRounding / L_A,
                               2 * std::sqrt(2) * kMarkerRounding / L_B,
                               2 * std::sqrt(2) * kMarkerRounding / std::hypot(0.50, 0.05)};
        const double rounding[3] = {seg[0], seg[0] + seg[1], seg[1] + seg[2]};
        std::vector<double> impulse(kSamples, 0.0);
        impulse[kSamples / 2] = 1;
        const std::vector<double> f = alembert::filter_lowpass(impulse, kRate, kCutoff);
        const std::vector<double> fd = alembert::differentiate(f, h),
                                  fdd = alembert::differentiate_twice(f, h);
        double gain[3] = {0, 0, 0};
        for (std::size_t k = 0; k < kSamples; ++k)
            gain[0] += std::fabs(f[k]), gain[1] += std::fabs(fd[k]), gain[2] += std::fabs(fdd[k]);
        MotionError out;
        for (int j = 0; j < 3; ++j) {
            std::vector<double> q(kSamples);
            for (std::size_t k = 0; k < kSamples; ++k) q[k] = q_of(j, time_of(k), 0);
            const std::vector<double> qf = alembert::filter_lowpass(q, kRate, kCutoff);
            const std::vector<double> qd = alembert::differentiate(qf, h),
                                      qdd = alembert::differentiate_twice(qf, h);
            for (std::size_t k = 0; k < kSamples; ++k) {
                const double t = time_of(k);
                out.q[j].push_back(std::fabs(qf[k] - q_of(j, t, 0)) + gain[0] * rounding[j]);
                out.qd[j].push_back(std::fabs(qd[k] - q_of(j, t, 1)) + gain[1] * rounding[j]);
                out.qdd[j].push_back(std::fabs(qdd[k] - q_of(j, t, 2)) + gain[2] * rounding[j]);
            }
        }
        return out;
    }();
    return e;
}

// a bound, to first order, on how much the joint torques at sample k change for the errors of
// q, q', q'' there: Delta T = M(q) Delta q'' + (velocity terms) + (gravity terms), with M the
// chain's mass matrix in joint coordinates, M = S^T M_abs S (absolute angles theta = S q, S
// lower triangular ones; M_abs of the three links); the velocity terms m a b q'_i q'_k sin(...)
// change by at most 2 c w |Delta q'|, c their coefficients' sum and w the sum of joint rates;
// the gravity terms by g sum(m r) |Delta q|
double torque_tolerance(int i, std::size_t k) {
    const MotionError& e = motion_error();
    const double t = time_of(k);
    const double th[3] = {q_of(0, t, 0), q_of(0, t, 0) + q_of(1, t, 0),
                          q_of(0, t, 0) + q_of(1, t, 0) + q_of(2, t, 0)};
    double Ma[3][3];
    Ma[0][0] = I_A + m_A * d_A * d_A + (m_B + m_C) * L_A * L_A;
    Ma[1][1] = I_B + m_B * d_B * d_B + m_C * L_B * L_B;
    Ma[2][2] = I_C + m_C * d_C * d_C;
    Ma[0][1] = Ma[1][0] = (m_B * d_B + m_C * L_B) * L_A * std::cos(th[1] - th[0]);
    Ma[0][2] = Ma[2][0] = m_C * d_C * L_A * std::cos(th[2] - th[0]);
    Ma[1][2] = Ma[2][1] = m_C * d_C * L_B * std::cos(th[2] - th[1]);
    // M_ij = sum over a >= i, b >= j of Ma[a][b]
    double tol = 0;
    for (int j = 0; j < 3; ++j) {
        double M_ij = 0;
        for (int a = i; a < 3; ++a)
            for (int b = j; b < 3; ++b) M_ij += Ma[a][b];
        tol += std::fabs(M_ij) * e.qdd[j][k];
    }
    const double c = m_B * d_B * L_A + m_C * (L_A * L_B + L_A * d_C + L_B * d_C);
    const double mr = m_A * d_A + m_B * (L_A + d_B) + m_C * (L_A + L_B + d_C);
    double w = 0;
    for (int j = 0; j < 3; ++j) w += std::fabs(q_of(j, t, 1));
    for (int j = 0; j < 3; ++j) tol += 2 * c * w * e.qd[j][k] + g * mr * e.q[j][k];
    return tol;
}

struct SitToStandLab : ::testing::Test {
    static inline alembert::Table formula, lab, residuals;
    static void SetUpTestSuite() {
        const fs::path dir =
            fs::temp_directory_path() / ("alembert_sts_lab_" + std::to_string(::getpid()));
        formula = run_example("model.alb", dir / "formula", "rising");
        lab = run_example("model_lab.alb", dir / "lab", "rising_lab");
        residuals = alembert::read_csv((dir / "lab" / "rising_lab" / "marker_residuals.csv").string());
        fs::remove_all(dir);
    }
    // the lab table's row at time t
    static std::size_t lab_row(double t) {
        for (std::size_t r = 0; r < lab.row_count(); ++r)
            if (std::fabs(lab.columns[0][r] - t) < 1e-9) return r;
        ADD_FAILURE() << "no lab sample at t = " << t;
        return 0;
    }
};

TEST_F(SitToStandLab, JointMomentsAgreeWithTheFormulaDrivenRiseToTheDerivedTolerance) {
    ASSERT_EQ(formula.names, lab.names);
    ASSERT_EQ(lab.row_count(), kSamples);
    // the rise t = 0..1.5 s (samples 50..200), and its middle 0.3..1.2 s away from the starts and
    // stops of the minimum-jerk motions, where the filter rounds the jerk's steps
    // the rise, t = 0 to 1.5 s: the tolerance at each sample, and how much of it is used
    double worst = 0, worst_tol = 0, used = 0;
    for (std::size_t r = 0; r < formula.row_count(); ++r) {
        const double t = formula.columns[0][r];
        const std::size_t k = lab_row(t);
        for (int c = 1; c <= 3; ++c) {
            const double tol = torque_tolerance(c - 1, k),
                         d = std::fabs(lab.columns[c][k] - formula.columns[c][r]);
            EXPECT_LE(d, tol) << lab.names[c] << " at t = " << t;
            worst = std::max(worst, d), worst_tol = std::max(worst_tol, tol),
            used = std::max(used, d / tol);
        }
    }
    std::cout << "t = 0 to 1.5 s: largest difference " << worst << " N m, largest tolerance "
              << worst_tol << " N m, at most " << used << " of the tolerance used\n";
}

TEST_F(SitToStandLab, MarkerResidualsPerFrameAreTheMarkersRounding) {
    // the markers were written from the model itself, rounded to 0.001 mm: each one's distance
    // from the model's is that rounding carried through the angles (a few micrometres); a
    // joint's marker declared on two bodies is one column
    ASSERT_EQ(residuals.names, (std::vector<std::string>{"time", "LMAL", "LFE", "GTR", "ACR", "rms", "max"}));
    ASSERT_EQ(residuals.row_count(), kSamples);
    for (std::size_t k = 0; k < kSamples; ++k) {
        double ss = 0, largest = 0;
        for (std::size_t c = 1; c <= 4; ++c) {
            const double d = residuals.columns[c][k];
            EXPECT_GE(d, 0);
            EXPECT_LT(d, 2e-5) << residuals.names[c] << " at t = " << residuals.columns[0][k];
            ss += d * d, largest = std::max(largest, d);
        }
        EXPECT_NEAR(residuals.columns[5][k], std::sqrt(ss / 4), 1e-15);
        EXPECT_EQ(residuals.columns[6][k], largest);
        EXPECT_NEAR(residuals.columns[0][k], time_of(k), 1e-9);
    }
}

TEST_F(SitToStandLab, SeatedTheChairsLoadTakesItsMomentOffTheKneeAndAnkleTorques) {
    // still in the seat-off posture with the chair's 300 N on the thighs (t <= -0.3 s): each
    // torque is the formula-driven one at t = 0 (the same posture, no chair) less the chair's
    // moment about the joint, (p_chair - p_joint) x F_chair; the hip's is unchanged
    const fs::path mot = fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/lab/rise.mot";
    const alembert::ForcePlate chair = alembert::force_plate_from_table(
        alembert::read_storage(mot.string()).table, "1_ground_force");
    const double qA = kMotion[0].start * kDeg;
    const double ankle[2] = {0.25, 0.08};  // the model's N_o in the lab
    const double knee[2] = {ankle[0] - L_A * std::sin(qA), ankle[1] + L_A * std::cos(qA)};
    for (std::size_t k = 5; k <= 20; ++k) {     // t = -0.45 to -0.3 s
        double tol = 2 * 300 * kPlateRounding;  // the centre of pressure's rounding
        for (int i = 0; i < 3; ++i)
            tol = std::max(tol, torque_tolerance(i, k) + 2 * 300 * kPlateRounding);
        const double t = time_of(k);
        ASSERT_NEAR(chair.t[k], t, 1e-9);
        const double Fy = chair.F[1][k], px = chair.p_CoP[0][k];
        ASSERT_NEAR(Fy, 300, 1e-9);
        const std::size_t r = lab_row(t);
        EXPECT_NEAR(lab.columns[1][r], formula.columns[1][0] - (px - ankle[0]) * Fy, tol)
            << "T_A at t = " << t;
        EXPECT_NEAR(lab.columns[2][r], formula.columns[2][0] - (px - knee[0]) * Fy, tol)
            << "T_B at t = " << t;
        EXPECT_NEAR(lab.columns[3][r], formula.columns[3][0], tol) << "T_C at t = " << t;
    }
}

TEST_F(SitToStandLab, TheFloorPlateGivesTheAnkleMomentBottomUp) {
    // the feet are still and massless: the floor's force on them, at its centre of pressure,
    // balances the ankle torque, T_A = (p_CoP - p_ankle) x F; the generator computed the floor's
    // record from its own dynamics, so this checks Alembert's formula-driven T_A independently,
    // to the plate file's rounding (|F| < 800 N, lever < 0.3 m)
    const fs::path mot = fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/lab/rise.mot";
    const alembert::ForcePlate floor = alembert::force_plate_from_table(
        alembert::read_storage(mot.string()).table, "ground_force");
    const double tol = kPlateRounding * (800 + 800 + 0.3 + 0.3);
    for (std::size_t r = 0; r < formula.row_count(); ++r) {
        const double t = formula.columns[0][r];
        const std::size_t k = static_cast<std::size_t>(std::lround((t - kT0) * kRate));
        ASSERT_NEAR(floor.t[k], t, 1e-9);
        const double T_A =
            (floor.p_CoP[0][k] - 0.25) * floor.F[1][k] - (floor.p_CoP[1][k] - 0.08) * floor.F[0][k];
        EXPECT_NEAR(T_A, formula.columns[1][r], tol) << "t = " << t;
    }
}

}  // namespace sit_to_stand_lab_test
