// SPDX-License-Identifier: MIT
// The syntax of the Autolev dialect: tokens, expressions and statements of a .al file.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/diagnostic.hpp"

namespace alembert::lang::autolev {

/// A token of an Autolev file. Names carry their primes (`Q1'`) and a trailing `>` (`A1>`,
/// `V_P_N>`, and `0>` the zero vector) or `>>` (a dyadic: `D>>`, `I_B_BO>>`, `1>>` the unit
/// dyadic, `0>>`) when written without a space.
struct Token {
    enum class Kind { name, number, symbol, end };
    Kind kind = Kind::end;
    std::string text{};  ///< the name, number or symbol as written (without primes, '>' and '>>')
    int primes = 0;
    bool vector = false;  ///< also set for a dyadic
    bool dyadic = false;
    Location where{};
};

/// An Autolev expression as written; names keep the user's spelling (resolved later, without
/// regard to case).
struct Expr {
    enum class Kind {
        number,  ///< text: the number
        name,    ///< text, primes, vector, dyadic
        call,    ///< text: function; args
        index,   ///< text: array name; args: the subscripts (`DEPENDENT[U3]`, `ZERO[1]`)
        unary,   ///< text "-" or "+"; args[0]
        binary,  ///< text: "+ - * / ^"; args[0], args[1]
        matrix,  ///< args: rows, each of kind row
        row,     ///< args: the elements
    };
    Kind kind = Kind::number;
    std::string text{};
    int primes = 0;
    bool vector = false;  ///< a name written with '>' (with '>>' too: `dyadic` tells)
    bool dyadic = false;
    std::vector<Expr> args{};
    Location where{};
};

/// One name of a declaration: `Q{2:3}''` is name Q, indices 2..3, two primes.
struct Declarator {
    std::string name{};
    int first = 0, last = -1;  ///< an index range when last >= first (`Q{3}`: 1..3)
    int first2 = 0, last2 = -1;  ///< a second index range (`C{2,3}`: C11, ..., C23)
    int primes = 0;
    char sign = 0;             ///< a qualifier after the name: '+', '-' or '~' (`CONSTANTS L+`)
    Location sign_where{};
    bool has_value = false;    ///< `CONSTANTS G = 9.81`, `SPECIFIED F = -K*X`
    Expr value{};
    std::string unit{};        ///< words after the value, as written (`M/S^2`)
    Location unit_where{};
    Location where{};
};

/// An item of a list statement: `P = M` (MASS), `Q1 = 30 DEG` (INPUT), `Q1 DEG` (OUTPUT).
struct Item {
    Expr lhs{};
    bool has_value = false;
    Expr value{};
    std::string unit{};  ///< words after the value, as written (`DEG`, `M/S`)
    Location where{};
};

/// A statement of an Autolev file.
struct Statement {
    enum class Kind {
        declaration,  ///< keyword (upper case), keyword_primes, declarators
        list,         ///< keyword MASS, INERTIA, INPUT, OUTPUT; items
        command,      ///< any other leading word that is not an expression (CODE, PAUSE, ...); text
        assignment,   ///< lhs = rhs (also `lhs := rhs`; `lhs += rhs` has rhs `lhs + (rhs)`)
        expression,   ///< expr (SIMPROT(...), KANE(), EXPRESS(...), ...)
    };
    Kind kind = Kind::expression;
    Location where{};
    std::string keyword{};
    int keyword_primes = 0;
    std::vector<Declarator> declarators{};
    std::vector<Item> items{};
    std::string text{};  ///< command: the rest of the line as written
    Expr lhs{}, rhs{};
    char compound = 0;  ///< '+', '-', '*' or '/' for `lhs += rhs` ... (rhs is then `lhs op (rhs)`)
    Expr expr{};
};

/// A statement that could not be read: where, and what is wrong.
struct SyntaxProblem {
    Location where{};
    std::string message{};
    std::string hint{};
};

/// The statements of an Autolev file and the problems of those that could not be read (each
/// such statement is skipped; reading goes on with the next line).
struct ParsedFile {
    std::vector<Statement> statements{};
    std::vector<SyntaxProblem> problems{};
};

/// Reads an Autolev file: `%` comments, one statement a line (or several separated by `;`),
/// a statement continuing onto the next lines while a bracket is open or after a line that
/// ends with `&`.
ParsedFile parse_autolev(std::string_view source);

/// `name` in upper case (Autolev's names do not depend on case).
std::string upper(std::string_view name);

}  // namespace alembert::lang::autolev
