// SPDX-License-Identifier: MIT
// Private helpers of the codegen layer: atomic file writes and running the compiler.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace alembert::detail {

/// Creates `dir` (and its parents) if missing.
/// @throws alembert::ArgumentError naming `who`, the directory and the reason if it cannot be
///         created or is not a directory.
void ensure_directory(const std::filesystem::path& dir, const char* who);

/// Writes `text` to `path` atomically: to a temporary file in the same directory, then
/// renamed over `path`, so readers see the old file or the whole new one.
/// @throws alembert::ArgumentError naming `who`, the file and the reason on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& text,
                           const char* who);

/// The executable `name` found on PATH (or `name` itself when it holds a slash and exists);
/// empty when not found.
std::filesystem::path find_program(const std::string& name);

/// Runs `argv` (argv[0] a path) with stdout and stderr sent to `log`; returns its exit
/// status, or -1 if it could not be started or was killed.
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log);

}  // namespace alembert::detail
