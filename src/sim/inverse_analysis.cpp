// SPDX-License-Identifier: MIT
// Inverse dynamics over a motion, written to torques.csv (forces.csv, loads.csv) and plotted.
#include "alembert/sim/inverse_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "alembert/error.hpp"
#include "alembert/sim/simulation.hpp"
#include "number_text.hpp"

namespace alembert {

namespace {

// "t = 0.5 s (sample 51)", "t = 0.5 to 0.52 s (samples 51-53)": runs of consecutive samples
std::string sample_runs(const std::vector<std::size_t>& samples, const std::vector<double>& t) {
    std::string out;
    std::size_t shown = 0;
    for (std::size_t a = 0; a < samples.size();) {
        std::size_t b = a;
        while (b + 1 < samples.size() && samples[b + 1] == samples[b] + 1) ++b;
        if (shown == 5) {
            out += ", ...";
            break;
        }
        out += (out.empty() ? "" : ", ") + std::string("t = ") + detail::number(t[samples[a]]);
        if (b > a) out += " to " + detail::number(t[samples[b]]);
        out += " s (sample" + std::string(b > a ? "s " : " ") + std::to_string(samples[a] + 1) +
               (b > a ? "-" + std::to_string(samples[b] + 1) : "") + ")";
        ++shown;
        a = b + 1;
    }
    return out;
}

}  // namespace

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
    if (names.empty()) names = id.load_names();
    if (units.empty()) units.assign(k, "N m");
    ALEMBERT_CHECK_ARG(
        names.size() == k && units.size() == k,
        who + "give one column name and one unit per load measure (" + std::to_string(k) + ")");
    Table table;
    table.add_column("t", "s");
    std::vector<double> factor;
    for (std::size_t j = 0; j < k; ++j) {
        for (const std::string& taken : table.names)
            ALEMBERT_CHECK_ARG(names[j] != taken,
                               who + "two columns of the table would be named '" + names[j] +
                                   "'; give the load measures distinct column names (t is the "
                                   "time column)");
        factor.push_back(parse_unit(units[j]).factor);
        table.add_column(names[j], parse_unit(units[j]).name);
    }
    // the motion satisfies the model's constraints at every sample
    std::vector<double> q(n), qd(n), qdd(n), loads(k);
    auto gather = [&](std::size_t s) {
        for (std::size_t i = 0; i < n; ++i)
            q[i] = motion.q[from[i]][s], qd[i] = motion.qd[from[i]][s],
            qdd[i] = motion.qdd[from[i]][s];
    };
    const std::vector<std::string>& constraints = id.constraint_names();
    std::vector<double> residual(constraints.size());
    std::vector<std::vector<std::size_t>> off(constraints.size());
    std::vector<double> worst(constraints.size(), 0.0);
    std::vector<std::size_t> worst_at(constraints.size(), 0);
    for (std::size_t s = 0; s < motion.t.size() && !constraints.empty(); ++s) {
        gather(s);
        id.calc_constraint_residuals(motion.t[s], q.data(), qd.data(), qdd.data(), residual.data());
        for (std::size_t c = 0; c < constraints.size(); ++c) {
            if (std::abs(residual[c]) <= options.constraint_tolerance) continue;
            off[c].push_back(s);
            if (!(std::abs(residual[c]) <= std::abs(worst[c]))) worst[c] = residual[c], worst_at[c] = s;
        }
    }
    for (std::size_t c = 0; c < constraints.size(); ++c) {
        if (off[c].empty()) continue;
        // "the configuration constraint 'loop_x'" -> loop_x, for its unit
        const std::size_t open = constraints[c].find('\''), close = constraints[c].rfind('\'');
        auto unit = options.constraint_units.find(constraints[c].substr(open + 1, close - open - 1));
        const std::string u = unit == options.constraint_units.end() ? "" : " " + unit->second;
        throw ArgumentError(who + "the motion violates " + constraints[c] + " at " +
                            std::to_string(off[c].size()) + " of " +
                            std::to_string(motion.t.size()) + " samples: " +
                            sample_runs(off[c], motion.t) + "; its largest residual is " +
                            detail::number(worst[c]) + u + " at t = " +
                            detail::number(motion.t[worst_at[c]]) + " s, beyond the tolerance " +
                            detail::number(options.constraint_tolerance) + u +
                            " (InverseAnalysisOptions::constraint_tolerance); loads of a motion "
                            "the model cannot make mean nothing: give coordinates that satisfy "
                            "the constraint (compute the dependent coordinates from it)");
    }
    // the loads at every sample; samples where they are not determined are gathered, and so
    // are those where an equation the loads were not solved from does not hold
    std::vector<std::size_t> undetermined;
    std::string first_problem, first_state;
    double worst_rcond = 1;
    const std::vector<std::string>& unused = id.unused_equation_names();
    std::vector<double> unused_out(2 * unused.size());
    std::vector<std::vector<std::size_t>> unmet(unused.size());
    std::vector<double> unmet_worst(unused.size(), 0.0), unmet_size(unused.size(), 0.0);
    std::vector<std::size_t> unmet_at(unused.size(), 0);
    for (std::size_t s = 0; s < motion.t.size(); ++s) {
        gather(s);
        double rcond = 1;
        std::string problem =
            id.try_calc_loads(motion.t[s], q.data(), qd.data(), qdd.data(), loads.data(), &rcond);
        if (!problem.empty()) {
            if (undetermined.empty())
                first_problem = problem,
                first_state = detail::describe_state(id.layout(), motion.t[s], q.data(), qd.data(),
                                                     nullptr);
            worst_rcond = std::min(worst_rcond, rcond);
            undetermined.push_back(s);
            continue;
        }
        table.columns[0].push_back(motion.t[s]);
        for (std::size_t j = 0; j < k; ++j) table.columns[j + 1].push_back(loads[j] / factor[j]);
        if (unused.empty()) continue;
        id.calc_unused_residuals(motion.t[s], q.data(), qd.data(), qdd.data(), loads.data(),
                                 unused_out.data());
        for (std::size_t e = 0; e < unused.size(); ++e) {
            const double r = unused_out[e], size = unused_out[unused.size() + e];
            if (std::abs(r) <= InverseDynamics::kUnusedEquationTolerance * size) continue;
            unmet[e].push_back(s);
            if (!(std::abs(r) <= std::abs(unmet_worst[e])))
                unmet_worst[e] = r, unmet_size[e] = size, unmet_at[e] = s;
        }
    }
    if (!undetermined.empty()) {
        std::string measures;
        for (const std::string& l : id.load_names()) measures += (measures.empty() ? "" : ", ") + l;
        throw SolveError(who + "the load measures " + measures + " are not determined at " +
                         std::to_string(undetermined.size()) + " of " +
                         std::to_string(motion.t.size()) + " samples: " +
                         sample_runs(undetermined, motion.t) + "; first: " + first_problem +
                         " at " + first_state +
                         "; the motion passes through a configuration where these loads cannot "
                         "hold it (a singular configuration, e.g. a closed loop losing rank); "
                         "no values are written: keep the motion away from it, or list loads "
                         "that act in that configuration");
    }
    for (std::size_t e = 0; e < unused.size(); ++e) {
        if (unmet[e].empty()) continue;
        std::string measures;
        for (const std::string& l : id.load_names()) measures += (measures.empty() ? "" : ", ") + l;
        throw ArgumentError(who + "the motion does not satisfy " + unused[e] + ", which the loads " +
                            measures + " were not solved from, at " + std::to_string(unmet[e].size()) +
                            " of " + std::to_string(motion.t.size()) + " samples: " +
                            sample_runs(unmet[e], motion.t) + "; its largest residual is " +
                            detail::number(unmet_worst[e]) + " (SI) at t = " +
                            detail::number(motion.t[unmet_at[e]]) + " s, against terms of size " +
                            detail::number(unmet_size[e]) +
                            "; no values of these loads make this motion: prescribe a motion the "
                            "model can make with them (simulate it), or list a load that acts on "
                            "that coordinate");
    }
    return table;
}

std::string inverse_dynamics_file_stem(const std::vector<std::string>& units) {
    bool forces = false, torques = false;
    for (const std::string& u : units) {
        std::string quantity;
        try {
            quantity = parse_unit(u).quantity;
        } catch (const ArgumentError&) {
        }
        forces = forces || quantity == "force";
        torques = torques || quantity != "force";
    }
    if (forces) return torques ? "loads" : "forces";
    return "torques";
}

InverseAnalysisReport run_inverse_dynamics(const InverseDynamics& id, const MotionSamples& motion,
                                           const std::string& out_dir,
                                           const InverseAnalysisOptions& options) {
    InverseAnalysisReport report;
    report.loads = calc_inverse_dynamics(id, motion, options);
    PlotOptions plot;
    plot.title = options.title.empty() ? "inverse dynamics of '" + id.model() + "'" : options.title;
    plot.y = options.plotted;
    plot.skip = !options.plot;
    const std::string stem = inverse_dynamics_file_stem(
        std::vector<std::string>(report.loads.units.begin() + 1, report.loads.units.end()));
    report.plot = write_table_and_plot(report.loads, out_dir, stem, plot);
    report.csv = out_dir + "/" + stem + ".csv";
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
