// SPDX-License-Identifier: MIT
// Force-plate records from OpenSim-named columns.
#include "alembert/biomech/force_plate.hpp"

#include <cmath>

#include "alembert/error.hpp"

namespace alembert {

bool ForcePlate::in_contact(std::size_t k) const {
    return std::hypot(F[0][k], F[1][k], F[2][k]) >= contact_threshold;
}

ForcePlate force_plate_from_table(const Table& table, const std::string& prefix,
                                  double contact_threshold) {
    ForcePlate plate;
    plate.name = prefix;
    plate.contact_threshold = contact_threshold;
    std::string torque = prefix;
    if (auto at = torque.find("force"); at != std::string::npos) torque.replace(at, 5, "torque");
    // a column in SI, or the names of those missing
    std::string missing;
    auto column = [&](const std::string& name) {
        for (std::size_t c = 0; c < table.names.size(); ++c)
            if (table.names[c] == name) {
                std::vector<double> v = table.columns[c];
                const double factor = parse_unit(table.units[c]).factor;
                for (double& x : v) x *= factor;
                return v;
            }
        missing += (missing.empty() ? "" : ", ") + name;
        return std::vector<double>(table.row_count(), 0.0);
    };
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        plate.F[i] = column(prefix + "_v" + axes[i]);
        plate.p_CoP[i] = column(prefix + "_p" + axes[i]);
        plate.T_free[i] = column(torque + "_" + axes[i]);
    }
    if (!missing.empty())
        throw ArgumentError("force_plate_from_table(): plate '" + prefix + "' lacks the columns " +
                            missing + "; name them as OpenSim's ground-reaction files do, or give "
                            "the prefix the file uses");
    plate.t = table.columns.at(0);
    const double tf = parse_unit(table.units[0]).factor;
    for (double& x : plate.t) x *= tf;
    return plate;
}

}  // namespace alembert
