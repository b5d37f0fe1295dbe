// SPDX-License-Identifier: MIT
// Lagrange's equations from kinetic and potential energy and non-conservative loads.
#pragma once

#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// Lagrange's equations Q_i + dL/dq_i - d/dt (dL/dq_i') = 0 with L = T - V: T the kinetic
/// energy of every body, V = System::calc_potential_energy() (gravity, springs,
/// inverse-square gravity), and Q_i the generalized forces of the loads that have no
/// potential (motors, dampers, drag, friction). Residuals follow Alembert's sign convention
/// (applied - inertial = 0), in coordinate order.
std::vector<ex> form_lagrange_equations(const System& sys, const std::vector<TimeVariable>& q);

}  // namespace alembert
