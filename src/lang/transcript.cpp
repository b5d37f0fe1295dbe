// SPDX-License-Identifier: MIT
// The transcript printer.
#include "alembert/lang/transcript.hpp"

#include <cmath>
#include <cstdio>

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
    if (muted_) return;
    *out_ << text;
    if (text.empty() || text.back() != '\n') *out_ << "\n";
}

std::string format_number(double x) {
    if (std::fabs(x) < 5e-13) x = 0;  // round-off around zero prints as 0
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

}  // namespace alembert::lang
