// SPDX-License-Identifier: MIT
// Assignments, printed values, and the statements of road-maps, Kane's and Lagrange's methods,
// solving and evaluating: their meaning, then their grammar and table (equation_statements()).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "alembert/cleanup.hpp"
#include "alembert/lang/parser.hpp"
#include "alembert/sim/block_solve.hpp"
#include "alembert/sym/cse.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

Value array_value(std::vector<ex> a) {
    Value v;
    v.kind = Kind::array;
    v.a = std::move(a);
    return v;
}

// "z3 = ..." for the intermediates `shown` names, then "E[i]: 0 = ..." for each equation
std::string format_equation_lines(const System* sys, const std::string& name, const std::vector<ex>& shown) {
    std::string out = sys ? format_intermediates(sys->symbols(), shown) : std::string();
    for (std::size_t i = 0; i < shown.size(); ++i)
        out += name + "[" + std::to_string(i + 1) + "]: 0 = " + to_string(shown[i]) + "\n";
    return out;
}

// the measures of a value, for the intermediates its printed form names
std::vector<ex> measures_of(const Value& v) {
    std::vector<ex> out;
    if (v.kind == Kind::scalar) out.push_back(v.s);
    else if (v.kind == Kind::array) out = v.a;
    else if (v.kind == Kind::vector) v.v.map([&](const ex& x) { out.push_back(x); return x; });
    else if (v.kind == Kind::matrix) out.assign(v.m.m.begin(), v.m.m.end());
    else if (v.kind == Kind::dyadic)
        for (const auto& part : v.d.components()) out.insert(out.end(), std::get<2>(part).m.begin(), std::get<2>(part).m.end());
    return out;
}

}  // namespace

namespace {

std::string with_separators(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

// "q1'', q2'', ..., q20''": a long list by its ends
std::string short_list(const std::vector<ex>& xs) {
    std::string out;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        if (xs.size() > 6 && i == 3) {
            out += ", ...";
            i = xs.size() - 2;
            continue;
        }
        out += (i ? ", " : "") + to_string(xs[i]);
    }
    return out;
}

}  // namespace

std::string Interpreter::Impl::print_large(const std::string& name, const std::vector<std::string>& labels,
                                           const std::vector<ex>& eqs, const std::vector<ex>& unknowns) {
    if (!sys) return {};
    const SymbolTable& table = sys->symbols();
    // measured over the DAG (count_ops memoizes shared nodes), never by printing
    const std::vector<ex> used = calc_reached_intermediates(table, eqs);
    std::vector<ex> all;
    for (const ex& z : used) all.push_back(table.definition(z));
    all.insert(all.end(), eqs.begin(), eqs.end());
    const std::size_t ops = count_ops(all);  // count_ops_with_intermediates
    if (ops <= print_limit) return {};
    constexpr std::size_t kWidth = 100;
    AbbreviatedText a = abbreviate(all, kWidth, "z", table.intermediates().size() + 1);
    std::string text = "% " + name + ": " + std::to_string(eqs.size()) + " equations" +
                       (unknowns.empty() ? "" : " in " + short_list(unknowns)) + "\n";
    std::size_t next = 0, lines = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (; next < a.defined_before[i]; ++next, ++lines) text += a.definitions[next] + "\n";
        text += (i < used.size() ? to_string(used[i]) + " = " : labels[i - used.size()]) + a.results[i] + "\n";
        ++lines;
    }
    const std::string file = name + ".txt";
    std::error_code ec;
    std::filesystem::create_directories(output_dir, ec);  // a failure is reported by the write
    write_file_atomically(std::filesystem::path(output_dir) / file, text, "'" + name + "'");
    return name + ": " + std::to_string(eqs.size()) + " equations" +
           (unknowns.empty() ? "" : " in " + short_list(unknowns)) + ", " + with_separators(ops) +
           " operations: too long to print here; written to " + file + " as " + with_separators(lines) +
           " lines of at most about " + std::to_string(kWidth) + " characters, " +
           with_separators(used.size() + a.definitions.size()) +
           " of them intermediates (print them here with --print-limit " + std::to_string(ops) + ")\n";
}

// Equations print as a person reads them: short intermediates written out, the result
// simplified and collected in the symbols it is solved for (calc_readable), and every
// intermediate still named defined first (format_intermediates). Past print_limit they go to
// a file, abbreviated (print_large).
void Interpreter::Impl::print_equations(const std::string& name, const std::vector<ex>& eqs,
                                        const std::vector<ex>& unknowns) {
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < eqs.size(); ++i) labels.push_back(name + "[" + std::to_string(i + 1) + "]: 0 = ");
    std::string large = print_large(name, labels, eqs, unknowns);
    if (!large.empty()) return transcript.result(large);
    std::vector<ex> shown = eqs;
    if (sys)
        for (ex& e : shown) e = calc_readable(sys->symbols(), e);
    transcript.result(format_equation_lines(sys.get(), name, shown));
}

// the definitions of the intermediates `v` names, before it is printed
std::string Interpreter::Impl::definitions_for(const Value& v) const {
    return sys ? format_intermediates(sys->symbols(), measures_of(v)) : std::string();
}

void Interpreter::Impl::assign(const Statement& s) {
    const Word& target = s.word("target");
    bool want_vector = s.flag("vector"), want_dyadic = s.flag("dyadic");
    std::string key = target.text + (want_vector ? ">" : want_dyadic ? ">>" : "");
    if (!want_vector && !want_dyadic) {
        if (is_reserved(target.text))
            throw ScriptError(target.location, "'" + target.text + "' is a word of the language and cannot be assigned",
                              "choose another name");
        auto it = names.find(target.text);
        if (it != names.end() && it->second.kind != NameKind::value)
            throw ScriptError(target.location, "'" + target.text + "' is already declared (line " +
                                                   std::to_string(it->second.declared.line) +
                                                   ") and cannot be assigned",
                              "assign the value to a new name");
        if (target.text.find('\'') != std::string::npos)
            throw ScriptError(target.location, "'" + target.text + "': only declared variables have primes",
                              "name the value without primes");
    }
    Value v = eval(*s.exprs.at("value"));
    if (want_vector && v.kind == Kind::scalar && v.s.is_zero()) v.kind = Kind::vector, v.v = Vector();
    if (want_dyadic && v.kind == Kind::scalar && v.s.is_zero()) v.kind = Kind::dyadic, v.d = Dyadic();
    if (want_vector && v.kind != Kind::vector)
        throw ScriptError(s.exprs.at("value")->location,
                          "'" + target.text + ">' names a vector, but this is not a vector",
                          v.kind == Kind::dyadic ? "name a dyadic with '>>': " + target.text + ">> = ..."
                                                 : "drop the '>' to assign a scalar, or multiply by a unit vector");
    if (want_dyadic && v.kind != Kind::dyadic)
        throw ScriptError(s.exprs.at("value")->location,
                          "'" + target.text + ">>' names a dyadic, but this is " +
                              (v.kind == Kind::vector ? "a vector" : v.kind == Kind::scalar ? "a scalar" : "not a dyadic"),
                          "form a dyadic with outer(a>, b>), inertia(B) or unitdyadic(N), or drop the '>>'");
    if (!want_vector && !want_dyadic && v.kind == Kind::vector)
        throw ScriptError(target.location, "a vector must be named with a trailing '>': " + target.text + ">",
                          "write " + target.text + "> = ...");
    if (!want_vector && !want_dyadic && v.kind == Kind::dyadic)
        throw ScriptError(target.location, "a dyadic must be named with a trailing '>>': " + target.text + ">>",
                          "write " + target.text + ">> = ...");
    if (!want_vector && !want_dyadic) names[target.text] = {NameKind::value, target.location};
    values[key] = v;
    if (v.kind == Kind::array) print_equations(target.text, v.a);
    else transcript.result(definitions_for(v) + key + " = " + print(v));
}

void Interpreter::Impl::show(const Statement& s) {
    const Expr& e = *s.exprs.at("value");
    Value v = eval(e);
    std::string name = monogram(e);
    if (!name.empty()) {
        // derived quantities print simplified under their monogram name, and keep that name
        v = guard(e.location, [&] {
            if (v.kind == Kind::scalar) v.s = alembert::simplify(v.s);
            else if (v.kind == Kind::vector) v.v = v.v.simplify();
            else if (v.kind == Kind::dyadic) v.d = v.d.map([](const ex& x) { return alembert::simplify(x); });
            else if (v.kind == Kind::matrix) {
                for (ex& x : v.a) x = alembert::simplify(x);
                v = matrix_value(v.rows, v.cols, v.a, v.dim);
            }
            return v;
        });
        if (v.kind != Kind::matrix) {
            values[name] = v;
            if (v.kind == Kind::scalar) names[name] = {NameKind::value, e.location};
        }
        transcript.result(definitions_for(v) + name + " = " + print(v));
        return;
    }
    if (e.kind == Expr::Kind::name && v.kind == Kind::array) return print_equations(e.text, v.a);
    std::string label;
    if (e.kind == Expr::Kind::name) label = e.text + " = ";
    else if (e.kind == Expr::Kind::vector_name) label = e.text + "> = ";
    else if (e.kind == Expr::Kind::dyadic_name) label = e.text + ">> = ";
    else if (e.kind == Expr::Kind::index)
        label = e.text + "[" + to_string(eval(*e.args[0]).s) +
                (e.args.size() > 1 ? ", " + to_string(eval(*e.args[1]).s) : std::string()) + "] = ";
    else label = "= ";
    transcript.result(definitions_for(v) + label + print(v));
}

// a road-map's table with short intermediates of its equations written out and the others
// defined before it; past print_limit, the table and a summary of the equations, which go to
// a file (print_large)
std::string Interpreter::Impl::format_readable_roadmap(const std::string& name, const System& m,
                                                       std::vector<RoadmapRow> rows) {
    std::vector<std::string> labels;
    std::vector<ex> eqs, unknowns;
    for (const RoadmapRow& r : rows) {
        labels.push_back("E_" + to_string(r.variable) + ": 0 = ");
        eqs.push_back(r.equation);
        unknowns.push_back(r.variable);
    }
    std::string large = print_large(name, labels, eqs, unknowns);
    if (!large.empty()) return format_roadmap_table(m, rows, false) + "\n" + large;
    std::vector<ex> shown;
    for (RoadmapRow& r : rows) {
        r.equation = calc_inlined_intermediates(m.symbols(), r.equation);
        shown.push_back(r.equation);
    }
    return format_intermediates(m.symbols(), shown) + format_roadmap_table(m, rows);
}

void Interpreter::Impl::roadmap(const Statement& s) {
    System& m = model(s.location);
    const Word& n = s.word("name");
    StepIndicator busy("roadmap " + n.text + ": planning, forming and printing");
    if (!s.lists.count("unknowns")) {
        auto it = roadmaps.find(n.text);
        if (it == roadmaps.end() || it->second.rows.empty())
            throw ScriptError(n.location, "there is no road-map '" + n.text + "'",
                              "plan one with 'roadmap " + n.text + " for x, y' or add rows with 'row " +
                                  n.text + " for x ...'");
        last_roadmap = n.text;
        transcript.result("MG road-map " + n.text + "\n" + format_readable_roadmap(n.text, m, it->second.rows));
        return;
    }
    if (names.count(n.text) && !roadmaps.count(n.text)) declare_name(n, NameKind::value);
    require_each_once(s.lists.at("unknowns"), "unknown");
    std::vector<ex> unknowns;
    for (const Word& w : s.lists.at("unknowns")) unknowns.push_back(symbol(w, "an unknown, coordinate or acceleration"));
    std::vector<TimeVariable> q = default_coordinates();
    Analysis analysis = s.flag("statics") ? Analysis::statics : Analysis::dynamics;
    // a speed no row holds is refused where the script names it
    std::vector<RoadmapRow> rows = guard(n.location, [&] {
        try {
            return plan_roadmap(m, q, unknowns, analysis);
        } catch (const ModelError& e) {
            const std::string what = e.what();
            for (std::size_t k = 0; k < unknowns.size(); ++k)
                if (what.find("holds the speed '" + to_string(unknowns[k]) + "'") != std::string::npos)
                    throw ScriptError(s.lists.at("unknowns")[k].location, in_script_words(what),
                                      "list the accelerations or loads the rows hold (roadmap " + n.text + " for " +
                                          to_string(unknowns[k]) + "' ...), or write a row yourself");
            throw;
        }
    });
    // a row is solved for its unknown: one that does not hold it (0 = 0 for a speed) would
    // leave the unknown at whatever a solve starts from
    for (const RoadmapRow& r : rows)
        if (!m.symbols().depends_on(r.equation, r.variable)) {
            const auto w = std::find_if(s.lists.at("unknowns").begin(), s.lists.at("unknowns").end(),
                                        [&](const Word& u) { return symbol(u, "").is_equal(r.variable); });
            const std::string x = to_string(r.variable);
            throw ScriptError(w != s.lists.at("unknowns").end() ? w->location : n.location,
                              "the road-map has no row that holds " + x + ": the row planned for it reads 0 = " +
                                  to_string(calc_readable(m.symbols(), r.equation)) + ", without " + x,
                              "road-maps solve for accelerations (q''), coordinates (statics) and load "
                              "measures; for another unknown write a row that holds it yourself (row " +
                                  n.text + " for " + x + " rotate S about O along u>), then solve it");
        }
    names[n.text] = {NameKind::value, n.location};
    roadmaps[n.text].rows = rows;
    values[n.text] = array_value(residuals_of(rows));
    last_roadmap = n.text;
    transcript.result("MG road-map " + n.text + " (" + (analysis == Analysis::statics ? "statics" : "dynamics") +
                      ")\n" + guard(n.location, [&] { return format_readable_roadmap(n.text, m, rows); }));
}

void Interpreter::Impl::row(const Statement& s) {
    System& m = model(s.location);
    const Word& n = s.word("name");
    auto it = names.find(n.text);
    if (it != names.end() && !roadmaps.count(n.text))
        throw ScriptError(n.location, "'" + n.text + "' is already used and is not a road-map",
                          "choose another name for the road-map");
    RoadmapRow r;
    r.variable = symbol(s.word("variable"), "an unknown, coordinate or acceleration");
    r.analysis = s.flag("statics") ? Analysis::statics : Analysis::dynamics;
    std::vector<ex> unknowns = m.symbols().symbols(SymbolKind::unknown);
    if (std::find(unknowns.begin(), unknowns.end(), r.variable) == unknowns.end())
        unknowns.push_back(r.variable);
    const std::string& motion = s.word("motion").text;
    if (motion == "constraint") {
        r.constraint = s.word("constraint").text;
        guard(s.word("constraint").location, [&] { form_constraint_row(m, r, unknowns); });
    } else {
        r.motion = motion == "rotate" ? Motion::rotate : Motion::translate;
        r.system = body_set(s.word("system"));
        if (r.motion == Motion::rotate) r.about = &point(s.word("about"));
        r.direction = vector(*s.exprs.at("direction"), Dimension::none(), "a direction");
        guard(s.word("motion").location, [&] { form_roadmap_row(m, r, unknowns); });
    }
    names[n.text] = {NameKind::value, n.location};
    ScriptRoadmap& rm = roadmaps[n.text];
    rm.rows.push_back(r);
    values[n.text] = array_value(residuals_of(rm.rows));
    last_roadmap = n.text;
    ex shown = calc_readable(m.symbols(), r.equation);
    transcript.result(format_intermediates(m.symbols(), {shown}) + n.text + "[" + std::to_string(rm.rows.size()) +
                      "] for " + to_string(r.variable) + ": 0 = " + to_string(shown));
}

void Interpreter::Impl::methods(const Statement& s) {
    System& m = model(s.location);
    const Word& n = s.word("name");
    StepIndicator busy(s.keyword + " " + n.text + ": forming and printing");
    auto it = names.find(n.text);
    if (it != names.end() && it->second.kind != NameKind::value)
        throw ScriptError(n.location, "'" + n.text + "' is already declared and cannot name equations",
                          "choose another name");
    require_each_once(s.lists.at("coordinates"), "coordinate");
    std::vector<TimeVariable> q;
    for (const Word& w : s.lists.at("coordinates")) q.push_back(variable(w));
    std::vector<ex> eqs;
    FormedEquations formed_here{.coordinates = q};
    if (s.keyword == "lagrange") {
        eqs = guard(n.location, [&] { return form_lagrange_equations(m, q); });
    } else if (s.lists.size() == 1 && s.exprs.empty()) {
        eqs = guard(n.location, [&] { return form_kane_equations(m, q); });
    } else {
        KaneOptions o;
        o.coordinates = q;
        auto symbols_of_list = [&](const char* role) {
            std::vector<ex> out;
            if (s.lists.count(role))
                for (const Word& w : s.lists.at(role)) out.push_back(symbol(w, "a speed"));
            return out;
        };
        o.speeds = symbols_of_list("speeds");
        o.dependent_speeds = symbols_of_list("dependent");
        o.auxiliary_speeds = symbols_of_list("auxiliary");
        if (s.expr("kinematics")) o.kinematic_equations = array(*s.expr("kinematics"), "the kinematic equations");
        if (s.expr("constraints")) o.motion_constraints = array(*s.expr("constraints"), "the motion constraints");
        KaneEquations k = guard(n.location, [&] { return form_kane_equations(m, o); });
        eqs = k.residuals;
        eqs.insert(eqs.end(), k.auxiliary_equations.begin(), k.auxiliary_equations.end());
        formed_here.kane = std::move(k);
    }
    names[n.text] = {NameKind::value, n.location};
    values[n.text] = array_value(eqs);
    formed_here.residuals = eqs;
    formed[n.text] = std::move(formed_here);
    // what the equations are in: the accelerations, or the rates of the independent speeds
    std::vector<ex> accelerations;
    if (formed[n.text].kane && !formed[n.text].kane->independent_speeds.empty())
        for (const ex& u : formed[n.text].kane->independent_speeds) accelerations.push_back(m.symbols().dt(u));
    else
        for (const TimeVariable& x : q) accelerations.push_back(x.d(x.order()));
    std::erase_if(formed_sets, [&](const ReportEquationSet& e) { return e.name == n.text; });
    formed_sets.push_back({n.text, s.keyword == "lagrange" ? "Lagrange's method" : "Kane's method",
                           s.location.line, eqs, accelerations});
    print_equations(n.text, eqs, accelerations);
}

void Interpreter::Impl::remember_solved_configuration(const SymbolTable& st, const exmap& at,
                                                       const std::vector<ex>& xs,
                                                       const std::vector<double>& values, int line) {
    exmap found;
    for (const auto& [x, v] : at)
        if (is_coordinate(x, 0)) found[x] = v;
    for (std::size_t i = 0; i < xs.size() && i < values.size(); ++i)
        if (is_coordinate(xs[i], 0)) found[xs[i]] = values[i];
    if (found.empty()) return;
    // with the state's rates and specified quantities the solve took (a push's F, a speed)
    for (const auto& [x, v] : at)
        if (!found.count(x) && st.owns(x) &&
            (st.kind(x) == SymbolKind::specified ||
             (st.kind(x) == SymbolKind::variable && st.derivative_order(x) > 0)))
            found[x] = v;
    solved_configuration = std::move(found);
    solved_line = line;
    solved_after_histories = histories.size();
}

void Interpreter::Impl::solve(const Statement& s) {
    System& m = model(s.location);
    SymbolTable& table = m.symbols();
    const Word& n = s.word("name");
    auto it = values.find(n.text);
    // equations: an array, or a matrix of one column or one row (E = [e1; e2])
    const bool vector_matrix = it != values.end() && it->second.kind == Kind::matrix &&
                               (it->second.rows == 1 || it->second.cols == 1);
    if (it == values.end() || (it->second.kind != Kind::array && !vector_matrix)) {
        if (!names.count(n.text))
            throw ScriptError(n.location, "there are no equations named '" + n.text + "'",
                              "form them first with kane, lagrange or roadmap, or assign a list");
        throw ScriptError(n.location, "'" + n.text + "' is not a list of equations",
                          "assign them as a list: E = [e1, e2]");
    }
    const std::vector<ex> eqs = it->second.a;
    require_each_once(s.lists.at("unknowns"), "unknown");
    std::vector<ex> xs;
    std::vector<std::string> printed;
    for (const Word& w : s.lists.at("unknowns")) {
        ex x = symbol(w, "a symbol to solve for");
        bool appears = std::any_of(eqs.begin(), eqs.end(), [&](const ex& e) { return table.depends_on(e, x); });
        if (!appears)
            throw ScriptError(w.location, "'" + w.text + "' does not appear in the equations " + n.text,
                              "solve for symbols the equations hold (print them with: " + n.text + ")");
        xs.push_back(x);
        printed.push_back(w.text);
    }
    // names for the solutions (solve ... as x1s, x2s or as S), checked before any work
    std::vector<Word> keep = s.lists.count("as") ? s.lists.at("as") : std::vector<Word>{};
    if (!keep.empty()) {
        require_each_once(keep, "name");
        if (keep.size() != 1 && keep.size() != xs.size())
            throw ScriptError(keep.front().location,
                              std::to_string(keep.size()) + " names for " + std::to_string(xs.size()) + " unknowns",
                              "give one name per unknown, or one name for all of them (an array)");
        for (const Word& w : keep) {
            if (is_reserved(w.text))
                throw ScriptError(w.location, "'" + w.text + "' is a word of the language and cannot name a value",
                                  "choose another name");
            auto nt = names.find(w.text);
            if (nt != names.end() && nt->second.kind != NameKind::value)
                throw ScriptError(w.location, "'" + w.text + "' is already declared (line " +
                                                  std::to_string(nt->second.declared.line) + ") and cannot name a value",
                                  "choose another name");
            if (w.text.find('\'') != std::string::npos)
                throw ScriptError(w.location, "'" + w.text + "': only declared variables have primes",
                                  "name the value without primes");
        }
    }
    // keeps the solutions under the names of 'as' (numbers in SI with the unknowns' dimensions)
    auto keep_values = [&](const std::vector<ex>& solved) {
        if (keep.empty()) return;
        if (keep.size() == 1 && xs.size() > 1) {
            Value v;
            v.kind = Kind::array, v.a = solved;
            names[keep[0].text] = {NameKind::value, keep[0].location};
            values[keep[0].text] = v;
            return;
        }
        for (std::size_t i = 0; i < xs.size(); ++i) {
            Value v;
            v.kind = Kind::scalar, v.s = solved[i], v.dim = symbol_dimension(printed[i]);
            names[keep[i].text] = {NameKind::value, keep[i].location};
            values[keep[i].text] = v;
        }
    };
    bool nonlinear = s.bindings.count("guess") != 0;
    if (s.quantities.count("limit") && (s.bindings.count("at") || nonlinear))
        throw ScriptError(s.quantities.at("limit").value->location,
                          "the term limit applies to symbolic solves only, not to a solve with "
                          "'at' or 'guess'",
                          "drop 'limit ...', or drop the values to solve symbolically");
    if (!nonlinear && xs.size() != eqs.size())
        throw ScriptError(s.lists.at("unknowns").front().location,
                          std::to_string(eqs.size()) + " equations cannot be solved for " +
                              std::to_string(xs.size()) + " unknowns",
                          "list as many unknowns as " + n.text + " has equations");
    exmap at = s.bindings.count("at") ? bindings(s.bindings.at("at"), "in 'at'") : exmap{};
    for (const auto& [x, v] : at)
        if (std::find(xs.begin(), xs.end(), x) != xs.end())
            throw ScriptError(s.bindings.at("at").front().name.location,
                              "'" + table.name(x) + "' is solved for and cannot also be given a value",
                              "remove it from 'at'");
    std::string out;
    if (nonlinear) {
        exmap guess = bindings(s.bindings.at("guess"), "in 'guess'");
        for (const auto& [x, v] : guess)
            if (std::find(xs.begin(), xs.end(), x) == xs.end())
                throw ScriptError(s.bindings.at("guess").front().name.location,
                                  "'" + table.name(x) + "' is guessed but not solved for",
                                  "guess only the unknowns after 'for'");
        // an unknown the equations do not depend on at the answer is refused, not returned
        // at its guess; a road-map's rows are named as it prints them
        StaticsOptions options{.require_determined = true};
        if (auto rm = roadmaps.find(n.text); rm != roadmaps.end() && rm->second.rows.size() == eqs.size())
            for (const RoadmapRow& r : rm->second.rows)
                options.residual_names.push_back("E_" + to_string(r.variable) + " (the row of " + n.text +
                                                 " for " + to_string(r.variable) + ")");
        Equilibrium q = guard(n.location, [&] {
            try {
                return solve_equilibrium(table, eqs, xs, guess, at, options);
            } catch (const SolveError& e) {
                if (std::string(e.what()).find("the equations do not fix") == std::string::npos) throw;
                throw ScriptError(n.location, in_script_words(e.what()),
                                  "solve for the unknowns the rows were planned for (roadmap " + n.text +
                                      " for ...), where each row holds its unknown at this state");
            }
        }, "try another guess, nearer the solution you want");
        for (std::size_t i = 0; i < xs.size(); ++i) out += format_value(printed[i], q.values[i]) + "\n";
        keep_values(std::vector<ex>(q.values.begin(), q.values.end()));
        remember_solved_configuration(table, at, xs, q.values, s.location.line);
    } else {
        // with values, rows that are not linear together may still be solved one block after
        // another (a friction's |Fn| is a number once the row of Fn is solved)
        std::optional<LinearSystem> linear;
        if (s.bindings.count("at")) {
            try {
                linear = form_linear_system(eqs, xs);
            } catch (const SolveError&) {
            }
        } else {
            linear = guard(n.location, [&] { return form_linear_system(eqs, xs); });
        }
        if (s.bindings.count("at")) {
            // every other symbol of the equations needs a value: a constant's, or one after 'at'
            Location where = s.bindings.at("at").front().name.location;
            for (const ex& e : eqs)
                for (const ex& y : symbols_of(table.expand_intermediates(e))) {
                    if (!table.owns(y) || at.count(y) || std::find(xs.begin(), xs.end(), y) != xs.end())
                        continue;
                    if (table.kind(y) == SymbolKind::constant && table.value(y)) continue;
                    throw ScriptError(where, "'" + table.name(y) + "' has no value",
                                      "give it one after 'at' (" + table.name(y) + " = ...), or solve for it");
                }
            Eigen::VectorXd x = guard(
                n.location,
                [&] {
                    if (linear) return solve_numeric(table, *linear, at);
                    try {
                        return solve_numeric_in_blocks(table, eqs, xs, at);
                    } catch (const SolveError&) {
                        form_linear_system(eqs, xs);  // the whole set's own message
                        throw;
                    }
                },
                "give every symbol a value after 'at'");
            for (std::size_t i = 0; i < xs.size(); ++i)
                out += format_value(printed[i], x(static_cast<Eigen::Index>(i))) + "\n";
            std::vector<ex> numbers;
            for (std::size_t i = 0; i < xs.size(); ++i) numbers.push_back(x(static_cast<Eigen::Index>(i)));
            keep_values(numbers);
            remember_solved_configuration(table, at, {}, {}, s.location.line);
        } else {
            SymbolicSolveOptions options;
            if (s.quantities.count("limit")) {
                const Quantity& q = s.quantities.at("limit");
                double limit = number_of(q, Dimension::none(), "the term limit", q.value->location);
                if (!(limit >= 1 && limit <= 1e15) || limit != std::floor(limit))
                    throw ScriptError(q.value->location,
                                      "the term limit must be a whole number from 1 to 1e15, not " +
                                          format_number(limit),
                                      "write solve " + n.text + " for ... limit 10000000");
                options.max_terms = limit;
            }
            // a progress line on a terminal (standard error), erased when the solve ends
            const bool terminal = ::isatty(2) == 1;
            bool shown = false;
            options.progress = [&](std::size_t step, std::size_t steps) {
                if (!terminal) return;
                if (step >= steps) {
                    if (shown) std::fprintf(stderr, "\r\033[K");
                    shown = false;
                    return;
                }
                const std::string what = step == 0 ? "eliminating"
                                                   : "simplifying " + printed[step - 1];
                std::fprintf(stderr, "\r\033[Ksolving %s symbolically: %s (step %zu of %zu)",
                             n.text.c_str(), what.c_str(), step + 1, steps);
                std::fflush(stderr);
                shown = true;
            };
            std::vector<ex> x;
            try {
                x = guard(n.location, [&] { return solve_symbolic(*linear, options); });
            } catch (...) {
                if (shown) std::fprintf(stderr, "\r\033[K");
                throw;
            }
            out = format_intermediates(table, x);
            for (std::size_t i = 0; i < xs.size(); ++i) out += printed[i] + " = " + to_string(x[i]) + "\n";
            keep_values(x);
        }
    }
    transcript.result(out);
}

void Interpreter::Impl::evaluate_statement(const Statement& s) {
    System& m = model(s.location);
    const Expr& e = *s.exprs.at("value");
    Value v = eval(e);
    if (v.kind != Kind::scalar)
        throw ScriptError(e.location, "evaluate takes a scalar", "take a measure with dot(v>, Nx>)");
    exmap at = s.bindings.count("at") ? bindings(s.bindings.at("at"), "in 'at'") : exmap{};
    double x = guard(e.location, [&] { return m.symbols().evaluate(v.s, at); },
                     "give every symbol a value after 'at'");
    std::string unit = si_unit(v.dim);
    transcript.result("= " + transcript.number(x) + (unit.empty() ? "" : " " + unit));
}


// ---- grammar -----------------------------------------------------------------------------

namespace {

void parse_roadmap(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("a name for the road-map's equations");
    if (p.accept_word("for")) {
        s.lists["unknowns"] = p.name_list("an unknown");
        if (p.accept_word("statics")) s.flags["statics"] = true;
    }
}

void parse_row(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("the road-map the row belongs to");
    p.expect_word("for", "and the unknown (row E for T_A rotate S about A_o along Nz>)");
    s.words["variable"] = p.name("the unknown of the row");
    if (p.accept_word("rotate")) {
        s.words["motion"] = {"rotate", p.peek().location};
        s.words["system"] = p.name("a system or body");
        p.expect_word("about", "and the about point");
        s.words["about"] = p.name("a point");
        p.expect_word("along", "and the direction");
        s.exprs["direction"] = p.expression();
    } else if (p.accept_word("translate")) {
        s.words["motion"] = {"translate", p.peek().location};
        s.words["system"] = p.name("a system or body");
        p.expect_word("along", "and the direction");
        s.exprs["direction"] = p.expression();
    } else if (p.accept_word("constraint")) {
        s.words["motion"] = {"constraint", p.peek().location};
        s.words["constraint"] = p.name("a declared constraint");
    } else {
        p.fail_expected("'rotate', 'translate' or 'constraint'");
    }
    if (p.accept_word("statics")) s.flags["statics"] = true;
}

// kane and lagrange: a name and the coordinates; Kane's method takes options after them
void parse_method(StatementParser& p, Statement& s) {
    const std::string& k = s.keyword;
    s.words["name"] = p.name("a name for the equations");
    p.expect_word("for", "and the coordinates (" + k + " K for q1, q2)");
    s.lists["coordinates"] = p.name_list("a coordinate");
    while (k == "kane" && !p.at_end()) {
        if (p.accept_word("speeds")) s.lists["speeds"] = p.name_list("a speed");
        else if (p.accept_word("kinematics")) s.exprs["kinematics"] = p.expression();
        else if (p.accept_word("constraints")) s.exprs["constraints"] = p.expression();
        else if (p.accept_word("dependent")) s.lists["dependent"] = p.name_list("a speed");
        else if (p.accept_word("auxiliary")) s.lists["auxiliary"] = p.name_list("a speed");
        else p.fail_expected("'speeds', 'kinematics', 'constraints', 'dependent' or 'auxiliary'");
    }
}

void parse_solve(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("the equations to solve");
    p.expect_word("for", "and the unknowns (solve E for x, y)");
    s.lists["unknowns"] = p.name_list("an unknown");
    while (!p.at_end()) {
        if (p.accept_word("guess")) s.bindings["guess"] = p.bindings("an unknown");
        else if (p.accept_word("at")) s.bindings["at"] = p.bindings("a symbol");
        else if (p.accept_word("limit")) s.quantities["limit"] = p.quantity();
        else if (p.accept_word("as")) s.lists["as"] = p.name_list("a name for the solution");
        else p.fail_expected("'at', 'guess', 'limit' or 'as'");
    }
}

void parse_evaluate(StatementParser& p, Statement& s) {
    s.exprs["value"] = p.expression();
    if (p.accept_word("at")) s.bindings["at"] = p.bindings("a symbol");
}

void parse_simplify(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("the equations to simplify (simplify K)");
}

// simplify E: E's equations rewritten equal in meaning, simplified, collected in the symbols
// they are solved for and with common factors taken out; printed and kept under E
void run_simplify(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& n = s.word("name");
    auto it = m.values.find(n.text);
    if (it == m.values.end() || it->second.kind != Value::Kind::array) {
        if (!m.names.count(n.text))
            throw ScriptError(n.location, "there are no equations named '" + n.text + "'",
                              "form them first with kane, lagrange or roadmap, or assign a list");
        throw ScriptError(n.location, "'" + n.text + "' is not a list of equations",
                          "simplify takes equations formed by kane, lagrange or roadmap; for one "
                          "expression write simplify(" + n.text + ")");
    }
    std::vector<ex> eqs = it->second.a;
    m.guard(n.location, [&] {
        for (ex& e : eqs) e = calc_readable(sys.symbols(), e, true);
        return 0;
    });
    it->second.a = eqs;
    // equations of motion stay known as such (linearize takes them), now in the new form
    auto formed = m.formed.find(n.text);
    if (formed != m.formed.end() && formed->second.residuals.size() == eqs.size()) formed->second.residuals = eqs;
    m.transcript.result(format_equation_lines(&sys, n.text, eqs));
}

void parse_digits(StatementParser& p, Statement& s) { s.quantities["digits"] = p.quantity(); }

// digits N: the significant digits of the numbers printed from here on
void run_digits(Interpreter::Impl& m, const Statement& s) {
    const Quantity& q = s.quantities.at("digits");
    double n = m.number_of(q, Dimension::none(), "the number of digits", q.value->location);
    if (!(n >= 1 && n <= 17) || n != std::floor(n))
        throw ScriptError(q.value->location,
                          "digits takes a whole number from 1 to 17, not " + format_number(n),
                          "write digits 12 (17 prints every number exactly, as it reads back)");
    m.transcript.set_digits(static_cast<int>(n));
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> equation_statements() {
    using M = Interpreter::Impl;
    const std::string_view equations = "Equations: road-maps, Kane, Lagrange", solving = "Solving";
    return {
        {.keyword = "roadmap", .family = equations,
         .help = "plans MG road-map equations for unknowns, or prints a road-map's table",
         .forms = {{"`roadmap` *E* `for` *unknowns* [`statics`]",
                    "roadmap E for T_A, T_B, T_C",
                    "`plan_roadmap` (over the `coordinates`, and the `specified` quantities for the loads that drive them) + `format_roadmap_table`: prints the table and `E_<unknown>: 0 = ...`; unknowns are accelerations, coordinates (statics), load measures and speeds (a steady precession rate `psi'`, from a row that holds it)"},
                   {"`roadmap` *E*",
                    "roadmap E",
                    "`format_roadmap_table` of the rows of E"}},
         .clauses = {"for", "statics"}, .parse = parse_roadmap,
         .run = [](M& m, const Statement& s) { m.roadmap(s); }},
        {.keyword = "row", .family = equations, .help = "adds a road-map row written by hand",
         .forms = {{"`row` *E* `for` *x* `rotate` *S* `about` *O* `along` *u* [`statics`]",
                    "row E for T_A rotate S about A_o along Nz>",
                    "`form_roadmap_row` (a row written by hand; prints its equation)"},
                   {"`row` *E* `for` *x* `translate` *S* `along` *u* [`statics`]",
                    "row E for F translate S along Nx>",
                    "`form_roadmap_row`"},
                   {"`row` *E* `for` *x* `constraint` *name* [`statics`]",
                    "row E for qC'' constraint loop_y",
                    "`form_constraint_row`"}},
         .clauses = {"for", "rotate", "translate", "constraint", "about", "along", "statics"},
         .parse = parse_row, .run = [](M& m, const Statement& s) { m.row(s); }},
        {.keyword = "kane", .family = equations, .help = "forms Kane's equations of motion",
         .forms = {{"`kane` *K* `for` *coordinates*",
                    "kane K for qA, qB",
                    "`form_kane_equations(sys, q)`; prints `K[1]: 0 = ...`"},
                   {"`kane` *K* `for` *coordinates* `speeds` *u...* `kinematics` *[...]* [`constraints` *[...]* `dependent` *u...*] [`auxiliary` *u...*]",
                    "kane K for q, x speeds u1, u2 kinematics [u1 - q', u2 - x']",
                    "`form_kane_equations(sys, KaneOptions{...})`; K holds the dynamical equations, then the auxiliary ones"}},
         .clauses = {"for", "speeds", "kinematics", "constraints", "dependent", "auxiliary"},
         .parse = parse_method, .run = [](M& m, const Statement& s) { m.methods(s); }},
        {.keyword = "lagrange", .family = equations, .help = "forms Lagrange's equations of motion",
         .forms = {{"`lagrange` *L* `for` *coordinates*",
                    "lagrange Lg for qA, qB",
                    "`form_lagrange_equations`; prints `Lg[1]: 0 = ...`"}},
         .clauses = {"for"}, .parse = parse_method, .run = [](M& m, const Statement& s) { m.methods(s); }},
        {.keyword = "simplify", .family = equations,
         .help = "simplifies equations: angle sums folded, collected in the accelerations, common factors out",
         .forms = {{"`simplify` *E*",
                    "simplify K",
                    "`calc_readable(table, e, factor = true)` on each equation: `simplify`, collected in the accelerations and unknowns, terms grouped by their time-varying factors, common factors out (`factor_common`); E keeps the result, equal in meaning; prints `K[1]: 0 = ...`"}},
         .parse = parse_simplify, .run = run_simplify},
        {.keyword = "solve", .family = solving,
         .help = "solves equations symbolically, numerically, or for an equilibrium from a guess",
         .forms = {{"`solve` *E* `for` *x...*",
                    "solve K for qA'', qB''",
                    "`form_linear_system` + `solve_symbolic`; prints `qA'' = ...` (a progress line on a terminal; refused, before any work, when the expected size, Cramer's rule written out, passes the term limit, default 1000)"},
                   {"`solve` *E* `for` *x...* `limit` *n*",
                    "solve E for qA'', qB'', F_x limit 10000000",
                    "`SymbolicSolveOptions::max_terms`: the symbolic solve with the term limit raised to n"},
                   {"`solve` *E* `for` *x...* `at` *name = value, ...*",
                    "solve E for T_A, T_B, T_C at qA = 20 deg, qB = -70 deg",
                    "`form_linear_system` + `solve_numeric` (unset speeds, accelerations: error); rows not linear together are solved one block after another (`solve_numeric_in_blocks`: a road-map with a friction's |Fn| solves the row of Fn first)"},
                   {"`solve` *E* `for` *x...* `guess` *name = value, ...* [`at` ...]",
                    "solve E for q1, q2 guess q1 = 10 deg, q2 = 20 deg",
                    "`solve_equilibrium` (nonlinear; speeds and accelerations not given after `at` are 0; refused, naming the unknown and the rows, when at the answer the equations do not change with an unknown)"},
                   {"`solve` *E* `for` *x...* [...] `as` *names*",
                    "solve E for x1, x2 as x1s, x2s",
                    "each form above, its solutions also kept as values: one name per unknown (scalars, in the unknowns' dimensions; in SI after `at` or `guess`), or one name for all (an array, `S[1]` the first); a singular system is refused"}},
         .clauses = {"for", "at", "guess", "limit", "as"}, .parse = parse_solve,
         .run = [](M& m, const Statement& s) { m.solve(s); }},
        {.keyword = "digits", .family = solving,
         .help = "sets the significant digits of the numbers printed from here on (6 at the start)",
         .forms = {{"`digits` *n*",
                    "digits 12",
                    "`Transcript::set_digits` (1 to 17; `alembert run --digits N` sets the start value)"}},
         .parse = parse_digits, .run = run_digits, .needs_model = false},
        {.keyword = "evaluate", .family = solving, .help = "prints the number an expression takes at given values",
         .forms = {{"`evaluate` *expr* `at` *name = value, ...*",
                    "evaluate PE at qA = 0",
                    "`SymbolTable::evaluate`"}},
         .clauses = {"at"}, .parse = parse_evaluate,
         .run = [](M& m, const Statement& s) { m.evaluate_statement(s); }},
    };
}

}  // namespace alembert::lang
