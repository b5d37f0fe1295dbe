// SPDX-License-Identifier: MIT
// What `inverse` writes: the loads, the coordinates' kinematics and the loads' powers, as CSV
// and as OpenSim storage files, per kg of body mass when asked.
#include "alembert/biomech/inverse_results.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <utility>

#include "alembert/biomech/gait_cycles.hpp"
#include "alembert/biomech/lab_files.hpp"
#include "alembert/cleanup.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

InverseOutputs Interpreter::Impl::write_inverse_results(
    const InverseDynamics& id, const MotionSamples& samples, const InverseRequest& r,
    const InverseAnalysisOptions& opts, const std::vector<TimeVariable>& q, Location where,
    const Table* marker_residuals) {
    InverseOutputs out;
    InverseAnalysisReport& rep = out.report;
    rep.loads = guard(where, [&] { return calc_inverse_dynamics(id, samples, opts); });
    const std::string stem = inverse_dynamics_file_stem(
        std::vector<std::string>(rep.loads.units.begin() + 1, rep.loads.units.end()));
    // each load's power: the load times the rate it works through; a model whose loads' rates
    // cannot be formed or compiled still gets its loads
    Table powers;
    try {
        powers = LoadRates(model(where), q, r.loads).calc_power_table(rep.loads, samples);
    } catch (const Error& e) {
        out.power_note = in_script_words(e.what());
    }
    if (r.body_mass_kg > 0) {
        rep.loads = guard(where, [&] { return calc_per_kg(rep.loads, r.body_mass_kg); });
        if (!powers.names.empty()) powers = calc_per_kg(powers, r.body_mass_kg);
    }
    // the coordinates' kind (rotation or translation) gives the kinematics' units
    std::vector<std::string> kinds;
    for (const std::string& name : samples.coordinates) {
        std::string kind;
        for (std::size_t i = 0; i < q.size(); ++i) {
            if (q[i].name() != name) continue;
            kind = i < opts.filter.kinematic_quantities.size() ? opts.filter.kinematic_quantities[i]
                                                               : "";
            const Dimension d = symbol_dimension(name);
            if (kind.empty())
                kind = d == Dimension::length() ? "length" : d.is_none() ? "angle" : "";
        }
        kinds.push_back(kind);
    }
    const Table kinematics = guard(where, [&] { return calc_coordinate_table(samples, kinds); });
    // every result over time in one table, for the cycles
    out.results = rep.loads;
    for (const Table* t : std::array<const Table*, 2>{&kinematics, &powers})
        for (std::size_t c = 1; c < t->names.size() && t->row_count() == out.results.row_count();
             ++c) {
            out.results.add_column(t->names[c], t->units[c]);
            out.results.columns.back() = t->columns[c];
        }
    // cycles an earlier run left in the directory are not this run's (a batch pools them)
    for (int k = 1; std::filesystem::exists(r.dir + "/cycle_" + std::to_string(k) + ".csv"); ++k) {
        std::error_code ec;
        std::filesystem::remove(r.dir + "/cycle_" + std::to_string(k) + ".csv", ec);
    }
    // the loads as CSV with their plot, then every table as CSV and as OpenSim storage
    PlotOptions plot;
    plot.title = "inverse dynamics of '" + id.model() + "'";
    plot.y = opts.plotted;
    plot.skip = !opts.plot;
    guard(where, [&] {
        rep.plot = write_table_and_plot(rep.loads, r.dir, stem, plot);
        rep.csv = r.dir + "/" + stem + ".csv";
        write_storage(rep.loads, r.dir + "/" + stem + ".sto", stem);
        out.files.push_back(stem + ".sto");
        for (const auto& [name, table] :
             {std::pair<std::string, const Table*>{"kinematics", &kinematics},
              std::pair<std::string, const Table*>{"powers", &powers},
              std::pair<std::string, const Table*>{"marker_residuals", marker_residuals}}) {
            if (!table || table->names.empty()) continue;
            write_csv(*table, r.dir + "/" + name + ".csv");
            write_storage(*table, r.dir + "/" + name + ".sto", name);
            out.files.push_back(name + ".csv");
            out.files.push_back(name + ".sto");
        }
        return 0;
    });
    return out;
}

std::string Interpreter::Impl::write_gait_cycles(const InverseRequest& r, const Table& results,
                                                 Location where) {
    // the foot's events from its plates, and the cycles from strike to strike
    const GaitEvents events = guard(where, [&] { return calc_gait_events(r.cycle_plates); });
    const std::vector<GaitCycle> cycles = calc_gait_cycles(events);
    std::string names, text = "gait events from ";
    for (const ForcePlate& p : r.cycle_plates) names += (names.empty() ? "" : ", ") + p.name;
    text += names + " (vertical force crossing " +
            transcript.number(r.cycle_plates.front().contact_threshold) + " N";
    text += r.cycle_plates.size() > 1 ? " or each plate's threshold):" : "):";
    auto times = [&](const std::vector<double>& ts) {
        std::string list;
        for (double t : ts) list += (list.empty() ? "" : ", ") + transcript.number(t);
        return list.empty() ? std::string("none") : "t = " + list + " s";
    };
    text += " foot strikes at " + times(events.strikes) + "; foot offs at " + times(events.offs);
    std::string rows = "event,t [s]\n";
    std::vector<std::pair<double, std::string>> all;
    for (double t : events.strikes) all.emplace_back(t, "foot strike");
    for (double t : events.offs) all.emplace_back(t, "foot off");
    std::sort(all.begin(), all.end());
    for (const auto& [t, what] : all) rows += what + "," + format_csv_number(t) + "\n";
    guard(where, [&] {
        write_file_atomically(r.dir + "/gait_events.csv", rows, "inverse");
        return 0;
    });
    // each cycle inside the results, resampled onto 0-100 % at 101 points
    std::size_t written = 0;
    const std::vector<double>& t = results.columns[0];
    for (const GaitCycle& c : cycles) {
        const std::string span =
            transcript.number(c.start) + " to " + transcript.number(c.end) + " s";
        if (c.start < t.front() || c.end > t.back()) {
            text += "\ncycle " + span +
                    ": not inside the results (t = " + transcript.number(t.front()) + " to " +
                    transcript.number(t.back()) + " s), not written";
            continue;
        }
        const std::string file = "cycle_" + std::to_string(++written) + ".csv";
        guard(where, [&] {
            write_csv(calc_cycle_table(results, c), r.dir + "/" + file);
            return 0;
        });
        text += "\ncycle " + span;
        if (!std::isnan(c.foot_off))
            text += ", foot off at " + transcript.number(c.foot_off_percent()) + " %";
        text += ": " + file;
    }
    if (cycles.empty())
        text +=
            "\nno complete cycle (a foot strike to the next strike of the same foot) in the "
            "plates' records";
    return text;
}

}  // namespace alembert::lang
