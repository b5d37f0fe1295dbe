// SPDX-License-Identifier: MIT
// Lagrange's equations.
#include "alembert/eom/lagrange.hpp"

#include "alembert/eom/kane.hpp"
#include "expression_lists.hpp"

namespace alembert {

std::vector<ex> form_lagrange_equations(const System& sys, const std::vector<TimeVariable>& q) {
    detail::require_distinct_coordinates(q, "form_lagrange_equations()");
    ex L = sys.calc_kinetic_energy(sys.bodies()) - sys.calc_potential_energy();
    std::vector<ex> Q = form_generalized_active_forces(sys, q, LoadSelection::nonconservative);
    SymbolTable& st = sys.newtonian().symbols();
    std::vector<ex> E;
    for (std::size_t i = 0; i < q.size(); ++i) {
        // through intermediates: the kinetic energy of a long chain is written in its named
        // velocity measures, which depend on q and q'
        E.push_back(Q[i] + st.diff(L, q[i].symbol()) - st.dt(st.diff(L, q[i].d(1))));
    }
    return E;
}

}  // namespace alembert
