// SPDX-License-Identifier: MIT
// The interpreter's numeric statements: simulation settings and outputs, simulate, prescribed
// motions and inverse dynamics over a motion: their meaning, then their grammar and table
// (number_statements(), which holds `codegen` too; its meaning is in interpreter_codegen.cpp).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <numbers>
#include <sstream>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/codegen/codegen.hpp"
#include "alembert/codegen/native.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/lang/parser.hpp"
#include "alembert/sim/speed_simulation.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

// the smallest power of ten above x (x > 0)
std::string bound_of(double x) {
    int e = static_cast<int>(std::ceil(std::log10(x)));
    if (std::pow(10.0, e) <= x) ++e;
    return "1e" + std::to_string(e);
}

}  // namespace

std::string format_table(const Table& t, int digits, std::size_t max_rows) {
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
        for (std::size_t k = 0; k < picked.size(); ++k) cells[k + 1][c] = format_number(t.columns[c][picked[k]], digits);
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

PlotOptions plot_options_of(const Statement& s, const std::vector<std::string>& columns) {
    PlotOptions o;
    if (!s.lists.count("plot")) return o;
    const std::vector<Word>& plot = s.lists.at("plot");
    if (plot.size() == 1 && plot.front().text == "none") {
        o.skip = true;
        return o;
    }
    for (const Word& w : plot) {
        if (std::find(columns.begin() + (columns.empty() ? 0 : 1), columns.end(), w.text) == columns.end()) {
            std::string list;
            for (std::size_t k = 1; k < columns.size(); ++k) list += (k > 1 ? ", " : "") + columns[k];
            throw ScriptError(w.location, "'" + w.text + "' is not a column of the table",
                              "plot some of: " + list + " (or 'plot none')");
        }
        o.y.push_back(w.text);
    }
    return o;
}

std::string file_list(const PlotResult& plot, const std::string& csv) {
    namespace fs = std::filesystem;
    std::string out = fs::path(csv).filename().string();
    for (const std::string& f : plot.files) out += ", " + fs::path(f).filename().string();
    return out;
}

Dimension residual_dimension_of(const ex& e, const std::function<Dimension(const std::string&)>& of_symbol) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return Dimension::none();
    if (GiNaC::is_a<GiNaC::symbol>(e)) return of_symbol(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    if (GiNaC::is_a<GiNaC::function>(e)) return Dimension::none();  // sin, cos, ...: of angles
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (const ex& term : e) {
            Dimension d = residual_dimension_of(term, of_symbol);
            if (d.known) return d;
        }
        return Dimension::open();
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        Dimension d = Dimension::none();
        for (const ex& factor : e) d = d * residual_dimension_of(factor, of_symbol);
        return d;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer())
        return pow(residual_dimension_of(e.op(0), of_symbol), GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int());
    return Dimension::open();
}

// ---- evaluation through compiled code ----------------------------------------------------

Evaluation Interpreter::Impl::evaluation_of(const Statement& s) const {
    if (s.flag("compiled")) return Evaluation::compiled;
    if (s.flag("tape")) return Evaluation::tape;
    return evaluation;
}

FunctionMaker Interpreter::Impl::function_maker(Evaluation e, std::string* why_not) const {
    if (e == Evaluation::tape) return {};
    NativeOptions options;
    if (isatty(STDERR_FILENO) != 0)  // a compilation of seconds is not a hang: say what it is
        options.on_compile = [](std::size_t operations, bool done) {
            if (done) std::cerr << "\r\033[K" << std::flush;
            else std::cerr << "compiling " << operations << " operations of C (once: cached for later runs)..." << std::flush;
        };
    const std::size_t limit = compile_limit;
    return [e, why_not, options, limit](const SymbolTable& t, const std::vector<ex>& in, const std::vector<ex>& out) {
        CompiledExpressions tape(t, in, out);
        if (e == Evaluation::automatic && tape.operation_count() > limit) {
            // the C compiler takes about half a millisecond per operation (bench/README.md)
            NumericFunction f = make_tape_function(std::move(tape));
            if (why_not && why_not->empty())
                *why_not = std::to_string(f.operation_count) + " operations take the C compiler tens of seconds " +
                           "(past " + std::to_string(limit) +
                           " only on request): write 'compiled' to compile them once, cached for later runs";
            return f;
        }
        auto native = std::make_shared<NativeExpressions>(std::move(tape), options);
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

std::string Interpreter::Impl::evaluator_note(Evaluation e, const std::string& why_not) {
    if (e == Evaluation::tape) return "";
    if (!why_not.empty()) return "evaluated on the tape, not compiled: " + why_not;
    return e == Evaluation::compiled ? "evaluated by compiled C code" : "";
}

void Interpreter::Impl::check_line_loads_apart(const exmap& at, const std::vector<TimeVariable>& q) const {
    const System& m = *sys;
    for (const ScriptLineLoad& l : line_loads) {
        const Vector r = l.P->pos_from(*l.Q);
        double length = 0;
        try {
            length = std::sqrt(m.symbols().evaluate(dot(r, r), at));
        } catch (const Error&) {
            continue;  // a value missing: the run names it
        }
        if (length != 0) continue;
        std::string state;
        for (int k = 0; k < 2; ++k)
            for (const TimeVariable& v : q) {
                auto it = at.find(v.d(k));
                if (it == at.end() || !GiNaC::is_a<GiNaC::numeric>(it->second)) continue;
                state += (state.empty() ? "" : ", ") + m.symbols().name(v.d(k)) + " = " +
                         transcript.number(GiNaC::ex_to<GiNaC::numeric>(it->second).to_double());
            }
        throw ScriptError(l.label.location,
                          "the " + l.kind + " '" + l.label.text + "' joins " + l.P->name() + " and " + l.Q->name() +
                              ", which coincide at the start (" + state +
                              "): the direction of its force, from one end to the other, is undefined there",
                          "start with its ends apart (initial values that separate " + l.P->name() + " and " +
                              l.Q->name() + "), or, if it acts along a fixed line, write its force instead: force " +
                              l.label.text + " on " + l.P->name() + " = ... along that line");
    }
}

// ---- settings ----------------------------------------------------------------------------

ex Interpreter::Impl::quantity_expression(const Quantity& q, const Dimension& expected,
                                          const std::string& what) {
    Value v = eval(*q.value);
    if (v.kind != Kind::scalar)
        throw ScriptError(q.value->location, what + " must be a scalar", "take a measure with dot(v>, Nx>)");
    if (q.unit.empty()) {
        if (v.dim.conflicts(expected) && !v.s.is_zero()) {
            // a bare number wants a unit; an expression of the wrong dimension, a factor
            std::string hint = "check the units of the quantities in it";
            if (v.dim.is_none() && expected.known && !expected.is_none())
                hint = "give the number a unit, e.g. " +
                       (GiNaC::is_a<GiNaC::numeric>(v.s)
                            ? transcript.number(GiNaC::ex_to<GiNaC::numeric>(v.s).to_double()) + " "
                            : std::string("(...) ")) +
                       si_unit(expected);
            else if (expected.is_none() && v.dim.known)
                hint = "it must have no unit: multiply it by a constant declared in " +
                       si_unit(Dimension::none() / v.dim) + " (or divide it by one in " + si_unit(v.dim) +
                       ") so that the units cancel";
            throw ScriptError(q.value->location, what + " must be " + describe(expected) + ", but it is " + describe(v.dim),
                              hint);
        }
        return v.s;
    }
    Unit u = parse_unit(q.unit);
    if (u.dimension.conflicts(expected))
        throw ScriptError(q.unit.location, what + " must be " + describe(expected) + ", but " + u.text +
                                               " is " + describe(u.dimension),
                          unit_of_dimension_hint(expected));
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
        numbers.initial[x] = binding_value(b, "the initial value of " + b.name.text);
    }
}

void Interpreter::Impl::set_inputs(const Statement& s) {
    const SymbolTable& table = model(s.location).symbols();
    for (const Binding& b : s.bindings.at("values")) {
        ex x = symbol(b.name, "a load measure");
        bool specified = table.kind(x) == SymbolKind::specified && table.derivative_order(x) == 0;
        if (table.kind(x) != SymbolKind::unknown && !specified)
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a load measure or a specified quantity",
                              "declare it with 'unknown' (or 'specified') and use it in a force or torque");
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
        if (specified) {
            // its derivatives are the law's: a law of the state would need the accelerations
            for (const TimeVariable& v : default_coordinates())
                if (table.variable(b.name.text).order() > 0 && table.depends_on(f, v.symbol()))
                    throw ScriptError(b.quantity.value->location,
                                      "'" + b.name.text + "' is declared with derivatives, so its law must be a "
                                      "formula of time; this one depends on " + v.name(),
                                      "declare it without primes (specified " + b.name.text +
                                          "), or give a formula of t");
            numbers.specified[x] = f;
            continue;
        }
        numbers.inputs[x] = f;
    }
}

void Interpreter::Impl::set_prescribed_motion(const Statement& s) {
    const SymbolTable& table = model(s.location).symbols();
    for (const Binding& b : s.bindings.at("values")) {
        ex x = symbol(b.name, "a coordinate");
        bool specified = table.kind(x) == SymbolKind::specified && table.derivative_order(x) == 0;
        if (!is_coordinate(x, 0) && !specified)
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a coordinate or a specified quantity",
                              "prescribe coordinates or specified quantities: motion qA = 30*sin(w*t) deg, "
                              "with constant w = 1 Hz");
        ex f = quantity_expression(b.quantity, symbol_dimension(b.name.text), "the motion of " + b.name.text);
        for (const ex& v : table.symbols(SymbolKind::variable))
            if (table.depends_on(f, v))
                throw ScriptError(b.quantity.value->location,
                                  "the motion of " + b.name.text + " depends on " + to_string(v) +
                                      "; a prescribed motion is a formula of time t",
                                  "write it with t and constants, e.g. minimum_jerk(t, 0, 1.5)");
        if (specified) numbers.specified[x] = f;  // drives simulate
        else numbers.motion[b.name.text] = f;
    }
}

void Interpreter::Impl::set_times_and_tolerances(const Statement& s) {
    auto positive = [&](const std::string& role, const Dimension& d, const std::string& what,
                        const std::string& example) {
        const Quantity& q = s.quantities.at(role);
        double x = number_of(q, d, what, q.value->location);
        if (!(x > 0) || !std::isfinite(x))
            throw ScriptError(q.value->location, what + " must be positive, not " + format_number(x),
                              "write " + example);
        return x;
    };
    if (s.keyword == "final")
        numbers.options.t_final = positive("time", Dimension::time(), "the final time", "final time 5 s");
    if (s.quantities.count("step"))
        numbers.options.output_step = positive("step", Dimension::time(), "the output step", "output step 0.01 s");
    if (s.quantities.count("abs"))
        numbers.options.abs_tol = positive("abs", Dimension::open(), "the absolute tolerance", "tolerance abs 1e-10");
    if (s.quantities.count("rel")) {
        numbers.options.rel_tol = positive("rel", Dimension::open(), "the relative tolerance", "tolerance rel 1e-10");
        // a fraction of each state's size: 1 or more lets every step pass, whatever its error
        if (!(numbers.options.rel_tol < 1)) {
            const Quantity& q = s.quantities.at("rel");
            throw ScriptError(q.value->location,
                              "the relative tolerance must be below 1, not " + format_number(numbers.options.rel_tol) +
                                  ": it is the error allowed per step as a fraction of each state's size",
                              "write tolerance rel 1e-10 (the default is 1e-8)");
        }
    }
    if (s.quantities.count("limit")) {
        const Quantity& q = s.quantities.at("limit");
        double n = number_of(q, Dimension::none(), "the row limit", q.value->location);
        if (!(n >= 1 && n <= 1e12) || n != std::floor(n))
            throw ScriptError(q.value->location,
                              "the row limit must be a whole number from 1 to 1e12, not " + format_number(n),
                              "write output limit 5000000");
        numbers.options.max_output_rows = static_cast<std::size_t>(n);
    }
}

void Interpreter::Impl::add_outputs(const Statement& s) {
    if (s.quantities.count("step") || s.quantities.count("limit")) return set_times_and_tolerances(s);
    const auto& labels = s.lists.at("labels");
    const auto& exprs = s.expr_lists.at("values");
    for (std::size_t i = 0; i < exprs.size(); ++i) {
        const Expr& e = *exprs[i];
        std::string name = labels[i].text;
        if (name.empty()) {
            if (e.kind != Expr::Kind::name) {
                // a vector first: a name would not make it a column
                if (eval(e).kind == Kind::vector)
                    throw ScriptError(e.location, "an output is a scalar or a matrix",
                                      "take a measure with dot(v>, Nx>) and name the column: output v_x = dot(v>, Nx>)");
                throw ScriptError(e.location, "this output needs a column name",
                                  "name it: output height = dot(pos(Ccm, N_o), Ny>) in m");
            }
            name = e.text;
        } else if (is_reserved(name)) {
            throw ScriptError(labels[i].location, "'" + name + "' is a word of the language", "choose another column name");
        }
        for (const OutputSpec& o : numbers.outputs)
            if (o.name == name)
                throw ScriptError(labels[i].text.empty() ? e.location : labels[i].location,
                                  "there is already an output named '" + name + "'", "name each column once");
        Value v = eval(e);
        // a column named like a symbol of the model holds that symbol: a motion table or a
        // reader of the CSV takes a column 'q' for the coordinate q
        const SymbolTable& symbols = model(e.location).symbols();
        if (!labels[i].text.empty() && symbols.contains(name) &&
            !(v.kind == Kind::scalar && v.s.is_equal(symbols.symbol(name)))) {
            const std::string held = v.kind == Kind::scalar ? to_string(v.s) : "a matrix";
            throw ScriptError(labels[i].location,
                              "the output column '" + name + "' would hold " + held + ", not " + name +
                                  "; a column named like the " + to_string(symbols.kind(symbols.symbol(name))) +
                                  " " + name + " is read as " + name + " (a motion table, a plot)",
                              "name the column after what it holds: output " + name + "_2 = " + held);
        }
        if (v.kind == Kind::matrix) {
            // a matrix is a column per entry, name_ij (row i, column j)
            if (!s.units[i].empty())
                throw ScriptError(s.units[i].location, "a matrix's columns are written in SI units", "drop the unit");
            for (int r = 0; r < v.rows; ++r)
                for (int c = 0; c < v.cols; ++c) {
                    std::string col = name + "_" + std::to_string(r + 1) + std::to_string(c + 1);
                    if (v.rows > 9 || v.cols > 9) col = name + "_" + std::to_string(r + 1) + "_" + std::to_string(c + 1);
                    numbers.outputs.push_back({col, v.a[static_cast<std::size_t>(r * v.cols + c)], "", 1.0});
                    numbers.output_si_units.push_back("");
                }
            continue;
        }
        if (v.kind != Kind::scalar)
            throw ScriptError(e.location, "an output is a scalar or a matrix", "take a measure with dot(v>, Nx>)");
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

const KaneEquations* Interpreter::Impl::speed_equations(Location where, const char* statement,
                                                        std::string* name) {
    const KaneEquations* speeds = nullptr;
    std::vector<std::string> named;
    for (const auto& [n, fe] : formed)
        if (fe.kane && !fe.kane->kinematic_equations.empty()) {
            speeds = &*fe.kane;
            named.push_back(n);
        }
    if (named.size() > 1)
        throw ScriptError(where, "the script forms Kane's equations in generalized speeds " +
                                     std::to_string(named.size()) + " times (" + named.front() + ", " +
                                     named.back() + "); " + statement + " takes one set",
                          "keep one kane statement with speeds");
    if (name && speeds) *name = named.front();
    return speeds;
}

void Interpreter::Impl::simulate(const Statement& s) {
    if (model_only) return;
    System& sys = model(s.location);
    const SymbolTable& table = sys.symbols();
    const std::string dir = output_path(s);  // refused before the work starts
    std::string kane_name;
    const KaneEquations* speeds = speed_equations(s.location, "simulate", &kane_name);
    SimulationRequest r;
    r.model = script_name;
    if (speeds) {
        for (const ex& x : speeds->coordinates) r.coordinates.push_back(table.variable(table.name(x)));
    } else {
        r.coordinates = default_coordinates();
    }
    if (r.coordinates.empty())
        throw ScriptError(s.location, "the model has no coordinates to simulate",
                          "declare variables (variable q'') and use them in rotations or translations");
    for (const TimeVariable& v : r.coordinates)
        if (!speeds && v.order() < 2)
            throw ScriptError(s.location, "the coordinate " + v.name() + " has no second derivative declared",
                              "declare it as variable " + v.name() + "'', or form Kane's equations in "
                              "generalized speeds (kane K for ... speeds ... kinematics [...])");
    r.inputs = numbers.inputs;
    for (const auto& [x, f] : numbers.specified) {
        // the quantity and each declared derivative: x, x' = dx/dt, ...
        TimeVariable v = table.variable(table.name(x));
        ex d = f;
        for (int k = 0; k <= v.order(); ++k) {
            if (k > 0) d = guard(s.location, [&] { return sys.symbols().dt(d); });
            r.specified[v.d(k)] = d;
        }
    }
    if (!speeds && !sys.constraints().empty())
        for (const ex& u : table.symbols(SymbolKind::unknown))
            if (!numbers.inputs.count(u)) r.constraint_forces.push_back(u);
    for (const auto& [x, value] : numbers.initial) r.initial_values[x] = value;
    r.outputs = numbers.outputs;
    const auto add_default_output = [&](const std::string& n, const ex& x) {
        std::optional<Unit> u = display_unit(n);
        r.outputs.push_back({n, x, u ? u->text : "", u ? u->scale : 1.0});
    };
    if (r.outputs.empty() && speeds) {
        // the coordinates and every speed
        for (const TimeVariable& v : r.coordinates) add_default_output(v.name(), v.symbol());
        for (const ex& u : speeds->speeds) add_default_output(table.name(u), u);
        // and the constraint forces its auxiliary speeds bring out
        for (const ex& f : auxiliary_measures(table, *speeds, numbers.inputs)) add_default_output(table.name(f), f);
    } else if (r.outputs.empty()) {
        for (const TimeVariable& v : r.coordinates)
            for (int k = 0; k < 2; ++k) add_default_output(k ? v.name() + "'" : v.name(), v.d(k));
    }
    r.events = numbers.events;
    r.options = numbers.options;
    // the unit of each constraint's residual, for its drift column and messages
    const auto residual_unit = [&](const std::string& name, const ex& residual) {
        Dimension d = residual_dimension_of(table.expand_intermediates(residual),
                                            [&](const std::string& n) { return symbol_dimension(n); });
        if (d.known && !d.is_none()) r.constraint_units[name] = si_unit(d);
    };
    for (const Constraint& c : sys.constraints()) residual_unit(c.name, c.residual);
    if (speeds)
        for (std::size_t i = 0; i < speeds->motion_constraints.size(); ++i)
            residual_unit("motion_" + std::to_string(i + 1), speeds->motion_constraints[i]);
    // a spring, damper or attraction between coincident points has no direction at the start
    exmap at{{table.time(), r.options.t_initial}};
    for (const TimeVariable& v : r.coordinates)
        for (int k = 0; k < 2 && k <= v.order(); ++k) at[v.d(k)] = 0;
    for (const auto& [x, value] : r.initial_values) at[x] = value;
    check_line_loads_apart(at, r.coordinates);
    r.options.progress = isatty(STDERR_FILENO) != 0;
    std::string why_not;
    const Evaluation evaluation = evaluation_of(s);
    r.make = function_maker(evaluation, &why_not);
    // the hint is for a failed solve; other errors carry their own fix
    SimulationResult res = guard(s.location, [&] {
        try {
            return speeds ? run_speed_simulation(sys, *speeds, r) : run_simulation(sys, r);
        } catch (const SolveError& e) {
            throw ScriptError(s.location, in_script_words(e.what()),
                              speeds ? "check the initial values and the loads; a singular mass matrix or "
                                       "dependent speed means the speeds or the constraints do not fix "
                                       "the motion there (choose other dependent speeds)"
                                     : "check the initial values and the loads; a singular mass matrix "
                                       "means the coordinates do not fix the model's configuration");
        }
    });
    PlotOptions plot_options = plot_options_of(s, res.table.names);
    PlotResult plot = guard(s.location, [&] { return write_table_and_plot(res.table, dir, "simulation", plot_options); });
    record_history("simulate", s.location.line, dir + "/simulation.csv", res.table, nullptr);
    if (!res.contact_lost.empty())
        throw ScriptError(s.location, in_script_words(res.contact_lost),
                          "the rows up to that instant are in " + dir +
                              "/simulation.csv; simulate what follows with a model of the "
                              "bodies apart, or end the run before it (final time)");
    std::ostringstream out;
    out << "simulated t = " << transcript.number(r.options.t_initial) << " to " << transcript.number(res.t_end) << " s";
    if (!res.stopped_by.empty()) out << ", stopped when " << res.stopped_by;
    out << ": " << res.table.row_count() << " rows";
    if (r.options.integrator != Integrator::dopri5)
        out << ", integrated by " << to_string(r.options.integrator) << " in " << res.steps << " steps";
    std::string note = evaluator_note(evaluation, why_not);
    if (!note.empty()) out << ", " << note;
    out << "\nwrote " << file_list(plot, "simulation.csv");
    if (!plot.drawn) out << " (no plot: " << plot.message << ")";
    out << "\n" << format_table(res.table, transcript.digits());
    // the checks users rely on
    for (std::size_t c = 0; c < res.table.names.size(); ++c) {
        const std::vector<double>& col = res.table.columns[c];
        if (col.empty()) continue;
        if (res.table.names[c] == "energy") {
            double scale = 0, change = 0;
            for (double e : col) scale = std::max(scale, std::abs(e));
            for (double e : col) change = std::max(change, std::abs(e - col.front()));
            out << "\nenergy: " << transcript.number(col.front()) << " J at the start; ";
            if (change == 0) out << "unchanged";
            // a relative bound of 1e0 or more says nothing (an energy that stays near zero): in J
            else if (scale > 0 && change / scale < 0.1) out << "its largest change is below " << bound_of(change / scale) << " of its largest value";
            else out << "its largest change is below " << bound_of(change) << " J";
        } else if (res.table.names[c].rfind("drift_", 0) == 0) {
            double worst = 0;
            for (double e : col) worst = std::max(worst, std::abs(e));
            const std::string unit = res.table.units[c].empty() ? "" : " " + res.table.units[c];
            out << "\nconstraint " << res.table.names[c].substr(6) << ": ";
            if (worst == 0) out << "residual 0 throughout";
            else out << "largest residual below " << bound_of(worst) << unit;
        }
    }
    transcript.result(out.str());
}

// ---- code generation ---------------------------------------------------------------------

namespace {

void parse_initial(StatementParser& p, Statement& s) {
    s.bindings["values"] = p.bindings("a coordinate or its rate (initial qA = 30 deg, qA' = 0)");
}

void parse_input(StatementParser& p, Statement& s) {
    s.bindings["values"] = p.bindings("a load measure (input T_A = -k*qA)");
}

void parse_motion(StatementParser& p, Statement& s) {
    s.bindings["values"] = p.bindings("a coordinate (motion qA = 30*sin(2*pi*f*t) deg)");
}

void parse_final(StatementParser& p, Statement& s) {
    p.expect_word("time", "(final time 5 s)");
    s.quantities["time"] = p.quantity();
}

void parse_tolerance(StatementParser& p, Statement& s) {
    if (p.at_end())
        throw ScriptError(s.location, "a tolerance statement needs 'abs' or 'rel' and a number",
                          "write tolerance abs 1e-10 rel 1e-10");
    while (!p.at_end()) {
        if (p.accept_word("abs")) s.quantities["abs"] = p.quantity();
        else if (p.accept_word("rel")) s.quantities["rel"] = p.quantity();
        else p.fail_expected("'abs' or 'rel' and a number (tolerance abs 1e-10 rel 1e-10)");
    }
}

// integrator dopri5 | rkf78 | bulirsch_stoer | bdf
void parse_integrator_choice(StatementParser& p, Statement& s) {
    s.words["method"] = p.name("an integrator: dopri5, rkf78, bulirsch_stoer or bdf");
}

void run_integrator_choice(Interpreter::Impl& m, const Statement& s) {
    const Word& w = s.word("method");
    try {
        m.numbers.options.integrator = parse_integrator(w.text);
    } catch (const ArgumentError&) {
        throw ScriptError(w.location, "there is no integrator named '" + w.text + "'",
                          "choose dopri5 (the default), rkf78 or bulirsch_stoer (tight tolerances), "
                          "or bdf (stiff models): integrator rkf78");
    }
    if (!integrator_available(m.numbers.options.integrator))
        throw ScriptError(w.location,
                          "this alembert was built without SUNDIALS CVODE, which is the bdf integrator",
                          "install it and build again (Debian: apt-get install libsundials-dev, or "
                          "bash scripts/install_deps.sh test), or choose dopri5, rkf78 or bulirsch_stoer");
}

// output step h, or columns: expr [in unit], name = expr [in unit], ...
void parse_output(StatementParser& p, Statement& s) {
    // a number after step or limit, signed or not, is the setting (its sign is checked where it runs)
    auto number_follows = [&] {
        return p.peek(1).kind == TokenKind::number ||
               ((p.peek(1).is("-") || p.peek(1).is("+")) && p.peek(2).kind == TokenKind::number);
    };
    if (p.at_word("step") && number_follows()) {
        p.next();
        s.quantities["step"] = p.quantity();
        return;
    }
    if (p.at_word("limit") && number_follows()) {
        p.next();
        s.quantities["limit"] = p.quantity();
        return;
    }
    do {
        Word label{};
        if (p.peek().kind == TokenKind::name && p.peek(1).is("=")) {
            label = p.name("a column name");
            p.next();
        }
        s.lists["labels"].push_back(label);
        s.expr_lists["values"].push_back(p.expression());
        s.units.push_back(p.accept_word("in") ? p.unit() : UnitText{});
    } while (p.accept_punct(","));
}

void parse_stop(StatementParser& p, Statement& s) {
    p.expect_word("when", "(stop when qA = 0 [rising | falling])");
    s.exprs["lhs"] = p.expression();
    p.expect_punct("=", "and the value it crosses (stop when qA = 0)");
    s.quantities["rhs"] = p.quantity();
    if (p.at_word("rising") || p.at_word("falling")) s.words["direction"] = p.take_word();
}

// simulate, inverse, codegen: their clauses in any order
void parse_run(StatementParser& p, Statement& s) {
    const std::string& k = s.keyword;
    if (k == "codegen") s.words["language"] = p.name("a language: c, cpp, matlab or python");
    while (!p.at_end()) {
        if (k == "inverse" && p.accept_word("for")) s.lists["loads"] = p.name_list("a load measure");
        else if (k == "codegen" && p.accept_word("for")) s.lists["loads"] = p.name_list("a load measure");
        else if (k == "inverse" && p.accept_word("from")) {
            s.words["from"] = p.text("the motion table's path");
            if (p.accept_word("cutoff")) s.quantities["cutoff"] = p.quantity();
        } else if (k == "inverse" && p.accept_word("per")) {
            p.expect_word("kg", "(per kg mass 70 kg: loads and powers per kg of body mass)");
            p.expect_word("mass", "and the body mass (per kg mass 70 kg)");
            s.quantities["mass"] = p.quantity();
        } else if (k == "inverse" && p.accept_word("cycles")) {
            s.lists["cycles"] = p.name_list("a plate one foot steps on (cycles floor1, floor2)");
        } else if (k == "codegen" && p.accept_word("name")) s.words["name"] = p.name("an identifier for the files");
        else if (k == "codegen" && p.accept_word("jacobian")) s.lists["jacobians"] = p.name_list("a point or a body");
        else if (k == "codegen" && p.at_word("derivatives")) s.words["derivatives"] = p.take_word();
        else if (k != "codegen" && (p.at_word("compiled") || p.at_word("tape"))) {
            const Word w = p.take_word();
            if (s.flags.count(w.text == "tape" ? "compiled" : "tape"))
                throw ScriptError(w.location, "'compiled' and 'tape' both given",
                                  "keep one: compiled C code is the default where a C compiler is found");
            s.flags[w.text] = true;
        }
        else if (k != "codegen" && p.accept_word("plot")) s.lists["plot"] = p.name_list("a column to plot, or none");
        else if (p.accept_word("to")) s.words["to"] = p.text("the output directory");
        else p.fail_expected(k == "simulate" ? "'compiled', 'tape', 'plot' or 'to'"
                             : k == "inverse" ? "'for', 'from', 'per kg', 'cycles', 'compiled', 'tape', 'plot' or 'to'"
                                              : "'for', 'name', 'jacobian', 'derivatives' or 'to'");
    }
    if (k == "inverse" && !s.lists.count("loads"))
        throw ScriptError(s.location, "inverse dynamics needs the load measures to solve for",
                          "write inverse for T_A, T_B");
}

// report [at q = value, ...] [plot names | plot none] [check] [matrices] [to "dir"]; latex [at ...] [to "dir"]
void parse_report(StatementParser& p, Statement& s) {
    const bool report = s.keyword == "report";
    while (!p.at_end()) {
        if (p.accept_word("at")) s.bindings["at"] = p.bindings("a coordinate");
        else if (report && p.accept_word("plot")) s.lists["plot"] = p.name_list("a column to plot, or none");
        else if (report && p.accept_word("check")) s.flags["check"] = true;
        else if (report && p.accept_word("matrices")) s.flags["matrices"] = true;
        else if (p.accept_word("to")) s.words["to"] = p.text("the output directory");
        else p.fail_expected(report ? "'at', 'plot', 'check', 'matrices' or 'to'" : "'at' or 'to'");
    }
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> number_statements() {
    using M = Interpreter::Impl;
    const std::string_view family = "Simulation, inverse dynamics, code generation";
    return {
        {.keyword = "initial", .family = family, .help = "sets initial values of coordinates and rates",
         .forms = {{"`initial` *q = value, q' = value, ...*",
                    "initial qA = 20 deg, qA' = 0",
                    "`SimulationRequest::initial_values` (others 0)"}},
         .parse = parse_initial, .run = [](M& m, const Statement& s) { m.set_initial(s); }},
        {.keyword = "input", .family = family,
         .help = "gives load measures as formulas of time and state for simulate",
         .forms = {{"`input` *load = formula, ...*",
                    "input T_A = -k*qA - c*qA'",
                    "`SimulationRequest::inputs`: a load measure as a formula of t, q, q' and constants (in a constrained model the others are the constraint forces, solved for; in minimal coordinates a friction's normal force and the contact forces an output reads are solved from their road-map rows, and a workless load no row determines is refused; the others are 0); for a `specified` quantity, `SimulationRequest::specified`"}},
         .parse = parse_input, .run = [](M& m, const Statement& s) { m.set_inputs(s); }},
        {.keyword = "final", .family = family, .help = "sets the final time of simulate and inverse",
         .forms = {{"`final time` *T*",
                    "final time 5 s",
                    "`SimulationOptions::t_final` (default 1 s)"}},
         .parse = parse_final, .run = [](M& m, const Statement& s) { m.set_times_and_tolerances(s); }},
        {.keyword = "output", .family = family,
         .help = "sets the output step, or adds columns to the table simulate writes",
         .forms = {{"`output step` *h*",
                    "output step 0.01 s",
                    "`SimulationOptions::output_step` (default 0.01 s): rows exactly at these times"},
                   {"`output limit` *n*",
                    "output limit 5000000",
                    "`SimulationOptions::max_output_rows` (default 1000000): `simulate` and `inverse` refuse, before they start, a run that would write more rows"},
                   {"`output` *expr* [`in` *unit*], *name* `=` *expr* [`in` *unit*], ...",
                    "output qA in deg, h = dot(pos(Ccm, N_o), Ny>) in cm",
                    "`SimulationRequest::outputs` (a name alone names its column; other expressions need `name =`, and a column named like a symbol of the model holds that symbol, `output q = 2*q` is an error; without `in`, a declared unit or SI)"}},
         .clauses = {"in"}, .parse = parse_output, .run = [](M& m, const Statement& s) { m.add_outputs(s); }},
        {.keyword = "tolerance", .family = family, .help = "sets the integrator's tolerances",
         .forms = {{"`tolerance` [`abs` *a*] [`rel` *r*]",
                    "tolerance abs 1e-12 rel 1e-12",
                    "`SimulationOptions::abs_tol`, `rel_tol` (default 1e-8)"}},
         .clauses = {"rel"}, .parse = parse_tolerance,
         .run = [](M& m, const Statement& s) { m.set_times_and_tolerances(s); }},
        {.keyword = "integrator", .family = family, .help = "chooses the method simulate integrates with",
         .forms = {{"`integrator` `dopri5`\\|`rkf78`\\|`bulirsch_stoer`\\|`bdf`",
                    "integrator rkf78",
                    "`SimulationOptions::integrator` (default `dopri5`, Dormand-Prince 5(4)); `rkf78` "
                    "(Runge-Kutta-Fehlberg 7(8)) and `bulirsch_stoer` for tight tolerances, `bdf` "
                    "(SUNDIALS CVODE, implicit) for stiff models; each keeps output times and "
                    "`stop when` events; generated code keeps Dormand-Prince"}},
         .parse = parse_integrator_choice, .run = run_integrator_choice},
        {.keyword = "stop", .family = family,
         .help = "stops simulate where an expression crosses a value",
         .forms = {{"`stop when` *expr* `=` *value* [`rising`\\|`falling`]",
                    "stop when dot(pos(Ccm, N_o), Ny>) = 50 cm falling",
                    "`SimulationRequest::events`: the run stops where expr − value crosses zero"}},
         .clauses = {"when", "rising", "falling"}, .parse = parse_stop,
         .run = [](M& m, const Statement& s) { m.add_event(s); }},
        {.keyword = "simulate", .family = family,
         .help = "integrates the equations of motion; writes a table and its plots",
         .forms = {{"`simulate` [`compiled` \\| `tape`] [`plot` *columns* \\| `plot none`] [`to` *\"dir\"*]",
                    "simulate to \"fall\"",
                    "`run_simulation` (after a `kane` statement with speeds and kinematics, `run_speed_simulation` on those equations: state q and the independent speeds, the dependent speeds from the constraints), then `write_table_and_plot(..., \"simulation\")`: `simulation.csv`, `.png`, `.svg`; prints a table of about ten rows, the energy check (conservative models: an `energy` column) and the drift of each constraint (a contact load it solves for that changes sign ends the run with an error naming it and the time, the rows up to then written: `SimulationResult::contact_lost`); `plot` chooses the columns drawn, `plot none` draws none (runs over 4000 rows are drawn from rows keeping each column's extremes)"}},
         .clauses = {"compiled", "tape", "plot", "to"}, .parse = parse_run,
         .run = [](M& m, const Statement& s) { m.simulate(s); }},
        {.keyword = "motion", .family = family,
         .help = "prescribes coordinates as formulas of time, for inverse",
         .forms = {{"`motion` *q = formula of t, ...*",
                    "motion qA = (-25 + 20*minimum_jerk(t, 0.15, 1.5)) deg",
                    "`PrescribedMotion` (q', q'' exact) for `inverse`; a `specified` quantity (`motion xb = A*sin(w*t)`) is driven in `simulate` and `inverse` with its derivatives (`SimulationRequest::specified`; `compile_inverse_dynamics(..., specified)`: the load that drives it comes from its road-map row)"}},
         .parse = parse_motion, .run = [](M& m, const Statement& s) { m.set_prescribed_motion(s); }},
        {.keyword = "inverse", .family = family,
         .help = "inverse dynamics over the prescribed motion or a motion table",
         .forms = {{"`inverse for` *loads* [`compiled` \\| `tape`] [`plot` *loads* \\| `plot none`] [`to` *\"dir\"*]",
                    "inverse for T_A, T_B, T_C",
                    "`compile_inverse_dynamics` + `run_inverse_dynamics` over the prescribed motion, sampled every output step to the final time: `torques.csv`, `.png`, `.svg`"},
                   {"`inverse for` *loads* `from` *\"file.csv\"* [`cutoff` *f*] [`compiled` \\| `tape`] [`plot` ...] [`to` *\"dir\"*]",
                    "inverse for T_A, T_B, T_C from \"motion.csv\" cutoff 6 Hz",
                    "the same over a motion table (columns `t [s]` and one per coordinate, units in the header), filtered at f in cycles per second (default 6 Hz; a bare number is Hz; 0: none) and differentiated"},
                   {"`inverse for` *loads* ... [`per kg mass` *M*] [`cycles` *plates*]",
                    "inverse for T_H, T_K from \"walk.trc\" per kg mass 56.7 kg cycles right",
                    "besides the loads (and their `.sto`): `kinematics.csv`/`.sto` (q, q', q''), `powers.csv`/`.sto` (each load times the rate it works through, `LoadRates`); `per kg mass`: loads and powers per kg (`calc_per_kg`); `cycles`: gait events from the plates one foot steps on (`calc_gait_events`) and each cycle, strike to strike, resampled onto 0-100 % at 101 points (`calc_cycle_table`): `cycle_1.csv`, ..., `gait_events.csv`"}},
         .clauses = {"for", "from", "cutoff", "per", "cycles", "compiled", "tape", "plot", "to"},
         .parse = parse_run, .run = [](M& m, const Statement& s) { m.inverse(s); }},
        {.keyword = "report", .family = family,
         .help = "writes an HTML report: road-map with free-body diagrams, equations, plots, motion",
         .forms = {{"`report` [`at` *q = value, ...*] [`plot` *columns* \\| `plot none`] [`check`] [`matrices`] [`to` *\"dir\"*]",
                    "report at qA = 20 deg, qB = -70 deg, qC = 60 deg to \"report\"",
                    "`write_report`: `index.html` (self-contained; KaTeX's fonts in `fonts/`) and `roadmap.tex` (the table, TikZ free-body diagrams and equations for LaTeX) with the model, the last road-map (or the planned one) with each row's free-body diagram drawn at the `at` configuration (default: the first sample of the motion, else the initial values), the equations typeset, the tables simulate and inverse wrote as plots (one unit per plot axis, at most ten series per plot, each titled with the statement, line and table that computed it; `plot` chooses the columns, `plot none` skips them; long runs thinned to about 2000 rows keeping their extremes), the motion animated in real time with a speed control (in 3D, turned by dragging; the plots' cursor moves it), and the checks (energy, constraint drift; with `check`, `compare_methods` and `compare_reactions`); with `matrices`, the mass matrix and forcing M q'' = f typeset (`form_forward_equations`, as simulate forms them)"}},
         .clauses = {"at", "plot", "check", "matrices", "to"}, .parse = parse_report, .run = [](M& m, const Statement& s) { m.report(s); }},
        {.keyword = "latex", .family = family,
         .help = "writes the road-map, its free-body diagrams and equations as a LaTeX document",
         .forms = {{"`latex` [`at` *q = value, ...*] [`to` *\"dir\"*]",
                    "latex at qA = 20 deg, qB = -70 deg, qC = 60 deg to \"paper\"",
                    "`write_report_latex`: `roadmap.tex` alone (article, amsmath, TikZ): the road-map table, each row's free-body diagram drawn in TikZ at the `at` configuration with its loads listed, and the equations with the intermediates they use"}},
         .clauses = {"at", "to"}, .parse = parse_report, .run = [](M& m, const Statement& s) { m.latex(s); }},
        {.keyword = "codegen", .family = family,
         .help = "generates C, C++, MATLAB or Python code for the model's equations",
         .forms = {{"`codegen` *c\\|cpp\\|matlab\\|python* [`name` *N*] [`for` *loads*] [`jacobian` *points, bodies*] [`derivatives`] [`to` *\"dir\"*]",
                    "codegen c name fall jacobian C derivatives to \"code\"",
                    "`generate_code` on Kane's equations (a tree's recursive rows when the model is one; after a `kane` statement with speeds and kinematics, on those equations in speeds): functions for M and f, forward and inverse dynamics, M alone and the bias forces (trees), the outputs, and a simulation program with the script's settings (the declared joint reactions without an `input` computed at every sample from their road-map rows, `NAME_reactions`; refused for constrained models and equations in speeds); per `jacobian` name its position, Jacobian and J' q' (`form_point_jacobian`, or `form_frame_jacobian` of a body at its origin B_o, else its mass centre); with `derivatives`, d u/d q and d u/d q' of inverse dynamics and q'' with d q''/d q and d q''/d q' (`add_dynamics_derivatives`; one load per coordinate, no constraints, not in generalized speeds)"}},
         .clauses = {"for", "jacobian", "derivatives", "to"}, .parse = parse_run, .run = [](M& m, const Statement& s) { m.codegen(s); }},
    };
}

}  // namespace alembert::lang
