// SPDX-License-Identifier: MIT
// The report statement: the model, its road-map and what simulate and inverse computed, as HTML.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "interpreter_impl.hpp"

namespace alembert::lang {

void Interpreter::Impl::record_history(const std::string& title, const Table& table,
                                       const MotionSamples* motion) {
    ReportHistory h;
    h.title = title;
    h.table = table;
    h.coordinates = default_coordinates();
    if (motion && motion->q.size() == h.coordinates.size()) {
        h.motion = motion->q;
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

std::string Interpreter::Impl::write_report_to(const std::string& dir, const exmap& configuration,
                                               Location where, const ReportSettings& settings) {
    System& sys = model(where);
    ReportContent c;
    c.system = &sys;
    // a script named model.alb is named by its directory (examples/sit_to_stand/model.alb)
    c.title = script_name;
    if (script_name == "model" && !base_dir.empty()) {
        std::string parent = std::filesystem::path(base_dir).lexically_normal().filename().string();
        if (!parent.empty() && parent != "." && parent != "..") c.title = parent;
    }
    c.coordinates = default_coordinates();
    c.histories = histories;
    // the road-map: the last the script formed, else the planner's
    if (!last_roadmap.empty()) {
        c.rows = roadmaps.at(last_roadmap).rows;
    } else if (!c.coordinates.empty()) {
        std::vector<ex> unknowns = sys.symbols().symbols(SymbolKind::unknown);
        if (unknowns.empty())
            for (const TimeVariable& v : c.coordinates)
                unknowns.push_back(v.d(std::min(2, v.order())));
        try {
            c.rows = plan_roadmap(sys, c.coordinates, unknowns);
        } catch (const Error& e) {
            // the rest of the report stands without it
            c.notes.push_back(std::string("No road-map: the script forms none and planning one failed: ") + in_script_words(e.what()) +
                              "; form one in the script (roadmap E for ...) to see it here.");
        }
    }
    // the configuration of the diagrams: as given, else the first sample of a motion, else
    // the initial values
    for (const auto& [x, v] : numbers.initial) c.configuration[x] = v;
    for (const ReportHistory& h : histories)
        if (!h.motion.empty()) {
            for (std::size_t k = 0; k < h.coordinates.size(); ++k)
                if (!h.motion[k].empty())
                    c.configuration[h.coordinates[k].symbol()] = h.motion[k].front();
            break;
        }
    for (const auto& [x, v] : configuration) c.configuration[x] = v;
    for (const auto& [name, u] : units)
        if (u.display) c.units[name] = u.display->text;
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
