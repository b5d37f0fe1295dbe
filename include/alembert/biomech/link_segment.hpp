// SPDX-License-Identifier: MIT
// Inverse dynamics of a planar chain of segments from joint positions and external loads.
#pragma once

#include <string>
#include <vector>

#include "alembert/biomech/force_plate.hpp"
#include "alembert/biomech/segment_angles.hpp"

namespace alembert {

/// A segment of a planar chain over a trial: its inertial parameters and the positions of its
/// proximal joint P and distal joint D in the plane (h forward, v up; m) at every sample, as
/// filtered marker or joint-centre trajectories.
struct ChainSegment {
    std::string name{};            ///< "leg"
    std::string proximal_joint{};  ///< the joint at P: "knee"
    double mass = 0;               ///< kg
    double com_fraction = 0;       ///< the centre of mass G is at P + com_fraction (D - P)
    double inertia = 0;            ///< about G, for rotation in the plane, kg m^2
    std::vector<double> p_h{}, p_v{}, d_h{}, d_v{};
};

/// An external load in the plane on the most distal segment, per sample: the force (N), its
/// point of application (m) and a free moment about the axis at the viewer (N m).
struct PlanarLoad {
    std::vector<double> F_h{}, F_v{}, p_h{}, p_v{}, M{};
};

/// A plate's record in the plane: its force and centre of pressure, and its free moment about
/// the axis at the viewer (h x v); all zero at samples out of contact (ForcePlate::in_contact),
/// so the load switches off when the foot leaves the plate.
PlanarLoad planar_load_from_plate(const ForcePlate& plate, SagittalPlane plane = {});

/// The sum of several plates' loads on one segment (a foot across two plates) as one
/// statically equivalent load: the forces add, the point is where the total's line of action
/// crosses the height of the first plate's centre of pressure, and the moment left is zero
/// (or, where the total vertical force is zero, the point is h = 0 and the moment is the
/// total's moment about it).
/// @throws alembert::ArgumentError if the loads have different lengths.
PlanarLoad combine_loads(const std::vector<PlanarLoad>& loads);

/// The loads at one joint over a trial: the force and moment on the segment below the joint
/// (distal) from the one above, and the joint's power.
struct JointLoads {
    std::string joint{};
    std::vector<double> F_h{}, F_v{}, M{};
    /// M (w_distal - w_proximal): positive when the joint's muscles generate energy; empty for
    /// the chain's top joint (the segment above it is not in the chain).
    std::vector<double> power{};
};

/// Bottom-up Newton-Euler inverse dynamics of a planar link-segment model (Winter 2009, ch.
/// 5): for each segment from the distal end, with a_G and alpha from the positions (G's
/// position and the angle of D->P, differentiated twice by central differences at spacing
/// dt), and F_D, M_D the load at its distal end (the external load on the first segment,
/// minus the joint load found for the segment below otherwise):
///   F_P = m a_G - m g - F_D,
///   M_P = I alpha - M_D - (r_D - r_G) x F_D - (r_P - r_G) x F_P,
/// with g = (0, -gravity) and a x b = a_h b_v - a_v b_h. `chain` runs from the distal segment
/// to the proximal one; `external` may be null (no contact, as in the swing phase).
/// @throws alembert::ArgumentError if the chain is empty, a segment's samples differ in number
///         (naming it), the external load has another length, or there are fewer than 4.
std::vector<JointLoads> calc_inverse_dynamics_bottom_up(const std::vector<ChainSegment>& chain,
                                                        double dt, const PlanarLoad* external,
                                                        double gravity = 9.81);

/// Top-down inverse dynamics of the same chain: from the proximal segment, whose load at its
/// proximal joint is `top` (null: a free end, no load), each segment's distal load follows from
///   F_D = m a_G - m g - F_P,   M_D = I alpha - M_P - (r_P - r_G) x F_P - (r_D - r_G) x F_D,
/// and is passed down, reversed, to the segment below. Returns the joint loads in the same order
/// and convention as the bottom-up solution (load on the segment below each joint), then one
/// more entry, "ground", with the load the data predict on the distal segment at its distal
/// point D; with a measured external load, the bottom-up and top-down results differ by the
/// inconsistency of the data (markers, segment parameters, plate): see
/// calc_top_down_residual.
/// @throws as calc_inverse_dynamics_bottom_up.
std::vector<JointLoads> calc_inverse_dynamics_top_down(const std::vector<ChainSegment>& chain,
                                                       double dt, const PlanarLoad* top,
                                                       double gravity = 9.81);

/// The residual of the classic consistency check: the external load that the top-down solution
/// predicts at the distal segment's point D minus the measured one (moved to D: M + (r_CoP -
/// r_D) x F), per sample, as a JointLoads named "residual" (force and moment; no power).
/// Zero for consistent data.
/// @throws alembert::ArgumentError if the lengths differ.
JointLoads calc_top_down_residual(const std::vector<JointLoads>& top_down,
                                  const ChainSegment& distal_segment, const PlanarLoad* measured);

/// The loads divided by the body mass (N/kg, N m/kg, W/kg), as gait reports show them.
/// @throws alembert::ArgumentError if body_mass is not positive.
void normalize_by_body_mass(std::vector<JointLoads>& loads, double body_mass);

}  // namespace alembert
