// SPDX-License-Identifier: MIT
// What inverse dynamics gives beyond loads: the coordinates' kinematics, each load's power, per kg.
#pragma once

#include <string>
#include <vector>

#include "alembert/mech/system.hpp"
#include "alembert/sim/motion.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// The coordinates of a motion with their rates and accelerations, as a table: "t [s]", then
/// per coordinate q, q' and q'' ("qK [rad]", "qK' [rad/s]", "qK'' [rad/s^2]"; a translation in
/// m, m/s, m/s^2). `quantities` gives each coordinate's kind in the motion's order: "angle" (a
/// rotation), "length" (a translation) or "" (no unit is written). Values are SI, as the motion
/// holds them.
/// @throws alembert::ArgumentError if `quantities` does not have one entry per coordinate, or
///         names another kind.
Table calc_coordinate_table(const MotionSamples& motion,
                            const std::vector<std::string>& quantities);

/// The rate each load measure works through, so that its power is the load times its rate.
///
/// With the generalized active forces F_r = sum v_r . F + w_r . T (u_r = q_r'; Kane & Levinson
/// 1985, eq. 5.1.1), the power of all loads is P = sum_r F_r q_r'. A load measure T_j enters
/// linearly, so the power it delivers is T_j dP/dT_j, and its rate is
///   rate_j = sum_r (dF_r/dT_j) q_r'.
/// For a joint torque T_K on the leg from the thigh about z (`torque T_K on Leg from Thigh =
/// T_K*Nz>`) the rate is w_Leg - w_Thigh about z: qK' when the leg is rotated from the thigh by
/// qK, qL' - qT' with absolute segment angles; for a force on a slider, the slider's speed. The
/// power is positive when the load does work on the model (a muscle moment generating energy,
/// concentric) and negative when it absorbs energy (eccentric), as in Winter (2009, sec. 5.2.5).
class LoadRates {
public:
    /// Forms the rates of `loads` (unknowns of the model `sys`) over the coordinates `q`.
    /// A load that does no work (a reaction at a fixed pin, or one no load holds) has rate 0.
    /// @throws alembert::ArgumentError naming a load measure the model's loads hold other than
    ///         linearly; as CompiledExpressions if a rate holds a constant without a value.
    LoadRates(const System& sys, const std::vector<TimeVariable>& q, const std::vector<ex>& loads);

    /// The rates as expressions of q and q' (in the order of the loads).
    const std::vector<ex>& rates() const { return rates_; }

    /// The powers of the load measures over a motion: "t [s]" and one column "P_<load> [W]" per
    /// column of `loads` after its time (a table calc_inverse_dynamics wrote, values in their
    /// units: N m, N, ...), P = load (SI) x rate at the motion's sample of the same time.
    /// @throws alembert::ArgumentError if `loads` has another number of load columns, a time the
    ///         motion does not hold, or a unit parse_unit does not know.
    Table calc_power_table(const Table& loads, const MotionSamples& motion) const;

private:
    std::vector<std::string> names_;
    std::vector<ex> rates_;
    std::vector<std::string> coordinates_;
    std::shared_ptr<const CompiledExpressions> tape_;  // rates of [t, q, q']
};

/// `table` with every column after the first (time) divided by `body_mass_kg`, and its unit
/// made per kg: N m -> N m/kg, N -> N/kg, W -> W/kg (gait reports compare subjects so).
/// @throws alembert::ArgumentError if the mass is not positive and finite, or a column's unit
///         is none of these (naming it).
Table calc_per_kg(const Table& table, double body_mass_kg);

}  // namespace alembert
