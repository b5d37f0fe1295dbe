// SPDX-License-Identifier: MIT
// The table of the language's statements: each one's keyword, grammar, meaning and help.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/ast.hpp"
#include "alembert/lang/interpreter.hpp"

namespace alembert::lang {

class StatementParser;

/// One form of a statement, as a row of docs/language.md: its grammar (Markdown: words of the
/// language in backticks, parts by role in italics, options in brackets), an example, and the
/// library call it makes (Markdown).
struct StatementForm {
    std::string_view grammar{};
    std::string_view example{};
    std::string_view call{};
};

/// A statement of the language: one unit with its keyword, its grammar by roles (`parse`), its
/// meaning (`run`, one library call) and its help. A family file (statements_kinematics.cpp,
/// interpreter_numbers.cpp, ...) lists the specs of its statements; statements() lists them
/// all, and the parser, the interpreter, `help`, docs/language.md's tables and the fuzzer's
/// dictionary are driven from that list.
struct StatementSpec {
    std::string_view keyword{};
    std::string_view family{};  ///< the section of docs/language.md that lists it
    std::string_view help{};    ///< one line: what the statement does
    std::vector<StatementForm> forms{};
    /// Words that mark its clauses (`from`, `about`, `by`); they are reserved, so they cannot
    /// name things, and a unit after a value stops at them.
    std::vector<std::string_view> clauses{};
    /// Parses the statement's parts after the keyword into `s` by role; the parser checks the
    /// end of the statement afterwards. @throws ScriptError naming what was expected.
    void (*parse)(StatementParser& p, Statement& s) = nullptr;
    /// Carries the statement out. @throws ScriptError at the user's mistake.
    void (*run)(Interpreter::Impl& m, const Statement& s) = nullptr;
    /// False for the one statement that may come before the model exists (`newtonian`).
    bool needs_model = true;
};

/// Every statement, in the order docs/language.md lists them.
const std::vector<StatementSpec>& statements();

/// The statement that `keyword` starts, or nullptr.
const StatementSpec* find_statement(std::string_view keyword);

/// The families of statements (sections of docs/language.md), in order.
std::vector<std::string_view> statement_families();

/// The reserved clause words of all statements, sorted, without repeats.
const std::vector<std::string>& statement_clause_words();

/// `help` of the interactive session: with an empty `keyword`, every statement with its one
/// line; otherwise that statement's forms with an example each. Text for a terminal, ending in
/// a newline; a word that is not a statement gets a line saying so.
std::string statement_help(std::string_view keyword = {});

/// The forms of a statement as plain text (`rotate B from A about [-]axis by angle`), one a
/// line, each after `indent` and ending in a newline; empty if `keyword` is not a statement.
std::string statement_forms(std::string_view keyword, std::string_view indent = "  ");

/// The Markdown table of a family's statements, as docs/language.md shows it (from the line
/// `| statement | example | library call |` to the last row, each line ending in a newline).
std::string statement_table_markdown(std::string_view family);

/// The libFuzzer dictionary of the language (keywords, clause words, punctuation), one entry
/// a line (tests/fuzz/alembert.dict).
std::string fuzz_dictionary();

}  // namespace alembert::lang
