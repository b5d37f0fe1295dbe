// SPDX-License-Identifier: MIT
// The parser of the Alembert language: tokens of one statement to a Statement.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/ast.hpp"
#include "alembert/lang/lexer.hpp"

namespace alembert::lang {

/// The statement words of the language, in the order docs/language.md lists them (the
/// keywords of statements(), statements.hpp).
const std::vector<std::string>& statement_keywords();

/// The names of the functions expressions may call (`sin`, `dot`, `vel`, ...), sorted.
const std::vector<std::string>& function_names();

/// True if `name` is reserved (a statement word, a clause word or a function name), so it
/// cannot name a model object.
bool is_reserved(std::string_view name);

/// Parses the tokens of one statement (as Lexer::next_statement returns them, ending with an
/// end token). `source` is the script the tokens index into (for Statement::source).
/// Comment statements come back with keyword "#" and the comment in Statement::source.
/// @throws ScriptError naming what was expected and where.
Statement parse_statement(const std::vector<Token>& tokens, std::string_view source);

}  // namespace alembert::lang
