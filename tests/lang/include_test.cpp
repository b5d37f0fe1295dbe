// SPDX-License-Identifier: MIT
// include "file.alb": a model and its studies in separate files, paths relative to the
// including script, errors at the included file's own line and column, cycles refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "alembert/lang/interpreter.hpp"

namespace include_lang_test {

namespace fs = std::filesystem;
using namespace alembert::lang;

struct Files {
    fs::path root;
    Files() {
        std::string t = (fs::temp_directory_path() / "alembert-include-XXXXXX").string();
        root = ::mkdtemp(t.data());
    }
    ~Files() {
        std::error_code ec;
        fs::remove_all(root, ec);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        fs::path p = root / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p;
    }
};

// runs the file as `alembert run` does: its text, named by its path
RunStatus run_file(const fs::path& p, std::string& out, std::string& err) {
    std::ostringstream o, e;
    Interpreter interp(o, e, false);
    interp.set_output_dir(p.parent_path().string());
    std::ifstream in(p);
    std::ostringstream text;
    text << in.rdbuf();
    RunStatus s = interp.run(text.str(), p.string());
    out = o.str(), err = e.str();
    return s;
}

TEST(Include, AStudyRunsTheModelItIncludesWithPathsRelativeToEachFile) {
    // study.alb includes models/pendulum.alb, which includes its constants beside it
    Files f;
    f.write("models/constants.alb", "constant L = 2 m, g = 9.81 m/s^2, m = 1 kg\n");
    f.write("models/pendulum.alb",
            "newtonian N\nparticle P\nvariable q'' rad\ninclude \"constants.alb\"\nframe A\n"
            "rotate A from N about z by q\ntranslate P from N_o by -L*Ay>\nmass P = m\n"
            "gravity -g*Ny>\nkane K for q\n");
    fs::path study = f.write("study.alb", "include \"models/pendulum.alb\"\nlinearize K at q = 0\n");
    std::string out, err;
    ASSERT_EQ(run_file(study, out, err), RunStatus::ok) << err;
    // the hanging pendulum: lambda = +-sqrt(g/L) i
    const double w = std::sqrt(9.81 / 2);
    std::ostringstream expected;
    expected.precision(6);
    expected << "lambda1 = " << w << "i";
    EXPECT_NE(out.find(expected.str()), std::string::npos) << out;
}

TEST(Include, AnErrorInAnIncludedFileIsReportedAtItsOwnLineThenAtTheInclude) {
    Files f;
    f.write("bad.alb", "newtonian N\nbody A\nrotate A from N about q by 1\n");
    fs::path top = f.write("top.alb", "# the model\ninclude \"bad.alb\"\n");
    std::string out, err;
    EXPECT_EQ(run_file(top, out, err), RunStatus::script_error);
    const std::string inner = (f.root / "bad.alb").string() + ":3:23: error: 'q' is not an axis";
    const std::string outer = (f.root / "top.alb").string() + ":2:9: error: the included file 'bad.alb' stopped at the error above";
    ASSERT_NE(err.find(inner), std::string::npos) << err;
    ASSERT_NE(err.find(outer), std::string::npos) << err;
    EXPECT_LT(err.find(inner), err.find(outer));
    EXPECT_NE(err.find("    3 | rotate A from N about q by 1\n      |                       ^"), std::string::npos) << err;
}

TEST(Include, MissingFilesAndCyclesAreErrorsAtTheInclude) {
    Files f;
    fs::path miss = f.write("miss.alb", "newtonian N\ninclude \"nowhere/model.alb\"\n");
    std::string out, err;
    EXPECT_EQ(run_file(miss, out, err), RunStatus::script_error);
    EXPECT_NE(err.find("miss.alb:2:9: error: the included file 'nowhere/model.alb' is not a file"), std::string::npos) << err;
    EXPECT_NE(err.find("hint: paths a script includes are relative to the including script's directory"), std::string::npos);
    // a.alb -> b.alb -> a.alb
    fs::path a = f.write("a.alb", "newtonian N\ninclude \"b.alb\"\n");
    f.write("b.alb", "frame A\ninclude \"a.alb\"\n");
    EXPECT_EQ(run_file(a, out, err), RunStatus::script_error);
    EXPECT_NE(err.find("b.alb:2:9: error: including 'a.alb' here makes a cycle: a.alb -> b.alb -> a.alb"),
              std::string::npos) << err;
    // a file that includes itself
    fs::path self = f.write("self.alb", "include \"self.alb\"\n");
    EXPECT_EQ(run_file(self, out, err), RunStatus::script_error);
    EXPECT_NE(err.find("makes a cycle: self.alb -> self.alb"), std::string::npos) << err;
}

}  // namespace include_lang_test
