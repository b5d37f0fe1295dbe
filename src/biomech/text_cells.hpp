// SPDX-License-Identifier: MIT
// Private helpers of the lab-file readers: splitting lines into cells and reading numbers.
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace alembert::detail {

inline std::string trim_cell(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/// Cells of a tab-separated line, empty cells kept (a missing marker is an empty cell).
inline std::vector<std::string> split_tabs(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    std::string text = line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    while (true) {
        std::size_t tab = text.find('\t', start);
        cells.push_back(trim_cell(text.substr(start, tab == std::string::npos ? tab : tab - start)));
        if (tab == std::string::npos) break;
        start = tab + 1;
    }
    return cells;
}

/// Cells of a line separated by runs of tabs or spaces (no empty cells).
inline std::vector<std::string> split_blanks(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        if (j > i) cells.push_back(line.substr(i, j - i));
        i = j;
    }
    return cells;
}

/// The first byte of `line` that no text file holds (a NUL or a control character other than
/// tab, carriage return, form feed), as "0x03", or "" if there is none: a spreadsheet (.xlsx is
/// a zip archive) or another binary file given where a lab's text file belongs.
inline std::string binary_byte(const std::string& line) {
    for (unsigned char c : line)
        if (c == 0x7f || (c < 0x20 && c != '\t' && c != '\r' && c != '\f')) {
            const char* hex = "0123456789abcdef";
            return std::string("0x") + hex[c >> 4] + hex[c & 15];
        }
    return "";
}

/// The number a whole cell holds, "nan"/"NaN" as NaN; false if the cell is not a number.
inline bool parse_number(const std::string& cell, double& value) {
    if (cell.empty()) return false;
    char* end = nullptr;
    value = std::strtod(cell.c_str(), &end);
    return end == cell.c_str() + cell.size();
}

}  // namespace alembert::detail
