// SPDX-License-Identifier: MIT
// Temporary files and child processes removed when a run is interrupted: fixed tables of
// atomically claimed slots, so that the signal handler reads them without locks.
#include "alembert/cleanup.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include "alembert/error.hpp"

namespace alembert {

namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

// a slot is free (0), being filled (1) or live (2); the handler only reads live slots
struct FileSlot {
    std::atomic<int> state{0};
    char path[kPathBytes];
};
struct ChildSlot {
    std::atomic<int> state{0};
    pid_t pid = 0;
};

std::array<FileSlot, kSlots> g_files;
std::array<ChildSlot, kSlots> g_children;

template <class Slots>
int claim(Slots& slots) {
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (slots[i].state.compare_exchange_strong(expected, 1)) return i;
    }
    return -1;  // all taken: this one is not cleaned up on interruption
}

extern "C" void alembert_cleanup_on_signal(int sig) {
    // async-signal-safe calls only: unlink, kill, signal, raise
    for (ChildSlot& c : g_children)
        if (c.state.load() == 2) ::kill(c.pid, SIGTERM);
    for (FileSlot& f : g_files)
        if (f.state.load() == 2) ::unlink(f.path);
    ::signal(sig, SIG_DFL);
    ::raise(sig);
}

}  // namespace

TemporaryFile::TemporaryFile(std::string path) : path_(std::move(path)), slot_(-1) {
    if (path_.size() >= kPathBytes) return;
    slot_ = claim(g_files);
    if (slot_ < 0) return;
    std::memcpy(g_files[slot_].path, path_.c_str(), path_.size() + 1);
    g_files[slot_].state.store(2);
}

TemporaryFile::~TemporaryFile() {
    if (!path_.empty()) std::remove(path_.c_str());
    release();
}

void TemporaryFile::release() {
    path_.clear();
    if (slot_ >= 0) g_files[slot_].state.store(0);
    slot_ = -1;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const std::string& who) {
    namespace fs = std::filesystem;
    static std::atomic<unsigned> counter{0};
    // hidden, and unique per process and call: writers in several threads or processes
    // (batches of trials) never share a temporary
    const fs::path temporary = path.parent_path() / ("." + path.filename().string() + ".tmp" +
                                                     std::to_string(::getpid()) + "." +
                                                     std::to_string(counter++));
    TemporaryFile guard(temporary.string());  // removed on failure and on interruption
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw ArgumentError(who + ": cannot write '" + path.string() + "' (" +
                                std::strerror(errno) +
                                "); create its directory or choose a writable path");
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out)
            throw ArgumentError(who + ": writing '" + path.string() + "' failed (disk full?)");
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec)
        throw ArgumentError(who + ": cannot replace '" + path.string() + "' (" + ec.message() +
                            ")");
    guard.release();
}

ChildProcess::ChildProcess(pid_t pid) : slot_(claim(g_children)) {
    if (slot_ < 0) return;
    g_children[slot_].pid = pid;
    g_children[slot_].state.store(2);
}

ChildProcess::~ChildProcess() {
    if (slot_ >= 0) g_children[slot_].state.store(0);
}

void install_interrupt_cleanup() {
    struct sigaction sa {};
    sa.sa_handler = alembert_cleanup_on_signal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old {};
        // a signal ignored by the parent (nohup) stays ignored
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        ::sigaction(sig, &sa, nullptr);
    }
}

}  // namespace alembert
