// SPDX-License-Identifier: MIT
// The `plate` statement: a force plate's record as a known load on a body of a script's model,
// in its road-map and its inverse dynamics; checked by statics worked by hand.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace plate_statement_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

constexpr double m_A = 2, d_A = 0.5, g = 9.81;
const double qA = 10 * std::numbers::pi / 180;

// one plate's samples: force (N), centre of pressure (m), free moment about z (N m)
struct PlateSample {
    double Fx, Fy, px, py, Tz;
};

// a .mot with plates "ground_force" and "1_ground_force", 21 samples 10 ms apart; `at(k)` gives
// the two plates' samples
template <class F>
void write_plates(const fs::path& path, F at) {
    std::ofstream out(path);
    out << "plates\nversion=1\nnRows=21\nnColumns=19\ninDegrees=no\nendheader\ntime";
    for (const char* p : {"ground", "1_ground"})
        for (const char* c :
             {"_force_vx", "_force_vy", "_force_vz", "_force_px", "_force_py", "_force_pz"})
            out << "\t" << p << c;
    for (const char* p : {"ground", "1_ground"})
        for (const char* c : {"_torque_x", "_torque_y", "_torque_z"}) out << "\t" << p << c;
    out << "\n";
    for (int k = 0; k <= 20; ++k) {
        const auto [a, b] = at(k);
        out << 0.01 * k;
        for (const PlateSample& s : {a, b})
            out << "\t" << s.Fx << "\t" << s.Fy << "\t0\t" << s.px << "\t" << s.py << "\t0";
        for (const PlateSample& s : {a, b}) out << "\t0\t0\t" << s.Tz;
        out << "\n";
    }
}

// a rod A hinged to the ground at A_o (N_o), held still at qA = 10 deg by the ankle torque T_A,
// with plates on it; T_A over 0.2 s, the road-map printed
struct StandingRod {
    fs::path dir = fs::temp_directory_path() / ("alembert_plate_" + std::to_string(::getpid()));
    std::ostringstream out, err;
    StandingRod() { fs::create_directories(dir); }
    ~StandingRod() { fs::remove_all(dir); }
    RunStatus run(const std::string& plates) {
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        return interp.run(
            "newtonian N\nbody A\n"
            "constant g = 9.81 m/s^2, m_A = 2 kg, d_A = 0.5 m, I_A = 0.1 kg*m^2\n"
            "variable qA''\nunknown T_A N*m\n"
            "rotate A from N about z by qA\ntranslate A_o from N_o by 0>\n"
            "translate Acm from A_o by d_A*Ay>\nmass A = m_A\ninertia A = 0, 0, I_A\n"
            "gravity -g*Ny>\ntorque T_A on A from N = T_A*Nz>\n" +
                plates +
                "roadmap E for T_A\nmotion qA = 10 deg\nfinal time 0.2 s\noutput step 0.01 s\n"
                "inverse for T_A to \"rod\"\n",
            "rod.alb");
    }
    std::vector<double> T_A() const {
        return alembert::read_csv((dir / "rod" / "torques.csv").string()).columns[1];
    }
};

// statics of the rod about A_o: T_A + m g d sin qA + sum (px Fy - py Fx + Tz) = 0
double holding_torque(std::initializer_list<PlateSample> plates) {
    double T = -m_A * g * d_A * std::sin(qA);
    for (const PlateSample& p : plates) T -= p.px * p.Fy - p.py * p.Fx + p.Tz;
    return T;
}

TEST(PlateStatement, ARodStandingStillOnAPlateHoldsTheMomentsWorkedByHand) {
    StandingRod rod;
    // in contact to 0.1 s: 100 N up, 5 N forward at (0.3, -0.02) m, free moment 2 N m; then 10 N
    // at a wild centre of pressure, below the 20 N threshold: no contact
    const PlateSample on{5, 100, 0.3, -0.02, 2}, off{0, 10, 9, 9, 0}, none{0, 0, 0, 0, 0};
    write_plates(rod.dir / "plate.mot", [&](int k) { return std::pair{k <= 10 ? on : off, none}; });
    ASSERT_EQ(rod.run("plate floor on A from \"" + (rod.dir / "plate.mot").string() + "\"\n"),
              RunStatus::ok)
        << rod.err.str();
    const std::vector<double> T = rod.T_A();
    ASSERT_EQ(T.size(), 21u);
    // -2*9.81*0.5*sin(10 deg) - (0.3*100 + 0.02*5) - 2 = -33.8035 N m; off: -1.70349 N m
    for (int k = 0; k <= 20; ++k)
        EXPECT_NEAR(T[k], k <= 10 ? holding_torque({on}) : holding_torque({}), 1e-9)
            << "t = " << 0.01 * k;
    EXPECT_NEAR(holding_torque({on}), -33.80348862291259, 1e-12);
    // the road-map keeps the plate as a known load of A's free-body diagram
    const std::string text = rod.out.str();
    EXPECT_NE(text.find("| floor at floor_CoP from N "), std::string::npos) << text;
    EXPECT_NE(text.find("| floor free moment on A from N "), std::string::npos) << text;
    EXPECT_EQ(text.find("joint force at floor_CoP"), std::string::npos) << text;
    EXPECT_NE(text.find("in contact at 11 (force of 20 N or more)"), std::string::npos) << text;
}

TEST(PlateStatement, TwoPlatesOnOneBodyAddTheirMoments) {
    StandingRod rod;
    // plate 1 pushes forward of the hinge, plate 2 behind it and pulls back; both on throughout
    const PlateSample a{0, 60, 0.25, 0, 0}, b{-8, 40, -0.1, -0.05, -1.5};
    write_plates(rod.dir / "plates.mot", [&](int) { return std::pair{a, b}; });
    const std::string file = "\"" + (rod.dir / "plates.mot").string() + "\"";
    ASSERT_EQ(rod.run("plate left on A from " + file + "\nplate right on A from " + file +
                      " columns \"1_ground_force\" threshold 5 N\n"),
              RunStatus::ok)
        << rod.err.str();
    for (double T : rod.T_A()) EXPECT_NEAR(T, holding_torque({a, b}), 1e-9);
}

TEST(PlateStatement, MistakesNameTheFileAndTheColumns) {
    StandingRod rod;
    write_plates(rod.dir / "plate.mot", [](int) {
        return std::pair{PlateSample{}, PlateSample{}};
    });
    EXPECT_EQ(rod.run("plate floor on A from \"" + (rod.dir / "plate.mot").string() +
                      "\" columns \"2_ground_force\"\n"),
              RunStatus::script_error);
    EXPECT_NE(rod.err.str().find("plate '2_ground_force' lacks the columns 2_ground_force_vx"),
              std::string::npos)
        << rod.err.str();
    EXPECT_EQ(rod.run("plate floor on A from \"" + (rod.dir / "plate.mot").string() +
                      "\" threshold -1 N\n"),
              RunStatus::script_error);
    EXPECT_NE(rod.err.str().find("the contact threshold must be a force of 0 N or more"),
              std::string::npos)
        << rod.err.str();
}

TEST(PlateStatement, AMissingForceSampleIsAnErrorNotNoContact) {
    // in contact throughout, but the vertical force of sample 6 (t = 0.05 s) is missing: read as
    // no contact it would drop T_A from -33.8 to -1.7 N m there; it is refused with its time
    StandingRod rod;
    const PlateSample on{5, 100, 0.3, -0.02, 2}, none{0, 0, 0, 0, 0};
    const double nan = std::nan("");
    write_plates(rod.dir / "plate.mot",
                 [&](int k) { return std::pair{k == 5 ? PlateSample{5, nan, 0.3, -0.02, 2} : on, none}; });
    ASSERT_EQ(rod.run("plate floor on A from \"" + (rod.dir / "plate.mot").string() + "\"\n"),
              RunStatus::script_error);
    EXPECT_NE(rod.err.str().find("plate.mot:13: plate 'ground_force': column 'ground_force_vy' has no value (NaN) "
                                 "at t = 0.05 s, where a missing force would be read as no contact; fill the gap"),
              std::string::npos)
        << rod.err.str();
    // a centre of pressure left out (NaN) where the foot is off the plate is not used: accepted
    StandingRod off;
    const PlateSample lifted{0, 0, nan, nan, 0};
    write_plates(off.dir / "plate.mot", [&](int k) { return std::pair{k <= 10 ? on : lifted, none}; });
    ASSERT_EQ(off.run("plate floor on A from \"" + (off.dir / "plate.mot").string() + "\"\n"), RunStatus::ok)
        << off.err.str();
    const std::vector<double> T = off.T_A();
    for (int k = 0; k <= 20; ++k)
        EXPECT_NEAR(T[k], k <= 10 ? holding_torque({on}) : holding_torque({}), 1e-9) << "t = " << 0.01 * k;
}

}  // namespace plate_statement_test
