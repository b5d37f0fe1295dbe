// SPDX-License-Identifier: MIT
// The derivatives of inverse dynamics with respect to q and q', through the intermediates.
#include "alembert/codegen/codegen.hpp"
#include "alembert/error.hpp"
#include "linear_split.hpp"

namespace alembert {

void add_dynamics_derivatives(SymbolTable& table, DynamicsEquations& eq) {
    constexpr const char* who = "add_dynamics_derivatives()";
    const std::size_t n = eq.coordinates.size();
    if (n == 0 || eq.residuals.size() != n)
        throw ArgumentError(std::string(who) + ": " + std::to_string(eq.residuals.size()) +
                            " residuals for " + std::to_string(n) +
                            " coordinates; give one equation of motion per coordinate");
    if (eq.loads.size() != n)
        throw ArgumentError(std::string(who) + ": " + std::to_string(eq.loads.size()) +
                            " loads for " + std::to_string(n) + " coordinates; the derivatives of "
                            "inverse and forward dynamics need one load per coordinate (list the "
                            "joint torques and forces, without joint-reaction measures)");
    if (!eq.constraints.empty())
        throw ArgumentError(std::string(who) + ": the model has " +
                            std::to_string(eq.constraints.size()) + " constraints; the "
                            "derivatives are formed for open chains and trees only");
    for (const TimeVariable& v : eq.coordinates)
        if (v.order() < 2)
            throw ArgumentError(std::string(who) + ": the coordinate '" + v.name() +
                                "' has no second derivative; declare it with order 2 (equations "
                                "in generalized speeds are not covered)");
    // u(q, q', q'') from the residuals, as inverse dynamics is generated
    const std::vector<ex> u = detail::solve_for_loads(table, eq.residuals, eq.loads, who);
    // forward mode through the intermediates: diff names each dz/ds once, so the rows share them
    std::vector<ex> dq(n * n), dqp(n * n);
    for (std::size_t j = 0; j < n; ++j) {
        const ex q = eq.coordinates[j].d(0), qp = eq.coordinates[j].d(1);
        for (std::size_t i = 0; i < n; ++i) {
            dq[i * n + j] = table.diff(u[i], q);
            dqp[i * n + j] = table.diff(u[i], qp);
        }
    }
    eq.inverse_dynamics_dq = std::move(dq);
    eq.inverse_dynamics_dqp = std::move(dqp);
}

}  // namespace alembert
