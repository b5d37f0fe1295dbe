// SPDX-License-Identifier: MIT
// Simple rotations and three-angle sequences as rotation matrices.
#pragma once

#include <string>

#include "alembert/sym/matrix.hpp"

namespace alembert {

/// A coordinate axis of a frame.
enum class Axis { x, y, z };

/// Sense of a simple rotation: right-handed (positive) or left-handed (negative) about the axis.
enum class Sense { positive, negative };

/// Three-angle rotation sequences: six Tait-Bryan (all axes differ) and six Euler (first and
/// last axis equal) sequences.
enum class RotationSequence { XYZ, XZY, YXZ, YZX, ZXY, ZYX, XYX, XZX, YXY, YZY, ZXZ, ZYZ };

/// Parses "XYZ", "zxz", ... into a sequence.
/// @throws alembert::ArgumentError naming the text and the accepted names.
RotationSequence parse_rotation_sequence(const std::string& text);
/// The name of a sequence ("XYZ").
std::string to_string(RotationSequence seq);
/// The three axes of a sequence, in order.
std::array<Axis, 3> axes_of(RotationSequence seq);
/// The index 0, 1, 2 of an axis.
inline int index_of(Axis a) { return static_cast<int>(a); }

/// R_PB of a simple rotation of B relative to P by `angle` about their common axis:
/// [v]_P = R_PB [v]_B, so its columns are B's unit vectors expressed in P (Kane 1985, 1.6).
Mat3 simple_rotation(Axis axis, const ex& angle);

}  // namespace alembert
