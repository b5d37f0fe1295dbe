// SPDX-License-Identifier: MIT
// The interpreter: the run loop, names, declarations and the model-building statements.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "alembert/lang/lexer.hpp"
#include "alembert/lang/parser.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

const char* kind_word(NameKind k) {
    switch (k) {
        case NameKind::frame: return "a frame";
        case NameKind::body: return "a rigid body";
        case NameKind::particle: return "a particle";
        case NameKind::point: return "a point";
        case NameKind::system: return "a system";
        case NameKind::symbol: return "a symbol";
        case NameKind::value: return "a value";
    }
    return "a name";
}

std::string at_line(Location l) { return " (line " + std::to_string(l.line) + ")"; }

Axis axis_of(const Word& w) {
    if (w.text == "x") return Axis::x;
    if (w.text == "y") return Axis::y;
    if (w.text == "z") return Axis::z;
    throw ScriptError(w.location, "'" + w.text + "' is not an axis", "write x, y or z (or -z)");
}

}  // namespace

std::string monogram_part(const std::string& name) {
    std::string out;
    for (char c : name)
        if (c != '_') out += c;
    return out.empty() ? name : out;
}

// ---- the public class ------------------------------------------------------------------

Interpreter::Interpreter(std::ostream& out, std::ostream& err, bool echo)
    : impl_(std::make_unique<Impl>(out, err, echo)) {}
Interpreter::~Interpreter() = default;

void Interpreter::set_echo(bool echo) { impl_->transcript.set_echo(echo); }

const std::optional<Diagnostic>& Interpreter::last_error() const { return impl_->last_error; }

const System* Interpreter::system() const { return impl_->sys.get(); }

void Interpreter::set_output_dir(const std::string& dir) { impl_->output_dir = dir.empty() ? "." : dir; }

void Interpreter::set_model_only(bool model_only) { impl_->model_only = model_only; }

void Interpreter::set_allow_outside_output(bool allow) { impl_->allow_outside_output = allow; }

void Interpreter::set_max_terms(std::size_t max_terms) { impl_->max_terms = max_terms; }

namespace {

// runs a command of the public API, reporting a ScriptError or library error as `who: error`
template <class F>
RunStatus run_command(Interpreter::Impl& m, const std::string& who, F&& f) {
    m.transcript.set_muted(false);
    try {
        f();
    } catch (const ScriptError& e) {
        m.transcript.flush();
        *m.err << who << ": error: " << e.what() << "\n";
        if (!e.hint().empty()) *m.err << "hint: " << e.hint() << "\n";
        return RunStatus::script_error;
    } catch (const InternalError& e) {
        *m.err << who << ": internal error: " << e.what() << "\n";
        return RunStatus::internal_error;
    } catch (const std::exception& e) {
        *m.err << who << ": internal error: " << e.what() << "\n";
        return RunStatus::internal_error;
    }
    m.transcript.flush();
    return RunStatus::ok;
}

}  // namespace

RunStatus Interpreter::run_inverse(const std::string& motion_csv, double cutoff_hz, bool compiled) {
    Impl& m = *impl_;
    return run_command(m, m.script_file, [&] {
        const System& sys = m.model({1, 1});
        InverseRequest r;
        r.loads = sys.symbols().symbols(SymbolKind::unknown);
        if (r.loads.empty())
            throw ScriptError({1, 1}, "the model declares no load measures to compute",
                              "declare the joint torques with 'unknown' and apply them with 'torque'");
        r.motion_file = motion_csv;
        r.cutoff_hz = cutoff_hz;
        r.compiled = compiled;
        r.dir = m.output_dir;
        m.run_inverse(r, {1, 1});
    });
}

RunStatus Interpreter::run_codegen(const std::string& language, const std::string& name) {
    Impl& m = *impl_;
    return run_command(m, m.script_file, [&] {
        CodegenRequest r;
        r.language = {language, {1, 1}};
        r.name = name;
        r.dir = m.output_dir;
        m.run_codegen(r, {1, 1});
    });
}

RunStatus Interpreter::run(std::string_view source, const std::string& file, int first_line) {
    Impl& m = *impl_;
    // a UTF-8 byte-order mark some editors put at the start of a file is not part of the script
    if (first_line == 1 && source.starts_with("\xEF\xBB\xBF")) source.remove_prefix(3);
    m.last_error.reset();
    m.transcript.set_muted(m.model_only);
    if (m.script_file.empty()) {
        namespace fs = std::filesystem;
        m.script_file = file;
        std::error_code ec;
        if (fs::is_regular_file(file, ec)) {
            m.base_dir = fs::path(file).parent_path().string();
            std::string stem = fs::path(file).stem().string();
            bool ok = !stem.empty() && (std::isalpha(static_cast<unsigned char>(stem[0])) || stem[0] == '_');
            for (char c : stem) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            if (ok) m.script_name = stem;
        }
    }
    auto report = [&](Location where, const std::string& message, const std::string& hint) {
        m.transcript.flush();
        Diagnostic d{Severity::error, file, where, message, hint};
        *m.err << format_diagnostic(d, source, first_line);
        m.err->flush();
        m.last_error = d;
    };
    try {
        Lexer lexer(source, first_line);
        for (;;) {
            std::vector<Token> tokens = lexer.next_statement();
            if (tokens.empty()) break;
            Statement s = parse_statement(tokens, source);
            if (s.keyword == "#") {
                m.transcript.comment(s.source);
                continue;
            }
            m.transcript.statement(s.source);
            m.execute(s);
        }
    } catch (const ScriptError& e) {
        report(e.where(), e.what(), e.hint());
        return RunStatus::script_error;
    } catch (const InternalError& e) {
        report({first_line, 1}, std::string("internal error: ") + e.what(),
               "this is a bug in Alembert; please report it with the script");
        return RunStatus::internal_error;
    } catch (const std::exception& e) {
        report({first_line, 1}, std::string("internal error: ") + e.what(),
               "this is a bug in Alembert; please report it with the script");
        return RunStatus::internal_error;
    }
    m.transcript.flush();
    return RunStatus::ok;
}

std::string Interpreter::roadmap_text(bool json) {
    Impl& m = *impl_;
    System& sys = m.model({1, 1});
    std::vector<RoadmapRow> rows;
    if (!m.last_roadmap.empty()) {
        rows = m.roadmaps.at(m.last_roadmap).rows;
    } else {
        std::vector<TimeVariable> q = m.default_coordinates();
        std::vector<ex> unknowns = sys.symbols().symbols(SymbolKind::unknown);
        if (unknowns.empty())
            for (const TimeVariable& v : q) unknowns.push_back(v.d(std::min(2, v.order())));
        if (q.empty()) throw ScriptError({1, 1}, "the model declares no variables to plan a road-map for",
                                         "declare coordinates with 'variable q''' and orient or locate with them");
        rows = m.guard({1, 1}, [&] { return plan_roadmap(sys, q, unknowns); });
    }
    return json ? format_roadmap_json(sys, rows) : format_roadmap_table(sys, rows);
}

// ---- names and objects -------------------------------------------------------------------

System& Interpreter::Impl::model(Location where) {
    if (!sys)
        throw ScriptError(where, "there is no model yet",
                          "start the script with the Newtonian frame: newtonian N");
    return *sys;
}

void Interpreter::Impl::declare_name(const Word& w, NameKind kind) {
    if (is_reserved(w.text))
        throw ScriptError(w.location, "'" + w.text + "' is a word of the language and cannot name " +
                                          kind_word(kind),
                          "choose another name");
    if (w.text.find('\'') != std::string::npos)
        throw ScriptError(w.location, "'" + w.text + "': only variables take primes",
                          "name it without primes");
    auto it = names.find(w.text);
    if (it != names.end())
        throw ScriptError(w.location, "'" + w.text + "' is already declared as " +
                                          kind_word(it->second.kind) + at_line(it->second.declared),
                          "choose another name");
    names[w.text] = {kind, w.location};
}

void Interpreter::Impl::undeclared(const Word& w, const std::string& wanted) const {
    auto it = names.find(w.text);
    if (it != names.end())
        throw ScriptError(w.location, "'" + w.text + "' is " + kind_word(it->second.kind) +
                                          at_line(it->second.declared) + ", not " + wanted,
                          "name " + wanted + " here");
    std::string base = w.text.substr(0, w.text.find('\''));
    if (base != w.text && names.count(base))
        throw ScriptError(w.location, "'" + w.text + "' is not declared: " + base +
                                          " has fewer derivatives",
                          "declare it with more primes, e.g. variable " + base + "''");
    throw ScriptError(w.location, "'" + w.text + "' is not declared",
                      "declare " + wanted + " first (docs/language.md, Declarations)");
}

Frame& Interpreter::Impl::frame(const Word& w) {
    System& s = model(w.location);
    auto it = names.find(w.text);
    if (it != names.end() && it->second.kind == NameKind::frame) return s.frame(w.text);
    if (it != names.end() && it->second.kind == NameKind::body) return s.rigid_body(w.text).body_frame();
    undeclared(w, "a frame or rigid body");
}

Point& Interpreter::Impl::point(const Word& w) {
    System& s = model(w.location);
    auto it = names.find(w.text);
    if (it != names.end() && (it->second.kind == NameKind::point || it->second.kind == NameKind::particle))
        return s.point(w.text);
    undeclared(w, "a point");
}

Body& Interpreter::Impl::body(const Word& w) {
    System& s = model(w.location);
    auto it = names.find(w.text);
    if (it != names.end() && (it->second.kind == NameKind::body || it->second.kind == NameKind::particle))
        return s.body(w.text);
    undeclared(w, "a body or particle");
}

RigidBody& Interpreter::Impl::rigid_body(const Word& w) {
    System& s = model(w.location);
    auto it = names.find(w.text);
    if (it != names.end() && it->second.kind == NameKind::body) return s.rigid_body(w.text);
    undeclared(w, "a rigid body");
}

BodySet Interpreter::Impl::body_set(const Word& w) {
    auto it = systems.find(w.text);
    if (it != systems.end()) return it->second;
    auto n = names.find(w.text);
    if (n != names.end() && (n->second.kind == NameKind::body || n->second.kind == NameKind::particle))
        return {&body(w)};
    undeclared(w, "a system or body (system S = A, B)");
}

ex Interpreter::Impl::symbol(const Word& w, const std::string& wanted) {
    System& s = model(w.location);
    if (s.symbols().contains(w.text)) return s.symbols().symbol(w.text);
    undeclared(w, wanted);
}

TimeVariable Interpreter::Impl::variable(const Word& w) {
    System& s = model(w.location);
    if (s.symbols().contains(w.text)) {
        const ex& x = s.symbols().symbol(w.text);
        SymbolKind k = s.symbols().kind(x);
        if ((k == SymbolKind::variable || k == SymbolKind::specified) &&
            s.symbols().derivative_order(x) == 0)
            return s.symbols().variable(w.text);
        throw ScriptError(w.location, "'" + w.text + "' is not a variable (it is a " +
                                          to_string(k) +
                                          (s.symbols().derivative_order(x) ? " derivative" : "") + ")",
                          "name a variable declared with 'variable', without primes");
    }
    undeclared(w, "a variable");
}

std::vector<TimeVariable> Interpreter::Impl::default_coordinates() {
    if (coordinates_given) return coordinates;
    std::vector<TimeVariable> q;
    const SymbolTable& t = sys->symbols();
    for (const ex& x : t.symbols(SymbolKind::variable))
        if (t.derivative_order(x) == 0) q.push_back(t.variable(t.name(x)));
    return q;
}

Dimension Interpreter::Impl::symbol_dimension(const std::string& printed) const {
    if (printed == "t") return Dimension::time();
    std::size_t p = printed.find('\'');
    std::string base = printed.substr(0, p);
    int primes = p == std::string::npos ? 0 : static_cast<int>(printed.size() - p);
    auto it = units.find(base);
    if (it == units.end()) return Dimension::open();
    return it->second.dim / pow(Dimension::time(), primes);
}

std::optional<Unit> Interpreter::Impl::display_unit(const std::string& printed) const {
    std::size_t p = printed.find('\'');
    std::string base = printed.substr(0, p);
    int primes = p == std::string::npos ? 0 : static_cast<int>(printed.size() - p);
    auto it = units.find(base);
    if (it == units.end()) return std::nullopt;
    Dimension d = symbol_dimension(printed);
    if (it->second.display) {
        Unit u = *it->second.display;
        if (primes > 0) u.text += "/s" + (primes > 1 ? "^" + std::to_string(primes) : std::string());
        u.dimension = d;
        return u;
    }
    if (d.known && !d.is_none()) return Unit{1, d, si_unit(d)};
    return std::nullopt;
}

std::string Interpreter::Impl::format_value(const std::string& printed, double si) const {
    std::optional<Unit> u = display_unit(printed);
    if (!u) return printed + " = " + format_number(si);
    return printed + " = " + format_number(si / u->scale) + " " + u->text;
}

double Interpreter::Impl::number_of(const Quantity& q, const Dimension& expected,
                                    const std::string& what, Location where, Dimension* got) {
    Value v = eval(*q.value);
    if (v.kind != Value::Kind::scalar)
        throw ScriptError(q.value->location, what + " must be a number", "");
    ex n = guard(q.value->location, [&] { return GiNaC::evalf(v.s); });
    if (!GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_real())
        throw ScriptError(q.value->location, what + " must be a number, not " + to_string(v.s),
                          "give a number with an optional unit, e.g. 20 deg");
    double x = GiNaC::ex_to<GiNaC::numeric>(n).to_double();
    Dimension d = Dimension::open();
    if (!q.unit.empty()) {
        Unit u = parse_unit(q.unit);
        x *= u.scale;
        d = u.dimension;
        if (d.conflicts(expected))
            throw ScriptError(q.unit.location, what + " must be " + describe(expected) + ", but " +
                                                   u.text + " is " + describe(d),
                              "write it in a unit of the declared dimension");
    }
    if (got) *got = d;
    (void)where;
    return x;
}

exmap Interpreter::Impl::bindings(const std::vector<Binding>& list, const std::string& purpose) {
    exmap out;
    for (const Binding& b : list) {
        ex x = symbol(b.name, "a symbol to give a value " + purpose);
        if (out.count(x))
            throw ScriptError(b.name.location, "'" + b.name.text + "' is given twice", "give each value once");
        out[x] = number_of(b.quantity, symbol_dimension(b.name.text), "the value of " + b.name.text,
                           b.name.location);
    }
    return out;
}

// ---- statements --------------------------------------------------------------------------

void Interpreter::Impl::execute(const Statement& s) {
    const std::string& k = s.keyword;
    if (k == "newtonian") {
        if (sys)
            throw ScriptError(s.location, "the Newtonian frame is already declared (" +
                                              sys->newtonian().name() + ")",
                              "a model has one Newtonian frame; declare other frames with 'frame'");
        const Word& n = s.word("name");
        declare_name(n, NameKind::frame);
        sys = std::make_unique<System>(n.text);
        names[n.text + "_o"] = {NameKind::point, n.location};
        return;
    }
    model(s.location);
    if (k == "frame" || k == "body" || k == "particle" || k == "point") return declare_objects(s);
    if (k == "constant" || k == "variable" || k == "specified" || k == "unknown")
        return declare_symbols(s);
    if (k == "coordinates") {
        std::vector<TimeVariable> q;
        for (const Word& w : s.lists.at("names")) q.push_back(variable(w));
        coordinates = q;
        coordinates_given = true;
        return;
    }
    if (k == "system") {
        const Word& n = s.word("name");
        BodySet S;
        for (const Word& w : s.lists.at("bodies")) {
            const Body* b = &body(w);
            if (std::find(S.begin(), S.end(), b) != S.end())
                throw ScriptError(w.location, "'" + w.text + "' is listed twice", "list each body once");
            S.push_back(b);
        }
        declare_name(n, NameKind::system);
        systems[n.text] = S;
        return;
    }
    if (k == "rotate") return orient(s);
    if (k == "translate" || k == "velocity" || k == "acceleration" || k == "angvel" || k == "angacc")
        return set_motion(s);
    if (k == "mass" || k == "inertia") return set_mass_or_inertia(s);
    if (k == "gravity" || k == "force" || k == "torque" || k == "spring" || k == "damper" ||
        k == "drag" || k == "friction" || k == "attraction")
        return add_load(s);
    if (k == "constraint") return add_constraint(s);
    if (k == "roadmap") return roadmap(s);
    if (k == "row") return row(s);
    if (k == "kane" || k == "lagrange") return methods(s);
    if (k == "solve") return solve(s);
    if (k == "evaluate") return evaluate_statement(s);
    if (k == "initial") return set_initial(s);
    if (k == "input") return set_inputs(s);
    if (k == "motion") return set_prescribed_motion(s);
    if (k == "final" || k == "tolerance") return set_times_and_tolerances(s);
    if (k == "output") return add_outputs(s);
    if (k == "stop") return add_event(s);
    if (k == "simulate") return simulate(s);
    if (k == "inverse") return inverse(s);
    if (k == "codegen") return codegen(s);
    if (k == "=") return assign(s);
    return show(s);
}

void Interpreter::Impl::declare_objects(const Statement& s) {
    System& m = model(s.location);
    const std::string& k = s.keyword;
    const Body* owner = s.has_word("on") ? &body(s.word("on")) : nullptr;
    for (const Word& w : s.lists.at("names")) {
        if (k == "frame") {
            declare_name(w, NameKind::frame);
            guard(w.location, [&] { m.add_frame(w.text); });
        } else if (k == "point") {
            declare_name(w, NameKind::point);
            guard(w.location, [&] { m.add_point(w.text, owner); });
        } else if (k == "particle") {
            declare_name(w, NameKind::particle);
            guard(w.location, [&] { m.add_particle(w.text); });
        } else {
            // the body's frame shares its name; its origin and mass centre are points
            for (const std::string& p : {w.text + "_o", w.text + "cm"})
                if (names.count(p))
                    throw ScriptError(w.location, "body '" + w.text + "' needs the point name '" + p +
                                                      "', which is already " + kind_word(names[p].kind) +
                                                      at_line(names[p].declared),
                                      "choose another name for the body");
            declare_name(w, NameKind::body);
            guard(w.location, [&] { m.add_rigid_body(w.text); });
            names[w.text + "_o"] = {NameKind::point, w.location};
            names[w.text + "cm"] = {NameKind::point, w.location};
        }
    }
}

void Interpreter::Impl::declare_symbols(const Statement& s) {
    System& m = model(s.location);
    SymbolTable& table = m.symbols();
    const std::string& k = s.keyword;
    for (const Declared& d : s.declared) {
        bool timed = k == "variable" || k == "specified";
        if (d.primes > 0 && !timed)
            throw ScriptError(d.name.location, "a " + k + " has no derivatives",
                              "declare '" + d.name.text + "' without primes, or as a variable");
        if (d.primes > Limits::max_derivative)
            throw ScriptError(d.name.location, "'" + d.name.text + "' declares " +
                                                   std::to_string(d.primes) +
                                                   " derivatives; at most 4 are allowed",
                              "declare only the derivatives the equations need (q'' for dynamics)");
        if (d.quantity.value && k != "constant")
            throw ScriptError(d.quantity.value->location, "only constants take a value when declared",
                              "give values to " + k + "s in 'solve ... at' or 'evaluate ... at'");
        SymbolUnits su;
        std::optional<double> value;
        if (!d.quantity.unit.empty()) {
            Unit u = parse_unit(d.quantity.unit);
            su.dim = u.dimension;
            su.display = u;
        }
        if (d.quantity.value) {
            Dimension got = Dimension::open();
            value = number_of(d.quantity, Dimension::open(), "the value of " + d.name.text,
                              d.name.location, &got);
        }
        declare_name(d.name, NameKind::symbol);
        guard(d.name.location, [&] {
            if (k == "constant") table.add_constant(d.name.text, value);
            else if (k == "variable") table.add_variable(d.name.text, d.primes);
            else if (k == "specified") table.add_specified(d.name.text, d.primes);
            else table.add_unknown(d.name.text);
        });
        for (int i = 1; i <= d.primes; ++i)
            names[d.name.text + std::string(static_cast<std::size_t>(i), '\'')] = {NameKind::symbol,
                                                                                   d.name.location};
        units[d.name.text] = su;
    }
}

void Interpreter::Impl::orient(const Statement& s) {
    const Word& target = s.word("target");
    const Word& from = s.word("from");
    Frame& B = frame(target);
    Frame& A = frame(from);
    const std::string& kind = s.word("kind").text;
    auto angle = [&](const ExprPtr& e) { return scalar(*e, Dimension::none(), "the rotation angle"); };
    static const std::vector<ExprPtr> none;
    const auto& angles = s.expr_lists.count("angles") ? s.expr_lists.at("angles") : none;
    Location where = from.location;
    if (kind == "about") {
        Axis axis = axis_of(s.word("axis"));
        ex q = angle(angles.at(0));
        guard(where, [&] { B.orient_axis(A, axis, q, s.flag("negative") ? Sense::negative : Sense::positive); });
    } else if (kind == "body" || kind == "space") {
        const Word& seq = s.word("sequence");
        RotationSequence rs = guard(seq.location, [&] { return parse_rotation_sequence(seq.text); });
        if (angles.size() != 3)
            throw ScriptError(angles.size() > 3 ? angles[3]->location : s.word("sequence").location,
                              "a " + kind + "-fixed sequence takes 3 angles, not " +
                                  std::to_string(angles.size()),
                              "write: rotate " + target.text + " from " + from.text + " " + kind +
                                  " " + seq.text + " by q1, q2, q3");
        ex q1 = angle(angles[0]), q2 = angle(angles[1]), q3 = angle(angles[2]);
        guard(where, [&] {
            if (kind == "body") B.orient_body_fixed(A, rs, q1, q2, q3);
            else B.orient_space_fixed(A, rs, q1, q2, q3);
        });
    } else {
        Value v = eval(*s.exprs.at("dcm"));
        if (v.kind != Value::Kind::matrix)
            throw ScriptError(s.exprs.at("dcm")->location,
                              "a direction-cosine matrix must be 3 by 3, written [a, b, c; d, e, f; g, h, i]",
                              "separate the rows with ';'");
        check_dimension(v.dim, Dimension::none(), "a direction-cosine matrix", s.exprs.at("dcm")->location);
        guard(where, [&] { B.orient_dcm(A, v.m); });
    }
}

void Interpreter::Impl::set_motion(const Statement& s) {
    const std::string& k = s.keyword;
    const Dimension L = Dimension::length(), T = Dimension::time();
    if (k == "translate") {
        Point& P = point(s.word("target"));
        Point& O = point(s.word("from"));
        Vector r = vector(*s.exprs.at("value"), L, "the position of " + s.word("target").text);
        guard(s.word("from").location, [&] { P.set_pos(O, r); });
        return;
    }
    if (k == "angvel" || k == "angacc") {
        Frame& B = frame(s.word("target"));
        Frame& A = frame(s.word("in"));
        bool acc = k == "angacc";
        Vector w = vector(*s.exprs.at("value"), acc ? pow(T, -2) : pow(T, -1),
                          acc ? "an angular acceleration" : "an angular velocity");
        guard(s.word("in").location, [&] { acc ? B.set_ang_acc(A, w) : B.set_ang_vel(A, w); });
        return;
    }
    Point& P = point(s.word("target"));
    Frame& N = frame(s.word("in"));
    bool acc = k == "acceleration";
    if (s.has_word("from")) {
        Point& O = point(s.word("from"));
        Frame& B = frame(s.word("on"));
        const std::string& how = s.word("how").text;
        guard(s.word("from").location, [&] {
            if (acc) P.set_acc_two_point(N, O, B);
            else if (how == "fixed") P.set_vel_two_point(N, O, B);
            else P.set_vel_one_point(N, O, B);
        });
        return;
    }
    Vector v = vector(*s.exprs.at("value"), acc ? L / pow(T, 2) : L / T,
                      acc ? "an acceleration" : "a velocity");
    guard(s.word("in").location, [&] { acc ? P.set_acc(N, v) : P.set_vel(N, v); });
}

void Interpreter::Impl::set_mass_or_inertia(const Statement& s) {
    if (s.keyword == "mass") {
        Body& B = body(s.word("target"));
        ex m = scalar(*s.exprs.at("value"), Dimension::mass(), "the mass of " + s.word("target").text);
        guard(s.word("target").location, [&] { B.set_mass(m); });
        return;
    }
    RigidBody& B = rigid_body(s.word("target"));
    const auto& list = s.expr_lists.at("moments");
    if (list.size() != 3 && list.size() != 6)
        throw ScriptError(list.size() > 6 ? list[6]->location : list.back()->location,
                          "inertia takes 3 moments (Ixx, Iyy, Izz) or 6 (and Ixy, Iyz, Izx), not " +
                              std::to_string(list.size()),
                          "write: inertia " + s.word("target").text + " = Ixx, Iyy, Izz");
    std::vector<ex> I;
    for (const ExprPtr& e : list) I.push_back(scalar(*e, Dimension{{2, 1, 0}, true}, "a moment of inertia"));
    while (I.size() < 6) I.push_back(0);
    const Point& about = s.has_word("about") ? point(s.word("about")) : B.cm();
    Location where = s.word("target").location;
    if (s.has_word("in")) {
        Frame& F = frame(s.word("in"));
        guard(where, [&] { B.set_inertia(about, inertia_dyadic(F, I[0], I[1], I[2], I[3], I[4], I[5])); });
    } else {
        guard(where, [&] { B.set_inertia(about, I[0], I[1], I[2], I[3], I[4], I[5]); });
    }
}

void Interpreter::Impl::add_load(const Statement& s) {
    System& m = model(s.location);
    const std::string& k = s.keyword;
    const Dimension L = Dimension::length(), M = Dimension::mass(), T = Dimension::time();
    if (k == "gravity") {
        Vector g = vector(*s.exprs.at("value"), L / pow(T, 2), "gravity (an acceleration)");
        guard(s.location, [&] { m.set_gravity(g); });
        return;
    }
    const Word& label = s.word("label");
    if (k == "force") {
        Point& P = point(s.word("on"));
        Vector F = vector(*s.exprs.at("value"), Dimension::force(), "the force " + label.text);
        if (s.has_word("from")) {
            Point& Q = point(s.word("from"));
            guard(label.location, [&] { m.add_force_pair(P, Q, F, label.text); });
        } else {
            guard(label.location, [&] { m.add_force(P, F, label.text); });
        }
    } else if (k == "torque") {
        Body& B = body(s.word("on"));
        Vector T_ = vector(*s.exprs.at("value"), Dimension::torque(), "the torque " + label.text);
        if (s.has_word("from")) {
            Frame& A = frame(s.word("from"));
            guard(label.location, [&] { m.add_torque_pair(B, A, T_, label.text); });
        } else {
            guard(label.location, [&] { m.add_torque(B, T_, label.text); });
        }
    } else if (k == "spring" || k == "damper" || k == "attraction") {
        Point& P = point(s.word("P"));
        Point& Q = point(s.word("Q"));
        if (k == "spring") {
            ex kk = scalar(*s.exprs.at("stiffness"), M / pow(T, 2), "a stiffness");
            ex L0 = scalar(*s.exprs.at("length"), L, "a natural length");
            guard(label.location, [&] { m.add_spring(P, Q, kk, L0, label.text); });
        } else if (k == "damper") {
            ex c = scalar(*s.exprs.at("coefficient"), M / T, "a damping coefficient");
            guard(label.location, [&] { m.add_damper(P, Q, c, label.text); });
        } else {
            ex G = scalar(*s.exprs.at("constant"), pow(L, 3) / M / pow(T, 2), "a gravitational constant");
            guard(label.location, [&] { m.add_inverse_square_gravity(P, Q, G, label.text); });
        }
    } else if (k == "drag") {
        Point& P = point(s.word("on"));
        bool linear = s.word("law").text == "linear";
        ex c = scalar(*s.exprs.at("coefficient"), linear ? M / T : M / L, "a drag coefficient");
        guard(label.location, [&] { m.add_drag(P, c, linear ? DragLaw::linear : DragLaw::quadratic, label.text); });
    } else if (k == "friction") {
        Point& P = point(s.word("on"));
        Point& Q = point(s.word("from"));
        ex mu = scalar(*s.exprs.at("coefficient"), Dimension::none(), "a friction coefficient");
        ex Fn = scalar(*s.exprs.at("normal"), Dimension::force(), "a normal force");
        Vector u = vector(*s.exprs.at("along"), Dimension::none(), "a direction");
        guard(label.location, [&] { m.add_coulomb_friction(P, Q, mu, Fn, u, label.text); });
    }
}

void Interpreter::Impl::add_constraint(const Statement& s) {
    System& m = model(s.location);
    const Word& n = s.word("name");
    bool motion = s.word("kind").text == "motion";
    const Expr& e = *s.exprs.at("value");
    Value v = eval(e);
    std::vector<std::string> made;
    if (v.kind == Value::Kind::vector) {
        if (!s.has_word("in"))
            throw ScriptError(e.location, "a vector constraint needs the frame of its measures",
                              "add 'in N' after the vector");
        Frame& F = frame(s.word("in"));
        auto cs = guard(n.location, [&] {
            return motion ? m.add_motion_constraint(n.text, v.v, F)
                          : m.add_configuration_constraint(n.text, v.v, F);
        });
        for (const Constraint& c : cs) made.push_back(c.name);
    } else if (v.kind == Value::Kind::scalar) {
        if (s.has_word("in"))
            throw ScriptError(s.word("in").location, "'in' is for vector constraints; this one is a scalar",
                              "remove 'in " + s.word("in").text + "'");
        guard(n.location, [&] {
            motion ? m.add_motion_constraint(n.text, v.s) : m.add_configuration_constraint(n.text, v.s);
        });
        made.push_back(n.text);
    } else {
        throw ScriptError(e.location, "a constraint is a scalar or a vector expression", "");
    }
    std::string out;
    for (const Constraint& c : m.constraints())
        if (std::find(made.begin(), made.end(), c.name) != made.end())
            out += c.name + ": 0 = " + to_string(c.residual) + "\n";
    transcript.result(out);
}

}  // namespace alembert::lang
