// SPDX-License-Identifier: MIT
// Formatting diagnostics with the offending line and a caret under the spot.
#include "alembert/lang/diagnostic.hpp"

#include <string>

namespace alembert::lang {

namespace {

const char* word(Severity s) {
    switch (s) {
        case Severity::error: return "error";
        case Severity::warning: return "warning";
        case Severity::note: return "note";
    }
    return "error";
}

// the text of 1-based line `n` of `source`, without its newline
std::string_view line_of(std::string_view source, int n) {
    std::size_t begin = 0;
    for (int i = 1; i < n; ++i) {
        std::size_t nl = source.find('\n', begin);
        if (nl == std::string_view::npos) return {};
        begin = nl + 1;
    }
    std::size_t end = source.find('\n', begin);
    std::string_view line = source.substr(begin, end == std::string_view::npos ? end : end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d, std::string_view source, int first_line) {
    std::string out = (d.file.empty() ? std::string("<input>") : d.file) + ":" +
                      std::to_string(d.location.line) + ":" + std::to_string(d.location.column) +
                      ": " + word(d.severity) + ": " + d.message + "\n";
    std::string_view line = line_of(source, d.location.line - first_line + 1);
    constexpr std::size_t shown = 200;  // long lines are cut around the caret
    if (!line.empty()) {
        // walk the line by characters to place the caret under column `column`
        std::string prefix, text, caret;
        std::size_t i = 0;
        int column = 1;
        std::size_t first = d.location.column > 100 ? static_cast<std::size_t>(d.location.column - 60) : 1;
        while (i < line.size()) {
            std::size_t len = 1;
            auto c = static_cast<unsigned char>(line[i]);
            if (c >= 0xF0) len = 4;
            else if (c >= 0xE0) len = 3;
            else if (c >= 0xC0) len = 2;
            if (i + len > line.size()) len = line.size() - i;
            if (static_cast<std::size_t>(column) >= first && text.size() < shown) {
                text.append(line.substr(i, len));
                if (column < d.location.column) caret += (c == '\t' ? '\t' : ' ');
            }
            i += len;
            ++column;
        }
        std::string number = std::to_string(d.location.line);
        std::string pad(number.size() < 5 ? 5 - number.size() : 0, ' ');
        std::string lead = first > 1 ? "..." : "";
        out += pad + number + " | " + lead + text + (i > text.size() + first - 1 && text.size() >= shown ? "..." : "") + "\n";
        out += std::string(pad.size() + number.size(), ' ') + " | " + std::string(lead.size(), ' ') +
               caret + "^\n";
    }
    if (!d.hint.empty()) out += "hint: " + d.hint + "\n";
    return out;
}

}  // namespace alembert::lang
