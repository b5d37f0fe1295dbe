// SPDX-License-Identifier: MIT
// The syntax of the Autolev dialect: tokens, expressions and statements of a .al file.
#pragma once
#include <string>
#include <string_view>
#include <utility>
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

struct Expr;

/// The operands of an expression: a vector of expressions whose copy and destructor walk a
/// chain of any depth with a worklist of their own (a 200,000-factor product is a left-nested
/// tree as deep as it is long, which the implicit recursive members would follow down the stack).
struct ExprArgs : std::vector<Expr> {
    using std::vector<Expr>::vector;
    ExprArgs() = default;
    ExprArgs(const ExprArgs& other);
    ExprArgs(ExprArgs&&) noexcept = default;
    ExprArgs& operator=(const ExprArgs& other);
    ExprArgs& operator=(ExprArgs&&) noexcept = default;
    ~ExprArgs();
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
    ExprArgs args{};
    Location where{};  // a member added to Expr is also copied in ExprArgs' copy constructor
};

// Level by level: each operand is copied without its operands, which are queued to be copied
// into it (its place in `to` stays put: `to` was reserved and is not grown again).
inline ExprArgs::ExprArgs(const ExprArgs& other) : std::vector<Expr>() {
    std::vector<std::pair<const ExprArgs*, ExprArgs*>> work{{&other, this}};
    while (!work.empty()) {
        auto [from, to] = work.back();
        work.pop_back();
        to->reserve(from->size());
        for (const Expr& e : *from) {
            Expr& c = to->emplace_back();
            c.kind = e.kind;
            c.text = e.text;
            c.primes = e.primes;
            c.vector = e.vector;
            c.dyadic = e.dyadic;
            c.where = e.where;
        }
        for (std::size_t i = 0; i < from->size(); ++i)
            if (!(*from)[i].args.empty()) work.emplace_back(&(*from)[i].args, &(*to)[i].args);
    }
}

inline ExprArgs& ExprArgs::operator=(const ExprArgs& other) {
    if (this != &other) *this = ExprArgs(other);
    return *this;
}

// Each operand's own operands are moved onto the worklist before the operand is destroyed, so
// every destructor that runs meets operands that have none: the stack stays two calls deep.
inline ExprArgs::~ExprArgs() {
    bool leaves = true;
    for (const Expr& e : *this) leaves = leaves && e.args.empty();
    if (leaves) return;
    std::vector<Expr> work;
    for (Expr& e : *this) work.push_back(std::move(e));
    while (!work.empty()) {
        Expr e = std::move(work.back());
        work.pop_back();
        for (Expr& c : e.args) work.push_back(std::move(c));
    }
}

/// One name of a declaration: `Q{2:3}''` is name Q, indices 2..3, two primes.
struct Declarator {
    std::string name{};
    int first = 0, last = -1;  ///< an index range when last >= first (`Q{3}`: 1..3)
    int first2 = 0, last2 = -1;  ///< a second index range (`C{2,3}`: C11, ..., C23)
    /// third and further index ranges (`C{2,2,2}`): read, and left out by the translator, as
    /// the script's names have at most two indices
    std::vector<std::pair<int, int>> more{};
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
