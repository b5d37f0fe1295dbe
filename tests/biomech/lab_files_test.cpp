// SPDX-License-Identifier: MIT
// Lab files: .trc, .mot/.sto and CSV read in SI, written as .sto, malformed files refused.
#include "alembert/biomech/lab_files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "alembert/error.hpp"
#include "biomech_data.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

namespace fs = std::filesystem;


fs::path lab_scratch(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("alembert_lab_files_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(ReadTrc, ReadsMarkersInMetresWithMissingCellsAsNaN) {
    MarkerTable m = read_trc(test::biomech_data("gappy.trc"));
    ASSERT_EQ(m.markers, (std::vector<std::string>{"R.Knee", "R.Ankle"}));
    EXPECT_EQ(m.data_rate_hz, 100.0);
    EXPECT_EQ(m.file_unit, "mm");
    ASSERT_EQ(m.table.row_count(), 5u);
    EXPECT_EQ(m.table.names[0], "time");
    EXPECT_DOUBLE_EQ(m.table.columns[0][3], 0.03);
    // 102.0 mm is 0.102 m
    EXPECT_DOUBLE_EQ(m.table.columns[m.column("R.Knee", 0)][1], 0.102);
    EXPECT_DOUBLE_EQ(m.table.columns[m.column("R.Ankle", 1)][0], 0.080);
    EXPECT_TRUE(std::isnan(m.table.columns[m.column("R.Ankle", 0)][1]));
    EXPECT_TRUE(std::isnan(m.table.columns[m.column("R.Ankle", 2)][2]));
    EXPECT_EQ(m.table.lines[0], 7);
    EXPECT_TRUE(m.notes.empty());
    EXPECT_THROW_MSG(m.column("L.Knee", 0), ArgumentError, "no marker 'L.Knee' in the marker file; its markers are: R.Knee, R.Ankle");
}

TEST(ReadTrc, MalformedFilesNameTheLineWhatAndFix) {
    EXPECT_THROW_MSG(read_trc(test::biomech_data("bad_cell.trc")), ArgumentError,
                     "bad_cell.trc:8: marker 'HEEL' Y: 'abc' is not a finite number; leave the cell empty");
    EXPECT_THROW_MSG(read_trc(test::biomech_data("wrong_count.trc")), ArgumentError,
                     "wrong_count.trc:4: 2 marker names, but the header's NumMarkers says 3");
    EXPECT_THROW_MSG(read_trc(test::biomech_data("angle_units.trc")), ArgumentError,
                     "angle_units.trc:3: the header's Units is 'deg', not a length");
    EXPECT_THROW_MSG(read_trc(test::biomech_data("ik_output.mot")), ArgumentError,
                     "ik_output.mot:1: not an OpenSim marker file");
    EXPECT_THROW_MSG(read_trc(test::biomech_data("none.trc")), ArgumentError, "cannot open");
}

TEST(ReadTrc, TimesGoingBackwardsAreRefusedAtTheirLine) {
    const fs::path p = lab_scratch("backwards.trc");
    std::ofstream(p) << "PathFileType\t4\t(X/Y/Z)\tb.trc\n"
                        "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
                        "100\t100\t2\t1\tm\n"
                        "Frame#\tTime\tA\t\t\n\t\tX1\tY1\tZ1\n\n"
                        "1\t0.01\t1\t2\t3\n2\t0.00\t1\t2\t3\n";
    EXPECT_THROW_MSG(read_trc(p.string()), ArgumentError,
                     "backwards.trc:8: time 0 does not come after 0.01");
}

TEST(ReadTrc, AnInfiniteCellIsRefusedAtItsMarkerAndLine) {
    // an infinite coordinate once reached the fit, which then blamed another marker at the
    // first sample; an infinite time was blamed on the row after it
    const std::string head = "PathFileType\t4\t(X/Y/Z)\ti.trc\n"
                             "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
                             "100\t100\t3\t2\tmm\n"
                             "Frame#\tTime\tA\t\t\tB\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n"
                             "1\t0.00\t1\t2\t3\t4\t5\t6\n";
    const fs::path cell = lab_scratch("inf_cell.trc");
    std::ofstream(cell) << head << "2\t0.01\t1\t2\t3\tinf\t5\t6\n3\t0.02\t1\t2\t3\t4\t5\t6\n";
    EXPECT_THROW_MSG(read_trc(cell.string()), ArgumentError,
                     "inf_cell.trc:8: marker 'B' X: 'inf' is not a finite number");
    const fs::path time = lab_scratch("inf_time.trc");
    std::ofstream(time) << head << "2\tinf\t1\t2\t3\t4\t5\t6\n3\t0.02\t1\t2\t3\t4\t5\t6\n";
    EXPECT_THROW_MSG(read_trc(time.string()), ArgumentError,
                     "inf_time.trc:8: the time cell 'inf' is not a finite number");
    // the header's numbers too: a DataRate of inf was read without a word
    const fs::path rate = lab_scratch("inf_rate.trc");
    std::string inf_head = head;
    inf_head.replace(inf_head.find("100\t100\t3"), 3, "inf");
    std::ofstream(rate) << inf_head << "2\t0.01\t1\t2\t3\t4\t5\t6\n";
    EXPECT_THROW_MSG(read_trc(rate.string()), ArgumentError,
                     "inf_rate.trc:3: the header's DataRate is 'inf'; it must be a positive, finite number");
}

TEST(ReadStorage, ReadsAnOpenSimMotionWithItsDegreesFlag) {
    StorageFile s = read_storage(test::biomech_data("ik_output.mot"));
    EXPECT_TRUE(s.in_degrees);
    EXPECT_EQ(s.header.at("version"), "1");
    ASSERT_EQ(s.table.names, (std::vector<std::string>{"time", "hip_flexion_r", "knee_angle_r"}));
    ASSERT_EQ(s.table.row_count(), 4u);
    EXPECT_DOUBLE_EQ(s.table.columns[2][3], -8.0);
    // angles marked as degrees convert to radians through their unit
    Table motion = motion_table_from_storage(s, {"hip_flexion_r", "knee_angle_r"});
    EXPECT_EQ(motion.names[0], "t");
    EXPECT_EQ(motion.units[1], "deg");
    EXPECT_DOUBLE_EQ(parse_unit(motion.units[1]).factor * motion.columns[1][0], std::numbers::pi / 18);
    EXPECT_THROW_MSG(motion_table_from_storage(s, {"ankle"}), ArgumentError, "'ankle'");
}

TEST(ReadStorage, MalformedHeadersAndRowsAreRefused) {
    EXPECT_THROW_MSG(read_storage(test::biomech_data("no_endheader.sto")), ArgumentError,
                     "no_endheader.sto:8: no 'endheader' line");
    EXPECT_THROW_MSG(read_storage(test::biomech_data("wrong_columns.mot")), ArgumentError,
                     "wrong_columns.mot:7: 2 column labels, but the header says nColumns=3");
    EXPECT_THROW_MSG(read_storage(test::biomech_data("bad_degrees.sto")), ArgumentError,
                     "bad_degrees.sto:3: inDegrees is 'maybe'; write inDegrees=yes or inDegrees=no");
    const fs::path inf = lab_scratch("inf_cell.sto");
    std::ofstream(inf) << "Coordinates\nnRows=2\nnColumns=2\ninDegrees=no\nendheader\ntime\tq\n"
                          "0\t1\n0.01\tinf\n";
    EXPECT_THROW_MSG(read_storage(inf.string()), ArgumentError,
                     "inf_cell.sto:8: column 'q': 'inf' is not a finite number");
    const fs::path p = lab_scratch("short_row.sto");
    std::ofstream(p) << "x\nendheader\ntime\ta\tb\n0\t1\t2\n0.1\t1\n";
    EXPECT_THROW_MSG(read_storage(p.string()), ArgumentError,
                     "short_row.sto:5: 2 cells, but there are 3 column labels");
}

TEST(ReadStorage, ALabelMayStateItsUnitAndInDegreesLeavesItAlone) {
    const fs::path p = lab_scratch("units.mot");
    std::ofstream(p) << "Coordinates\nversion=1\nnRows=2\nnColumns=4\ninDegrees=yes\nendheader\n"
                        "time\tpelvis_tx [m]\tknee [rad]\thip\n0\t0.5\t1\t10\n0.01\t0.6\t1.1\t20\n";
    StorageFile s = read_storage(p.string());
    ASSERT_EQ(s.table.names, (std::vector<std::string>{"time", "pelvis_tx", "knee", "hip"}));
    EXPECT_EQ(s.table.units, (std::vector<std::string>{"s", "m", "rad", ""}));
    // inDegrees=yes gives degrees to the listed rotations without a unit of their own
    Table motion = motion_table_from_storage(s, {"knee", "hip"});
    EXPECT_EQ(motion.units, (std::vector<std::string>{"s", "m", "rad", "deg"}));
    const fs::path bad = lab_scratch("bad_unit.mot");
    std::ofstream(bad) << "x\nendheader\ntime\tq [furlong]\n0\t1\n";
    EXPECT_THROW_MSG(read_storage(bad.string()), ArgumentError,
                     "bad_unit.mot:3: column 'q [furlong]': unknown unit 'furlong'");
}

TEST(ReadLabFiles, ABinaryFileIsRefusedByNameWithoutItsBytes) {
    // an .xlsx is a zip archive: "PK\x03\x04..."
    using namespace std::string_literals;
    const std::string zip = "PK\x03\x04\x14\x00\x06\x00\x08\x00!\x00\n\x00\x01"s;
    for (const char* name : {"sheet.trc", "sheet.sto", "sheet.csv"}) std::ofstream(lab_scratch(name), std::ios::binary) << zip;
    EXPECT_THROW_MSG(read_trc(lab_scratch("sheet.trc").string()), ArgumentError,
                     "sheet.trc:1: not a text file (byte 0x03); this reader reads OpenSim marker files");
    EXPECT_THROW_MSG(read_storage(lab_scratch("sheet.sto").string()), ArgumentError,
                     "sheet.sto:1: not a text file (byte 0x03); this reader reads OpenSim storage files");
    EXPECT_THROW_MSG(read_lab_table(lab_scratch("sheet.csv").string()), ArgumentError,
                     "sheet.csv:1: not a text file (byte 0x03); read_csv() reads CSV text");
    EXPECT_THROW_MSG(read_lab_table("sheet.xlsx"), ArgumentError,
                     "has the extension '.xlsx'; known lab files are .trc");
}

TEST(WriteStorage, WritesSIValuesThatReadBackExactly) {
    Table t;
    t.add_column("t", "s");
    t.add_column("knee", "deg");
    t.add_column("M_knee", "N m");
    t.columns[0] = {0, 0.01, 0.02};
    t.columns[1] = {90, 45, 0.84};
    t.columns[2] = {1.5, -2.25, 3};
    const fs::path p = lab_scratch("out.sto");
    write_storage(t, p.string(), "inverse dynamics");
    const std::string text = slurp(p);
    EXPECT_EQ(text.substr(0, text.find("endheader")),
              "inverse dynamics\nversion=1\nnRows=3\nnColumns=3\ninDegrees=no\n");
    StorageFile back = read_storage(p.string());
    EXPECT_FALSE(back.in_degrees);
    EXPECT_EQ(back.table.names, (std::vector<std::string>{"time", "knee", "M_knee"}));
    EXPECT_DOUBLE_EQ(back.table.columns[1][0], std::numbers::pi / 2);
    EXPECT_EQ(back.table.columns[1][2], 0.84 * (std::numbers::pi / 180));
    EXPECT_EQ(back.table.columns[2][1], -2.25);
    // same table, same bytes
    write_storage(t, p.string(), "inverse dynamics");
    EXPECT_EQ(slurp(p), text);
    EXPECT_THROW_MSG(write_storage(t, "/nonexistent_dir/x.sto", "x"), ArgumentError,
                     "cannot write '/nonexistent_dir/x.sto'");
}

TEST(ReadLabTable, ChoosesTheReaderByExtension) {
    EXPECT_EQ(read_lab_table(test::biomech_data("gappy.trc")).columns.size(), 7u);
    EXPECT_EQ(read_lab_table(test::biomech_data("ik_output.mot")).columns.size(), 3u);
    Table csv = read_lab_table(test::biomech_data("irregular.csv"));
    EXPECT_EQ(csv.units[0], "ms");
    EXPECT_EQ(csv.units[1], "deg");
    EXPECT_THROW_MSG(read_lab_table("trial.xlsx"), ArgumentError,
                     "has the extension '.xlsx'; known lab files are .trc");
}

}  // namespace
}  // namespace alembert
