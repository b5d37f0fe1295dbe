// SPDX-License-Identifier: MIT
// Private to codegen: the joint-reaction measures solved from their road-map rows in order.
#include "reaction_solve.hpp"

#include <string>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "linear_split.hpp"

namespace alembert::detail {

std::vector<ex> solve_reaction_rows(const SymbolTable& table, const std::vector<ex>& rows,
                                    const std::vector<ex>& measures, const char* who) {
    const auto n = static_cast<unsigned>(measures.size());
    if (rows.size() != measures.size())
        throw ArgumentError(std::string(who) + ": " + std::to_string(rows.size()) +
                            " road-map rows for " + std::to_string(n) +
                            " joint-reaction measures; give the planner's row of each measure");
    // E_i = b_i - sum_j A_ij r_j
    const LinearSystem L = split_linear(table, rows, measures, who);
    std::vector<ex> r(n);
    std::vector<bool> solved(n, false);
    // b_i with the measures solved so far moved to the right side
    auto known_side = [&](unsigned i) {
        ex s = L.b(i, 0);
        for (unsigned j = 0; j < n; ++j)
            if (solved[j] && !L.A(i, j).is_zero()) s -= L.A(i, j) * r[j];
        return s;
    };
    for (unsigned first = 0; first < n;) {
        // the block opened by row `first`: rows first..last, closed when every unsolved measure
        // its rows hold is one of its own
        unsigned last = first;
        for (unsigned i = first; i <= last; ++i)
            for (unsigned j = 0; j < n; ++j)
                if (!solved[j] && j > last && !L.A(i, j).is_zero()) last = j;
        if (last == first) {
            const ex& a = L.A(first, first);
            if (a.is_zero())
                throw SolveError(std::string(who) + ": the road-map row of the joint-reaction "
                                 "measure '" + to_string(measures[first]) + "' does not hold it; "
                                 "plan the rows with plan_roadmap for the measures");
            r[first] = known_side(first) / a;
        } else {
            const unsigned k = last - first + 1;
            GiNaC::matrix A(k, k), B(k, 1);
            std::vector<ex> block;
            for (unsigned i = 0; i < k; ++i) {
                block.push_back(measures[first + i]);
                B(i, 0) = known_side(first + i);
                for (unsigned j = 0; j < k; ++j) A(i, j) = L.A(first + i, first + j);
            }
            GiNaC::matrix X =
                solve_by_blocks(A, B, block, std::string(who) + ": the joint-reaction rows");
            for (unsigned i = 0; i < k; ++i) r[first + i] = X(i, 0);
        }
        for (unsigned i = first; i <= last; ++i) solved[i] = true;
        first = last + 1;
    }
    return r;
}

}  // namespace alembert::detail
