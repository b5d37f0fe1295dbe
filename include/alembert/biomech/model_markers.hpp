// SPDX-License-Identifier: MIT
// A planar model's coordinates from marker trajectories: segment angles, then joint angles.
#pragma once

#include <string>
#include <vector>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/segment_angles.hpp"
#include "alembert/sim/table.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

/// A marker of a model: the name it has in marker files, the body it is fixed in, and its
/// position from the model's origin N_o in the Newtonian frame, x_N = p_NoM . Nx> and
/// y_N = p_NoM . Ny>, as functions of the model's coordinates.
struct ModelMarker {
    std::string name{};
    std::string body{};
    ex x_N{}, y_N{};
};

/// How calc_coordinates_from_markers reads the markers and checks them against the model.
struct MarkerCoordinatesOptions {
    /// The lab's axes that carry the model's Nx> (horizontal) and Ny> (vertical).
    SagittalPlane plane{};
    /// The largest distance (m) allowed between a measured marker and where the model puts it
    /// at the coordinates found, after one constant shift of the lab's origin to the model's.
    double position_tolerance_m = 0.02;
    /// The largest difference (rad) allowed between a segment's angle from the file and the
    /// angle the model's marker points give at the coordinates found.
    double angle_tolerance_rad = 0.01;
};

/// The coordinates of a model over a marker trial, and how well the model fits the markers.
struct MarkerCoordinates {
    /// "t [s]" and one column per coordinate in rad, as differentiate_motion reads it.
    Table motion{};
    /// The bodies with two or more markers, whose angles gave the coordinates.
    std::vector<std::string> segments{};
    /// Per segment, how its angle in N changes with each coordinate (-1, 0 or 1): the model's
    /// sign conventions, theta_B = theta_B(0) + sum_j c_Bj q_j.
    std::vector<std::vector<int>> turns{};
    /// Per marker (in the order given), the largest distance between the measured marker and
    /// the model's over the trial, m.
    std::vector<double> marker_residual_m{};
    /// Where the model's origin N_o is in the lab (horizontal, vertical), m.
    double origin_h = 0, origin_v = 0;
    /// Per frame, each marker's distance from the model's (a marker declared on two bodies at
    /// one point once), their RMS and the largest: "time [s]", one column per marker, "rms",
    /// "max", in m (as InverseKinematicsResult::calc_residual_table).
    Table residuals{};
};

/// The coordinates q(t) of a planar model from marker trajectories: each body B with two or
/// more markers gives its angle in N, theta_B(t), from the file (calc_segment_angle from its
/// first to its second marker, or calc_segment_angle_fit of all of them); the model's own
/// marker points give theta_B(q) = atan2(y_N2 - y_N1, x_N2 - x_N1), which for a planar chain
/// rotating about Nz> is theta_B(0) + sum_j c_Bj q_j with c_Bj in {-1, 0, 1} (found from the
/// model at a reference configuration, so `rotate B from A about -z by q` counts q backwards);
/// then q solves sum_j c_Bj q_j = theta_B(t) - theta_B(0) (least squares if more segments than
/// coordinates), a turn of 2 pi taken out at the first sample. Checks, at every sample: each
/// segment's angle from the model at q agrees with the file's (options.angle_tolerance_rad),
/// and each marker lies where the model puts it, after one constant shift of origin
/// (options.position_tolerance_m); marker_residual_m reports the distances.
/// @throws alembert::ModelError naming the coordinate no segment's markers determine (a
///         length, or a joint with no markers beyond it), a coordinate that turns a segment by
///         other than +-1 (not a planar chain about Nz>), or the coordinate and marker where
///         the angle or a position disagrees with the file (a sign or an offset of the model's
///         markers against the lab's), with the time;
///         alembert::ArgumentError naming a marker the file lacks, or as calc_segment_angle.
MarkerCoordinates calc_coordinates_from_markers(const SymbolTable& table,
                                                const std::vector<TimeVariable>& q,
                                                const std::vector<ModelMarker>& markers,
                                                const MarkerTable& trial,
                                                const MarkerCoordinatesOptions& options = {});

}  // namespace alembert
