// SPDX-License-Identifier: MIT
// Lab files in a script's model: `marker NAME on B at P` declares a point of the model as the
// marker a .trc file names, so a marker trial gives the model's coordinates.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/model_markers.hpp"
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
    for (const ScriptMarker& k : m.markers)
        if (k.name.text == name.text && k.body == on.text)
            throw ScriptError(name.location,
                              "the marker '" + name.text + "' is declared on " + on.text + " twice" + at_line(k.name.location),
                              "give each marker one point of each body it serves (a joint's marker may serve both segments)");
    m.markers.push_back({name, on.text, at.text});
}

}  // namespace

Table Interpreter::Impl::coordinates_from_markers(const std::string& path, const std::vector<TimeVariable>& q,
                                                  Location where, std::string& note) {
    System& sys = model(where);
    if (markers.empty())
        throw ScriptError(where, "the script declares no markers, so a marker file (.trc) cannot drive it",
                          "declare the model's markers with the names the file uses: marker KNEE on A at B_o");
    // the markers' positions from N_o in N
    const Frame& N = sys.newtonian();
    std::vector<ModelMarker> model_markers;
    for (const ScriptMarker& k : markers) {
        const Col3 p = sys.point(k.point).pos_from(sys.origin()).components_in(N);
        model_markers.push_back({k.name.text, k.body, p[0], p[1]});
    }
    // the trial: read, gaps filled, coordinates from the segments' angles
    MarkerTable trial = read_trc(path);
    const TimeBaseReport base = regularize_time_base(trial.table, 0, path);
    const MarkerCoordinates mc = calc_coordinates_from_markers(sys.symbols(), q, model_markers, trial);
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
    for (const std::string& line : {base.describe()})
        if (!line.empty()) out << "\n" << line;
    note = out.str();
    while (!note.empty() && note.back() == '\n') note.pop_back();
    return mc.motion;
}

std::vector<StatementSpec> lab_statements() {
    return {
        {.keyword = "marker", .family = "Kinematics",
         .help = "a model point as a marker of .trc files, so a marker trial drives the model's coordinates",
         .forms = {{"`marker` *name* \\| *\"name\"* `on` *B* `at` *P*",
                    "marker KNEE on A at B_o",
                    "`calc_coordinates_from_markers` when `inverse` reads a `.trc`: segment angles from each body's markers, joint angles by the model's own signs, checked against the model's marker points"}},
         .clauses = {"on", "at"},
         .parse = parse_marker, .run = run_marker},
    };
}

}  // namespace alembert::lang
