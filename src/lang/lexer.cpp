// SPDX-License-Identifier: MIT
// The lexer: UTF-8 validation, tokens, statement ends, bracket balance and the input limits.
#include "alembert/lang/lexer.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace alembert::lang {

namespace {

bool is_name_start(char32_t c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char32_t c) { return is_name_start(c) || (c >= '0' && c <= '9'); }
bool is_digit(char32_t c) { return c >= '0' && c <= '9'; }

std::string describe_char(char32_t c, std::string_view bytes) {
    if (c < 0x20 || c == 0x7F) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
        return std::string("control character ") + buf;
    }
    // invisible in an editor: named (only the start of a script may carry one)
    if (c == 0xFEFF) return "U+FEFF (a byte-order mark, allowed only at the start of the script)";
    return "'" + std::string(bytes) + "'";
}

}  // namespace

void validate_utf8(std::string_view s, int first_line) {
    int line = first_line, column = 1;
    std::size_t i = 0;
    while (i < s.size()) {
        auto c = static_cast<unsigned char>(s[i]);
        std::size_t len = 0;
        char32_t cp = 0;
        if (c < 0x80) len = 1, cp = c;
        else if (c >= 0xC2 && c <= 0xDF) len = 2, cp = c & 0x1F;
        else if (c >= 0xE0 && c <= 0xEF) len = 3, cp = c & 0x0F;
        else if (c >= 0xF0 && c <= 0xF4) len = 4, cp = c & 0x07;
        bool ok = len != 0 && i + len <= s.size();
        for (std::size_t k = 1; ok && k < len; ++k) {
            auto cc = static_cast<unsigned char>(s[i + k]);
            if ((cc & 0xC0) != 0x80) ok = false;
            cp = (cp << 6) | (cc & 0x3F);
        }
        if (ok && ((len == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) ||
                   (len == 4 && (cp < 0x10000 || cp > 0x10FFFF))))
            ok = false;
        if (!ok) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "0x%02X", c);
            throw ScriptError({line, column},
                              std::string("the script is not valid UTF-8 text (byte ") + buf + ")",
                              "save the file as UTF-8");
        }
        if (c == '\n') ++line, column = 1;
        else ++column;
        i += len;
    }
}

Lexer::Lexer(std::string_view source, int first_line) : src_(source), line_(first_line) {
    validate_utf8(source, first_line);
}

char32_t Lexer::peek_char(std::size_t at, std::size_t* length) const {
    if (at >= src_.size()) {
        if (length) *length = 0;
        return 0;
    }
    auto c = static_cast<unsigned char>(src_[at]);
    std::size_t len = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1F) : len == 3 ? (c & 0x0F) : (c & 0x07);
    for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (static_cast<unsigned char>(src_[at + k]) & 0x3F);
    if (length) *length = len;
    return cp;
}

// moves past one character of `bytes` bytes, counting lines and columns and the line length
void Lexer::advance(std::size_t bytes) {
    if (src_[pos_] == '\n') {
        ++line_, column_ = 1, line_chars_ = 0;
    } else {
        ++column_;
        if (src_[pos_] != '\r' && ++line_chars_ > Limits::max_line_length)
            throw ScriptError({line_, column_ - 1},
                              "line " + std::to_string(line_) + " is longer than " +
                                  std::to_string(Limits::max_line_length) + " characters",
                              "break the statement over several lines inside ( ) or [ ]");
    }
    pos_ += bytes;
}

void Lexer::skip_space_and_comments() {
    while (pos_ < src_.size()) {
        char c = src_[pos_];
        if (c == ' ' || c == '\t' || c == '\r' || (c == '\n' && !open_.empty())) {
            advance(1);
        } else if (c == '#') {
            while (pos_ < src_.size() && src_[pos_] != '\n') {
                std::size_t len = 1;
                peek_char(pos_, &len);
                advance(len);
            }
        } else if (c == '\\' && pos_ + 1 < src_.size() && src_[pos_ + 1] == '\n') {
            advance(1), advance(1);  // an explicit line continuation
        } else {
            return;
        }
    }
}

std::vector<Token> Lexer::next_statement() {
    std::vector<Token> out;
    // blank lines and ';' between statements
    while (pos_ < src_.size()) {
        char c = src_[pos_];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ';') advance(1);
        else break;
    }
    if (pos_ >= src_.size()) return out;
    if (src_[pos_] == '#') {  // a comment line is a statement of its own
        Token t;
        t.kind = TokenKind::comment, t.location = here(), t.begin = pos_;
        while (pos_ < src_.size() && src_[pos_] != '\n') {
            std::size_t len = 1;
            peek_char(pos_, &len);
            advance(len);
        }
        t.end = pos_;
        t.text = std::string(src_.substr(t.begin, t.end - t.begin));
        while (!t.text.empty() && t.text.back() == '\r') t.text.pop_back();
        out.push_back(t);
        out.push_back(Token{TokenKind::end, "", 0, here(), pos_, pos_});
        return out;
    }
    // the end of the statement is reported just after its last token, on the same line
    Location after_last{};
    std::size_t after_last_pos = pos_;
    for (;;) {
        skip_space_and_comments();
        if (pos_ >= src_.size()) {
            if (!open_.empty())
                throw ScriptError(open_.back().where,
                                  std::string("the statement never ends: '") + open_.back().bracket +
                                      "' is not closed before the end of the input",
                                  std::string("close it with '") +
                                      (open_.back().bracket == '(' ? ')' : ']') + "'");
            break;
        }
        char c = src_[pos_];
        if (open_.empty() && (c == '\n' || c == ';')) {
            advance(1);
            break;
        }
        out.push_back(lex_token());
        after_last = here(), after_last_pos = pos_;
        if (out.size() > Limits::max_statement_tokens)
            throw ScriptError(out.back().location, "the statement is too long (more than " +
                                                       std::to_string(Limits::max_statement_tokens) +
                                                       " tokens)",
                              "split it into several statements");
    }
    if (out.empty()) after_last = here(), after_last_pos = pos_;
    out.push_back(Token{TokenKind::end, "", 0, after_last, after_last_pos, after_last_pos});
    return out;
}

Token Lexer::lex_token() {
    Token t;
    t.location = here();
    t.begin = pos_;
    std::size_t len = 1;
    char32_t c = peek_char(pos_, &len);
    if (is_name_start(c)) {
        while (pos_ < src_.size() && is_name_char(peek_char(pos_))) advance(1);
        while (pos_ < src_.size() && src_[pos_] == '\'') advance(1);
        t.kind = TokenKind::name;
        t.text = std::string(src_.substr(t.begin, pos_ - t.begin));
        if (pos_ < src_.size() && src_[pos_] == '>') {
            advance(1);
            t.kind = TokenKind::vector_name;
            if (pos_ < src_.size() && src_[pos_] == '>') {
                advance(1);
                t.kind = TokenKind::dyadic_name;
            }
        }
    } else if (is_digit(c) || (c == '.' && is_digit(peek_char(pos_ + 1)))) {
        while (pos_ < src_.size() && is_digit(peek_char(pos_))) advance(1);
        if (pos_ < src_.size() && src_[pos_] == '.') {
            advance(1);
            while (pos_ < src_.size() && is_digit(peek_char(pos_))) advance(1);
        }
        if (pos_ < src_.size() && (src_[pos_] == 'e' || src_[pos_] == 'E')) {
            std::size_t k = pos_ + 1;
            if (k < src_.size() && (src_[k] == '+' || src_[k] == '-')) ++k;
            if (k < src_.size() && is_digit(peek_char(k))) {
                while (pos_ < k) advance(1);
                while (pos_ < src_.size() && is_digit(peek_char(pos_))) advance(1);
            }
        }
        t.kind = TokenKind::number;
        t.text = std::string(src_.substr(t.begin, pos_ - t.begin));
        if (t.text.size() > Limits::max_number_length)
            throw ScriptError(t.location, "the number '" + t.text.substr(0, 20) + "...' is too long",
                              "write it with an exponent, e.g. 1.5e6");
        t.number = std::strtod(t.text.c_str(), nullptr);
        if (!std::isfinite(t.number) || std::fabs(t.number) > Limits::max_number)
            throw ScriptError(t.location, "the number " + t.text + " is too large (the limit is 1e30)",
                              "choose units in which the value is smaller");
        if (t.text == "0" && pos_ < src_.size() && src_[pos_] == '>') {
            advance(1);
            t.kind = TokenKind::zero_vector;
            t.text = "0";
        }
    } else {
        static constexpr std::string_view puncts = "()[],=+-*/^:;";
        if (c < 0x80 && puncts.find(static_cast<char>(c)) != std::string_view::npos) {
            char p = static_cast<char>(c);
            if (p == '(' || p == '[') {
                if (static_cast<int>(open_.size()) >= Limits::max_nesting)
                    throw ScriptError(t.location, "brackets are nested more than " +
                                                      std::to_string(Limits::max_nesting) + " deep",
                                      "name parts of the expression with assignments");
                open_.push_back({p, t.location});
            } else if (p == ')' || p == ']') {
                char want = p == ')' ? '(' : '[';
                if (open_.empty())
                    throw ScriptError(t.location, std::string("unbalanced '") + p + "': there is no '" +
                                                      want + "' to close",
                                      "remove it or add the opening bracket");
                if (open_.back().bracket != want)
                    throw ScriptError(t.location,
                                      std::string("'") + p + "' does not match the '" +
                                          open_.back().bracket + "' opened at " +
                                          std::to_string(open_.back().where.line) + ":" +
                                          std::to_string(open_.back().where.column),
                                      std::string("close it with '") +
                                          (open_.back().bracket == '(' ? ')' : ']') + "' first");
                open_.pop_back();
            }
            advance(1);
            t.kind = TokenKind::punct;
            t.text = std::string(1, p);
        } else if (c == '"') {
            advance(1);
            std::size_t start = pos_;
            while (pos_ < src_.size() && src_[pos_] != '"' && src_[pos_] != '\n') {
                std::size_t n = 1;
                peek_char(pos_, &n);
                advance(n);
            }
            if (pos_ >= src_.size() || src_[pos_] != '"')
                throw ScriptError(t.location, "the text in quotes is not closed on its line",
                                  "close it with '\"', e.g. from \"motion.csv\"");
            t.kind = TokenKind::string;
            t.text = std::string(src_.substr(start, pos_ - start));
            advance(1);
        } else if (c == '>') {
            throw ScriptError(t.location, "'>' must follow a name directly, as in Ax> or r>",
                              "vectors are named with a trailing '>' and no space");
        } else if (c == '\'') {
            throw ScriptError(t.location, "a prime must follow a name directly, as in qA'",
                              "write the derivative of qA as qA' or qA''");
        } else {
            std::string text = describe_char(c, src_.substr(pos_, len));
            throw ScriptError(t.location, "unexpected character " + text,
                              c >= 0x80 ? "names use ASCII letters, digits and '_'"
                                        : "this character has no meaning in Alembert scripts");
        }
    }
    t.end = pos_;
    return t;
}

bool statement_is_open(std::string_view text) {
    // a line ending in a backslash continues
    std::string_view t = text;
    while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.remove_suffix(1);
    if (!t.empty() && t.back() == '\\' && text.size() > t.size()) return true;
    try {
        Lexer lx(text);
        try {
            while (!lx.next_statement().empty()) {
            }
        } catch (const ScriptError&) {
            return lx.at_end() && lx.open_brackets() > 0;  // only the end of input came too soon
        }
    } catch (const ScriptError&) {
    }
    return false;
}

}  // namespace alembert::lang
