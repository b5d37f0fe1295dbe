// SPDX-License-Identifier: MIT
// Test helpers for scripts that write files: a temporary directory removed at the end, and an
// interpreter writing into it.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

namespace alembert::test {

/// A fresh directory under the system's temporary directory, removed with what it holds.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& prefix = "alembert-test") {
        std::string t = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
        path = ::mkdtemp(t.data());
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
};

/// A script interpreter whose outputs (simulate, inverse, report, codegen) go to `dir`.
struct ScriptInDir {
    std::ostringstream out, err;
    lang::Interpreter interp{out, err, false};
    explicit ScriptInDir(const std::filesystem::path& dir) { interp.set_output_dir(dir.string()); }
    /// Runs `text` as test.alb, expecting it to succeed.
    void run(const std::string& text) {
        ASSERT_EQ(interp.run(text, "test.alb"), lang::RunStatus::ok) << err.str();
    }
};

/// One interpreter that runs script texts in turn, each as test.alb: ok() expects it to run
/// and returns what it printed, fails() expects a script error and returns the message, at()
/// returns the value `evaluate e at values` prints.
struct ScriptSession {
    std::ostringstream out, err;
    lang::Interpreter interp{out, err, false};
    std::string ok(const std::string& text) {
        out.str("");
        EXPECT_EQ(interp.run(text, "test.alb"), lang::RunStatus::ok) << err.str();
        return out.str();
    }
    std::string fails(const std::string& text) {
        err.str("");
        EXPECT_EQ(interp.run(text, "test.alb"), lang::RunStatus::script_error) << out.str();
        return err.str();
    }
    double at(const std::string& e, const std::string& values) {
        std::string o = ok("evaluate " + e + (values.empty() ? "" : " at " + values) + "\n");
        std::size_t p = o.find("= ");
        if (p == std::string::npos) {
            ADD_FAILURE() << "no value for " << e << " in " << o;
            return NAN;
        }
        return std::stod(o.substr(p + 2));
    }
};

/// Whether `text` holds `part`.
inline bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// `v` written with 17 significant digits, to be read back exactly by a script.
inline std::string digits17(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace alembert::test
