// SPDX-License-Identifier: MIT
// Diagnostics of the Alembert language: where in the script, what is wrong, how to fix it.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace alembert::lang {

/// A place in a script: 1-based line and column (columns count characters, not bytes).
struct Location {
    int line = 1;
    int column = 1;
};

/// How bad a diagnostic is.
enum class Severity { error, warning, note };

/// A message about a script: `file:line:col: error: message`, the offending line with a caret
/// under `location`, and a hint on how to fix it.
struct Diagnostic {
    Severity severity = Severity::error;
    std::string file{};
    Location location{};
    std::string message{};
    std::string hint{};
};

/// Formats a diagnostic as the tool prints it:
/// ```
/// model.alb:7:23: error: 'Q' is not declared
///     7 | rotate B from A about Q by qB
///       |                       ^
/// hint: declare it first
/// ```
/// `source` is the script text (the line is taken from it), whose first line is numbered
/// `first_line` (an interactive session runs its input in pieces); an empty source prints no
/// line.
std::string format_diagnostic(const Diagnostic& d, std::string_view source, int first_line = 1);

/// Thrown by the lexer, parser and interpreter for a mistake in the script; the interpreter
/// catches it and reports the diagnostic (the language never throws at the user).
class ScriptError : public std::runtime_error {
public:
    ScriptError(Location where, const std::string& message, std::string hint = "")
        : std::runtime_error(message), where_(where), hint_(std::move(hint)) {}
    Location where() const { return where_; }
    const std::string& hint() const { return hint_; }

private:
    Location where_;
    std::string hint_;
};

}  // namespace alembert::lang
