// SPDX-License-Identifier: MIT
// The `marker` statement: a script's model driven by a .trc trial, and a model whose markers
// disagree with the file named at the inverse statement with its coordinate.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/lang/interpreter.hpp"

namespace marker_statement_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

// model_lab.alb with `from` replaced by `to` in its text, run into a temporary directory
struct LabScript {
    fs::path dir = fs::temp_directory_path() / ("alembert_marker_" + std::to_string(::getpid()));
    std::ostringstream out, err;
    ~LabScript() { fs::remove_all(dir); }
    RunStatus run(const std::string& from, const std::string& to) {
        const fs::path path = fs::path(ALEMBERT_SOURCE_DIR) / "examples/sit_to_stand/model_lab.alb";
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        const std::size_t at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) s.replace(at, from.size(), to);
        Interpreter interp(out, err, false);
        interp.set_output_dir(dir.string());
        return interp.run(s, path.string());
    }
};

TEST(MarkerStatement, AMarkerAtTheWrongPointOfTheModelIsAnErrorNamingItsCoordinate) {
    // the thigh's knee marker declared at the thigh's centre of mass, 23.62 cm from the knee (21.1
    // cm after the lab's origin is fitted to all the markers)
    LabScript lab;
    EXPECT_EQ(lab.run("marker LFE on B at B_o", "marker LFE on B at Bcm"), RunStatus::script_error);
    const std::string e = lab.err.str();
    EXPECT_NE(e.find("model_lab.alb:45:1: error"), std::string::npos) << e;
    EXPECT_NE(e.find("marker 'LFE' (on B) is 21.1 cm from where the model puts it"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("check the sign and offset of 'qB'"), std::string::npos) << e;
}

TEST(MarkerStatement, AScriptWithoutMarkersCannotReadATrcTrial) {
    LabScript lab;
    EXPECT_EQ(lab.run("marker LMAL on A at A_o\n", "# no ankle marker\n"), RunStatus::script_error);
    EXPECT_NE(lab.err.str().find(
                  "'qA', 'qB' can change together without turning a segment with two markers"),
              std::string::npos)
        << lab.err.str();
}

}  // namespace marker_statement_test
