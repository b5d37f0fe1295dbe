// SPDX-License-Identifier: MIT
// Lab files as labs write them, through `inverse`: rounded time columns read at their rate,
// markers the model does not use, missing samples, inDegrees for rotations only, units that
// contradict a coordinate, files in formats `inverse` does not read. Loads are checked against
// the closed-form inverse dynamics of the models.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace lab_motion_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

constexpr double kPi = std::numbers::pi;
constexpr double M = 1, m = 0.1, L = 0.5, g = 9.81;  // cart, pendulum, its centre, gravity
constexpr double m_swing = 2;                        // the marker trial's pendulum

// a scratch directory, removed at the end
struct Scratch {
    fs::path dir;
    explicit Scratch(const std::string& name)
        : dir(fs::temp_directory_path() /
              ("alembert_lab_motion_" + name + "_" + std::to_string(::getpid()))) {
        fs::create_directories(dir);
    }
    ~Scratch() { fs::remove_all(dir); }
};

// the script's model (built only), then `inverse` over `motion` with cutoff 0 (no filter)
struct InverseRun {
    RunStatus status;
    std::string out, err;
    alembert::Table loads;
};
InverseRun run_inverse(const std::string& model, const fs::path& motion, const fs::path& out_dir) {
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_model_only(true);
    interp.set_output_dir(out_dir.string());
    InverseRun r{interp.run(model, "model.alb"), "", "", {}};
    if (r.status == RunStatus::ok) r.status = interp.run_inverse(motion.string(), 0.0);
    r.out = out.str(), r.err = err.str();
    for (const char* name : {"loads.csv", "torques.csv", "forces.csv"})
        if (r.status == RunStatus::ok && fs::exists(out_dir / name))
            r.loads = alembert::read_csv((out_dir / name).string());
    return r;
}

// ---- a cart x (a translation) carrying a pendulum th (a rotation), no units declared ------

const std::string kCartPendulum = R"(newtonian N
particle Cart
body A
constant M = 1 kg, m = 0.1 kg, L = 0.5 m, g = 9.81 m/s^2
variable x'', th''
unknown F N, T_A N*m
translate Cart from N_o by x*Nx>
rotate A from N about z by th
translate A_o from Cart by 0>
translate Acm from A_o by -L*Ay>
mass Cart = M
mass A = m
inertia A = 0, 0, m*L^2/12
gravity -g*Ny>
force push on Cart = F*Nx>
torque T_A on A from N = T_A*Nz>
)";

std::string ten_decimals(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.10f", v);
    return text;
}

// the motion: x = 0.2 sin 2t m, th = 0.6 sin 3t rad
double x_of(double t) { return 0.2 * std::sin(2 * t); }
double th_of(double t) { return 0.6 * std::sin(3 * t); }

// closed form (Kane's equations by hand, Acm = (x + L sin th, -L cos th)):
// F = (M + m) x'' + m L (th'' cos th - th'^2 sin th), T_A = (I + m L^2) th'' + m L cos th x'' + m g
// L sin th
void cart_pendulum_loads(double t, double& F, double& T) {
    const double x2 = -0.8 * std::sin(2 * t), th = th_of(t), th1 = 1.8 * std::cos(3 * t),
                 th2 = -5.4 * std::sin(3 * t);
    const double I = m * L * L / 12;
    F = (M + m) * x2 + m * L * (th2 * std::cos(th) - th1 * th1 * std::sin(th));
    T = (I + m * L * L) * th2 + m * L * std::cos(th) * x2 + m * g * L * std::sin(th);
}

// a .mot of the motion at `rate` Hz for 2 s, times printed with `decimals`; th in degrees
// (inDegrees=yes), x in metres, values to 10 decimals; `labels` the column labels; `cell(k, c,
// text)` may replace the text of column c (0: x, 1: th) at sample k; `jitter` s is added to
// every third sample's time and taken from the next's, the motion sampled at those times
void write_cart_mot(const fs::path& p, double rate, int decimals,
                    const std::string& labels = "time\tx\tth",
                    const std::function<std::string(int, int, const std::string&)>& cell = nullptr,
                    double jitter = 0) {
    const int n = static_cast<int>(std::lround(2 * rate)) + 1;
    std::ofstream out(p);
    out << "Coordinates\nversion=1\nnRows=" << n << "\nnColumns=3\ninDegrees=yes\nendheader\n"
        << labels << "\n";
    char text[64];
    for (int k = 0; k < n; ++k) {
        const double t = k / rate + jitter * (k % 3 == 1 ? 1 : k % 3 == 2 ? -1 : 0);
        std::snprintf(text, sizeof text, "%.*f", decimals, t);
        out << text;
        const double values[2] = {x_of(t), th_of(t) * 180 / kPi};
        for (int c = 0; c < 2; ++c) {
            std::snprintf(text, sizeof text, "%.10f", values[c]);
            out << "\t" << (cell ? cell(k, c, text) : std::string(text));
        }
        out << "\n";
    }
}

// the largest difference of the loads from the closed form over the rows inside the ends (the
// one-sided differences there are less accurate), against their largest value
void expect_cart_pendulum_loads(const alembert::Table& loads, double rel) {
    ASSERT_EQ(loads.names, (std::vector<std::string>{"t", "F", "T_A"}));
    const std::size_t n = loads.row_count();
    double worst = 0, scale = 0;
    for (std::size_t r = 2; r + 2 < n; ++r) {
        double F, T;
        cart_pendulum_loads(loads.columns[0][r], F, T);
        worst =
            std::max({worst, std::abs(loads.columns[1][r] - F), std::abs(loads.columns[2][r] - T)});
        scale = std::max({scale, std::abs(F), std::abs(T)});
    }
    EXPECT_GT(scale, 0.5);
    EXPECT_LT(worst, rel * scale) << "worst " << worst << " of " << scale;
}

TEST(LabMotion, InDegreesConvertsThePendulumsAngleButNotTheCartsMetres) {
    // as OpenSim reads inDegrees=yes: th in degrees, x (a translation: it turns no frame) in m;
    // read as degrees, x would shrink 57-fold and F with it (0.24 N instead of 4.1 N)
    Scratch s("degrees");
    write_cart_mot(s.dir / "cart.mot", 100, 2);
    const InverseRun r = run_inverse(kCartPendulum, s.dir / "cart.mot", s.dir / "out");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    EXPECT_EQ(r.loads.row_count(), 201u);
    // central differences at 10 ms err by (3 h)^2/12 = 7.5e-5 of th''
    expect_cart_pendulum_loads(r.loads, 1e-3);
}

TEST(LabMotion, AMotAt150HzWithTimesTo8DecimalsIsReadAsUniform) {
    // 1/150 s printed to 8 decimals: steps of 0.00666666 and 0.00666667 s are rounding
    Scratch s("rate150");
    write_cart_mot(s.dir / "cart.mot", 150, 8);
    const InverseRun r = run_inverse(kCartPendulum, s.dir / "cart.mot", s.dir / "out");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    EXPECT_EQ(r.loads.row_count(), 301u);
    EXPECT_NEAR(r.loads.columns[0][1], 1.0 / 150, 1e-12);
    expect_cart_pendulum_loads(r.loads, 1e-3);
    EXPECT_NE(
        r.out.find(
            "301 samples at 150 Hz; the time column is printed to 1e-08 s and lies on that grid"),
        std::string::npos)
        << r.out;
}

TEST(LabMotion, AMotWithJitterIsResampledAtItsTypicalStepAndSaysSo) {
    // 0.3 ms of jitter at 100 Hz, times printed to 0.1 ms: not rounding; resampled at 100 Hz
    // (the typical step, not the median 10.3 ms step), stated, and the loads are those of the
    // motion at the grid's times
    Scratch s("jitter");
    write_cart_mot(s.dir / "cart.mot", 100, 4, "time\tx\tth", nullptr, 0.3e-3);
    const InverseRun r = run_inverse(kCartPendulum, s.dir / "cart.mot", s.dir / "out");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    EXPECT_NE(r.out.find("are not uniform; 201 samples became 200 at 100 Hz (the time column's "
                         "typical step) by a "
                         "natural cubic spline per column (a time was 0.3"),
              std::string::npos)
        << r.out;
    ASSERT_EQ(r.loads.row_count(), 200u);
    // the least-squares step of the times is 10 ms to 3e-6 of it
    EXPECT_NEAR(r.loads.columns[0][199], 1.99, 1e-5);
    expect_cart_pendulum_loads(r.loads, 2e-3);
}

TEST(LabMotion, AMissingSampleInAMotIsFilledWhenShortAndStatedOrNamedWithItsTime) {
    Scratch s("nan");
    // th missing at 3 samples (30 ms): filled by the spline through its valid samples, stated
    write_cart_mot(s.dir / "short.mot", 100, 2, "time\tx\tth",
                   [](int k, int c, const std::string& v) {
                       return c == 1 && k >= 100 && k < 103 ? std::string("NaN") : v;
                   });
    const InverseRun a = run_inverse(kCartPendulum, s.dir / "short.mot", s.dir / "a");
    ASSERT_EQ(a.status, RunStatus::ok) << a.err;
    EXPECT_NE(a.out.find("gap filled: 'th' missing from t = 1 s to 1.02 s (3 samples), filled by a "
                         "natural cubic "
                         "spline"),
              std::string::npos)
        << a.out;
    expect_cart_pendulum_loads(a.loads, 1e-2);
    // missing for 0.2 s: refused, naming the file, the column and the times
    write_cart_mot(s.dir / "long.mot", 100, 2, "time\tx\tth",
                   [](int k, int c, const std::string& v) {
                       return c == 1 && k >= 100 && k < 120 ? std::string("NaN") : v;
                   });
    const InverseRun b = run_inverse(kCartPendulum, s.dir / "long.mot", s.dir / "b");
    EXPECT_EQ(b.status, RunStatus::script_error);
    EXPECT_NE(
        b.err.find(
            "long.mot:108: 'th' is missing from t = 1 s to 1.19 s (20 samples: frames 101 to 120, "
            "lines 108 to 127), a gap of 0.21 s, longer than the 0.1 s that may be filled"),
        std::string::npos)
        << b.err;
}

TEST(LabMotion, AColumnInMetresForARotationIsRefusedOnEveryPath) {
    // th turns the pendulum's frame: a column 'th [m]' contradicts it, in a CSV and in a .mot
    Scratch s("units");
    {
        std::ofstream csv(s.dir / "cart.csv");
        csv << "t [s],x [m],th [m]\n";
        for (int k = 0; k <= 20; ++k)
            csv << 0.01 * k << "," << x_of(0.01 * k) << "," << th_of(0.01 * k) << "\n";
    }
    write_cart_mot(s.dir / "cart.mot", 100, 2, "time\tx [m]\tth [m]");
    for (const char* file : {"cart.csv", "cart.mot"}) {
        const InverseRun r = run_inverse(kCartPendulum, s.dir / file, s.dir / "out");
        EXPECT_EQ(r.status, RunStatus::script_error) << file;
        EXPECT_NE(r.err.find(std::string(file) +
                             ": column 'th [m]' is a length, but the coordinate 'th' is an angle "
                             "(it turns a frame of the model); give the column a unit of an angle"),
                  std::string::npos)
            << r.err;
    }
    // a unit of its own is kept whatever inDegrees says: th [rad] in an inDegrees=yes file
    write_cart_mot(s.dir / "rad.mot", 100, 2, "time\tx [m]\tth [rad]",
                   [](int k, int c, const std::string& v) {
                       return c == 1 ? ten_decimals(th_of(k / 100.0)) : v;
                   });
    const InverseRun r = run_inverse(kCartPendulum, s.dir / "rad.mot", s.dir / "rad");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    expect_cart_pendulum_loads(r.loads, 2e-3);
}

TEST(LabMotion, AFileInAnotherFormatIsNamedWithTheFormatsReadAndNoBytesPrinted) {
    Scratch s("formats");
    using namespace std::string_literals;
    const std::string zip =
        "PK\x03\x04\x14\x00\x06\x00\x08\x00\x00\x00!\x00\xb5U\x80\x01\n\x00\x00\x01"s;
    std::ofstream(s.dir / "trial.xlsx", std::ios::binary) << zip;
    std::ofstream(s.dir / "trial.csv", std::ios::binary) << zip;
    std::ofstream(s.dir / "trial.mot", std::ios::binary) << zip;
    const InverseRun x = run_inverse(kCartPendulum, s.dir / "trial.xlsx", s.dir / "out");
    EXPECT_EQ(x.status, RunStatus::script_error);
    EXPECT_NE(x.err.find("trial.xlsx' is a '.xlsx' file; inverse reads a motion from .csv"),
              std::string::npos)
        << x.err;
    const InverseRun c = run_inverse(kCartPendulum, s.dir / "trial.csv", s.dir / "out");
    EXPECT_NE(c.err.find("trial.csv:1: not a text file (byte 0x03); read_csv() reads CSV text"),
              std::string::npos)
        << c.err;
    const InverseRun o = run_inverse(kCartPendulum, s.dir / "trial.mot", s.dir / "out");
    EXPECT_NE(
        o.err.find(
            "trial.mot:1: not a text file (byte 0x03); this reader reads OpenSim storage files"),
        std::string::npos)
        << o.err;
    for (const std::string& e : {x.err, c.err, o.err})
        EXPECT_TRUE(std::none_of(e.begin(), e.end(), [](char ch) {
            const auto u = static_cast<unsigned char>(ch);
            return (u < 0x20 && ch != '\n') || u >= 0x80;
        })) << e;
}

// ---- a pendulum driven by a marker trial (.trc) ------------------------------------------

const std::string kMarkerPendulum = R"(newtonian N
body A
constant L = 0.5 m, m = 2 kg, g = 9.81 m/s^2
variable qA''
unknown T_A N*m
rotate A from N about z by qA
translate A_o from N_o by 0>
translate Acm from A_o by -L*Ay>
mass A = m
inertia A = 0, 0, m*L^2/12
gravity -g*Ny>
torque T_A on A from N = T_A*Nz>
marker PIV on A at A_o
marker MID on A at Acm
)";

TEST(LabMotion, A60HzTrcRoundedToMillisecondsKeepsItsFramesDespiteAMarkerNeverSeen) {
    // 151 frames at 60 Hz (DataRate 60), times rounded to ms; the marker RASH, which the model
    // does not use, is empty throughout. qA = 0.5 sin(pi t); T_A = (m L^2/12 + m L^2) qA'' + m g L
    // sin qA
    Scratch s("trc60");
    {
        std::ofstream out(s.dir / "swing.trc");
        out << "PathFileType\t4\t(X/Y/"
               "Z)\tswing.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
               "60\t60\t151\t3\tmm\nFrame#\tTime\tPIV\t\t\tMID\t\t\tRASH\t\t\n"
               "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\n\n";
        char row[256];
        for (int k = 0; k <= 150; ++k) {
            const double t = k / 60.0, q = 0.5 * std::sin(kPi * t);
            std::snprintf(row, sizeof row, "%d\t%.3f\t0\t0\t0\t%.6f\t%.6f\t0\t\t\t\n", k + 1, t,
                          1000 * L * std::sin(q), -1000 * L * std::cos(q));
            out << row;
        }
    }
    const InverseRun r = run_inverse(kMarkerPendulum, s.dir / "swing.trc", s.dir / "out");
    ASSERT_EQ(r.status, RunStatus::ok) << r.err;
    ASSERT_EQ(r.loads.row_count(), 151u);  // not resampled (at 58.8 Hz, to 148)
    EXPECT_NEAR(r.loads.columns[0][1], 1.0 / 60, 1e-12);
    EXPECT_NEAR(r.loads.columns[0][150], 2.5, 1e-12);
    double worst = 0, scale = 0;
    for (std::size_t k = 2; k + 2 < 151; ++k) {
        const double t = r.loads.columns[0][k], q = 0.5 * std::sin(kPi * t),
                     q2 = -0.5 * kPi * kPi * std::sin(kPi * t);
        const double T =
            (m_swing * L * L / 12 + m_swing * L * L) * q2 + m_swing * g * L * std::sin(q);
        worst = std::max(worst, std::abs(r.loads.columns[1][k] - T));
        scale = std::max(scale, std::abs(T));
    }
    // central differences at 1/60 s err by (pi h)^2/12 = 2.3e-4 of qA''
    EXPECT_GT(scale, 1.5);
    EXPECT_LT(worst, 1e-3 * scale) << worst;
    EXPECT_NE(r.out.find("151 samples at 60 Hz (the rate the file states); the time column is "
                         "printed to 0.001 s"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("markers in the file that the model does not use, not read: RASH"),
              std::string::npos)
        << r.out;
}

}  // namespace lab_motion_test
