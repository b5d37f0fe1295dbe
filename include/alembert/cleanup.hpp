// SPDX-License-Identifier: MIT
// What an interrupted run must not leave behind: temporary files and child processes.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace alembert {

/// A temporary file registered for removal if the process is interrupted (SIGINT, SIGTERM,
/// SIGHUP) while it exists; the writer renames it over its target when complete. The
/// destructor removes the file unless release() was called after the rename.
class TemporaryFile {
public:
    /// Registers `path` (not yet created) for removal on interruption and at destruction.
    explicit TemporaryFile(std::string path);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::string& path() const { return path_; }
    /// The file was renamed into place (or removed): nothing is left to clean up.
    void release();

private:
    std::string path_;
    int slot_;
};

/// Writes `bytes` to `path` all or nothing: into a temporary file beside it (registered as a
/// TemporaryFile, so an interrupted run leaves none behind), renamed over `path` once complete.
/// Every file Alembert writes goes through here. `who` names the caller in errors.
/// @throws alembert::ArgumentError naming `path` if it cannot be written (directory missing or
///         not writable, disk full) or replaced; `path` is then as it was.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const std::string& who);

/// A child process registered to be terminated (SIGTERM) if this process is interrupted
/// while the child runs; unregistered at destruction, after the caller has waited for it.
class ChildProcess {
public:
    explicit ChildProcess(pid_t pid);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

private:
    int slot_;
};

/// Installs handlers of SIGINT, SIGTERM and SIGHUP that remove the registered temporary
/// files, terminate the registered children and then end the process by the same signal
/// (so its exit status tells the signal, as a shell expects). Call once, from main().
void install_interrupt_cleanup();

}  // namespace alembert
