// SPDX-License-Identifier: MIT
// The declaration statements: the Newtonian frame, frames, bodies, particles, points, symbols,
// coordinates and systems. Each statement's grammar, meaning and help, and their table.
#include <algorithm>

#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// ---- grammar -----------------------------------------------------------------------------

void parse_newtonian(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("the name of the Newtonian frame");
}

// frame, body, particle, point: a list of new names (a point may be on a body)
void parse_objects(StatementParser& p, Statement& s) {
    s.lists["names"] = p.name_list("a name for the new " + s.keyword);
    if (s.keyword == "point" && p.accept_word("on")) s.words["on"] = p.name("the body the points are on");
}

// constant, variable, specified, unknown: names with primes, values and units
void parse_symbols(StatementParser& p, Statement& s) { s.declared = p.declarations(); }

void parse_coordinates(StatementParser& p, Statement& s) { s.lists["names"] = p.name_list("a variable"); }

void parse_system(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("a name for the system");
    p.expect_punct("=", "after the system's name (system S = A, B, C)");
    s.lists["bodies"] = p.name_list("a body or particle");
}

// ---- meaning -----------------------------------------------------------------------------

void declare_symbol(Interpreter::Impl& m, const PendingSymbol& p) {
    SymbolTable& table = m.sys->symbols();
    m.guard(p.name.location, [&] {
        if (p.keyword == "constant" || p.keyword == "positive")
            table.add_constant(p.name.text, p.value, p.keyword == "positive");
        else if (p.keyword == "variable") table.add_variable(p.name.text, p.primes);
        else if (p.keyword == "specified") table.add_specified(p.name.text, p.primes);
        else table.add_unknown(p.name.text);
    });
}

void run_newtonian(Interpreter::Impl& m, const Statement& s) {
    if (m.sys)
        throw ScriptError(s.location, "the Newtonian frame is already declared (" +
                                          m.sys->newtonian().name() + ")",
                          "a model has one Newtonian frame; declare other frames with 'frame'");
    const Word& n = s.word("name");
    m.declare_name(n, NameKind::frame);
    m.sys = std::make_unique<System>(n.text);
    m.names[n.text + "_o"] = {NameKind::point, n.location};
    // the symbols declared before the model, in their order
    for (const PendingSymbol& p : m.pending_symbols) declare_symbol(m, p);
    m.pending_symbols.clear();
}

void run_objects(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const std::string& k = s.keyword;
    const Body* owner = s.has_word("on") ? &m.body(s.word("on")) : nullptr;
    for (const Word& w : s.lists.at("names")) {
        if (k == "frame") {
            m.declare_name(w, NameKind::frame);
            m.guard(w.location, [&] { sys.add_frame(w.text); });
        } else if (k == "point") {
            m.declare_name(w, NameKind::point);
            m.guard(w.location, [&] { sys.add_point(w.text, owner); });
        } else if (k == "particle") {
            m.declare_name(w, NameKind::particle);
            m.guard(w.location, [&] { sys.add_particle(w.text); });
        } else {
            // the body's frame shares its name; its origin and mass centre are points
            for (const std::string& p : {w.text + "_o", w.text + "cm"})
                if (m.names.count(p))
                    throw ScriptError(w.location, "body '" + w.text + "' needs the point name '" + p +
                                                      "', which is already " + kind_word(m.names[p].kind) +
                                                      at_line(m.names[p].declared),
                                      "choose another name for the body");
            m.declare_name(w, NameKind::body);
            m.guard(w.location, [&] { sys.add_rigid_body(w.text); });
            m.names[w.text + "_o"] = {NameKind::point, w.location};
            m.names[w.text + "cm"] = {NameKind::point, w.location};
        }
    }
}

// `constant L = 2 m` again in a session: the new value for the numbers from now on
void redefine_constant(Interpreter::Impl& m, const Declared& d, const SymbolUnits& su,
                       std::optional<double> value) {
    SymbolTable& table = m.sys->symbols();
    const ex& c = table.symbol(d.name.text);
    if (!value)
        throw ScriptError(d.name.location, "'" + d.name.text + "' is already a constant",
                          "give it a new value to change it: constant " + d.name.text + " = ...");
    const SymbolUnits& old = m.units[d.name.text];
    if (su.dim.conflicts(old.dim))
        throw ScriptError(d.quantity.value->location,
                          "'" + d.name.text + "' is " + describe(old.dim) + ", but the new value is " +
                              describe(su.dim),
                          "give the new value in a unit of the same dimension");
    if (GiNaC::is_a<GiNaC::possymbol>(c) && !(*value > 0))
        throw ScriptError(d.quantity.value->location, "'" + d.name.text + "' is declared positive",
                          "give it a value greater than 0");
    std::optional<double> before = table.value(c);
    table.set_value(c, *value);
    std::string was = before ? " (was " + m.format_value(d.name.text, *before).substr(d.name.text.size() + 3) + ")" : "";
    m.transcript.result(m.format_value(d.name.text, *value) + was +
                        "; expressions, equations and road-maps keep the symbol " + d.name.text +
                        " and stand; evaluate, solve ... at, linearize, simulate, inverse and codegen "
                        "use the new value from now on, and results printed before are not recomputed\n");
}

void run_symbols(Interpreter::Impl& m, const Statement& s) {
    const std::string& k = s.keyword;
    bool is_constant = k == "constant" || k == "positive";
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
        if (d.quantity.value && !is_constant)
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
            value = m.number_of(d.quantity, su.dim, "the value of " + d.name.text,
                                d.name.location, &got);
            // units inside the value (constant W = 2 kg * 9.81 m/s^2) give its dimension
            if (d.quantity.unit.empty() && got.known && !got.is_none()) su.dim = got;
            if (k == "positive" && !(*value > 0))
                throw ScriptError(d.quantity.value->location,
                                  "'" + d.name.text + "' is declared positive, but its value is " +
                                      format_number(*value),
                                  "give it a value greater than 0, or declare it with 'constant'");
        }
        if (m.session && is_constant && m.sys && m.sys->symbols().contains(d.name.text) &&
            m.sys->symbols().kind(m.sys->symbols().symbol(d.name.text)) == SymbolKind::constant) {
            redefine_constant(m, d, su, value);
            continue;
        }
        m.declare_name(d.name, NameKind::symbol);
        PendingSymbol p{k, d.name, d.primes, value};
        if (m.sys) declare_symbol(m, p);
        else m.pending_symbols.push_back(p);  // before newtonian: declared with the model
        for (int i = 1; i <= d.primes; ++i)
            m.names[d.name.text + std::string(static_cast<std::size_t>(i), '\'')] = {NameKind::symbol,
                                                                                     d.name.location};
        m.units[d.name.text] = su;
    }
}

void run_coordinates(Interpreter::Impl& m, const Statement& s) {
    std::vector<TimeVariable> q;
    for (const Word& w : s.lists.at("names")) q.push_back(m.variable(w));
    m.coordinates = q;
    m.coordinates_given = true;
}

void run_system(Interpreter::Impl& m, const Statement& s) {
    const Word& n = s.word("name");
    BodySet S;
    Interpreter::Impl::require_each_once(s.lists.at("bodies"), "body");
    for (const Word& w : s.lists.at("bodies")) {
        S.push_back(&m.body(w));
    }
    m.declare_name(n, NameKind::system);
    m.systems[n.text] = S;
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> declaration_statements() {
    const std::string_view family = "Declarations";
    return {
        {.keyword = "newtonian", .family = family,
         .help = "names the Newtonian (ground) frame; it comes first",
         .forms = {{"`newtonian` *N*",
                    "newtonian N",
                    "`System(\"N\")` (must come first)"}},
         .parse = parse_newtonian, .run = run_newtonian, .needs_model = false},
        {.keyword = "frame", .family = family, .help = "declares reference frames",
         .forms = {{"`frame` *names*",
                    "frame Y, L",
                    "`System::add_frame`"}},
         .parse = parse_objects, .run = run_objects},
        {.keyword = "body", .family = family,
         .help = "declares rigid bodies, each with its frame, its origin B_o and mass centre Bcm",
         .forms = {{"`body` *names*",
                    "body A, B, C",
                    "`System::add_rigid_body` (frame A, points `A_o`, `Acm`)"}},
         .parse = parse_objects, .run = run_objects},
        {.keyword = "particle", .family = family, .help = "declares particles (point masses)",
         .forms = {{"`particle` *names*",
                    "particle Q",
                    "`System::add_particle` (point Q)"}},
         .parse = parse_objects, .run = run_objects},
        {.keyword = "point", .family = family, .help = "declares points, on a body if given",
         .forms = {{"`point` *names* [`on` *body*]",
                    "point B_P on B",
                    "`System::add_point` (on a body: forces there act on it)"}},
         .clauses = {"on"}, .parse = parse_objects, .run = run_objects},
        {.keyword = "constant", .family = family,
         .help = "declares constants, with a value and a unit if given",
         .forms = {{"`constant` *name* [`=` *value*] [*unit*], ...",
                    "constant g = 9.81 m/s^2, k N/m, c",
                    "`SymbolTable::add_constant`"}},
         .parse = parse_symbols, .run = run_symbols, .needs_model = false},
        {.keyword = "positive", .family = family,
         .help = "declares constants known to be greater than 0, so sqrt(L^2) is L",
         .forms = {{"`positive` *name* [`=` *value*] [*unit*], ...",
                    "positive L = 0.5 m, m = 2 kg",
                    "`SymbolTable::add_constant(name, value, true)` (a GiNaC possymbol)"}},
         .parse = parse_symbols, .run = run_symbols, .needs_model = false},
        {.keyword = "variable", .family = family,
         .help = "declares functions of time (coordinates, speeds) and their derivatives",
         .forms = {{"`variable` *name*`''` [*unit*], ...",
                    "variable qA'', x'' m, u1'",
                    "`SymbolTable::add_variable(name, primes)`"}},
         .parse = parse_symbols, .run = run_symbols, .needs_model = false},
        {.keyword = "specified", .family = family,
         .help = "declares given functions of time and their derivatives",
         .forms = {{"`specified` *name*`''` [*unit*], ...",
                    "specified F' N",
                    "`SymbolTable::add_specified`"}},
         .parse = parse_symbols, .run = run_symbols, .needs_model = false},
        {.keyword = "unknown", .family = family,
         .help = "declares unknowns: load measures and values to solve for",
         .forms = {{"`unknown` *name* [*unit*], ...",
                    "unknown T_A N*m, F_x N",
                    "`SymbolTable::add_unknown`"}},
         .parse = parse_symbols, .run = run_symbols, .needs_model = false},
        {.keyword = "coordinates", .family = family,
         .help = "sets the coordinates road-maps plan with",
         .forms = {{"`coordinates` *variables*",
                    "coordinates qA, qB, qC",
                    "the coordinates road-maps plan with (default: every variable)"}},
         .parse = parse_coordinates, .run = run_coordinates},
        {.keyword = "system", .family = family,
         .help = "names a set of bodies (a road-map row's system, mass(S), kinetic(S), ...)",
         .forms = {{"`system` *S* `=` *bodies*",
                    "system S = A, B, C",
                    "`System::bodies({...})`, the system S of a road-map row"}},
         .parse = parse_system, .run = run_system},
    };
}

}  // namespace alembert::lang
