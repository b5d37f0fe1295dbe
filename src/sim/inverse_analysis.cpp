// SPDX-License-Identifier: MIT
// Inverse dynamics over a motion, written to torques.csv and plotted.
#include "alembert/sim/inverse_analysis.hpp"

#include <algorithm>

#include "alembert/error.hpp"
#include "alembert/sim/simulation.hpp"

namespace alembert {

Table calc_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                            const InverseAnalysisOptions& options) {
    const std::string who = "calc_inverse_dynamics('" + id.model() + "'): ";
    const std::size_t n = id.coordinate_count(), k = id.load_count();
    // where each model coordinate sits in the motion
    std::vector<std::size_t> from;
    for (const std::string& name : id.layout().coordinate_names) {
        auto it = std::find(motion.coordinates.begin(), motion.coordinates.end(), name);
        ALEMBERT_CHECK_ARG(it != motion.coordinates.end(),
                           who + "the motion has no coordinate '" + name +
                               "'; give it a column named '" + name + "'");
        from.push_back(static_cast<std::size_t>(it - motion.coordinates.begin()));
    }
    std::vector<std::string> names = options.columns, units = options.units;
    if (names.empty())
        for (std::string s : id.load_names()) {
            s.erase(std::remove(s.begin(), s.end(), '_'), s.end());
            names.push_back(s);
        }
    if (units.empty()) units.assign(k, "N m");
    ALEMBERT_CHECK_ARG(
        names.size() == k && units.size() == k,
        who + "give one column name and one unit per load measure (" + std::to_string(k) + ")");
    Table table;
    table.add_column("t", "s");
    std::vector<double> factor;
    for (std::size_t j = 0; j < k; ++j) {
        factor.push_back(parse_unit(units[j]).factor);
        table.add_column(names[j], parse_unit(units[j]).name);
    }
    // the loads at every sample
    std::vector<double> q(n), qd(n), qdd(n), loads(k);
    for (std::size_t s = 0; s < motion.t.size(); ++s) {
        for (std::size_t i = 0; i < n; ++i)
            q[i] = motion.q[from[i]][s], qd[i] = motion.qd[from[i]][s],
            qdd[i] = motion.qdd[from[i]][s];
        id.calc_loads(motion.t[s], q.data(), qd.data(), qdd.data(), loads.data());
        table.columns[0].push_back(motion.t[s]);
        for (std::size_t j = 0; j < k; ++j) table.columns[j + 1].push_back(loads[j] / factor[j]);
    }
    return table;
}

InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options) {
    InverseAnalysisReport report;
    report.loads = calc_inverse_dynamics(id, motion, options);
    PlotOptions plot;
    plot.title = options.title.empty() ? "inverse dynamics of '" + id.model() + "'" : options.title;
    report.plot = write_table_and_plot(report.loads, out_dir, "torques", plot);
    report.csv = out_dir + "/torques.csv";
    return report;
}

InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const std::string& motion_csv,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options) {
    return run_inverse_dynamics(
        id, read_motion(motion_csv, id.layout().coordinate_names, options.filter), out_dir,
        options);
}

}  // namespace alembert
