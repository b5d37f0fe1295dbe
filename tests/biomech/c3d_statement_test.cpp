// SPDX-License-Identifier: MIT
// A C3D trial through a script: its markers drive `inverse` and its force plate is a `plate`,
// giving the loads the same trial gives written as .trc + .mot, and the closed form.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"
#include "c3d_writer.hpp"

namespace c3d_statement_test {

namespace fs = std::filesystem;
using namespace alembert::lang;
using alembert::test::C3dPlateSpec;
using alembert::test::C3dSpec;

constexpr double kPi = std::numbers::pi;
constexpr double L = 0.5, m = 2, g = 9.81;

// a pendulum A hinged at N_o, its markers at the pivot and the mass centre, pushed by a plate's
// record (a lab with y up: the model's plane is the lab's X, Y)
std::string script(const std::string& plate_file, const std::string& motion_file) {
    return "newtonian N\nbody A\nconstant L = 0.5 m, m = 2 kg, g = 9.81 m/s^2\nvariable qA''\n"
           "unknown T_A N*m\nrotate A from N about z by qA\ntranslate A_o from N_o by 0>\n"
           "translate Acm from A_o by -L*Ay>\nmass A = m\ninertia A = 0, 0, m*L^2/12\ngravity -g*Ny>\n"
           "torque T_A on A from N = T_A*Nz>\nmarker PIV on A at A_o\nmarker MID on A at Acm\n"
           "plate floor on A from \"" + plate_file + "\"\ninverse for T_A from \"" + motion_file + "\" to \"out\"\n";
}

// the trial: 101 frames at 100 Hz, qA = 0.5 sin(pi t); the plate pushes with
// G = (20 + 10 t, 150 - 30 t, 0) N at (0.1 + 0.05 t, 0, 0) m, free moment 0.3 N m about Y
constexpr int kFrames = 101;
double q_of(double t) { return 0.5 * std::sin(kPi * t); }
struct Push {
    double G[3], Q[3], tau_y;
};
Push push_at(double t) { return {{20 + 10 * t, 150 - 30 * t, 0}, {0.1 + 0.05 * t, 0, 0}, 0.3}; }
// markers in mm, as floats (as the C3D file stores them)
float marker_mm(double t, int marker, int axis) {
    const double q = q_of(t);
    const double p[2][3] = {{0, 0, 0}, {L * std::sin(q), -L * std::cos(q), 0}};
    return static_cast<float>(1000 * p[marker][axis]);
}

// The plate in the floor Y = 0, centred at the lab's origin, 600 x 400 mm, its axes x = X,
// y = Z, z = -Y (down), ORIGIN (0, 0, -40) mm: its channels are the reaction on the body, G at
// Q with the couple tau Y, in its axes, the moment about O = (0, -0.04, 0) m in N mm.
C3dSpec c3d_trial() {
    C3dSpec s;
    s.rate = 100;
    s.labels = {"PIV", "MID"};
    C3dPlateSpec p;
    p.type = 2;
    p.corners = {300, 0, 200, -300, 0, 200, -300, 0, -200, 300, 0, -200};
    p.origin = {0, 0, -40};
    p.channels = {1, 2, 3, 4, 5, 6};
    s.plates = {p};
    for (const char* c : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
        s.analog_labels.push_back(c);
        s.analog_units.push_back(c[0] == 'F' ? "N" : "Nmm");
        s.analog_scale.push_back(1), s.analog_offset.push_back(0);
    }
    for (int k = 0; k < kFrames; ++k) {
        const double t = k / 100.0;
        s.points.push_back({{marker_mm(t, 0, 0), marker_mm(t, 0, 1), marker_mm(t, 0, 2)},
                            {marker_mm(t, 1, 0), marker_mm(t, 1, 1), marker_mm(t, 1, 2)}});
        const Push b = push_at(t);
        const double F[3] = {b.G[0], b.G[1], b.G[2]}, r[3] = {b.Q[0], b.Q[1] + 0.04, b.Q[2]};
        double M[3] = {r[1] * F[2] - r[2] * F[1], r[2] * F[0] - r[0] * F[2], r[0] * F[1] - r[1] * F[0]};
        M[1] += b.tau_y;
        // the plate's components of a lab vector: (v.x, v.z, -v.y)
        s.analog.push_back({F[0], F[2], -F[1], 1000 * M[0], 1000 * M[2], -1000 * M[1]});
    }
    return s;
}

// the same trial as OpenSim files: markers (.trc, the same floats) and ground reaction (.mot)
void write_trc_and_mot(const fs::path& trc, const fs::path& mot) {
    std::ofstream out(trc);
    out << "PathFileType\t4\t(X/Y/Z)\ttrial.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
        << "100\t100\t" << kFrames << "\t2\tmm\nFrame#\tTime\tPIV\t\t\tMID\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n";
    char text[64];
    for (int k = 0; k < kFrames; ++k) {
        const double t = k / 100.0;
        out << k + 1 << "\t" << alembert::format_csv_number(t);
        for (int i = 0; i < 2; ++i)
            for (int a = 0; a < 3; ++a) {
                std::snprintf(text, sizeof text, "%.9g", static_cast<double>(marker_mm(t, i, a)));
                out << "\t" << text;
            }
        out << "\n";
    }
    std::ofstream grf(mot);
    grf << "grf\nversion=1\nnRows=" << kFrames << "\nnColumns=10\ninDegrees=no\nendheader\ntime"
        << "\tground_force_vx\tground_force_vy\tground_force_vz\tground_force_px\tground_force_py\tground_force_pz"
        << "\tground_torque_x\tground_torque_y\tground_torque_z\n";
    for (int k = 0; k < kFrames; ++k) {
        const double t = k / 100.0;
        const Push b = push_at(t);
        grf << alembert::format_csv_number(t);
        for (double v : {b.G[0], b.G[1], b.G[2], b.Q[0], b.Q[1], b.Q[2], 0.0, b.tau_y, 0.0})
            grf << "\t" << alembert::format_csv_number(v);
        grf << "\n";
    }
}

struct ScriptRun {
    RunStatus status;
    std::string out, err;
    alembert::Table loads;
};
ScriptRun run_script(const fs::path& dir, const std::string& text) {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(dir.string());
    ScriptRun r{interp.run(text, (dir / "trial.alb").string()), out.str(), err.str(), {}};
    if (r.status == RunStatus::ok) r.loads = alembert::read_csv((dir / "out" / "torques.csv").string());
    return r;
}

struct C3dScratchDir {
    fs::path dir = fs::temp_directory_path() / ("alembert_c3d_script_" + std::to_string(::getpid()));
    C3dScratchDir() { fs::create_directories(dir); }
    ~C3dScratchDir() { fs::remove_all(dir); }
};

TEST(C3dStatement, AC3dTrialGivesTheLoadsOfTheSameTrialAsTrcAndMot) {
    C3dScratchDir s;
    fs::create_directories(s.dir / "c3d");
    fs::create_directories(s.dir / "opensim");
    const std::string c3d_path = (s.dir / "c3d" / "trial.c3d").string();
    alembert::test::write_c3d(c3d_path, c3d_trial());
    write_trc_and_mot(s.dir / "opensim" / "trial.trc", s.dir / "opensim" / "trial.mot");
    const ScriptRun c3d = run_script(s.dir / "c3d", script(c3d_path, c3d_path));
    ASSERT_EQ(c3d.status, RunStatus::ok) << c3d.err;
    const ScriptRun osim = run_script(s.dir / "opensim", script((s.dir / "opensim" / "trial.mot").string(), (s.dir / "opensim" / "trial.trc").string()));
    ASSERT_EQ(osim.status, RunStatus::ok) << osim.err;
    ASSERT_EQ(c3d.loads.row_count(), static_cast<std::size_t>(kFrames));
    ASSERT_EQ(osim.loads.row_count(), static_cast<std::size_t>(kFrames));
    // the same markers; the plate's channels are floats (7 digits): T_A within 1e-4 N m
    double worst = 0, worst_closed = 0, scale = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(kFrames); ++k) {
        EXPECT_EQ(c3d.loads.columns[0][k], osim.loads.columns[0][k]);
        worst = std::max(worst, std::abs(c3d.loads.columns[1][k] - osim.loads.columns[1][k]));
        if (k < 2 || k + 2 >= static_cast<std::size_t>(kFrames)) continue;
        // closed form: T_A = (m L^2/12 + m L^2) qA'' + m g L sin qA - (px Fy - py Fx)
        const double t = c3d.loads.columns[0][k], q = q_of(t), q2 = -0.5 * kPi * kPi * std::sin(kPi * t);
        const Push b = push_at(t);
        const double T = (m * L * L / 12 + m * L * L) * q2 + m * g * L * std::sin(q) - (b.Q[0] * b.G[1] - b.Q[1] * b.G[0]);
        worst_closed = std::max(worst_closed, std::abs(c3d.loads.columns[1][k] - T));
        scale = std::max(scale, std::abs(T));
    }
    EXPECT_LT(worst, 1e-4) << worst;
    // central differences at 0.01 s err by (pi h)^2/12 = 8e-5 of qA''
    EXPECT_GT(scale, 10);
    EXPECT_LT(worst_closed, 1e-3 * scale) << worst_closed;
    EXPECT_NE(c3d.out.find("/trial.c3d, 101 samples, t = 0 to 1 s"), std::string::npos) << c3d.out;
}

TEST(C3dStatement, AMarkerTheModelNeedsMissingFromTheC3dIsNamed) {
    C3dScratchDir s;
    C3dSpec spec = c3d_trial();
    spec.labels = {"PIV", "KNEE"};
    alembert::test::write_c3d((s.dir / "trial.c3d").string(), spec);
    const ScriptRun r = run_script(s.dir, script((s.dir / "trial.c3d").string(), (s.dir / "trial.c3d").string()));
    EXPECT_EQ(r.status, RunStatus::script_error);
    EXPECT_NE(r.err.find("the marker 'MID' is not in the marker file"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the file's markers are: PIV, KNEE"), std::string::npos) << r.err;
}

TEST(C3dStatement, ATruncatedC3dIsAScriptErrorNamingTheFile) {
    C3dScratchDir s;
    const std::string bytes = alembert::test::c3d_bytes(c3d_trial());
    std::ofstream((s.dir / "trial.c3d").string(), std::ios::binary).write(bytes.data(), 2000);
    const ScriptRun r = run_script(s.dir, script((s.dir / "trial.c3d").string(), (s.dir / "trial.c3d").string()));
    EXPECT_EQ(r.status, RunStatus::script_error);
    EXPECT_NE(r.err.find("trial.c3d: the file holds 101 frames"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the file is truncated"), std::string::npos) << r.err;
}

}  // namespace c3d_statement_test
