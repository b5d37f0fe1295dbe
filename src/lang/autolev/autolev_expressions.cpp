// SPDX-License-Identifier: MIT
// Autolev expressions to Alembert expressions: numbers, operators, functions, and the names of
// scalars, frames, points and vectors.
#include <cstdlib>
#include <string>
#include <vector>

#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

std::string Translator::number_text(const Expr& e, const std::string& what) {
    if (e.kind == Expr::Kind::unary && e.args[0].kind == Expr::Kind::number)
        return (e.text == "-" ? "-" : "") + number_text(e.args[0], what);
    if (e.kind != Expr::Kind::number)
        fail(e.where, what + " must be a number", "give the number itself, such as 9.81");
    std::string s = e.text;
    if (s.front() == '.') s = "0" + s;
    std::size_t dot = s.find('.');
    if (dot != std::string::npos && (dot + 1 == s.size() || !std::isdigit(static_cast<unsigned char>(s[dot + 1]))))
        s.insert(dot + 1, "0");
    return s;
}

Text Translator::expr(const Expr& e) {
    switch (e.kind) {
        case Expr::Kind::number: return {number_text(e, "a number"), false, 5, true};
        case Expr::Kind::name: {
            if (!e.vector && e.primes == 0 && upper(e.text) == "T" && !find(e.text)) {
                // Autolev's time is a number (of seconds): t/t_unit with t_unit = 1 s, so that
                // SIN(T) is the sine of a number, as in Autolev
                if (time_unit_.empty()) {
                    time_unit_ = "t_unit";
                    for (int k = 2; find(time_unit_) || extra_names_.count(time_unit_); ++k)
                        time_unit_ = "t_unit" + std::to_string(k);
                    extra_names_.insert({time_unit_, 0});
                }
                return {"t/" + time_unit_, false, 2, false};
            }
            if (e.dyadic) return dyadic_name(e);
            if (const Entry* m = e.vector || e.primes ? nullptr : find(e.text); m && m->kind == Kind::matrix)
                return m->indices ? whole_array(e, *m) : Text{m->name, false, 5, false, m->rows, m->cols};
            if (!e.vector && !e.primes && !find(e.text)) {
                // A_B, the direction cosine matrix of frames A and B, as a value: element (i, j)
                // is Ai> . Bj> (its columns are B's unit vectors in A, as in A_B = [...])
                auto fr = [this](std::string_view n) { return frame_of(n); };
                if (auto s = split(std::string_view(e.text), fr, fr)) {
                    std::string m = "[";
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            m += "dot(" + s->first + "xyz"[i] + ">, " + s->second + "xyz"[j] + ">)" +
                                 (j < 2 ? ", " : i < 2 ? "; " : "]");
                    return {m, false, 5, false, 3, 3};
                }
            }
            resolved_numeric_ = false;
            Text t = e.vector ? Text{vector_name(e), true, 5} : Text{scalar_name(e), false, 5};
            t.numeric = resolved_numeric_;
            return t;
        }
        case Expr::Kind::call: return call(e);
        case Expr::Kind::index:
            if (const Entry* m = find(e.text); m && m->kind == Kind::matrix)
                return m->indices ? array_element(e, *m) : matrix_element(e, *m);
            if (upper(e.text) == "ZERO" && kane_at_) {
                // ZERO[i] of ZERO = FR() + FRSTAR(): Fr + Fr* of the i-th independent speed,
                // which is K[i] of the kane statement (its equations 0 = Fr + Fr*, in the order
                // of the speeds); the name is known when the script is assembled
                if (e.args.size() != 1 || e.args[0].kind != Expr::Kind::number ||
                    e.args[0].text.find_first_not_of("0123456789") != std::string::npos ||
                    e.args[0].text.size() > 6 || std::stoi(e.args[0].text) < 1)
                    fail(e.where, "an element of Kane's equations is ZERO[i], i a whole number from 1",
                         "write ZERO[1] for the equation of the first independent speed");
                return {"\x02[" + e.args[0].text + "]", false, 5};
            }
            if (const Entry* other = find(e.text))
                fail(e.where, "'" + e.text + "' is " + kind_word(other->kind) + ", not an array",
                     "an array is assigned by its elements first: NAME[1] = ...");
            fail(e.where, "the array '" + e.text + "' is not assigned",
                 "assign its elements before this line: " + e.text + "[1] = ...");
        case Expr::Kind::unary: {
            Text a = expr(e.args[0]);
            if (e.text == "+") return a;
            return {"-" + paren(a, 4), a.vector, 3, a.numeric, a.rows, a.cols, a.dyadic};
        }
        case Expr::Kind::binary: return binary(e);
        case Expr::Kind::matrix: return matrix_literal(e);
        case Expr::Kind::row: break;
    }
    fail(e.where, "an expression that is not translated");
}

Text Translator::binary(const Expr& e) {
    if (e.text == "=" || e.text == ":")
        fail(e.where, std::string(e.text == "=" ? "a substitution 'x = v'" : "a range 'm:n'") +
                          " stands only among the arguments of " +
                          (e.text == "=" ? "REPLACE(), EVALUATE() and TAYLOR()" : "TAYLOR()"),
             "write REPLACE(e, X = 1) or TAYLOR(e, 0:3, X = 0)");
    std::vector<const Expr*> chain;
    const Expr* x = &e;
    while (x->kind == Expr::Kind::binary) {
        chain.push_back(x);
        x = &x->args[0];
    }
    Text acc = expr(*x);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        Text b = expr((*it)->args[1]);
        bool numeric = acc.numeric && b.numeric;
        acc = combine(**it, std::move(acc), std::move(b));
        acc.numeric = numeric;
    }
    return acc;
}

Text Translator::combine(const Expr& e, Text a, Text b) {
    const std::string& op = e.text;
    if (a.dyadic || b.dyadic || (op == "*" && a.vector && b.vector)) return dyadic_combine(e, std::move(a), std::move(b));
    auto wrapped = [](Text& t, bool wrap) { return wrap ? "(" + std::move(t.s) + ")" : std::move(t.s); };
    auto size = [](const Text& t) { return std::to_string(t.rows) + " by " + std::to_string(t.cols); };
    auto known = [](const Text& t) { return t.size_known(); };
    int rows = 0, cols = 0;  // the result's size, if a matrix
    if (a.matrix() || b.matrix()) {
        if (a.vector || b.vector)
            fail(e.where, std::string("'") + op + "' between a matrix and a vector",
                 "write the vector's measures as a column [X; Y; Z]");
        if (op == "+" || op == "-") {
            if (!a.matrix() || !b.matrix())
                fail(e.where, std::string("'") + op + "' between a matrix and a scalar",
                     "add matrices of the same size; DIAGMAT(n, X) is X times the identity");
            if (known(a) && known(b) && (a.rows != b.rows || a.cols != b.cols))
                fail(e.where, std::string("'") + op + "' between a " + size(a) + " and a " + size(b) + " matrix",
                     "matrices added must have the same size");
            rows = known(a) ? a.rows : b.rows, cols = known(a) ? a.cols : b.cols;
        } else if (op == "*") {
            if (a.matrix() && b.matrix()) {
                if (known(a) && known(b) && a.cols != b.rows)
                    fail(e.where, "'*' between a " + size(a) + " and a " + size(b) + " matrix",
                         "the first's columns must match the second's rows; TRANSPOSE(M) turns rows into columns");
                rows = known(a) && known(b) ? a.rows : -1, cols = known(a) && known(b) ? b.cols : -1;
            } else {
                rows = a.matrix() ? a.rows : b.rows, cols = a.matrix() ? a.cols : b.cols;
            }
        } else if (op == "/") {
            if (b.matrix()) fail(e.where, "division by a matrix", "multiply by its inverse: A*INV(B)");
            rows = a.rows, cols = a.cols;
        } else {
            // M^k: the script's power of a square matrix (k a whole number, checked when it runs)
            if (b.matrix()) fail(e.where, "a power with a matrix as exponent", "raise a square matrix to a whole number: M^2");
            if (known(a) && a.rows != a.cols)
                fail(e.where, "a power of a " + size(a) + " matrix", "only a square matrix has powers: M^2 is M*M");
            std::string s = wrapped(a, a.prec <= 4);
            s += "^";
            s += wrapped(b, b.prec < 5);
            return {std::move(s), false, 4, false, a.rows, a.cols};
        }
    }
    if (op == "+" || op == "-") {
        if (a.vector != b.vector)
            fail(e.where, std::string("'") + op + "' between a vector and a scalar",
                 "both sides must be vectors (with '>') or both scalars");
        // a sign on the right needs brackets (a + (-b)), and so does a sum after '-'
        bool wrap = b.prec == 3 || (op == "-" && b.prec <= 1);
        std::string s = std::move(a.s);
        s += " " + op + " ";
        s += wrapped(b, wrap);
        return {std::move(s), a.vector, 1, false, rows, cols};
    }
    if (op == "*" || op == "/") {
        if (op == "/" && b.vector) fail(e.where, "division by a vector", "divide by a scalar such as MAG(v>)");
        bool vector = a.vector || b.vector;
        std::string s = wrapped(a, a.prec < 2);
        s += op;
        s += wrapped(b, b.prec <= 3);
        return {std::move(s), vector, 2, false, rows, cols};
    }
    // ^
    if (a.vector || b.vector) fail(e.where, "a power of a vector", "use DOT(v>, v>) for the square of a magnitude");
    std::string s = wrapped(a, a.prec <= 4);
    s += "^";
    s += wrapped(b, b.prec < 5);
    return {std::move(s), false, 4};
}

namespace {

// Numbers joined by signs and + - * / ^ alone: no name, not even PI (a worklist, not recursion).
bool only_numbers(const Expr& e) {
    std::vector<const Expr*> work{&e};
    while (!work.empty()) {
        const Expr* x = work.back();
        work.pop_back();
        if (x->kind == Expr::Kind::number) continue;
        if (x->kind != Expr::Kind::unary && x->kind != Expr::Kind::binary) return false;
        if (x->kind == Expr::Kind::binary && x->text != "+" && x->text != "-" && x->text != "*" && x->text != "/" &&
            x->text != "^")
            return false;
        for (const Expr& a : x->args) work.push_back(&a);
    }
    return true;
}

bool is_zero_number(const Expr& e) {
    return e.kind == Expr::Kind::number && std::strtod(e.text.c_str(), nullptr) == 0.0;
}

}  // namespace

// Autolev reads an angle given by numbers alone in degrees unless the file says DEGREES OFF
// (SIMPROT(N, A, 3, 30) turns A by 30 degrees, SIN(30) is 1/2); an angle holding a name (Q1,
// PI/6) is in radians. The script reads every angle without a unit as radians, so such an
// angle is written times pi/180, and a note says so at its column.
Text Translator::angle(const Expr& e, Text t, const std::string& where_used) {
    if (!degrees_ || is_zero_number(e) || !only_numbers(e)) return t;
    Text d{paren(t, 2) + "*pi/180", false, 2, true};
    report(Severity::note, e.where,
           "the angle " + t.s + " of " + where_used +
               " is written with numbers alone, so Autolev reads it in degrees (DEGREES ON, its default): "
               "translated as " + d.s,
           "write DEGREES OFF before it if the file's numbers are radians");
    return d;
}

// ASIN(0.5) is 30 under DEGREES ON: a number of degrees, which Autolev then reads in degrees
// again where it stands as an angle, while a name holding it is in radians. The script's angles
// are radians throughout, so this is refused rather than given a meaning Autolev does not have.
void Translator::number_of_degrees_refused(const Expr& e, const std::string& f) {
    if (!degrees_ || e.args.size() != 1 || !only_numbers(e.args[0])) return;
    fail(e.where,
         f + "() of a number is an angle in degrees under DEGREES ON (Autolev's default), which the script "
             "has no counterpart for: its angles are radians",
         "write DEGREES OFF at the top of the file (the angle is then radians), or write the angle itself");
}

Text Translator::call(const Expr& e) {
    bool numeric = true;  // every argument numeric (each translated once)
    Text t = call_text(e, numeric);
    t.numeric = numeric;
    return t;
}

Text Translator::call_text(const Expr& e, bool& numeric) {
    std::string f = upper(e.text);
    auto args = [&](std::size_t lo, std::size_t hi) {
        if (e.args.size() < lo || e.args.size() > hi)
            fail(e.where,
                 e.text + "() takes " +
                     (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                     " arguments, not " + std::to_string(e.args.size()));
    };
    auto scalar_arg = [&](std::size_t i) {
        Text t = expr(e.args[i]);
        numeric = numeric && t.numeric;
        if (t.vector)
            fail(e.args[i].where, e.text + "() takes a scalar here, not a vector", "take a measure: DOT(v>, N1>)");
        if (t.matrix())
            fail(e.args[i].where, e.text + "() takes a scalar here, not a matrix", "take an element: M[i, j]");
        if (t.dyadic) not_a_dyadic(e.args[i], "a scalar");
        return t;
    };
    auto vector_arg = [&](std::size_t i) {
        Text t = expr(e.args[i]);
        numeric = numeric && t.numeric;
        if (!t.vector) fail(e.args[i].where, e.text + "() takes a vector here (a name ending in '>')");
        return t;
    };
    static const std::map<std::string, std::string> elementary{
        {"SIN", "sin"},   {"COS", "cos"},   {"TAN", "tan"}, {"ASIN", "asin"}, {"ACOS", "acos"},
        {"ATAN", "atan"}, {"SQRT", "sqrt"}, {"EXP", "exp"}, {"LOG", "log"},   {"ABS", "abs"},
        {"LN", "log"}};
    if (auto it = elementary.find(f); it != elementary.end()) {
        args(1, 1);
        if (f == "SIN" || f == "COS" || f == "TAN") {
            Text a = angle(e.args[0], scalar_arg(0), e.text + "()");
            return {it->second + "(" + a.s + ")", false, 5};
        }
        if (f == "ASIN" || f == "ACOS" || f == "ATAN") number_of_degrees_refused(e, f);
        return {it->second + "(" + scalar_arg(0).s + ")", false, 5};
    }
    if (f == "DOT") {
        args(2, 2);
        Text a = expr(e.args[0]), b = expr(e.args[1]);
        numeric = numeric && a.numeric && b.numeric;
        if (a.dyadic || b.dyadic) return dyadic_dot(e, a, b);
        for (std::size_t i = 0; i < 2; ++i)
            if (!(i ? b : a).vector) fail(e.args[i].where, e.text + "() takes a vector here (a name ending in '>')");
        return {"dot(" + a.s + ", " + b.s + ")", false, 5};
    }
    if (f == "CROSS") {
        args(2, 2);
        return {"cross(" + vector_arg(0).s + ", " + vector_arg(1).s + ")", true, 5};
    }
    if (f == "MAG") {
        args(1, 1);
        return {"mag(" + vector_arg(0).s + ")", false, 5};
    }
    if (f == "UNITVEC") {
        args(1, 1);
        return {"unit(" + vector_arg(0).s + ")", true, 5};
    }
    if (f == "EXPRESS") {
        args(2, 2);
        Text v = expr(e.args[0]);
        numeric = v.numeric;
        if (v.dyadic) return {"express(" + v.s + ", " + frame_name(e.args[1]) + ")", false, 5, false, 0, 0, true};
        if (!v.vector) return v;  // a scalar is the same in every frame
        return {"express(" + v.s + ", " + frame_name(e.args[1]) + ")", true, 5};
    }
    if (f == "DT") {
        args(1, 2);
        Text v = expr(e.args[0]);
        numeric = v.numeric;
        if (v.dyadic) {
            if (e.args.size() != 2)
                fail(e.where, "DT of a dyadic needs the frame: DT(D>>, N)",
                     "a dyadic's rate depends on the frame it is taken in, as a vector's does");
            return {"dt(" + v.s + ", " + frame_name(e.args[1]) + ")", false, 5, false, 0, 0, true};
        }
        if (v.matrix()) {
            // the script's dt takes scalars: the matrix of its elements' rates
            if (e.args.size() == 2) fail(e.args[1].where, "DT of a matrix takes no frame", "write DT(M)");
            if (!v.size_known())
                fail(e.args[0].where, "DT of a matrix whose size is known only when the script runs is not translated",
                     "assign the matrix to a name with its elements written out first");
            std::string m = "[";
            for (int i = 1; i <= v.rows; ++i)
                for (int j = 1; j <= v.cols; ++j)
                    m += "dt(element(" + v.s + ", " + std::to_string(i) + ", " + std::to_string(j) + "))" +
                         (j < v.cols ? ", " : i < v.rows ? "; " : "]");
            return {m, false, 5, false, v.rows, v.cols};
        }
        if (v.vector) {
            if (e.args.size() != 2) fail(e.where, "DT of a vector needs the frame: DT(v>, N)");
            return {"dt(" + v.s + ", " + frame_name(e.args[1]) + ")", true, 5};
        }
        if (e.args.size() == 2) fail(e.args[1].where, "DT of a scalar takes no frame", "write DT(s)");
        return {"dt(" + v.s + ")", false, 5};
    }
    if (f == "EXPAND") {
        if (e.args.size() != 1)
            fail(e.where, "EXPAND() with a range of terms is not translated",
                 "Alembert's expand() keeps every term: write EXPAND(e)");
        Text v = expr(e.args[0]);
        numeric = v.numeric;
        return {"expand(" + v.s + ")", v.vector, 5, false, 0, 0, v.dyadic};
    }
    if (f == "EXPLICIT" || f == "ARRANGE") {
        // the same value, printed another way: EXPLICIT writes intermediates out, ARRANGE
        // collects terms; Alembert prints its own way
        if (f == "EXPLICIT" ? e.args.size() != 1 : e.args.empty())
            fail(e.where, e.text + "() takes " + (f == "EXPLICIT" ? "one argument" : "the expression first"));
        Text v = expr(e.args[0]);
        numeric = v.numeric;
        return v;
    }
    if (f == "D") {
        // the partial derivative by a constant, variable (or one of its derivatives) or
        // specified quantity
        args(2, 2);
        Text v = expr(e.args[0]);
        if (v.vector)
            fail(e.args[0].where, "D() of a vector is not translated",
                 "take its measures first: D(DOT(v>, N1>), Q1)");
        const Expr& x = e.args[1];
        const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
        if (x.kind == Expr::Kind::name && !x.vector && upper(x.text) == "T" && !en)
            fail(x.where, "D() by time is not translated", "write DT(e) for the time derivative");
        if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
            fail(x.where, "D() differentiates by a constant, variable or specified quantity",
                 "write D(e, Q1) or D(e, U1)");
        // a speed written as a rate (U1 is Q1') is differentiated by that rate, as it is the same
        numeric = false;
        return {"diff(" + v.s + ", " + scalar(x).s + ")", false, 5};
    }
    if (f == "RHS") {
        // the right side of X = ...: the value of X itself
        args(1, 1);
        const Expr& x = e.args[0];
        const Entry* en = x.kind == Expr::Kind::name && x.primes == 0 ? find(x.text) : nullptr;
        if (!en || (en->kind != Kind::scalar && en->kind != Kind::vector && en->kind != Kind::dyadic))
            fail(x.where, "RHS() is translated for a name the file assigns (X = ..., V> = ...)",
                 "RHS of an equation other than an assignment has no counterpart; write the expression");
        Text v = expr(x);
        numeric = v.numeric;
        return v;
    }
    if (f == "COEF") {
        // the coefficient of X (or X^n) in a polynomial in X
        args(2, 2);
        Text v = scalar_arg(0), x = scalar_arg(1);
        numeric = false;
        return {"coef(" + v.s + ", " + x.s + ")", false, 5};
    }
    if (f == "REPLACE" || f == "EVALUATE") {
        // substitutions inside an expression: replace(e, x = v, ...)
        if (e.args.size() < 2)
            fail(e.where, e.text + "() without substitutions is not translated: the script keeps constants as "
                                   "symbols and gives numbers with the statement 'evaluate e at x = v'",
                 "write " + e.text + "(e, X = 1, ...)");
        Text v = expr(e.args[0]);
        std::string s = "replace(" + v.s;
        for (std::size_t i = 1; i < e.args.size(); ++i) s += ", " + substitution(e.args[i], e.text);
        numeric = false;
        return {s + ")", v.vector, 5, false, 0, 0, v.dyadic};
    }
    if (f == "TAYLOR") {
        // TAYLOR(e, m:n, X = X0, ...): the terms of orders m to n of the Taylor polynomial,
        // taylor(e, X = X0, n) less taylor(e, X = X0, m - 1)
        if (e.args.size() < 3)
            fail(e.where, "TAYLOR() takes the expression, the orders and at least one X = X0",
                 "write TAYLOR(e, 0:3, X = 0)");
        Text v = expr(e.args[0]);
        const Expr& r = e.args[1];
        auto order = [&](const Expr& x) {
            if (x.kind != Expr::Kind::number || x.text.find_first_not_of("0123456789") != std::string::npos ||
                x.text.size() > 2)
                fail(x.where, "the orders of TAYLOR() must be whole numbers", "write TAYLOR(e, 0:3, X = 0)");
            return std::stoi(x.text);
        };
        int lo = 0, hi = 0;
        if (r.kind == Expr::Kind::binary && r.text == ":") lo = order(r.args[0]), hi = order(r.args[1]);
        else hi = order(r);
        if (lo > hi) fail(r.where, "the orders of TAYLOR() run from the lower to the higher", "write TAYLOR(e, 0:3, X = 0)");
        std::string at;
        for (std::size_t i = 2; i < e.args.size(); ++i) at += ", " + substitution(e.args[i], e.text);
        numeric = false;
        std::string s = "taylor(" + v.s + at + ", " + std::to_string(hi) + ")";
        if (lo == 0) return {s, v.vector, 5, false, 0, 0, v.dyadic};
        return {"(" + s + " - taylor(" + v.s + at + ", " + std::to_string(lo - 1) + "))", v.vector, 5, false, 0, 0, v.dyadic};
    }
    if (f == "FLOOR") {
        args(1, 1);
        return {"floor(" + scalar_arg(0).s + ")", false, 5};
    }
    if (f == "FACTOR" && e.args.size() == 1) {
        Text v = scalar_arg(0);
        return {"factor(" + v.s + ")", false, 5};
    }
    if (auto m = dyadic_call(e, f, numeric)) return *m;
    if (auto m = matrix_call(e, f, numeric)) return *m;
    if (auto t = term_call(e, f, numeric)) return *t;
    if (f == "SOLVE")
        fail(e.where, "SOLVE() is translated as a statement of its own: SOLVE(M, X1, X2) alone on its line",
             "solve first, then use X1 and X2 in the expressions after it");
    static const std::map<std::string, std::string> missing{
        {"FACTOR", "FACTOR(e) is factor(e); Alembert takes no factor chosen by name (FACTOR(e, X))"},
        {"NICHECK", "the translation has no nonholonomic checks"},
        {"SQR", "whether it is read as the square or the square root differs between Autolev's dialects; "
                "write X^2 or SQRT(X)"},
        {"CEIL", "the script has floor() only: write -FLOOR(-X)"},
        {"ROUND", "the script has floor() only: write FLOOR(X + 0.5)"},
        {"INT", "the script has floor() only: the whole part of X >= 0 is FLOOR(X)"},
        {"SIGN", "the script has no sign function: write X/ABS(X) where X is not 0"},
        {"LOG10", "the script's log is the natural one: write LN(X)/LN(10)"},
        {"FACTORIAL", "the script has no factorial: write the product of the numbers"},
        {"PARTIALS", "the translation forms partial velocities inside Kane's equations only: write D(v>, U) "
                     "measure by measure (D(DOT(v>, N1>), U))"},
        {"SPLINE", "the script has no tables of numbers read from files"},
        {"MOMENTUM", "write the sum of the bodies' and particles' momenta: M*V_P_N> (linear), "
                     "DOT(I_B_BO>>, W_B_N>) + CROSS(P_O_BO>, MB*V_BO_N>) (angular about O)"},
        {"KE", "write the sum of the kinetic energies: M*DOT(V_P_N>, V_P_N>)/2 + DOT(W_B_N>, DOT(I_B_BO>>, W_B_N>))/2"}};
    if (auto it = missing.find(f); it != missing.end())
        leave_out(e.where, "the Autolev function " + f + "() has no translation: " + it->second,
                  "docs/autolev.md lists each Autolev function with its translation or the reason it has none");
    if (f == "FR" || f == "FRSTAR")
        fail(e.where, e.text + "() is translated only in ZERO = FR() + FRSTAR()",
             "write ZERO = FR() + FRSTAR() and then KANE()");
    fail(e.where, "the Autolev function '" + e.text + "' is not translated",
         "the translator knows SIN, COS, TAN, ASIN, ACOS, ATAN, SQRT, EXP, LOG, ABS, DOT, CROSS, MAG, "
         "UNITVEC, EXPRESS, DT, D, EXPAND, EXPLICIT, ARRANGE, RHS, COEF, REPLACE, EVALUATE, TAYLOR, FLOOR, "
         "FACTOR, SOLVE, TRANSPOSE, INV, DET, DIAGMAT, ELEMENT, ROWS, COLS, EIG, POLYNOMIAL, ROOTS, MASS, CM, "
         "ANGVEL, EXCLUDE, INCLUDE, MATRIX, VECTOR and INERTIA");
}

Text Translator::matrix_element(const Expr& e, const Entry& m) {
    std::vector<int> at;
    for (const Expr& a : e.args) {
        if (a.kind != Expr::Kind::number || a.text.find_first_not_of("0123456789") != std::string::npos ||
            a.text.size() > 6)
            fail(a.where, "the index of matrix '" + e.text + "' must be a whole number",
                 "write " + e.text + "[1, 2]");
        at.push_back(std::stoi(a.text));
    }
    if (at.size() == 1 && (m.rows == 1 || m.cols == 1)) at = m.rows == 1 ? std::vector<int>{1, at[0]} : std::vector<int>{at[0], 1};
    // a size known when the script runs (-1) is checked there
    auto count = [](int n) { return n > 0 ? std::to_string(n) : std::string("n"); };
    const std::string size = count(m.rows) + " by " + count(m.cols);
    if (at.size() != 2)
        fail(e.where, "matrix '" + e.text + "' is " + size + ": give its row and column", "write " + e.text + "[i, j]");
    if (at[0] < 1 || at[1] < 1 || (m.rows > 0 && at[0] > m.rows) || (m.cols > 0 && at[1] > m.cols))
        fail(e.where, "[" + std::to_string(at[0]) + ", " + std::to_string(at[1]) + "] is outside matrix '" + e.text +
                          "', which is " + size,
             "rows run from 1 to " + count(m.rows) + " and columns from 1 to " + count(m.cols));
    return {m.name + "[" + std::to_string(at[0]) + ", " + std::to_string(at[1]) + "]", false, 5, false};
}

std::string Translator::scalar_name(const Expr& e) {
    const Entry* en = find(e.text);
    std::string primes(static_cast<std::size_t>(e.primes), '\'');
    if (!en) {
        std::string key = upper(e.text);
        if (key == "T") return "t" + primes;
        if (key == "PI" && e.primes == 0) {
            resolved_numeric_ = true;
            return "pi";
        }
        fail(e.where, "'" + e.text + "' is not declared",
             "declare it (CONSTANTS, VARIABLES, ...) or assign it before this line");
    }
    if (!solved_.empty())
        if (auto sv = solved_.find(en->name + primes); sv != solved_.end()) {
            // a symbol SOLVE assigned is its solution from there on
            resolved_numeric_ = false;
            return sv->second;
        }
    switch (en->kind) {
        case Kind::constant:
        case Kind::scalar:
            resolved_numeric_ = en->numeric;
            if (e.primes && en->kind == Kind::scalar) {
                // Z' of a named expression is its time derivative
                std::string d = en->name;
                for (int k = 0; k < e.primes; ++k) d = "dt(" + d + ")";
                resolved_numeric_ = false;
                return d;
            }
            if (e.primes) fail(e.where, "'" + e.text + "' is " + kind_word(en->kind) + "; it has no derivative",
                               "declare it with VARIABLES to give it derivatives");
            return en->name;
        case Kind::variable:
        case Kind::specified: {
            if (auto r = rate_of_.find(en->name); r != rate_of_.end()) {
                int& p = used_primes_[r->second];
                p = std::max(p, e.primes + 1);
                return r->second + primes + "'";
            }
            if (en->kind == Kind::variable) {
                int& p = used_primes_[en->name];
                p = std::max(p, e.primes);
            }
            return en->name + primes;
        }
        case Kind::matrix:
            fail(e.where, "the matrix '" + e.text + "' stands where a scalar is expected",
                 "take an element: " + e.text + "[i, j]");
        default:
            fail(e.where, "'" + e.text + "' is " + kind_word(en->kind) + ", not a value",
                 "a vector needs '>' (A1>, V_P_N>); points and frames are arguments of V2PTS, SIMPROT, ...");
    }
}

std::string Translator::substitution(const Expr& e, const std::string& f) {
    if (e.kind != Expr::Kind::binary || e.text != "=")
        fail(e.where, f + "() takes substitutions X = v after the expression", "write " + f + "(e, X = 1)");
    const Expr& x = e.args[0];
    const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
    if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
        fail(x.where, f + "() substitutes for a constant, variable or specified quantity",
             "write " + f + "(e, Q1 = 0) or " + f + "(e, U1 = 0)");
    return scalar(x).s + " = " + scalar(e.args[1]).s;
}

std::string Translator::fresh_name(const std::string& base) {
    std::string n = base;
    for (int k = 2; find(n) || find_object(n) || extra_names_.count(n) || is_reserved(n); ++k)
        n = base + "_" + std::to_string(k);
    extra_names_.insert({n, 0});
    return n;
}

std::string Translator::frame_name(const Expr& e) {
    if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0)
        if (auto f = frame_of(e.text)) return *f;
    fail(e.where, "expected a frame or body here", "name a frame declared with NEWTONIAN, FRAMES or BODIES");
}

std::string Translator::point_name(const Expr& e) {
    if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0)
        if (auto p = point_of(e.text)) return *p;
    std::string hint = "name a point declared with POINTS or PARTICLES";
    if (e.kind == Expr::Kind::name) {
        const Entry* en = find_object(e.text);
        if (en && en->kind == Kind::body)
            hint = "a body is not a point: its mass centre is " + e.text + "O";
    }
    fail(e.where, "expected a point here", hint);
}

std::string Translator::body_name(const Expr& e) {
    if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0) {
        const Entry* en = find_object(e.text);
        if (en && en->kind == Kind::body) return en->name;
    }
    fail(e.where, "expected a body here", "name a body declared with BODIES");
}

std::string Translator::vector_name(const Expr& e) {
    if (e.primes) fail(e.where, "a prime on a vector name", "write DT(v>, N) for the derivative of a vector");
    if (e.text == "0") {
        resolved_numeric_ = true;
        return "0>";
    }
    if (const Entry* en = find(e.text); en && en->kind == Kind::vector) {
        resolved_numeric_ = en->numeric;
        return en->name + ">";
    }
    std::string key = upper(e.text);
    char last = key.back();
    if (last >= '1' && last <= '3')
        if (auto f = frame_of(std::string_view(e.text).substr(0, e.text.size() - 1))) {
            resolved_numeric_ = true;
            return *f + std::string(1, "xyz"[last - '1']) + ">";
        }
    auto pt = [this](std::string_view n) { return point_of(n); };
    auto fr = [this](std::string_view n) { return frame_of(n); };
    std::string_view rest(e.text);
    if (key.rfind("P_", 0) == 0)
        if (auto s = split(rest.substr(2), pt, pt)) return "pos(" + s->second + ", " + s->first + ")";
    if (key.rfind("V_", 0) == 0)
        if (auto s = split(rest.substr(2), pt, fr)) return "vel(" + s->first + ", " + s->second + ")";
    if (key.rfind("A_", 0) == 0)
        if (auto s = split(rest.substr(2), pt, fr)) return "acc(" + s->first + ", " + s->second + ")";
    if (key.rfind("W_", 0) == 0)
        if (auto s = split(rest.substr(2), fr, fr)) return "angvel(" + s->first + ", " + s->second + ")";
    if (key.rfind("ALF_", 0) == 0)
        if (auto s = split(rest.substr(4), fr, fr)) return "angacc(" + s->first + ", " + s->second + ")";
    fail(e.where, "the vector '" + e.text + ">' is not defined",
         "unit vectors are a frame's name and 1, 2 or 3 (N1>); P_O_P>, V_P_N>, W_B_N> need declared "
         "points and frames; other vectors must be assigned before they are used");
}

}  // namespace alembert::lang::autolev
