// SPDX-License-Identifier: MIT
// Test helpers for scripts that write files: a temporary directory removed at the end, and an
// interpreter writing into it.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

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

/// The whole content of a file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace alembert::test
