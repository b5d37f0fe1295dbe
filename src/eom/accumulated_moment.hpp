// SPDX-License-Identifier: MIT
// Rotate rows of large systems formed by accumulating moments along the tree of points.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <unordered_map>

#include "alembert/eom/roadmap.hpp"

namespace alembert::detail {

/// Rotate rows whose system S holds more bodies than this are formed by
/// form_accumulated_moment_row; smaller ones as written (sum over S of r x F and I alpha +
/// w x I w about O), which keeps the rows of small models in their textbook form.
inline constexpr std::size_t kAccumulatedRowBodies = 8;

/// The residual of a rotate row, u . (M^{S/O} - M*^{S/O}) (statics: u . M^{S/O}), with the
/// moments of the loads on S accumulated from the tips of the tree of located points towards
/// O, as a Newton-Euler recursion does: every point P below O carries the resultant force F^P
/// and moment M^P (about P, in the frame of P's body) of the items at P and below it, with
///     F^P = sum over P's children C of F^C + (items at P),
///     M^P = sum over C of (M^C + r^{C/P} x F^C) + (couples at P),
/// each measure named as an intermediate (shared by every row that meets the same sums, so a
/// chain's rows about successive joints add a few intermediates each). The items are each
/// body's weight and inertia force at its mass centre with its inertia torque, and the loads
/// external to S with known measures; loads with unknown measures, and items at points not
/// located (through other points) from O, enter directly as r^{P/O} x F. The accelerations
/// (and other solve-level symbols) are then made explicit again: E = sum_x (dE/dx) x + E|x=0,
/// the coefficients by differentiation through the intermediates (each dz/dx taken once) and
/// E|x=0 by the same accumulation with x = 0 in the items.
/// Nothing (std::nullopt) if the row is not a rotate row or its items are not visibly linear in
/// the solve-level symbols (the caller forms it as written then).
std::optional<ex> form_accumulated_moment_row(const System& sys, const RoadmapRow& row);

/// While one is alive on this thread, form_accumulated_moment_row forms each body's inertia
/// force and torque, and their values with the accelerations at zero, once and remembers them
/// (a plan's rows meet the same bodies: a chain's n rows formed each body's loads up to n
/// times, each holding the accelerations of every joint inward of it). The model must not
/// change while one lives: plan_roadmap keeps one for the rows it forms.
class InertiaLoadsMemo {
public:
    InertiaLoadsMemo();
    ~InertiaLoadsMemo();
    InertiaLoadsMemo(const InertiaLoadsMemo&) = delete;
    InertiaLoadsMemo& operator=(const InertiaLoadsMemo&) = delete;

    struct Entry;

private:
    InertiaLoadsMemo* outer_;
    std::unordered_map<const Body*, std::unique_ptr<Entry>> entries_;
    friend std::optional<ex> form_accumulated_moment_row(const System&, const RoadmapRow&);
};

}  // namespace alembert::detail
