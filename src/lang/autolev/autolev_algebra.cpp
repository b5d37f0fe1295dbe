// SPDX-License-Identifier: MIT
// Autolev's choice of terms and eigenvectors to the script's: EXCLUDE(E, X, ...) and
// INCLUDE(E, X, ...) to exclude() and include(), and the statement EIG(M, VALUES, VECTORS) to
// two assignments, VALUES = eig(M) and VECTORS = eigvec(M).
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

std::optional<Text> Translator::term_call(const Expr& e, const std::string& f, bool& numeric) {
    if (f != "EXCLUDE" && f != "INCLUDE") return std::nullopt;
    // the terms of the expanded E that hold none (EXCLUDE) or some (INCLUDE) of the symbols
    const std::string form = f + "(E, X) or " + f + "(E, X, Y)";
    if (e.args.size() < 2) fail(e.where, e.text + "() takes the expression and at least one symbol", "write " + form);
    Text v = expr(e.args[0]);
    std::string s = (f == "EXCLUDE" ? "exclude(" : "include(") + v.s;
    for (std::size_t i = 1; i < e.args.size(); ++i) {
        const Expr& x = e.args[i];
        const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
        if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
            fail(x.where, e.text + "() takes constants, variables or specified quantities after the expression",
                 "write " + form);
        const std::string key = en->name + std::string(static_cast<std::size_t>(x.primes), '\'');
        if (solved_.count(key))
            fail(x.where, "'" + x.text + "' stands for its solution after SOLVE, so it is no symbol to choose terms by",
                 "choose the terms before SOLVE, or by the symbols of the solution");
        s += ", " + scalar(x).s;
    }
    numeric = false;
    return Text{s + ")", v.vector, 5, false, v.rows, v.cols};
}

void Translator::eig_statement(const Expr& e) {
    if (e.args.size() != 2 && e.args.size() != 3)
        fail(e.where, "EIG() as a statement takes the matrix and the names of its eigenvalues (and eigenvectors)",
             "write EIG(M, VALUES) or EIG(M, VALUES, VECTORS)");
    Text m = expr(e.args[0]);
    if (!m.matrix())
        fail(e.args[0].where, "EIG() takes a matrix here, not a " + std::string(m.vector ? "vector" : "scalar"),
             "give a matrix: a name assigned [a, b; c, d], or [a, b; c, d] itself");
    if (m.size_known() && m.rows != m.cols)
        fail(e.args[0].where, "EIG() takes a square matrix, and this is " + std::to_string(m.rows) + " by " +
                                  std::to_string(m.cols), "give as many rows as columns");
    // each name a matrix of the file from here on (assigned again if it is one already)
    auto target = [&](const Expr& x, int cols) {
        if (x.kind != Expr::Kind::name || x.vector || x.primes)
            fail(x.where, "EIG() names its eigenvalues and eigenvectors with plain names", "write EIG(M, VALUES, VECTORS)");
        const Entry* old = find(x.text);
        if (old && old->kind != Kind::matrix)
            fail(x.where, "'" + x.text + "' is " + kind_word(old->kind) + " and cannot be assigned the " +
                              (cols == 1 ? "eigenvalues" : "eigenvectors"),
                 "name them with names of their own");
        const Entry& en = old ? *old : add(x.text, Kind::matrix, x.where);
        Entry& stored = names_[en.key];
        stored.rows = m.rows;
        stored.cols = cols == 1 ? 1 : m.rows;
        stored.elements.clear(), stored.indices = 0;  // assigned whole from here on
        return en.name;
    };
    const Expr& values = e.args[1];
    const Expr* vectors = e.args.size() == 3 ? &e.args[2] : nullptr;
    if (vectors && values.kind == Expr::Kind::name && vectors->kind == Expr::Kind::name &&
        upper(values.text) == upper(vectors->text))
        fail(vectors->where, "EIG() names its eigenvalues and eigenvectors alike", "give them two names");
    const Expr& matrix = e.args[0];
    for (const Expr* x : {&values, vectors})
        if (x && matrix.kind == Expr::Kind::name && x->kind == Expr::Kind::name && upper(matrix.text) == upper(x->text))
            fail(x->where, "EIG() would assign '" + x->text + "', its own matrix, before it is done with it",
                 "name the eigenvalues and eigenvectors apart from the matrix");
    const std::string v = target(values, 1);
    emit(v + " = eig(" + m.s + ")");
    if (!vectors) return;  // EIG(M, VALUES): the eigenvalues alone
    const std::string w = target(*vectors, 0);
    emit(w + " = eigvec(" + m.s + ")");
}

}  // namespace alembert::lang::autolev
