// SPDX-License-Identifier: MIT
// write_file_atomically: all or nothing, no temporary left behind.
#include "alembert/cleanup.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace {

namespace fs = std::filesystem;
using alembert::ArgumentError;

fs::path fresh_directory(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t entries(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

}  // namespace

TEST(WriteFileAtomically, WritesAndReplacesLeavingOnlyTheTarget) {
    const fs::path dir = fresh_directory("alembert-atomic");
    const fs::path target = dir / "table.csv";
    alembert::write_file_atomically(target, std::string("a,b\n1,2\n\0x", 10), "test");
    EXPECT_EQ(read(target), std::string("a,b\n1,2\n\0x", 10));  // bytes as given, NUL included
    alembert::write_file_atomically(target, "c\n", "test");
    EXPECT_EQ(read(target), "c\n");
    EXPECT_EQ(entries(dir), 1u);  // no temporary beside it
    fs::remove_all(dir);
}

TEST(WriteFileAtomically, AFailureNamesThePathAndLeavesTheTargetAsItWas) {
    const fs::path dir = fresh_directory("alembert-atomic-fail");
    // a directory that does not exist: nothing is written, the caller and path are named
    EXPECT_THROW_MSG(alembert::write_file_atomically(dir / "missing" / "x.csv", "1\n", "write_csv()"),
                     ArgumentError, "write_csv(): cannot write '");
    // the target is a directory: it cannot be replaced, and the temporary is removed
    fs::create_directories(dir / "taken");
    std::ofstream(dir / "taken" / "keep") << "kept";
    EXPECT_THROW_MSG(alembert::write_file_atomically(dir / "taken", "1\n", "test"), ArgumentError,
                     "cannot replace '");
    EXPECT_EQ(read(dir / "taken" / "keep"), "kept");
    EXPECT_EQ(entries(dir), 1u);
    fs::remove_all(dir);
}
