// SPDX-License-Identifier: MIT
// The report statement: the model, its road-map and what simulate and inverse computed, as HTML.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>

#include "alembert/eom/statics.hpp"
#include "alembert/lang/equation_units.hpp"
#include "alembert/lang/units.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

std::string Interpreter::Impl::report_file_name(const std::string& file) const {
    // the file as the script named it: relative to the output directory when inside it
    namespace fs = std::filesystem;
    const fs::path relative = fs::path(file).lexically_relative(output_dir);
    const bool inside = !relative.empty() && *relative.begin() != "..";
    return (inside ? relative : fs::path(file).lexically_normal()).generic_string();
}

void Interpreter::Impl::record_sweep(const std::string& statement, int line, const std::string& file,
                                     const Table& table, std::vector<std::string> axes) {
    ReportSweep w;
    w.file = file.empty() ? "" : report_file_name(file);
    w.title = report_history_title(statement, line, w.file);
    w.table = table;
    w.axes = std::move(axes);
    running_sweep = std::move(w);
}

void Interpreter::Impl::record_history(const std::string& statement, int line,
                                       const std::string& file, const Table& table,
                                       const MotionSamples* motion, const exmap& first_row_data) {
    ReportHistory h;
    h.file = report_file_name(file);
    h.line = line;
    h.title = report_history_title(statement, line, h.file);
    h.table = table;
    h.coordinates = default_coordinates();
    h.first_row_data = first_row_data;
    if (motion && motion->t.size() == table.row_count()) {
        // the samples of the motion, prescribed or read from a file, each coordinate by name
        for (const TimeVariable& q : h.coordinates) {
            auto it = std::find(motion->coordinates.begin(), motion->coordinates.end(), q.name());
            if (it == motion->coordinates.end()) break;
            h.motion.push_back(motion->q[static_cast<std::size_t>(it - motion->coordinates.begin())]);
        }
        if (h.motion.size() != h.coordinates.size()) h.motion.clear();
    } else {
        // a table holding every coordinate (simulate's default outputs): back to SI
        for (const TimeVariable& q : h.coordinates) {
            auto it = std::find(table.names.begin(), table.names.end(), q.name());
            if (it == table.names.end()) break;
            const auto c = static_cast<std::size_t>(it - table.names.begin());
            double factor = 1.0;
            try {
                factor = alembert::parse_unit(table.units[c]).factor;
            } catch (const ArgumentError&) {
                break;
            }
            std::vector<double> si = table.columns[c];
            for (double& v : si) v *= factor;
            h.motion.push_back(std::move(si));
        }
        if (h.motion.size() != h.coordinates.size()) h.motion.clear();
    }
    histories.push_back(std::move(h));
}

namespace {

// The model's configuration constraints (loops) closed at `configuration`: where they are
// not met there, the coordinates they hold that were not given (`given`) are solved for,
// the last ones first (a loop's dependent coordinates), from the values at hand, and
// `source` says so. A loop that cannot be closed from there is said, not fatal.
void close_loops(const System& sys, const std::vector<TimeVariable>& q, const exmap& given,
                 exmap& configuration, std::string& source) {
    const SymbolTable& st = sys.symbols();
    std::vector<ex> residuals;
    for (const Constraint& k : sys.constraints())
        if (k.kind == ConstraintKind::configuration) residuals.push_back(k.residual);
    if (residuals.empty()) return;
    exmap values;
    for (const TimeVariable& v : q) values[v.symbol()] = 0;
    for (const auto& [x, v] : configuration) values[x] = v;
    double worst = 0;
    try {
        for (const ex& r : residuals) worst = std::max(worst, std::abs(st.evaluate(r, values)));
    } catch (const Error&) {
        return;  // a loop that needs what has no value: drawn as it is
    }
    if (worst <= 1e-10) return;
    // the loops' own coordinates, the last first, as many as there are loop equations that
    // can move (those not given)
    std::vector<ex> free;
    for (auto v = q.rbegin(); v != q.rend() && free.size() < residuals.size(); ++v) {
        if (given.count(v->symbol())) continue;
        if (std::any_of(residuals.begin(), residuals.end(),
                        [&](const ex& r) { return st.depends_on(r, v->symbol()); }))
            free.push_back(v->symbol());
    }
    if (free.empty()) return;
    std::reverse(free.begin(), free.end());
    exmap fixed = values, guess;
    for (const ex& x : free) {
        guess[x] = values[x];
        fixed.erase(x);
    }
    try {
        const Equilibrium e = solve_equilibrium(st, residuals, free, guess, fixed);
        std::string names;
        for (std::size_t i = 0; i < free.size(); ++i) {
            configuration[free[i]] = e.values[i];
            names += (i ? ", " : "") + st.name(free[i]);
        }
        source += ", with " + names + " solved to close the loops";
    } catch (const Error&) {
        source += "; the loops do not close there (solve for the configuration first)";
    }
}

// Whether the points' positions make the coordinate `x` a length: it places some point from
// the point that one is located from, and every measure of a position holding it is affine in
// it, a length in the units the script declared when x is one (x Nx>, L + x; not L x, whose
// x is a number, nor sin(x)). `declared` gives the other symbols' dimensions (open where the
// script declared none, which leaves the measure unchecked and x without a unit).
bool positions_imply_length(const System& sys, const ex& x, const std::function<Dimension(const ex&)>& declared) {
    EquationUnitChecker checker(sys.symbols(),
                                [&](const ex& s) { return s.is_equal(x) ? Dimension::length() : declared(s); });
    bool placed = false;
    for (const Point* P : sys.points()) {
        if (!P->located_from()) continue;
        const Vector r = P->pos_from(*P->located_from());
        for (const auto& [F, c] : r.components())
            for (int i = 0; i < 3; ++i) {
                if (!c[i].has(x)) continue;
                if (c[i].diff(GiNaC::ex_to<GiNaC::symbol>(x)).has(x) ||
                    checker.check(c[i], Dimension::length()).verdict != ReportUnitCheck::Verdict::consistent)
                    return false;
                placed = true;
            }
    }
    return placed;
}

}  // namespace

// each road-map row's equation checked term by term in the units the script declares: N for
// a translate row, N*m for a rotate row, one unit for a constraint row; a coordinate declared
// without a unit that turns a frame is an angle (its rates in rad/s, rad/s^2)
std::vector<ReportUnitCheck> Interpreter::Impl::row_unit_checks(const System& sys,
                                                                const std::vector<RoadmapRow>& rows,
                                                                const std::vector<TimeVariable>& q,
                                                                Location where) {
    std::set<std::string> angles;
    try {
        const std::vector<std::string> kinds = coordinate_quantities(q, where);
        for (std::size_t k = 0; k < q.size() && k < kinds.size(); ++k)
            if (kinds[k] == "angle") angles.insert(q[k].name());
    } catch (const ScriptError&) {
        // a coordinate whose kind cannot be told stays without a unit
    }
    const SymbolTable& st = sys.symbols();
    EquationUnitChecker checker(st, [&](const ex& s) {
        const std::string printed = st.owns(s) ? st.name(s) : to_string(s);
        const Dimension d = symbol_dimension(printed);
        if (d.known) return d;
        const std::string base = printed.substr(0, printed.find('\''));
        if (!angles.count(base)) return d;
        return Dimension::none() / pow(Dimension::time(), static_cast<int>(printed.size() - base.size()));
    });
    std::vector<ReportUnitCheck> out;
    for (const RoadmapRow& r : rows)
        out.push_back(checker.check(r.equation, r.motion == Motion::translate ? Dimension::force()
                                                : r.motion == Motion::rotate  ? Dimension::torque()
                                                                              : Dimension::open()));
    return out;
}

std::string Interpreter::Impl::write_report_to(const std::string& dir, const exmap& configuration,
                                               Location where, const ReportSettings& settings) {
    System& sys = model(where);
    ReportContent c;
    c.system = &sys;
    // a script named model.alb is named by its directory (examples/sit_to_stand/model.alb),
    // model_X.alb by its directory and X (examples/sit_to_stand/model_lab.alb: sit_to_stand_lab)
    c.title = script_name;
    if ((script_name == "model" || script_name.starts_with("model_")) && !base_dir.empty()) {
        std::string parent = std::filesystem::path(base_dir).lexically_normal().filename().string();
        if (!parent.empty() && parent != "." && parent != "..") c.title = parent + script_name.substr(5);
    }
    c.coordinates = default_coordinates();
    c.histories = histories;
    c.results = results;
    c.equation_sets = formed_sets;
    // the road-map: the last the script formed, else the planner's
    if (!last_roadmap.empty()) {
        c.rows = roadmaps.at(last_roadmap).rows;
    } else if (!c.coordinates.empty()) {
        try {
            c.rows = plan_default_roadmap(sys, c.coordinates);
        } catch (const Error& e) {
            // the rest of the report stands without it
            std::string formed, in_rates;
            for (const ReportEquationSet& set : formed_sets) {
                formed += (formed.empty() ? "" : ", ") + set.name;
                std::string rates;
                for (const ex& u : set.unknowns) rates += (rates.empty() ? "" : ", ") + to_string(u);
                in_rates += std::string(in_rates.empty() ? "" : "; ") + set.name + " by " + set.method +
                            (rates.empty() ? "" : ", in " + rates);
            }
            const bool in_speeds = std::any_of(c.coordinates.begin(), c.coordinates.end(),
                                               [](const TimeVariable& q) { return q.order() < 2; });
            c.notes.push_back(
                !formed.empty() && in_speeds
                    ? "This model is written in generalized speeds: the page shows its equations of motion (" +
                          in_rates + ") below, in place of a road-map, whose rows are formed for coordinates "
                          "declared with their second derivatives."
                : formed.empty()
                    ? std::string("No road-map: the script forms none and planning one failed: ") +
                          in_script_words(e.what()) + "; form one in the script (roadmap E for ...) to see it here."
                    : "No road-map: the script forms none; its equations of motion (" + formed +
                          ") are below. Planning one for the accelerations failed: " + in_script_words(e.what()) + ".");
        }
    }
    // the configuration of the diagrams: as given, else where the later of the last solve and
    // the first motion puts the model, else the initial values; then the loops closed. With
    // it the rates and specified quantities that state gives (the loads that need them are
    // drawn with their values there; those it does not give, with none): the initial state's
    // rates (0 where the script gives none, as simulate starts), the solve's `at` values, the
    // data the motion's run read at its first row
    for (const TimeVariable& q : c.coordinates)
        for (int k = 1; k < q.order(); ++k) c.configuration[q.d(k)] = 0;
    for (const auto& [x, v] : numbers.initial) c.configuration[x] = v;
    c.configuration_source = "the initial values";
    auto motion = std::find_if(histories.begin(), histories.end(),
                               [](const ReportHistory& h) { return !h.motion.empty(); });
    const bool solved_last =
        !solved_configuration.empty() &&
        (motion == histories.end() ||
         solved_after_histories > static_cast<std::size_t>(motion - histories.begin()));
    const auto is_rate = [&](const ex& x) {
        return std::any_of(c.coordinates.begin(), c.coordinates.end(), [&](const TimeVariable& q) {
            for (int k = 1; k <= q.order(); ++k)
                if (x.is_equal(q.d(k))) return true;
            return false;
        });
    };
    const auto keep_coordinates = [&](const exmap& also) {
        for (auto it = c.configuration.begin(); it != c.configuration.end();)
            it = is_rate(it->first) && !also.count(it->first) ? c.configuration.erase(it) : std::next(it);
    };
    if (solved_last) {
        keep_coordinates(solved_configuration);  // the solve's state has its own rates
        for (const auto& [x, v] : solved_configuration) c.configuration[x] = v;
        c.configuration_source = "where solve at line " + std::to_string(solved_line) + " puts it";
    } else if (motion != histories.end()) {
        keep_coordinates({});  // the motion's rates are not the initial state's
        for (std::size_t k = 0; k < motion->coordinates.size(); ++k)
            if (!motion->motion[k].empty())
                c.configuration[motion->coordinates[k].symbol()] = motion->motion[k].front();
        // the data the run read at that row (a plate's force and centre of pressure)
        for (const auto& [x, v] : motion->first_row_data) c.configuration[x] = v;
        c.configuration_source = "the first sample of " + motion->title;
    }
    if (!configuration.empty()) {
        for (const auto& [x, v] : configuration) c.configuration[x] = v;
        const bool all = std::all_of(c.coordinates.begin(), c.coordinates.end(),
                                     [&](const TimeVariable& q) { return configuration.count(q.symbol()); });
        c.configuration_source = all ? "given with report at"
                                     : "given with report at, the other coordinates from " + c.configuration_source;
        // drawn at no state of the run: the rates and data (a plate's) of the state the other
        // source gives are not those of this configuration
        if (all)
            for (auto it = c.configuration.begin(); it != c.configuration.end();)
                it = !is_coordinate(it->first, 0) && !configuration.count(it->first)
                         ? c.configuration.erase(it)
                         : std::next(it);
    }
    close_loops(sys, c.coordinates, configuration, c.configuration, c.configuration_source);
    for (const auto& [x, v] : configuration) c.configuration[x] = v;
    const SymbolTable& st = sys.symbols();
    for (const auto& [name, u] : units)
        if (u.display) {
            c.units[name] = u.display->text;
            c.unit_scales[name] = u.display->scale;
        } else if (u.dim.known && !u.dim.is_none()) {
            // a data symbol declared by its dimension (a plate's chair_Fx): shown in SI
            if (st.contains(name) && st.kind(st.symbol(name)) == SymbolKind::specified)
                c.units[name] = si_unit(u.dim);
        }
    // a coordinate declared without a unit that turns a frame is an angle: shown in degrees,
    // as a reader measures a joint, not in radians; one that turns none is shown in m where
    // the positions it enters make it a length
    const auto declared = [&](const ex& s) { return symbol_dimension(st.owns(s) ? st.name(s) : to_string(s)); };
    try {
        const std::vector<std::string> kinds = coordinate_quantities(c.coordinates, where);
        for (std::size_t k = 0; k < c.coordinates.size() && k < kinds.size(); ++k) {
            const std::string& name = c.coordinates[k].name();
            if (c.units.count(name)) continue;
            if (kinds[k] == "angle") {
                c.units[name] = "deg";
                c.unit_scales[name] = std::numbers::pi / 180;
            } else if (kinds[k] == "length" && positions_imply_length(sys, c.coordinates[k].symbol(), declared)) {
                c.units[name] = "m";
            }
        }
    } catch (const ScriptError&) {
        // a coordinate whose kind cannot be told keeps SI
    }
    c.unit_checks = row_unit_checks(sys, c.rows, c.coordinates, where);
    c.plot_histories = settings.plots;
    c.plotted = settings.plotted;
    for (const std::string& name : settings.plotted) {
        bool found = false;
        for (const ReportHistory& h : histories)
            found = found || std::find(h.table.names.begin() + (h.table.names.empty() ? 0 : 1), h.table.names.end(),
                                       name) != h.table.names.end();
        if (!found)
            throw ScriptError(where, "'" + name + "' is not a column of the tables simulate and inverse wrote",
                              "plot columns of their tables (simulation.csv, torques.csv)");
    }
    if (settings.check && !settings.latex_only && !c.coordinates.empty()) {
        // the methods compared at random states; what cannot be compared is said, not fatal
        try {
            c.methods = compare_methods(sys, c.coordinates);
        } catch (const Error& e) {
            c.notes.push_back(std::string("The methods were not compared: ") + in_script_words(e.what()));
        }
        if (!sys.joint_reactions().empty()) {
            try {
                c.reactions = compare_reactions(sys, c.coordinates);
            } catch (const Error& e) {
                c.notes.push_back(std::string("The joint reactions were not compared: ") + in_script_words(e.what()));
            }
        }
    }
    if (settings.matrices && !c.coordinates.empty()) {
        // M q'' = f as simulate forms them; a model they cannot be formed for says why
        try {
            c.matrices = form_forward_equations(sys, c.coordinates);
        } catch (const Error& e) {
            c.notes.push_back(std::string("No mass matrix and forcing: ") + in_script_words(e.what()));
        }
    }
    if (settings.latex_only) return guard(where, [&] { return alembert::write_report_latex(c, dir); });
    return guard(where, [&] { return alembert::write_report(c, dir); });
}

// the `at` clause: values of coordinates and rates only
exmap Interpreter::Impl::report_configuration(const Statement& s) {
    exmap at = s.bindings.count("at") ? bindings(s.bindings.at("at"), "in 'at'") : exmap{};
    for (const auto& [x, v] : at) {
        const SymbolTable& st = model(s.location).symbols();
        if (!st.owns(x) || st.kind(x) != SymbolKind::variable)
            throw ScriptError(s.bindings.at("at").front().name.location,
                              "'" + to_string(x) + "' is not a coordinate or rate",
                              "give values to coordinates (report at qA = 20 deg)");
    }
    return at;
}

void Interpreter::Impl::report(const Statement& s) {
    if (model_only) return;
    StepIndicator busy("report: writing the page and roadmap.tex");
    const exmap at = report_configuration(s);
    ReportSettings settings;
    settings.check = s.flag("check");
    settings.matrices = s.flag("matrices");
    if (s.lists.count("plot")) {
        const std::vector<Word>& plot = s.lists.at("plot");
        if (plot.size() == 1 && plot.front().text == "none") {
            settings.plots = false;
        } else {
            // each name a column of a table simulate or inverse wrote
            std::vector<std::string> columns;
            for (const ReportHistory& h : histories)
                for (std::size_t k = 1; k < h.table.names.size(); ++k)
                    if (std::find(columns.begin(), columns.end(), h.table.names[k]) == columns.end())
                        columns.push_back(h.table.names[k]);
            for (const Word& w : plot) {
                if (std::find(columns.begin(), columns.end(), w.text) != columns.end()) {
                    settings.plotted.push_back(w.text);
                    continue;
                }
                std::string list;
                for (const std::string& c : columns) list += (list.empty() ? "" : ", ") + c;
                throw ScriptError(w.location,
                                  "'" + w.text + "' is not a column of the tables simulate and inverse wrote",
                                  columns.empty() ? std::string("run simulate or inverse before report, or write "
                                                                "'plot none'")
                                                  : "plot some of: " + list + " (or 'plot none')");
            }
        }
    }
    (void)write_report_to(output_path(s), at, s.location, settings);
    transcript.result("wrote " + (s.has_word("to") ? s.word("to").text + "/" : std::string()) +
                      "index.html");
}

void Interpreter::Impl::latex(const Statement& s) {
    if (model_only) return;
    const exmap at = report_configuration(s);
    ReportSettings settings;
    settings.latex_only = true;
    (void)write_report_to(output_path(s), at, s.location, settings);
    transcript.result("wrote " + (s.has_word("to") ? s.word("to").text + "/" : std::string()) +
                      "roadmap.tex");
}

}  // namespace alembert::lang
