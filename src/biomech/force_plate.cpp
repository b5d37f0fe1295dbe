// SPDX-License-Identifier: MIT
// Force-plate records from OpenSim-named columns.
#include "alembert/biomech/force_plate.hpp"

#include <cmath>

#include "alembert/error.hpp"

namespace alembert {

bool ForcePlate::in_contact(std::size_t k) const {
    // a missing force is not "no contact": NaN fails every comparison (and the three-argument
    // hypot may drop it), so it is refused here
    if (std::isnan(F[0][k]) || std::isnan(F[1][k]) || std::isnan(F[2][k]))
        throw ArgumentError("ForcePlate::in_contact(): plate '" + name + "' has no force (NaN) at sample " +
                            std::to_string(k + 1) + (k < t.size() ? " (t = " + format_csv_number(t[k]) + " s)" : "") +
                            "; a missing sample cannot tell contact from none: fill the gap in the lab's "
                            "software, or trim the trial");
    return std::hypot(F[0][k], F[1][k], F[2][k]) >= contact_threshold;
}

ForcePlate force_plate_from_table(const Table& table, const std::string& prefix,
                                  double contact_threshold, const std::string& source) {
    ForcePlate plate;
    plate.name = prefix;
    plate.contact_threshold = contact_threshold;
    std::string torque = prefix;
    if (auto at = torque.find("force"); at != std::string::npos) torque.replace(at, 5, "torque");
    // a column in SI, or the names of those missing
    std::string missing;
    std::vector<std::string> names[3];  // the columns of F, p_CoP, T_free
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
        names[0].push_back(prefix + "_v" + axes[i]);
        names[1].push_back(prefix + "_p" + axes[i]);
        names[2].push_back(torque + "_" + axes[i]);
        plate.F[i] = column(names[0].back());
        plate.p_CoP[i] = column(names[1].back());
        plate.T_free[i] = column(names[2].back());
    }
    if (!missing.empty())
        throw ArgumentError("force_plate_from_table(): plate '" + prefix + "' lacks the columns " +
                            missing + "; name them as OpenSim's ground-reaction files do, or give "
                            "the prefix the file uses");
    plate.t = table.columns.at(0);
    const double tf = parse_unit(table.units[0]).factor;
    for (double& x : plate.t) x *= tf;

    // missing samples (NaN): a force never (it would read as no contact); a centre of pressure
    // or free moment only out of contact, where they are not used
    auto refuse = [&](const std::string& label, std::size_t k, const std::string& why) {
        const std::string where = (source.empty() ? std::string("force_plate_from_table()") : source) +
                                  (k < table.lines.size() ? ":" + std::to_string(table.lines[k]) : "") + ": ";
        throw ArgumentError(where + "plate '" + prefix + "': column '" + label + "' has no value (NaN) at t = " +
                            format_csv_number(plate.t[k]) + " s" + why +
                            "; fill the gap in the lab's software (or export it with the plate's values), "
                            "or trim the trial to where the plate's record is complete");
    };
    for (std::size_t k = 0; k < plate.t.size(); ++k) {
        for (int i = 0; i < 3; ++i)
            if (std::isnan(plate.F[i][k]))
                refuse(names[0][i], k, ", where a missing force would be read as no contact");
        if (std::hypot(plate.F[0][k], plate.F[1][k], plate.F[2][k]) < contact_threshold) continue;
        for (int i = 0; i < 3; ++i) {
            if (std::isnan(plate.p_CoP[i][k])) refuse(names[1][i], k, ", during contact");
            if (std::isnan(plate.T_free[i][k])) refuse(names[2][i], k, ", during contact");
        }
    }
    return plate;
}

}  // namespace alembert
