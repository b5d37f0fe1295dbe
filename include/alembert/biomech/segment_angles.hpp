// SPDX-License-Identifier: MIT
// Planar (sagittal) segment and joint angles from marker trajectories.
#pragma once

#include <string>
#include <vector>

#include "alembert/biomech/lab_files.hpp"

namespace alembert {

/// The plane of a planar analysis as two of the markers' axes (0 X, 1 Y, 2 Z of the .trc):
/// `horizontal` points forward (the direction of progression), `vertical` up. The third axis
/// h x v points at the viewer, and angles are counterclockwise about it as the viewer sees
/// them: the same sense as a model's `rotate B from N about z by q` with x forward, y up.
struct SagittalPlane {
    int horizontal = 0;
    int vertical = 1;
};

/// The angle of a segment from two of its markers: theta = atan2(p_PD . v, p_PD . h), the
/// direction of the line from marker `from` (P) to marker `to` (D) measured counterclockwise
/// from the forward axis h, in rad, one value per sample, unwrapped (consecutive samples differ
/// by less than pi, so a full turn reads 2 pi, not a jump).
/// Winter (2009, ch. 3) measures each segment from its distal marker to its proximal one (leg:
/// ankle to knee).
/// @throws alembert::ArgumentError naming a marker the table lacks, or a marker missing (NaN)
///         at a sample with its time (fill gaps first with regularize_time_base), or two
///         markers at the same place (no direction).
std::vector<double> calc_segment_angle(const MarkerTable& markers, const std::string& from,
                                       const std::string& to, SagittalPlane plane = {});

/// The angle of a segment from several of its markers by least squares: the planar rotation
/// phi_k that best carries the markers' positions at the first sample onto those at sample k
/// (both about their centroids), phi_k = atan2(sum r_i x c_i, sum r_i . c_i) (the planar case
/// of Kabsch's or Soederkvist and Wedin's fit, 1993), added to the angle from the first to the
/// second marker at the first sample. With two markers it equals calc_segment_angle of them;
/// with more, errors of single markers are averaged.
/// @throws alembert::ArgumentError for fewer than two markers, or as calc_segment_angle.
std::vector<double> calc_segment_angle_fit(const MarkerTable& markers,
                                           const std::vector<std::string>& names,
                                           SagittalPlane plane = {});

/// The angle of a joint from its segments' angles: q = sign * (theta_distal - theta_proximal),
/// the rotation of the distal segment relative to the proximal one, counterclockwise positive
/// for sign +1, which is the coordinate of a model that rotates the distal body from the
/// proximal one about the axis at the viewer (`rotate Leg from Thigh about z by qK`). Clinical
/// conventions that call knee flexion positive for a subject walking in +h use sign -1 at the
/// knee (Winter 2009, ch. 3: knee angle = theta_thigh - theta_leg).
/// @throws alembert::ArgumentError if the lengths differ or sign is not +1 or -1.
std::vector<double> calc_joint_angle(const std::vector<double>& theta_proximal,
                                     const std::vector<double>& theta_distal, int sign = 1);

}  // namespace alembert
