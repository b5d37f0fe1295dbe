// SPDX-License-Identifier: MIT
// The lexer of the Alembert language: UTF-8 text to tokens, one statement at a time.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/diagnostic.hpp"

namespace alembert::lang {

/// Limits that keep hostile input harmless (docs/language.md, "Lexical rules").
struct Limits {
    static constexpr std::size_t max_line_length = 10000;   ///< characters per line
    static constexpr int max_nesting = 64;                  ///< brackets and operators
    static constexpr double max_number = 1e30;              ///< magnitude of a literal
    static constexpr std::size_t max_number_length = 64;    ///< characters of a literal
    static constexpr int max_power = 64;                    ///< |n| of an integer power
    static constexpr int max_derivative = 4;                ///< primes of a declaration
    static constexpr std::size_t max_statement_tokens = 100000;
};

/// What a token is.
enum class TokenKind {
    name,         ///< qA, qA'', L_A
    vector_name,  ///< Ax>, r>, w_A_N> (text without the '>')
    dyadic_name,  ///< D>>, I_B>> (text without the '>>')
    zero_vector,  ///< 0>
    number,       ///< 9.81, 1e-3
    string,       ///< "motion.csv" (text without the quotes; one line, no escapes)
    punct,        ///< ( ) [ ] , = + - * / ^ :
    comment,      ///< a line that holds only a comment (text from '#')
    end,          ///< end of the statement
};

/// One token with where it starts and where its text lies in the source.
struct Token {
    TokenKind kind = TokenKind::end;
    std::string text{};
    double number = 0;
    Location location{};
    std::size_t begin = 0;  ///< byte offset of the first character
    std::size_t end = 0;    ///< byte offset past the last character
    bool is(std::string_view punct) const { return kind == TokenKind::punct && text == punct; }
};

/// Checks that `text` is valid UTF-8.
/// @throws ScriptError at the first invalid byte.
void validate_utf8(std::string_view text, int first_line = 1);

/// Splits a script into statements of tokens. A statement ends at the end of a line or at ';'
/// unless a '(' or '[' is still open; a line holding only a comment is a statement of its own
/// (one comment token), so transcripts can echo it.
class Lexer {
public:
    /// Lexes `source`, whose first line is numbered `first_line`. The source must outlive the
    /// lexer. The whole text is checked for valid UTF-8 first.
    /// @throws ScriptError for invalid UTF-8.
    explicit Lexer(std::string_view source, int first_line = 1);

    /// The tokens of the next statement, ending with a TokenKind::end token; empty at the end
    /// of the source.
    /// @throws ScriptError for a character that starts no token, a line that is too long, a
    ///         number out of range, unbalanced or too deeply nested brackets, or a statement
    ///         still open at the end of the source.
    std::vector<Token> next_statement();

    /// How many '(' and '[' are open at the current position.
    std::size_t open_brackets() const { return open_.size(); }
    /// True when the whole source has been read.
    bool at_end() const { return pos_ >= src_.size(); }

private:
    Token lex_token();
    void skip_space_and_comments();
    char32_t peek_char(std::size_t at, std::size_t* length = nullptr) const;
    void advance(std::size_t bytes);
    Location here() const { return {line_, column_}; }

    std::string_view src_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    std::size_t line_chars_ = 0;
    struct Open {
        char bracket;
        Location where;
    };
    std::vector<Open> open_;
};

/// True when `text` ends inside an open '(' or '[' (an interactive session then reads another
/// line before running it). Lexical errors count as complete (running reports them).
bool statement_is_open(std::string_view text);

}  // namespace alembert::lang
