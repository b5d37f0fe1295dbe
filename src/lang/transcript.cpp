// SPDX-License-Identifier: MIT
// The transcript printer.
#include "alembert/lang/transcript.hpp"

#include <cmath>
#include <cstdio>

#include "alembert/error.hpp"
#include "alembert/sim/progress.hpp"

namespace alembert::lang {

void Transcript::statement(const std::string& source) {
    if (!echo_ || muted_) return;
    std::string out = "> ";
    for (char c : source) {
        out += c;
        if (c == '\n') out += "  ";
    }
    *out_ << out << "\n";
}

void Transcript::comment(const std::string& text) {
    if (echo_ && !muted_) *out_ << text << "\n";
}

void Transcript::result(const std::string& text) {
    if (keeping_) kept_ += text.empty() || text.back() != '\n' ? text + "\n" : text;
    if (muted_) return;
    StepIndicator::clear_line();  // a step's progress line on the terminal, if one shows
    *out_ << text;
    if (text.empty() || text.back() != '\n') *out_ << "\n";
}

void Transcript::set_digits(int digits) {
    if (digits < 1 || digits > 17)
        throw ArgumentError("Transcript::set_digits(): " + std::to_string(digits) +
                            " significant digits; give a whole number from 1 to 17 (17 prints "
                            "every double exactly)");
    digits_ = digits;
}

std::string Transcript::number(double x) const { return format_number(x, digits_); }

std::string format_number(double x, int digits) {
    if (std::fabs(x) < 5e-13) x = 0;  // round-off around zero prints as 0
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

}  // namespace alembert::lang
