// SPDX-License-Identifier: MIT
// simulate after a kane statement with speeds, kinematics and motion constraints: the rolling
// disk of examples/rolling_disk in its speeds moves as the same disk simulated in coordinates
// alone with the no-slip constraint and its contact forces (the road-map's constrained
// dynamics), keeps the energy computed by hand, and its columns and checks are those of
// other simulations; the Autolev rolling disk imported simulates alike.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/sim/table.hpp"
#include "support/script_dir.hpp"

namespace simulate_speeds_script {

namespace {

using alembert::Table;
using alembert::test::has;
using alembert::test::ScriptInDir;
using alembert::test::TempDir;

// the disk's model, shared by both formulations: its declarations, then (after the
// variables) its kinematics
const char* const kDiskHead = R"(newtonian N
frame Y, L
body D
point P; point D_P on D
constant m = 2 kg, r = 0.3 m, g = 9.81 m/s^2
)";
const char* const kDisk = R"(rotate Y from N about z by q1
rotate L from Y about x by q2
rotate D from L about y by q3
translate P from N_o by x*Nx> + y*Ny>
translate Dcm from P by r*Lz>
translate D_P from Dcm by -r*Lz>
velocity D_P in N from Dcm fixed on D
mass D = m
inertia D = m*r^2/4, m*r^2/2, m*r^2/4 in L
gravity -g*Nz>
final time 2 s
output step 0.1 s
tolerance abs 1e-11 rel 1e-11
)";

// in speeds: u1..u3 the measures of D's angular velocity in L, u4 = x', u5 = y' dependent
const char* const kSpeedVariables = R"(variable q1' rad, q2' rad, q3' rad, x' m, y' m
variable u1' rad/s, u2' rad/s, u3' rad/s, u4' m/s, u5' m/s
)";
const char* const kInSpeeds = R"(w> = angvel(D, N)
kane K for q1, q2, q3, x, y speeds u1, u2, u3, u4, u5 \
  kinematics [u1 - dot(w>, Lx>), u2 - dot(w>, Ly>), u3 - dot(w>, Lz>), u4 - x', u5 - y'] \
  constraints [dot(vel(D_P, N), Nx>), dot(vel(D_P, N), Ny>)] dependent u4, u5
initial q2 = 0.1 rad, u1 = 0.3 rad/s, u2 = 8 rad/s, u3 = -0.5 rad/s
)";

// in coordinates alone: the contact forces F_x, F_y solved with q'' (the road-map), the
// same state: q2' = u1, q1' = u3/cos(q2), q3' = u2 - q1' sin(q2), and x', y' from rolling
// (the contact P moves at r (u2 - q1' sin q2) Lx - r u1 ... see below)
const char* const kCoordinateVariables = R"(variable q1'' rad, q2'' rad, q3'' rad, x'' m, y'' m
unknown F_x N, F_y N
)";
const char* const kInCoordinates = R"(force grip on D_P = F_x*Nx> + F_y*Ny>
constraint motion roll = vel(D_P, N) in N
)";

std::string num(double v) { return alembert::test::digits17(v); }

// the table's column, in SI (the columns here are written in SI units)
const std::vector<double>& col(const Table& t, const std::string& name) {
    return t.columns[t.column_index(name)];
}

TEST(SimulateSpeedsScript, RollingDiskInSpeedsMovesAsInCoordinatesWithItsContactForces) {
    // The initial state in coordinates, by hand: w_D = q1' Nz + q2' Yx + q3' Ly with
    // Nz = sin(q2) Ly + cos(q2) Lz, so u1 = q2', u2 = q3' + q1' sin(q2), u3 = q1' cos(q2).
    // The contact point P = Dcm - r Lz moves at v_Dcm - r w_L x Lz with v_Dcm = w_D x r Lz =
    // r (u2 Lx - u1 Ly) and w_L x Lz = (u1 Lx + q1' sin(q2) Ly + u3 Lz) x Lz =
    // q1' sin(q2) Lx - u1 Ly: v_P = r (u2 - q1' sin(q2)) Lx = r q3' Lx, horizontal along Yx.
    const double q2 = 0.1, u1 = 0.3, u2 = 8, u3 = -0.5, r = 0.3;
    const double q1d = u3 / std::cos(q2), q3d = u2 - q1d * std::sin(q2);
    TempDir dir("alembert-speeds");
    ScriptInDir a(dir.path / "a"), b(dir.path / "b");
    a.run(std::string(kDiskHead) + kSpeedVariables + kDisk + kInSpeeds + "simulate\n");
    b.run(std::string(kDiskHead) + kCoordinateVariables + kDisk + kInCoordinates + "initial q2 = " + num(q2) + " rad, q1' = " + num(q1d) +
          " rad/s, q2' = " + num(u1) + " rad/s, q3' = " + num(q3d) + " rad/s, x' = " + num(r * q3d) + " m/s\n" +
          "simulate\n");
    const Table ta = alembert::read_csv((dir.path / "a" / "simulation.csv").string());
    const Table tb = alembert::read_csv((dir.path / "b" / "simulation.csv").string());
    // the speeds' default columns: the coordinates, then every speed, then the checks
    EXPECT_EQ(ta.names, (std::vector<std::string>{"t", "q1", "q2", "q3", "x", "y", "u1", "u2", "u3", "u4",
                                                  "u5", "energy", "drift_motion_1", "drift_motion_2"}));
    ASSERT_EQ(ta.row_count(), 21u);
    ASSERT_EQ(tb.row_count(), 21u);
    double worst = 0;
    for (const char* q : {"q1", "q2", "q3", "x", "y"})
        for (std::size_t k = 0; k < ta.row_count(); ++k)
            worst = std::max(worst, std::abs(col(ta, q)[k] - col(tb, q)[k]));
    EXPECT_LT(worst, 1e-7);
    // the dependent speeds are the contact point's velocity: x' and y' of the other run
    for (std::size_t k = 0; k < ta.row_count(); ++k) {
        EXPECT_NEAR(col(ta, "u4")[k], col(tb, "x'")[k], 1e-7);
        EXPECT_NEAR(col(ta, "u5")[k], col(tb, "y'")[k], 1e-7);
    }
    // it rolled and turned
    EXPECT_GT(std::abs(col(ta, "x").back()), 1.0);
    EXPECT_GT(std::abs(col(ta, "q1").back()), 0.5);
    // the energy, by hand at the start: T = m r^2 (u1^2 + u2^2)/2 + (A u1^2 + C u2^2 + A u3^2)/2,
    // A = m r^2/4, C = m r^2/2; V = m g r cos(q2); kept, as both transcripts say
    const double m = 2, A = m * r * r / 4, C = m * r * r / 2;
    const double E0 = m * r * r * (u1 * u1 + u2 * u2) / 2 + (A * u1 * u1 + C * u2 * u2 + A * u3 * u3) / 2 +
                      m * 9.81 * r * std::cos(q2);
    for (double e : col(ta, "energy")) EXPECT_NEAR(e, E0, 1e-9 * E0);
    for (double e : col(tb, "energy")) EXPECT_NEAR(e, E0, 1e-8 * E0);
    const std::string said = a.out.str();
    EXPECT_TRUE(has(said, "simulated t = 0 to 2 s: 21 rows")) << said;
    EXPECT_TRUE(has(said, "constraint motion_1: ")) << said;
    EXPECT_TRUE(has(said, "energy: ")) << said;
}

TEST(SimulateSpeedsScript, AuxiliarySpeedsBringOutTheContactForcesTheRoadMapSolvesFor) {
    // The disk in speeds again, with the no-slip constraints opened by auxiliary speeds ua1,
    // ua2 written into them as their violation (Kane & Levinson 1985, sec. 5.7) and the
    // grip's measures F_x, F_y unknown: the motion is the same, and the auxiliary equations'
    // forces at every row are those the disk simulated in coordinates solves with its
    // accelerations (its road-map's constrained dynamics), another method.
    const double q2 = 0.1, u1 = 0.3, u2 = 8, u3 = -0.5, r = 0.3;
    const double q1d = u3 / std::cos(q2), q3d = u2 - q1d * std::sin(q2);
    const std::string aux = R"(variable ua1' m/s, ua2' m/s
unknown F_x N, F_y N
force grip on D_P = F_x*Nx> + F_y*Ny>
w> = angvel(D, N)
kane K for q1, q2, q3, x, y speeds u1, u2, u3, u4, u5 \
  kinematics [u1 - dot(w>, Lx>), u2 - dot(w>, Ly>), u3 - dot(w>, Lz>), u4 - x', u5 - y'] \
  constraints [dot(vel(D_P, N), Nx>) - ua1, dot(vel(D_P, N), Ny>) - ua2] dependent u4, u5 auxiliary ua1, ua2
initial q2 = 0.1 rad, u1 = 0.3 rad/s, u2 = 8 rad/s, u3 = -0.5 rad/s
)";
    TempDir dir("alembert-speeds");
    ScriptInDir a(dir.path / "a"), b(dir.path / "b");
    a.run(std::string(kDiskHead) + kSpeedVariables + kDisk + aux + "simulate\n");
    b.run(std::string(kDiskHead) + kCoordinateVariables + kDisk + kInCoordinates + "initial q2 = " + num(q2) +
          " rad, q1' = " + num(q1d) + " rad/s, q2' = " + num(u1) + " rad/s, q3' = " + num(q3d) +
          " rad/s, x' = " + num(r * q3d) + " m/s\n" + "output q1, x, y, F_x, F_y\nsimulate\n");
    const Table ta = alembert::read_csv((dir.path / "a" / "simulation.csv").string());
    const Table tb = alembert::read_csv((dir.path / "b" / "simulation.csv").string());
    // the default columns hold the forces after the speeds
    EXPECT_EQ(ta.names, (std::vector<std::string>{"t", "q1", "q2", "q3", "x", "y", "u1", "u2", "u3", "u4", "u5",
                                                  "F_x", "F_y", "energy", "drift_motion_1", "drift_motion_2"}));
    ASSERT_EQ(ta.row_count(), 21u);
    ASSERT_EQ(tb.row_count(), 21u);
    double largest = 0;
    for (std::size_t k = 0; k < ta.row_count(); ++k) {
        for (const char* q : {"q1", "x", "y"}) EXPECT_NEAR(col(ta, q)[k], col(tb, q)[k], 1e-7) << q << " at row " << k;
        for (const char* f : {"F_x", "F_y"}) {
            EXPECT_NEAR(col(ta, f)[k], col(tb, f)[k], 1e-6) << f << " at row " << k;
            largest = std::max(largest, std::abs(col(tb, f)[k]));
        }
    }
    // the grip turns the disk: the forces are not zero (m v^2 / radius of its turn)
    EXPECT_GT(largest, 0.1);
    // energy is kept: the auxiliary speeds are zero in the motion
    const std::string said = a.out.str();
    EXPECT_TRUE(has(said, "energy: ")) << said;
}

TEST(SimulateSpeedsScript, AnAuxiliarySpeedAlongARodGivesItsTensionAsDerivedByHand) {
    // A particle P of mass m on a massless rod of length L turned by q about Nz from Nx, speed
    // u = q', gravity -g Ny; the auxiliary speed ua opens the rod along Ax, where its tension
    // T pulls P towards the pin. Along Ax: -T - m g sin(q) = m a.Ax = -m L u^2, so
    // T = m L u^2 - m g sin(q) at every row.
    TempDir dir("alembert-speeds");
    ScriptInDir a(dir.path);
    a.run(R"(newtonian N
frame A
particle P
constant m = 2 kg, L = 1.5 m, g = 9.81 m/s^2
variable q' rad, u' rad/s, ua' m/s
unknown T N
rotate A from N about z by q
translate P from N_o by L*Ax>
velocity P in N = L*u*Ay> + ua*Ax>
mass P = m
gravity -g*Ny>
force rod on P = -T*Ax>
kane K for q speeds u kinematics [u - q'] auxiliary ua
initial q = -0.5 rad, u = 1 rad/s
final time 3 s
output step 0.1 s
tolerance abs 1e-11 rel 1e-11
simulate
)");
    const Table t = alembert::read_csv((dir.path / "simulation.csv").string());
    EXPECT_EQ(t.names, (std::vector<std::string>{"t", "q", "u", "T", "energy"}));
    ASSERT_EQ(t.row_count(), 31u);
    const double m = 2, L = 1.5, g = 9.81;
    double lowest = 1e9, highest = -1e9;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double q = col(t, "q")[k], u = col(t, "u")[k];
        const double T = m * L * u * u - m * g * std::sin(q);
        EXPECT_NEAR(col(t, "T")[k], T, 1e-10 * std::max(1.0, std::abs(T))) << "at row " << k;
        lowest = std::min(lowest, col(t, "T")[k]);
        highest = std::max(highest, col(t, "T")[k]);
    }
    // it swung: the tension changed by more than half its weight
    EXPECT_GT(highest - lowest, m * g / 2);
}

TEST(SimulateSpeedsScript, TheImportedAutolevRollingDiskSimulatesAsTheScript) {
    // tests/lang/autolev/models/rolling_disk.al: the same disk, speeds U1..U3 D's angular
    // velocity in the lean frame B, U4 = X', U5 = Y' dependent
    std::ifstream in(std::string(ALEMBERT_SOURCE_DIR) + "/tests/lang/autolev/models/rolling_disk.al");
    std::stringstream source;
    source << in.rdbuf();
    alembert::lang::AutolevTranslation t = alembert::lang::translate_autolev(source.str(), "rolling_disk.al");
    ASSERT_TRUE(t.ok());
    TempDir dir("alembert-speeds");
    ScriptInDir a(dir.path / "a"), b(dir.path / "b");
    a.run(t.script + "initial Q2 = 0.1, U1 = 0.3, U2 = 8, U3 = -0.5\nfinal time 2 s\noutput step 0.1 s\n"
                     "tolerance abs 1e-11 rel 1e-11\nsimulate\n");
    b.run(std::string(kDiskHead) + kSpeedVariables + kDisk + kInSpeeds + "simulate\n");
    const Table ta = alembert::read_csv((dir.path / "a" / "simulation.csv").string());
    const Table tb = alembert::read_csv((dir.path / "b" / "simulation.csv").string());
    ASSERT_EQ(ta.row_count(), tb.row_count());
    for (const auto& [autolev, script] : std::vector<std::pair<std::string, std::string>>{
             {"Q1", "q1"}, {"Q2", "q2"}, {"Q3", "q3"}, {"X", "x"}, {"Y", "y"}, {"U4", "u4"}})
        for (std::size_t k = 0; k < ta.row_count(); ++k)
            EXPECT_NEAR(col(ta, autolev)[k], col(tb, script)[k], 1e-8) << autolev << " at row " << k;
    for (std::size_t k = 0; k < ta.row_count(); ++k)
        EXPECT_NEAR(col(ta, "energy")[k], col(tb, "energy")[k], 1e-9);
}

}  // namespace

}  // namespace simulate_speeds_script
