// SPDX-License-Identifier: MIT
// Numeric solve of equations one block after another (road-map rows in the planner's order).
#include "alembert/sim/block_solve.hpp"

#include <algorithm>
#include <string>

#include "alembert/eom/equations.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

Eigen::VectorXd solve_numeric_in_blocks(const SymbolTable& table, const std::vector<ex>& residuals,
                                        const std::vector<ex>& unknowns, const exmap& values) {
    const std::size_t n = unknowns.size();
    if (residuals.size() != n)
        throw SolveError("solve_numeric_in_blocks(): " + std::to_string(residuals.size()) +
                         " equations for " + std::to_string(n) + " unknowns");
    // the residuals with their intermediates written out, so that a substitution reaches them
    std::vector<ex> left;
    for (const ex& r : residuals) left.push_back(table.expand_intermediates(r));
    // which unknowns each residual holds
    std::vector<std::vector<std::size_t>> holds(n);
    for (std::size_t i = 0; i < n; ++i) {
        const GiNaC::exset held = symbols_of(left[i]);
        for (std::size_t j = 0; j < n; ++j)
            if (held.count(unknowns[j])) holds[i].push_back(j);
    }

    Eigen::VectorXd x(static_cast<Eigen::Index>(n));
    std::vector<bool> known(n, false), used(n, false);
    exmap numbers;
    std::size_t solved = 0;
    const auto unsolved_in = [&](const std::vector<std::size_t>& rows) {
        std::vector<std::size_t> js;
        for (std::size_t i : rows)
            for (std::size_t j : holds[i])
                if (!known[j] && std::find(js.begin(), js.end(), j) == js.end()) js.push_back(j);
        return js;
    };
    while (solved < n) {
        // the next block: one residual with one unsolved unknown, else the shortest run
        std::vector<std::size_t> rows, cols;
        for (std::size_t i = 0; i < n && rows.empty(); ++i)
            if (!used[i] && unsolved_in({i}).size() == 1) rows = {i}, cols = unsolved_in({i});
        if (rows.empty()) {
            std::vector<std::size_t> run;
            for (std::size_t i = 0; i < n; ++i) {
                if (used[i]) continue;
                run.push_back(i);
                std::vector<std::size_t> js = unsolved_in(run);
                if (js.size() == run.size()) {
                    rows = run, cols = std::move(js);
                    break;
                }
            }
        }
        if (rows.empty())
            throw SolveError("solve_numeric_in_blocks(): the equations are not linear in the "
                             "unknowns together, and they do not split into blocks solved one "
                             "after another; solve them from a guess");
        std::vector<ex> eqs, xs;
        for (std::size_t i : rows) eqs.push_back(left[i].subs(numbers));
        for (std::size_t j : cols) xs.push_back(unknowns[j]);
        const Eigen::VectorXd block = solve_numeric(table, form_linear_system(eqs, xs), values);
        for (std::size_t k = 0; k < cols.size(); ++k) {
            const double v = block(static_cast<Eigen::Index>(k));
            x(static_cast<Eigen::Index>(cols[k])) = v;
            known[cols[k]] = true;
            numbers[unknowns[cols[k]]] = v;
        }
        for (std::size_t i : rows) used[i] = true;
        solved += cols.size();
    }
    return x;
}

}  // namespace alembert
