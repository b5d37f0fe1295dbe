// SPDX-License-Identifier: MIT
// Kane's method: chosen generalized speeds, motion constraints, auxiliary speeds.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "alembert/eom/equations.hpp"
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

/// What Kane's method is asked to form: coordinates, the generalized speeds and how they
/// relate to the coordinates' rates, motion constraints with the speeds they are solved for,
/// and auxiliary speeds that bring out constraint forces. Every list but `coordinates` may be
/// left empty; with only coordinates this is the classical u_r = q_r'.
///
/// Written with designated initializers:
/// `KaneOptions{.coordinates = {q1, q2}, .speeds = {u1, u2},
///              .kinematic_equations = {u1 - q1.d(1), u2 - q2.d(1)}}`.
struct KaneOptions {
    /// The generalized coordinates q_1..q_n.
    std::vector<TimeVariable> coordinates{};
    /// The generalized speeds u_1..u_p, dependent ones included: symbols declared with
    /// SymbolTable::add_variable(name, 1) (or higher order: u' must exist). Empty: u_r = q_r'.
    std::vector<ex> speeds{};
    /// Kinematic differential equations: n residuals (= 0), linear in the rates q', that fix
    /// q' in terms of the speeds, q and t (Kane 1985, sec. 2.12), e.g. u1 - dot(w_NB, Bx>).
    /// Given exactly when `speeds` is.
    std::vector<ex> kinematic_equations{};
    /// Motion constraints: residuals (= 0) linear in the speeds (Kane 1985, sec. 2.13), such as
    /// rolling without slip, dot(v_NP, Nx>) for the contact point P of a rolling body. The
    /// time derivative of a configuration constraint (holding q') may be given too: q' is
    /// replaced by its expression in the speeds first. They may hold auxiliary speeds, and
    /// are solved with them present: the auxiliary motion keeps every listed constraint.
    std::vector<ex> motion_constraints{};
    /// The speeds the motion constraints are solved for, one per constraint (a subset of
    /// `speeds`, or of the q_r' when `speeds` is empty).
    std::vector<ex> dependent_speeds{};
    /// Auxiliary speeds u~_a (Kane 1985, sec. 5.7): symbols that open the constraint whose
    /// force is wanted, either added to velocities with Point::set_vel (or to angular
    /// velocities with Frame::set_ang_vel) along the force, or written into that constraint
    /// as its violation (a pin opened: dot(v_NP - v_NQ, Nx>) - ux). Every other motion
    /// constraint must hold in the auxiliary motion, so the constraints are solved with the
    /// u~_a present. The constraint forces are added as loads with unknown measures. The
    /// u~_a are zero in the motion; their equations F~_a + F~_a* = 0 give the forces.
    std::vector<ex> auxiliary_speeds{};
    /// Simplify the results (alembert::simplify; the residuals collected in the u'). Off,
    /// nothing is normalised or simplified: the motion constraints are solved by elimination
    /// (detail::solve_by_elimination), with named intermediates when they are large, as they
    /// are when on but the constraints are too large for closed-form solving; past such a
    /// solve nothing is simplified either way (the Whipple bicycle's front contact: the
    /// equations form in about two seconds).
    bool simplify = true;
};

/// Kane's equations of a model and everything formed on the way (Kane & Levinson 1985,
/// ch. 2 and 6). With n coordinates, p speeds, m motion constraints, the p - m independent
/// speeds u_r and the m dependent ones u_s:
///  - kinematics: q' = k(q, u, t), the kinematic equations solved for q';
///  - constraints: u_s = sum_r A_sr u_r + B_s, the motion constraints solved for u_s;
///  - unconstrained forces: F_r, F_r* for every speed, with partial velocities
///    v_r = d v / d u_r taken from velocities in which q' is replaced by k(q, u, t);
///  - constrained forces (Kane 1985, eqs. 6.1.2, 6.1.3):
///       F~_r = F_r + sum_s F_s A_sr,   F~_r* = F_r* + sum_s F_s* A_sr,
///    with u_s and u_s' replaced by their expressions in the independent speeds;
///  - the dynamical equations F~_r + F~_r* = 0, in mass-matrix form M(q, t) u' = f(q, u, t);
///  - with auxiliary speeds u~_a, the constraints solved with them present,
///       u_s = sum_r A_sr u_r + sum_a C_sa u~_a + B_s,
///    and F~_a = F_a + sum_s F_s C_sa, F~_a* = F_a* + sum_s F_s* C_sa at u~ = u~' = 0.
/// Accelerations are ^N d/dt of those velocities (accelerations set with Point::set_acc or
/// Frame::set_ang_acc are not used); R* = -m ^N a^{cm}, T* = -(I . alpha + w x I . w).
struct KaneEquations {
    std::vector<ex> coordinates{};         ///< q_1..q_n
    std::vector<ex> speeds{};              ///< u_1..u_p (the q' when no speeds were chosen)
    std::vector<ex> independent_speeds{};  ///< the u_r of the equations, in `speeds` order
    std::vector<ex> dependent_speeds{};    ///< the u_s, in the order given
    /// q_1'..q_n', the coordinate-rate symbols.
    std::vector<ex> coordinate_rate_symbols{};
    /// The kinematic differential equations as given (empty when u_r = q_r').
    std::vector<ex> kinematic_equations{};
    /// The motion constraints as given (empty without them).
    std::vector<ex> motion_constraints{};
    /// q_i' = k_i(q, u_r, t), i = 1..n: the kinematic equations solved for q', the dependent
    /// speeds replaced (the q_i' themselves when u = q' and q_i' is independent).
    std::vector<ex> coordinate_rates{};
    /// u_s = sum_r A_sr u_r + B_s(q, t), s = 1..m: the motion constraints solved (at zero
    /// auxiliary speeds).
    std::vector<ex> dependent_speed_values{};
    /// u_s' in terms of q, u_r, u_r' and t (the time derivative of the line above).
    std::vector<ex> dependent_speed_rates{};
    /// A_sr = d u_s / d u_r (m x (p - m)), the coefficients of Kane's elimination.
    GiNaC::matrix constraint_coefficients{};
    /// C_sa = d u_s / d u~_a (m x number of auxiliary speeds): how the dependent speeds follow
    /// an auxiliary speed so that the motion constraints keep holding.
    GiNaC::matrix auxiliary_constraint_coefficients{};
    /// F_r for every speed u_1..u_p, before elimination (dependent speeds still in them).
    std::vector<ex> unconstrained_active_forces{};
    /// F_r* for every speed u_1..u_p, before elimination.
    std::vector<ex> unconstrained_inertia_forces{};
    /// F~_r, r over the independent speeds (F_r when there are no constraints).
    std::vector<ex> active_forces{};
    /// F~_r*, r over the independent speeds.
    std::vector<ex> inertia_forces{};
    /// F~_r + F~_r* (= 0), one per independent speed: applied - inertial.
    std::vector<ex> residuals{};
    /// The residuals as M u' = f: A = M (the mass matrix), b = f (the forcing), unknowns u_r'.
    LinearSystem dynamics{};
    /// The auxiliary speeds, as given.
    std::vector<ex> auxiliary_speeds{};
    /// F~_a + F~_a* (= 0), one per auxiliary speed: F~_a = F_a + sum_s F_s C_sa and likewise
    /// F~_a*, with u~ = u~' = 0 and the dependent speeds replaced; linear in the
    /// constraint-force measures, which they determine (they may hold u_r', to be replaced
    /// by the solution of the dynamical equations). They hold no u~ and no u~'.
    std::vector<ex> auxiliary_equations{};
};

/// Forms Kane's equations of `sys` as `options` asks (see KaneOptions and KaneEquations).
/// With only coordinates given, the residuals equal form_kane_equations(sys, q) in meaning.
/// @throws alembert::ArgumentError if the lists do not fit together (kinematic equations
///         without speeds or one count off, a dependent speed that is not a speed or appears
///         in no constraint, a speed that is also a coordinate rate or auxiliary, ...);
///         alembert::ModelError if a speed has no declared derivative, a velocity holds the
///         rate of a variable that is neither a speed nor a listed coordinate, or an auxiliary
///         speed's equation is 0 = 0 (its motion moves no loaded point and no mass);
///         alembert::SolveError if the kinematic equations are not linear in q' or cannot be
///         solved for it, if a motion constraint is not linear in the speeds, or if the
///         constraints cannot be solved for the dependent speeds (singular coefficients).
KaneEquations form_kane_equations(const System& sys, const KaneOptions& options);

namespace detail {
/// Solves A X = B symbolically, one decoupled block of unknowns at a time (rows and columns
/// linked by non-zero coefficients), each entry normalised and simplified. Shared by Kane's
/// method and linearization; throws SolveError with `what` and the unknowns of a singular
/// block.
GiNaC::matrix solve_by_blocks(const GiNaC::matrix& A, const GiNaC::matrix& B,
                              const std::vector<ex>& unknowns, const std::string& what);

/// True if A and B together hold more operations than closed-form symbolic solving handles
/// without swell (Gauss elimination followed by normalisation, as solve_by_blocks does).
bool is_large(const GiNaC::matrix& A, const GiNaC::matrix& B);

/// Solves A X = B by Gauss elimination and back substitution without normalising. When A and
/// B are large (is_large), every multiplier, updated entry and solved entry larger than a few
/// operations is named as an intermediate of `table`, so the solution grows linearly with the
/// size of A, never by the swell of rational normalisation (multivariate gcds); small
/// systems come out written out. Row pivots are chosen by magnitude
/// at the reference configuration (variables at 0, constants at their values), or at
/// pseudo-random values where every candidate vanishes there; the entries of A and B must
/// not hold solve-level symbols (accelerations, unknowns), which intermediates may not hide.
/// @throws alembert::SolveError with `what` if no pivot is found (a singular A).
GiNaC::matrix solve_by_elimination(SymbolTable& table, const GiNaC::matrix& A,
                                   const GiNaC::matrix& B, const std::vector<ex>& unknowns,
                                   const std::string& what);
}  // namespace detail

}  // namespace alembert
