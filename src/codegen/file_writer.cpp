// SPDX-License-Identifier: MIT
// Private helpers of the codegen layer: atomic file writes and running the compiler.
#include "file_writer.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

extern char** environ;

namespace alembert::detail {

namespace fs = std::filesystem;

void ensure_directory(const fs::path& dir, const char* who) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw ArgumentError(std::string(who) + ": the output directory '" + dir.string() +
                            "' exists and is not a directory; choose another path or remove it");
    fs::create_directories(dir, ec);
    if (ec)
        throw ArgumentError(std::string(who) + ": cannot create the output directory '" +
                            dir.string() + "' (" + ec.message() +
                            "); choose a path you can write to");
}

void write_file_atomically(const fs::path& path, const std::string& text, const char* who) {
    alembert::write_file_atomically(path, text, who);
}

fs::path find_program(const std::string& name) {
    if (name.empty()) return {};
    std::error_code ec;
    if (name.find('/') != std::string::npos)
        return fs::exists(name, ec) ? fs::path(name) : fs::path();
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (fs::exists(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

int run_program(const std::vector<std::string>& argv, const fs::path& log) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    int rc = ::posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    ChildProcess child(pid);  // terminated if the run is interrupted
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace alembert::detail
