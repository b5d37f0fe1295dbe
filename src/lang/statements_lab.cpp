// SPDX-License-Identifier: MIT
// Lab files in a script's model: `marker NAME on B at P` declares a point of the model as the
// marker a .trc file names, so a marker trial gives the model's coordinates.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "alembert/biomech/c3d_file.hpp"
#include "alembert/biomech/inverse_kinematics.hpp"
#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/model_markers.hpp"
#include "alembert/biomech/plate_load.hpp"
#include "alembert/biomech/time_base.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// ---- grammar -----------------------------------------------------------------------------

void parse_marker(StatementParser& p, Statement& s) {
    // the name as the marker file has it: a name, or any text in double quotes ("R.Knee")
    s.words["name"] = p.peek().kind == TokenKind::string ? p.text("the marker's name in the .trc file")
                                                         : p.name("the marker's name in the .trc file");
    p.expect_word("on", "(marker KNEE on A at B_o)");
    s.words["on"] = p.name("the body the marker is fixed in");
    p.expect_word("at", "(marker KNEE on A at B_o)");
    s.words["at"] = p.name("a point of the model");
    // the marker's weight in the inverse-kinematics fit (OpenSim's IKMarkerTask weight)
    if (p.accept_word("weight")) s.quantities["weight"] = p.quantity();
    if (!p.at_end()) p.fail_expected("'weight' (marker KNEE on A at B_o weight 2) or the end of the statement");
}

// ---- meaning -----------------------------------------------------------------------------

void run_marker(Interpreter::Impl& m, const Statement& s) {
    const Word& name = s.word("name");
    const Word& on = s.word("on");
    const Word& at = s.word("at");
    Body& B = m.body(on);
    if (!dynamic_cast<RigidBody*>(&B))
        throw ScriptError(on.location, "'" + on.text + "' is a particle; a marker gives a segment's angle",
                          "put markers on rigid bodies");
    m.point(at);
    double weight = 1;
    if (s.quantities.count("weight")) {
        const Quantity& q = s.quantities.at("weight");
        weight = m.number_of(q, Dimension::none(), "the marker's weight", q.value->location);
        if (!(weight > 0) || !std::isfinite(weight))
            throw ScriptError(q.value->location,
                              "the marker '" + name.text + "' has weight " + m.transcript.number(weight) +
                                  "; a weight multiplies the marker's squared distance in the fit and must be a number above 0",
                              "give a positive weight (marker " + name.text + " on " + on.text + " at " + at.text +
                                  " weight 2), or remove the marker statement to leave the marker out");
    }
    for (const ScriptMarker& k : m.markers) {
        if (k.name.text == name.text && k.body == on.text)
            throw ScriptError(name.location,
                              "the marker '" + name.text + "' is declared on " + on.text + " twice" + at_line(k.name.location),
                              "give each marker one point of each body it serves (a joint's marker may serve both segments)");
        // a joint's marker declared on both its segments is one marker of the fit: one weight
        if (k.name.text == name.text && k.weight != weight)
            throw ScriptError(name.location,
                              "the marker '" + name.text + "' has weight " + m.transcript.number(weight) + " here but " +
                                  m.transcript.number(k.weight) + " on " + k.body + at_line(k.name.location) +
                                  "; it is one marker of the fit, with one weight",
                              "give both statements the same weight");
    }
    m.markers.push_back({name, on.text, at.text, weight});
}

void parse_plate(StatementParser& p, Statement& s) {
    s.words["label"] = p.name("the plate's name (plate chair on B from \"trial.mot\")");
    p.expect_word("on", "(plate chair on B from \"trial.mot\")");
    s.words["on"] = p.name("the body the plate's force acts on");
    p.expect_word("from", "(plate chair on B from \"trial.mot\")");
    s.words["from"] = p.text("the force record's path (.mot, .sto or .c3d)");
    while (!p.at_end()) {
        if (p.accept_word("columns")) s.words["columns"] = p.text("the prefix of the plate's columns (\"ground_force\")");
        else if (p.accept_word("threshold")) s.quantities["threshold"] = p.quantity();
        else p.fail_expected("'columns' or 'threshold'");
    }
}

void run_plate(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& label = s.word("label");
    const Word& on = s.word("on");
    RigidBody& B = m.rigid_body(on);
    const Word& file = s.word("from");
    std::string path = m.input_path(file.text);
    // "{trial}": the trial of `alembert inverse --motion TRIAL`, its path without extension
    if (const std::size_t at = file.text.find("{trial}"); at != std::string::npos) {
        if (m.trial.empty())
            throw ScriptError(file.location, "'{trial}' stands for the trial that alembert inverse SCRIPT --motion TRIAL reads, and there is none",
                              "run the script so (a batch gives each trial its own force record: trials/walk1.trc reads "
                              "trials/walk1_grf.mot from \"{trial}_grf.mot\"), or name the plate's file");
        std::filesystem::path stem(m.trial);
        stem.replace_extension();
        path = file.text;
        path.replace(at, 7, stem.string());
    }
    const std::string prefix = s.has_word("columns") ? s.word("columns").text : "ground_force";
    double threshold = 20;
    if (s.quantities.count("threshold")) {
        const Quantity& q = s.quantities.at("threshold");
        threshold = m.number_of(q, Dimension::force(), "the contact threshold", q.value->location);
        if (!(threshold >= 0) || !std::isfinite(threshold))
            throw ScriptError(q.value->location, "the contact threshold must be a force of 0 N or more", "");
    }
    // the record: an OpenSim storage file, not a marker file
    if (std::filesystem::path(file.text).extension() == ".trc")
        throw ScriptError(file.location, "'" + file.text + "' is a marker file (.trc); a plate reads a force record",
                          "give the force plate's OpenSim file (.mot or .sto) or the trial's C3D file; the markers drive the model through "
                          "inverse for ... from \"" + file.text + "\"");
    ScriptPlate plate{label, {}, {}};
    // a C3D trial: its plates' ground reactions, named as OpenSim's columns (plate 1
    // "ground_force", plate 2 "1_ground_force", ...), at its marker frames
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::vector<std::string> notes;
    plate.record = m.guard(file.location, [&] {
        if (ext == ".c3d") {
            const C3dFile c3d = read_c3d(path);
            notes = c3d.notes;
            if (c3d.plates.empty())
                throw ArgumentError(path + ": the C3D file has no force plates (FORCE_PLATFORM:USED is 0); give "
                                    "the trial's force record as a .mot, or export the plates with the trial");
            return force_plate_from_table(c3d.forces, prefix, threshold, path);
        }
        return force_plate_from_table(read_storage(path).table, prefix, threshold, path);
    });
    std::size_t on_samples = 0;
    for (std::size_t k = 0; k < plate.record.t.size(); ++k) on_samples += plate.record.in_contact(k) ? 1 : 0;
    // its symbols: force, centre of pressure and free moment, known functions of time
    SymbolTable& symbols = sys.symbols();
    const std::string names[5] = {label.text + "_Fx", label.text + "_Fy", label.text + "_px", label.text + "_py",
                                  label.text + "_Tz"};
    const Dimension dims[5] = {Dimension::force(), Dimension::force(), Dimension::length(), Dimension::length(),
                               Dimension::torque()};
    ex x[5];
    for (int i = 0; i < 5; ++i) {
        m.declare_name(Word{names[i], label.location}, NameKind::symbol);
        x[i] = m.guard(label.location, [&] { return symbols.add_specified(names[i], 0).symbol(); });
        m.units[names[i]] = SymbolUnits{dims[i], std::nullopt};
    }
    plate.symbols = {x[0], x[1], x[2], x[3], x[4]};
    // the load: the force at the point of B at the centre of pressure, and the free moment
    const Frame& N = sys.newtonian();
    const std::string cop = label.text + "_CoP";
    m.declare_name(Word{cop, label.location}, NameKind::point);
    m.guard(label.location, [&] {
        Point& P = sys.add_point(cop, &B);
        // located from B's mass centre, so it is a point of B and no joint with N
        P.set_pos(B.cm(), Vector(N, Col3{x[2], x[3], 0}) - B.cm().pos_from(sys.origin()));
        P.set_vel_two_point(N, B.cm(), B.body_frame());  // the material point of B there
        sys.add_force(P, Vector(N, Col3{x[0], x[1], 0}), label.text);
        sys.add_torque(B, Vector(N, Col3{0, 0, x[4]}), label.text + " free moment");
    });
    m.transcript.result("plate " + label.text + " on " + on.text + ": " + prefix + " of " + file.text + ", " +
                        std::to_string(plate.record.t.size()) + " samples, t = " +
                        m.transcript.number(plate.record.t.front()) + " to " +
                        m.transcript.number(plate.record.t.back()) + " s, in contact at " + std::to_string(on_samples) +
                        " (force of " + m.transcript.number(threshold) + " N or more)\n  force " + names[0] +
                        "*Nx> + " + names[1] + "*Ny> at " + cop + " = " + names[2] + "*Nx> + " + names[3] +
                        "*Ny> from N_o, free moment " + names[4] + "*Nz>");
    for (const std::string& n : notes) m.transcript.result("  " + n);
    m.plates.push_back(std::move(plate));
}

}  // namespace

MarkerCoordinates Interpreter::Impl::coordinates_from_markers(const std::string& path,
                                                              const std::vector<TimeVariable>& q, Location where,
                                                              std::string& note) {
    System& sys = model(where);
    if (markers.empty())
        throw ScriptError(where, "the script declares no markers, so a marker file (.trc, .c3d) cannot drive it",
                          "declare the model's markers with the names the file uses: marker KNEE on A at B_o");
    // the markers' positions from N_o in N
    const Frame& N = sys.newtonian();
    std::vector<ModelMarker> model_markers;
    bool spatial = false;  // a marker leaves the plane Nz = const as a coordinate changes
    for (const ScriptMarker& k : markers) {
        const Col3 p = sys.point(k.point).pos_from(sys.origin()).components_in(N);
        model_markers.push_back({k.name.text, k.body, p[0], p[1]});
        for (const TimeVariable& v : q) spatial = spatial || sys.symbols().depends_on(p[2], v.symbol());
    }
    // the trial (a .trc, or a C3D file's markers): read, gaps filled, coordinates from the
    // segments' angles
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    MarkerTable trial = ext == ".c3d" ? read_c3d(path).markers : read_trc(path);
    // every marker the script declares is in the file, under the same name
    for (const ScriptMarker& k : markers) {
        if (std::find(trial.markers.begin(), trial.markers.end(), k.name.text) != trial.markers.end()) continue;
        std::string list;
        for (const std::string& name : trial.markers) list += (list.empty() ? "" : ", ") + name;
        throw ScriptError(k.name.location,
                          "the marker '" + k.name.text + "' is not in the marker file '" + path +
                              "' (read by the statement at line " + std::to_string(where.line) +
                              "); the file's markers are: " + list,
                          "name the marker as the file does (marker " + trial.markers.front() + " on " + k.body +
                              " at " + k.point + "), or remove this marker statement");
    }
    // each marker's point is fixed in its body: a segment's angle comes from two such points
    for (const ScriptMarker& k : markers) {
        const RigidBody& B = sys.rigid_body(k.body);
        const bool fixed = sys.point(k.point).pos_from(B.cm()).dt_in(B.body_frame()).simplify().is_zero();
        if (!fixed)
            throw ScriptError(k.name.location,
                              "the marker '" + k.name.text + "' is at " + k.point + ", which moves relative to " + k.body +
                                  ": a marker on " + k.body + " gives " + k.body + "'s angle only at a point fixed in it",
                              "put the marker at a point of " + k.body + " (point P on " + k.body + "; translate P from " +
                                  k.body + "_o by ...), or declare it on the body " + k.point + " is fixed in");
    }
    // the markers the model uses: one it does not use (never seen, say) cannot block the trial
    std::vector<std::string> used, unused;
    for (const ScriptMarker& k : markers)
        if (std::find(used.begin(), used.end(), k.name.text) == used.end()) used.push_back(k.name.text);
    for (const std::string& name : trial.markers)
        if (std::find(used.begin(), used.end(), name) == used.end()) unused.push_back(name);
    trial = select_markers(trial, used);
    // gaps filled and the time base checked, at the header's DataRate where the times fit it
    const TimeBaseReport base = regularize_time_base(trial.table, 0, path, {.rate_hz = trial.data_rate_hz});
    std::string unused_text;
    for (const std::string& name : unused) unused_text += (unused_text.empty() ? "" : ", ") + name;
    if (!unused.empty()) unused_text = "markers in the file that the model does not use, not read: " + unused_text + "\n";
    // a moving root (a translation among the coordinates, as a walking subject's hip) cannot be
    // read from segment angles: the coordinates are then fitted to the markers, as in 3D
    const std::vector<std::string> kinds = coordinate_quantities(q, where);
    for (std::size_t i = 0; i < q.size(); ++i)
        spatial = spatial || kinds[i] == "length" || symbol_dimension(q[i].name()) == Dimension::length();
    if (spatial) {
        note = unused_text;  // stated after the fit's report
        return spatial_coordinates_from_markers(trial, base, q, where, note);
    }
    const MarkerCoordinates mc = calc_coordinates_from_markers(sys.symbols(), q, model_markers, trial);
    // weights belong to the least-squares fit; segment angles from two markers have none
    std::string unweighted;
    for (const ScriptMarker& k : markers)
        if (k.weight != 1 && unweighted.find("'" + k.name.text + "'") == std::string::npos)
            unweighted += (unweighted.empty() ? "'" : ", '") + k.name.text + "'";
    // what was done, for the transcript
    std::ostringstream out;
    out << "markers: " << model_markers.size() << " on " << mc.segments.size() << " segments (";
    for (std::size_t s = 0; s < mc.segments.size(); ++s) {
        out << (s ? "; " : "") << "theta_" << mc.segments[s] << " =";
        bool first = true;
        for (std::size_t j = 0; j < q.size(); ++j) {
            const int c = mc.turns[s][j];
            if (!c) continue;
            out << (c < 0 ? (first ? " -" : " - ") : (first ? " " : " + ")) << q[j].name();
            first = false;
        }
        out << " + const";
    }
    const auto worst = std::max_element(mc.marker_residual_m.begin(), mc.marker_residual_m.end());
    const std::size_t wi = static_cast<std::size_t>(worst - mc.marker_residual_m.begin());
    out << "); largest distance from the model's marker " << transcript.number(*worst * 1000) << " mm ('"
        << model_markers[wi].name << "')";
    std::string base_text = base.describe();
    base_text += unused_text;
    if (!unweighted.empty())
        base_text += "marker weights not used (" + unweighted +
                     "): this model's coordinates come from its segments' angles, not from a weighted fit\n";
    while (!base_text.empty() && base_text.back() == '\n') base_text.pop_back();
    if (!base_text.empty()) out << "\n" << base_text;
    note = out.str();
    if (!plates.empty())
        out << "\nthe plates' centres of pressure from N_o: the lab's origin is at (" << transcript.number(mc.origin_h)
            << ", " << transcript.number(mc.origin_v) << ") m from it";
    note = out.str();
    while (!note.empty() && note.back() == '\n') note.pop_back();
    return mc;
}

MarkerCoordinates Interpreter::Impl::spatial_coordinates_from_markers(const MarkerTable& trial,
                                                                      const TimeBaseReport& base,
                                                                      const std::vector<TimeVariable>& q,
                                                                      Location where, std::string& note) {
    // a spatial model: least-squares inverse kinematics over the model's marker points, the
    // lab's X, Y, Z taken as Nx>, Ny>, Nz> and its origin as N_o (a marker declared on two
    // bodies at one point, as a joint's marker is, is one marker of the fit)
    System& sys = model(where);
    std::vector<MarkerPoint> points;
    for (const ScriptMarker& k : markers) {
        const bool seen = std::any_of(points.begin(), points.end(),
                                      [&](const MarkerPoint& m) { return m.name == k.name.text; });
        if (!seen) points.push_back({k.name.text, &sys.point(k.point), k.weight});
    }
    std::vector<ex> coordinates;
    for (const TimeVariable& v : q) coordinates.push_back(v.symbol());
    const InverseKinematics ik(sys, coordinates, points);
    const InverseKinematicsResult r = ik.solve(trial);
    MarkerCoordinates mc;
    mc.motion = r.calc_coordinate_table();
    mc.residuals = r.calc_residual_table();
    for (std::size_t i = 0; i < r.markers.size(); ++i) {
        double worst = 0;
        for (const InverseKinematicsFrame& f : r.frames)
            if (!std::isnan(f.residual[i])) worst = std::max(worst, f.residual[i]);
        mc.marker_residual_m.push_back(worst);
    }
    const auto worst = std::max_element(mc.marker_residual_m.begin(), mc.marker_residual_m.end());
    std::ostringstream out;
    out << "markers: " << points.size() << ", the coordinates by inverse kinematics in three dimensions "
        << "(Levenberg-Marquardt per frame); largest distance from the model's marker "
        << transcript.number(*worst * 1000) << " mm ('"
        << r.markers[static_cast<std::size_t>(worst - mc.marker_residual_m.begin())] << "')";
    std::string text = r.describe() + base.describe();
    text += note;  // the caller's notes on the trial (markers not used)
    while (!text.empty() && text.back() == '\n') text.pop_back();
    if (!text.empty()) out << "\n" << text;
    note = out.str();
    return mc;
}

std::shared_ptr<PlateInputs> Interpreter::Impl::plate_inputs() const {
    if (plates.empty()) return nullptr;
    auto data = std::make_shared<PlateInputs>();
    for (const ScriptPlate& p : plates) data->add(p.record, p.symbols);
    return data;
}

std::vector<StatementSpec> lab_statements() {
    return {
        {.keyword = "marker", .family = "Kinematics",
         .help = "a model point as a marker of .trc (or .c3d) files, so a marker trial drives the model's coordinates",
         .forms = {{"`marker` *name* \\| *\"name\"* `on` *B* `at` *P* [`weight` *w*]",
                    "marker KNEE on A at B_o weight 2",
                    "`calc_coordinates_from_markers` when `inverse` reads a `.trc` (or a `.c3d` trial's markers): segment angles from each body's markers, joint angles by the model's own signs, checked against the model's marker points; a model with a moving root or leaving the plane: `InverseKinematics`, each marker's squared distance times its weight (default 1)"}},
         .clauses = {"on", "at", "weight"},
         .parse = parse_marker, .run = run_marker},
        {.keyword = "plate", .family = "Mass and loads",
         .help = "a force plate's record (force, centre of pressure, free moment) as a known load on a body",
         .forms = {{"`plate` *name* `on` *B* `from` *\"file.mot\"* [`columns` *\"prefix\"*] [`threshold` *F*]",
                    "plate chair on B from \"lab/rise.mot\" columns \"1_ground_force\"",
                    "`force_plate_from_table` (OpenSim's ground-reaction columns, default `ground_force`) + `System::add_force` at the point of B at the centre of pressure, `System::add_torque` (free moment); known data symbols name_Fx, _Fy, _px, _py, _Tz, given their values by `with_plate_inputs` in `inverse`, zero out of contact (force below the threshold, default 20 N); a file written `\"{trial}_grf.mot\"` is each trial's own record in `alembert inverse SCRIPT --motion TRIAL` (a batch); a `.c3d` trial's plates (`read_c3d`) go by the same names: plate 1 `ground_force`, plate 2 `1_ground_force`"}},
         .clauses = {"on", "from", "columns", "threshold"},
         .parse = parse_plate, .run = run_plate},
    };
}

}  // namespace alembert::lang
