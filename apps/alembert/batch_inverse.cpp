// SPDX-License-Identifier: MIT
// Batches of inverse-dynamics trials run as child processes, with progress and a summary.
#include "batch_inverse.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <thread>
#include <vector>

#include "alembert/biomech/trial_batch.hpp"
#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

extern char** environ;

namespace alembert::cli {

namespace {

namespace fs = std::filesystem;

// the first line of a trial's log that says what went wrong
std::string failure_line(const fs::path& log, int status) {
    std::ifstream in(log);
    std::string line, first;
    while (std::getline(in, line)) {
        if (first.empty() && !line.empty()) first = line;
        if (line.find("error") != std::string::npos) return line;
    }
    if (!first.empty()) return first;
    return WIFSIGNALED(status) ? "ended by signal " + std::to_string(WTERMSIG(status)) : "exit status " + std::to_string(WEXITSTATUS(status));
}

void show_progress(std::size_t done, std::size_t total, std::size_t failed) {
    constexpr int width = 30;
    const int filled = total ? static_cast<int>(width * done / total) : width;
    std::cerr << "\rinverse: [" << std::string(static_cast<std::size_t>(filled), '#')
              << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << done << "/" << total
              << " trials" << (failed ? ", " + std::to_string(failed) + " failed" : "") << std::flush;
}

// the signal that interrupted the batch (SIGINT, SIGTERM, SIGHUP), 0 while none has
volatile std::sig_atomic_t g_batch_signal = 0;
extern "C" void on_batch_signal(int sig) { g_batch_signal = sig; }

// While a batch runs, an interruption is noted rather than ending the process at once: the
// running trials are stopped, what they left is removed, the finished trials' summary is
// written, and then the process ends by the same signal through the handlers it had (which
// remove registered temporary files and give the shell the signal's exit status).
class BatchInterruption {
public:
    BatchInterruption() {
        struct sigaction sa {};
        sa.sa_handler = on_batch_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = 0;  // no SA_RESTART: waitpid returns EINTR and the loop sees the signal
        for (std::size_t i = 0; i < kSignals.size(); ++i) {
            ::sigaction(kSignals[i], nullptr, &old_[i]);
            // a signal ignored by the parent (nohup) stays ignored
            if (old_[i].sa_handler != SIG_IGN) ::sigaction(kSignals[i], &sa, nullptr);
        }
    }
    ~BatchInterruption() { restore(); }
    void restore() {
        if (restored_) return;
        restored_ = true;
        for (std::size_t i = 0; i < kSignals.size(); ++i) ::sigaction(kSignals[i], &old_[i], nullptr);
    }
    // ends the process by the signal that interrupted the batch, through the old handlers
    [[noreturn]] void end_by_signal() {
        const int sig = g_batch_signal;
        restore();
        std::raise(sig);
        std::signal(sig, SIG_DFL);  // the old handler returned: end by the default action
        std::raise(sig);
        std::_Exit(128 + sig);
    }

private:
    static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
    std::array<struct sigaction, 3> old_{};
    bool restored_ = false;
};

}  // namespace

int run_inverse_batch(const BatchInverseOptions& o, const char* self) {
    // the trials: pattern, then this task's shard
    std::vector<std::string> trials;
    try {
        trials = expand_trial_pattern(o.pattern);
        if (!o.shard.empty()) trials = select_shard(trials, parse_shard(o.shard));
    } catch (const Error& e) {
        std::cerr << "alembert inverse: " << e.what() << "\n";
        return 2;
    }
    std::map<std::string, std::string> stems;
    for (const auto& t : trials) {
        const std::string stem = fs::path(t).stem().string();
        if (auto [it, fresh] = stems.emplace(stem, t); !fresh) {
            std::cerr << "alembert inverse: trials '" << it->second << "' and '" << t
                      << "' would share the result directory '" << stem << "'; rename one\n";
            return 2;
        }
    }
    const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    const bool progress = ::isatty(2) != 0;

    // children: at most `jobs` running; each writes OUT/STEM and its log
    std::vector<TrialOutcome> outcomes(trials.size());
    std::map<pid_t, std::size_t> running;
    std::vector<std::unique_ptr<ChildProcess>> guards;
    std::size_t next = 0, done = 0, failed = 0;
    g_batch_signal = 0;
    BatchInterruption interruption;
    std::vector<bool> stopped(trials.size(), false);  // trials stopped by the interruption
    auto finish = [&](pid_t pid, int status) {
        const std::size_t i = running.at(pid);
        running.erase(pid);
        const fs::path dir = fs::path(o.out) / fs::path(trials[i]).stem();
        TrialOutcome& out = outcomes[i];
        out.trial = trials[i];
        out.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        if (g_batch_signal && !out.ok) {
            // stopped part-way: nothing it wrote is a result
            stopped[i] = true;
            out.message = "interrupted before it finished; its results were removed";
            std::error_code ec;
            fs::remove_all(dir, ec);
            ++done;
            return;
        }
        if (out.ok) {
            try {
                // the table inverse wrote: loads.csv, or torques.csv / forces.csv when all of one kind
                fs::path table = dir / "loads.csv";
                for (const char* stem : {"torques.csv", "forces.csv"})
                    if (!fs::exists(table) && fs::exists(dir / stem)) table = dir / stem;
                out.peaks = calc_peaks(read_csv(table.string()));
            } catch (const Error& e) {
                out.ok = false, out.message = e.what();
            }
        } else {
            out.message = failure_line(dir / "log.txt", status);
        }
        failed += out.ok ? 0 : 1;
        ++done;
        if (progress) show_progress(done, trials.size(), failed);
    };
    bool stopping = false;
    while (done < trials.size()) {
        if (g_batch_signal && !stopping) {
            // stop: start no more trials, and end the running ones
            stopping = true;
            for (const auto& [pid, i] : running) ::kill(pid, SIGTERM);
        }
        if (stopping && running.empty()) break;
        while (!stopping && next < trials.size() && running.size() < jobs) {
            const fs::path dir = fs::path(o.out) / fs::path(trials[next]).stem();
            std::error_code ec;
            fs::create_directories(dir, ec);
            const std::string log = (dir / "log.txt").string(), dir_text = dir.string(),
                              cutoff = std::to_string(o.cutoff_hz);
            std::vector<std::string> args = {self, "inverse", o.model, "--motion", trials[next], "--out", dir_text,
                                             "--cutoff", cutoff};
            if (o.compiled) args.push_back("--compiled");
            if (o.tape) args.push_back("--tape");
            if (!o.unitless.empty()) args.insert(args.end(), {"--unitless", o.unitless});
            std::vector<char*> argv;
            for (auto& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            posix_spawn_file_actions_t actions;
            posix_spawn_file_actions_init(&actions);
            posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            posix_spawn_file_actions_adddup2(&actions, 1, 2);
            pid_t pid = 0;
            const int rc = ::posix_spawn(&pid, self, &actions, nullptr, argv.data(), environ);
            posix_spawn_file_actions_destroy(&actions);
            if (rc != 0) {
                std::cerr << "alembert inverse: cannot start a trial (" << std::strerror(rc) << ")\n";
                return 3;
            }
            guards.push_back(std::make_unique<ChildProcess>(pid));
            running[pid] = next++;
        }
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, 0);
        if (pid > 0 && running.count(pid)) finish(pid, status);
        else if (pid < 0 && errno != EINTR) break;
    }
    if (progress) std::cerr << "\n";
    if (stopping) {
        // the trials that finished keep their results and their summary; the others are named
        std::vector<TrialOutcome> finished;
        std::size_t not_run = 0, interrupted = 0;
        for (std::size_t i = 0; i < trials.size(); ++i) {
            if (i >= next) ++not_run;
            else if (stopped[i]) ++interrupted;
            else finished.push_back(outcomes[i]);
        }
        const std::string summary = (fs::path(o.out) / "summary.csv").string();
        try {
            write_batch_summary(finished, summary);
        } catch (const Error& e) {
            std::cerr << "alembert inverse: " << e.what() << "\n";
        }
        std::cerr << "alembert inverse: interrupted: " << finished.size() << " of " << trials.size()
                  << " trials finished (summary in " << summary << "), " << interrupted
                  << " stopped and their results removed, " << not_run << " not started\n";
        interruption.end_by_signal();
    }

    // the summary
    const std::string summary = (fs::path(o.out) / "summary.csv").string();
    try {
        write_batch_summary(outcomes, summary);
    } catch (const Error& e) {
        std::cerr << "alembert inverse: " << e.what() << "\n";
        return 2;
    }
    std::cout << trials.size() << " trials: " << trials.size() - failed << " ok, " << failed << " failed; summary in "
              << summary << "\n";
    for (const auto& out : outcomes)
        if (!out.ok) std::cout << "failed: " << out.trial << ": " << out.message << "\n";
    // the trials' gait cycles (inverse ... cycles): mean and SD across them, plotted
    std::vector<std::string> ok_dirs;
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (outcomes[i].ok) ok_dirs.push_back((fs::path(o.out) / fs::path(trials[i]).stem()).string());
    try {
        const CycleStatisticsReport cycles = write_cycle_statistics(ok_dirs, o.out);
        if (cycles.curves) {
            std::cout << "cycles: " << cycles.curves << " from " << cycles.trials << " trials; mean and SD in";
            for (const std::string& f : cycles.files) std::cout << " " << f;
            for (const std::string& f : cycles.plot.files) std::cout << " " << f;
            if (!cycles.plot.drawn) std::cout << " (no plot: " << cycles.plot.message << ")";
            std::cout << "\n";
        }
    } catch (const Error& e) {
        std::cout << "cycles: not pooled: " << e.what() << "\n";
        return 1;
    }
    return failed ? 1 : 0;
}

}  // namespace alembert::cli
