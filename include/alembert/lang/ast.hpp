// SPDX-License-Identifier: MIT
// The syntax tree of the Alembert language: expressions and statements.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "alembert/lang/diagnostic.hpp"

namespace alembert::lang {

/// A name as written, with where it is.
struct Word {
    std::string text{};
    Location location{};
};

/// A unit as written after a number or a declared name: factors with integer powers.
struct UnitText {
    struct Factor {
        Word name{};
        int power = 1;
    };
    std::vector<Factor> factors{};
    Location location{};
    bool empty() const { return factors.empty(); }
};

/// An expression. Sums and products are n-ary (a + b - c is one node), so long flat chains do
/// not make deep trees; nesting is limited by the parser (Limits::max_nesting).
struct Expr {
    enum class Kind {
        number,       ///< `number`
        name,         ///< a scalar, array or object name (`text`)
        vector_name,  ///< Ax>, r> (`text` without '>')
        dyadic_name,  ///< D>> (`text` without '>>')
        zero_vector,  ///< 0>
        sum,          ///< args[i] added, or subtracted where `inverted[i]`
        product,      ///< args[i] multiplied, or divided where `inverted[i]`
        power,        ///< args[0] ^ args[1]
        negate,       ///< -args[0]
        call,         ///< text(args...)
        index,        ///< text[args[0]]
        list,         ///< [a, b, c]
        matrix,       ///< [a, b; c, d]: `rows` rows of args.size()/rows entries
        binding,      ///< args[0] = args[1], an argument of replace() and taylor() (`q = 0`)
    };
    Kind kind = Kind::number;
    Location location{};
    std::string text{};
    double number = 0;
    std::string number_text{};
    std::vector<std::unique_ptr<Expr>> args{};
    std::vector<bool> inverted{};
    int rows = 0;
    UnitText unit{};  ///< a number's unit, `0.1575 m` (a number node only; empty: none)
};
using ExprPtr = std::unique_ptr<Expr>;

/// A number with an optional unit (`9.81 m/s^2`), or an expression where one is allowed.
struct Quantity {
    ExprPtr value{};   ///< the number or expression (null: none given)
    UnitText unit{};
};

/// A declared item: `qA''`, `g = 9.81 m/s^2`, `k N/m`, `T_A N*m`.
struct Declared {
    Word name{};      ///< the base name, without primes
    int primes = 0;
    Quantity quantity{};
};

/// `name = value` in `at` and `guess` clauses.
struct Binding {
    Word name{};
    Quantity quantity{};
};

/// A statement: the keyword that starts it and its parts by role. Roles are the clause words
/// of docs/language.md ("from", "about", "by", ...); the interpreter reads the ones its
/// statement has. An expression statement has an empty keyword and its expression in
/// exprs["value"]; an assignment has keyword "=" and words["target"].
struct Statement {
    std::string keyword{};
    Location location{};
    std::string source{};  ///< the statement's text, for the transcript
    std::map<std::string, Word> words{};
    std::map<std::string, std::vector<Word>> lists{};
    std::map<std::string, ExprPtr> exprs{};
    std::map<std::string, std::vector<ExprPtr>> expr_lists{};
    std::vector<Declared> declared{};
    std::map<std::string, std::vector<Binding>> bindings{};
    std::map<std::string, bool> flags{};
    std::map<std::string, Quantity> quantities{};     ///< `final time 5 s`: quantities["time"]
    std::vector<UnitText> units{};                    ///< `output x in m, y`: one per expr_lists["values"]

    bool has_word(const std::string& role) const { return words.count(role) != 0; }
    const Word& word(const std::string& role) const { return words.at(role); }
    const Expr* expr(const std::string& role) const {
        auto it = exprs.find(role);
        return it == exprs.end() ? nullptr : it->second.get();
    }
    bool flag(const std::string& role) const { return flags.count(role) != 0; }
};

}  // namespace alembert::lang
