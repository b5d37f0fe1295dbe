// SPDX-License-Identifier: MIT
// Autolev matrices, polynomials and mass functions to the script's: TRANSPOSE, INV, DET,
// DIAGMAT, ELEMENT, ROWS, COLS, EIG, POLYNOMIAL, ROOTS, MASS, CM and ANGVEL, each with the size
// of the matrix it gives, so that sums and products of matrices are checked here.
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

int Translator::whole_number(const Expr& e, const std::string& what) {
    if (e.kind != Expr::Kind::number || e.text.find_first_not_of("0123456789") != std::string::npos || e.text.size() > 3 ||
        std::stoi(e.text) < 1)
        fail(e.where, what + " must be a whole number from 1 to 999 written in the file", "write it as a number, such as 2");
    return std::stoi(e.text);
}

Text Translator::matrix_literal(const Expr& m) {
    std::vector<std::vector<std::string>> cells;
    const std::size_t cols = m.args.empty() ? 0 : m.args.front().args.size();
    for (const Expr& row : m.args) {
        if (row.args.size() != cols)
            fail(row.where, "the rows of the matrix have different lengths", "give every row " + std::to_string(cols) + " elements");
        cells.emplace_back();
        for (const Expr& c : row.args) cells.back().push_back(scalar(c).s);
    }
    if (cells.empty() || cols == 0) fail(m.where, "an empty matrix", "give its elements: [a, b; c, d]");
    const int rows = static_cast<int>(cells.size());
    // [a, b] alone is a list in the script; a row matrix is the transpose of a column
    if (rows == 1 && cols > 1) return {"transpose([" + join(cells.front(), "; ") + "])", false, 5, false, 1, static_cast<int>(cols)};
    std::vector<std::string> lines;
    for (const auto& r : cells) lines.push_back(join(r));
    return {"[" + join(lines, "; ") + "]", false, 5, false, rows, static_cast<int>(cols)};
}

std::optional<Text> Translator::matrix_call(const Expr& e, const std::string& f, bool& numeric) {
    static const std::set<std::string> known{"TRANSPOSE", "INV", "DET", "DIAGMAT", "ELEMENT", "ROWS", "COLS",
                                             "EIG", "POLYNOMIAL", "ROOTS", "MASS", "CM", "ANGVEL"};
    if (!known.count(f)) return std::nullopt;
    const auto& a = e.args;
    auto count = [&](std::size_t lo, std::size_t hi, const std::string& form) {
        if (a.size() < lo || a.size() > hi)
            fail(e.where,
                 e.text + "() takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                     " argument" + (hi == 1 ? "" : "s") + ", not " + std::to_string(a.size()),
                 "write " + form);
    };
    auto matrix_arg = [&](std::size_t i) {
        Text t = expr(a[i]);
        numeric = numeric && t.numeric;
        if (!t.matrix())
            fail(a[i].where, e.text + "() takes a matrix here, not a " + (t.vector ? "vector" : "scalar"),
                 "give a matrix: a name assigned [a, b; c, d], or [a, b; c, d] itself");
        return t;
    };
    auto square = [&](const Text& m) {
        if (m.size_known() && m.rows != m.cols)
            fail(a[0].where, e.text + "() takes a square matrix, and this is " + std::to_string(m.rows) + " by " +
                                 std::to_string(m.cols), "give as many rows as columns");
    };

    if (f == "TRANSPOSE") {
        count(1, 1, "TRANSPOSE(M)");
        Text m = matrix_arg(0);
        return Text{"transpose(" + m.s + ")", false, 5, false, m.cols, m.rows};
    }
    if (f == "INV" || f == "DET") {
        count(1, 1, e.text + "(M)");
        Text m = matrix_arg(0);
        square(m);
        numeric = false;
        if (f == "DET") return Text{"det(" + m.s + ")", false, 5};
        return Text{"inv(" + m.s + ")", false, 5, false, m.rows, m.cols};
    }
    if (f == "DIAGMAT") {
        // DIAGMAT(n, X): X times the n by n identity; DIAGMAT(n, m, X): n by m
        count(2, 3, "DIAGMAT(3, X) or DIAGMAT(2, 3, X)");
        const int n = whole_number(a[0], "the number of rows of DIAGMAT()");
        const int m = a.size() == 3 ? whole_number(a[1], "the number of columns of DIAGMAT()") : n;
        Text x = scalar(a.back());
        numeric = numeric && x.numeric;
        std::string s = "diagmat(" + std::to_string(n) + (a.size() == 3 ? ", " + std::to_string(m) : "") + ", " + x.s + ")";
        return Text{s, false, 5, false, n, m};
    }
    if (f == "ELEMENT") {
        count(3, 3, "ELEMENT(M, i, j)");
        Text m = matrix_arg(0);
        const int i = whole_number(a[1], "the row of ELEMENT()"), j = whole_number(a[2], "the column of ELEMENT()");
        if ((m.rows > 0 && i > m.rows) || (m.cols > 0 && j > m.cols))
            fail(e.where, "[" + std::to_string(i) + ", " + std::to_string(j) + "] is outside the " + std::to_string(m.rows) +
                              " by " + std::to_string(m.cols) + " matrix",
                 "rows run from 1 to " + std::to_string(m.rows) + " and columns from 1 to " + std::to_string(m.cols));
        return Text{"element(" + m.s + ", " + std::to_string(i) + ", " + std::to_string(j) + ")", false, 5, m.numeric};
    }
    if (f == "ROWS" || f == "COLS") {
        // ROWS(M): how many; ROWS(M, i), ROWS(M, i:j), ROWS(M, i, j, ...): those rows
        const bool by_row = f == "ROWS";
        if (a.empty()) count(1, 1, e.text + "(M)");
        Text m = matrix_arg(0);
        if (a.size() == 1) {
            numeric = true;
            return Text{(by_row ? "rows(" : "cols(") + m.s + ")", false, 5, true};
        }
        const int n = by_row ? m.rows : m.cols;
        const std::string what = std::string("the ") + (by_row ? "row" : "column") + " of " + e.text + "()";
        std::vector<int> picked;
        for (std::size_t k = 1; k < a.size(); ++k) {
            if (a[k].kind == Expr::Kind::binary && a[k].text == ":") {
                const int lo = whole_number(a[k].args[0], what), hi = whole_number(a[k].args[1], what);
                if (lo > hi) fail(a[k].where, "a range of " + e.text + "() runs from the lower to the higher", "write 1:2");
                for (int x = lo; x <= hi; ++x) picked.push_back(x);
            } else {
                picked.push_back(whole_number(a[k], what));
            }
            if (n > 0 && picked.back() > n)
                fail(a[k].where, std::string(by_row ? "row " : "column ") + std::to_string(picked.back()) +
                                     " is outside the " + std::to_string(m.rows) + " by " + std::to_string(m.cols) + " matrix",
                     "count from 1 to " + std::to_string(n));
        }
        std::string s = (by_row ? "rows(" : "cols(") + m.s;
        for (int x : picked) s += ", " + std::to_string(x);
        const int k = static_cast<int>(picked.size());
        return Text{s + ")", false, 5, false, by_row ? k : m.rows, by_row ? m.cols : k};
    }
    if (f == "EIG") {
        if (a.size() > 1)
            fail(e.where, "EIG() with names for the eigenvalues and eigenvectors is translated as a statement of its "
                          "own: EIG(M, VALUES, VECTORS) alone on its line",
                 "write EIG(M, VALUES, VECTORS), then use VALUES and VECTORS; VALUES = EIG(M) gives the eigenvalues");
        count(1, 1, "EIG(M)");
        Text m = matrix_arg(0);
        square(m);
        return Text{"eig(" + m.s + ")", false, 5, false, m.rows, 1};
    }
    if (f == "POLYNOMIAL") {
        // POLYNOMIAL([C1, C2, C3], X) = C1*X^2 + C2*X + C3; POLYNOMIAL(P, X): P's coefficients,
        // highest power first, as a row (as long as P's degree, known when the script runs)
        count(2, 2, "POLYNOMIAL([1, -3, 2], X) or POLYNOMIAL(P, X)");
        Text c = expr(a[0]);
        if (c.vector)
            fail(a[0].where, "POLYNOMIAL() takes a polynomial or a row or column of coefficients, not a vector",
                 "take a measure first: POLYNOMIAL(DOT(V>, N1>), X)");
        if (c.size_known() && c.rows != 1 && c.cols != 1)
            fail(a[0].where, "POLYNOMIAL() takes a row or column of coefficients, highest power first, and this is " +
                                 std::to_string(c.rows) + " by " + std::to_string(c.cols),
                 "write POLYNOMIAL([C1, C2, C3], X), or POLYNOMIAL(P, X) for the coefficients of P");
        const Expr& x = a[1];
        const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
        if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
            fail(x.where, "POLYNOMIAL() takes a constant, variable or specified quantity as its variable",
                 "write POLYNOMIAL([1, -3, 2], X)");
        numeric = false;
        const std::string s = "polynomial(" + c.s + ", " + scalar(x).s + ")";
        if (c.matrix()) return Text{s, false, 5};
        return Text{s, false, 5, false, 1, -1};
    }
    if (f == "ROOTS") {
        // ROOTS(P, X): the real roots of a polynomial of numbers; ROOTS([C1, C2, C3])
        count(1, 2, "ROOTS(P, X) or ROOTS([1, -3, 2])");
        numeric = false;
        if (a.size() == 1) {
            Text c = expr(a[0]);
            if (!c.matrix() || (c.size_known() && c.rows != 1 && c.cols != 1))
                fail(a[0].where, "ROOTS() with one argument takes a row or column of coefficients, highest power first",
                     "write ROOTS([1, -3, 2]) or ROOTS(P, X)");
            const int n = c.size_known() ? std::max(c.rows, c.cols) - 1 : -1;
            return Text{"roots(" + c.s + ")", false, 5, false, n, 1};
        }
        Text p = scalar(a[0]);
        const Expr& x = a[1];
        const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
        if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
            fail(x.where, "ROOTS() takes a constant, variable or specified quantity as its variable", "write ROOTS(P, X)");
        // as many roots as the degree, known when the script runs
        return Text{"roots(" + p.s + ", " + scalar(x).s + ")", false, 5, false, -1, 1};
    }
    auto object = [&](const Expr& x) {
        const Entry* en = x.kind == Expr::Kind::name && !x.vector && x.primes == 0 ? find_object(x.text) : nullptr;
        if (!en || (en->kind != Kind::body && en->kind != Kind::particle))
            fail(x.where, e.text + "() takes bodies and particles here", "name a body declared with BODIES or PARTICLES");
        return en->name;
    };
    numeric = false;
    if (f == "MASS") {
        // MASS(A, B): the sum of their masses; MASS(): of every body and particle
        std::string s = "mass(";
        for (std::size_t k = 0; k < a.size(); ++k) s += (k ? ", " : "") + object(a[k]);
        return Text{s + ")", false, 5};
    }
    if (f == "CM") {
        // CM(O): the position of the mass centre of every body and particle from O; CM(O, A, B)
        if (a.empty()) count(1, 1, "CM(O) or CM(O, A, B)");
        std::string s = "cm(" + point_name(a[0]);
        for (std::size_t k = 1; k < a.size(); ++k) s += ", " + object(a[k]);
        return Text{s + ")", true, 5};
    }
    // ANGVEL(A, B): the angular velocity of B in A
    count(2, 2, "ANGVEL(A, B), B's angular velocity in A");
    return Text{"angvel(" + frame_name(a[1]) + ", " + frame_name(a[0]) + ")", true, 5};
}

}  // namespace alembert::lang::autolev
