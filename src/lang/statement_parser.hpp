// SPDX-License-Identifier: MIT
// The parser's tools that statements' grammars use (private to src/lang): tokens, names,
// expressions, quantities with units, bindings, and errors that say what was expected.
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/ast.hpp"
#include "alembert/lang/lexer.hpp"
#include "alembert/lang/statements.hpp"

namespace alembert::lang {

/// Walks the tokens of one statement. parse() reads the keyword, hands the rest to the
/// statement's StatementSpec::parse, which takes its parts with the methods below, and then
/// checks the end of the statement.
class StatementParser {
public:
    StatementParser(const std::vector<Token>& tokens, std::string_view source)
        : t_(tokens), src_(source) {}

    Statement parse();

    // ---- tokens ----------------------------------------------------------------------------
    const Token& peek(std::size_t ahead = 0) const {
        return t_[std::min(i_ + ahead, t_.size() - 1)];
    }
    const Token& next() {
        const Token& t = peek();
        if (i_ + 1 < t_.size()) ++i_;
        return t;
    }
    bool at_end() const { return peek().kind == TokenKind::end; }
    bool at_word(std::string_view w) const {
        return peek().kind == TokenKind::name && peek().text == w;
    }
    bool accept_punct(std::string_view p) {
        if (!peek().is(p)) return false;
        next();
        return true;
    }
    bool accept_word(std::string_view w) {
        if (!at_word(w)) return false;
        next();
        return true;
    }
    /// The current word as the value of a choice (`linear`, `fixed`), consumed.
    Word take_word() {
        Word w{peek().text, peek().location};
        next();
        return w;
    }

    // ---- errors ----------------------------------------------------------------------------
    /// @throws ScriptError "expected WHAT, found ..." at the current token, with a hint to the
    /// statement's forms.
    [[noreturn]] void fail_expected(const std::string& what) const;
    void expect_punct(std::string_view p, const std::string& context);
    void expect_word(std::string_view w, const std::string& context);
    void expect_end(const std::string& context);

    // ---- parts by role ---------------------------------------------------------------------
    Word name(const std::string& what);
    Word text(const std::string& what);  ///< a string in double quotes (a path)
    std::vector<Word> name_list(const std::string& what);
    UnitText unit();
    Quantity quantity();  ///< a value and, unless a clause word follows, its unit
    std::vector<Binding> bindings(const std::string& what);  ///< name = value, ...
    std::vector<Declared> declarations();                    ///< qA'', g = 9.81 m/s^2, ...
    ExprPtr expression();
    std::vector<ExprPtr> expression_list();

private:
    ExprPtr sum();
    ExprPtr term();
    ExprPtr unary();
    ExprPtr power();
    ExprPtr primary();
    UnitText unit_after_number();
    bool unit_name_follows(std::size_t ahead) const;
    bool own_clause_word(std::string_view w) const;  ///< `m/s^2` in `9.81 m/s^2 * Nz>`: known unit names only

    const std::vector<Token>& t_;
    std::string_view src_;
    std::size_t i_ = 0;
    int depth_ = 0;
    std::string keyword_;
};

// The families of statements, each defined in its own file; statements.cpp lists them in the
// order of docs/language.md.
std::vector<StatementSpec> include_statements();      // statements_include.cpp
std::vector<StatementSpec> declaration_statements();  // statements_declarations.cpp
std::vector<StatementSpec> kinematics_statements();   // statements_kinematics.cpp
std::vector<StatementSpec> load_statements();         // statements_loads.cpp
std::vector<StatementSpec> biomech_statements();      // statements_biomech.cpp
std::vector<StatementSpec> lab_statements();          // statements_lab.cpp
std::vector<StatementSpec> scale_statements();        // statements_scale.cpp
std::vector<StatementSpec> constraint_statements();   // statements_kinematics.cpp
std::vector<StatementSpec> equation_statements();     // interpreter_equations.cpp
std::vector<StatementSpec> number_statements();       // interpreter_numbers.cpp
std::vector<StatementSpec> linearize_statements();    // statements_linearize.cpp

}  // namespace alembert::lang
