// SPDX-License-Identifier: MIT
// A progress line on a terminal for long runs.
#pragma once

#include <chrono>
#include <string>

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

}  // namespace alembert
