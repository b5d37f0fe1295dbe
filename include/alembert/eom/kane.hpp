// SPDX-License-Identifier: MIT
// Kane's method with the generalized speeds u_r = q_r'.
#pragma once

#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// Kane's equations F_r + F_r* = 0, r = 1..n (Kane & Levinson 1985, ch. 6), with the
/// generalized speeds u_r = q_r':
///   F_r  = sum over loads of v_r^P . F (forces at P) + w_r^B . T (torques on B),
///          and v_r^{cm} . m g for gravity;
///   F_r* = sum over bodies of v_r^{cm} . R* + w_r^B . T*,
/// with partial velocities v_r = d v / d u_r and w_r = d w / d u_r, and R*, T* the inertia
/// force and torque (alembert::calc_inertia_loads). The residuals follow Alembert's sign
/// convention (applied - inertial = 0) and are returned in coordinate order.
std::vector<ex> form_kane_equations(const System& sys, const std::vector<TimeVariable>& q);

/// Which loads generalized active forces include.
enum class LoadSelection {
    all,              ///< every load and gravity (Kane's F_r; statics: F_r = 0)
    nonconservative,  ///< only loads without a potential (Lagrange's Q_r)
};

/// The generalized active forces F_r = sum v_r . F + w_r . T with u_r = q_r'.
std::vector<ex> form_generalized_active_forces(const System& sys,
                                               const std::vector<TimeVariable>& q,
                                               LoadSelection which = LoadSelection::all);

}  // namespace alembert
