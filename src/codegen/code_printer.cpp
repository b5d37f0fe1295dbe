// SPDX-License-Identifier: MIT
// Printers of straight-line programs: a C-like base and one printer per target language.
#include "alembert/codegen/code_printer.hpp"

#include <charconv>
#include <cmath>
#include <regex>

#include "alembert/error.hpp"

namespace alembert {

namespace {

// <math.h> names of the functions, by operation
const char* c_function(ProgramOp op) {
    switch (op) {
        case ProgramOp::abs: return "fabs";
        default: return to_string(op);
    }
}

std::set<std::string> c_words() {
    return {"auto", "break", "case", "char", "const", "continue", "default", "do", "double",
            "else", "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long",
            "register", "restrict", "return", "short", "signed", "sizeof", "static", "struct",
            "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool",
            "_Complex", "_Imaginary", "NULL", "INFINITY", "NAN", "errno", "main", "printf",
            // <math.h>
            "sin", "cos", "tan", "exp", "log", "sqrt", "pow", "fabs", "asin", "acos", "atan",
            "atan2", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "sincos",
            // names of the generated code
            "t", "q", "qp", "qpp", "u", "M", "f", "y", "h", "p", "c", "x", "dx", "n", "i", "j",
            "k", "s", "ok", "A", "b", "a", "e", "lambda", "reaction"};
}

}  // namespace

// ---- numbers and statements ------------------------------------------------------------------

std::string CodePrinter::number(double x) const {
    if (std::isnan(x)) return "NAN";
    if (std::isinf(x)) return x > 0 ? "INFINITY" : "-INFINITY";
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    std::string s(buf, end);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string CodePrinter::define(const std::string& name, const std::string& expression) const {
    return "const double " + name + " = " + expression + ";";
}

std::string CodePrinter::assign(const std::string& place, const std::string& expression) const {
    return place + " = " + expression + ";";
}

std::string CodePrinter::comment(const std::string& text) const { return "/* " + text + " */"; }

std::string CodePrinter::element(const std::string& array, std::size_t k) const {
    return array + "[" + std::to_string(k) + "]";
}

std::string CodePrinter::function(ProgramOp op, const std::string& a, const std::string& b) const {
    switch (op) {
        case ProgramOp::pow: return "pow(" + a + ", " + b + ")";
        case ProgramOp::atan2: return "atan2(" + a + ", " + b + ")";
        case ProgramOp::csgn: return "(double)((" + a + " > 0.0) - (" + a + " < 0.0))";
        case ProgramOp::step: return "(" + a + " > 0.0 ? 1.0 : (" + a + " < 0.0 ? 0.0 : 0.5))";
        default: return std::string(c_function(op)) + "(" + a + ")";
    }
}

const std::set<std::string>& CodePrinter::reserved() const {
    static const std::set<std::string> words = c_words();
    return words;
}

// ---- programs ----------------------------------------------------------------------------------

std::string CodePrinter::operand(const StraightLineProgram& p, std::uint32_t v,
                                 const ValueSpelling& names) const {
    switch (p.kind(v)) {
        case ValueKind::input: return names.inputs.at(v);
        case ValueKind::parameter: return names.parameters.at(v - p.input_count);
        case ValueKind::literal: {
            std::string s = number(p.literal(v));
            return s.front() == '-' ? "(" + s + ")" : s;
        }
        case ValueKind::hoisted: return names.hoisted(v - p.first_hoisted());
        case ValueKind::temporary:
            return names.temporary_prefix + std::to_string(v - p.first_temporary + 1);
    }
    return "?";
}

std::string CodePrinter::expression(const StraightLineProgram& p, const ProgramInstruction& in,
                                    const ValueSpelling& names) const {
    auto at = [&](std::uint32_t v) { return operand(p, v, names); };
    switch (in.op) {
        case ProgramOp::combine: {
            // c1*a + b - c3*d + 2.5: numbers and unit coefficients printed without a product
            std::string s;
            for (std::uint32_t k = in.a; k < in.a + in.b; ++k) {
                const ProgramTerm& t = p.terms[k];
                bool literal = p.kind(t.value) == ValueKind::literal;
                double c = literal ? t.c * p.literal(t.value) : t.c;
                bool negative = std::signbit(c);
                std::string mag = number(std::fabs(c));
                std::string term = literal ? mag
                                   : std::fabs(c) == 1 ? at(t.value)
                                                       : mag + "*" + at(t.value);
                if (s.empty())
                    s = negative ? "-" + term : term;
                else
                    s += (negative ? " - " : " + ") + term;
            }
            return s;
        }
        case ProgramOp::add: return at(in.a) + " + " + at(in.b);
        case ProgramOp::sub: return at(in.a) + " - " + at(in.b);
        case ProgramOp::mul: return at(in.a) + "*" + at(in.b);
        case ProgramOp::div: return at(in.a) + "/" + at(in.b);
        case ProgramOp::neg: return "-" + at(in.a);
        case ProgramOp::sincos:
            throw InternalError("CodePrinter::expression(): sincos has two results");
        default: return function(in.op, at(in.a), at(in.b));
    }
}

void CodePrinter::print(std::ostream& os, const StraightLineProgram& p,
                        const std::vector<ProgramInstruction>& code, const ValueSpelling& names,
                        const std::string& indent) const {
    auto line = [&](std::uint32_t v, const std::string& rhs) {
        if (p.kind(v) == ValueKind::hoisted)
            os << indent << assign(operand(p, v, names), rhs) << '\n';
        else
            os << indent << define(operand(p, v, names), rhs) << '\n';
    };
    for (const ProgramInstruction& in : code) {
        if (in.op == ProgramOp::sincos) {
            std::string a = operand(p, in.a, names);
            line(in.result, function(ProgramOp::sin, a, a));
            line(in.b, function(ProgramOp::cos, a, a));
        } else {
            line(in.result, expression(p, in, names));
        }
    }
}

std::string CodePrinter::identifier(const std::string& name, std::set<std::string>& taken) const {
    // primes as p (qA'' -> qApp, as MotionGenesis writes them), anything else not allowed as _
    std::string s;
    for (char ch : name) {
        if (ch == '\'')
            s += 'p';
        else if (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_')
            s += ch;
        else
            s += '_';
    }
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s.front()))) s = "v" + s;
    static const std::regex numbered("z[0-9]+");
    while (reserved().count(s) || taken.count(s) || std::regex_match(s, numbered)) s += '_';
    taken.insert(s);
    return s;
}

// ---- C++ -------------------------------------------------------------------------------------

std::string CppPrinter::comment(const std::string& text) const { return "// " + text; }

std::string CppPrinter::function(ProgramOp op, const std::string& a, const std::string& b) const {
    switch (op) {
        case ProgramOp::csgn: return "double((" + a + " > 0.0) - (" + a + " < 0.0))";
        case ProgramOp::step: return CodePrinter::function(op, a, b);
        case ProgramOp::pow: return "std::pow(" + a + ", " + b + ")";
        case ProgramOp::atan2: return "std::atan2(" + a + ", " + b + ")";
        default: return "std::" + std::string(c_function(op)) + "(" + a + ")";
    }
}

const std::set<std::string>& CppPrinter::reserved() const {
    static const std::set<std::string> words = [] {
        std::set<std::string> w = c_words();
        for (const char* k :
             {"alignas", "alignof", "and", "asm", "bool", "catch", "class", "concept", "consteval",
              "constexpr", "constinit", "const_cast", "co_await", "co_return", "co_yield",
              "decltype", "delete", "dynamic_cast", "explicit", "export", "false", "friend",
              "mutable", "namespace", "new", "noexcept", "not", "nullptr", "operator", "or",
              "private", "protected", "public", "reinterpret_cast", "requires", "static_assert",
              "static_cast", "template", "this", "thread_local", "throw", "true", "try",
              "typeid", "typename", "using", "virtual", "wchar_t", "xor", "std", "Model",
              "Parameters"})
            w.insert(k);
        return w;
    }();
    return words;
}

// ---- MATLAB/Octave -----------------------------------------------------------------------------

std::string MatlabPrinter::number(double x) const {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "Inf" : "-Inf";
    return CodePrinter::number(x);
}

std::string MatlabPrinter::define(const std::string& name, const std::string& expression) const {
    return name + " = " + expression + ";";
}

std::string MatlabPrinter::assign(const std::string& place, const std::string& expression) const {
    return place + " = " + expression + ";";
}

std::string MatlabPrinter::comment(const std::string& text) const { return "% " + text; }

std::string MatlabPrinter::element(const std::string& array, std::size_t k) const {
    return array + "(" + std::to_string(k + 1) + ")";
}

std::string MatlabPrinter::function(ProgramOp op, const std::string& a,
                                    const std::string& b) const {
    switch (op) {
        case ProgramOp::pow: return a + "^" + b;
        case ProgramOp::atan2: return "atan2(" + a + ", " + b + ")";
        case ProgramOp::abs: return "abs(" + a + ")";
        case ProgramOp::csgn: return "sign(" + a + ")";
        case ProgramOp::step: return "((" + a + " > 0) + 0.5*(" + a + " == 0))";
        default: return std::string(to_string(op)) + "(" + a + ")";
    }
}

const std::set<std::string>& MatlabPrinter::reserved() const {
    static const std::set<std::string> words = {
        "break", "case", "catch", "classdef", "continue", "else", "elseif", "end", "for",
        "function", "global", "if", "otherwise", "parfor", "persistent", "return", "spmd",
        "switch", "try", "while", "ans", "pi", "i", "j", "e", "eps", "Inf", "NaN", "inf", "nan",
        "sin", "cos", "tan", "exp", "log", "sqrt", "abs", "asin", "acos", "atan", "atan2",
        "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "sign", "chol", "zeros", "ones",
        "numel", "size", "struct", "fopen", "fclose", "fprintf", "ode45", "odeset", "disp",
        "error", "t", "q", "qp", "qpp", "u", "M", "f", "y", "h", "p", "x", "xdot", "ctx", "n",
        "R", "sol", "k", "s", "fid", "reaction"};
    return words;
}

// ---- Python -------------------------------------------------------------------------------------

std::string PythonPrinter::number(double x) const {
    if (std::isnan(x)) return "math.nan";
    if (std::isinf(x)) return x > 0 ? "math.inf" : "-math.inf";
    return CodePrinter::number(x);
}

std::string PythonPrinter::define(const std::string& name, const std::string& expression) const {
    return name + " = " + expression;
}

std::string PythonPrinter::assign(const std::string& place, const std::string& expression) const {
    return place + " = " + expression;
}

std::string PythonPrinter::comment(const std::string& text) const { return "# " + text; }

std::string PythonPrinter::function(ProgramOp op, const std::string& a,
                                    const std::string& b) const {
    switch (op) {
        case ProgramOp::pow: return a + "**" + b;
        case ProgramOp::atan2: return "math.atan2(" + a + ", " + b + ")";
        case ProgramOp::abs: return "abs(" + a + ")";
        case ProgramOp::csgn: return "float((" + a + " > 0) - (" + a + " < 0))";
        case ProgramOp::step:
            return "(1.0 if " + a + " > 0 else (0.0 if " + a + " < 0 else 0.5))";
        default: return "math." + std::string(to_string(op)) + "(" + a + ")";
    }
}

const std::set<std::string>& PythonPrinter::reserved() const {
    static const std::set<std::string> words = {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
        "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
        "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise",
        "return", "try", "while", "with", "yield", "math", "np", "numpy", "self", "float",
        "abs", "len", "range", "print", "t", "q", "qp", "qpp", "u", "M", "f", "y", "h", "p",
        "x", "ctx", "n", "L", "sol", "k", "s", "reaction"};
    return words;
}

}  // namespace alembert
