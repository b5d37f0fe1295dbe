// SPDX-License-Identifier: MIT
// A road-map row's derivation: momenta, their rates, the loads' resultants, the projection.
#include "alembert/eom/row_derivation.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

#include "alembert/eom/inertia_forces.hpp"
#include "alembert/eom/moving_bodies.hpp"
#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "accumulated_moment.hpp"

namespace alembert {

namespace {

bool in_set(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

// the coordinate whose change alone moves exactly the bodies of S (a body moves if its mass
// centre's partial velocity or its partial angular velocity for that speed is not zero),
// tested symbolically: where the velocities cannot be evaluated at the random states
std::string coordinate_moving_symbolically(const System& sys, const BodySet& S) {
    const SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    for (const ex& x : st.symbols(SymbolKind::variable)) {
        if (st.derivative_order(x) != 0) continue;
        const TimeVariable q = st.variable(st.name(x));
        if (q.order() < 1) continue;
        const ex speed = q.d(1);
        bool same = true;
        for (const Body* b : sys.bodies()) {
            bool moves = !is_zero_at_random_states(st, b->cm().vel_in(N).diff(speed), N);
            if (!moves && b->frame())
                moves = !is_zero_at_random_states(st, b->frame()->ang_vel_in(N).diff(speed), N);
            if (moves != in_set(S, b)) {
                same = false;
                break;
            }
        }
        if (same) return q.name();
    }
    return "";
}

std::string about_words(const System& sys, const RoadmapRow& row) {
    const Point& O = *row.about;
    if (row.about_owned)
        return O.name() + " is located for this row (the instantaneous centre of S, or where the "
                          "lines of two unknown forces meet): those forces have no moment about it";
    const Body* other = nullptr;
    if (in_set(row.system, O.owner()) && is_joint_point(sys, O, &other) && !in_set(row.system, other))
        return "the joint at " + O.name() + " joins S to " +
               (other ? other->name() : sys.newtonian().name()) +
               ": its unknown force acts at " + O.name() + " and has no moment about it";
    for (const Load& l : sys.loads())
        if (l.kind == LoadKind::force && l.point == &O && in_set(row.system, l.on) &&
            !in_set(row.system, l.from))
            return "the force " + (l.label.empty() ? std::string("at ") + O.name() : l.label) +
                   " acts at " + O.name() + ": it has no moment about it";
    return "the point the row's moments are taken about";
}

}  // namespace

RowDerivation calc_row_derivation(const System& sys, const RoadmapRow& row) {
    MovingBodies moving(sys);
    return calc_row_derivation(sys, row, moving);
}

RowDerivation calc_row_derivation(const System& sys, const RoadmapRow& row, MovingBodies& moving) {
    RowDerivation d;
    d.motion = row.motion;
    d.analysis = row.analysis;
    const Frame& N = sys.newtonian();
    if (row.motion == Motion::constraint) {
        for (const Constraint& c : sys.constraints())
            if (c.name == row.constraint) {
                d.constraint_residual = c.residual;
                d.constraint_derivatives =
                    row.analysis == Analysis::statics ? 0
                    : c.kind == ConstraintKind::configuration ? 2 : 1;
            }
        d.projected = row.equation;
        return d;
    }
    if (row.system.empty())
        throw ArgumentError("calc_row_derivation(): the row for '" + to_string(row.variable) +
                            "' has an empty system S; list the bodies it moves");
    try {
        d.moved_by = moving.calc_coordinate_moving(row.system);
    } catch (const std::domain_error&) {
        d.moved_by = coordinate_moving_symbolically(sys, row.system);
    }
    const bool dynamics = row.analysis == Analysis::dynamics;
    if (row.motion == Motion::translate) {
        d.force = sys.calc_resultant(row.system, sys.origin()).force;
        d.mass = sys.calc_mass(row.system);
        Vector F = d.force;
        if (dynamics) {
            d.mass_acceleration = calc_inertial_force(row.system, N);
            F -= d.mass_acceleration;
        }
        d.projected = dot(row.direction, F);
        return d;
    }
    if (!row.about)
        throw ArgumentError("calc_row_derivation(): the rotate row for '" + to_string(row.variable) +
                            "' has no about point; give one");
    d.about_reason = about_words(sys, row);
    d.moment = sys.calc_resultant(row.system, *row.about).moment;
    if (!dynamics) {
        d.projected = dot(row.direction, d.moment);
        return d;
    }
    if (row.system.size() > detail::kAccumulatedRowBodies) {
        d.accumulated = true;
        d.projected = row.equation;
        return d;
    }
    // H^{S/O} with absolute mass-centre velocities, L^S, and the moving-point form
    d.angular_momentum = sys.calc_angular_momentum(row.system, *row.about);
    d.linear_momentum = sys.calc_linear_momentum(row.system);
    d.angular_momentum_rate = d.angular_momentum.dt_in(N);
    d.transport = cross(row.about->vel_in(N), d.linear_momentum);
    d.projected = dot(row.direction, d.moment - d.angular_momentum_rate - d.transport);
    return d;
}

}  // namespace alembert
