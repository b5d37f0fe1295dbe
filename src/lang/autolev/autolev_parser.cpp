// SPDX-License-Identifier: MIT
// The reader of Autolev files: lines to tokens, tokens to statements and expressions.
#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "autolev_syntax.hpp"

namespace alembert::lang::autolev {

std::string upper(std::string_view name) {
    std::string s(name);
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

namespace {

constexpr int kMaxDepth = 64;           // nested brackets and operators
constexpr std::size_t kMaxIndexed = 1000;  // Q{n}: at most this many names

struct Problem {
    Location where;
    std::string message;
    std::string hint;
};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Splits the file into statements of tokens. A statement ends at a line end outside brackets
// or at ';'; '%' starts a comment.
class Lexer {
public:
    explicit Lexer(std::string_view s) : s_(s) {}

    // the tokens of the next statement, ending with an end token; false at the end of file
    bool next_statement(std::vector<Token>& out, std::vector<Problem>& problems) {
        out.clear();
        int depth = 0;
        while (i_ < s_.size()) {
            char c = s_[i_];
            if (c == '\n') {
                advance();
                if (depth == 0 && !out.empty()) break;
                continue;
            }
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') { advance(); continue; }
            if (c == '%') {
                while (i_ < s_.size() && s_[i_] != '\n') advance();
                continue;
            }
            if (c == '&' && continues_line()) {
                // `&` at the end of a line (before an optional comment) joins the next line
                while (i_ < s_.size() && s_[i_] != '\n') advance();
                if (i_ < s_.size()) advance();
                continue;
            }
            if (c == ';' && depth == 0) {
                advance();
                if (!out.empty()) break;
                continue;
            }
            Token t;
            t.where = here();
            if (is_name_start(c)) {
                std::size_t b = i_;
                while (i_ < s_.size() && is_name_char(s_[i_])) advance();
                t.kind = Token::Kind::name;
                t.text = std::string(s_.substr(b, i_ - b));
                while (i_ < s_.size() && s_[i_] == '\'') { advance(); ++t.primes; }
                if (i_ < s_.size() && s_[i_] == '>') { advance(); t.vector = true; }
                if (t.vector && i_ < s_.size() && s_[i_] == '>') { advance(); t.dyadic = true; }
            } else if (is_digit(c) || (c == '.' && i_ + 1 < s_.size() && is_digit(s_[i_ + 1]))) {
                std::size_t b = i_;
                while (i_ < s_.size() && (is_digit(s_[i_]) || s_[i_] == '.')) advance();
                if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
                    std::size_t save = i_;
                    int save_col = col_;
                    advance();
                    if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) advance();
                    if (i_ < s_.size() && is_digit(s_[i_])) {
                        while (i_ < s_.size() && is_digit(s_[i_])) advance();
                    } else {
                        i_ = save;
                        col_ = save_col;
                    }
                }
                t.kind = Token::Kind::number;
                t.text = std::string(s_.substr(b, i_ - b));
                if (i_ < s_.size() && s_[i_] == '>') {
                    if (t.text == "0") {
                        advance();
                        t.kind = Token::Kind::name;
                        t.vector = true;
                    }
                    // 0>> the zero dyadic, 1>> the unit dyadic
                    if ((t.text == "0" || t.text == "1") && i_ + (t.vector ? 0 : 1) < s_.size() &&
                        s_[i_ + (t.vector ? 0 : 1)] == '>') {
                        if (!t.vector) advance();
                        advance();
                        t.kind = Token::Kind::name;
                        t.vector = t.dyadic = true;
                    }
                }
            } else if (std::string_view("+-*/^()[]{},=':;").find(c) != std::string_view::npos) {
                t.kind = Token::Kind::symbol;
                t.text = std::string(1, c);
                advance();
                if (c == '(' || c == '[' || c == '{') ++depth;
                if ((c == ')' || c == ']' || c == '}') && depth > 0) --depth;
            } else if (c == '>' || c == '<' || c == '!' || c == '&' || c == '|' || c == '"' ||
                       c == '#' || c == '@' || c == '$' || c == '?' || c == '\\' || c == '.' ||
                       c == '~' || c == '_' || c == '`') {
                t.kind = Token::Kind::symbol;
                t.text = std::string(1, c);
                advance();
            } else {
                // a byte the dialect does not use (often a non-ASCII character)
                problems.push_back({here(), "unexpected character in an Autolev statement",
                                    "Autolev names are letters, digits and '_'; remove the character"});
                advance();
                t.kind = Token::Kind::symbol;
                t.text = "?";
            }
            out.push_back(std::move(t));
            after_last_ = here();
        }
        Token e;
        e.kind = Token::Kind::end;
        e.where = out.empty() ? here() : after_last_;  // just after the statement's last token
        out.push_back(e);
        return out.size() > 1;
    }

    // the text of the file from where token `t` starts to the end of its line
    std::string_view rest_of_line(const Token& t) const {
        std::size_t b = offset_of(t.where);
        std::size_t e = s_.find('\n', b);
        if (e == std::string_view::npos) e = s_.size();
        std::string_view r = s_.substr(b, e - b);
        std::size_t pct = r.find('%');
        if (pct != std::string_view::npos) r = r.substr(0, pct);
        while (!r.empty() && (r.back() == ' ' || r.back() == '\t' || r.back() == '\r' || r.back() == ';'))
            r.remove_suffix(1);
        return r;
    }

private:
    // true if only blanks or a comment follow the '&' at i_ on its line
    bool continues_line() const {
        for (std::size_t k = i_ + 1; k < s_.size(); ++k) {
            char c = s_[k];
            if (c == '\n' || c == '%') return true;
            if (c != ' ' && c != '\t' && c != '\r') return false;
        }
        return true;
    }
    Location here() const { return {line_, col_}; }
    void advance() {
        char c = s_[i_++];
        if (c == '\n') {
            ++line_;
            col_ = 1;
            line_start_.push_back(i_);
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            ++col_;
        }
    }
    std::size_t offset_of(Location w) const {
        std::size_t b = line_start_[static_cast<std::size_t>(w.line - 1)];
        int col = 1;
        while (b < s_.size() && col < w.column) {
            ++b;
            if (b < s_.size() && (static_cast<unsigned char>(s_[b]) & 0xC0) != 0x80) ++col;
        }
        return b;
    }

    std::string_view s_;
    std::size_t i_ = 0;
    int line_ = 1, col_ = 1;
    Location after_last_{};
    std::vector<std::size_t> line_start_{0};
};

// Recursive descent over one statement's tokens.
class Parser {
public:
    explicit Parser(const std::vector<Token>& t) : t_(t) {}

    const Token& peek(std::size_t k = 0) const { return t_[std::min(p_ + k, t_.size() - 1)]; }
    bool at_end() const { return peek().kind == Token::Kind::end; }
    bool is_symbol(const char* s, std::size_t k = 0) const {
        return peek(k).kind == Token::Kind::symbol && peek(k).text == s;
    }
    const Token& take() { return t_[p_ < t_.size() - 1 ? p_++ : p_]; }

    [[noreturn]] void fail(const Token& at, const std::string& message, const std::string& hint = "") {
        throw ScriptError(at.where, message, hint);
    }
    std::string describe(const Token& t) const {
        if (t.kind == Token::Kind::end) return "the end of the statement";
        return "'" + t.text + std::string(static_cast<std::size_t>(t.primes), '\'') +
               (t.dyadic ? ">>" : t.vector ? ">" : "") + "'";
    }
    void expect(const char* s) {
        if (!is_symbol(s))
            fail(peek(), std::string("expected '") + s + "' but found " + describe(peek()),
                 "close each bracket that is opened, and separate arguments with ','");
        take();
    }

    Expr expression() { return sum(); }

    Expr sum() {
        Expr left = product();
        while (is_symbol("+") || is_symbol("-")) {
            const Token& op = take();
            Expr right = product();
            left = binary(op, std::move(left), std::move(right));
        }
        return left;
    }
    Expr product() {
        Expr left = signed_factor();
        while (is_symbol("*") || is_symbol("/")) {
            const Token& op = take();
            Expr right = signed_factor();
            left = binary(op, std::move(left), std::move(right));
        }
        return left;
    }
    Expr signed_factor() {
        if (is_symbol("-") || is_symbol("+")) {
            const Token& op = take();
            Guard g(*this, op);
            Expr e;
            e.kind = Expr::Kind::unary;
            e.text = op.text;
            e.where = op.where;
            e.args.push_back(signed_factor());
            return e;
        }
        return power();
    }
    Expr power() {
        Expr base = primary();
        if (is_symbol("^")) {
            const Token& op = take();
            Guard g(*this, op);
            Expr exponent = signed_factor();  // right-associative
            return binary(op, std::move(base), std::move(exponent));
        }
        return base;
    }
    Expr primary() {
        const Token& t = peek();
        Guard g(*this, t);
        Expr e;
        e.where = t.where;
        if (t.kind == Token::Kind::number) {
            take();
            e.kind = Expr::Kind::number;
            e.text = t.text;
            return e;
        }
        if (t.kind == Token::Kind::name) {
            take();
            e.text = t.text;
            e.primes = t.primes;
            e.vector = t.vector;
            e.dyadic = t.dyadic;
            if (t.vector) {
                e.kind = Expr::Kind::name;
                if (t.text == "0") e.text = "0";
                return e;
            }
            if (t.primes == 0 && is_symbol("(")) {
                take();
                e.kind = Expr::Kind::call;
                // an argument may be a range or a substitution, TAYLOR(e, 0:3, Q = 0) and
                // EVALUATE(e, Q = 1): a binary ':' or '=' node, which only the functions that
                // take them accept
                if (!is_symbol(")")) {
                    for (;;) {
                        Expr arg = expression();
                        if (is_symbol(":") || is_symbol("=")) {
                            const Token& op = take();
                            arg = binary(op, std::move(arg), expression());
                        }
                        e.args.push_back(std::move(arg));
                        if (!is_symbol(",")) break;
                        take();
                    }
                }
                expect(")");
                return e;
            }
            if (t.primes == 0 && is_symbol("[")) {
                take();
                e.kind = Expr::Kind::index;
                e.args.push_back(expression());
                while (is_symbol(",")) {
                    take();
                    e.args.push_back(expression());
                }
                expect("]");
                return e;
            }
            e.kind = Expr::Kind::name;
            return e;
        }
        if (is_symbol("(")) {
            take();
            Expr inner = expression();
            expect(")");
            return inner;
        }
        if (is_symbol("[")) {
            take();
            e.kind = Expr::Kind::matrix;
            Expr row;
            row.kind = Expr::Kind::row;
            row.where = peek().where;
            for (;;) {
                row.args.push_back(expression());
                if (is_symbol(",")) {
                    take();
                } else if (is_symbol(";")) {
                    take();
                    e.args.push_back(std::move(row));
                    row = Expr{};
                    row.kind = Expr::Kind::row;
                    row.where = peek().where;
                } else {
                    break;
                }
            }
            e.args.push_back(std::move(row));
            expect("]");
            return e;
        }
        fail(t, "expected a value but found " + describe(t),
             "an Autolev expression is numbers, names, vectors such as A1>, and calls such as SIN(Q1)");
    }

    Expr binary(const Token& op, Expr a, Expr b) {
        Expr e;
        e.kind = Expr::Kind::binary;
        e.text = op.text;
        e.where = op.where;
        e.args.push_back(std::move(a));
        e.args.push_back(std::move(b));
        return e;
    }

    // a depth guard against hostile nesting
    struct Guard {
        Guard(Parser& p, const Token& t) : p_(p) {
            if (++p_.depth_ > kMaxDepth)
                p_.fail(t, "the expression is nested more than 64 levels deep", "split it into named parts");
        }
        ~Guard() { --p_.depth_; }
        Parser& p_;
    };

    // the words after a value up to ',' or the end: a unit such as DEG or M/S
    std::string unit_words() {
        std::string u;
        while (!at_end() && !is_symbol(",")) {
            const Token& t = take();
            u += t.text;
            if (t.primes) u += std::string(static_cast<std::size_t>(t.primes), '\'');
        }
        return u;
    }

    std::size_t position() const { return p_; }

private:
    const std::vector<Token>& t_;
    std::size_t p_ = 0;
    int depth_ = 0;
};

bool is_declaration_word(const std::string& w) {
    static const char* const words[] = {
        "NEWTONIAN", "FRAMES", "FRAME", "BODIES", "BODY", "PARTICLES", "PARTICLE", "POINTS", "POINT",
        "CONSTANTS", "CONSTANT", "VARIABLES", "VARIABLE", "MOTIONVARIABLES", "MOTIONVARIABLE",
        "SPECIFIED", "SPECIFIEDS", "IMAGINARY"};
    for (const char* x : words)
        if (w == x) return true;
    return false;
}

bool is_list_word(const std::string& w) {
    return w == "MASS" || w == "INERTIA" || w == "INPUT" || w == "INPUTS" || w == "OUTPUT" || w == "OUTPUTS";
}

// Declarators: NAME[{n} | {a:b}][primes][+|-|~][= value], ...
void parse_declarators(Parser& p, Statement& st) {
    for (;;) {
        const Token& t = p.peek();
        if (t.kind != Token::Kind::name || t.vector)
            p.fail(t, "expected a name to declare but found " + p.describe(t),
                   "a declaration lists names: CONSTANTS L, M, G or VARIABLES Q{2}'");
        p.take();
        Declarator d;
        d.name = t.text;
        d.primes = t.primes;
        d.where = t.where;
        if (p.is_symbol("{")) {
            p.take();
            // one range: n (1..n) or a:b
            auto range = [&](int& first, int& last) -> const Token& {
                const Token& a = p.peek();
                if (a.kind != Token::Kind::number || a.text.find_first_not_of("0123456789") != std::string::npos)
                    p.fail(a, "expected a whole number of names in '" + d.name + "{...}' but found " + p.describe(a),
                           "write Q{3} for Q1, Q2, Q3, Q{2:4} for Q2, Q3, Q4 or C{2,3} for C11, ..., C23");
                p.take();
                if (a.text.size() > 6) p.fail(a, "too many indexed names in '" + d.name + "{...}'", "declare at most 1000");
                first = 1;
                last = std::stoi(a.text);
                if (p.is_symbol(":")) {
                    p.take();
                    const Token& b = p.peek();
                    if (b.kind != Token::Kind::number || b.text.find_first_not_of("0123456789") != std::string::npos ||
                        b.text.size() > 6)
                        p.fail(b, "expected the last index of '" + d.name + "{" + a.text + ":...}' but found " + p.describe(b));
                    p.take();
                    first = last;
                    last = std::stoi(b.text);
                }
                return a;
            };
            int first = 1, last = 0;
            const Token& a = range(first, last);
            std::size_t count = last < first ? 0 : static_cast<std::size_t>(last - first + 1);
            if (p.is_symbol(",")) {  // C{2,3}: C11, C12, C13, C21, C22, C23
                p.take();
                range(d.first2, d.last2);
                count *= d.last2 < d.first2 ? 0 : static_cast<std::size_t>(d.last2 - d.first2 + 1);
                // C{2,2,2}: read (the translator leaves it out, naming the names it would declare)
                while (p.is_symbol(",")) {
                    p.take();
                    int f = 1, l = 0;
                    range(f, l);
                    d.more.emplace_back(f, l);
                    count *= l < f ? 0 : static_cast<std::size_t>(l - f + 1);
                    count = std::min(count, kMaxIndexed + 1);  // no overflow: more than 1000 is refused below
                }
            }
            p.expect("}");
            if (count == 0 || count > kMaxIndexed)
                p.fail(a, "'" + d.name + "{...}' declares no names or more than 1000",
                       "write Q{3} for Q1, Q2, Q3, Q{2:4} for Q2, Q3, Q4 or C{2,3} for C11, ..., C23");
            d.first = first;
            d.last = last;
            while (p.is_symbol("'")) {
                p.take();
                ++d.primes;
            }
        }
        // a sign qualifier (L+ positive, L- negative, L~ nonzero): kept for the translator
        while (p.is_symbol("+") || p.is_symbol("-") || p.is_symbol("~")) {
            const Token& s = p.take();
            if (d.sign && d.sign != s.text[0])
                p.fail(s, "two sign qualifiers on '" + d.name + "'", "write one of '+', '-' or '~' after the name");
            d.sign = s.text[0];
            d.sign_where = s.where;
        }
        if (p.is_symbol("=")) {
            p.take();
            d.has_value = true;
            d.value = p.expression();
            d.unit_where = p.peek().where;
            d.unit = p.unit_words();
        }
        st.declarators.push_back(std::move(d));
        if (p.at_end()) break;
        p.expect(",");
    }
}

void parse_items(Parser& p, Statement& st) {
    if (p.at_end()) return;
    for (;;) {
        Item it;
        it.where = p.peek().where;
        it.lhs = p.expression();
        if (p.is_symbol("=")) {
            p.take();
            it.has_value = true;
            it.value = p.expression();
        }
        it.unit = p.unit_words();
        st.items.push_back(std::move(it));
        if (p.at_end()) break;
        p.expect(",");
    }
}

Statement parse_statement(Parser& p, const Lexer& lex, const std::vector<Token>& toks) {
    Statement st;
    const Token& first = p.peek();
    st.where = first.where;
    std::string w = first.kind == Token::Kind::name && !first.vector ? upper(first.text) : "";
    bool followed_by_operator = p.is_symbol("=", 1) || p.is_symbol("(", 1) || p.is_symbol("[", 1) ||
                                p.is_symbol("+", 1) || p.is_symbol("*", 1) || p.is_symbol("/", 1) ||
                                p.is_symbol("^", 1) || p.is_symbol("-", 1);
    if (!w.empty() && is_declaration_word(w) && !followed_by_operator) {
        st.kind = Statement::Kind::declaration;
        st.keyword = w;
        st.keyword_primes = first.primes;
        p.take();
        parse_declarators(p, st);
        return st;
    }
    if (!w.empty() && is_list_word(w) && first.primes == 0 && !p.is_symbol("=", 1) && !p.is_symbol("(", 1)) {
        st.kind = Statement::Kind::list;
        st.keyword = w == "INPUTS" ? "INPUT" : w == "OUTPUTS" ? "OUTPUT" : w;
        p.take();
        parse_items(p, st);
        return st;
    }
    // a leading word followed by another word is a command (CODE DYNAMICS() f.c, AUTOZ ON)
    if (!w.empty() && first.primes == 0 && (p.peek(1).kind == Token::Kind::name || p.peek(1).kind == Token::Kind::end ||
                                            p.peek(1).kind == Token::Kind::number)) {
        st.kind = Statement::Kind::command;
        st.keyword = w;
        std::string_view rest = lex.rest_of_line(first);
        rest.remove_prefix(std::min(rest.size(), first.text.size()));
        while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
        st.text = std::string(rest);
        while (!p.at_end()) p.take();
        (void)toks;
        return st;
    }
    // `X := e` is `X = e`; `X += e` is `X = X + (e)` (also -=, *=, /=)
    if (first.kind == Token::Kind::name && p.is_symbol("=", 2) &&
        (p.is_symbol(":", 1) || p.is_symbol("+", 1) || p.is_symbol("-", 1) || p.is_symbol("*", 1) ||
         p.is_symbol("/", 1))) {
        Expr lhs;
        lhs.kind = Expr::Kind::name;
        lhs.text = first.text;
        lhs.primes = first.primes;
        lhs.vector = first.vector;
        lhs.dyadic = first.dyadic;
        lhs.where = first.where;
        p.take();
        const Token& op = p.take();
        p.take();
        st.kind = Statement::Kind::assignment;
        Expr rhs = p.expression();
        if (op.text != ":") st.compound = op.text[0];
        st.rhs = op.text == ":" ? std::move(rhs) : p.binary(op, lhs, std::move(rhs));
        st.lhs = std::move(lhs);
        if (!p.at_end())
            p.fail(p.peek(), "unexpected " + p.describe(p.peek()) + " after the statement",
                   "one statement a line; separate statements with ';'");
        return st;
    }
    // `ZERO[1] += e` is `ZERO[1] = ZERO[1] + (e)` (also -=, *=, /=)
    if (first.kind == Token::Kind::name && p.is_symbol("[", 1)) {
        std::size_t k = 2;
        for (int depth = 1; depth > 0 && p.peek(k).kind != Token::Kind::end; ++k)
            depth += p.is_symbol("[", k) ? 1 : p.is_symbol("]", k) ? -1 : 0;
        if (p.is_symbol("=", k + 1) &&
            (p.is_symbol("+", k) || p.is_symbol("-", k) || p.is_symbol("*", k) || p.is_symbol("/", k))) {
            Expr lhs = p.primary();
            const Token& op = p.take();
            p.take();
            st.kind = Statement::Kind::assignment;
            Expr rhs = p.expression();
            st.compound = op.text[0];
            st.rhs = p.binary(op, lhs, std::move(rhs));
            st.lhs = std::move(lhs);
            if (!p.at_end())
                p.fail(p.peek(), "unexpected " + p.describe(p.peek()) + " after the statement",
                       "one statement a line; separate statements with ';'");
            return st;
        }
    }
    Expr e = p.expression();
    if (p.is_symbol("=")) {
        p.take();
        st.kind = Statement::Kind::assignment;
        st.lhs = std::move(e);
        st.rhs = p.expression();
    } else {
        st.kind = Statement::Kind::expression;
        st.expr = std::move(e);
    }
    if (!p.at_end())
        p.fail(p.peek(), "unexpected " + p.describe(p.peek()) + " after the statement",
               "one statement a line; separate statements with ';'");
    return st;
}

}  // namespace

ParsedFile parse_autolev(std::string_view source) {
    ParsedFile out;
    Lexer lex(source);
    std::vector<Token> toks;
    std::vector<Problem> lex_problems;
    while (lex.next_statement(toks, lex_problems)) {
        if (!lex_problems.empty()) {
            for (Problem& pr : lex_problems) out.problems.push_back({pr.where, pr.message, pr.hint});
            lex_problems.clear();
            continue;
        }
        Parser p(toks);
        try {
            out.statements.push_back(parse_statement(p, lex, toks));
        } catch (const ScriptError& e) {
            out.problems.push_back({e.where(), e.what(), e.hint()});
        }
    }
    return out;
}

}  // namespace alembert::lang::autolev
