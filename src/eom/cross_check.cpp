// SPDX-License-Identifier: MIT
// Road-map, Kane and Lagrange side by side at random states.
#include "alembert/eom/cross_check.hpp"

#include <algorithm>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"
#include "alembert/eom/planner.hpp"

namespace alembert {

MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states, unsigned seed) {
    std::vector<ex> acc;
    for (const TimeVariable& qi : q) acc.push_back(qi.d(2));
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, acc)) roadmap.push_back(r.equation);
    std::vector<LinearSystem> forms{form_linear_system(roadmap, acc),
                                    form_linear_system(form_kane_equations(sys, q), acc),
                                    form_linear_system(form_lagrange_equations(sys, q), acc)};
    MethodComparison out{{"road-map", "Kane", "Lagrange"}, states, 0};

    const SymbolTable& st = sys.symbols();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
    for (int k = 0; k < states; ++k) {
        // a random state: coordinates, speeds, specified inputs, unknown loads, free constants
        exmap values;
        for (SymbolKind kind : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
            for (const ex& s : st.symbols(kind))
                if (!(kind == SymbolKind::variable && st.derivative_order(s) >= 2))
                    values[s] = unit(rng);
        for (const ex& c : st.symbols(SymbolKind::constant))
            if (!st.value(c)) values[c] = positive(rng);
        values[st.time()] = positive(rng);
        Eigen::VectorXd ref = solve_numeric(st, forms[0], values);
        for (std::size_t m = 1; m < forms.size(); ++m) {
            Eigen::VectorXd x = solve_numeric(st, forms[m], values);
            for (int i = 0; i < x.size(); ++i)
                out.max_difference = std::max(
                    out.max_difference, std::abs(x(i) - ref(i)) / std::max(1.0, std::abs(ref(i))));
        }
    }
    return out;
}

}  // namespace alembert
