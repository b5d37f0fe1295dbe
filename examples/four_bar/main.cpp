// SPDX-License-Identifier: MIT
// A closed loop: the four-bar linkage (make_four_bar). Prints the statics road-map, whose
// balance rows keep the loop's pin force and whose constraint rows close the system, then
// solves it on both assembly branches for the crank torque that holds the linkage still.
#include <cstdio>
#include <iostream>
#include <numbers>

#include <alembert/alembert.hpp>

using namespace alembert;

int main() {
    SampleModel m = make_four_bar();
    const System& sys = m.system;
    const SymbolTable& s = sys.symbols();
    ex qA = m.q[0].symbol(), qB = m.q[1].symbol(), qC = m.q[2].symbol();
    ex T = m.unknowns[0];
    std::vector<ex> unknowns{T, m.unknowns[1], m.unknowns[2], qB, qC};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns, Analysis::statics);
    std::cout << "MG road-map (statics of the four-bar)\n" << format_roadmap_table(sys, rows);

    // which side of the line from the crank tip to the rocker pivot the coupler's pin is on
    ex LA = s.symbol("L_A"), LN = s.symbol("L_N");
    ex side = (LN - LA * GiNaC::cos(qA)) * GiNaC::sin(qA + qB) +
              LA * GiNaC::sin(qA) * GiNaC::cos(qA + qB);
    const double crank = std::numbers::pi / 3;
    std::printf("\nholding the crank at qA = 60 deg:\n");
    for (bool above : {true, false}) {
        StaticsOptions opt;
        opt.conditions = {{side, above, above ? "pin above" : "pin below"}};
        exmap guess{{qB, above ? -0.5 : -2.0}, {qC, above ? 1.5 : -1.5}};  // a rough sketch of each
        Equilibrium eq = solve_equilibrium(s, residuals_of(rows), unknowns, guess, {{qA, crank}}, opt);
        std::printf("  %s branch: qB = %8.4f rad, qC = %8.4f rad, T = %8.4f N m, "
                    "pin force (%.4f, %.4f) N (%d Newton iterations)\n",
                    above ? "pin-above" : "pin-below", eq.value(qB), eq.value(qC), eq.value(T),
                    eq.value(m.unknowns[1]), eq.value(m.unknowns[2]), eq.iterations);
    }
    return 0;
}
