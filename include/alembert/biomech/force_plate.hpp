// SPDX-License-Identifier: MIT
// Force-plate records: force, centre of pressure and free moment, switched on by contact.
#pragma once

#include <string>
#include <vector>

#include "alembert/sim/table.hpp"

namespace alembert {

/// One force plate's record in SI, in the lab's axes: the ground reaction force on the body
/// F (N), its point of application, the centre of pressure p_CoP (m), and the free moment T
/// about the vertical (N m), per sample at the times t (s).
struct ForcePlate {
    std::string name{};
    std::vector<double> t{};
    std::vector<double> F[3]{}, p_CoP[3]{}, T_free[3]{};
    /// Below this force magnitude (N) the body is not in contact: the plate's load is zero and
    /// its centre of pressure (noise divided by a small force) is not used.
    double contact_threshold = 20;

    /// Whether the body touches the plate at sample k (|F| >= contact_threshold).
    /// @throws alembert::ArgumentError naming the plate, the sample and its time if the force
    ///         there is missing (NaN): a missing force is not "no contact".
    bool in_contact(std::size_t k) const;
};

/// The plate whose columns in `table` start with `prefix`, as OpenSim's ground-reaction .mot
/// files name them: PREFIX_vx, _vy, _vz (force), PREFIX_px, _py, _pz (centre of pressure) and,
/// with "force" replaced by "torque" in the prefix, TPREFIX_x, _y, _z (free moment); e.g.
/// "ground_force" gives ground_force_vx ... ground_torque_z, and "1_ground_force" the second
/// plate. Columns without units are read in SI (N, m, N m); with units they are converted.
/// Time is the first column. A missing sample (NaN) of a force column is refused, since it
/// would read as no contact; of a centre-of-pressure or free-moment column it is refused in
/// contact and left alone out of contact (where exporters write NaN and the value is not used).
/// `source` names the table in messages (the file's path; with table.lines, its line).
/// @throws alembert::ArgumentError naming the plate's missing columns; or "source:line: plate
///         'P': column 'C' has no value (NaN) at t = ... s" for a missing sample as above.
ForcePlate force_plate_from_table(const Table& table, const std::string& prefix,
                                  double contact_threshold = 20, const std::string& source = "");

}  // namespace alembert
