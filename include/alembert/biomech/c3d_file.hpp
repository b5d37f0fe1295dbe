// SPDX-License-Identifier: MIT
// C3D motion-capture files: markers, analog channels and force plates in SI, read with checks.
#pragma once

#include <string>
#include <vector>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// One force plate of a C3D file's FORCE_PLATFORM group, its geometry in SI.
struct C3dForcePlate {
    int type = 0;                       ///< TYPE: 1, 2, 3 or 4
    double corners[4][3]{};             ///< CORNERS in the lab, m (corner 1 in the plate's +x +y quadrant)
    double origin[3]{};                 ///< ORIGIN in the plate's axes, m (z < 0: below the surface)
    std::vector<std::size_t> channels{};  ///< CHANNEL: the analog columns (1-based, as analog's columns)
    std::vector<double> cal_matrix{};   ///< type 4: CAL_MATRIX, 36 values, element (r, c) at r + 6 c
    int zero[2]{0, 0};                  ///< ZERO: the frames whose mean is the baseline (0: none)
};

/// What a C3D file holds, in SI. Times are t_k = (first frame - 1 + k) / POINT:RATE, so a
/// trial that starts at frame 1 starts at t = 0.
struct C3dFile {
    /// The markers (POINT group) as read_trc gives them: "time" [s], then per label M the
    /// columns "M.X", "M.Y", "M.Z" [m] from POINT:UNITS (mm, cm, m); a point whose residual word
    /// is negative (invalid, a gap) is NaN at that frame. data_rate_hz is POINT:RATE and
    /// file_unit POINT:UNITS.
    MarkerTable markers{};
    /// The analog channels (ANALOG group) at ANALOG:RATE: "time" [s], then one column per
    /// channel named by ANALOG:LABELS, in ANALOG:UNITS, scaled as
    /// (value - OFFSET) * SCALE * GEN_SCALE.
    Table analog{};
    double analog_rate_hz = 0;
    std::size_t analog_per_frame = 0;  ///< analog samples per marker frame
    std::string processor{};           ///< "Intel", "DEC" or "MIPS" (big-endian)
    bool float_data = false;           ///< POINT:SCALE < 0: data stored as floats
    std::vector<C3dForcePlate> plates{};  ///< FORCE_PLATFORM:USED plates
    /// The plates' ground reaction on the body at the marker frames, as OpenSim's
    /// ground-reaction .mot files name its columns (force_plate_from_table reads it): plate 1
    /// "ground_force", plate 2 "1_ground_force", ...: PREFIX_vx/vy/vz (N), _px/py/pz (m),
    /// TORQUE_x/y/z (N m, the free moment), in the lab's axes. See calc_c3d_ground_forces.
    Table forces{};
    /// Things a reader should know that are not errors (a baseline subtracted, a unit assumed),
    /// one sentence each; markers.notes holds them too.
    std::vector<std::string> notes{};
};

/// Reads a C3D file as C3D.org's "C3D File Format User Guide" describes it: 512-byte blocks;
/// the header (first parameter block, points, analog samples per frame, first and last frame,
/// scale factor, data start block, frame rate); the parameter section (groups and parameters,
/// processor type 84 Intel, 85 DEC, 86 MIPS); the data, integer (POINT:SCALE > 0: coordinates
/// are the stored words times the scale) or floating point (scale < 0). Parameters read: POINT
/// USED, LABELS (LABELS2, ...), UNITS, RATE; ANALOG USED, LABELS (LABELS2, ...), UNITS, RATE,
/// SCALE, GEN_SCALE, OFFSET, FORMAT (SIGNED/UNSIGNED); FORCE_PLATFORM USED, TYPE, ZERO,
/// CORNERS, ORIGIN, CHANNEL, CAL_MATRIX. A label named twice gets "_2", "_3" (a note says so).
/// The frames are the header's first to last; where the data hold fewer and POINT:FRAMES fits
/// them (an exporter that left the header's last frame wrong), POINT:FRAMES frames are read
/// from the header's first, and a note says so.
/// @throws alembert::ArgumentError "path: what is wrong (byte N); how to fix it" for a file
///         that cannot be opened, is not a C3D file, is truncated (the block or frame that
///         runs past its end), has a parameter block pointer past the end, an unknown processor
///         type, a parameter whose size runs past its section, a rate that is not positive, a
///         point unit that is not a length, a force plate of a type other than 1-4 or with a
///         channel outside the analog channels (naming the plate).
C3dFile read_c3d(const std::string& path);

/// The plates' ground reaction on the body at the marker frames (C3dFile::forces), from the
/// analog channels and each plate's corners and origin, following the C3D guide:
///  - the plate's axes from its corners (corner 1 in the +x +y quadrant, 2 in -x +y, 3 in
///    -x -y, 4 in +x -y): x along (c1 + c4 - c2 - c3), z = x × (c1 + c2 - c3 - c4), y = z × x;
///    its surface centre S the corners' mean;
///  - the channels, in the plate's axes, are the ground's reaction on the body (its force F
///    and moment M), as capture systems write them and C3D readers (BTK, ezc3d, Visual3D) take
///    them: under a standing subject Fz, along the plate's downward z, is negative; the table
///    holds F and the free moment T taken into the lab's axes;
///  - type 2: Fx, Fy, Fz, Mx, My, Mz, the moment about the plate's origin O, ORIGIN the vector
///    from O to S in the plate's axes; type 4: the same after the calibration matrix
///    (CAL_MATRIX times the six channels, the channels' units read as those of its outputs); type 3 (eight channels Fx12, Fx34, Fy14, Fy23,
///    Fz1..Fz4 of four sensors at (±a, ±b) with a, b = ORIGIN(1), ORIGIN(2)): F and the moment
///    about the sensors' centre, directly below S at depth ORIGIN(3), then as type 2; in each,
///    the centre of pressure is where the line of F meets the surface (z = ORIGIN(3) from O):
///    px = (oz Fx - My) / Fz, py = (Mx + oz Fy) / Fz, and the free moment
///    T = Mz - (px Fy - py Fx) about the plate's z;
///  - type 1: Fx, Fy, Fz, the centre of pressure X, Y from S in the plate's axes (in
///    POINT:UNITS, or the channel's length unit), and the free moment Tz;
///  - an ORIGIN with z > 0 (the older convention, O above the surface) is negated, and a note
///    says so; moments in N mm or N m by their ANALOG:UNITS ("Nmm", "N.mm", "Nm", ...), else
///    N times POINT:UNITS (a note says so); forces in N (another unit: a note);
///  - FORCE_PLATFORM:ZERO (first, last) with first >= 1: each channel's mean over those
///    frames (counted from the file's first frame) is subtracted, and a note says so;
///  - the analog samples of frame k are its analog_per_frame samples from k * analog_per_frame
///    on, the first at the frame's time; each channel is averaged over one frame period
///    centred on the frame's time (n + 1 samples for an even n, the two end ones weighted 1/2;
///    fewer at the ends of the trial), and the centre of pressure is computed from the averaged
///    channels (so it is the load's, not an average of ratios);
///  - a sample with Fz = 0 has no centre of pressure (NaN), as out of contact.
/// @throws alembert::ArgumentError naming the plate for a type other than 1-4, too few
///         channels, or a type 4 plate without CAL_MATRIX.
Table calc_c3d_ground_forces(const C3dFile& file, const std::string& source,
                             std::vector<std::string>& notes);

}  // namespace alembert
