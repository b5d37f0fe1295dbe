// SPDX-License-Identifier: MIT
// Helpers shared by the report's sources (private to src/report).
#pragma once

#include <string>

namespace alembert::report_detail {

/// The viewer's script and style (src/report/viewer), compiled in.
extern const char* const kViewerScript;
extern const char* const kViewerStyle;

}  // namespace alembert::report_detail
