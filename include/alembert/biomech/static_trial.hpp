// SPDX-License-Identifier: MIT
// A segment's length from a static trial: the mean distance between its two joint-centre markers.
#pragma once

#include <string>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/segment_angles.hpp"

namespace alembert {

/// A segment's length measured on a trial, and how steady the measurement was.
struct StaticLength {
    std::string from{}, to{};     ///< the two markers (the segment's joint centres)
    double length_m = 0;          ///< the mean distance between them, m
    double sd_m = 0;              ///< its standard deviation over the frames, m
    double max_deviation_m = 0;   ///< the largest |distance - mean| at one frame, m
    double max_deviation_t = 0;   ///< the time of that frame, s
    std::size_t frames = 0;       ///< the frames where both markers are seen
};

/// How calc_static_length accepts a trial.
struct StaticLengthOptions {
    /// The largest |distance - mean| allowed at a frame (m): two markers on one rigid segment
    /// keep their distance up to the noise and the skin's motion.
    double max_deviation_m = 0.01;
};

/// The length of a segment as the distance between two markers at its joint centres, in
/// space (sqrt(dX^2 + dY^2 + dZ^2)), averaged over the frames of `trial` where both are seen
/// (a frame with either missing, NaN, is left out): the step of OpenSim's Scale tool that
/// measures a segment on a static trial (there as a ratio to the generic model's length; here
/// the length itself, for a model stated with its lengths).
/// @throws alembert::ArgumentError naming a marker the trial lacks (and listing its markers),
///         a marker given twice, no frame where both are seen, two markers at one place, or
///         a frame where the distance departs from the mean by more than
///         options.max_deviation_m (naming the time: the markers are not on one segment, or
///         one was swapped or slid).
StaticLength calc_static_length(const MarkerTable& trial, const std::string& from, const std::string& to,
                                const StaticLengthOptions& options = {});

/// A marker's place in a planar segment's frame, measured on a trial.
struct StaticPlace {
    std::string marker{};
    double along_m = 0;          ///< mean of (M - P) . u, m
    double across_m = 0;         ///< mean of (M - P) . n, m
    double sd_along_m = 0, sd_across_m = 0;  ///< their standard deviations over the frames, m
    std::size_t frames = 0;      ///< the frames where the three markers are seen
};

/// Where marker M sits in a segment, in the plane `plane`, from a (static) trial: with P and D
/// the segment's markers `from` and `to` (its joint centres), u the unit vector from P to D
/// in the plane and n = u turned a quarter turn counterclockwise (about h x v, the axis at the
/// viewer), along = (M - P) . u and across = (M - P) . n, each averaged over the frames where
/// the three markers are seen. A model whose segment B has its origin at P, Bx> along u and
/// By> along n puts M at along*Bx> + across*By> (a thigh stated hanging along -Thighy> from the
/// hip, Thighx> forward, has u = -Thighy> and n = Thighx>: M at across*Thighx> - along*Thighy>).
/// @throws alembert::ArgumentError as calc_static_length for the markers, for no frame that
///         sees all three, or for P and D at one place.
StaticPlace calc_static_place(const MarkerTable& trial, const std::string& from, const std::string& to,
                              const std::string& marker, SagittalPlane plane = {});

}  // namespace alembert
