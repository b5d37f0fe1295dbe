// SPDX-License-Identifier: MIT
// `alembert inverse` over an OpenSim motion (.mot, inDegrees=yes) gives the loads of the same
// motion as a CSV table in degrees.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/lang/interpreter.hpp"
#include "alembert/sim/table.hpp"

namespace {

namespace fs = std::filesystem;
using namespace alembert::lang;

TEST(StorageMotion, AMotFileDrivesInverseDynamicsLikeTheSameCsv) {
    const fs::path src(ALEMBERT_SOURCE_DIR);
    const fs::path dir = fs::temp_directory_path() / ("alembert_storage_motion_" + std::to_string(::getpid()));
    fs::create_directories(dir / "csv"), fs::create_directories(dir / "mot");
    // the sit-to-stand motion (t [s], qA, qB, qC [deg]) as OpenSim writes a coordinate file
    alembert::Table csv = alembert::read_csv((src / "examples/sit_to_stand_inverse/motion.csv").string());
    {
        std::ofstream mot(dir / "motion.mot");
        mot << "Coordinates\nversion=1\nnRows=" << csv.row_count() << "\nnColumns=4\ninDegrees=yes\n\n"
            << "Units are S.I. units (second, meters, Newtons, ...)\nendheader\ntime\tqA\tqB\tqC\n";
        for (std::size_t r = 0; r < csv.row_count(); ++r)
            mot << "\t" << alembert::format_csv_number(csv.columns[0][r]) << "\t" << alembert::format_csv_number(csv.columns[1][r])
                << "\t" << alembert::format_csv_number(csv.columns[2][r]) << "\t" << alembert::format_csv_number(csv.columns[3][r])
                << "\n";
    }
    std::ifstream in(src / "examples/sit_to_stand/model.alb");
    std::stringstream text;
    text << in.rdbuf();
    auto run = [&](const fs::path& motion, const fs::path& out) {
        std::ostringstream o, e;
        Interpreter interp(o, e, false);
        interp.set_model_only(true);
        interp.set_output_dir(out.string());
        EXPECT_EQ(interp.run(text.str(), "model.alb"), RunStatus::ok) << e.str();
        EXPECT_EQ(interp.run_inverse(motion.string(), 6.0), RunStatus::ok) << e.str();
        return alembert::read_csv((out / "loads.csv").string());
    };
    const alembert::Table a = run(src / "examples/sit_to_stand_inverse/motion.csv", dir / "csv");
    const alembert::Table b = run(dir / "motion.mot", dir / "mot");
    ASSERT_EQ(a.names, b.names);
    ASSERT_EQ(a.row_count(), b.row_count());
    for (std::size_t c = 0; c < a.columns.size(); ++c)
        for (std::size_t r = 0; r < a.row_count(); ++r)
            EXPECT_NEAR(a.columns[c][r], b.columns[c][r], 1e-9 * (1 + std::fabs(a.columns[c][r]))) << a.names[c];
    fs::remove_all(dir);
}

}  // namespace
