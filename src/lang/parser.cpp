// SPDX-License-Identifier: MIT
// The parser: one statement's tokens to a Statement, expressions by precedence climbing.
#include "alembert/lang/parser.hpp"

#include <algorithm>
#include <set>

#include "alembert/lang/statements.hpp"
#include "alembert/lang/units.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

const std::set<std::string, std::less<>>& function_words() {
    static const std::set<std::string, std::less<>> w{
        "sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "exp", "log", "abs", "dot", "cross",
        "express", "dt", "mag", "unit", "simplify", "expand", "angvel", "angacc", "vel", "acc",
        "pos", "rotation", "mass", "momentum", "angmomentum", "kinetic", "potential",
        "resultant", "moment", "pi", "minimum_jerk", "massmatrix", "jacobian", "diff", "coef",
        "replace", "taylor", "floor", "factor", "transpose", "inv", "det", "diagmat", "element",
        "rows", "cols", "eig", "eigvec", "polynomial", "roots", "cm", "exclude", "include", "outer",
        "unitdyadic", "inertia", "matrix", "vector"};
    return w;
}

// a word that marks a clause of some statement, or `t` (time): never a unit after a value
bool is_clause_word(std::string_view w) {
    const auto& c = statement_clause_words();
    return w == "t" || std::binary_search(c.begin(), c.end(), w);
}

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::end: return "the end of the statement";
        case TokenKind::number: return "the number " + t.text;
        case TokenKind::string: return "the text \"" + t.text + "\"";
        case TokenKind::vector_name: return "the vector " + t.text + ">";
        case TokenKind::dyadic_name: return "the dyadic " + t.text + ">>";
        case TokenKind::zero_vector: return "0>";
        case TokenKind::punct: return "'" + t.text + "'";
        default: return "'" + t.text + "'";
    }
}

// edits (insertions, deletions, substitutions) that turn a into b
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// the statement a mistyped word most likely meant (at most two edits away, the first in the
// registry's order among the nearest), and where to find the others
std::string unknown_statement_hint(std::string_view word) {
    std::string_view best;
    std::size_t best_distance = 3;
    if (word.size() <= 64)
        for (const StatementSpec& spec : statements()) {
            std::size_t d = edit_distance(word, spec.keyword);
            if (d < best_distance) best = spec.keyword, best_distance = d;
        }
    std::string hint = best.empty() ? std::string()
                                    : "did you mean '" + std::string(best) + "'? ";
    return hint + "statements start with a word such as body, rotate, kane or solve "
                  "(docs/language.md; help in a session lists them), or are assignments name = value";
}

struct DepthGuard {
    int& depth;
    DepthGuard(int& d, Location where) : depth(d) {
        if (++depth > Limits::max_nesting)
            throw ScriptError(where, "the expression is nested too deeply (more than " +
                                         std::to_string(Limits::max_nesting) + " levels)",
                              "name parts of it with assignments");
    }
    ~DepthGuard() { --depth; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
};

}  // namespace

void StatementParser::fail_expected(const std::string& what) const {
    // the hint shows the statement's forms, from the registry
    std::string hint, forms = keyword_.empty() ? std::string() : statement_forms(keyword_, "    ");
    if (!forms.empty()) {
        bool one = forms.find('\n') + 1 == forms.size();
        hint = "'" + keyword_ + "' takes " + (one ? "this form" : "one of these forms") +
               " (docs/language.md; help " + keyword_ + " in a session):\n" +
               forms.substr(0, forms.size() - 1);
    }
    throw ScriptError(peek().location, "expected " + what + ", found " + describe(peek()), hint);
}

void StatementParser::expect_punct(std::string_view p, const std::string& context) {
    if (!accept_punct(p)) fail_expected("'" + std::string(p) + "' " + context);
}

void StatementParser::expect_word(std::string_view w, const std::string& context) {
    if (!accept_word(w)) fail_expected("'" + std::string(w) + "' " + context);
}

void StatementParser::expect_end(const std::string& context) {
    if (!at_end() && i_ > 0 && t_[i_ - 1].kind == TokenKind::number && peek().kind == TokenKind::name &&
        find_unit(peek().text))
        throw ScriptError(peek().location,
                          "'" + peek().text + "' is a clause of the '" + keyword_ +
                              "' statement here, so it cannot be the unit of the number before it",
                          "name the value first, e.g. c = " + t_[i_ - 1].text + " " + peek().text);
    if (!at_end()) {
        throw ScriptError(peek().location,
                          "unexpected " + describe(peek()) + " after " + context,
                          "one statement per line, or separate statements with ';'");
    }
}

Word StatementParser::name(const std::string& what) {
    if (peek().kind != TokenKind::name) fail_expected(what);
    const Token& t = next();
    return {t.text, t.location};
}

Word StatementParser::text(const std::string& what) {
    if (peek().kind != TokenKind::string) fail_expected(what + " in double quotes");
    const Token& t = next();
    if (t.text.empty()) throw ScriptError(t.location, "the " + what + " is empty", "write a path such as \"out\"");
    return {t.text, t.location};
}

std::vector<Word> StatementParser::name_list(const std::string& what) {
    std::vector<Word> out{name(what)};
    while (accept_punct(",")) out.push_back(name(what));
    return out;
}

UnitText StatementParser::unit() {
    UnitText u;
    u.location = peek().location;
    bool divide = false;
    for (;;) {
        if (peek().kind != TokenKind::name) fail_expected("a unit name (m, kg, s, N, deg, ...)");
        UnitText::Factor f;
        const Token& n = next();
        f.name = {n.text, n.location};
        if (accept_punct("^")) {
            bool minus = accept_punct("-");
            if (peek().kind != TokenKind::number || peek().text.find_first_not_of("0123456789") != std::string::npos ||
                peek().text.size() > 2)
                fail_expected("a small whole number as the power of a unit");
            f.power = std::stoi(next().text) * (minus ? -1 : 1);
        }
        if (divide) f.power = -f.power;
        u.factors.push_back(f);
        if (peek().is("*") && peek(1).kind == TokenKind::name) {
            next();
            continue;
        }
        if (peek().is("/") && peek(1).kind == TokenKind::name) {
            next();
            divide = true;
            continue;
        }
        return u;
    }
}

// a word that marks a clause of the statement being parsed (`in` of output), or `t`
bool StatementParser::own_clause_word(std::string_view w) const {
    if (w == "t") return true;
    const StatementSpec* spec = keyword_.empty() ? nullptr : find_statement(keyword_);
    return spec && std::find(spec->clauses.begin(), spec->clauses.end(), w) != spec->clauses.end();
}

// a known unit name that no clause of this statement or call claims: `m` in `0.1575 m`, but
// not `in` of `output x in cm` or `sin(`
bool StatementParser::unit_name_follows(std::size_t ahead) const {
    const Token& n = peek(ahead);
    return n.kind == TokenKind::name && find_unit(n.text) && !own_clause_word(n.text) &&
           !peek(ahead + 1).is("(") && !peek(ahead + 1).is("[");
}

UnitText StatementParser::unit_after_number() {
    UnitText u;
    u.location = peek().location;
    bool divide = false;
    for (;;) {
        UnitText::Factor f;
        const Token& n = next();
        f.name = {n.text, n.location};
        if (peek().is("^") && (peek(1).kind == TokenKind::number ||
                               (peek(1).is("-") && peek(2).kind == TokenKind::number))) {
            next();
            bool minus = accept_punct("-");
            if (peek().text.find_first_not_of("0123456789") != std::string::npos || peek().text.size() > 2)
                fail_expected("a small whole number as the power of a unit");
            f.power = std::stoi(next().text) * (minus ? -1 : 1);
        }
        if (divide) f.power = -f.power;
        u.factors.push_back(f);
        if ((peek().is("*") || peek().is("/")) && unit_name_follows(1)) {
            divide = next().text == "/" || divide;
            continue;
        }
        return u;
    }
}

Quantity StatementParser::quantity() {
    Quantity q;
    q.value = expression();
    // a lone number's unit is the quantity's unit, read as before: `constant I = 0.1 kg*m^2`
    if (q.value->kind == Expr::Kind::number && !q.value->unit.empty()) {
        q.unit = std::move(q.value->unit);
        q.value->unit = {};
        return q;
    }
    if (peek().kind == TokenKind::name && !own_clause_word(peek().text)) q.unit = unit();
    return q;
}

std::vector<Binding> StatementParser::bindings(const std::string& what) {
    std::vector<Binding> out;
    do {
        Binding b;
        b.name = name(what);
        expect_punct("=", "after '" + b.name.text + "' (give its value: name = value)");
        b.quantity = quantity();
        out.push_back(std::move(b));
    } while (accept_punct(","));
    return out;
}

std::vector<Declared> StatementParser::declarations() {
    std::vector<Declared> out;
    do {
        Declared d;
        Word w = name("a name to declare");
        std::size_t primes = w.text.size() - std::min(w.text.size(), w.text.find('\''));
        if (w.text.find('\'') == std::string::npos) primes = 0;
        d.primes = static_cast<int>(primes);
        d.name = {w.text.substr(0, w.text.size() - primes), w.location};
        if (accept_punct("=")) {
            d.quantity = quantity();
        } else if (peek().kind == TokenKind::name) {
            d.quantity.unit = unit();
        }
        out.push_back(std::move(d));
    } while (accept_punct(","));
    return out;
}

std::vector<ExprPtr> StatementParser::expression_list() {
    std::vector<ExprPtr> out;
    out.push_back(expression());
    while (accept_punct(",")) out.push_back(expression());
    return out;
}

// ---- expressions -----------------------------------------------------------------------

ExprPtr StatementParser::expression() { return sum(); }

ExprPtr StatementParser::sum() {
    Location where = peek().location;
    ExprPtr first = term();
    if (!peek().is("+") && !peek().is("-")) return first;
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::sum;
    node->location = where;
    node->args.push_back(std::move(first));
    node->inverted.push_back(false);
    while (peek().is("+") || peek().is("-")) {
        bool minus = next().text == "-";
        node->args.push_back(term());
        node->inverted.push_back(minus);
    }
    return node;
}

ExprPtr StatementParser::term() {
    Location where = peek().location;
    ExprPtr first = unary();
    if (!peek().is("*") && !peek().is("/")) return first;
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::product;
    node->location = where;
    node->args.push_back(std::move(first));
    node->inverted.push_back(false);
    while (peek().is("*") || peek().is("/")) {
        bool divide = next().text == "/";
        node->args.push_back(unary());
        node->inverted.push_back(divide);
    }
    return node;
}

ExprPtr StatementParser::unary() {
    if (peek().is("-") || peek().is("+")) {
        Location where = peek().location;
        DepthGuard guard(depth_, where);
        bool minus = next().text == "-";
        ExprPtr operand = unary();
        if (!minus) return operand;
        auto node = std::make_unique<Expr>();
        node->kind = Expr::Kind::negate;
        node->location = where;
        node->args.push_back(std::move(operand));
        return node;
    }
    return power();
}

ExprPtr StatementParser::power() {
    ExprPtr base = primary();
    if (!peek().is("^")) return base;
    Location where = peek().location;
    next();
    DepthGuard guard(depth_, where);
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::power;
    node->location = where;
    node->args.push_back(std::move(base));
    node->args.push_back(unary());
    return node;
}

ExprPtr StatementParser::primary() {
    const Token& t = peek();
    auto node = std::make_unique<Expr>();
    node->location = t.location;
    switch (t.kind) {
        case TokenKind::number:
            node->kind = Expr::Kind::number;
            node->number = t.number;
            node->number_text = t.text;
            next();
            if (unit_name_follows(0)) node->unit = unit_after_number();
            return node;
        case TokenKind::zero_vector:
            node->kind = Expr::Kind::zero_vector;
            next();
            return node;
        case TokenKind::vector_name:
            node->kind = Expr::Kind::vector_name;
            node->text = t.text;
            next();
            return node;
        case TokenKind::dyadic_name:
            node->kind = Expr::Kind::dyadic_name;
            node->text = t.text;
            next();
            return node;
        case TokenKind::name: {
            node->text = t.text;
            next();
            if (peek().is("(")) {
                DepthGuard guard(depth_, peek().location);
                next();
                node->kind = Expr::Kind::call;
                if (!peek().is(")")) {
                    // an argument may be a binding `x = v` (replace(e, q = 0), taylor(e, q = 0, 3))
                    do {
                        ExprPtr arg = expression();
                        if (peek().is("=")) {
                            auto b = std::make_unique<Expr>();
                            b->kind = Expr::Kind::binding;
                            b->location = peek().location;
                            next();
                            b->args.push_back(std::move(arg));
                            b->args.push_back(expression());
                            arg = std::move(b);
                        }
                        node->args.push_back(std::move(arg));
                    } while (accept_punct(","));
                }
                expect_punct(")", "to close the arguments of " + node->text + "(...)");
                return node;
            }
            if (peek().is("[")) {
                DepthGuard guard(depth_, peek().location);
                next();
                node->kind = Expr::Kind::index;
                node->args.push_back(expression());
                if (accept_punct(",")) node->args.push_back(expression());  // a matrix's row, column
                expect_punct("]", "after the index of " + node->text);
                return node;
            }
            node->kind = Expr::Kind::name;
            return node;
        }
        case TokenKind::punct:
            if (t.is("(")) {
                DepthGuard guard(depth_, t.location);
                next();
                ExprPtr inner = expression();
                expect_punct(")", "to close '(' at " + std::to_string(node->location.line) + ":" +
                                      std::to_string(node->location.column));
                return inner;
            }
            if (t.is("[")) {
                DepthGuard guard(depth_, t.location);
                next();
                node->kind = Expr::Kind::list;
                int rows = 1;
                std::size_t per_row = 0;
                if (!peek().is("]")) {
                    for (;;) {
                        node->args.push_back(expression());
                        if (accept_punct(",")) continue;
                        if (peek().is(";")) {
                            Location semi = peek().location;
                            next();
                            if (per_row == 0) per_row = node->args.size();
                            if (node->args.size() != per_row * static_cast<std::size_t>(rows))
                                throw ScriptError(semi, "the rows of the matrix have different lengths",
                                                  "give every row the same number of entries");
                            ++rows;
                            continue;
                        }
                        break;
                    }
                }
                Location close = peek().location;
                expect_punct("]", "to close the list");
                if (rows > 1) {
                    if (node->args.size() != per_row * static_cast<std::size_t>(rows))
                        throw ScriptError(close, "the rows of the matrix have different lengths",
                                          "give every row the same number of entries");
                    node->kind = Expr::Kind::matrix;
                    node->rows = rows;
                }
                return node;
            }
            break;
        default: break;
    }
    fail_expected("a value (a number, a name, a vector such as Ax>, or '(')");
}

// ---- statements ------------------------------------------------------------------------

Statement StatementParser::parse() {
    Statement s;
    const Token& first = peek();
    s.location = first.location;
    std::size_t last = t_.size() >= 2 ? t_.size() - 2 : 0;
    // the statement's text, with a comment that ends its line
    std::size_t end = t_[last].end;
    std::size_t k = end;
    while (k < src_.size() && (src_[k] == ' ' || src_[k] == '\t')) ++k;
    if (k < src_.size() && src_[k] == '#') {
        end = src_.find('\n', k);
        if (end == std::string_view::npos) end = src_.size();
        while (end > k && src_[end - 1] == '\r') --end;
    }
    s.source = std::string(src_.substr(first.begin, end - first.begin));
    if (first.kind == TokenKind::comment) {
        s.keyword = "#";
        s.source = first.text;
        return s;
    }
    // a statement word starts its statement, unless an assignment uses the word or the word is
    // also a function's name and '(' follows (`mass(A)` is a call, `evaluate (a + q) at q = 1`
    // a statement)
    const StatementSpec* spec = first.kind == TokenKind::name ? find_statement(first.text) : nullptr;
    const bool call = peek(1).is("(") && function_words().count(first.text) != 0;
    if (spec && !call && !peek(1).is("=")) {
        s.keyword = first.text;
        keyword_ = s.keyword;
        next();
        spec->parse(*this, s);
        expect_end("the '" + s.keyword + "' statement");
        return s;
    }
    if ((first.kind == TokenKind::name || first.kind == TokenKind::vector_name ||
         first.kind == TokenKind::dyadic_name) &&
        peek(1).is("=")) {
        s.keyword = "=";
        s.words["target"] = {first.text, first.location};
        if (first.kind == TokenKind::vector_name) s.flags["vector"] = true;
        if (first.kind == TokenKind::dyadic_name) s.flags["dyadic"] = true;
        next();
        next();
        s.exprs["value"] = expression();
        expect_end("the assignment");
        return s;
    }
    if (first.kind == TokenKind::name && !peek(1).is("(") && !peek(1).is("[") &&
        peek(1).kind == TokenKind::name && !is_clause_word(first.text))
        throw ScriptError(first.location, "unknown statement '" + first.text + "'", unknown_statement_hint(first.text));
    s.exprs["value"] = expression();
    expect_end("the expression");
    return s;
}

const std::vector<std::string>& statement_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> out;
        for (const StatementSpec& spec : statements()) out.emplace_back(spec.keyword);
        return out;
    }();
    return k;
}

const std::vector<std::string>& function_names() {
    static const std::vector<std::string> f(function_words().begin(), function_words().end());
    return f;
}

bool is_reserved(std::string_view name) {
    return find_statement(name) != nullptr || is_clause_word(name) || function_words().count(name) != 0;
}

Statement parse_statement(const std::vector<Token>& tokens, std::string_view source) {
    if (tokens.empty() || tokens.back().kind != TokenKind::end)
        throw ScriptError({}, "internal: a statement must end with an end token");
    return StatementParser(tokens, source).parse();
}

}  // namespace alembert::lang
