// SPDX-License-Identifier: MIT
// When derived kinematic vectors of long chains are rewritten in one frame with named measures.
#pragma once

#include <cstddef>

#include "alembert/vec/vector.hpp"

namespace alembert {

/// A derived kinematic vector (an angular velocity, a point's velocity or acceleration) and
/// whether it is in compact form.
///
/// Short chains keep the textbook form: a vector stays a sum of parts in the frames it was
/// written in (L_A qA' Ax> + L_B (qA' + qB') Bx>), unnamed. Long chains would grow without
/// bound that way, so a vector that spans more than kReadableFrames frames, or that is formed
/// from a compact one, is rewritten in one frame with each measure larger than
/// kCompactNameOps operations named as an intermediate (solve-level symbols such as q'' kept
/// explicit, see SymbolTable::name_if_large). Formed outward body by body, every measure of a
/// chain then stays a few operations on the measures of its parent, and the size of a chain's
/// kinematics grows linearly in its length.
struct FormedVector {
    Vector value;
    bool compact = false;
};

/// Frames a derived vector may span before it is put in compact form.
inline constexpr std::size_t kReadableFrames = 3;
/// Measures of compact vectors larger than this are named.
inline constexpr std::size_t kCompactNameOps = 20;

/// `v` itself (not compact) if it spans at most kReadableFrames frames and `from_compact` is
/// false; otherwise `v` written in frame E with its large measures named (compact).
FormedVector form_compact_if_long(const Vector& v, const Frame& E, bool from_compact);

}  // namespace alembert
