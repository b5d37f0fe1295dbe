// SPDX-License-Identifier: MIT
// Messages in the script's own words: library errors reach a script's user as the statements,
// names, files and units of the script, with whole hints, never as C++ calls.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

struct MessagesDir {
    fs::path path;
    MessagesDir() {
        std::string t = (fs::temp_directory_path() / "alembert-messages-XXXXXX").string();
        path = ::mkdtemp(t.data());
    }
    ~MessagesDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// the diagnostic (message, quoted line, caret and hint) a script stops with
std::string error_of(const std::string& text, const fs::path& file = "test.alb") {
    MessagesDir dir;
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(dir.path.string());
    EXPECT_EQ(interp.run(text, file.string()), RunStatus::script_error) << out.str();
    return err.str();
}

// a C++ call or scope in a message: "Frame::orient_axis(", "A.set_inertia(", "run_simulation('"
void expect_no_cxx(const std::string& message) {
    static const std::regex cxx(R"re(::|\b\w+\.set_\w+\(|\b[a-z]+_[a-z_]+\((\)|')|SymbolTable|Options\b)re");
    EXPECT_FALSE(std::regex_search(message, cxx)) << message;
}

const std::string kMessagesPendulum =
    "newtonian N\nbody A\nvariable q''\nconstant M = 1 kg, L = 1 m, g = 9.81 m/s^2\n"
    "rotate A from N about z by q\ntranslate Acm from N_o by L*Ax>\nmass A = M\ngravity -g*Ny>\n";

TEST(ScriptMessages, AMissingInertiaNamesTheInertiaStatement) {
    const std::string e = error_of(kMessagesPendulum + "kane K for q\n");
    EXPECT_NE(e.find("test.alb:9:6: error: the inertia of 'A' is not set; give it: inertia A = Ixx, Iyy, Izz"),
              std::string::npos)
        << e;
    expect_no_cxx(e);
}

TEST(ScriptMessages, AnUndefinedVelocityNamesTheTranslateAndVelocityStatements) {
    const std::string e = error_of(
        "newtonian N\nbody A, B\nvariable q''\nrotate A from N about z by q\nrotate B from A about z by q\n"
        "translate Acm from N_o by 1 m*Ax>\nmass A = 1 kg; mass B = 1 kg\n"
        "inertia A = 0, 0, 1 kg*m^2; inertia B = 0, 0, 1 kg*m^2\nkane K for q\n");
    EXPECT_NE(e.find("error: velocity of 'Bcm' in frame 'N' is not defined; locate Bcm from a point whose "
                     "velocity in N is known (translate Bcm from N_o by ...), or give its velocity: "
                     "velocity Bcm in N = ..."),
              std::string::npos)
        << e;
    expect_no_cxx(e);
}

TEST(ScriptMessages, AConstantWithoutAValueNamesItsDeclarationNotTheSymbolTable) {
    const std::string e = error_of(
        "newtonian N\nparticle P\nvariable x''\nconstant M = 1 kg, k\ntranslate P from N_o by x*Nx>\n"
        "mass P = M\nforce spring on P = -k*x*Nx>\ninitial x = 1 m\nsimulate plot none\n");
    EXPECT_NE(e.find("test.alb:9:1: error: the constant 'k' has no value; give it one where it is declared "
                     "(constant k = ...)\n"),
              std::string::npos)
        << e;
    // the hint of a failed solve (a singular mass matrix) is not given for a missing value
    EXPECT_EQ(e.find("singular"), std::string::npos) << e;
    expect_no_cxx(e);
}

TEST(ScriptMessages, ASpringBetweenCoincidentPointsIsNamedWithItsFix) {
    // its force -k (|r| - L0) r/|r| is 0/0 where r = 0: once a NaN blamed on masses and inertias
    const std::string e = error_of(
        "newtonian N\nparticle P\nvariable x''\nconstant M = 1 kg, k = 10 N/m\ntranslate P from N_o by x*Nx>\n"
        "mass P = M\nspring s1 between P and N_o stiffness k length 0.1 m\ninitial x = 0\nsimulate plot none\n");
    EXPECT_NE(e.find("test.alb:7:8: error: the spring 's1' joins P and N_o, which coincide at the start "
                     "(x = 0, x' = 0): the direction of its force, from one end to the other, is undefined"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("hint: start with its ends apart"), std::string::npos) << e;
    EXPECT_EQ(e.find("nan"), std::string::npos) << e;
}

TEST(ScriptMessages, AnUncontrollableSystemHasReciprocalConditionZero) {
    // F pushes P only; Q's spring-mass states are out of its reach: rank 2 of 4
    const std::string e = error_of(
        "newtonian N\nparticle P, Q\nvariable x'', y''\nunknown F N\nconstant M = 1 kg, k = 1 N/m\n"
        "translate P from N_o by x*Nx>\ntranslate Q from N_o by y*Ny>\nmass P = M; mass Q = M\n"
        "force push on P = F*Nx>\nforce sp on Q = -k*y*Ny>\nkane K for x, y\n"
        "linearize K at x = 0, y = 0 inputs F poles -1, -2, -3, -4 gains G\n");
    EXPECT_NE(e.find("error: the input cannot steer every state: the controllability matrix [b, A b, ...] "
                     "reaches 2 of the 4 states (reciprocal condition number 0, below 1e-12)"),
              std::string::npos)
        << e;
    expect_no_cxx(e);
}

TEST(ScriptMessages, UnitHintsAreWhole) {
    // an angle given a time: once "give the number a unit, e.g. " and nothing after it
    std::string e = error_of("newtonian N\nbody A\nvariable q'' rad\nrotate A from N about z by q\nmotion q = t\n");
    EXPECT_NE(e.find("error: the motion of q must be an angle or a number, but it is a time (s)"), std::string::npos)
        << e;
    EXPECT_NE(e.find("hint: it must have no unit: multiply it by a constant declared in 1/s (or divide it by "
                     "one in s) so that the units cancel\n"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find("e.g. \n"), std::string::npos) << e;
    // a bare number where a length is wanted: the number with the unit
    e = error_of(kMessagesPendulum + "inertia A = 0, 0, 1 kg*m^2\nstop when dot(pos(Acm, N_o), Ny>) = 2\n");
    EXPECT_NE(e.find("hint: give the number a unit, e.g. 2 m\n"), std::string::npos) << e;
    // gravity without units
    e = error_of("newtonian N\nparticle P\nvariable x''\ngravity -9.81*Ny>\n");
    EXPECT_NE(e.find("hint: give its numbers units so that it comes out in m/s^2 (e.g. 2 m/s^2)\n"),
              std::string::npos)
        << e;
}

TEST(ScriptMessages, ANegativeOutputStepIsTheOutputStepNotAColumn) {
    const std::string e =
        error_of(kMessagesPendulum + "inertia A = 0, 0, 1 kg*m^2\noutput step -0.1 s\nsimulate plot none\n");
    EXPECT_NE(e.find("error: the output step must be positive, not -0.1"), std::string::npos) << e;
    EXPECT_NE(e.find("hint: write output step 0.01 s\n"), std::string::npos) << e;
    EXPECT_EQ(e.find("column name"), std::string::npos) << e;
}

TEST(ScriptMessages, ARelativeToleranceOfOneOrMoreIsRefused) {
    // 5 let every step pass whatever its error: a pendulum's q(5 s) came out -6.64 rad, not -3.17,
    // with exit status 0
    const std::string e = error_of(kMessagesPendulum + "inertia A = 0, 0, 1 kg*m^2\ntolerance rel 5\n");
    EXPECT_NE(e.find("error: the relative tolerance must be below 1, not 5"), std::string::npos) << e;
    EXPECT_NE(e.find("hint: write tolerance rel 1e-10 (the default is 1e-8)\n"), std::string::npos) << e;
}

TEST(ScriptMessages, AMarkerMissingFromTheFileIsNamedWithTheFile) {
    MessagesDir dir;
    std::ofstream(dir.path / "trial.trc") << "PathFileType\t4\t(X/Y/Z)\ttrial.trc\n"
                                             "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
                                             "100\t100\t2\t2\tmm\n"
                                             "Frame#\tTime\tANK\t\t\tKNEE\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n"
                                             "1\t0.00\t0\t0\t0\t0\t400\t0\n2\t0.01\t0\t0\t0\t0\t400\t0\n";
    const fs::path script = dir.path / "lab.alb";
    std::ofstream(script) << "";
    const std::string e = error_of(
        "newtonian N\nbody A\nvariable qA''\nunknown T N*m\nrotate A from N about z by qA\n"
        "translate A_o from N_o by 0>\ntranslate Acm from A_o by 20 cm*Ay>\nmass A = 6 kg; inertia A = 0, 0, 0.1 kg*m^2\n"
        "point Top on A\ntranslate Top from A_o by 40 cm*Ay>\ntorque T on A from N = T*Nz>\n"
        "marker ANK on A at A_o\nmarker ACR on A at Top\ninverse for T from \"trial.trc\"\n",
        script);
    EXPECT_NE(e.find("lab.alb:13:8: error: the marker 'ACR' is not in the marker file '"), std::string::npos) << e;
    EXPECT_NE(e.find("trial.trc' (read by the statement at line 14); the file's markers are: ANK, KNEE"),
              std::string::npos)
        << e;
    expect_no_cxx(e);
}

}  // namespace
