// SPDX-License-Identifier: MIT
// Body-segment parameters from published anthropometric tables, scaled to a subject.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace alembert {

/// One row of an anthropometric table: a segment between two landmarks, its mass as a
/// fraction of body mass, its centre of mass as a fraction of its length from the proximal
/// landmark, and its radii of gyration about the centre of mass as fractions of its length.
/// A radius the source does not give is NaN.
struct SegmentRow {
    std::string_view name{};       ///< "thigh", "shank_kjc_lmal", ...
    std::string_view endpoints{};  ///< proximal-distal landmarks as the source names them
    double mass_fraction = 0;
    double com_fraction = 0;  ///< from the proximal landmark
    /// Radius of gyration about the centre of mass for rotation about the medio-lateral axis
    /// (flexion-extension, the sagittal plane's rotation).
    double rg_flexion = 0;
    /// About the antero-posterior axis (ab-adduction) and the long axis; NaN if not given.
    double rg_abduction = 0;
    double rg_long = 0;
};

/// A published table of segment parameters.
struct SegmentTable {
    std::string_view key{};     ///< "winter", "de_leva_male", "de_leva_female"
    std::string_view source{};  ///< the citation
    std::string_view note{};    ///< how its values are read (landmarks, axes)
    std::vector<SegmentRow> rows{};
};

/// The table named `key`: "winter" (Dempster's cadaver data as tabulated by Winter 2009,
/// Table 4.1), "de_leva_male" or "de_leva_female" (de Leva 1996, Table 4: Zatsiorsky and
/// Seluyanov's gamma-scanner data adjusted to joint centres).
/// @throws alembert::ArgumentError for another key, listing the known ones.
const SegmentTable& segment_table(std::string_view key);

/// Every table's key, in the order above.
std::vector<std::string_view> segment_table_keys();

/// A segment's parameters for one subject.
struct SegmentParameters {
    std::string name{};
    double mass = 0;          ///< kg
    double length = 0;        ///< m
    double com_distance = 0;  ///< from the proximal landmark, m
    double inertia_flexion = 0;  ///< about the centre of mass, medio-lateral axis, kg m^2
};

/// Scales a table row to a subject: m = mass_fraction * body_mass,
/// r_com = com_fraction * length, I = m (rg_flexion * length)^2 (Winter 2009, sec. 4.1).
/// @throws alembert::ArgumentError naming the segment if the table has no such row (listing
///         its rows), or if body_mass or length is not positive.
SegmentParameters calc_segment_parameters(const SegmentTable& table, std::string_view segment,
                                          double body_mass, double length);

/// The table as text for a transcript: its source and note, then one row per segment with
/// its landmarks and fractions (the radii as the source gives them).
std::string format_segment_table(const SegmentTable& table);

}  // namespace alembert
