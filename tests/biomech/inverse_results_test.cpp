// SPDX-License-Identifier: MIT
// What `inverse` writes beyond loads: the coordinates' rates and accelerations, each load's power
// (the load times the rate it works through), per kg, and OpenSim storage files; checked against
// the closed-form dynamics of a swinging rod and the relative rate of a two-segment limb.
#include "alembert/biomech/inverse_results.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/error.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace inverse_results_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

constexpr double m_A = 2, d_A = 0.5, I_A = 0.1, g = 9.81;

// a rod A hinged at N_o, swung by T_A as qA = 0.3 sin(2 t) over 1 s
struct SwingingRod {
    fs::path dir = fs::temp_directory_path() / ("alembert_results_" + std::to_string(::getpid()));
    std::ostringstream out, err;
    SwingingRod() { fs::create_directories(dir); }
    ~SwingingRod() { fs::remove_all(dir); }
    RunStatus run(const std::string& model, const std::string& clauses) {
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        return interp.run(model + "final time 1 s\noutput step 0.05 s\ninverse for " + clauses +
                              " plot none to \"out\"\n",
                          "swing.alb");
    }
    alembert::Table table(const std::string& name) const {
        return alembert::read_csv((dir / "out" / (name + ".csv")).string());
    }
    std::string text(const std::string& name) const {
        std::ifstream in(dir / "out" / name);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

const std::string kRod =
    "newtonian N\nbody A\n"
    "constant g = 9.81 m/s^2, m_A = 2 kg, d_A = 0.5 m, I_A = 0.1 kg*m^2\n"
    "variable qA''\nunknown T_A N*m\n"
    "rotate A from N about z by qA\ntranslate A_o from N_o by 0>\n"
    "translate Acm from A_o by d_A*Ay>\nmass A = m_A\ninertia A = 0, 0, I_A\n"
    "gravity -g*Ny>\ntorque T_A on A from N = T_A*Nz>\nconstant w = 2 rad/s\nmotion qA = "
    "0.3*sin(w*t)\n";

// qA and its derivatives, and the torque that makes it: the centre of mass at
// d (-sin qA, cos qA) has potential m g d cos qA, so (I + m d^2) qA'' = T_A + m g d sin qA
struct RodState {
    double q, qd, qdd, T;
};
RodState rod_at(double t) {
    RodState s{0.3 * std::sin(2 * t), 0.6 * std::cos(2 * t), -1.2 * std::sin(2 * t), 0};
    s.T = (I_A + m_A * d_A * d_A) * s.qdd - m_A * g * d_A * std::sin(s.q);
    return s;
}

TEST(InverseResults, ARodsKinematicsAndPowerAreItsClosedForm) {
    SwingingRod rod;
    ASSERT_EQ(rod.run(kRod, "T_A"), RunStatus::ok) << rod.err.str();
    const alembert::Table T = rod.table("torques"), K = rod.table("kinematics"),
                          P = rod.table("powers");
    ASSERT_EQ(K.names, (std::vector<std::string>{"t", "qA", "qA'", "qA''"}));
    EXPECT_EQ(K.units, (std::vector<std::string>{"s", "rad", "rad/s", "rad/s^2"}));
    ASSERT_EQ(P.names, (std::vector<std::string>{"t", "P_T_A"}));
    EXPECT_EQ(P.units[1], "W");
    ASSERT_EQ(K.row_count(), 21u);
    ASSERT_EQ(P.row_count(), 21u);
    for (std::size_t k = 0; k < 21; ++k) {
        const double t = K.columns[0][k];
        const RodState s = rod_at(t);
        EXPECT_NEAR(K.columns[1][k], s.q, 1e-12) << t;
        EXPECT_NEAR(K.columns[2][k], s.qd, 1e-12) << t;
        EXPECT_NEAR(K.columns[3][k], s.qdd, 1e-12) << t;
        EXPECT_NEAR(T.columns[1][k], s.T, 1e-9) << t;
        // the power is the rate of the rod's energy: T_A qA' = d/dt (1/2 I_o qA'^2 + m g d cos qA)
        EXPECT_NEAR(P.columns[1][k], s.T * s.qd, 1e-9) << t;
        const double dE =
            (I_A + m_A * d_A * d_A) * s.qd * s.qdd - m_A * g * d_A * std::sin(s.q) * s.qd;
        EXPECT_NEAR(P.columns[1][k], dE, 1e-9) << t;
    }
    // at t = 0.5 s the rod swings forward (qA' = 0.324) while T_A = -0.58 N m brakes it: the
    // torque absorbs energy, so its power is negative
    EXPECT_LT(P.columns[1][10], 0);
    EXPECT_NE(
        rod.out.str().find("torques.sto, kinematics.csv, kinematics.sto, powers.csv, powers.sto"),
        std::string::npos)
        << rod.out.str();
}

TEST(InverseResults, AKneeTorquesPowerIsItsMomentTimesTheRelativeAngularVelocity) {
    // thigh T and leg L each at its absolute angle from N; the knee torque T_K acts on L from T,
    // so it works through w_L - w_T = qL' - qT', the hip torque T_H through qT'
    SwingingRod limb;
    const std::string model =
        "newtonian N\nbody T, L\n"
        "constant g = 9.81 m/s^2, m_T = 7 kg, m_L = 3 kg, l_T = 0.4 m, d_T = 0.17 m, d_L = 0.18 m\n"
        "constant I_T = 0.1 kg*m^2, I_L = 0.04 kg*m^2\n"
        "variable qT'', qL''\nunknown T_H N*m, T_K N*m\n"
        "rotate T from N about z by qT\nrotate L from N about z by qL\n"
        "translate T_o from N_o by 0>\ntranslate Tcm from T_o by -d_T*Ty>\n"
        "translate L_o from T_o by -l_T*Ty>\ntranslate Lcm from L_o by -d_L*Ly>\n"
        "mass T = m_T\ninertia T = 0, 0, I_T\nmass L = m_L\ninertia L = 0, 0, I_L\n"
        "gravity -g*Ny>\n"
        "torque T_H on T from N = T_H*Nz>\ntorque T_K on L from T = T_K*Nz>\n"
        "constant w = 3 rad/s\nmotion qT = 0.4*sin(w*t), qL = 0.4*sin(w*t) - 0.5*(1 - cos(w*t))\n";
    ASSERT_EQ(limb.run(model, "T_H, T_K"), RunStatus::ok) << limb.err.str();
    const alembert::Table T = limb.table("torques"), P = limb.table("powers");
    ASSERT_EQ(P.names, (std::vector<std::string>{"t", "P_T_H", "P_T_K"}));
    ASSERT_EQ(P.row_count(), 21u);
    for (std::size_t k = 0; k < 21; ++k) {
        const double t = P.columns[0][k];
        const double qTd = 1.2 * std::cos(3 * t), qLd = qTd - 1.5 * std::sin(3 * t);
        EXPECT_NEAR(P.columns[1][k], T.columns[1][k] * qTd, 1e-9) << t;
        EXPECT_NEAR(P.columns[2][k], T.columns[2][k] * (qLd - qTd), 1e-9) << t;
    }
}

TEST(InverseResults, PerKgDividesLoadsAndPowersByTheBodyMass) {
    SwingingRod rod;
    ASSERT_EQ(rod.run(kRod, "T_A per kg mass 80 kg"), RunStatus::ok) << rod.err.str();
    const alembert::Table T = rod.table("torques"), P = rod.table("powers");
    EXPECT_EQ(T.units[1], "N m/kg");
    EXPECT_EQ(P.units[1], "W/kg");
    for (std::size_t k = 0; k < T.row_count(); ++k) {
        const RodState s = rod_at(T.columns[0][k]);
        EXPECT_NEAR(T.columns[1][k], s.T / 80, 1e-11);
        EXPECT_NEAR(P.columns[1][k], s.T * s.qd / 80, 1e-11);
    }
    EXPECT_NE(rod.out.str().find("loads and powers per kg of body mass 80 kg"), std::string::npos)
        << rod.out.str();
    // a mass that is not one is refused at its place
    SwingingRod bad;
    EXPECT_EQ(bad.run(kRod, "T_A per kg mass 80 m"), RunStatus::script_error);
    EXPECT_EQ(bad.run(kRod, "T_A per kg 80 kg"), RunStatus::script_error);
    EXPECT_NE(bad.err.str().find("per kg mass 70 kg"), std::string::npos) << bad.err.str();
}

TEST(InverseResults, StorageFilesBesideTheCsvHoldTheSameNumbersInSI) {
    SwingingRod rod;
    ASSERT_EQ(rod.run(kRod, "T_A"), RunStatus::ok) << rod.err.str();
    for (const std::string name : {"torques", "kinematics", "powers"}) {
        const std::string sto = rod.text(name + ".sto");
        const alembert::Table csv = rod.table(name);
        const std::string header =
            name + "\nversion=1\nnRows=21\nnColumns=" + std::to_string(csv.names.size()) +
            "\ninDegrees=no\nendheader\ntime";
        EXPECT_EQ(sto.substr(0, header.size()), header) << sto;
        const alembert::StorageFile s =
            alembert::read_storage((rod.dir / "out" / (name + ".sto")).string());
        ASSERT_EQ(s.table.columns.size(), csv.columns.size());
        for (std::size_t c = 0; c < csv.columns.size(); ++c)
            EXPECT_EQ(s.table.columns[c], csv.columns[c]) << name;
    }
    // the same run writes the same bytes
    const std::string first = rod.text("powers.sto") + rod.text("kinematics.csv");
    ASSERT_EQ(rod.run(kRod, "T_A"), RunStatus::ok) << rod.err.str();
    EXPECT_EQ(rod.text("powers.sto") + rod.text("kinematics.csv"), first);
}

// one plate's record, 101 samples 10 ms apart: the vertical force rises from 0 to 400 N over
// 0.1 s from t = 0.05 s and from t = 0.65 s, and falls over 0.1 s from t = 0.4 s and t = 1 s;
// its centre of pressure stays at the hinge, so it pushes along the rod's pivot only
void write_steps(const fs::path& path) {
    std::ofstream out(path);
    out << "steps\nversion=1\nnRows=101\nnColumns=10\ninDegrees=no\nendheader\ntime\tground_force_"
           "vx\t"
           "ground_force_vy\tground_force_vz\tground_force_px\tground_force_py\tground_force_pz\t"
           "ground_torque_x\tground_torque_y\tground_torque_z\n";
    for (int k = 0; k <= 100; ++k) {
        const int ms = 10 * k;  // exact ramps: 40 N per 10 ms
        double F = 0;
        for (int on : {50, 650}) {
            const int off = on + 350;
            if (ms > on && ms < on + 100)
                F = 4 * (ms - on);
            else if (ms >= on + 100 && ms <= off)
                F = 400;
            else if (ms > off && ms < off + 100)
                F = 400 - 4 * (ms - off);
        }
        out << 0.01 * k << "\t0\t" << F << "\t0\t0\t0\t0\t0\t0\t0\n";
    }
}

TEST(InverseResults, CyclesFromAPlateAreResampledFromStrikeToStrike) {
    SwingingRod rod;
    write_steps(rod.dir / "steps.mot");
    const std::string plate =
        "plate floor on A from \"" + (rod.dir / "steps.mot").string() + "\"\n";
    ASSERT_EQ(rod.run(kRod + plate, "T_A cycles floor"), RunStatus::ok) << rod.err.str();
    // strikes 5 ms into each rise (20 N of 40 N per 10 ms): 0.055 and 0.655 s; foot off 5 ms
    // before the end of the first fall: 0.495 s, (0.495 - 0.055) / 0.6 = 73.3 % of the cycle
    std::istringstream events(rod.text("gait_events.csv"));
    std::string line;
    std::getline(events, line);
    EXPECT_EQ(line, "event,t [s]");
    for (const auto& [what, t] :
         {std::pair{"foot strike", 0.055}, {"foot off", 0.495}, {"foot strike", 0.655}}) {
        ASSERT_TRUE(std::getline(events, line));
        EXPECT_EQ(line.substr(0, line.find(',')), what);
        EXPECT_NEAR(std::stod(line.substr(line.find(',') + 1)), t, 1e-12) << line;
    }
    const alembert::Table c = rod.table("cycle_1");
    ASSERT_EQ(c.row_count(), 101u);
    EXPECT_EQ(c.names[0], "cycle");
    const std::size_t q = c.column_index("qA"), qd = c.column_index("qA'"),
                      P = c.column_index("P_T_A");
    for (std::size_t i = 0; i <= 100; i += 10) {
        const double t = 0.055 + 0.6 * static_cast<double>(i) / 100;
        const RodState s = rod_at(t);
        // linear interpolation between samples 0.05 s apart: error below h^2/8 max|f''|
        EXPECT_NEAR(c.columns[q][i], s.q, 0.05 * 0.05 / 8 * 1.2 + 1e-12) << i;
        EXPECT_NEAR(c.columns[qd][i], s.qd, 0.05 * 0.05 / 8 * 2.4 + 1e-12) << i;
        EXPECT_NEAR(c.columns[P][i], s.T * s.qd, 0.05) << i;
    }
    EXPECT_NE(rod.out.str().find("cycle 0.055 to 0.655 s, foot off at 73.3"), std::string::npos)
        << rod.out.str();
    EXPECT_NE(rod.out.str().find(
                  "gait events from floor (vertical force crossing 20 N): foot strikes at t = "
                  "0.055, 0.655 s; foot offs at t = 0.495 s"),
              std::string::npos)
        << rod.out.str();
    // run again without cycles: the cycles of the earlier run are not left to be taken for its
    ASSERT_EQ(rod.run(kRod + plate, "T_A"), RunStatus::ok) << rod.err.str();
    EXPECT_FALSE(fs::exists(rod.dir / "out" / "cycle_1.csv"));
    // a name that is no plate is refused at its place
    SwingingRod bad;
    EXPECT_EQ(bad.run(kRod, "T_A cycles floor"), RunStatus::script_error);
    EXPECT_NE(bad.err.str().find("'floor' is not a plate"), std::string::npos) << bad.err.str();
}

TEST(InverseResults, APlateFileOfTheTrialNeedsATrial) {
    // "{trial}_grf.mot" is each trial's record in `alembert inverse --motion`; run otherwise, it
    // is refused with how to run it
    SwingingRod rod;
    EXPECT_EQ(rod.run(kRod + "plate floor on A from \"{trial}_grf.mot\"\n", "T_A"),
              RunStatus::script_error);
    EXPECT_NE(
        rod.err.str().find(
            "'{trial}' stands for the trial that alembert inverse SCRIPT --motion TRIAL reads"),
        std::string::npos)
        << rod.err.str();
}

TEST(InverseResults, PerKgRefusesAColumnThatIsNotALoad) {
    alembert::Table t;
    t.add_column("t", "s");
    t.add_column("qA", "rad");
    t.columns[0] = {0};
    t.columns[1] = {1};
    try {
        alembert::calc_per_kg(t, 70);
        FAIL();
    } catch (const alembert::ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("column 'qA' is in 'rad'"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(alembert::calc_per_kg(t, 0), alembert::ArgumentError);
}

}  // namespace inverse_results_test
