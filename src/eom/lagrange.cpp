// SPDX-License-Identifier: MIT
// Lagrange's equations.
#include "alembert/eom/lagrange.hpp"

#include "alembert/eom/kane.hpp"

namespace alembert {

std::vector<ex> form_lagrange_equations(const System& sys, const std::vector<TimeVariable>& q) {
    ex L = sys.calc_kinetic_energy(sys.bodies()) - sys.calc_potential_energy();
    std::vector<ex> Q = form_generalized_active_forces(sys, q, LoadSelection::nonconservative);
    SymbolTable& st = sys.newtonian().symbols();
    std::vector<ex> E;
    for (std::size_t i = 0; i < q.size(); ++i) {
        const GiNaC::symbol& qi = GiNaC::ex_to<GiNaC::symbol>(q[i].symbol());
        const GiNaC::symbol& ui = GiNaC::ex_to<GiNaC::symbol>(q[i].d(1));
        E.push_back(Q[i] + L.diff(qi) - st.dt(L.diff(ui)));
    }
    return E;
}

}  // namespace alembert
