// SPDX-License-Identifier: MIT
// Road-map, Kane, Lagrange and brute-force Newton–Euler side by side at random states.
#include "alembert/eom/cross_check.hpp"

#include <algorithm>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"

namespace alembert {

MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states, unsigned seed) {
    std::vector<ex> acc;
    for (const TimeVariable& qi : q) acc.push_back(qi.d(2));
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, acc)) roadmap.push_back(r.equation);
    // Newton–Euler solves for the accelerations and every joint reaction together
    NewtonEulerEquations ne = form_newton_euler_equations(sys, q, acc);
    std::vector<LinearSystem> forms{form_linear_system(roadmap, acc),
                                    form_linear_system(form_kane_equations(sys, q), acc),
                                    form_linear_system(form_lagrange_equations(sys, q), acc),
                                    form_linear_system(ne.equations, ne.unknowns)};
    MethodComparison out{{"road-map", "Kane", "Lagrange", "Newton–Euler"}, states, 0, {}};

    out.differences.assign(forms.size(), 0.0);
    auto is_reaction = [&](const ex& s) {
        return std::any_of(ne.reactions.begin(), ne.reactions.end(),
                           [&](const ex& r) { return r.is_equal(s); });
    };

    const SymbolTable& st = sys.symbols();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
    for (int k = 0; k < states; ++k) {
        // a random state: coordinates, speeds, specified inputs, unknown loads, free constants
        exmap values;
        for (SymbolKind kind : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
            for (const ex& s : st.symbols(kind))
                if (!(kind == SymbolKind::variable && st.derivative_order(s) >= 2) &&
                    !is_reaction(s))
                    values[s] = unit(rng);
        for (const ex& c : st.symbols(SymbolKind::constant))
            if (!st.value(c)) values[c] = positive(rng);
        values[st.time()] = positive(rng);
        Eigen::VectorXd ref = solve_numeric(st, forms[0], values);
        for (std::size_t m = 1; m < forms.size(); ++m) {
            Eigen::VectorXd x = solve_numeric(st, forms[m], values);
            for (int i = 0; i < ref.size(); ++i)
                out.differences[m] = std::max(out.differences[m], std::abs(x(i) - ref(i)) /
                                                                      std::max(1.0, std::abs(ref(i))));
            out.max_difference = std::max(out.max_difference, out.differences[m]);
        }
    }
    return out;
}

}  // namespace alembert
