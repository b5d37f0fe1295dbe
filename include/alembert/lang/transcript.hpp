// SPDX-License-Identifier: MIT
// The transcript printer: each statement echoed, then what it produced.
#pragma once
#include <ostream>
#include <string>

namespace alembert::lang {

/// Writes a session's transcript, like a calculator's: each statement echoed after "> "
/// (continuation lines indented to match), followed by the lines it produced. Quiet
/// transcripts print only the produced lines.
class Transcript {
public:
    /// A transcript on `out`; `echo` prints statements and comment lines as well as results.
    Transcript(std::ostream& out, bool echo) : out_(&out), echo_(echo) {}

    void set_echo(bool echo) { echo_ = echo; }
    /// A muted transcript prints nothing (a script run only to build its model).
    void set_muted(bool muted) { muted_ = muted; }
    bool echo() const { return echo_; }

    /// Echoes a statement's source text (nothing when not echoing).
    void statement(const std::string& source);
    /// Echoes a comment line (nothing when not echoing).
    void comment(const std::string& text);
    /// Prints what a statement produced; `text` may hold several lines.
    void result(const std::string& text);
    /// Starts keeping what result() prints (muted or not), until take_kept().
    void keep_results() {
        keeping_ = true;
        kept_.clear();
    }
    /// What result() printed since keep_results(); stops keeping.
    std::string take_kept() {
        keeping_ = false;
        return std::move(kept_);
    }
    /// Flushes the stream.
    void flush() { out_->flush(); }

    /// Significant digits of the numbers the transcript prints (the `digits` statement,
    /// `alembert run --digits N`): 1 to 17, 6 by default.
    /// @throws alembert::ArgumentError if `digits` is outside 1..17.
    void set_digits(int digits);
    int digits() const { return digits_; }
    /// `x` as this transcript prints numbers: format_number(x, digits()).
    std::string number(double x) const;

private:
    std::ostream* out_;
    bool echo_;
    bool muted_ = false;
    bool keeping_ = false;
    std::string kept_{};
    int digits_ = kDefaultDigits;

public:
    static constexpr int kDefaultDigits = 6;
};

/// A number as transcripts print it: `digits` significant digits (printf's %.*g: no trailing
/// zeros), round-off below 5e-13 in size and "-0" as "0". With 17 digits every double prints
/// so that it reads back exactly.
std::string format_number(double x, int digits = Transcript::kDefaultDigits);

}  // namespace alembert::lang
