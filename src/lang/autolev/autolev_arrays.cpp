// SPDX-License-Identifier: MIT
// Arrays assigned by element, as Autolev's own examples write them: ZERO[1] = e1, ZERO[2] = e2,
// then SOLVE(ZERO, U1', U2'). Each element is a scalar of the script (ZERO_1 = e1), read back
// where the file writes ZERO[1]; where the file uses the array whole, the script's matrix is
// written from its elements first (ZERO = [ZERO_1; ZERO_2]), so that an element assigned
// again later is in the matrix from its next use on. One index makes a column, two a matrix.
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

std::pair<int, int> Translator::array_index(const Expr& e, const Entry& m) {
    if (e.args.size() > 2)
        leave_out(e.where, "an array of " + std::to_string(e.args.size()) + " indices ('" + e.text +
                               "[...]') has no counterpart: the script's matrices have two",
                  "write its elements as names of their own (" + e.text + "_1_1_1 = ...)");
    if (e.args.empty())
        fail(e.where, "an array takes one index (" + e.text + "[i]) or two (" + e.text + "[i, j])",
             "write " + e.text + "[1] or " + e.text + "[1, 2]");
    if (m.indices != 0 && static_cast<int>(e.args.size()) != m.indices)
        fail(e.where, "array '" + e.text + "' is assigned with " + (m.indices == 1 ? "one index" : "two indices") +
                          " and used here with " + (e.args.size() == 1 ? "one" : "two"),
             m.indices == 1 ? "write " + e.text + "[i]" : "write " + e.text + "[i, j]");
    const std::string what = "the index of array '" + e.text + "'";
    const int i = whole_number(e.args[0], what);
    const int j = e.args.size() == 2 ? whole_number(e.args[1], what) : 1;
    return {i, j};
}

static std::string element_text(const std::string& array, std::pair<int, int> at, int indices) {
    return array + "[" + std::to_string(at.first) + (indices == 2 ? ", " + std::to_string(at.second) : "") + "]";
}

void Translator::array_assignment(const Statement& st) {
    const Expr& lhs = st.lhs;
    std::string key = upper(lhs.text);
    if (key == "DEPENDENT") {
        if (lhs.args.size() != 1 || lhs.args[0].kind != Expr::Kind::number)
            fail(lhs.where, "DEPENDENT takes one index: DEPENDENT[1] = ...");
        constraints_.push_back(scalar(st.rhs).s);
        if (!constraints_where_) constraints_where_ = st.where;
        return;
    }
    if (key == "AUXILIARY") {
        if (lhs.args.size() != 1 || lhs.args[0].kind != Expr::Kind::number)
            fail(lhs.where, "AUXILIARY takes one index: AUXILIARY[1] = ...");
        aux_constraints_.push_back({scalar(st.rhs).s, st.where});
        return;
    }
    const Entry* en = find(lhs.text);
    if (key == "ZERO" && !en && kane_at_)
        fail(lhs.where, "ZERO holds Kane's equations here (ZERO = FR() + FRSTAR() or KANE() before), and an element of "
                        "them is not assigned alone",
             "give the file's own equations another name: EQ[1] = ..., then SOLVE(EQ, ...)");
    if (en && en->kind == Kind::matrix && en->indices == 0)
        fail(lhs.where, "an element of matrix '" + lhs.text + "' is not assigned alone",
             "assign the whole matrix: " + lhs.text + " = [...]");
    if (en && en->kind != Kind::matrix)
        fail(lhs.where, "'" + lhs.text + "' is " + kind_word(en->kind) + " and cannot be assigned as an array",
             "give the array a name of its own");
    if (st.rhs.kind == Expr::Kind::matrix)
        fail(st.rhs.where, "an element of array '" + lhs.text + "' is a scalar, not a matrix",
             "assign the whole matrix: " + lhs.text + " = [...]");
    Entry probe{};
    probe.indices = en ? en->indices : 0;
    const std::pair<int, int> at = array_index(lhs, probe);
    // the value first: ZERO[1] += e reads ZERO[1] before it is assigned
    const Text value = scalar(st.rhs);
    const Entry& array = en ? *en : add(lhs.text, Kind::matrix, lhs.where);
    Entry& stored = names_[array.key];
    stored.indices = static_cast<int>(lhs.args.size());
    std::string& name = stored.elements[at];
    if (name.empty()) {
        // ZERO_1, M_1_2, or with a suffix if the file or the script has that name
        std::string base = array.name + "_" + std::to_string(at.first) +
                           (stored.indices == 2 ? "_" + std::to_string(at.second) : "");
        name = base;
        for (int k = 2; assigned_.count(upper(name)) || find(name) || find_object(name) || extra_names_.count(name) ||
                        is_reserved(name);
             ++k)
            name = base + "_" + std::to_string(k);
        extra_names_.insert({name, 0});
    }
    stored.rows = std::max(stored.rows, at.first);
    stored.cols = std::max(stored.cols, at.second);
    stored.whole_written = false;
    emit(name + " = " + value.s);
}

Text Translator::array_element(const Expr& e, const Entry& m) {
    const std::pair<int, int> at = array_index(e, m);
    auto it = m.elements.find(at);
    if (it == m.elements.end())
        fail(e.where, "'" + element_text(e.text, at, m.indices) + "' is not assigned",
             "assign it before this line: " + element_text(e.text, at, m.indices) + " = ...");
    return {it->second, false, 5, false};
}

Text Translator::whole_array(const Expr& e, const Entry& m) {
    Entry& stored = names_[m.key];
    std::vector<std::vector<std::string>> cells(static_cast<std::size_t>(stored.rows));
    for (int i = 1; i <= stored.rows; ++i)
        for (int j = 1; j <= stored.cols; ++j) {
            auto it = stored.elements.find({i, j});
            if (it == stored.elements.end())
                fail(e.where,
                     "array '" + e.text + "' is used whole, and its element '" +
                         element_text(e.text, {i, j}, stored.indices) + "' is not assigned",
                     "assign every element from " + element_text(e.text, {1, 1}, stored.indices) + " to " +
                         element_text(e.text, {stored.rows, stored.cols}, stored.indices) + " before this line");
            cells[static_cast<std::size_t>(i - 1)].push_back(it->second);
        }
    if (!stored.whole_written) {
        std::string value;
        if (stored.rows == 1 && stored.cols > 1) {
            value = "transpose([" + join(cells.front(), "; ") + "])";  // [a, b] alone is a list in the script
        } else {
            std::vector<std::string> lines;
            for (const auto& r : cells) lines.push_back(join(r));
            value = "[" + join(lines, "; ") + "]";
        }
        emit(stored.name + " = " + value);
        stored.whole_written = true;
        wholes_written_.push_back(stored.key);
    }
    return {stored.name, false, 5, false, stored.rows, stored.cols};
}

}  // namespace alembert::lang::autolev
