// SPDX-License-Identifier: MIT
// Autolev statements to Alembert statements: lists (MASS, INERTIA, INPUT, OUTPUT), commands,
// assignments, kinematics and loads.
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

void Translator::translate(const Statement& st) {
    statement_where_ = st.where;
    switch (st.kind) {
        case Statement::Kind::declaration: return definitions(st);
        case Statement::Kind::list: return list(st);
        case Statement::Kind::command: return command(st);
        case Statement::Kind::assignment: return assignment(st);
        case Statement::Kind::expression: return expression_statement(st);
    }
}

void Translator::definitions(const Statement& st) {
    auto it = definitions_.find({st.where.line, st.where.column});
    if (it == definitions_.end()) return;
    for (const Definition& d : it->second) {
        Text r = scalar(d.value);
        names_[upper(d.name)].numeric = r.numeric;
        emit(d.name + " = " + r.s);
    }
}

void Translator::list(const Statement& st) {
    const std::string& w = st.keyword;
    if (w == "MASS") {
        if (st.items.empty()) fail(st.where, "MASS names no body or particle", "write MASS A = MA, P = MP");
        // every mass first: a statement left out gives none of them
        std::vector<std::pair<std::string, std::string>> masses;
        for (const Item& it : st.items) {
            const Entry* en = it.lhs.kind == Expr::Kind::name && !it.lhs.vector ? find_object(it.lhs.text) : nullptr;
            if (!en || (en->kind != Kind::body && en->kind != Kind::particle))
                fail(it.where, "MASS takes a body or a particle before '='", "write MASS A = MA");
            if (!it.has_value) fail(it.where, "the mass of '" + it.lhs.text + "' is missing", "write MASS " + it.lhs.text + " = M");
            if (!it.unit.empty()) fail(it.where, "a unit in MASS", "give units in INPUT");
            masses.emplace_back(en->name, dimensioned(scalar(it.value), "m_" + en->name));
        }
        for (const auto& [body, m] : masses) {
            emit("mass " + body + " = " + m);
            massive_.insert(body);
            release_inertias();  // INERTIA B(P) before MASS B
        }
        return;
    }
    if (w == "INERTIA") {
        if (st.items.size() != 4 && st.items.size() != 7)
            fail(st.where, "INERTIA takes a body and 3 or 6 measures, not " + std::to_string(st.items.empty() ? 0 : st.items.size() - 1),
                 "write INERTIA B, I11, I22, I33 [, I12, I23, I31]");
        const Item& b = st.items[0];
        // INERTIA B(P), ...: the measures about point P (in B's unit vectors, as about BO)
        std::string about;
        Expr body_expr = b.lhs;
        if (b.lhs.kind == Expr::Kind::call) {
            if (b.lhs.args.size() != 1)
                fail(b.where, "INERTIA " + b.lhs.text + "(...) takes one point, about which the measures are given",
                     "write INERTIA " + b.lhs.text + "(P), I11, I22, I33");
            body_expr = Expr{};
            body_expr.kind = Expr::Kind::name;
            body_expr.text = b.lhs.text;
            body_expr.where = b.lhs.where;
            about = point_name(b.lhs.args[0]);
        }
        std::string body = body_name(body_expr);
        if (about == body + "cm") about.clear();  // INERTIA B(BO): about the mass centre
        std::vector<std::string> m;
        for (std::size_t i = 1; i < st.items.size(); ++i) {
            if (st.items[i].has_value || !st.items[i].unit.empty())
                fail(st.items[i].where, "an inertia measure must be a scalar expression");
            m.push_back(dimensioned(scalar(st.items[i].lhs), "I" + std::to_string(i) + "_" + body));
        }
        std::string line = "inertia " + body + " = " + join(m);
        if (about.empty()) return emit(line);
        // the script moves the inertia to the mass centre where it stands (I - m((r.r) U - r r),
        // r from P to the mass centre), so it needs the mass and that position: it is written
        // after MASS B and P_P_BO> (directly or through other points) if they come later
        line += " about " + about;
        if (inertia_waiting_.count(body))
            fail(b.where, "a second INERTIA " + b.lhs.text + "(...) before the first is placed (MASS " + b.lhs.text +
                              " and the position of its mass centre from the point come later)",
                 "give the inertia once");
        inertia_waiting_[body] = {line, about, b.where, b.lhs.text + "(" + b.lhs.args[0].text + ")"};
        release_inertias();
        return;
    }
    if (w == "INPUT") {
        for (const Item& it : st.items) input(it);
        return;
    }
    // OUTPUT
    std::vector<std::string> cols;
    for (const Item& it : st.items) {
        if (it.lhs.kind == Expr::Kind::name && !it.lhs.vector && upper(it.lhs.text) == "T" && !find(it.lhs.text))
            continue;  // time is always the first column
        if (it.has_value) fail(it.where, "'=' in OUTPUT", "list the quantities: OUTPUT Q1, U1");
        Text v = scalar(it.lhs);
        std::string col = v.s;
        if (it.lhs.kind != Expr::Kind::name) {
            col = "output_" + std::to_string(++outputs_) + " = " + v.s;
        } else if (const Entry* en = find(it.lhs.text); en && rate_of_.count(en->name) && it.lhs.primes == 0) {
            col = en->name + " = " + v.s;  // the column keeps the speed's name: U1 = Q1'
        }
        if (!it.unit.empty()) col += " in " + unit(it.unit, it.where);
        cols.push_back(col);
    }
    if (!cols.empty()) tail_outputs_.push_back("output " + join(cols));
}

void Translator::input(const Item& it) {
    if (it.lhs.kind != Expr::Kind::name || it.lhs.vector || !it.has_value)
        fail(it.where, "INPUT takes name = value", "write INPUT L = 0.5, Q1 = 30 DEG");
    std::string key = upper(it.lhs.text);
    std::string value = number_text(it.value, "the value of '" + it.lhs.text + "' in INPUT");
    std::string u = it.unit.empty() ? "" : " " + unit(it.unit, it.where);
    const Entry* en = find(it.lhs.text);
    if (!en) {
        if (key == "TFINAL") { tail_settings_["final time"] = "final time " + value + (u.empty() ? "" : u); return; }
        if (key == "INTEGSTP") { tail_settings_["output step"] = "output step " + value + (u.empty() ? "" : u); return; }
        if (key == "ABSERR") { abs_tol_ = value; return; }
        if (key == "RELERR") { rel_tol_ = value; return; }
        if (key == "PRINTINT") {
            not_translated(it.where, "INPUT PRINTINT", "Alembert writes a row every output step");
            return;
        }
        fail(it.where, "'" + it.lhs.text + "' in INPUT is not declared",
             "INPUT gives values of constants, initial values of variables, and TFINAL, INTEGSTP, ABSERR, RELERR");
    }
    if (en->kind == Kind::constant && it.lhs.primes == 0) {
        auto [g, i] = constant_index_.at(key);
        constants_[g][i].value = value;
        constants_[g][i].unit = u;
        return;
    }
    if (en->kind == Kind::variable) {
        std::string n = en->name + std::string(static_cast<std::size_t>(it.lhs.primes), '\'');
        if (auto r = rate_of_.find(en->name); r != rate_of_.end())  // U1 = 0 is Q1' = 0
            n = r->second + std::string(static_cast<std::size_t>(it.lhs.primes + 1), '\'');
        initial_[n] = value + u;
        initial_order_.push_back(n);
        return;
    }
    if (en->kind == Kind::specified) {
        tail_inputs_.push_back(en->name + " = " + value + u);
        return;
    }
    fail(it.where, "INPUT gives a value to '" + it.lhs.text + "', " + kind_word(en->kind),
         "INPUT gives values of constants and initial values of variables");
}

std::string Translator::unit(const std::string& words, Location where) {
    static const std::map<std::string, std::string> units{
        {"DEG", "deg"}, {"DEGREES", "deg"}, {"DEGREE", "deg"}, {"RAD", "rad"}, {"RADIANS", "rad"},
        {"REV", "rev"}, {"M", "m"}, {"METER", "m"}, {"METERS", "m"}, {"CM", "cm"}, {"MM", "mm"},
        {"KM", "km"}, {"KG", "kg"}, {"S", "s"}, {"SEC", "s"}, {"SECOND", "s"}, {"SECONDS", "s"},
        {"MS", "ms"}, {"MIN", "min"}, {"N", "N"}, {"NEWTON", "N"}, {"KN", "kN"}, {"J", "J"},
        {"W", "W"}, {"HZ", "Hz"}, {"RPM", "rpm"}};
    std::string out, word;
    auto flush = [&] {
        if (word.empty()) return;
        auto it = units.find(upper(word));
        if (it == units.end())
            fail(where, "the unit '" + word + "' is not translated",
                 "use SI units or deg, rad, rev, cm, mm, km, ms, min, kN, Hz, rpm");
        out += it->second;
        word.clear();
    };
    for (char c : words) {
        if (c == '*' || c == '/' || c == '^' || c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
            flush();
            out += c;
        } else {
            word += c;
        }
    }
    flush();
    return out;
}

void Translator::command(const Statement& st) {
    const std::string& w = st.keyword;
    if (w == "CODE") return code(st);
    std::string on = upper(st.text.substr(st.text.find_first_not_of(" \t") == std::string::npos
                                               ? st.text.size() : st.text.find_first_not_of(" \t")));
    while (!on.empty() && (on.back() == ' ' || on.back() == '\t')) on.pop_back();
    if (w == "COMPLEX") {
        if (on == "OFF") {
            report(Severity::note, st.where, "COMPLEX OFF: the script's numbers are real; nothing to translate");
            return;
        }
        leave_out(st.where, "COMPLEX " + (on.empty() ? std::string("") : on + " ") +
                                "has no counterpart: the script's numbers are real, and the statements after it are "
                                "read with real numbers",
                  "remove it; the script's constants and variables are real");
    }
    if (w == "DEGREES" || w == "DEGREE") {
        if (on == "OFF") {  // angles without a unit are radians: as the translation reads them
            degrees_ = false;
            report(Severity::note, st.where,
                   "DEGREES OFF: angles without a unit are radians, as the script reads them; nothing to translate");
            return;
        }
        if (on == "ON") {
            degrees_ = true;
            report(Severity::note, st.where,
                   "DEGREES ON (Autolev's default): an angle written with numbers alone (SIMPROT(N, A, 3, 30), "
                   "SIN(30)) is in degrees and is translated times pi/180; angles holding names are radians");
            return;
        }
        fail(st.where, on.empty() ? std::string("DEGREES without ON or OFF") : "DEGREES " + on + " is not an Autolev setting",
             "write DEGREES ON or DEGREES OFF");
    }
    static const char* const ignored[] = {"PAUSE", "SAVE", "AUTOZ", "AUTORHS", "AUTOEPS", "AUTOLEV", "OVERWRITE",
                                          "UNITSYSTEM", "UNITS", "DISPLAY", "ANIMATE", "ENCODE", "EXPLICIT",
                                          "PRINT", "RUN", "SHOW", "CLEAR", "DIGITS", "WRITE"};
    for (const char* x : ignored)
        if (w == x) {
            not_translated(st.where, w, "it changes how Autolev works or prints, not the model");
            return emit("# left out (" + file_ + ":" + std::to_string(st.where.line) + "): " + w +
                        " changes how Autolev works or prints, not the model");
        }
    if (const Entry* en = find(w); en && st.text.empty()) {  // a name alone: print it
        Expr e;
        e.kind = Expr::Kind::name;
        e.text = w;
        e.where = st.where;
        emit(expr(e).s);
        return;
    }
    fail(st.where, "'" + w + "' is not an Autolev statement the translator knows",
         "docs/autolev.md lists the statements it translates");
}

void Translator::code(const Statement& st) {
    // CODE DYNAMICS() file.c
    std::string text = st.text;
    std::string kind = upper(text.substr(0, text.find_first_of("( \t")));
    if (kind != "DYNAMICS") {
        not_translated(st.where, "CODE " + kind, "only CODE DYNAMICS() has a counterpart (codegen)");
        return emit("# left out (" + file_ + ":" + std::to_string(st.where.line) + "): CODE " + kind +
                    " has no counterpart: only CODE DYNAMICS() has one (codegen)");
    }
    std::size_t open = text.find('('), close = text.find(')');
    if (open != std::string::npos && close != std::string::npos && close > open &&
        text.find_first_not_of(" \t", open + 1) != close)
        report(Severity::warning, st.where,
               "the arguments of CODE DYNAMICS(" + text.substr(open + 1, close - open - 1) + ") are not translated",
               "Alembert's codegen writes the dynamics of every coordinate and speed; the code is generated "
               "without them");
    std::string file = close == std::string::npos ? "" : text.substr(close + 1);
    file.erase(0, file.find_first_not_of(" \t"));
    std::string lang = "c";
    std::string stem = file;
    std::size_t dot = file.rfind('.');
    if (dot != std::string::npos) {
        std::string ext = upper(file.substr(dot + 1));
        stem = file.substr(0, dot);
        if (ext == "C") lang = "c";
        else if (ext == "CPP" || ext == "CC" || ext == "CXX") lang = "cpp";
        else if (ext == "M") lang = "matlab";
        else if (ext == "PY") lang = "python";
        else
            fail(st.where, "CODE DYNAMICS() to a '." + file.substr(dot + 1) + "' file is not translated",
                 "Alembert writes C (.c), C++ (.cpp), MATLAB (.m) and Python (.py)");
    }
    std::string name;
    for (char c : stem)
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') name += c;
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) name = "dynamics";
    tail_codegen_.push_back({st.where, "codegen " + lang + " name " + name});
}

void Translator::assignment(const Statement& st) {
    const Expr& lhs = st.lhs;
    if (lhs.kind == Expr::Kind::index) return array_assignment(st);
    if (lhs.kind != Expr::Kind::name)
        fail(lhs.where, "the left side of '=' must be a name", "write NAME = ..., NAME> = ... or Q1' = ...");
    if (lhs.dyadic) return dyadic_assignment(st);
    if (lhs.vector) return vector_assignment(st);
    std::string key = upper(lhs.text);
    const Entry* en = find(lhs.text);
    if (lhs.primes > 0) {
        if (st.compound)
            fail(lhs.where, std::string("'") + st.compound + "=' on a derivative is not translated",
                 "write the kinematical equation whole: " + lhs.text + "' = ...");
        if (!en || en->kind != Kind::variable)
            fail(lhs.where, "'" + lhs.text + "' is not a variable, so '" + lhs.text + "'' cannot be assigned",
                 "declare it with VARIABLES or MOTIONVARIABLES");
        if (lhs.primes == 2 || (lhs.primes == 1 && rate_of_.count(en->name)))
            return differential_equation(st, *en);  // X'' = f, or V' = f with X' = V
        if (lhs.primes != 1)
            fail(lhs.where, "an equation for '" + lhs.text + std::string(static_cast<std::size_t>(lhs.primes), '\'') +
                                "' is not translated", "give equations for first or second derivatives: X' = V, X'' = f");
        if (aliased_coordinates_.count(en->name)) return;  // Q1' = U1: U1 is written Q1'
        Text r = scalar(st.rhs);
        for (const KinematicEquation& k : kinematics_)
            if (k.coordinate == en->name)
                fail(lhs.where, "a second kinematical equation for '" + lhs.text + "'", "give one for each coordinate");
        kinematics_.push_back({en->name, en->name + "' - " + (r.prec <= 1 ? "(" + r.s + ")" : r.s), st.where});
        return;
    }
    if (key == "ZEE_NOT" && !en)
        return not_translated(st.where, "ZEE_NOT",
                              "it tells Autolev which names to keep out of its intermediates Z1, Z2, ... so that "
                              "KANE(...) can solve for them; the script solves for load measures through its "
                              "intermediates, so the list changes nothing");
    if (key == "ZERO" && en && en->indices && is_fr_plus_frstar(st.rhs)) {
        // Kane's equations replace the file's own array ZERO[i] from here on
        names_.erase(en->key);
        en = nullptr;
    }
    if (key == "ZERO" && !en) {
        if (!is_fr_plus_frstar(st.rhs))
            fail(st.rhs.where, "ZERO is translated only as ZERO = FR() + FRSTAR()",
                 "Kane's equations are formed by ZERO = FR() + FRSTAR() and KANE()");
        need_placed_inertia(st.where, "ZERO = FR() + FRSTAR()");
        if (!kane_at_) kane_at_ = model_.size(), emit("");
        kane_where_ = st.where;
        return;
    }
    if (en) {
        if (en->kind == Kind::matrix) return matrix_assignment(st);
        if (en->kind == Kind::variable) return kinematical_assignment(st, *en);
        if (en->kind == Kind::scalar) {
            Text r = expr(st.rhs);
            if (r.matrix())
                fail(st.rhs.where, "'" + lhs.text + "' is a scalar and is assigned only a scalar", "give the matrix another name");
            if (r.vector) fail(st.rhs.where, "a vector where a scalar is expected", "take a measure: DOT(v>, N1>)");
            if (r.dyadic) not_a_dyadic(st.rhs, "a scalar");
            names_[upper(lhs.text)].numeric = r.numeric;
            emit(en->name + " = " + r.s);
            return;
        }
        if (en->kind == Kind::newtonian || en->kind == Kind::frame || en->kind == Kind::body)
            fail(lhs.where, "'" + lhs.text + "' is " + kind_word(en->kind) + " and cannot be assigned");
        fail(lhs.where, "'" + lhs.text + "' is " + kind_word(en->kind) + " and cannot be assigned",
             "INPUT gives constants their values; use another name for the expression");
    }
    // a direction cosine matrix N_A = [...]
    if (st.rhs.kind == Expr::Kind::matrix) {
        auto fr = [this](std::string_view n) { return frame_of(n); };
        auto s = split(std::string_view(lhs.text), fr, fr);
        if (!s) return matrix_assignment(st);
        parent_[s->second] = s->first;
        return emit("rotate " + s->second + " from " + s->first + " dcm " + matrix(st.rhs));
    }
    Text r = expr(st.rhs);
    if (r.matrix()) {
        const Entry& ne = add(lhs.text, Kind::matrix, lhs.where);
        Entry& stored = names_[ne.key];
        stored.rows = r.rows, stored.cols = r.cols;
        return emit(ne.name + " = " + r.s);
    }
    if (r.vector) fail(st.rhs.where, "a vector where a scalar is expected", "take a measure: DOT(v>, N1>)");
    if (r.dyadic) fail(st.rhs.where, "a dyadic assigned to a name without '>>'", "write " + lhs.text + ">> = ...");
    const Entry& ne = add(lhs.text, Kind::scalar, lhs.where);
    names_[upper(lhs.text)].numeric = r.numeric;
    emit(ne.name + " = " + r.s);
}

void Translator::kinematical_assignment(const Statement& st, const Entry& speed) {
    if (rate_of_.count(speed.name)) return;  // OMEGA = THETA': OMEGA is written THETA'
    const Expr& r = st.rhs;
    const Entry* q = r.kind == Expr::Kind::name && !r.vector && r.primes == 1 ? find(r.text) : nullptr;
    if (!q || q->kind != Kind::variable)
        fail(st.lhs.where,
             "'" + st.lhs.text + "' is a variable; it is assigned only as a coordinate's rate (" + st.lhs.text +
                 " = Q')",
             "write the kinematical equation Q' = " + st.lhs.text +
                 ", or give the expression another name (Autolev's VARIABLES Z = ... defines one)");
    for (const KinematicEquation& k : kinematics_)
        if (k.coordinate == q->name)
            fail(st.lhs.where, "a second kinematical equation for '" + r.text + "'", "give one for each coordinate");
    kinematics_.push_back({q->name, q->name + "' - " + speed.name, st.where});
}

void Translator::differential_equation(const Statement& st, const Entry& v) {
    auto r = rate_of_.find(v.name);
    const std::string q = r == rate_of_.end() ? v.name : r->second;
    for (const auto& [x, where] : odes_)
        if (x == q)
            fail(st.lhs.where, "a second equation for " + q + "'' (the first is at line " + std::to_string(where.line) + ")",
                 "give one equation for each variable");
    Text f = scalar(st.rhs);
    if (newtonian_.empty()) {  // a file of equations alone: the particles need a frame to move in
        newtonian_ = "N";
        for (int k = 2; find(newtonian_) || object_spelt(newtonian_); ++k) newtonian_ = "N" + std::to_string(k);
        report(Severity::note, st.where,
               "the model is given by its differential equations; each variable is the coordinate of a particle "
               "of unit mass in a Newtonian frame '" + newtonian_ + "'");
    }
    if (ode_mass_.empty()) ode_mass_ = dimensioned(Text{"1", false, 5, true}, "m_ode");
    std::string p = q + "_ode";
    for (int k = 2; find(p) || object_spelt(p) || labels_.count(p); ++k) p = q + "_ode" + std::to_string(k);
    labels_.insert({p, 0});
    ode_particles_.insert(p);
    frames_lines_.push_back("particle " + p);
    odes_.emplace_back(q, st.where);
    const std::string x = newtonian_ + "x>";
    emit("# " + q + "'' = " + f.s + ": a particle of unit mass moved along " + x + " by that force");
    emit("translate " + p + " from " + newtonian_ + "_o by " + q + "*" + x);
    emit("mass " + p + " = " + ode_mass_);
    Text push{paren(f, 2) + "*" + x, true, 2, f.numeric};
    force(p, std::nullopt, dimensioned(push, "f_" + p));
}

void Translator::check_differential_model() {
    if (odes_.empty()) return;
    const Location at = odes_.front().second;
    const std::string first = odes_.front().first;
    auto refuse = [&](const std::string& why, const std::string& hint) {
        report(Severity::error, at, "the equation for " + first + "'' is not translated: " + why, hint);
    };
    for (const auto& [k, e] : objects_)
        if ((e.kind == Kind::body || e.kind == Kind::particle) && !ode_particles_.count(e.name))
            return refuse("the model also has " + std::string(kind_word(e.kind)) + " '" + e.name + "'",
                          "a file is either a model of bodies and particles (KANE()) or a set of differential "
                          "equations X'' = ...; give " + first + " a particle and forces instead");
    if (kane_at_) return refuse("the file also forms Kane's equations (ZERO = FR() + FRSTAR())", "write either one");
    if (has_gravity_) return refuse("GRAVITY would act on the equations' particles", "leave GRAVITY out");
    for (const KinematicEquation& k : kinematics_)
        report(Severity::error, k.where,
               "the first-order equation " + k.coordinate + "' = ... is not translated: Alembert simulates "
               "equations for second derivatives",
               "write it as a second-order equation, or as " + k.coordinate + "' = V with a variable V and V' = ...");
    for (const std::string& v : variables_) {
        if (rate_of_.count(v)) continue;
        bool has = false;
        for (const auto& [x, where] : odes_) has = has || x == v;
        const Entry* en = find(v);
        if (!has && !odes_left_out_.count(v))  // a left-out equation is said where it was left out
            report(Severity::error, en ? en->where : at,
                   "the variable '" + v + "' has no equation (" + v + "'' = ...) among the model's differential equations",
                   "give it one, or declare it SPECIFIED and give its value with INPUT");
    }
}

std::string Translator::matrix(const Expr& m) {
    if (m.args.size() != 3) fail(m.where, "a direction cosine matrix has 3 rows", "write [a, b, c; d, e, f; g, h, i]");
    std::vector<std::string> rows;
    for (const Expr& row : m.args) {
        if (row.args.size() != 3) fail(row.where, "a direction cosine matrix has 3 columns");
        std::vector<std::string> cells;
        for (const Expr& c : row.args) cells.push_back(scalar(c).s);
        rows.push_back(join(cells));
    }
    return "[" + join(rows, "; ") + "]";
}

void Translator::matrix_assignment(const Statement& st) {
    // M = [a, b; c, d], or M = a matrix expression (TRANSPOSE(A)*B, ...)
    if (st.rhs.kind == Expr::Kind::matrix)
        for (const Expr& row : st.rhs.args)
            if (row.args.size() != st.rhs.args.front().args.size())
                fail(row.where, "the rows of matrix '" + st.lhs.text + "' have different lengths",
                     "give every row " + std::to_string(st.rhs.args.front().args.size()) + " elements");
    Text m = st.rhs.kind == Expr::Kind::matrix ? matrix_literal(st.rhs) : expr(st.rhs);
    if (!m.matrix()) fail(st.rhs.where, "'" + st.lhs.text + "' is a matrix and is assigned only a matrix", "give the expression another name");
    const Entry* old = find(st.lhs.text);
    const Entry& e = old ? *old : add(st.lhs.text, Kind::matrix, st.lhs.where);
    Entry& stored = names_[e.key];
    stored.rows = m.rows;
    stored.cols = m.cols;
    stored.elements.clear(), stored.indices = 0;  // assigned whole from here on
    emit(e.name + " = " + m.s);
}

void Translator::vector_assignment(const Statement& st) {
    const Expr& lhs = st.lhs;
    std::string key = upper(lhs.text);
    if (lhs.primes) fail(lhs.where, "a prime on a vector name", "assign the vector itself");
    auto pt = [this](std::string_view n) { return point_of(n); };
    auto fr = [this](std::string_view n) { return frame_of(n); };
    auto bd = [this](std::string_view n) -> std::optional<std::string> {
        const Entry* en = find_object(n);
        if (en && (en->kind == Kind::body || en->kind == Kind::frame || en->kind == Kind::newtonian)) return en->name;
        return std::nullopt;
    };
    std::string_view name(lhs.text);
    const Entry* existing = find(lhs.text);
    if (!existing) {
        if (key.rfind("P_", 0) == 0)
            if (auto s = split(name.substr(2), pt, pt)) {
                emit("translate " + s->second + " from " + s->first + " by " +
                     dimensioned(vec(st.rhs), "r_" + s->second));
                joined_[s->first].insert(s->second);
                joined_[s->second].insert(s->first);
                return release_inertias();
            }
        if (key.rfind("V_", 0) == 0)
            if (auto s = split(name.substr(2), pt, fr))
                return emit("velocity " + s->first + " in " + s->second + " = " +
                            dimensioned(vec(st.rhs), "v_" + s->first));
        if (key.rfind("A_", 0) == 0)
            if (auto s = split(name.substr(2), pt, fr))
                return emit("acceleration " + s->first + " in " + s->second + " = " +
                            dimensioned(vec(st.rhs), "a_" + s->first));
        if (key.rfind("W_", 0) == 0)
            if (auto s = split(name.substr(2), fr, fr))
                return angular_velocity(s->first, s->second, dimensioned_text(vec(st.rhs), "w_" + s->first));
        if (key.rfind("ALF_", 0) == 0)
            if (auto s = split(name.substr(4), fr, fr))
                return emit("angacc " + s->first + " in " + s->second + " = " +
                            dimensioned(vec(st.rhs), "alf_" + s->first));
        if (key.rfind("FORCE_", 0) == 0)
            if (auto p = point_of(name.substr(6)))
                return force(*p, std::nullopt, dimensioned(load_value(st, key), "f_" + *p));
        if (key.rfind("TORQUE_", 0) == 0)
            if (auto b = bd(name.substr(7)))
                return torque(*b, std::nullopt, dimensioned(load_value(st, key), "tau_" + *b));
        // a name of Autolev's own form whose points or frames are not declared is a mistake,
        // not a new vector
        static const std::pair<const char*, const char*> forms[] = {
            {"P_", "a position: P_O_P> needs two declared points"},
            {"V_", "a velocity: V_P_N> needs a declared point and frame"},
            {"A_", "an acceleration: A_P_N> needs a declared point and frame"},
            {"W_", "an angular velocity: W_B_N> needs two declared frames or bodies"},
            {"ALF_", "an angular acceleration: ALF_B_N> needs two declared frames or bodies"},
            {"FORCE_", "a force: FORCE_P> needs a declared point or particle"},
            {"TORQUE_", "a torque: TORQUE_B> needs a declared frame or body"}};
        for (const auto& [prefix, meaning] : forms)
            if (key.rfind(prefix, 0) == 0)
                fail(lhs.where, "'" + lhs.text + ">' has the form of " + meaning,
                     "declare the points and frames it names (POINTS, FRAMES, BODIES), or give the vector "
                     "another name");
        Text r = vec(st.rhs);
        const Entry& ne = add(lhs.text, Kind::vector, lhs.where);
        names_[key].numeric = r.numeric;
        return emit(ne.name + "> = " + r.s);
    }
    if (existing->kind != Kind::vector)
        fail(lhs.where, "'" + lhs.text + "' is " + kind_word(existing->kind) + ", not a vector");
    Text r = vec(st.rhs);
    names_[key].numeric = r.numeric;
    emit(existing->name + "> = " + r.s);
}

Text Translator::load_value(const Statement& st, const std::string& key) {
    if (st.compound == 0) {
        if (assigned_loads_.count(key))
            fail(st.lhs.where, "'" + st.lhs.text + ">' is assigned a second time, which replaces its first value",
                 "add to it with " + st.lhs.text + "> += v> (or FORCE(...), TORQUE(...)), or remove the first");
        Text v = vec(st.rhs);  // first: a value left out leaves the load unassigned
        assigned_loads_.insert(key);
        return v;
    }
    if (st.compound != '+' && st.compound != '-')
        fail(st.lhs.where, std::string("'") + st.compound + "=' on a force or torque is not translated",
             "write the whole load: " + st.lhs.text + "> = ...");
    Text v = vec(st.rhs.args[1]);
    assigned_loads_.insert(key);
    if (st.compound == '-') v = {"-" + paren(v, 4), true, 3, v.numeric};
    return v;
}

std::string Translator::label(const std::string& base) {
    std::string l = base;
    for (int k = 2; labels_.count(l) || find(l); ++k) l = base + "_" + std::to_string(k);
    labels_.insert({l, 0});
    return l;
}

void Translator::force(const std::string& on, const std::optional<std::string>& from, const std::string& v) {
    std::vector<std::string> at{on};
    if (from) at.push_back(*from);
    for (const std::string& x : at)
        if (object_spelt(x) && object_spelt(x)->kind == Kind::point) forced_points_.emplace_back(x, statement_where_);
    std::string l = label("F_" + on);
    emit("force " + l + " on " + on + (from ? " from " + *from : "") + " = " + v);
}

void Translator::torque(const std::string& on, const std::optional<std::string>& from, const std::string& v) {
    std::string l = label("T_" + on);
    emit("torque " + l + " on " + on + (from ? " from " + *from : "") + " = " + v);
}

void Translator::expression_statement(const Statement& st) {
    const Expr& e = st.expr;
    if (e.kind != Expr::Kind::call) return emit(expr(e).s);
    std::string f = upper(e.text);
    auto nargs = [&](std::size_t n, const char* form) {
        if (e.args.size() != n)
            fail(e.where, e.text + "() takes " + std::to_string(n) + " arguments, not " + std::to_string(e.args.size()),
                 std::string("write ") + form);
    };
    if (f == "SOLVE") return solve_statement(e);
    if (f == "EIG" && e.args.size() > 1) return eig_statement(e);
    if (f == "SIMPROT") {
        nargs(4, "SIMPROT(A, B, 3, Q1)");
        std::string a = frame_name(e.args[0]), b = frame_name(e.args[1]);
        std::string axis = simprot_axis(e.args[2], a, b);
        const std::string by = angle(e.args[3], scalar(e.args[3]), "SIMPROT").s;
        parent_[b] = a;
        return emit("rotate " + b + " from " + a + " about " + axis + " by " + by);
    }
    if (f == "V2PTS" || f == "V1PT" || f == "A2PTS") {
        nargs(4, (e.text + "(N, B, P, Q)").c_str());
        std::string n = frame_name(e.args[0]), b = frame_name(e.args[1]);
        std::string p = point_name(e.args[2]), q = point_name(e.args[3]);
        std::string what = f == "A2PTS" ? "acceleration " : "velocity ";
        if (f == "V2PTS") {  // both points are fixed on B: forces there act on B
            for (const std::string& x : {p, q})
                if (object_spelt(x) && object_spelt(x)->kind == Kind::point && !point_body_.count(x)) point_body_[x] = b;
        }
        return emit(what + q + " in " + n + " from " + p + (f == "V1PT" ? " moving on " : " fixed on ") + b);
    }
    if (f == "A1PT") {
        // Q moving on B, P fixed on B: a_Q_N = a_Q_B + a_P_N + alf_B_N x r + w_B_N x (w_B_N x r)
        // + 2 w_B_N x v_Q_B, r from P to Q (the one-point theorem for accelerations)
        nargs(4, "A1PT(N, B, P, Q)");
        const std::string n = frame_name(e.args[0]), b = frame_name(e.args[1]);
        const std::string p = point_name(e.args[2]), q = point_name(e.args[3]);
        const std::string r = "pos(" + q + ", " + p + ")", w = "angvel(" + b + ", " + n + ")";
        return emit("acceleration " + q + " in " + n + " = acc(" + q + ", " + b + ") + acc(" + p + ", " + n +
                    ") + cross(angacc(" + b + ", " + n + "), " + r + ") + cross(" + w + ", cross(" + w + ", " + r +
                    ")) + 2*cross(" + w + ", vel(" + q + ", " + b + "))");
    }
    if (f == "GRAVITY") {
        if (e.args.empty()) fail(e.where, "GRAVITY() needs the vector", "write GRAVITY(-G*N2>)");
        if (e.args.size() > 1)
            leave_out(e.args[1].where, "GRAVITY on some bodies only has no counterpart: the script's gravity acts on "
                                       "every body and particle",
                      "apply a force m*g> at each of these bodies' mass centres instead (FORCE_BO> = MB*g>)");
        has_gravity_ = true;
        return emit("gravity " + dimensioned(vec(e.args[0]), "g_" + newtonian_));
    }
    if (f == "FORCE" || f == "TORQUE") {
        nargs(2, f == "FORCE" ? "FORCE(P, v>) or FORCE(P/Q, v>)" : "TORQUE(B, v>) or TORQUE(A/B, v>)");
        const Expr& at = e.args[0];
        std::optional<std::string> from;
        std::string on;
        auto object = [&](const Expr& x) { return f == "FORCE" ? point_name(x) : frame_or_body(x); };
        if (at.kind == Expr::Kind::binary && at.text == "/") {
            from = object(at.args[0]);
            on = object(at.args[1]);
        } else {
            on = object(at);
        }
        std::string v = dimensioned(vec(e.args[1]), (f == "FORCE" ? "f_" : "tau_") + on);
        return f == "FORCE" ? force(on, from, v) : torque(on, from, v);
    }
    if (f == "KANE") {
        // KANE(F1, ...): the auxiliary equations are solved for these load measures
        for (const Expr& a : e.args) {
            const Entry* en = a.kind == Expr::Kind::name && !a.vector && a.primes == 0 ? find(a.text) : nullptr;
            if (!en || (en->kind != Kind::specified && en->kind != Kind::variable))
                fail(a.where, "KANE(...) names the load measures the auxiliary equations determine, declared "
                              "with SPECIFIED or VARIABLES",
                     "declare '" + a.text + "' with SPECIFIED and use it in a FORCE or TORQUE");
            kane_forces_.push_back({en->name, a.where});
        }
        if (!e.args.empty() && aux_speeds_.empty())
            fail(e.args[0].where, "KANE(" + e.args[0].text + ", ...) solves for load measures, and the file has no "
                                  "auxiliary speeds to bring them out",
                 "open the constraint each force enforces: AUXILIARY[1] = U4, CONSTRAIN(AUXILIARY[U4]) before KANE()");
        if (const Entry* z = find("ZERO"); z && z->indices)
            fail(e.where, "KANE() forms Kane's equations from the bodies and loads, and ZERO holds the file's own "
                          "equations (assigned by element at line " + std::to_string(z->where.line) + ")",
                 "solve the file's equations with SOLVE(ZERO, U1', ...), or form Kane's with ZERO = FR() + FRSTAR()");
        need_placed_inertia(st.where, "KANE()");
        if (!kane_at_) kane_at_ = model_.size(), emit("");
        kane_where_ = st.where;
        return;
    }
    if (f == "CONSTRAIN") {
        bool dependent = false;
        for (const Expr& a : e.args) {
            const std::string which = a.kind == Expr::Kind::index ? upper(a.text) : "";
            if (which != "DEPENDENT" && which != "AUXILIARY")
                fail(a.where, "CONSTRAIN() takes DEPENDENT[U3, ...] or AUXILIARY[U4, ...]",
                     "name the dependent speeds with CONSTRAIN(DEPENDENT[U3]), the auxiliary ones with "
                     "CONSTRAIN(AUXILIARY[U4])");
            for (const Expr& u : a.args) {
                // a speed (U3), or a coordinate's rate (Q1') in a model without speeds
                const Entry* en = u.kind == Expr::Kind::name && !u.vector && u.primes <= 1 ? find(u.text) : nullptr;
                if (!en || en->kind != Kind::variable)
                    fail(u.where, which + "[...] lists speeds, declared with VARIABLES or MOTIONVARIABLES",
                         which == "DEPENDENT"
                             ? "write CONSTRAIN(DEPENDENT[U3]), or CONSTRAIN(DEPENDENT[Q1']) in a model without speeds"
                             : "name a speed here, or declare '" + u.text + "' with MOTIONVARIABLES");
                if (which == "DEPENDENT") {
                    dependent_.push_back(en->name + (u.primes ? "'" : ""));
                    dependent_where_.push_back(u.where);
                } else {
                    if (u.primes)
                        fail(u.where, "AUXILIARY[...] lists speeds, not rates",
                             "name the speed the auxiliary constraint is solved for: CONSTRAIN(AUXILIARY[U4])");
                    aux_speeds_.push_back(en->name);
                }
            }
            dependent = dependent || which == "DEPENDENT";
        }
        if (aux_constraints_.size() != aux_speeds_.size())
            fail(e.where,
                 std::to_string(aux_speeds_.size()) + " auxiliary speeds for " + std::to_string(aux_constraints_.size()) +
                     " auxiliary constraints (AUXILIARY[...] = ...)",
                 "give one AUXILIARY[i] = ... for each auxiliary speed, before CONSTRAIN");
        if (!dependent) return;
        if (constraints_.size() != dependent_.size())
            fail(e.where,
                 std::to_string(dependent_.size()) + " dependent speeds for " + std::to_string(constraints_.size()) +
                     " constraints (DEPENDENT[...] = ...)",
                 "give one DEPENDENT[i] = ... for each dependent speed, before CONSTRAIN");
        return;
    }
    emit(expr(e).s);
}

bool Translator::located(const std::string& a, const std::string& b) const {
    std::set<std::string> seen{a};
    std::vector<std::string> todo{a};
    while (!todo.empty()) {
        const std::string p = todo.back();
        todo.pop_back();
        if (p == b) return true;
        if (auto it = joined_.find(p); it != joined_.end())
            for (const std::string& q : it->second)
                if (seen.insert(q).second) todo.push_back(q);
    }
    return false;
}

void Translator::need_placed_inertia(Location where, const std::string& what, const std::string& body) {
    for (const auto& [b, w] : inertia_waiting_)
        if (body.empty() || b == body)
            fail(where,
                 what + " needs the inertia of INERTIA " + w.said + " at line " + std::to_string(w.where.line) +
                     ", which is moved to the mass centre only once the mass and the position of the mass centre "
                     "from the point are given, and they are not yet",
                 "give MASS and the position before this line");
}

void Translator::release_inertias() {
    for (auto it = inertia_waiting_.begin(); it != inertia_waiting_.end();) {
        if (massive_.count(it->first) && located(it->first + "cm", it->second.about)) {
            emit(it->second.line);
            it = inertia_waiting_.erase(it);
        } else {
            ++it;
        }
    }
}

Text Translator::dimensioned_text(const Text& t, const std::string& base) {
    if (!t.numeric || t.s == "0" || t.s == "0>") return t;
    std::string name = base;
    for (int k = 2; find(name) || extra_names_.count(name); ++k) name = base + "_" + std::to_string(k);
    extra_names_.insert({name, 0});
    bool plain_number = !t.vector && t.s.find_first_not_of("0123456789.e-+") == std::string::npos;
    if (plain_number) {
        extra_constants_.push_back(name + " = " + t.s);
        return {name, false, 5, false};
    }
    extra_constants_.push_back(name + " = 1");
    return {name + "*" + (t.prec <= 3 ? "(" + t.s + ")" : t.s), t.vector, 2, false};
}

void Translator::angular_velocity(const std::string& b, const std::string& a, const Text& w) {
    auto it = parent_.find(b);
    if (it == parent_.end() || it->second == a) return emit("angvel " + b + " in " + a + " = " + w.s);
    const std::string& p = it->second;
    emit("angvel " + b + " in " + p + " = " + w.s + " - angvel(" + p + ", " + a + ")");
}

std::string Translator::simprot_axis(const Expr& ax, const std::string& a, const std::string& b) {
    std::string sign;
    const Expr* x = &ax;
    if (x->kind == Expr::Kind::unary && x->text == "-") {
        sign = "-";
        x = &x->args[0];
    }
    if (x->kind == Expr::Kind::number && (x->text == "1" || x->text == "2" || x->text == "3"))
        return sign + std::string(1, "xyz"[x->text[0] - '1']);
    if (x->kind == Expr::Kind::name && x->vector) {
        std::string v = vector_name(*x);
        for (const std::string& f : {a, b})
            for (char c : std::string("xyz"))
                if (v == f + std::string(1, c) + ">") return sign + std::string(1, c);
    }
    fail(ax.where, "SIMPROT about this axis is not translated",
         "give the axis as 1, 2 or 3 (or -1, -2, -3), or as a unit vector of either frame");
}

void Translator::solve_statement(const Expr& e) {
    if (e.args.size() < 2)
        fail(e.where, "SOLVE() takes the equations and the unknowns", "write SOLVE(M, X1, X2) or SOLVE(e, X)");
    const Expr& m = e.args[0];
    // the equations: Kane's (ZERO = FR() + FRSTAR() before), a matrix of one row or column the
    // file assigned, or one expression
    std::string eqs;
    std::size_t count = 1;
    if (m.kind == Expr::Kind::name && !m.vector && upper(m.text) == "ZERO" && !find(m.text)) {
        if (!kane_at_)
            fail(m.where, "SOLVE(ZERO, ...) needs ZERO = FR() + FRSTAR() before it",
                 "form Kane's equations first: ZERO = FR() + FRSTAR()");
        eqs = "\x02";  // Kane's equations' name, known when the script is assembled
        count = e.args.size() - 1;
    } else if (const Entry* en = m.kind == Expr::Kind::name && !m.vector ? find(m.text) : nullptr;
        en && en->kind == Kind::matrix) {
        if (en->indices) whole_array(m, *en);  // ZERO[1] = ...: the matrix written from its elements
        if (en->rows < 0 || en->cols < 0)
            fail(m.where, "SOLVE() takes a matrix whose size is known here, and the size of '" + m.text +
                              "' is known only when the script runs", "write the equations out: EQ = [e1; e2]");
        if (en->rows != 1 && en->cols != 1)
            fail(m.where, "SOLVE() takes a matrix of one row or one column, and '" + m.text + "' is " +
                              std::to_string(en->rows) + " by " + std::to_string(en->cols),
                 "write the equations as a column: M = [e1; e2]");
        eqs = en->name;
        count = static_cast<std::size_t>(en->rows * en->cols);
    } else {
        std::string value = scalar(m).s;
        eqs = fresh_name("solve_eq");
        emit(eqs + " = [" + value + "]");
    }
    if (e.args.size() - 1 != count)
        fail(e.args[1].where,
             std::to_string(count) + " equation" + (count == 1 ? "" : "s") + " for " + std::to_string(e.args.size() - 1) +
                 " unknowns", "give as many unknowns as equations");
    std::vector<std::string> xs, keep;
    std::vector<std::string> keys;
    for (std::size_t i = 1; i < e.args.size(); ++i) {
        const Expr& x = e.args[i];
        const Entry* en = x.kind == Expr::Kind::name && !x.vector ? find(x.text) : nullptr;
        if (!en || (en->kind != Kind::constant && en->kind != Kind::variable && en->kind != Kind::specified))
            fail(x.where, "SOLVE() solves for constants, variables or specified quantities",
                 "write SOLVE(M, X1, X2) with X1, X2 declared");
        const std::string key = en->name + std::string(static_cast<std::size_t>(x.primes), '\'');
        if (solved_.count(key) || std::find(keys.begin(), keys.end(), key) != keys.end())
            fail(x.where, "'" + x.text + "' is solved for already (here or by a SOLVE before this one)",
                 "solve for each unknown once");
        xs.push_back(scalar(x).s);
        std::string base = en->name;
        base += std::string(static_cast<std::size_t>(x.primes), 'd');  // U' -> Ud_solved
        keep.push_back(fresh_name(base + "_solved"));
        keys.push_back(key);
    }
    emit("solve " + eqs + " for " + join(xs) + " as " + join(keep));
    for (std::size_t i = 0; i < keys.size(); ++i) solved_[keys[i]] = keep[i];
}

}  // namespace alembert::lang::autolev
