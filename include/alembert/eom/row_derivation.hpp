// SPDX-License-Identifier: MIT
// A road-map row's derivation step by step: the quantities its equation is formed from.
#pragma once

#include <string>
#include <vector>

#include "alembert/eom/roadmap.hpp"

namespace alembert {

class MovingBodies;

/// The steps of one road-map row as a textbook writes them (Mitiguy ch. 21), each quantity
/// formed by the same functions as the row (System::calc_resultant, calc_inertial_force, the
/// bodies' momenta):
///  - translate: F^S, m^S, sum over S of m^B ^N a^{Bcm}, then E = u . (F^S - sum m a);
///  - rotate:    H^{S/O} = sum (I^{B/Bcm} . w^B + r^{Bcm/O} x m^B ^N v^{Bcm}), L^S = sum m^B
///    ^N v^{Bcm}, ^N d/dt H^{S/O}, ^N v^O x L^S, M^{S/O}, then E = u . (M - dH/dt - v^O x L);
///  - statics: F^S or M^{S/O} alone, E = u . F^S or u . M^{S/O};
///  - constraint rows: the declared residual and how often it is differentiated.
/// Rotate rows of systems formed by accumulating moments (more than eight bodies) give
/// M^{S/O} and E = the row's equation (H and its derivative are not formed for them).
/// `projected` is the dot product the steps end with: it equals the row's equation
/// (E - projected is zero), since ^N d/dt H^{S/O} + ^N v^O x L^S = sum (I . alpha + w x I . w
/// + r^{Bcm/O} x m ^N a^{Bcm}), the form the row is computed in.
struct RowDerivation {
    Motion motion = Motion::rotate;
    Analysis analysis = Analysis::dynamics;
    bool accumulated = false;       ///< formed by accumulating moments along the point tree
    /// The coordinate that moves exactly the bodies of S when it alone changes (empty: none);
    /// "qB" for a knee row whose S is the thigh and trunk.
    std::string moved_by{};
    /// Why O: "the joint at B_o joins S to A: its force has no moment about B_o", ...
    std::string about_reason{};
    ex mass{};                      ///< m^S (translate rows)
    Vector force{};                 ///< F^S, the resultant of the loads external to S
    Vector mass_acceleration{};     ///< sum over S of m^B ^N a^{Bcm}
    Vector angular_momentum{};      ///< ^N H^{S/O}
    Vector linear_momentum{};       ///< ^N L^S
    Vector angular_momentum_rate{}; ///< ^N d/dt ^N H^{S/O}
    Vector transport{};             ///< ^N v^O x ^N L^S
    Vector moment{};                ///< M^{S/O}, the moment of the loads external to S about O
    ex projected{};                 ///< u . (...): the row's equation as the steps form it
    ex constraint_residual{};       ///< constraint rows: the residual as declared
    int constraint_derivatives = 0; ///< constraint rows: times differentiated (0, 1 or 2)
};

/// The derivation of `row` (formed already: form_roadmap_row), from the model's quantities.
/// @throws alembert::ArgumentError as form_roadmap_equation does (no about point, empty S).
RowDerivation calc_row_derivation(const System& sys, const RoadmapRow& row);
/// The same, `moving` telling which coordinate moves exactly S (MovingBodies: each speed's
/// motions found once for all the model's rows, not once per row).
RowDerivation calc_row_derivation(const System& sys, const RoadmapRow& row, MovingBodies& moving);

}  // namespace alembert
