// SPDX-License-Identifier: MIT
// Autolev statements to Alembert statements: the translation's outline, names and declarations.
#include "autolev_translator.hpp"

namespace alembert::lang {

bool AutolevTranslation::ok() const {
    return std::none_of(diagnostics.begin(), diagnostics.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
}

namespace autolev {

AutolevTranslation Translator::run(std::string_view source) {
    ParsedFile parsed = parse_autolev(source);
    // problems of reading come in file order together with those of translating
    std::size_t next_problem = 0;
    auto flush_problems = [&](Location upto, bool all) {
        while (next_problem < parsed.problems.size() &&
               (all || parsed.problems[next_problem].where.line < upto.line)) {
            const SyntaxProblem& p = parsed.problems[next_problem++];
            report(Severity::error, p.where, p.message, p.hint);
        }
    };
    // declarations first: Autolev may declare NEWTONIAN after the constants and variables
    for (const Statement& st : parsed.statements) {
        if (st.kind != Statement::Kind::declaration) continue;
        try {
            declare(st);
        } catch (const ScriptError& e) {
            pending_.push_back({Severity::error, file_, e.where(), e.what(), e.hint()});
        }
    }
    // MASS A = MA and INERTIA B, I1, I2, I3 declare their undeclared names as constants,
    // unless the file assigns them (MA = 2*M)
    for (const Statement& st : parsed.statements)
        if (st.kind == Statement::Kind::assignment && st.lhs.kind == Expr::Kind::name && !st.lhs.vector &&
            st.lhs.primes == 0)
            assigned_.insert(upper(st.lhs.text));
    for (const Statement& st : parsed.statements)
        if (st.kind == Statement::Kind::list && (st.keyword == "MASS" || st.keyword == "INERTIA")) {
            try {
                implicit_constants(st);
            } catch (const ScriptError& e) {
                pending_.push_back({Severity::error, file_, e.where(), e.what(), e.hint()});
            }
        }
    find_rate_speeds(parsed);
    if (newtonian_.empty()) frame_as_newtonian(parsed);
    std::vector<Diagnostic> declaration_problems = std::move(pending_);
    pending_.clear();
    std::size_t next_declaration_problem = 0;
    const std::vector<StatementNames> index = index_names(parsed);
    for (std::size_t i = 0; i < parsed.statements.size(); ++i) {
        const Statement& st = parsed.statements[i];
        flush_problems(st.where, false);
        while (next_declaration_problem < declaration_problems.size() &&
               declaration_problems[next_declaration_problem].location.line <= st.where.line)
            out_.diagnostics.push_back(declaration_problems[next_declaration_problem++]);
        try {
            translate_or_leave_out(st, index[i]);
        } catch (const ScriptError& e) {
            report(Severity::error, e.where(), e.what(), e.hint());
        }
    }
    flush_problems({}, true);
    for (const auto& [body, waiting] : inertia_waiting_) {
        const bool mass = massive_.count(body) > 0;
        const std::string b = waiting.said.substr(0, waiting.said.find('('));
        report(Severity::error, waiting.where,
               "INERTIA " + waiting.said + " gives the inertia about another point than the mass centre, and " +
                   (mass ? "the file gives no position of " + b + "'s mass centre from that point"
                         : "'" + b + "' has no MASS") +
                   ", which moving it to the mass centre needs",
               mass ? "give the position, P_..._" + b + "O> = ..., directly or through other points"
                    : "give MASS " + b + " = ...");
    }
    while (next_declaration_problem < declaration_problems.size())
        out_.diagnostics.push_back(declaration_problems[next_declaration_problem++]);
    if (newtonian_.empty() && !parsed.statements.empty())
        report(Severity::error, parsed.statements.front().where, "the model declares no NEWTONIAN frame",
               "add NEWTONIAN N (Alembert needs the Newtonian frame first)");
    assemble();
    std::stable_sort(out_.diagnostics.begin(), out_.diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.location.line != b.location.line ? a.location.line < b.location.line
                                                  : a.location.column < b.location.column;
    });
    // the lines of the file left out, in whole or in part (each warning leaves something out)
    for (const Diagnostic& d : out_.diagnostics)
        if (d.severity == Severity::warning && !model_warnings_.count(d.message) &&
            (out_.left_out_lines.empty() || out_.left_out_lines.back() != d.location.line))
            out_.left_out_lines.push_back(d.location.line);
    return std::move(out_);
}

void Translator::frame_as_newtonian(const ParsedFile& parsed) {
    // masses, loads and Kane's equations need the Newtonian frame: those files keep the error
    for (const Statement& st : parsed.statements) {
        if (st.kind == Statement::Kind::list && (st.keyword == "MASS" || st.keyword == "INERTIA")) return;
        if (st.kind == Statement::Kind::expression && st.expr.kind == Expr::Kind::call) {
            std::string f = upper(st.expr.text);
            if (f == "GRAVITY" || f == "FORCE" || f == "TORQUE" || f == "KANE") return;
        }
        if (st.kind == Statement::Kind::assignment && st.lhs.kind == Expr::Kind::name) {
            std::string k = upper(st.lhs.text);
            if (k == "ZERO" || k.rfind("FORCE_", 0) == 0 || k.rfind("TORQUE_", 0) == 0) return;
            const Entry* en = st.lhs.vector ? nullptr : find(st.lhs.text);
            if (en && en->kind == Kind::variable && (st.lhs.primes == 2 || (st.lhs.primes == 1 && rate_of_.count(en->name))))
                return;  // a differential equation: the model has a frame of its own
        }
    }
    for (std::string& l : frames_lines_) {
        if (l.rfind("frame ", 0) != 0) continue;
        const std::string rest = l.substr(6);
        const std::size_t comma = rest.find(", ");
        const std::string name = rest.substr(0, comma);
        const Entry* spelt = object_spelt(name);
        if (!spelt) return;
        Entry& e = objects_.at(spelt->key);
        e.kind = Kind::newtonian;
        newtonian_ = e.name;
        implicit_points_[e.key + "O"] = e.name + "_o";
        l = comma == std::string::npos ? "" : "frame " + rest.substr(comma + 2);
        report(Severity::note, e.where,
               "the file declares no NEWTONIAN frame and forms no equations of motion; its first frame '" + e.name +
                   "' is the script's Newtonian frame (positions, velocities and accelerations name their frames, "
                   "so they do not depend on which frame that is)");
        return;
    }
}

std::string Translator::alembert_spelling(const std::string& name, Location where) {
    if (name == "t" || name == "pi" || is_reserved(name)) {
        std::string renamed = name + "_";
        report(Severity::note, where,
               "'" + name + "' is a word of the Alembert language; it is called '" + renamed + "' in the script");
        return renamed;
    }
    return name;
}

// "a frame" -> "frame", "the Newtonian frame" -> "Newtonian frame"
static std::string noun(Kind k) {
    std::string w = kind_word(k);
    return w.substr(w.find(' ') + 1);
}

const Entry& Translator::add(const std::string& name, Kind kind, Location where) {
    std::string key = upper(name);
    std::map<std::string, Entry>& same = is_object(kind) ? objects_ : names_;
    std::map<std::string, Entry>& other = is_object(kind) ? names_ : objects_;
    auto it = same.find(key);
    if (it != same.end()) {
        const Entry& old = it->second;
        std::string both = "'" + name + "' is declared as " + kind_word(kind) + " at line " +
                           std::to_string(where.line) + ", and '" + old.name + "' as " + kind_word(old.kind) +
                           " at line " + std::to_string(old.where.line);
        if (upper(old.name) == key && old.name != name && old.name != name + "_")
            fail(where, both + ": '" + name + "' is already declared",
                 "Autolev names do not depend on case: '" + name + "' and '" + old.name +
                     "' are the same name; rename one");
        fail(where, both + ": '" + name + "' is already declared",
             "an Alembert script has one name for one thing, whatever its kind; rename one of the two "
             "in the Autolev file");
    }
    Entry e{kind, alembert_spelling(name, where), where, false, key};
    added_.emplace_back(key, is_object(kind));
    if (auto o = other.find(key); o != other.end()) {
        // a frame A beside a variable A: the later one is renamed (A_var), as the script has
        // one name for one thing
        static const std::map<Kind, std::string> suffix{
            {Kind::newtonian, "frame"}, {Kind::frame, "frame"},  {Kind::body, "body"},
            {Kind::particle, "particle"}, {Kind::point, "point"}, {Kind::constant, "const"},
            {Kind::variable, "var"},     {Kind::specified, "spec"}, {Kind::scalar, "val"},
            {Kind::vector, "vec"},       {Kind::matrix, "mat"},       {Kind::dyadic, "dyad"}};
        std::string base = name + "_" + suffix.at(kind), renamed = base;
        for (int k = 2; find(renamed) || object_spelt(renamed); ++k) renamed = base + std::to_string(k);
        e.name = renamed;
        std::string says = "'" + name + "' is declared as " + std::string(kind_word(kind)) + " at line " +
                           std::to_string(where.line) + " and as " + kind_word(o->second.kind) + " at line " +
                           std::to_string(o->second.where.line) + "; the " + noun(kind) + " is called '" + renamed +
                           "' in the script";
        report(Severity::note, where, says);
        renames_.push_back(says);
    }
    return same.emplace(key, std::move(e)).first->second;
}

void Translator::declare(const Statement& st) {
    const std::string& w = st.keyword;
    std::vector<std::string> line;
    auto each = [&](Kind kind, auto&& on_name) {
        for (const Declarator& d : st.declarators)
            for (const std::string& n : expand(d)) {
                const Entry& e = add(n, kind, d.where);
                on_name(d, e);
                line.push_back(e.name);
            }
    };
    auto no_primes = [&](const Declarator& d) {
        if (d.primes > 0)
            fail(d.where, "'" + d.name + "' is declared with primes in " + w,
                 "only VARIABLES, MOTIONVARIABLES and SPECIFIED take primes");
        // frames, bodies, particles and points take neither a value nor a sign
        if (w != "CONSTANTS" && w != "CONSTANT" && d.has_value)
            fail(d.value.where, "'" + d.name + "' is declared in " + w + " with a value",
                 "frames, bodies, particles and points have no value: declare the name alone and orient "
                 "or locate it (SIMPROT(N, A, 3, Q), P_O_P> = ...)");
        if (w != "CONSTANTS" && w != "CONSTANT" && d.sign)
            fail(d.sign_where, "'" + d.name + "' is declared in " + w + " with the sign qualifier '" +
                                   std::string(1, d.sign) + "'",
                 "sign qualifiers belong to CONSTANTS (L+ is a positive constant)");
    };
    // a sign qualifier that Alembert cannot state is said, not dropped
    auto sign_warning = [&](const Declarator& d, const char* what) {
        if (!d.sign) return;
        std::string q(1, d.sign);
        std::string meaning = d.sign == '+' ? "positive" : d.sign == '-' ? "negative" : "nonzero";
        report(Severity::warning, d.sign_where,
               "the qualifier '" + q + "' (" + meaning + ") of '" + d.name + "' is not translated: " + what,
               "'" + d.name + "' is declared without it; expressions that rely on its sign (sqrt(" + d.name +
                   "^2), abs(" + d.name + ")) keep both signs");
    };
    if (w == "IMAGINARY") {
        // the script's numbers are real: the names are left out, and so is what uses them
        for (const Declarator& d : st.declarators) {
            std::vector<std::string> keys;
            for (const std::string& n : expand(d)) keys.push_back(upper(n));
            record_left_out(st, d.where, "IMAGINARY " + d.name + " has no counterpart: the script's numbers are real",
                            "write complex quantities as their real and imaginary parts, two real names", keys, true);
        }
        return;
    }
    if (w != "NEWTONIAN" &&
        std::any_of(st.declarators.begin(), st.declarators.end(), [](const Declarator& d) { return !d.more.empty(); })) {
        // C{2,2,2}: the script's names have at most two indices; the others are declared
        Statement kept = st;
        kept.declarators.clear();
        for (const Declarator& d : st.declarators) {
            if (d.more.empty()) {
                kept.declarators.push_back(d);
                continue;
            }
            std::vector<std::string> names = expand(d), keys;
            for (const auto& [first, last] : d.more) {
                std::vector<std::string> longer;
                for (const std::string& n : names)
                    for (int k = first; k <= last; ++k) longer.push_back(n + std::to_string(k));
                names = std::move(longer);
            }
            for (const std::string& n : names) keys.push_back(upper(n));
            record_left_out(st, d.where,
                            "'" + d.name + "{...}' has " + std::to_string(2 + d.more.size()) +
                                " indices, and the script's indexed names have at most two (" + names.front() +
                                ", ..., " + names.back() + " are not declared)",
                            "declare them as names of two indices or one by one", keys, true);
        }
        if (kept.declarators.empty()) return;
        return declare(kept);
    }
    bool takes_primes = w == "VARIABLES" || w == "VARIABLE" || w == "MOTIONVARIABLES" || w == "MOTIONVARIABLE" ||
                        w == "SPECIFIED" || w == "SPECIFIEDS";
    if (st.keyword_primes > 0 && !takes_primes)
        fail(st.where, w + " is written with primes",
             "only VARIABLES, MOTIONVARIABLES and SPECIFIED take primes (MOTIONVARIABLES' Q{2}')");
    if (w == "NEWTONIAN") {
        if (st.declarators.size() != 1 || st.declarators[0].last >= st.declarators[0].first)
            fail(st.where, "NEWTONIAN declares one frame", "write NEWTONIAN N");
        if (!newtonian_.empty())
            fail(st.where, "a second NEWTONIAN frame", "a model has one Newtonian frame; declare the others with FRAMES");
        const Declarator& d = st.declarators[0];
        no_primes(d);
        const Entry& e = add(d.name, Kind::newtonian, d.where);
        newtonian_ = e.name;
        implicit_points_[e.key + "O"] = e.name + "_o";
        return;
    }
    if (w == "FRAMES" || w == "FRAME") {
        each(Kind::frame, [&](const Declarator& d, const Entry&) { no_primes(d); });
        frames_lines_.push_back("frame " + join(line));
        return;
    }
    if (w == "BODIES" || w == "BODY") {
        each(Kind::body, [&](const Declarator& d, const Entry& e) {
            no_primes(d);
            implicit_points_[e.key + "O"] = e.name + "cm";
            // Alembert's own names for the body's points are accepted too
            implicit_points_[e.key + "CM"] = e.name + "cm";
            implicit_points_[e.key + "_O"] = e.name + "_o";
        });
        frames_lines_.push_back("body " + join(line));
        return;
    }
    if (w == "PARTICLES" || w == "PARTICLE") {
        each(Kind::particle, [&](const Declarator& d, const Entry&) { no_primes(d); });
        frames_lines_.push_back("particle " + join(line));
        return;
    }
    if (w == "POINTS" || w == "POINT") {
        each(Kind::point, [&](const Declarator& d, const Entry&) { no_primes(d); });
        // written at the end, when V2PTS has told which bodies they are fixed on
        frames_lines_.push_back("\x01" + join(line, "\x01"));
        return;
    }
    if (w == "CONSTANTS" || w == "CONSTANT") {
        // the group is kept even if a later name fails, so the index stays valid
        constants_.emplace_back();
        const std::size_t g = constants_.size() - 1;
        for (const Declarator& d : st.declarators) {
            no_primes(d);
            if (d.sign != '+') sign_warning(d, "Alembert's constants are real or positive ('positive L')");
            for (const std::string& n : expand(d)) {
                ConstantDecl c{"", "", "", d.sign == '+'};
                if (d.has_value) c.value = number_text(d.value, "the value of constant '" + d.name + "'");
                if (d.has_value && !d.unit.empty()) c.unit = " " + unit(d.unit, d.unit_where);
                c.name = add(n, Kind::constant, d.where).name;
                constant_index_[upper(n)] = {g, constants_[g].size()};
                constants_[g].push_back(std::move(c));
            }
        }
        return;
    }
    bool is_variables = w == "VARIABLES" || w == "VARIABLE" || w == "MOTIONVARIABLES" || w == "MOTIONVARIABLE";
    if (is_variables || w == "SPECIFIED" || w == "SPECIFIEDS") {
        for (const Declarator& d : st.declarators) {
            sign_warning(d, "Alembert's variables and specified quantities are real");
            if (d.has_value && !d.unit.empty())
                fail(d.unit_where, "a unit after the definition of '" + d.name + "' is not translated",
                     "Autolev values have no units; drop '" + d.unit + "'");
            for (const std::string& n : expand(d)) {
                if (d.has_value) {
                    // a definition: the name stands for the expression (Autolev does the same)
                    const Entry& e = add(n, Kind::scalar, d.where);
                    definitions_[{st.where.line, st.where.column}].push_back({e.name, d.value});
                    continue;
                }
                const Entry& e = add(n, is_variables ? Kind::variable : Kind::specified, d.where);
                int primes = std::max(d.primes, st.keyword_primes);
                if (is_variables) {
                    variables_.push_back(e.name);
                    primes_[e.name] = primes;
                } else {
                    specified_.push_back(e.name + std::string(static_cast<std::size_t>(primes), '\''));
                }
            }
        }
        return;
    }
    fail(st.where, "'" + w + "' is not a declaration the translator knows", "docs/autolev.md lists the declarations");
}

void Translator::implicit_constants(const Statement& st) {
    std::vector<const Expr*> values;
    for (std::size_t i = 0; i < st.items.size(); ++i) {
        const Item& it = st.items[i];
        if (st.keyword == "MASS" && it.has_value) values.push_back(&it.value);
        if (st.keyword == "INERTIA" && i > 0 && !it.has_value) values.push_back(&it.lhs);
    }
    for (const Expr* v : values) {
        if (v->kind != Expr::Kind::name || v->vector || v->primes || find(v->text)) continue;
        std::string key = upper(v->text);
        if (assigned_.count(key)) continue;  // MA = 2*M: a scalar of the file
        if (key == "T" || key == "PI") continue;
        if (!implicit_group_) {
            constants_.emplace_back();
            implicit_group_ = constants_.size() - 1;
        }
        const Entry& e = add(v->text, Kind::constant, v->where);
        constant_index_[key] = {*implicit_group_, constants_[*implicit_group_].size()};
        constants_[*implicit_group_].push_back({e.name, "", "", false});
        report(Severity::note, v->where,
               "'" + v->text + "' is not declared; " + st.keyword + " declares it as a constant, as in Autolev");
    }
}

void Translator::find_rate_speeds(const ParsedFile& parsed) {
    std::map<std::string, std::string> rate_of;  // speed -> coordinate
    std::set<std::string> coordinates;
    std::vector<std::string> derivative_equations;  // X of X' = f, f not a variable
    auto variable = [this](const Expr& e, int primes) -> const Entry* {
        if (e.kind != Expr::Kind::name || e.vector || e.primes != primes) return nullptr;
        const Entry* en = find(e.text);
        return en && en->kind == Kind::variable ? en : nullptr;
    };
    for (const Statement& st : parsed.statements) {
        if (st.kind == Statement::Kind::expression && st.expr.kind == Expr::Kind::call &&
            upper(st.expr.text) == "CONSTRAIN")
            return;
        if (st.kind != Statement::Kind::assignment) continue;
        if (st.lhs.kind == Expr::Kind::index) {
            std::string a = upper(st.lhs.text);
            if (a == "DEPENDENT" || a == "AUXILIARY") return;
            continue;
        }
        const Entry *q = nullptr, *u = nullptr;
        if (variable(st.lhs, 1)) {  // Q' = U
            q = variable(st.lhs, 1);
            u = variable(st.rhs, 0);
            if (!u) {  // a kinematical equation of another form, or U' = f for a speed U (below)
                derivative_equations.push_back(q->name);
                continue;
            }
        } else if (variable(st.lhs, 0) && variable(st.rhs, 1)) {  // U = Q'
            u = variable(st.lhs, 0);
            q = variable(st.rhs, 1);
        } else {
            continue;
        }
        if (q == u || rate_of.count(u->name) || coordinates.count(q->name)) return;
        rate_of[u->name] = q->name;
        coordinates.insert(q->name);
    }
    for (const auto& [u, q] : rate_of)
        if (coordinates.count(u) || rate_of.count(q)) return;  // chains such as Q' = U, U' = W
    // U' = f is a differential equation for Q'' when Q' = U; for anything else, Q' = f is a
    // kinematical equation of another form, and the speeds stay speeds
    for (const std::string& x : derivative_equations)
        if (!rate_of.count(x)) return;
    rate_of_ = std::move(rate_of);
    aliased_coordinates_ = std::move(coordinates);
}

}  // namespace autolev

AutolevTranslation translate_autolev(std::string_view source, const std::string& file) {
    return autolev::Translator(file).run(source);
}

}  // namespace alembert::lang
