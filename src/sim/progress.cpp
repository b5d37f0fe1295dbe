// SPDX-License-Identifier: MIT
// Progress indicator on standard error.
#include "alembert/sim/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace alembert {

ProgressIndicator::ProgressIndicator(std::string label, double t0, double t1, bool enabled,
                                     std::chrono::milliseconds delay)
    : label_(std::move(label)),
      t0_(t0),
      t1_(t1),
      enabled_(enabled && ::isatty(2) == 1),
      delay_(delay),
      start_(Clock::now()),
      last_(start_) {}

ProgressIndicator::~ProgressIndicator() {
    if (shown_) std::fprintf(stderr, "\r\033[K");
}

void ProgressIndicator::update(double t) {
    if (!enabled_) return;
    const Clock::time_point now = Clock::now();
    if (now - start_ < delay_) return;
    if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    shown_ = true;
    const double span = t1_ - t0_;
    const double percent = span > 0 ? 100 * (t - t0_) / span : 100;
    std::fprintf(stderr, "\r\033[K%s: t = %.4g of %.4g s (%.0f%%)", label_.c_str(), t, t1_,
                 percent);
    std::fflush(stderr);
}

namespace {
// the indicator whose thread is running (steps do not nest: the inner one takes over)
std::atomic<StepIndicator*> g_running{nullptr};
}  // namespace

StepIndicator::StepIndicator(std::string label, bool enabled, std::chrono::milliseconds delay)
    : label_(std::move(label)), delay_(delay) {
    // ALEMBERT_PROGRESS_DELAY_MS sets the delay for every step (a test shows the line at once)
    if (const char* ms = std::getenv("ALEMBERT_PROGRESS_DELAY_MS")) {
        char* end = nullptr;
        const long v = std::strtol(ms, &end, 10);
        if (end != ms && *end == '\0' && v >= 0) delay_ = std::chrono::milliseconds(v);
    }
    if (enabled && ::isatty(2) == 1) {
        ticker_ = std::thread([this] { run(); });
        g_running.store(this);
    }
}

void StepIndicator::clear_line() {
    StepIndicator* s = g_running.load();
    if (!s) return;
    std::lock_guard<std::mutex> lock(s->mutex_);
    if (s->shown_) std::fprintf(stderr, "\r\033[K");
    s->shown_ = false;
    std::fflush(stderr);
}

StepIndicator::~StepIndicator() {
    if (!ticker_.joinable()) return;
    StepIndicator* self = this;
    g_running.compare_exchange_strong(self, nullptr);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    stop_.notify_all();
    ticker_.join();
    if (shown_) std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

void StepIndicator::run() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    auto next = start + delay_;
    while (!stop_.wait_until(lock, next, [this] { return stopping_; })) {
        const auto seconds =
            std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start);
        std::fprintf(stderr, "\r\033[K%s ... %lld s", label_.c_str(), static_cast<long long>(seconds.count()));
        std::fflush(stderr);
        shown_ = true;
        next += std::chrono::seconds(1);
    }
}

}  // namespace alembert
