// SPDX-License-Identifier: MIT
// Progress indicator on standard error.
#include "alembert/sim/progress.hpp"

#include <unistd.h>

#include <cstdio>

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

}  // namespace alembert
