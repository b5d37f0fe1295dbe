// SPDX-License-Identifier: MIT
// The interpreter: the run loop, names and objects of the script, and dispatch to the statements
// of the registry (statements.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include "alembert/lang/lexer.hpp"
#include "alembert/lang/parser.hpp"
#include "alembert/lang/statements.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

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

void Interpreter::set_digits(int digits) { impl_->transcript.set_digits(digits); }

const std::optional<Diagnostic>& Interpreter::last_error() const { return impl_->last_error; }

const System* Interpreter::system() const { return impl_->sys.get(); }

void Interpreter::set_output_dir(const std::string& dir) { impl_->output_dir = dir.empty() ? "." : dir; }

void Interpreter::set_model_only(bool model_only) { impl_->model_only = model_only; }
void Interpreter::set_trial(const std::string& motion_path) { impl_->trial = motion_path; }
void Interpreter::set_evaluation(Evaluation evaluation) { impl_->evaluation = evaluation; }
void Interpreter::set_compile_limit(std::size_t operations) { impl_->compile_limit = operations; }
void Interpreter::set_session(bool session) { impl_->session = session; }

void Interpreter::set_allow_outside_output(bool allow) { impl_->allow_outside_output = allow; }

void Interpreter::set_max_terms(std::size_t max_terms) { impl_->max_terms = max_terms; }
void Interpreter::set_print_limit(std::size_t ops) { impl_->print_limit = ops; }

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

RunStatus Interpreter::run_inverse(const std::string& motion_csv, double cutoff_hz, Evaluation evaluation,
                                  const std::string& unitless_unit) {
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
        r.unitless_unit = unitless_unit;
        r.evaluation = evaluation;
        r.dir = m.output_dir;
        r.body_mass_kg = m.script_inverse.body_mass_kg;
        r.cycle_plates = m.script_inverse.cycle_plates;
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

RunStatus Interpreter::write_report(const std::string& dir, const ReportSettings& settings) {
    Impl& m = *impl_;
    return run_command(m, m.script_file, [&] { (void)m.write_report_to(dir, {}, {1, 1}, settings); });
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
        if (q.empty()) throw ScriptError({1, 1}, "the model declares no variables to plan a road-map for",
                                         "declare coordinates with 'variable q''' and orient or locate with them");
        rows = m.guard({1, 1}, [&] { return plan_default_roadmap(sys, q); });
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
    // a unit where a name stands: a unit in parentheses, or a unit without its number
    if (find_unit(w.text))
        throw ScriptError(w.location,
                          "'" + w.text + "' is not declared; it is a unit, but a unit goes right after its number",
                          "for the unit, write the units after the number without parentheses: 1 m^3/kg/s^2, "
                          "not 1 m^3/(kg*s^2); for a name, declare " + wanted + " first");
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
    if (!u) return printed + " = " + transcript.number(si);
    return printed + " = " + transcript.number(si / u->scale) + " " + u->text;
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
    if (q.unit.empty() && carries_unit(*q.value)) {
        // units inside the expression: 2 kg * 9.81 m/s^2
        d = v.dim;
        check_dimension(d, expected, what, q.value->location);
    }
    if (!q.unit.empty()) {
        Unit u = parse_unit(q.unit);
        x *= u.scale;
        d = u.dimension;
        if (d.conflicts(expected))
            throw ScriptError(q.unit.location, what + " must be " + describe(expected) + ", but " +
                                                   u.text + " is " + describe(d),
                              unit_of_dimension_hint(expected));
    }
    if (got) *got = d;
    (void)where;
    return x;
}

void Interpreter::Impl::require_each_once(const std::vector<Word>& list, const std::string& what) {
    for (std::size_t i = 0; i < list.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (list[j].text == list[i].text)
                throw ScriptError(list[i].location, "'" + list[i].text + "' is listed twice",
                                  "list each " + what + " once");
}

exmap Interpreter::Impl::bindings(const std::vector<Binding>& list, const std::string& purpose) {
    exmap out;
    for (const Binding& b : list) {
        ex x = symbol(b.name, "a symbol to give a value " + purpose);
        if (out.count(x))
            throw ScriptError(b.name.location, "'" + b.name.text + "' is given twice", "give each value once");
        out[x] = binding_value(b, "the value of " + b.name.text);
    }
    return out;
}

double Interpreter::Impl::binding_value(const Binding& b, const std::string& what) {
    Dimension given = Dimension::open();
    double x = number_of(b.quantity, symbol_dimension(b.name.text), what, b.name.location, &given);
    // a coordinate declared without a unit that turns a frame is an angle: `q = 1 m` was read
    // as 1 rad in silence
    if (!symbol_dimension(b.name.text).known && given.known && !given.is_none()) {
        const std::string base = b.name.text.substr(0, b.name.text.find('\''));
        const int primes = static_cast<int>(b.name.text.size() - base.size());
        const Dimension angle_rate = Dimension::none() / pow(Dimension::time(), primes);
        if (sys && sys->symbols().contains(base) &&
            sys->symbols().kind(sys->symbols().symbol(base)) == SymbolKind::variable &&
            given.conflicts(angle_rate)) {
            const std::vector<std::string> kind =
                coordinate_quantities({sys->symbols().variable(base)}, b.name.location);
            if (kind.at(0) == "angle")
                throw ScriptError(b.quantity.unit.empty() ? b.quantity.value->location
                                                          : b.quantity.unit.location,
                                  "'" + base + "' turns a frame, so it is an angle, but " +
                                      what + " is " + describe(given),
                                  "give an angle (" + b.name.text + " = 1 rad, or 57.3 deg), " +
                                      "or declare its unit (variable " + base + "'' rad)");
        }
    }
    if (b.quantity.unit.empty() && !carries_unit(*b.quantity.value) && x != 0) {
        std::optional<Unit> u = display_unit(b.name.text);
        if (u && u->scale != 1)
            throw ScriptError(b.quantity.value->location,
                              "'" + b.name.text + "' is declared in " + u->text + ", so " +
                                  format_number(x) + " without a unit is ambiguous (" +
                                  format_number(x) + " " + u->text + ", or in SI units?)",
                              "write the unit: " + b.name.text + " = " + format_number(x) + " " +
                                  u->text);
    }
    return x;
}

// ---- statements --------------------------------------------------------------------------

void Interpreter::Impl::execute(const Statement& s) {
    const std::string& k = s.keyword;
    if (k == "=" || k.empty()) {
        model(s.location);
        return k.empty() ? show(s) : assign(s);
    }
    const StatementSpec* spec = find_statement(k);
    if (!spec) throw InternalError("the statement '" + k + "' is parsed but not registered");
    if (spec->needs_model) model(s.location);
    // what solve, evaluate and linearize print goes on the report's page too
    const bool result = k == "solve" || k == "evaluate" || k == "linearize";
    if (!result) {
        spec->run(*this, s);
        return;
    }
    transcript.keep_results();
    running_sweep.reset();
    try {
        spec->run(*this, s);
    } catch (...) {
        (void)transcript.take_kept();
        running_sweep.reset();
        throw;
    }
    std::optional<ReportSweep> sweep = std::move(running_sweep);
    running_sweep.reset();
    std::string text = transcript.take_kept();
    if (text.empty()) return;
    // the statement on one line: continuation lines ("\" at a line's end) joined
    std::string statement;
    for (std::size_t i = 0; i < s.source.size(); ++i) {
        if (s.source[i] == '\\' && i + 1 < s.source.size() && s.source[i + 1] == '\n') {
            while (!statement.empty() && statement.back() == ' ') statement.pop_back();
            statement += ' ';
            for (i += 2; i < s.source.size() && (s.source[i] == ' ' || s.source[i] == '\t'); ++i) {
            }
            --i;
            continue;
        }
        statement += s.source[i];
    }
    results.push_back({s.location.line, statement, std::move(text), std::move(sweep)});
}

}  // namespace alembert::lang
