// SPDX-License-Identifier: MIT
// The interpreter's numeric statements: simulation settings and outputs, simulate, prescribed
// motions, inverse dynamics over a motion, and code generation.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "alembert/codegen/codegen.hpp"
#include "alembert/codegen/native.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/lang/parser.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// qA'' -> qA_dd: a name the generated code can use
std::string code_identifier(const std::string& printed) {
    std::string out;
    std::size_t p = printed.find('\'');
    out = printed.substr(0, p);
    if (p != std::string::npos) out += "_" + std::string(printed.size() - p, 'd');
    return out;
}

// the smallest power of ten above x (x > 0)
std::string bound_of(double x) {
    int e = static_cast<int>(std::ceil(std::log10(x)));
    if (std::pow(10.0, e) <= x) ++e;
    return "1e" + std::to_string(e);
}

// a table as transcripts print it: at most `max_rows` rows spread evenly, the last included
std::string format_table(const Table& t, std::size_t max_rows = 11) {
    const std::size_t rows = t.row_count(), cols = t.names.size();
    std::vector<std::size_t> picked;
    if (rows <= max_rows) {
        for (std::size_t r = 0; r < rows; ++r) picked.push_back(r);
    } else {
        for (std::size_t k = 0; k + 1 < max_rows; ++k) picked.push_back(k * (rows - 1) / (max_rows - 1));
        picked.push_back(rows - 1);
    }
    std::vector<std::vector<std::string>> cells(picked.size() + 1, std::vector<std::string>(cols));
    std::vector<std::size_t> width(cols, 0);
    for (std::size_t c = 0; c < cols; ++c) {
        cells[0][c] = t.names[c] + (t.units[c].empty() ? "" : " [" + t.units[c] + "]");
        for (std::size_t k = 0; k < picked.size(); ++k) cells[k + 1][c] = format_number(t.columns[c][picked[k]]);
        for (const auto& row : cells) width[c] = std::max(width[c], row[c].size());
    }
    std::ostringstream out;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        out << " ";
        for (std::size_t c = 0; c < cols; ++c)
            out << " " << std::string(width[c] - cells[k][c].size(), ' ') << cells[k][c];
        if (k + 1 < cells.size()) out << "\n";
    }
    return out.str();
}

std::string file_list(const PlotResult& plot, const std::string& csv) {
    namespace fs = std::filesystem;
    std::string out = fs::path(csv).filename().string();
    for (const std::string& f : plot.files) out += ", " + fs::path(f).filename().string();
    return out;
}

}  // namespace

// ---- evaluation through compiled code ----------------------------------------------------

FunctionMaker Interpreter::Impl::function_maker(bool compiled, std::string* why_not) {
    if (!compiled) return {};
    return [why_not](const SymbolTable& t, const std::vector<ex>& in, const std::vector<ex>& out) {
        auto native = std::make_shared<NativeExpressions>(CompiledExpressions(t, in, out));
        NumericFunction f;
        f.input_count = native->input_count();
        f.output_count = native->output_count();
        f.operation_count = native->tape().operation_count();
        f.kind = native->is_native() ? "compiled" : "tape";
        if (!native->is_native() && why_not && why_not->empty()) *why_not = native->message();
        f.evaluate = [native](const double* x, double* y) { (*native)(x, y); };
        return f;
    };
}

std::string Interpreter::Impl::evaluator_note(bool compiled, const std::string& why_not) const {
    if (!compiled) return "";
    if (why_not.empty()) return "evaluated by compiled C code";
    return "evaluated on the tape, not compiled: " + why_not;
}

// ---- settings ----------------------------------------------------------------------------

ex Interpreter::Impl::quantity_expression(const Quantity& q, const Dimension& expected,
                                          const std::string& what) {
    Value v = eval(*q.value);
    if (v.kind != Kind::scalar)
        throw ScriptError(q.value->location, what + " must be a scalar", "take a measure with dot(v>, Nx>)");
    if (q.unit.empty()) {
        if (v.dim.conflicts(expected) && !v.s.is_zero())
            throw ScriptError(q.value->location, what + " must be " + describe(expected) + ", but it is " + describe(v.dim),
                              expected.known ? "give the number a unit, e.g. " + si_unit(expected) : "check the units");
        return v.s;
    }
    Unit u = parse_unit(q.unit);
    if (u.dimension.conflicts(expected))
        throw ScriptError(q.unit.location, what + " must be " + describe(expected) + ", but " + u.text +
                                               " is " + describe(u.dimension),
                          "write it in a unit of the declared dimension");
    check_dimension(v.dim * u.dimension, expected, what, q.value->location);
    return v.s * u.scale;
}

bool Interpreter::Impl::is_coordinate(const ex& x, int order) {
    for (const TimeVariable& v : default_coordinates())
        if (v.order() >= order && x.is_equal(v.d(order))) return true;
    return false;
}

void Interpreter::Impl::set_initial(const Statement& s) {
    for (const Binding& b : s.bindings.at("values")) {
        ex x = symbol(b.name, "a coordinate or its rate");
        if (!is_coordinate(x, 0) && !is_coordinate(x, 1))
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a coordinate or a coordinate's rate",
                              "give initial values of the coordinates and their first derivatives "
                              "(initial qA = 30 deg, qA' = 0)");
        numbers.initial[x] = number_of(b.quantity, symbol_dimension(b.name.text),
                                       "the initial value of " + b.name.text, b.name.location);
    }
}

void Interpreter::Impl::set_inputs(const Statement& s) {
    const SymbolTable& table = model(s.location).symbols();
    for (const Binding& b : s.bindings.at("values")) {
        ex x = symbol(b.name, "a load measure");
        if (table.kind(x) != SymbolKind::unknown)
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a load measure",
                              "declare it with 'unknown' and use it in a force or torque");
        ex f = quantity_expression(b.quantity, symbol_dimension(b.name.text), "the law of " + b.name.text);
        for (const ex& u : table.symbols(SymbolKind::unknown))
            if (table.depends_on(f, u))
                throw ScriptError(b.quantity.value->location,
                                  "the law of " + b.name.text + " holds the unknown " + to_string(u),
                                  "write a load as a formula of t, the coordinates, their rates and constants");
        for (const TimeVariable& v : default_coordinates())
            if (v.order() >= 2 && table.depends_on(f, v.d(2)))
                throw ScriptError(b.quantity.value->location,
                                  "the law of " + b.name.text + " holds the acceleration " + to_string(v.d(2)),
                                  "write a load as a formula of t, the coordinates, their rates and constants");
        numbers.inputs[x] = f;
    }
}

void Interpreter::Impl::set_prescribed_motion(const Statement& s) {
    const SymbolTable& table = model(s.location).symbols();
    for (const Binding& b : s.bindings.at("values")) {
        ex x = symbol(b.name, "a coordinate");
        if (!is_coordinate(x, 0))
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a coordinate",
                              "prescribe coordinates: motion qA = 30*sin(2*pi*t) deg");
        ex f = quantity_expression(b.quantity, symbol_dimension(b.name.text), "the motion of " + b.name.text);
        for (const ex& v : table.symbols(SymbolKind::variable))
            if (table.depends_on(f, v))
                throw ScriptError(b.quantity.value->location,
                                  "the motion of " + b.name.text + " depends on " + to_string(v) +
                                      "; a prescribed motion is a formula of time t",
                                  "write it with t and constants, e.g. minimum_jerk(t, 0, 1.5)");
        numbers.motion[b.name.text] = f;
    }
}

void Interpreter::Impl::set_times_and_tolerances(const Statement& s) {
    auto positive = [&](const std::string& role, const Dimension& d, const std::string& what) {
        const Quantity& q = s.quantities.at(role);
        double x = number_of(q, d, what, q.value->location);
        if (!(x > 0) || !std::isfinite(x))
            throw ScriptError(q.value->location, what + " must be positive, not " + format_number(x), "");
        return x;
    };
    if (s.keyword == "final") numbers.options.t_final = positive("time", Dimension::time(), "the final time");
    if (s.quantities.count("step"))
        numbers.options.output_step = positive("step", Dimension::time(), "the output step");
    if (s.quantities.count("abs"))
        numbers.options.abs_tol = positive("abs", Dimension::open(), "the absolute tolerance");
    if (s.quantities.count("rel"))
        numbers.options.rel_tol = positive("rel", Dimension::open(), "the relative tolerance");
}

void Interpreter::Impl::add_outputs(const Statement& s) {
    if (s.quantities.count("step")) return set_times_and_tolerances(s);
    const auto& labels = s.lists.at("labels");
    const auto& exprs = s.expr_lists.at("values");
    for (std::size_t i = 0; i < exprs.size(); ++i) {
        const Expr& e = *exprs[i];
        std::string name = labels[i].text;
        if (name.empty()) {
            if (e.kind != Expr::Kind::name)
                throw ScriptError(e.location, "this output needs a column name",
                                  "name it: output height = dot(pos(Ccm, N_o), Ny>) in m");
            name = e.text;
        } else if (is_reserved(name)) {
            throw ScriptError(labels[i].location, "'" + name + "' is a word of the language", "choose another column name");
        }
        for (const OutputSpec& o : numbers.outputs)
            if (o.name == name)
                throw ScriptError(labels[i].text.empty() ? e.location : labels[i].location,
                                  "there is already an output named '" + name + "'", "name each column once");
        Value v = eval(e);
        if (v.kind != Kind::scalar)
            throw ScriptError(e.location, "an output is a scalar", "take a measure with dot(v>, Nx>)");
        OutputSpec o{name, v.s, "", 1.0};
        const UnitText& ut = s.units[i];
        if (!ut.empty()) {
            Unit u = parse_unit(ut);
            if (u.dimension.conflicts(v.dim))
                throw ScriptError(ut.location, "the output " + name + " is " + describe(v.dim) + ", but " +
                                                   u.text + " is " + describe(u.dimension),
                                  "print it in a unit of its dimension");
            o.unit = u.text, o.factor = u.scale;
        } else if (std::optional<Unit> u = e.kind == Expr::Kind::name ? display_unit(e.text) : std::nullopt) {
            o.unit = u->text, o.factor = u->scale;
        } else if (v.dim.known && !v.dim.is_none()) {
            o.unit = si_unit(v.dim);
        }
        numbers.outputs.push_back(o);
        numbers.output_si_units.push_back(v.dim.known && !v.dim.is_none() ? si_unit(v.dim) : "");
    }
}

void Interpreter::Impl::add_event(const Statement& s) {
    Value l = eval(*s.exprs.at("lhs"));
    if (l.kind != Kind::scalar)
        throw ScriptError(s.exprs.at("lhs")->location, "a stop condition compares scalars",
                          "stop when dot(pos(Ccm, N_o), Ny>) = 0.5 m");
    ex r = quantity_expression(s.quantities.at("rhs"), l.dim, "the value the stop condition crosses");
    EventDirection d = EventDirection::any;
    if (s.has_word("direction")) d = s.word("direction").text == "rising" ? EventDirection::rising : EventDirection::falling;
    std::string name = s.source.substr(s.source.find("when") + 5);
    if (s.has_word("direction")) name = name.substr(0, name.rfind(s.word("direction").text));
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    numbers.events.push_back({name, l.s - r, d});
}

// ---- simulate ----------------------------------------------------------------------------

std::string Interpreter::Impl::output_path(const Statement& s) const {
    namespace fs = std::filesystem;
    if (!s.has_word("to")) return output_dir;
    const Word& to = s.word("to");
    fs::path p(to.text);
    // a script writes inside the output directory unless its user allows more
    if (!allow_outside_output) {
        const fs::path inside = p.lexically_normal();
        if (p.is_absolute() || p.has_root_name() || (!inside.empty() && *inside.begin() == ".."))
            throw ScriptError(to.location, "to \"" + to.text + "\" leaves the output directory '" +
                                               output_dir + "' (--out)",
                              "write to a directory inside it, such as to \"results\", or allow it with "
                              "--allow-outside-out");
    }
    return p.is_absolute() ? p.string() : (fs::path(output_dir) / p).string();
}

std::string Interpreter::Impl::input_path(const std::string& written) const {
    namespace fs = std::filesystem;
    fs::path p(written);
    if (p.is_absolute() || base_dir.empty()) return p.string();
    return (fs::path(base_dir) / p).string();
}

void Interpreter::Impl::simulate(const Statement& s) {
    if (model_only) return;
    System& sys = model(s.location);
    const SymbolTable& table = sys.symbols();
    const std::string dir = output_path(s);  // refused before the work starts
    SimulationRequest r;
    r.model = script_name;
    r.coordinates = default_coordinates();
    if (r.coordinates.empty())
        throw ScriptError(s.location, "the model has no coordinates to simulate",
                          "declare variables (variable q'') and use them in rotations or translations");
    for (const TimeVariable& v : r.coordinates)
        if (v.order() < 2)
            throw ScriptError(s.location, "the coordinate " + v.name() + " has no second derivative declared",
                              "declare it as variable " + v.name() + "''");
    r.inputs = numbers.inputs;
    if (!sys.constraints().empty())
        for (const ex& u : table.symbols(SymbolKind::unknown))
            if (!numbers.inputs.count(u)) r.constraint_forces.push_back(u);
    for (const auto& [x, value] : numbers.initial) r.initial_values[x] = value;
    r.outputs = numbers.outputs;
    if (r.outputs.empty())
        for (const TimeVariable& v : r.coordinates)
            for (int k = 0; k < 2; ++k) {
                std::string n = k ? v.name() + "'" : v.name();
                std::optional<Unit> u = display_unit(n);
                r.outputs.push_back({n, v.d(k), u ? u->text : "", u ? u->scale : 1.0});
            }
    r.events = numbers.events;
    r.options = numbers.options;
    r.options.progress = isatty(STDERR_FILENO) != 0;
    std::string why_not;
    r.make = function_maker(s.flag("compiled"), &why_not);
    SimulationResult res = guard(s.location, [&] { return run_simulation(sys, r); },
                                 "check the initial values and the loads; a singular mass matrix "
                                 "means the coordinates do not fix the model's configuration");
    PlotResult plot = guard(s.location, [&] { return write_table_and_plot(res.table, dir, "simulation"); });
    std::ostringstream out;
    out << "simulated t = " << format_number(r.options.t_initial) << " to " << format_number(res.t_end) << " s";
    if (!res.stopped_by.empty()) out << ", stopped when " << res.stopped_by;
    out << ": " << res.table.row_count() << " rows";
    std::string note = evaluator_note(s.flag("compiled"), why_not);
    if (!note.empty()) out << ", " << note;
    out << "\nwrote " << file_list(plot, "simulation.csv");
    if (!plot.drawn) out << " (no plot: " << plot.message << ")";
    out << "\n" << format_table(res.table);
    // the checks users rely on
    for (std::size_t c = 0; c < res.table.names.size(); ++c) {
        const std::vector<double>& col = res.table.columns[c];
        if (col.empty()) continue;
        if (res.table.names[c] == "energy") {
            double scale = 0, change = 0;
            for (double e : col) scale = std::max(scale, std::abs(e));
            for (double e : col) change = std::max(change, std::abs(e - col.front()));
            out << "\nenergy: " << format_number(col.front()) << " J at the start; ";
            if (change == 0) out << "unchanged";
            else if (scale > 0) out << "its largest change is below " << bound_of(change / scale) << " of its largest value";
        } else if (res.table.names[c].rfind("drift_", 0) == 0) {
            double worst = 0;
            for (double e : col) worst = std::max(worst, std::abs(e));
            out << "\nconstraint " << res.table.names[c].substr(6) << ": ";
            if (worst == 0) out << "residual 0 throughout";
            else out << "largest residual below " << bound_of(worst);
        }
    }
    transcript.result(out.str());
}

// ---- inverse dynamics --------------------------------------------------------------------

void Interpreter::Impl::inverse(const Statement& s) {
    if (model_only) return;
    const SymbolTable& table = model(s.location).symbols();
    InverseRequest r;
    for (const Word& w : s.lists.at("loads")) {
        ex x = symbol(w, "a load measure");
        if (table.kind(x) != SymbolKind::unknown)
            throw ScriptError(w.location, "'" + w.text + "' is not a load measure",
                              "list unknowns declared with 'unknown' and used in loads");
        if (std::find(r.loads.begin(), r.loads.end(), x) != r.loads.end())
            throw ScriptError(w.location, "'" + w.text + "' is listed twice", "list each load once");
        r.loads.push_back(x);
    }
    if (s.has_word("from")) {
        r.motion_file = input_path(s.word("from").text);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(r.motion_file, ec))
            throw ScriptError(s.word("from").location, "the motion table '" + s.word("from").text + "' is not a file",
                              "paths a script reads are relative to the script's directory");
    }
    if (s.quantities.count("cutoff")) {
        const Quantity& q = s.quantities.at("cutoff");
        double hz = number_of(q, pow(Dimension::time(), -1), "the cutoff frequency", q.value->location);
        if (!(hz >= 0) || !std::isfinite(hz))
            throw ScriptError(q.value->location, "the cutoff frequency must be 0 (no filter) or positive", "");
        r.cutoff_hz = hz;
    }
    r.compiled = s.flag("compiled");
    r.dir = output_path(s);
    run_inverse(r, s.location);
}

void Interpreter::Impl::run_inverse(const InverseRequest& r, Location where) {
    System& sys = model(where);
    const SymbolTable& table = sys.symbols();
    std::vector<TimeVariable> q = default_coordinates();
    std::string why_not;
    FunctionMaker make = function_maker(r.compiled, &why_not);
    InverseDynamics id = guard(where, [&] { return compile_inverse_dynamics(sys, q, r.loads, script_name, make); },
                               "list as many load measures as the model has coordinates, one acting at each joint");
    InverseAnalysisOptions opts;
    opts.filter.cutoff_hz = r.cutoff_hz;
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
    InverseAnalysisReport rep;
    std::string span;
    if (!r.motion_file.empty()) {
        rep = guard(where, [&] { return run_inverse_dynamics(id, r.motion_file, r.dir, opts); });
        span = "the motion table " + std::filesystem::path(r.motion_file).filename().string();
    } else {
        std::vector<ex> formulas;
        for (const TimeVariable& v : q) {
            auto it = numbers.motion.find(v.name());
            if (it == numbers.motion.end())
                throw ScriptError(where, "no motion is prescribed for " + v.name(),
                                  "prescribe every coordinate (motion " + v.name() +
                                      " = ...), or read a table: inverse for ... from \"motion.csv\"");
            formulas.push_back(it->second);
        }
        const SimulationOptions& o = numbers.options;
        std::vector<double> times;
        const auto steps = static_cast<std::size_t>(std::floor((o.t_final - o.t_initial) / o.output_step + 1e-9));
        for (std::size_t k = 0; k <= steps; ++k) times.push_back(o.t_initial + static_cast<double>(k) * o.output_step);
        if (times.back() < o.t_final - 1e-12) times.push_back(o.t_final);
        rep = guard(where, [&] {
            PrescribedMotion motion(table, q, formulas);
            return run_inverse_dynamics(id, motion.sample(times), r.dir, opts);
        });
        span = "the prescribed motion";
    }
    const Table& t = rep.loads;
    std::ostringstream out;
    out << "inverse dynamics over " << span << ", t = " << format_number(t.columns[0].front()) << " to "
        << format_number(t.columns[0].back()) << " s: " << t.row_count() << " samples";
    std::string note = evaluator_note(r.compiled, why_not);
    if (!note.empty()) out << ", " << note;
    out << "\nwrote " << file_list(rep.plot, rep.csv);
    if (!rep.plot.drawn) out << " (no plot: " << rep.plot.message << ")";
    for (std::size_t c = 1; c < t.names.size(); ++c) {
        const std::vector<double>& col = t.columns[c];
        auto hi = std::max_element(col.begin(), col.end()), lo = std::min_element(col.begin(), col.end());
        const std::string unit = t.units[c].empty() ? "" : " " + t.units[c];
        out << "\n" << t.names[c] << ": largest " << format_number(*hi) << unit << " at t = "
            << format_number(t.columns[0][static_cast<std::size_t>(hi - col.begin())]) << " s, smallest "
            << format_number(*lo) << unit << " at t = "
            << format_number(t.columns[0][static_cast<std::size_t>(lo - col.begin())]) << " s";
    }
    out << "\n" << format_table(t);
    transcript.result(out.str());
}

// ---- code generation ---------------------------------------------------------------------

void Interpreter::Impl::codegen(const Statement& s) {
    if (model_only) return;
    const SymbolTable& table = model(s.location).symbols();
    CodegenRequest r;
    r.language = s.word("language");
    if (s.lists.count("loads"))
        for (const Word& w : s.lists.at("loads")) {
            ex x = symbol(w, "a load measure");
            if (table.kind(x) != SymbolKind::unknown)
                throw ScriptError(w.location, "'" + w.text + "' is not a load measure",
                                  "list unknowns declared with 'unknown' and used in loads");
            r.loads.push_back(x);
        }
    if (s.has_word("name")) r.name = s.word("name").text;
    r.dir = output_path(s);
    run_codegen(r, s.location);
}

void Interpreter::Impl::run_codegen(const CodegenRequest& r, Location where) {
    System& sys = model(where);
    const SymbolTable& table = sys.symbols();
    Language language = guard(r.language.location, [&] { return parse_language(r.language.text); });
    std::vector<TimeVariable> q = default_coordinates();
    if (q.empty())
        throw ScriptError(where, "the model has no coordinates to generate code for",
                          "declare variables (variable q'') and use them in rotations or translations");
    if (!sys.constraints().empty())
        throw ScriptError(where, "code generation for models with constraints is not available yet",
                          "generate code for the model without its constraint statements, or use simulate");
    std::vector<ex> loads = r.loads.empty() ? table.symbols(SymbolKind::unknown) : r.loads;
    CodegenOptions opts;
    opts.name = r.name.empty() ? script_name : r.name;
    if (!is_identifier(opts.name))
        throw ScriptError(where, "'" + opts.name + "' cannot name generated code (letters, digits and _ only)",
                          "choose a name: codegen c name pendulum");
    opts.source = script_file;
    for (const auto& [name, u] : units)
        if (u.display) opts.units[name] = u.display->text;
        else if (u.dim.known && !u.dim.is_none()) opts.units[name] = si_unit(u.dim);
    for (std::size_t i = 0; i < numbers.outputs.size(); ++i) {
        // coordinates and rates are columns of the generated simulation already
        bool state = false;
        for (const TimeVariable& v : q) state = state || numbers.outputs[i].expression.is_equal(v.symbol()) ||
                                                numbers.outputs[i].expression.is_equal(v.d(1));
        if (state) continue;
        opts.outputs.push_back({code_identifier(numbers.outputs[i].name), numbers.outputs[i].expression,
                                numbers.output_si_units[i]});
    }
    // the script's simulation settings make the generated simulation program
    opts.simulation = true;
    SimulationSpec& spec = opts.simulation_spec;
    spec.final_time = numbers.options.t_final;
    spec.output_step = numbers.options.output_step;
    spec.absolute_tolerance = numbers.options.abs_tol;
    spec.relative_tolerance = numbers.options.rel_tol;
    for (const TimeVariable& v : q) {
        auto q0 = numbers.initial.find(v.symbol());
        auto qd0 = numbers.initial.find(v.d(1));
        spec.initial_q.push_back(q0 == numbers.initial.end() ? 0.0 : table.evaluate(q0->second));
        spec.initial_qp.push_back(qd0 == numbers.initial.end() ? 0.0 : table.evaluate(qd0->second));
    }
    for (const ex& l : loads) {
        auto it = numbers.inputs.find(l);
        spec.load_laws.push_back(it == numbers.inputs.end() ? ex(0) : it->second);
    }
    // a tree of bodies in relative coordinates: the recursive formation (linear in the number
    // of bodies, forward dynamics with no solve); otherwise Kane's equations with their M
    bool tree = false;
    GeneratedCode g = guard(where, [&] {
        if (std::optional<TreeEquations> t = form_tree_equations_if_tree(sys, q)) {
            tree = true;
            DynamicsEquations eqs{q, t->residuals, loads, std::nullopt, t->accelerations};
            return generate_code(table, eqs, language, r.dir, opts);
        }
        KaneEquations k = form_kane_equations(sys, KaneOptions{.coordinates = q});
        DynamicsEquations eqs{q, k.residuals, loads, k.dynamics};
        return generate_code(table, eqs, language, r.dir, opts);
    });
    std::ostringstream out;
    const char* language_name[] = {"C", "C++", "MATLAB/Octave", "Python"};
    out << "generated " << language_name[static_cast<int>(language)] << " for '" << opts.name << "': ";
    for (std::size_t i = 0; i < g.files.size(); ++i) out << (i ? ", " : "") << g.files[i].filename().string();
    // (operation counts are left out: they shift by a few with GiNaC's term order from run to run)
    if (tree)
        out << "\n  recursive formation: mass matrix and forcing, accelerations by the articulated-body "
               "recursion (no solve)";
    else
        out << "\n  mass matrix and forcing (" << (g.symmetric_mass_matrix ? "Cholesky" : "LU")
            << " solve for the accelerations)";
    if (g.inverse_dynamics) out << ", inverse dynamics";
    else out << "; no inverse dynamics (" << loads.size() << " loads for " << q.size() << " coordinates)";
    if (!opts.outputs.empty()) out << ", " << opts.outputs.size() << " outputs";
    out << ", a simulation program";
    transcript.result(out.str());
}

}  // namespace alembert::lang
