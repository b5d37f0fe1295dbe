// SPDX-License-Identifier: MIT
// Autolev statements to Alembert statements: names, declarations, kinematics, loads, Kane.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/parser.hpp"
#include "autolev_syntax.hpp"

namespace alembert::lang {

bool AutolevTranslation::ok() const {
    return std::none_of(diagnostics.begin(), diagnostics.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
}

namespace autolev {
namespace {

// What an Autolev name stands for.
enum class Kind { newtonian, frame, body, particle, point, constant, variable, specified, scalar, vector };

const char* kind_word(Kind k) {
    switch (k) {
        case Kind::newtonian: return "the Newtonian frame";
        case Kind::frame: return "a frame";
        case Kind::body: return "a body";
        case Kind::particle: return "a particle";
        case Kind::point: return "a point";
        case Kind::constant: return "a constant";
        case Kind::variable: return "a variable";
        case Kind::specified: return "a specified quantity";
        case Kind::scalar: return "a scalar";
        case Kind::vector: return "a vector";
    }
    return "a name";
}

struct Entry {
    Kind kind = Kind::scalar;
    std::string name{};  // the Alembert spelling
    Location where{};
    bool numeric = false;  // a scalar or vector the file assigned from numbers alone
};

// A translated expression: its Alembert text, whether it is a vector, its precedence
// (1 sum, 2 product, 3 sign, 4 power, 5 atom).
struct Text {
    std::string s{};
    bool vector = false;
    int prec = 5;
    bool numeric = false;  // numbers and unit vectors only: no quantity with a dimension
};

// A declared constant: its declaration group (one `constant` line each) and its value.
struct ConstantDecl {
    std::string name{};
    std::string value{};  // empty: symbolic
    std::string unit{};
    bool positive = false;  // CONSTANTS L+
};

// A name declared with a definition (SPECIFIED F = -K*X, VARIABLES Z = 2*X): a scalar of the
// script, assigned where the declaration stands.
struct Definition {
    std::string name{};
    Expr value{};
};

struct KinematicEquation {
    std::string coordinate{};
    std::string residual{};
};

class Translator {
public:
    explicit Translator(std::string file) : file_(std::move(file)) {}

    AutolevTranslation run(std::string_view source) {
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
        // MASS A = MA and INERTIA B, I1, I2, I3 declare their undeclared names as constants
        for (const Statement& st : parsed.statements)
            if (st.kind == Statement::Kind::list && (st.keyword == "MASS" || st.keyword == "INERTIA")) {
                try {
                    implicit_constants(st);
                } catch (const ScriptError& e) {
                    pending_.push_back({Severity::error, file_, e.where(), e.what(), e.hint()});
                }
            }
        find_rate_speeds(parsed);
        std::vector<Diagnostic> declaration_problems = std::move(pending_);
        pending_.clear();
        std::size_t next_declaration_problem = 0;
        for (const Statement& st : parsed.statements) {
            flush_problems(st.where, false);
            while (next_declaration_problem < declaration_problems.size() &&
                   declaration_problems[next_declaration_problem].location.line <= st.where.line)
                out_.diagnostics.push_back(declaration_problems[next_declaration_problem++]);
            try {
                translate(st);
            } catch (const ScriptError& e) {
                report(Severity::error, e.where(), e.what(), e.hint());
            }
        }
        flush_problems({}, true);
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
        return std::move(out_);
    }

private:
    // ---- diagnostics ----------------------------------------------------------------------

    void report(Severity s, Location where, std::string message, std::string hint = "") {
        out_.diagnostics.push_back({s, file_, where, std::move(message), std::move(hint)});
    }
    [[noreturn]] static void fail(Location where, const std::string& message, const std::string& hint = "") {
        throw ScriptError(where, message, hint);
    }
    void not_translated(Location where, const std::string& what, const std::string& why) {
        report(Severity::warning, where, what + " is not translated: " + why,
               "the statement is left out of the Alembert script; write its counterpart by hand if needed");
    }

    // ---- names ----------------------------------------------------------------------------

    std::string alembert_spelling(const std::string& name, Location where) {
        if (name == "t" || name == "pi" || is_reserved(name)) {
            std::string renamed = name + "_";
            report(Severity::note, where,
                   "'" + name + "' is a word of the Alembert language; it is called '" + renamed + "' in the script");
            return renamed;
        }
        return name;
    }

    const Entry& add(const std::string& name, Kind kind, Location where) {
        std::string key = upper(name);
        auto it = names_.find(key);
        if (it != names_.end()) {
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
        Entry e{kind, alembert_spelling(name, where), where};
        return names_.emplace(key, std::move(e)).first->second;
    }

    const Entry* find(std::string_view name) const {
        auto it = names_.find(upper(name));
        return it == names_.end() ? nullptr : &it->second;
    }

    // the expanded names of a declarator: Q{3} -> Q1, Q2, Q3
    static std::vector<std::string> expand(const Declarator& d) {
        if (d.last < d.first) return {d.name};
        std::vector<std::string> v;
        for (int i = d.first; i <= d.last; ++i) v.push_back(d.name + std::to_string(i));
        return v;
    }

    void declare(const Statement& st) {
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
                     "frames, bodies, particles and points have no value; give it with POINTS, SIMPROT, ...");
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
        if (w == "NEWTONIAN") {
            if (st.declarators.size() != 1 || st.declarators[0].last >= st.declarators[0].first)
                fail(st.where, "NEWTONIAN declares one frame", "write NEWTONIAN N");
            if (!newtonian_.empty())
                fail(st.where, "a second NEWTONIAN frame", "a model has one Newtonian frame; declare the others with FRAMES");
            const Declarator& d = st.declarators[0];
            no_primes(d);
            const Entry& e = add(d.name, Kind::newtonian, d.where);
            newtonian_ = e.name;
            implicit_points_[upper(d.name) + "O"] = e.name + "_o";
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
                implicit_points_[upper(e.name) + "O"] = e.name + "cm";
                // Alembert's own names for the body's points are accepted too
                implicit_points_[upper(e.name) + "CM"] = e.name + "cm";
                implicit_points_[upper(e.name) + "_O"] = e.name + "_o";
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
        not_translated(st.where, w, "Alembert has no imaginary numbers");
    }

    // Autolev declares a name that MASS or INERTIA gives alone (MASS A = MA, INERTIA B, I1,
    // I2, I3) and that no declaration names as a constant; so does the translation.
    void implicit_constants(const Statement& st) {
        std::vector<const Expr*> values;
        for (std::size_t i = 0; i < st.items.size(); ++i) {
            const Item& it = st.items[i];
            if (st.keyword == "MASS" && it.has_value) values.push_back(&it.value);
            if (st.keyword == "INERTIA" && i > 0 && !it.has_value) values.push_back(&it.lhs);
        }
        for (const Expr* v : values) {
            if (v->kind != Expr::Kind::name || v->vector || v->primes || find(v->text)) continue;
            std::string key = upper(v->text);
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

    // Speeds that are a coordinate's rate (Q1' = U1, or OMEGA = THETA') are written as that rate
    // (U1 as Q1', U1' as Q1''), so that Kane's equations are in the coordinates' rates, as
    // Alembert's simulate and codegen take them. Only when every kinematical equation has this
    // form and the model has no constraints; otherwise the speeds stay speeds.
    void find_rate_speeds(const ParsedFile& parsed) {
        std::map<std::string, std::string> rate_of;  // speed -> coordinate
        std::set<std::string> coordinates;
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
                if (!u) return;  // a kinematical equation of another form
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
        rate_of_ = std::move(rate_of);
        aliased_coordinates_ = std::move(coordinates);
    }

    static std::string join(const std::vector<std::string>& v, const char* sep = ", ") {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
        return s;
    }

    // ---- expressions ----------------------------------------------------------------------

    // a plain number (with its sign), as Alembert reads it
    std::string number_text(const Expr& e, const std::string& what) {
        if (e.kind == Expr::Kind::unary && e.args[0].kind == Expr::Kind::number)
            return (e.text == "-" ? "-" : "") + number_text(e.args[0], what);
        if (e.kind != Expr::Kind::number)
            fail(e.where, what + " must be a number", "give the number itself, such as 9.81");
        std::string s = e.text;
        if (s.front() == '.') s = "0" + s;
        std::size_t dot = s.find('.');
        if (dot != std::string::npos && (dot + 1 == s.size() || !std::isdigit(static_cast<unsigned char>(s[dot + 1]))))
            s.insert(dot + 1, "0");
        return s;
    }

    static std::string paren(const Text& t, int need) { return t.prec < need ? "(" + t.s + ")" : t.s; }

    Text expr(const Expr& e) {
        switch (e.kind) {
            case Expr::Kind::number: return {number_text(e, "a number"), false, 5, true};
            case Expr::Kind::name: {
                if (!e.vector && e.primes == 0 && upper(e.text) == "T" && !find(e.text)) {
                    // Autolev's time is a number (of seconds): t/t_unit with t_unit = 1 s, so that
                    // SIN(T) is the sine of a number, as in Autolev
                    if (time_unit_.empty()) {
                        time_unit_ = "t_unit";
                        for (int k = 2; find(time_unit_) || extra_names_.count(time_unit_); ++k)
                            time_unit_ = "t_unit" + std::to_string(k);
                        extra_names_.insert({time_unit_, 0});
                    }
                    return {"t/" + time_unit_, false, 2, false};
                }
                resolved_numeric_ = false;
                Text t = e.vector ? Text{vector_name(e), true, 5} : Text{scalar_name(e), false, 5};
                t.numeric = resolved_numeric_;
                return t;
            }
            case Expr::Kind::call: return call(e);
            case Expr::Kind::index:
                fail(e.where, "the array element '" + e.text + "[...]' is not translated",
                     "Alembert arrays hold equations; name the value as a scalar instead");
            case Expr::Kind::unary: {
                Text a = expr(e.args[0]);
                if (e.text == "+") return a;
                return {"-" + paren(a, 4), a.vector, 3, a.numeric};
            }
            case Expr::Kind::binary: return binary(e);
            case Expr::Kind::matrix:
            case Expr::Kind::row:
                fail(e.where, "a matrix is translated only as a direction cosine matrix (N_A = [...])",
                     "write the matrix as N_A = [...] or with SIMPROT");
        }
        fail(e.where, "an expression that is not translated");
    }

    // A chain of operators (a + b + c ..., read as ((a + b) + c) ...) is translated along its
    // left operands by iteration, so that a chain of any length needs no deeper stack.
    Text binary(const Expr& e) {
        std::vector<const Expr*> chain;
        const Expr* x = &e;
        while (x->kind == Expr::Kind::binary) {
            chain.push_back(x);
            x = &x->args[0];
        }
        Text acc = expr(*x);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            Text b = expr((*it)->args[1]);
            bool numeric = acc.numeric && b.numeric;
            acc = combine(**it, std::move(acc), std::move(b));
            acc.numeric = numeric;
        }
        return acc;
    }
    // `a op b` from the translations of a and b (a's text is moved, not copied, so that a
    // long chain costs time in proportion to its length)
    Text combine(const Expr& e, Text a, Text b) {
        const std::string& op = e.text;
        auto wrapped = [](Text& t, bool wrap) { return wrap ? "(" + std::move(t.s) + ")" : std::move(t.s); };
        if (op == "+" || op == "-") {
            if (a.vector != b.vector)
                fail(e.where, std::string("'") + op + "' between a vector and a scalar",
                     "both sides must be vectors (with '>') or both scalars");
            // a sign on the right needs brackets (a + (-b)), and so does a sum after '-'
            bool wrap = b.prec == 3 || (op == "-" && b.prec <= 1);
            std::string s = std::move(a.s);
            s += " " + op + " ";
            s += wrapped(b, wrap);
            return {std::move(s), a.vector, 1};
        }
        if (op == "*" || op == "/") {
            if (op == "*" && a.vector && b.vector)
                fail(e.where, "'*' between two vectors", "use DOT(a>, b>) or CROSS(a>, b>)");
            if (op == "/" && b.vector) fail(e.where, "division by a vector", "divide by a scalar such as MAG(v>)");
            bool vector = a.vector || b.vector;
            std::string s = wrapped(a, a.prec < 2);
            s += op;
            s += wrapped(b, b.prec <= 3);
            return {std::move(s), vector, 2};
        }
        // ^
        if (a.vector || b.vector) fail(e.where, "a power of a vector", "use DOT(v>, v>) for the square of a magnitude");
        std::string s = wrapped(a, a.prec <= 4);
        s += "^";
        s += wrapped(b, b.prec < 5);
        return {std::move(s), false, 4};
    }

    Text call(const Expr& e) {
        bool numeric = true;  // every argument numeric (each translated once)
        Text t = call_text(e, numeric);
        t.numeric = numeric;
        return t;
    }
    Text call_text(const Expr& e, bool& numeric) {
        std::string f = upper(e.text);
        auto args = [&](std::size_t lo, std::size_t hi) {
            if (e.args.size() < lo || e.args.size() > hi)
                fail(e.where,
                     e.text + "() takes " +
                         (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                         " arguments, not " + std::to_string(e.args.size()));
        };
        auto scalar_arg = [&](std::size_t i) {
            Text t = expr(e.args[i]);
            numeric = numeric && t.numeric;
            if (t.vector) fail(e.args[i].where, e.text + "() takes a scalar here, not a vector");
            return t;
        };
        auto vector_arg = [&](std::size_t i) {
            Text t = expr(e.args[i]);
            numeric = numeric && t.numeric;
            if (!t.vector) fail(e.args[i].where, e.text + "() takes a vector here (a name ending in '>')");
            return t;
        };
        static const std::map<std::string, std::string> elementary{
            {"SIN", "sin"},   {"COS", "cos"},   {"TAN", "tan"}, {"ASIN", "asin"}, {"ACOS", "acos"},
            {"ATAN", "atan"}, {"SQRT", "sqrt"}, {"EXP", "exp"}, {"LOG", "log"},   {"ABS", "abs"},
            {"LN", "log"}};
        if (auto it = elementary.find(f); it != elementary.end()) {
            args(1, 1);
            return {it->second + "(" + scalar_arg(0).s + ")", false, 5};
        }
        if (f == "DOT") {
            args(2, 2);
            return {"dot(" + vector_arg(0).s + ", " + vector_arg(1).s + ")", false, 5};
        }
        if (f == "CROSS") {
            args(2, 2);
            return {"cross(" + vector_arg(0).s + ", " + vector_arg(1).s + ")", true, 5};
        }
        if (f == "MAG") {
            args(1, 1);
            return {"mag(" + vector_arg(0).s + ")", false, 5};
        }
        if (f == "UNITVEC") {
            args(1, 1);
            return {"unit(" + vector_arg(0).s + ")", true, 5};
        }
        if (f == "EXPRESS") {
            args(2, 2);
            Text v = expr(e.args[0]);
            numeric = v.numeric;
            if (!v.vector) return v;  // a scalar is the same in every frame
            return {"express(" + v.s + ", " + frame_name(e.args[1]) + ")", true, 5};
        }
        if (f == "DT") {
            args(1, 2);
            Text v = expr(e.args[0]);
            numeric = v.numeric;
            if (v.vector) {
                if (e.args.size() != 2) fail(e.where, "DT of a vector needs the frame: DT(v>, N)");
                return {"dt(" + v.s + ", " + frame_name(e.args[1]) + ")", true, 5};
            }
            if (e.args.size() == 2) fail(e.args[1].where, "DT of a scalar takes no frame", "write DT(s)");
            return {"dt(" + v.s + ")", false, 5};
        }
        if (f == "FR" || f == "FRSTAR")
            fail(e.where, e.text + "() is translated only in ZERO = FR() + FRSTAR()",
                 "write ZERO = FR() + FRSTAR() and then KANE()");
        fail(e.where, "the Autolev function '" + e.text + "' is not translated",
             "the translator knows SIN, COS, TAN, ASIN, ACOS, ATAN, SQRT, EXP, LOG, ABS, DOT, CROSS, MAG, "
             "UNITVEC, EXPRESS and DT");
    }

    std::string scalar_name(const Expr& e) {
        const Entry* en = find(e.text);
        std::string primes(static_cast<std::size_t>(e.primes), '\'');
        if (!en) {
            std::string key = upper(e.text);
            if (key == "T") return "t" + primes;
            if (key == "PI" && e.primes == 0) {
                resolved_numeric_ = true;
                return "pi";
            }
            fail(e.where, "'" + e.text + "' is not declared",
                 "declare it (CONSTANTS, VARIABLES, ...) or assign it before this line");
        }
        switch (en->kind) {
            case Kind::constant:
            case Kind::scalar:
                resolved_numeric_ = en->numeric;
                if (e.primes && en->kind == Kind::scalar) {
                    // Z' of a named expression is its time derivative
                    std::string d = en->name;
                    for (int k = 0; k < e.primes; ++k) d = "dt(" + d + ")";
                    resolved_numeric_ = false;
                    return d;
                }
                if (e.primes) fail(e.where, "'" + e.text + "' is " + kind_word(en->kind) + "; it has no derivative",
                                   "declare it with VARIABLES to give it derivatives");
                return en->name;
            case Kind::variable:
            case Kind::specified: {
                if (auto r = rate_of_.find(en->name); r != rate_of_.end()) {
                    int& p = used_primes_[r->second];
                    p = std::max(p, e.primes + 1);
                    return r->second + primes + "'";
                }
                if (en->kind == Kind::variable) {
                    int& p = used_primes_[en->name];
                    p = std::max(p, e.primes);
                }
                return en->name + primes;
            }
            default:
                fail(e.where, "'" + e.text + "' is " + kind_word(en->kind) + ", not a value",
                     "a vector needs '>' (A1>, V_P_N>); points and frames are arguments of V2PTS, SIMPROT, ...");
        }
    }

    // ---- frames, points and vectors -------------------------------------------------------

    std::optional<std::string> frame_of(std::string_view name) const {
        const Entry* en = find(name);
        if (en && (en->kind == Kind::newtonian || en->kind == Kind::frame || en->kind == Kind::body)) return en->name;
        return std::nullopt;
    }
    std::optional<std::string> point_of(std::string_view name) const {
        const Entry* en = find(name);
        if (en && (en->kind == Kind::point || en->kind == Kind::particle)) return en->name;
        auto it = implicit_points_.find(upper(name));
        if (!en && it != implicit_points_.end()) return it->second;
        return std::nullopt;
    }
    std::string frame_name(const Expr& e) {
        if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0)
            if (auto f = frame_of(e.text)) return *f;
        fail(e.where, "expected a frame or body here", "name a frame declared with NEWTONIAN, FRAMES or BODIES");
    }
    std::string point_name(const Expr& e) {
        if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0)
            if (auto p = point_of(e.text)) return *p;
        std::string hint = "name a point declared with POINTS or PARTICLES";
        if (e.kind == Expr::Kind::name) {
            const Entry* en = find(e.text);
            if (en && en->kind == Kind::body)
                hint = "a body is not a point: its mass centre is " + e.text + "O";
        }
        fail(e.where, "expected a point here", hint);
    }
    std::string body_name(const Expr& e) {
        if (e.kind == Expr::Kind::name && !e.vector && e.primes == 0) {
            const Entry* en = find(e.text);
            if (en && en->kind == Kind::body) return en->name;
        }
        fail(e.where, "expected a body here", "name a body declared with BODIES");
    }

    // "X_Y" split into two names that satisfy `a` and `b`
    template <class A, class B>
    static std::optional<std::pair<std::string, std::string>> split(std::string_view rest, A a, B b) {
        for (std::size_t i = 1; i + 1 < rest.size(); ++i) {
            if (rest[i] != '_') continue;
            auto x = a(rest.substr(0, i));
            auto y = b(rest.substr(i + 1));
            if (x && y) return std::make_pair(*x, *y);
        }
        return std::nullopt;
    }

    // A vector name: 0>, a unit vector A1>, P_O_P>, V_P_N>, A_P_N>, W_B_N>, ALF_B_N>, or one
    // the file assigned.
    std::string vector_name(const Expr& e) {
        if (e.primes) fail(e.where, "a prime on a vector name", "write DT(v>, N) for the derivative of a vector");
        if (e.text == "0") {
            resolved_numeric_ = true;
            return "0>";
        }
        if (const Entry* en = find(e.text); en && en->kind == Kind::vector) {
            resolved_numeric_ = en->numeric;
            return en->name + ">";
        }
        std::string key = upper(e.text);
        char last = key.back();
        if (last >= '1' && last <= '3')
            if (auto f = frame_of(std::string_view(e.text).substr(0, e.text.size() - 1))) {
                resolved_numeric_ = true;
                return *f + std::string(1, "xyz"[last - '1']) + ">";
            }
        auto pt = [this](std::string_view n) { return point_of(n); };
        auto fr = [this](std::string_view n) { return frame_of(n); };
        std::string_view rest(e.text);
        if (key.rfind("P_", 0) == 0)
            if (auto s = split(rest.substr(2), pt, pt)) return "pos(" + s->second + ", " + s->first + ")";
        if (key.rfind("V_", 0) == 0)
            if (auto s = split(rest.substr(2), pt, fr)) return "vel(" + s->first + ", " + s->second + ")";
        if (key.rfind("A_", 0) == 0)
            if (auto s = split(rest.substr(2), pt, fr)) return "acc(" + s->first + ", " + s->second + ")";
        if (key.rfind("W_", 0) == 0)
            if (auto s = split(rest.substr(2), fr, fr)) return "angvel(" + s->first + ", " + s->second + ")";
        if (key.rfind("ALF_", 0) == 0)
            if (auto s = split(rest.substr(4), fr, fr)) return "angacc(" + s->first + ", " + s->second + ")";
        fail(e.where, "the vector '" + e.text + ">' is not defined",
             "unit vectors are a frame's name and 1, 2 or 3 (N1>); P_O_P>, V_P_N>, W_B_N> need declared "
             "points and frames; other vectors must be assigned before they are used");
    }

    // ---- statements -----------------------------------------------------------------------

    void emit(std::string line) { model_.push_back(std::move(line)); }

    void translate(const Statement& st) {
        statement_where_ = st.where;
        switch (st.kind) {
            case Statement::Kind::declaration: return definitions(st);
            case Statement::Kind::list: return list(st);
            case Statement::Kind::command: return command(st);
            case Statement::Kind::assignment: return assignment(st);
            case Statement::Kind::expression: return expression_statement(st);
        }
    }

    // SPECIFIED F = -K*X: F is assigned where it is declared, so the statements before it
    // that use it are reported by the script, not given another meaning
    void definitions(const Statement& st) {
        auto it = definitions_.find({st.where.line, st.where.column});
        if (it == definitions_.end()) return;
        for (const Definition& d : it->second) {
            Text r = scalar(d.value);
            names_[upper(d.name)].numeric = r.numeric;
            emit(d.name + " = " + r.s);
        }
    }

    void list(const Statement& st) {
        const std::string& w = st.keyword;
        if (w == "MASS") {
            if (st.items.empty()) fail(st.where, "MASS names no body or particle", "write MASS A = MA, P = MP");
            for (const Item& it : st.items) {
                const Entry* en = it.lhs.kind == Expr::Kind::name && !it.lhs.vector ? find(it.lhs.text) : nullptr;
                if (!en || (en->kind != Kind::body && en->kind != Kind::particle))
                    fail(it.where, "MASS takes a body or a particle before '='", "write MASS A = MA");
                if (!it.has_value) fail(it.where, "the mass of '" + it.lhs.text + "' is missing", "write MASS " + it.lhs.text + " = M");
                if (!it.unit.empty()) fail(it.where, "a unit in MASS", "give units in INPUT");
                emit("mass " + en->name + " = " + dimensioned(scalar(it.value), "m_" + en->name));
            }
            return;
        }
        if (w == "INERTIA") {
            if (st.items.size() != 4 && st.items.size() != 7)
                fail(st.where, "INERTIA takes a body and 3 or 6 measures, not " + std::to_string(st.items.empty() ? 0 : st.items.size() - 1),
                     "write INERTIA B, I11, I22, I33 [, I12, I23, I31]");
            const Item& b = st.items[0];
            if (b.lhs.kind == Expr::Kind::call)
                fail(b.where, "INERTIA about a point other than the mass centre ('" + b.lhs.text + "(...)') is not translated",
                     "give the central inertia: INERTIA " + b.lhs.text + ", I11, I22, I33");
            std::string body = body_name(b.lhs);
            std::vector<std::string> m;
            for (std::size_t i = 1; i < st.items.size(); ++i) {
                if (st.items[i].has_value || !st.items[i].unit.empty())
                    fail(st.items[i].where, "an inertia measure must be a scalar expression");
                m.push_back(dimensioned(scalar(st.items[i].lhs), "I" + std::to_string(i) + "_" + body));
            }
            emit("inertia " + body + " = " + join(m));
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
            }
            if (!it.unit.empty()) col += " in " + unit(it.unit, it.where);
            cols.push_back(col);
        }
        if (!cols.empty()) tail_outputs_.push_back("output " + join(cols));
    }

    void input(const Item& it) {
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

    std::string unit(const std::string& words, Location where) {
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

    void command(const Statement& st) {
        const std::string& w = st.keyword;
        if (w == "CODE") return code(st);
        static const char* const ignored[] = {"PAUSE", "SAVE", "AUTOZ", "AUTORHS", "AUTOEPS", "AUTOLEV", "OVERWRITE",
                                              "UNITSYSTEM", "UNITS", "DISPLAY", "ANIMATE", "ENCODE", "EXPLICIT",
                                              "PRINT", "RUN", "SHOW", "CLEAR", "DIGITS", "WRITE"};
        for (const char* x : ignored)
            if (w == x) return not_translated(st.where, w, "it changes how Autolev works or prints, not the model");
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

    void code(const Statement& st) {
        // CODE DYNAMICS() file.c
        std::string text = st.text;
        std::string kind = upper(text.substr(0, text.find_first_of("( \t")));
        if (kind != "DYNAMICS")
            return not_translated(st.where, "CODE " + kind, "only CODE DYNAMICS() has a counterpart (codegen)");
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

    Text scalar(const Expr& e) {
        Text t = expr(e);
        if (t.vector) fail(e.where, "a vector where a scalar is expected", "take a measure: DOT(v>, N1>)");
        return t;
    }
    Text vec(const Expr& e) {
        Text t = expr(e);
        if (!t.vector) fail(e.where, "a scalar where a vector is expected", "multiply by a unit vector such as N1>");
        return t;
    }

    void assignment(const Statement& st) {
        const Expr& lhs = st.lhs;
        if (lhs.kind == Expr::Kind::index) return array_assignment(st);
        if (lhs.kind != Expr::Kind::name)
            fail(lhs.where, "the left side of '=' must be a name", "write NAME = ..., NAME> = ... or Q1' = ...");
        if (lhs.vector) return vector_assignment(st);
        std::string key = upper(lhs.text);
        const Entry* en = find(lhs.text);
        if (lhs.primes > 0) {
            if (!en || en->kind != Kind::variable)
                fail(lhs.where, "'" + lhs.text + "' is not a variable, so '" + lhs.text + "'' cannot be assigned",
                     "declare it with VARIABLES or MOTIONVARIABLES");
            if (lhs.primes != 1)
                fail(lhs.where, "an equation for '" + lhs.text + std::string(static_cast<std::size_t>(lhs.primes), '\'') +
                                    "' is not translated", "kinematical equations give first derivatives: Q1' = U1");
            if (aliased_coordinates_.count(en->name)) return;  // Q1' = U1: U1 is written Q1'
            Text r = scalar(st.rhs);
            for (const KinematicEquation& k : kinematics_)
                if (k.coordinate == en->name)
                    fail(lhs.where, "a second kinematical equation for '" + lhs.text + "'", "give one for each coordinate");
            kinematics_.push_back({en->name, en->name + "' - " + (r.prec <= 1 ? "(" + r.s + ")" : r.s)});
            return;
        }
        if (key == "ZERO") {
            if (!is_fr_plus_frstar(st.rhs))
                fail(st.rhs.where, "ZERO is translated only as ZERO = FR() + FRSTAR()",
                     "Kane's equations are formed by ZERO = FR() + FRSTAR() and KANE()");
            if (!kane_at_) kane_at_ = model_.size(), emit("");
            kane_where_ = st.where;
            return;
        }
        if (en) {
            if (en->kind == Kind::variable) return kinematical_assignment(st, *en);
            if (en->kind == Kind::scalar) {
                Text r = scalar(st.rhs);
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
            if (!s) fail(lhs.where, "'" + lhs.text + "' is not a direction cosine matrix name",
                         "write N_A = [...] with two declared frames, or use SIMPROT");
            parent_[s->second] = s->first;
            return emit("rotate " + s->second + " from " + s->first + " dcm " + matrix(st.rhs));
        }
        Text r = scalar(st.rhs);
        const Entry& ne = add(lhs.text, Kind::scalar, lhs.where);
        names_[upper(lhs.text)].numeric = r.numeric;
        emit(ne.name + " = " + r.s);
    }

    // OMEGA = THETA': a kinematical equation written as an assignment, THETA' - OMEGA = 0
    void kinematical_assignment(const Statement& st, const Entry& speed) {
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
        kinematics_.push_back({q->name, q->name + "' - " + speed.name});
    }

    std::string matrix(const Expr& m) {
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

    static bool is_call(const Expr& e, const char* f) {
        return e.kind == Expr::Kind::call && e.args.empty() && upper(e.text) == f;
    }
    static bool is_fr_plus_frstar(const Expr& e) {
        return e.kind == Expr::Kind::binary && e.text == "+" &&
               ((is_call(e.args[0], "FR") && is_call(e.args[1], "FRSTAR")) ||
                (is_call(e.args[0], "FRSTAR") && is_call(e.args[1], "FR")));
    }

    void array_assignment(const Statement& st) {
        const Expr& lhs = st.lhs;
        std::string key = upper(lhs.text);
        if (key == "DEPENDENT") {
            if (lhs.args.size() != 1 || lhs.args[0].kind != Expr::Kind::number)
                fail(lhs.where, "DEPENDENT takes one index: DEPENDENT[1] = ...");
            constraints_.push_back(scalar(st.rhs).s);
            return;
        }
        if (key == "AUXILIARY")
            fail(lhs.where, "auxiliary speeds (AUXILIARY[...]) are not translated",
                 "Alembert's kane statement takes them as 'auxiliary u...'; add them by hand");
        fail(lhs.where, "the array '" + lhs.text + "[...]' is not translated",
             "name each element as a scalar of its own");
    }

    void vector_assignment(const Statement& st) {
        const Expr& lhs = st.lhs;
        std::string key = upper(lhs.text);
        if (lhs.primes) fail(lhs.where, "a prime on a vector name", "assign the vector itself");
        auto pt = [this](std::string_view n) { return point_of(n); };
        auto fr = [this](std::string_view n) { return frame_of(n); };
        auto bd = [this](std::string_view n) -> std::optional<std::string> {
            const Entry* en = find(n);
            if (en && (en->kind == Kind::body || en->kind == Kind::frame || en->kind == Kind::newtonian)) return en->name;
            return std::nullopt;
        };
        std::string_view name(lhs.text);
        const Entry* existing = find(lhs.text);
        if (!existing) {
            if (key.rfind("P_", 0) == 0)
                if (auto s = split(name.substr(2), pt, pt))
                    return emit("translate " + s->second + " from " + s->first + " by " +
                                dimensioned(vec(st.rhs), "r_" + s->second));
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

    // FORCE_P> = v> gives the force on P, FORCE_P> += v> adds v> to it (another load of the
    // script); a second FORCE_P> = would replace the first, which the script cannot say
    Text load_value(const Statement& st, const std::string& key) {
        if (st.compound == 0) {
            if (!assigned_loads_.insert(key).second)
                fail(st.lhs.where, "'" + st.lhs.text + ">' is assigned a second time, which replaces its first value",
                     "add to it with " + st.lhs.text + "> += v> (or FORCE(...), TORQUE(...)), or remove the first");
            return vec(st.rhs);
        }
        if (st.compound != '+' && st.compound != '-')
            fail(st.lhs.where, std::string("'") + st.compound + "=' on a force or torque is not translated",
                 "write the whole load: " + st.lhs.text + "> = ...");
        assigned_loads_.insert(key);
        Text v = vec(st.rhs.args[1]);
        if (st.compound == '-') v = {"-" + paren(v, 4), true, 3, v.numeric};
        return v;
    }

    std::string label(const std::string& base) {
        std::string l = base;
        for (int k = 2; labels_.count(l) || find(l); ++k) l = base + "_" + std::to_string(k);
        labels_.insert({l, 0});
        return l;
    }
    void force(const std::string& on, const std::optional<std::string>& from, const std::string& v) {
        std::vector<std::string> at{on};
        if (from) at.push_back(*from);
        for (const std::string& x : at)
            if (find(x) && find(x)->kind == Kind::point) forced_points_.emplace_back(x, statement_where_);
        std::string l = label("F_" + on);
        emit("force " + l + " on " + on + (from ? " from " + *from : "") + " = " + v);
    }
    void torque(const std::string& on, const std::optional<std::string>& from, const std::string& v) {
        std::string l = label("T_" + on);
        emit("torque " + l + " on " + on + (from ? " from " + *from : "") + " = " + v);
    }

    void expression_statement(const Statement& st) {
        const Expr& e = st.expr;
        if (e.kind != Expr::Kind::call) return emit(expr(e).s);
        std::string f = upper(e.text);
        auto nargs = [&](std::size_t n, const char* form) {
            if (e.args.size() != n)
                fail(e.where, e.text + "() takes " + std::to_string(n) + " arguments, not " + std::to_string(e.args.size()),
                     std::string("write ") + form);
        };
        if (f == "SIMPROT") {
            nargs(4, "SIMPROT(A, B, 3, Q1)");
            std::string a = frame_name(e.args[0]), b = frame_name(e.args[1]);
            std::string axis = simprot_axis(e.args[2], a, b);
            parent_[b] = a;
            return emit("rotate " + b + " from " + a + " about " + axis + " by " + scalar(e.args[3]).s);
        }
        if (f == "V2PTS" || f == "V1PT" || f == "A2PTS") {
            nargs(4, (e.text + "(N, B, P, Q)").c_str());
            std::string n = frame_name(e.args[0]), b = frame_name(e.args[1]);
            std::string p = point_name(e.args[2]), q = point_name(e.args[3]);
            std::string what = f == "A2PTS" ? "acceleration " : "velocity ";
            if (f == "V2PTS") {  // both points are fixed on B: forces there act on B
                for (const std::string& x : {p, q})
                    if (find(x) && find(x)->kind == Kind::point && !point_body_.count(x)) point_body_[x] = b;
            }
            return emit(what + q + " in " + n + " from " + p + (f == "V1PT" ? " moving on " : " fixed on ") + b);
        }
        if (f == "A1PT")
            fail(e.where, "A1PT() is not translated",
                 "Alembert forms accelerations from velocities; give V1PT() and leave the acceleration to it");
        if (f == "GRAVITY") {
            if (e.args.empty()) fail(e.where, "GRAVITY() needs the vector", "write GRAVITY(-G*N2>)");
            if (e.args.size() > 1)
                fail(e.args[1].where, "GRAVITY on some bodies only is not translated",
                     "Alembert's gravity acts on every body and particle; apply FORCE() to these instead");
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
            if (!e.args.empty())
                fail(e.args[0].where, "KANE() with arguments is not translated",
                     "declare the dependent speeds with CONSTRAIN(DEPENDENT[...]) and write KANE()");
            if (!kane_at_) kane_at_ = model_.size(), emit("");
            kane_where_ = st.where;
            return;
        }
        if (f == "CONSTRAIN") {
            for (const Expr& a : e.args) {
                if (a.kind != Expr::Kind::index || upper(a.text) != "DEPENDENT")
                    fail(a.where, "CONSTRAIN() is translated only as CONSTRAIN(DEPENDENT[U3, ...])",
                         "auxiliary speeds are not translated");
                for (const Expr& u : a.args) {
                    const Entry* en = u.kind == Expr::Kind::name && !u.vector && u.primes == 0 ? find(u.text) : nullptr;
                    if (!en || en->kind != Kind::variable)
                        fail(u.where, "DEPENDENT[...] lists speeds, declared with VARIABLES or MOTIONVARIABLES");
                    dependent_.push_back(en->name);
                }
            }
            if (constraints_.size() != dependent_.size())
                fail(e.where,
                     std::to_string(dependent_.size()) + " dependent speeds for " + std::to_string(constraints_.size()) +
                         " constraints (DEPENDENT[...] = ...)",
                     "give one DEPENDENT[i] = ... for each dependent speed, before CONSTRAIN");
            return;
        }
        emit(expr(e).s);
    }

    // Unit-less values: Autolev's numbers have no units, while Alembert checks that a mass is
    // a mass, a position a length, and so on. An expression of numbers alone (no constant or
    // variable, whose dimension is open) in such a place becomes a constant without a unit: a
    // number is the constant's value (MASS P = 2: m_P = 2), anything else is scaled by a
    // constant equal to 1 (P_O_P> = N1>: r_P*(Nx>) with r_P = 1).
    std::string dimensioned(const Text& t, const std::string& base) { return dimensioned_text(t, base).s; }
    Text dimensioned_text(const Text& t, const std::string& base) {
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

    // W_B_A> = w>: Alembert sets a frame's angular velocity in the frame it is oriented from
    // (its parent P), so in another frame A it becomes w> - W_P_A>
    void angular_velocity(const std::string& b, const std::string& a, const Text& w) {
        auto it = parent_.find(b);
        if (it == parent_.end() || it->second == a) return emit("angvel " + b + " in " + a + " = " + w.s);
        const std::string& p = it->second;
        emit("angvel " + b + " in " + p + " = " + w.s + " - angvel(" + p + ", " + a + ")");
    }

    std::string frame_or_body(const Expr& e) { return frame_name(e); }

    std::string simprot_axis(const Expr& ax, const std::string& a, const std::string& b) {
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

    // ---- the script -----------------------------------------------------------------------

    std::string kane_statement() {
        std::vector<std::string> coordinates, speeds, residuals;
        for (const KinematicEquation& k : kinematics_) {
            coordinates.push_back(k.coordinate);
            residuals.push_back(k.residual);
        }
        if (coordinates.empty()) {
            for (const std::string& v : variables_)
                if (!rate_of_.count(v) && !given_.count(v)) coordinates.push_back(v);
        } else {
            // the speeds are the variables the kinematical equations give the rates with
            for (const std::string& v : variables_)
                if (std::find(coordinates.begin(), coordinates.end(), v) == coordinates.end() && !given_.count(v))
                    speeds.push_back(v);
        }
        std::string name = "K";
        for (int k = 2; find(name) || labels_.count(name); ++k) name = "K" + std::to_string(k);
        kane_name_ = name;
        std::string s = "kane " + name + " for " + join(coordinates);
        if (!speeds.empty()) {
            s += " speeds " + join(speeds) + " \\\n  kinematics [" + join(residuals) + "]";
            if (!constraints_.empty())
                s += " \\\n  constraints [" + join(constraints_) + "] dependent " + join(dependent_);
        } else if (!constraints_.empty()) {
            report(Severity::error, kane_where_, "constraints (DEPENDENT[...]) without speeds are not translated",
                   "declare speeds U with MOTIONVARIABLES and kinematical equations Q1' = U1");
        }
        return s;
    }

    // true if the text `s` holds the name `n` as a whole word
    static bool mentions(const std::string& s, const std::string& n) {
        for (std::size_t at = s.find(n); at != std::string::npos; at = s.find(n, at + 1)) {
            auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
            bool starts = at == 0 || !word(s[at - 1]);
            bool ends = at + n.size() == s.size() || !word(s[at + n.size()]);
            if (starts && ends) return true;
        }
        return false;
    }

    // In a model with kinematical equations, a variable that is neither a coordinate nor in
    // any kinematical or constraint equation is no speed: Autolev takes it as a given function
    // of time, and so does the translation (a specified quantity; INPUT gives its value).
    void find_given_variables() {
        if (!kane_at_ || (kinematics_.empty() && rate_of_.empty())) return;
        for (const std::string& v : variables_) {
            if (rate_of_.count(v)) continue;
            bool coordinate = aliased_coordinates_.count(v) > 0, named = false;
            for (const KinematicEquation& k : kinematics_) {
                coordinate = coordinate || k.coordinate == v;
                named = named || mentions(k.residual, v);
            }
            for (const std::string& c : constraints_) named = named || mentions(c, v);
            if (coordinate || named) continue;
            given_.insert(v);
            const Entry* en = find(v);
            report(Severity::note, en ? en->where : kane_where_,
                   "'" + v + "' is neither a coordinate nor a speed (no kinematical equation names it); it is "
                   "declared as a specified quantity, a given function of time",
                   "give its value with INPUT " + v + " = ..., or a kinematical equation if it is a speed");
        }
    }

    void assemble() {
        find_given_variables();
        for (const auto& [p, where] : forced_points_) {
            auto it = point_body_.find(p);
            const Entry* body = it == point_body_.end() ? nullptr : find(it->second);
            if (!body || body->kind != Kind::body)
                report(Severity::error, where, "the force at point '" + p + "' acts on no body",
                       "Alembert applies forces at points fixed on a body: say which body '" + p +
                           "' is fixed on with V2PTS(N, B, O, " + p + "), or apply the force at a particle");
        }
        if (kane_at_) {
            if (!kinematics_.empty() && dependent_.size() != constraints_.size())
                report(Severity::error, kane_where_,
                       std::to_string(constraints_.size()) + " constraints (DEPENDENT[...] = ...) but " +
                           std::to_string(dependent_.size()) + " dependent speeds",
                       "name the dependent speeds with CONSTRAIN(DEPENDENT[U3, ...]) before KANE()");
            model_[*kane_at_] = kane_statement();
        }
        std::string& s = out_.script;
        s = "# " + file_ + ", translated from Autolev by alembert import\n";
        if (!newtonian_.empty()) s += "newtonian " + newtonian_ + "\n";
        for (const std::string& l : frames_lines_) {
            if (l.empty() || l[0] != '\x01') {
                s += l + "\n";
                continue;
            }
            // points: those fixed on a body (V2PTS) are declared on it
            std::vector<std::string> free;
            std::size_t b = 1;
            while (b <= l.size()) {
                std::size_t e = l.find('\x01', b);
                if (e == std::string::npos) e = l.size();
                std::string p = l.substr(b, e - b);
                b = e + 1;
                auto it = point_body_.find(p);
                const Entry* body = it == point_body_.end() ? nullptr : find(it->second);
                if (body && body->kind == Kind::body) s += "point " + p + " on " + body->name + "\n";
                else free.push_back(p);
            }
            if (!free.empty()) s += "point " + join(free) + "\n";
        }
        for (std::size_t g = 0; g < constants_.size(); ++g) {
            const auto& group = constants_[g];
            if (implicit_group_ && g == *implicit_group_ && !group.empty())
                s += "# declared by MASS and INERTIA, as in Autolev\n";
            // CONSTANTS L+, M: positive L, then constant M
            for (bool positive : {true, false}) {
                std::vector<std::string> parts;
                for (const ConstantDecl& c : group)
                    if (c.positive == positive)
                        parts.push_back(c.name + (c.value.empty() ? "" : " = " + c.value + c.unit));
                if (!parts.empty()) s += (positive ? "positive " : "constant ") + join(parts) + "\n";
            }
        }
        if (!time_unit_.empty())
            s += "# Autolev's time T is a number of seconds: t/" + time_unit_ + "\nconstant " + time_unit_ + " = 1 s\n";
        if (!extra_constants_.empty())
            s += "# numbers where Alembert needs a dimension, as constants without a unit\n"
                 "constant " + join(extra_constants_) + "\n";
        if (!rate_of_.empty()) {
            std::vector<std::string> said;
            for (const std::string& v : variables_)
                if (auto r = rate_of_.find(v); r != rate_of_.end()) said.push_back(v + " is " + r->second + "'");
            s += "# " + join(said) + " (kinematical equations " + rate_of_.begin()->second + "' = " +
                 rate_of_.begin()->first + ", ...): written as the rates, which simulate and codegen take as speeds\n";
        }
        if (!variables_.empty()) {
            std::vector<std::string> parts;
            for (const std::string& v : variables_) {
                if (given_.count(v) || rate_of_.count(v)) continue;
                // Kane's equations, their linearization and generated code take the second
                // derivatives of coordinates and the first of speeds: two primes serve both
                int p = std::max({primes_[v], used_primes_[v], 2});
                parts.push_back(v + std::string(static_cast<std::size_t>(p), '\''));
            }
            if (!parts.empty()) s += "variable " + join(parts) + "\n";
        }
        for (const std::string& v : variables_)
            if (given_.count(v)) specified_.push_back(v + std::string(static_cast<std::size_t>(std::max(primes_[v], used_primes_[v])), '\''));
        if (!specified_.empty()) s += "specified " + join(specified_) + "\n";
        for (const std::string& l : model_)
            if (!l.empty()) s += l + "\n";
        for (const std::string& n : initial_order_)
            if (given_.count(n) && std::find(tail_inputs_.begin(), tail_inputs_.end(), n + " = " + initial_[n]) == tail_inputs_.end())
                tail_inputs_.push_back(n + " = " + initial_[n]);
        if (!tail_inputs_.empty()) s += "input " + join(tail_inputs_) + "\n";
        if (!initial_order_.empty()) {
            std::vector<std::string> parts, seen;
            for (const std::string& n : initial_order_) {
                if (std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
                seen.push_back(n);
                if (given_.count(n)) continue;  // given above with `input`
                parts.push_back(n + " = " + initial_[n]);
            }
            if (!parts.empty()) s += "initial " + join(parts) + "\n";
        }
        for (const auto& [k, l] : tail_settings_) s += l + "\n";
        if (!abs_tol_.empty() || !rel_tol_.empty())
            s += "tolerance" + (abs_tol_.empty() ? "" : " abs " + abs_tol_) + (rel_tol_.empty() ? "" : " rel " + rel_tol_) + "\n";
        for (const std::string& l : tail_outputs_) s += l + "\n";
        for (const auto& [where, l] : tail_codegen_) {
            if (!kane_at_) {
                report(Severity::error, where, "CODE DYNAMICS() without KANE()",
                       "form Kane's equations (ZERO = FR() + FRSTAR(), KANE()) before generating code");
            } else if (!kinematics_.empty()) {
                // Alembert generates code with the coordinates' rates as the speeds
                not_translated(where, "CODE DYNAMICS()",
                               "Alembert's codegen takes the coordinates' rates as the speeds, and this model has "
                               "speeds of its own (kinematical equations such as " + kinematics_.front().coordinate +
                                   "' = ...)");
            } else {
                s += l + "\n";
            }
        }
    }

    std::string file_;
    AutolevTranslation out_{};
    std::vector<Diagnostic> pending_{};
    std::map<std::string, Entry> names_{};                  // key: upper case
    std::map<std::string, std::string> implicit_points_{};  // NO, BO (upper case) -> N_o, Bcm
    std::map<std::string, int> labels_{};
    std::set<std::string> assigned_loads_{};  // FORCE_P>, TORQUE_B> (upper case) assigned with '='
    std::map<std::string, std::string> point_body_{};  // point -> the body V2PTS fixes it on
    std::vector<std::pair<std::string, Location>> forced_points_{};
    Location statement_where_{};
    std::map<std::string, int> extra_names_{};
    std::vector<std::string> extra_constants_{};
    std::string time_unit_{};  // the constant 1 s that Autolev's time T is divided by  // numbers given a place with a dimension
    bool resolved_numeric_ = false;
    std::map<std::string, std::string> parent_{};  // frame -> the frame it is oriented from
    std::string newtonian_{};
    std::vector<std::string> frames_lines_{};
    std::vector<std::vector<ConstantDecl>> constants_{};
    std::map<std::string, std::pair<std::size_t, std::size_t>> constant_index_{};
    std::optional<std::size_t> implicit_group_{};  // the constants MASS and INERTIA declare
    std::vector<std::string> variables_{};
    std::set<std::string> given_{};
    std::map<std::string, std::string> rate_of_{};  // a speed that is a coordinate's rate -> the coordinate
    std::set<std::string> aliased_coordinates_{};  // variables that are no coordinate and no speed: specified
    std::map<std::string, int> primes_{}, used_primes_{};
    std::vector<std::string> specified_{};
    std::map<std::pair<int, int>, std::vector<Definition>> definitions_{};  // by the declaration's line, column
    std::vector<std::string> model_{};
    std::optional<std::size_t> kane_at_{};
    Location kane_where_{};
    std::string kane_name_{};
    std::vector<KinematicEquation> kinematics_{};
    std::vector<std::string> constraints_{}, dependent_{};
    std::map<std::string, std::string> initial_{};
    std::vector<std::string> initial_order_{};
    std::vector<std::string> tail_inputs_{}, tail_outputs_{};
    std::vector<std::pair<Location, std::string>> tail_codegen_{};
    std::map<std::string, std::string> tail_settings_{};
    std::string abs_tol_{}, rel_tol_{};
    int outputs_ = 0;
};

}  // namespace
}  // namespace autolev

AutolevTranslation translate_autolev(std::string_view source, const std::string& file) {
    return autolev::Translator(file).run(source);
}

}  // namespace alembert::lang
