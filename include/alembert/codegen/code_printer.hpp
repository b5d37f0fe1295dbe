// SPDX-License-Identifier: MIT
// Printers of straight-line programs: a C-like base and one printer per target language.
#pragma once

#include <functional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "alembert/sym/program.hpp"

namespace alembert {

/// How the values of one program are spelled in one generated function.
struct ValueSpelling {
    std::vector<std::string> inputs;      ///< one per program input
    std::vector<std::string> parameters;  ///< one per program parameter
    /// The k-th value computed by the prelude (k from 0), e.g. "h[3]".
    std::function<std::string(std::size_t)> hoisted;
    /// Prefix of the numbered intermediates of the body: z1, z2, ... in dependency order.
    std::string temporary_prefix = "z";
};

/// Prints a StraightLineProgram as statements of a target language, in the manner of
/// SymEngine's code printers: the base spells C (operators, <math.h> names, `const double`
/// definitions, `/* */` comments, 0-based brackets); each language overrides what differs.
/// Every operand of an instruction is a name or a number, so expressions need no precedence
/// rules beyond parenthesised negative numbers.
class CodePrinter {
public:
    virtual ~CodePrinter() = default;

    /// A double that reads back as the same double (shortest round trip, always with a
    /// decimal point or exponent so it cannot be taken for an integer).
    virtual std::string number(double x) const;
    /// A statement defining a new local variable.
    virtual std::string define(const std::string& name, const std::string& expression) const;
    /// A statement assigning to an existing place (an array element, an output).
    virtual std::string assign(const std::string& place, const std::string& expression) const;
    /// A comment on one line.
    virtual std::string comment(const std::string& text) const;
    /// Element k (from 0) of an array.
    virtual std::string element(const std::string& array, std::size_t k) const;
    /// The function `op` applied to a (and b for pow and atan2), for ops other than the
    /// arithmetic operators, combine and sincos.
    virtual std::string function(ProgramOp op, const std::string& a, const std::string& b) const;
    /// Words the language reserves (keywords, names the generated code uses itself).
    virtual const std::set<std::string>& reserved() const;

    /// The right-hand side computing instruction `in` (any op but sincos).
    std::string expression(const StraightLineProgram& p, const ProgramInstruction& in,
                           const ValueSpelling& names) const;
    /// How value v is spelled as an operand.
    std::string operand(const StraightLineProgram& p, std::uint32_t v,
                        const ValueSpelling& names) const;
    /// Prints `code` (p.prelude or p.body) one statement per line after `indent`: prelude
    /// results are assigned to their hoisted places, body results defined as new locals.
    void print(std::ostream& os, const StraightLineProgram& p,
               const std::vector<ProgramInstruction>& code, const ValueSpelling& names,
               const std::string& indent) const;
    /// A valid identifier for `name` in this language, distinct from `taken` (which it joins).
    std::string identifier(const std::string& name, std::set<std::string>& taken) const;
};

/// C99 (<math.h>).
class CPrinter : public CodePrinter {};

/// C++ (<cmath>, std:: functions, `//` comments).
class CppPrinter : public CodePrinter {
public:
    std::string comment(const std::string& text) const override;
    std::string function(ProgramOp op, const std::string& a, const std::string& b) const override;
    const std::set<std::string>& reserved() const override;
};

/// MATLAB/Octave: `z1 = ...;`, `%` comments, 1-based parentheses, `^`.
class MatlabPrinter : public CodePrinter {
public:
    std::string number(double x) const override;
    std::string define(const std::string& name, const std::string& expression) const override;
    std::string assign(const std::string& place, const std::string& expression) const override;
    std::string comment(const std::string& text) const override;
    std::string element(const std::string& array, std::size_t k) const override;
    std::string function(ProgramOp op, const std::string& a, const std::string& b) const override;
    const std::set<std::string>& reserved() const override;
};

/// Python 3 (scalars with the math module): `z1 = ...`, `#` comments, `**`.
class PythonPrinter : public CodePrinter {
public:
    std::string number(double x) const override;
    std::string define(const std::string& name, const std::string& expression) const override;
    std::string assign(const std::string& place, const std::string& expression) const override;
    std::string comment(const std::string& text) const override;
    std::string function(ProgramOp op, const std::string& a, const std::string& b) const override;
    const std::set<std::string>& reserved() const override;
};

}  // namespace alembert
