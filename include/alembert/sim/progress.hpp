// SPDX-License-Identifier: MIT
// A progress line on a terminal for long runs.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace alembert {

/// A one-line progress indicator "label: t = 2.31 of 5 s (46%)" on standard error, shown
/// only when standard error is a terminal (isatty) and the run has lasted a second, refreshed
/// at most ten times a second, and erased when the run ends. Silent otherwise (pipes, CI).
class ProgressIndicator {
public:
    /// Progress of `label` from t0 to t1; `enabled` = false keeps it silent; the line appears
    /// once the run has lasted `delay`.
    ProgressIndicator(std::string label, double t0, double t1, bool enabled = true,
                      std::chrono::milliseconds delay = std::chrono::seconds(1));
    ProgressIndicator(const ProgressIndicator&) = delete;
    ProgressIndicator& operator=(const ProgressIndicator&) = delete;
    /// Erases the line if one was shown.
    ~ProgressIndicator();

    /// Reports that the run has reached t.
    void update(double t);
    /// True once a line has been shown.
    bool shown() const { return shown_; }

private:
    using Clock = std::chrono::steady_clock;
    std::string label_;
    double t0_, t1_;
    bool enabled_;
    std::chrono::milliseconds delay_;
    bool shown_ = false;
    Clock::time_point start_, last_;
};

/// A one-line indicator "label ... 12 s" on standard error for a step whose progress cannot
/// be counted (forming equations, planning a road-map, printing, a report): shown only when
/// standard error is a terminal and the step has lasted `delay`, its elapsed seconds refreshed
/// every second by a thread of its own, and erased when the step ends (the destructor).
/// Silent on pipes and in CI. The environment variable ALEMBERT_PROGRESS_DELAY_MS, a whole
/// number of milliseconds, replaces `delay` for every step.
class StepIndicator {
public:
    explicit StepIndicator(std::string label, bool enabled = true,
                           std::chrono::milliseconds delay = std::chrono::seconds(2));
    StepIndicator(const StepIndicator&) = delete;
    StepIndicator& operator=(const StepIndicator&) = delete;
    /// Stops the thread and erases the line if one was shown.
    ~StepIndicator();

    /// Erases the line of the indicator that is running, if any, so that what is printed next
    /// starts on a clean line (the indicator shows again at its next refresh). Called by
    /// whatever prints results while a step is under way.
    static void clear_line();

private:
    void run();
    std::string label_;
    std::chrono::milliseconds delay_;
    std::mutex mutex_;
    std::condition_variable stop_;
    bool stopping_ = false;
    bool shown_ = false;
    std::thread ticker_;
};

}  // namespace alembert
