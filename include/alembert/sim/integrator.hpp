// SPDX-License-Identifier: MIT
// The integration methods simulate offers, by name.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace alembert {

/// The method simulate integrates x = (q, q') with. Each one steps under error control
/// (|err_i| <= abs_tol + rel_tol |x_i| per step) and has dense output, so output rows land
/// exactly on the requested times and events are located by bisection inside a step.
enum class Integrator {
    /// Dormand-Prince 5(4) (Boost.Odeint runge_kutta_dopri5) with its fourth-order dense
    /// output. The default: cheap per step, good at tolerances down to about 1e-10.
    dopri5,
    /// Runge-Kutta-Fehlberg 7(8) (Boost.Odeint runge_kutta_fehlberg78, 13 stages) under
    /// error control; a state inside the last step is computed by one more 7(8) step from the
    /// step's start, so outputs and events keep the method's order. For tight tolerances
    /// (1e-10 to 1e-14) on smooth, non-stiff models.
    rkf78,
    /// Bulirsch-Stoer extrapolation of the modified midpoint rule with its dense output
    /// (Boost.Odeint bulirsch_stoer_dense_out). Very tight tolerances on smooth models.
    bulirsch_stoer,
    /// Variable-order (1 to 5) BDF, implicit, from SUNDIALS CVODE with Newton iterations on a
    /// dense Jacobian of finite differences and CVODE's interpolating dense output. For stiff
    /// models (stiff springs, contact penalties, fast actuators): steps follow the slow motion,
    /// not the fastest time constant.
    bdf,
};

/// The name scripts and messages use: "dopri5", "rkf78", "bulirsch_stoer", "bdf".
std::string_view to_string(Integrator method);

/// Every method's name, in the order of the enumeration.
const std::vector<std::string>& integrator_names();

/// Whether this build of Alembert has `method`: every method but bdf always; bdf where it was
/// built with SUNDIALS CVODE (ALEMBERT_WITH_SUNDIALS, docs/building.md).
bool integrator_available(Integrator method);

/// The method named `name` (see to_string).
/// @throws alembert::ArgumentError listing the names if `name` is none of them.
Integrator parse_integrator(std::string_view name);

}  // namespace alembert
