// SPDX-License-Identifier: MIT
// Helpers shared by the report's sources (private to src/report).
#pragma once

#include <string>
#include <vector>

namespace alembert {
struct ReportContent;
}

namespace alembert::report_detail {

/// Each row's equation typeset (LaTeX, readable form). Simplifying an equation for the reader
/// is the costly part of a report (seconds for a 42-row arm), so write_report typesets once
/// and hands the result to both the page and roadmap.tex.
std::vector<std::string> typeset_equations(const ReportContent& content);

/// render_report_json / render_report_latex / render_report_html with the rows' equations
/// already typeset (`equations`, one per row of `content`).
std::string render_json(const ReportContent& content, const std::vector<std::string>& equations);
std::string render_latex(const ReportContent& content, const std::vector<std::string>& equations);
std::string render_html(const ReportContent& content, const std::vector<std::string>& equations,
                        const std::string& katex_dir, const std::string& three_dir);

/// The viewer's script and style (src/report/viewer), compiled in.
extern const char* const kViewerScript;
extern const char* const kViewerStyle;

}  // namespace alembert::report_detail
