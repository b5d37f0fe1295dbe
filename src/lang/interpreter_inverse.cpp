// SPDX-License-Identifier: MIT
// The inverse statement: the load measures, the motion (prescribed, a motion table, an OpenSim
// storage file or a marker trial) and the clauses for results, then one run.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "alembert/biomech/lab_files.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

// ---- inverse dynamics --------------------------------------------------------------------

void Interpreter::Impl::inverse(const Statement& s) {
    const SymbolTable& table = model(s.location).symbols();
    InverseRequest r;
    // the clauses for results: body mass and cycles, kept for `alembert inverse` in a model-only
    // run
    if (s.quantities.count("mass")) {
        const Quantity& q = s.quantities.at("mass");
        const double kg = number_of(q, Dimension::mass(), "the body mass", q.value->location);
        if (!(kg > 0) || !std::isfinite(kg))
            throw ScriptError(q.value->location, "the body mass must be positive",
                              "give the subject's mass: per kg mass 70 kg");
        r.body_mass_kg = kg;
    }
    for (const Word& w : s.lists.count("cycles") ? s.lists.at("cycles") : std::vector<Word>{}) {
        auto it = std::find_if(plates.begin(), plates.end(),
                               [&](const ScriptPlate& p) { return p.name.text == w.text; });
        if (it == plates.end())
            throw ScriptError(w.location, "'" + w.text + "' is not a plate",
                              "name plates declared with plate " + w.text +
                                  " on B from \"trial.mot\", those one foot steps on");
        r.cycle_plates.push_back(it->record);
        r.cycle_plates.back().name = w.text;  // named as the script names it
    }
    if (model_only) {
        script_inverse = r;
        return;
    }
    for (const Word& w : s.lists.at("loads")) {
        ex x = symbol(w, "a load measure");
        if (table.kind(x) != SymbolKind::unknown)
            throw ScriptError(w.location, "'" + w.text + "' is not a load measure",
                              "list unknowns declared with 'unknown' and used in loads");
        if (std::find(r.loads.begin(), r.loads.end(), x) != r.loads.end())
            throw ScriptError(w.location, "'" + w.text + "' is listed twice",
                              "list each load once");
        r.loads.push_back(x);
    }
    if (s.has_word("from")) {
        r.motion_file = input_path(s.word("from").text);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(r.motion_file, ec))
            throw ScriptError(s.word("from").location,
                              "the motion table '" + s.word("from").text + "' is not a file",
                              "paths a script reads are relative to the script's directory");
    }
    if (s.quantities.count("cutoff")) {
        const Quantity& q = s.quantities.at("cutoff");
        // a filter's cutoff counts cycles per second: 6 Hz (= 6 rev/s, 12*pi rad/s in SI) is 6
        // cycles per second, and a bare number is read in Hz
        double hz =
            number_of(q, pow(Dimension::time(), -1), "the cutoff frequency", q.value->location);
        if (!q.unit.empty() || carries_unit(*q.value)) hz /= 2 * std::numbers::pi;
        if (!(hz >= 0) || !std::isfinite(hz))
            throw ScriptError(q.value->location,
                              "the cutoff frequency must be 0 (no filter) or positive", "");
        r.cutoff_hz = hz;
    }
    r.evaluation = evaluation_of(s);
    r.dir = output_path(s);
    r.line = s.location.line;
    if (s.lists.count("plot")) r.plotted = s.lists.at("plot");
    run_inverse(r, s.location);
}

void Interpreter::Impl::run_inverse(const InverseRequest& r, Location where) {
    System& sys = model(where);
    // the motion's format, by its extension, before any work
    const std::string ext =
        r.motion_file.empty() ? "" : guard(where, [&] { return motion_format(r.motion_file); });
    const SymbolTable& table = sys.symbols();
    std::vector<TimeVariable> q = default_coordinates();
    std::string why_not;
    FunctionMaker make = function_maker(r.evaluation, &why_not);
    // force plates: their records give the plate symbols' values at each time
    std::shared_ptr<PlateInputs> plate_data = plate_inputs();
    if (plate_data) make = with_plate_inputs(make, plate_data);
    // the specified quantities a `motion` drives, with their declared derivatives: their rows
    // give the loads that drive them
    exmap specified;
    for (const auto& [x, f] : numbers.specified) {
        TimeVariable v = table.variable(table.name(x));
        ex d = f;
        for (int k = 0; k <= v.order(); ++k) {
            if (k > 0) d = guard(where, [&] { return sys.symbols().dt(d); });
            specified[v.d(k)] = d;
        }
    }
    // the hint is for a count of load measures that does not match the equations
    InverseDynamics id = guard(where, [&] {
        try {
            return compile_inverse_dynamics(sys, q, r.loads, script_name, make, specified);
        } catch (const ArgumentError& e) {
            // a specified quantity the rows need, with no motion to give it
            const std::string what = e.what();
            for (const ex& x : table.symbols(SymbolKind::specified))
                if (table.derivative_order(x) == 0 && !numbers.specified.count(x) &&
                    what.find("the specified '" + table.name(x) + "'") != std::string::npos)
                    throw ScriptError(where,
                                      "the specified quantity " + table.name(x) +
                                          " has no motion, and inverse dynamics needs it and its "
                                          "derivatives at every sample",
                                      "prescribe it with the coordinates: motion " + table.name(x) +
                                          " = ... (a formula of t)");
            if (what.find(" equations for ") == std::string::npos) throw;
            throw ScriptError(where, in_script_words(e.what()),
                              "list as many load measures as the model has coordinates, one acting "
                              "at each joint");
        }
    });
    InverseAnalysisOptions opts;
    {
        Statement plot;  // the `plot` clause against the load measures' columns
        if (!r.plotted.empty()) plot.lists["plot"] = r.plotted;
        std::vector<std::string> columns{"t"};
        for (const ex& x : r.loads) columns.push_back(table.name(x));
        PlotOptions p = plot_options_of(plot, columns);
        opts.plotted = p.y;
        opts.plot = !p.skip;
    }
    opts.filter.cutoff_hz = r.cutoff_hz;
    opts.filter.unitless_unit = r.unitless_unit;
    // the units the coordinates are declared in, against which a motion table's columns are read,
    // or for those declared without one the quantity of their kinematics (rotation: an angle)
    for (const TimeVariable& v : q) {
        std::optional<Unit> u = display_unit(v.name());
        opts.filter.declared_units.push_back(u ? u->text : "");
    }
    opts.filter.kinematic_quantities =
        guard(where, [&] { return coordinate_quantities(q, where); });
    for (const Constraint& c : sys.constraints()) {
        Dimension d =
            residual_dimension_of(table.expand_intermediates(c.residual),
                                  [&](const std::string& n) { return symbol_dimension(n); });
        if (d.known && !d.is_none()) opts.constraint_units[c.name] = si_unit(d);
    }
    for (const ex& x : r.loads) {
        std::optional<Unit> u = display_unit(table.name(x));
        std::string text = u ? u->text : "";
        try {
            alembert::parse_unit(text);
        } catch (const ArgumentError&) {
            text = "";  // a unit the CSV reader does not know: the column is in SI, unnamed
        }
        opts.units.push_back(text);
    }
    // the motion as samples of q, q', q'' (SI)
    MotionSamples samples;
    Table marker_residuals;  // a marker trial's distances from the model's markers per frame
    std::string span;
    if (ext == ".mot" || ext == ".sto") {
        // an OpenSim motion: inDegrees applies to the rotational coordinates only
        std::string note;
        const Table motion =
            guard(where, [&] { return storage_motion_table(r.motion_file, q, where, note); });
        if (!note.empty()) transcript.result(note);
        samples = guard(where, [&] {
            return differentiate_motion(motion, r.motion_file, id.layout().coordinate_names,
                                        opts.filter);
        });
        span = "the motion table " + std::filesystem::path(r.motion_file).filename().string();
    } else if (ext == ".trc" || ext == ".c3d") {
        // a marker trial (.trc, or a C3D file's markers): the coordinates from the script's
        // markers, then as a motion table
        std::string note;
        const MarkerCoordinates mc =
            guard(where, [&] { return coordinates_from_markers(r.motion_file, q, where, note); });
        const Table& motion = mc.motion;
        marker_residuals = mc.residuals;
        if (plate_data)
            plate_data->set_origin(mc.origin_h,
                                   mc.origin_v);  // the plates' centres of pressure from N_o
        transcript.result(note);
        samples = guard(where, [&] {
            return differentiate_motion(motion, r.motion_file, id.layout().coordinate_names,
                                        opts.filter);
        });
        span = "the marker trial " + std::filesystem::path(r.motion_file).filename().string();
    } else if (!r.motion_file.empty()) {
        samples = guard(where, [&] {
            return read_motion(r.motion_file, id.layout().coordinate_names, opts.filter);
        });
        span = "the motion table " + std::filesystem::path(r.motion_file).filename().string();
    } else {
        std::vector<ex> formulas;
        for (const TimeVariable& v : q) {
            auto it = numbers.motion.find(v.name());
            if (it == numbers.motion.end())
                throw ScriptError(
                    where, "no motion is prescribed for " + v.name(),
                    "prescribe every coordinate (motion " + v.name() +
                        " = ...), or read a table: inverse for ... from \"motion.csv\"");
            formulas.push_back(it->second);
        }
        const SimulationOptions& o = numbers.options;
        guard(where, [&] {
            return calc_output_row_count(o, "inverse dynamics of '" + script_name + "': ");
        });
        std::vector<double> times;
        const auto steps =
            static_cast<std::size_t>(std::floor((o.t_final - o.t_initial) / o.output_step + 1e-9));
        for (std::size_t k = 0; k <= steps; ++k)
            times.push_back(o.t_initial + static_cast<double>(k) * o.output_step);
        if (times.back() < o.t_final - 1e-12) times.push_back(o.t_final);
        samples = guard(where, [&] { return PrescribedMotion(table, q, formulas).sample(times); });
        span = "the prescribed motion";
    }
    const InverseOutputs results =
        write_inverse_results(id, samples, r, opts, q, where,
                              marker_residuals.names.empty() ? nullptr : &marker_residuals);
    const InverseAnalysisReport& rep = results.report;
    // the plates' records at the motion's first row, for the report's diagrams drawn there: a
    // plate out of contact there has no centre of pressure
    exmap first_row;
    if (plate_data && !samples.t.empty()) {
        std::vector<double> v(plate_data->symbols().size());
        guard(where, [&] { plate_data->calc_values(samples.t.front(), v.data()); });
        for (std::size_t i = 0; i + 4 < v.size(); i += 5) {
            const std::vector<ex>& s = plate_data->symbols();
            const bool contact = v[i] != 0 || v[i + 1] != 0;
            for (std::size_t j = 0; j < 5; ++j)
                if (contact || (j != 2 && j != 3)) first_row[s[i + j]] = v[i + j];
        }
    }
    record_history("inverse", r.line, rep.csv, rep.loads, &samples, first_row);
    const Table& t = rep.loads;
    std::ostringstream out;
    out << "inverse dynamics over " << span << ", t = " << transcript.number(t.columns[0].front())
        << " to " << transcript.number(t.columns[0].back()) << " s: " << t.row_count()
        << " samples";
    std::string note = evaluator_note(r.evaluation, why_not);
    if (!note.empty()) out << ", " << note;
    out << "\nwrote " << file_list(rep.plot, rep.csv);
    for (const std::string& f : results.files) out << ", " << f;
    if (!rep.plot.drawn) out << " (no plot: " << rep.plot.message << ")";
    if (!results.power_note.empty()) out << "\nno powers: " << results.power_note;
    if (!r.cycle_plates.empty()) out << "\n" << write_gait_cycles(r, results.results, where);
    if (r.body_mass_kg > 0)
        out << "\nloads and powers per kg of body mass " << transcript.number(r.body_mass_kg)
            << " kg";
    for (std::size_t c = 1; c < t.names.size(); ++c) {
        const std::vector<double>& col = t.columns[c];
        auto hi = std::max_element(col.begin(), col.end()),
             lo = std::min_element(col.begin(), col.end());
        const std::string unit = t.units[c].empty() ? "" : " " + t.units[c];
        out << "\n"
            << t.names[c] << ": largest " << transcript.number(*hi) << unit << " at t = "
            << transcript.number(t.columns[0][static_cast<std::size_t>(hi - col.begin())])
            << " s, smallest " << transcript.number(*lo) << unit << " at t = "
            << transcript.number(t.columns[0][static_cast<std::size_t>(lo - col.begin())]) << " s";
    }
    out << "\n" << format_table(t, transcript.digits());
    transcript.result(out.str());
}

}  // namespace alembert::lang
