// SPDX-License-Identifier: MIT
// The translator of Autolev statements into Alembert statements, private to src/lang/autolev:
// names and declarations (autolev_translator.cpp), expressions and vector names
// (autolev_expressions.cpp), statements (autolev_statements.cpp), the script (autolev_script.cpp).
#pragma once
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/parser.hpp"
#include "autolev_syntax.hpp"

namespace alembert::lang::autolev {

// What an Autolev name stands for.
enum class Kind { newtonian, frame, body, particle, point, constant, variable, specified, scalar, vector, matrix, dyadic };

inline const char* kind_word(Kind k) {
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
        case Kind::matrix: return "a matrix";
        case Kind::dyadic: return "a dyadic";
    }
    return "a name";
}

struct Entry {
    Kind kind = Kind::scalar;
    std::string name{};  // the Alembert spelling
    Location where{};
    bool numeric = false;  // a scalar or vector the file assigned from numbers alone
    std::string key{};     // the Autolev name in upper case
    int rows = 0, cols = 0;  // a matrix's size
    // an array the file assigns by element (ZERO[1] = ..., M[1, 2] = ...): each element a
    // scalar of the script, by its row and column; the whole matrix is written when it is used
    std::map<std::pair<int, int>, std::string> elements{};
    int indices = 0;          // 1 (ZERO[i]) or 2 (M[i, j]); 0: not assigned by element
    bool whole_written = false;  // the script's matrix holds the elements as they are now
};

// Frames, bodies, particles and points are named apart from values (constants, variables,
// scalars, vectors): Autolev lets a frame A and a variable A stand side by side.
inline bool is_object(Kind k) {
    return k == Kind::newtonian || k == Kind::frame || k == Kind::body || k == Kind::particle || k == Kind::point;
}

// A translated expression: its Alembert text, whether it is a vector, its precedence
// (1 sum, 2 product, 3 sign, 4 power, 5 atom).
struct Text {
    std::string s{};
    bool vector = false;
    int prec = 5;
    bool numeric = false;  // numbers and unit vectors only: no quantity with a dimension
    int rows = 0, cols = 0;  // a matrix's size (0: not a matrix; -1: known when the script runs)
    bool matrix() const { return rows != 0; }
    // both the rows and the columns known (POLYNOMIAL(P, X) is a row of a length not known)
    bool size_known() const { return rows > 0 && cols > 0; }
    bool dyadic = false;  // a dyadic (`vector` is then false)
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

// A statement that has no counterpart in the script (as opposed to input that cannot be read or
// cannot mean anything): it is left out with a warning and a comment in the script, and the
// statements after it that use what it defined are left out too (autolev_left_out.cpp).
class LeftOut : public ScriptError {
public:
    using ScriptError::ScriptError;
};

// The names one statement uses (as written, where) and those it defines or changes (upper
// case): found once per statement, before translating, so that a statement using a name a
// left-out statement defined is found by lookups, not rescans.
struct NameUse {
    std::string key{};
    std::string said{};
    Location where{};
};
struct StatementNames {
    std::vector<NameUse> uses{};
    std::vector<std::string> defines{};
};

struct KinematicEquation {
    std::string coordinate{};
    std::string residual{};
    Location where{};
};

// Translates one Autolev file: declarations first (they may come in any order), then each
// statement in the file's order, then the script assembled from the parts.
class Translator {
public:
    explicit Translator(std::string file) : file_(std::move(file)) {}

    AutolevTranslation run(std::string_view source);

private:
    // ---- diagnostics ----------------------------------------------------------------------

    void report(Severity s, Location where, std::string message, std::string hint = "") {
        out_.diagnostics.push_back({s, file_, where, std::move(message), std::move(hint)});
    }
    [[noreturn]] static void fail(Location where, const std::string& message, const std::string& hint = "") {
        throw ScriptError(where, message, hint);
    }
    [[noreturn]] static void leave_out(Location where, const std::string& reason, const std::string& hint = "") {
        throw LeftOut(where, reason, hint);
    }
    void not_translated(Location where, const std::string& what, const std::string& why) {
        report(Severity::warning, where, what + " is not translated: " + why,
               "the statement is left out of the Alembert script; write its counterpart by hand if needed");
    }

    // ---- names ----------------------------------------------------------------------------

    std::string alembert_spelling(const std::string& name, Location where);

    const Entry& add(const std::string& name, Kind kind, Location where);

    // the value named `name` (Autolev's spelling, any case), else the frame, body, particle
    // or point
    const Entry* find(std::string_view name) const {
        auto it = names_.find(upper(name));
        return it == names_.end() ? find_object(name) : &it->second;
    }
    const Entry* find_object(std::string_view name) const {
        auto it = objects_.find(upper(name));
        return it == objects_.end() ? nullptr : &it->second;
    }
    // the frame, body, particle or point spelt `name` in the script
    const Entry* object_spelt(const std::string& name) const {
        for (const auto& [k, e] : objects_)
            if (e.name == name) return &e;
        return nullptr;
    }

    // the expanded names of a declarator: Q{3} -> Q1, Q2, Q3; C{2,2} -> C11, C12, C21, C22
    static std::vector<std::string> expand(const Declarator& d) {
        if (d.last < d.first) return {d.name};
        std::vector<std::string> v;
        for (int i = d.first; i <= d.last; ++i) {
            if (d.last2 < d.first2) {
                v.push_back(d.name + std::to_string(i));
                continue;
            }
            for (int j = d.first2; j <= d.last2; ++j) v.push_back(d.name + std::to_string(i) + std::to_string(j));
        }
        return v;
    }

    void declare(const Statement& st);

    // Autolev declares a name that MASS or INERTIA gives alone (MASS A = MA, INERTIA B, I1,
    // I2, I3) and that no declaration names as a constant; so does the translation.
    void implicit_constants(const Statement& st);

    // Speeds that are a coordinate's rate (Q1' = U1, or OMEGA = THETA') are written as that rate
    // (U1 as Q1', U1' as Q1''), so that Kane's equations are in the coordinates' rates, as
    // Alembert's simulate and codegen take them. Only when every kinematical equation has this
    // form and the model has no constraints; otherwise the speeds stay speeds.
    void find_rate_speeds(const ParsedFile& parsed);

    // A file of kinematics alone (no NEWTONIAN, no masses, loads or equations of motion): its
    // first frame becomes the script's Newtonian frame, which Alembert needs first.
    void frame_as_newtonian(const ParsedFile& parsed);

    static std::string join(const std::vector<std::string>& v, const char* sep = ", ") {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
        return s;
    }

    // ---- expressions ----------------------------------------------------------------------

    // a plain number (with its sign), as Alembert reads it
    std::string number_text(const Expr& e, const std::string& what);

    static std::string paren(const Text& t, int need) { return t.prec < need ? "(" + t.s + ")" : t.s; }

    Text expr(const Expr& e);

    // A chain of operators (a + b + c ..., read as ((a + b) + c) ...) is translated along its
    // left operands by iteration, so that a chain of any length needs no deeper stack.
    Text binary(const Expr& e);
    // `a op b` from the translations of a and b (a's text is moved, not copied, so that a
    // long chain costs time in proportion to its length)
    Text combine(const Expr& e, Text a, Text b);

    Text call(const Expr& e);
    Text call_text(const Expr& e, bool& numeric);

    std::string scalar_name(const Expr& e);

    // x = v of REPLACE, EVALUATE and TAYLOR: x a constant, variable or specified quantity
    std::string substitution(const Expr& e, const std::string& f);
    // a name no entry, extra name or word of the language takes: base, base_2, ...
    std::string fresh_name(const std::string& base);
    // SOLVE(M, X1, X2): `solve M for X1, X2 as X1_solved, X2_solved`, and X1 written as
    // X1_solved from there on
    void solve_statement(const Expr& e);

    // ---- frames, points and vectors -------------------------------------------------------

    std::optional<std::string> frame_of(std::string_view name) const {
        const Entry* en = find_object(name);
        if (en && (en->kind == Kind::newtonian || en->kind == Kind::frame || en->kind == Kind::body)) return en->name;
        return std::nullopt;
    }
    std::optional<std::string> point_of(std::string_view name) const {
        const Entry* en = find_object(name);
        if (en && (en->kind == Kind::point || en->kind == Kind::particle)) return en->name;
        auto it = implicit_points_.find(upper(name));
        if (!en && it != implicit_points_.end()) return it->second;
        return std::nullopt;
    }
    std::string frame_name(const Expr& e);
    std::string point_name(const Expr& e);
    std::string body_name(const Expr& e);

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
    std::string vector_name(const Expr& e);

    // ---- statements -----------------------------------------------------------------------

    void emit(std::string line) { model_.push_back(std::move(line)); }

    void translate(const Statement& st);

    // SPECIFIED F = -K*X: F is assigned where it is declared, so the statements before it
    // that use it are reported by the script, not given another meaning
    void definitions(const Statement& st);

    void list(const Statement& st);

    void input(const Item& it);

    std::string unit(const std::string& words, Location where);

    void command(const Statement& st);

    void code(const Statement& st);

    // DEGREES ON (Autolev's default): an angle written with numbers alone is in degrees.
    Text angle(const Expr& e, Text t, const std::string& where_used);
    void number_of_degrees_refused(const Expr& e, const std::string& f);

    Text scalar(const Expr& e) {
        Text t = expr(e);
        if (t.vector) fail(e.where, "a vector where a scalar is expected", "take a measure: DOT(v>, N1>)");
        if (t.matrix())
            fail(e.where, "a matrix where a scalar is expected", "take an element: M[i, j] or ELEMENT(M, i, j)");
        if (t.dyadic) not_a_dyadic(e, "a scalar");
        return t;
    }
    Text vec(const Expr& e) {
        Text t = expr(e);
        if (t.dyadic) not_a_dyadic(e, "a vector");
        if (!t.vector)
            fail(e.where, std::string("a ") + (t.matrix() ? "matrix" : "scalar") + " where a vector is expected",
                 "multiply by a unit vector such as N1>");
        return t;
    }

    void assignment(const Statement& st);

    // OMEGA = THETA': a kinematical equation written as an assignment, THETA' - OMEGA = 0
    void kinematical_assignment(const Statement& st, const Entry& speed);

    // X'' = f (or V' = f with X' = V): a model given by its differential equations. Each such
    // X is the coordinate of a particle of unit mass on the Newtonian x axis pushed by the
    // force f*Nx>, whose Kane equation f - 1*X'' = 0 is the file's equation itself.
    void differential_equation(const Statement& st, const Entry& v);
    // a model given by differential equations has no bodies, particles, gravity or KANE()
    // of its own, and every variable has its equation
    void check_differential_model();

    std::string matrix(const Expr& m);

    // M = [a, b; c, d] with M no direction cosine matrix: a matrix value, used by its
    // elements M[i, j] (M[i] of a row or a column)
    void matrix_assignment(const Statement& st);
    Text matrix_element(const Expr& e, const Entry& m);
    // an Autolev matrix function (TRANSPOSE, INV, DET, DIAGMAT, ELEMENT, ROWS, COLS, EIG,
    // POLYNOMIAL, ROOTS), or nothing if `f` is none
    std::optional<Text> matrix_call(const Expr& e, const std::string& f, bool& numeric);
    // a matrix literal [a, b; c, d] inside an expression
    Text matrix_literal(const Expr& m);
    // EXCLUDE(E, X, ...) and INCLUDE(E, X, ...) (autolev_algebra.cpp), or nothing if `f` is
    // neither
    std::optional<Text> term_call(const Expr& e, const std::string& f, bool& numeric);
    // EIG(M, VALUES, VECTORS), a statement: VALUES = eig(M) and VECTORS = eigvec(M); EIG(M,
    // VALUES) the eigenvalues alone
    void eig_statement(const Expr& e);
    // a whole number written in the file (a size or an index), or an error naming `what`
    int whole_number(const Expr& e, const std::string& what);

    static bool is_call(const Expr& e, const char* f) {
        return e.kind == Expr::Kind::call && e.args.empty() && upper(e.text) == f;
    }
    static bool is_fr_plus_frstar(const Expr& e) {
        return e.kind == Expr::Kind::binary && e.text == "+" &&
               ((is_call(e.args[0], "FR") && is_call(e.args[1], "FRSTAR")) ||
                (is_call(e.args[0], "FRSTAR") && is_call(e.args[1], "FR")));
    }

    // ZERO[1] = e (M[1, 2] = e): the element a scalar of the script, ZERO_1 = e (autolev_arrays.cpp)
    void array_assignment(const Statement& st);
    // the row and column of ZERO[i] (a column) or M[i, j], whole numbers written in the file
    std::pair<int, int> array_index(const Expr& e, const Entry& m);
    // ZERO[i] of an array assigned by element: its element's scalar
    Text array_element(const Expr& e, const Entry& m);
    // the array assigned by element, used whole: `ZERO = [ZERO_1; ZERO_2]` written before the
    // statement (unless written already since its last element), and its name
    Text whole_array(const Expr& e, const Entry& m);

    void vector_assignment(const Statement& st);

    // FORCE_P> = v> gives the force on P, FORCE_P> += v> adds v> to it (another load of the
    // script); a second FORCE_P> = would replace the first, which the script cannot say
    Text load_value(const Statement& st, const std::string& key);

    std::string label(const std::string& base);
    void force(const std::string& on, const std::optional<std::string>& from, const std::string& v);
    void torque(const std::string& on, const std::optional<std::string>& from, const std::string& v);

    void expression_statement(const Statement& st);

    // Unit-less values: Autolev's numbers have no units, while Alembert checks that a mass is
    // a mass, a position a length, and so on. An expression of numbers alone (no constant or
    // variable, whose dimension is open) in such a place becomes a constant without a unit: a
    // number is the constant's value (MASS P = 2: m_P = 2), anything else is scaled by a
    // constant equal to 1 (P_O_P> = N1>: r_P*(Nx>) with r_P = 1).
    std::string dimensioned(const Text& t, const std::string& base) { return dimensioned_text(t, base).s; }
    Text dimensioned_text(const Text& t, const std::string& base);

    // W_B_A> = w>: Alembert sets a frame's angular velocity in the frame it is oriented from
    // (its parent P), so in another frame A it becomes w> - W_P_A>
    void angular_velocity(const std::string& b, const std::string& a, const Text& w);

    std::string frame_or_body(const Expr& e) { return frame_name(e); }

    std::string simprot_axis(const Expr& ax, const std::string& a, const std::string& b);

    // ---- dyadics (autolev_dyadics.cpp) ----------------------------------------------------

    // ---- inertia about another point (autolev_statements.cpp) ------------------------------

    // true if positions the file gave join points a and b, directly or through others
    bool located(const std::string& a, const std::string& b) const;
    // the `inertia B = ... about P` of INERTIA B(P) whose mass and position are now given,
    // written here: the script moves the inertia to the mass centre where it stands
    void release_inertias();
    // the error for `what` (KANE(), the inertia of B) needing an inertia still waiting
    void need_placed_inertia(Location where, const std::string& what, const std::string& body = "");

    // D>> assigned, 1>>, 0>>, or I_B_P>> (B's inertia about P, or a particle's about P)
    Text dyadic_name(const Expr& e);
    // D>> = ...: a dyadic of the script
    void dyadic_assignment(const Statement& st);
    // `a op b` with a or b a dyadic, or a>*b> (the dyad, Autolev's product of two vectors)
    Text dyadic_combine(const Expr& e, Text a, Text b);
    // DOT(a, b) with a or b a dyadic (D>> . v> or v> . D>>, a vector; D>> . E>>, a dyadic)
    Text dyadic_dot(const Expr& e, const Text& a, const Text& b);
    // MATRIX(A, v>), MATRIX(A, D>>), VECTOR(A, M) and INERTIA(O, ...), or nothing if `f` is
    // none of them
    std::optional<Text> dyadic_call(const Expr& e, const std::string& f, bool& numeric);
    // unitdyadic(N), N the Newtonian frame (or the first frame)
    std::string unit_dyadic(const Expr& e);
    // the inertia dyadic of body or particle `b` about point `p`
    Text inertia_about(const Expr& e, const std::string& b, const std::string& p);
    // the error for a dyadic where `wanted` (a scalar, a vector) stands
    [[noreturn]] static void not_a_dyadic(const Expr& e, const std::string& wanted) {
        fail(e.where, "a dyadic where " + wanted + " is expected",
             wanted == "a scalar" ? "take a measure: DOT(N1>, DOT(D>>, N1>))" : "dot it with a vector: DOT(D>>, v>)");
    }

    // ---- statements left out (autolev_left_out.cpp) ---------------------------------------

    // the names each statement uses and defines, in the file's order
    static std::vector<StatementNames> index_names(const ParsedFile& parsed);
    // the state a left-out statement is rolled back to
    struct Journal {
        std::size_t model = 0, diagnostics = 0, extra_constants = 0, renames = 0;
        std::string time_unit{};
    };
    Journal open_journal();
    // the first name in `e` that a left-out statement defined, if any
    std::optional<NameUse> left_out_use(const Expr& e) const;
    void roll_back(const Journal& j);
    // translates `st`, or leaves it out (with what it defines) if it uses a name a statement
    // before it left out, or if it has no counterpart
    void translate_or_leave_out(const Statement& st, const StatementNames& names);
    // the warning, the script's comment and the names made unknown of a statement left out
    // whole (`part` false) or in part
    void record_left_out(const Statement& st, Location where, const std::string& reason, const std::string& hint,
                         const std::vector<std::string>& defines, bool part);
    // true if leaving `st` out changes the model's equations of motion (a mass, a load, a
    // rotation, a velocity, a constraint)
    bool shapes_model(const Statement& st) const;
    // the model's equations, said plainly if what was left out changes them or leaves no model
    void say_model_changes();

    // ---- the script -----------------------------------------------------------------------

    std::string kane_statement();

    // true if the text `s` holds the name `n` as a whole word
    static bool mentions(const std::string& s, const std::string& n);

    // In a model with kinematical equations, a variable declared and used without derivatives
    // that is neither a coordinate nor in any kinematical or constraint equation is no speed:
    // Autolev takes it as a given function of time, and so does the translation (a specified
    // quantity; INPUT gives its value).
    void find_given_variables();

    void assemble();

    std::string file_;
    AutolevTranslation out_{};
    // statements left out: the names they defined (upper case) -> the line that left them out
    std::map<std::string, int> left_out_names_{};
    std::vector<std::pair<std::string, bool>> added_{};  // names add() declared in this statement (key, object)
    std::vector<std::string> wholes_written_{};          // arrays written whole in this statement
    std::vector<std::pair<int, std::string>> model_changes_{};  // left-out lines that change the equations
    std::vector<int> dynamics_left_out_{};  // left-out lines that gave equations of motion
    std::set<std::string> odes_left_out_{};  // variables whose X'' = f was left out
    std::set<std::string> model_warnings_{};  // the warnings on the model as a whole (no line left out)
    std::map<std::pair<int, int>, std::vector<std::string>> part_comments_{};  // declarations left out in part
    // CONSTRAIN(DEPENDENT[Q1']) in a model without speeds: each coordinate's speed (q -> u = q')
    std::vector<std::pair<std::string, std::string>> rate_speeds_{};
    std::vector<Diagnostic> pending_{};
    std::map<std::string, Entry> names_{};                  // key: upper case
    std::map<std::string, Entry> objects_{};               // frames, bodies, particles, points
    std::vector<std::string> renames_{};  // the script's comments on names renamed
    std::map<std::string, std::string> implicit_points_{};  // NO, BO (upper case) -> N_o, Bcm
    std::map<std::string, int> labels_{};
    std::set<std::string> assigned_loads_{};  // FORCE_P>, TORQUE_B> (upper case) assigned with '='
    std::map<std::string, std::string> point_body_{};  // point -> the body V2PTS fixes it on
    std::vector<std::pair<std::string, Location>> forced_points_{};
    std::set<std::string> massive_{};  // bodies and particles MASS gave a mass, so far
    // points joined by a position P_O_Q> so far (both ways)
    std::map<std::string, std::set<std::string>> joined_{};
    // INERTIA B(P) waiting for MASS B and the position of B's mass centre from P
    struct WaitingInertia {
        std::string line{};   // the script's `inertia B = ... about P`
        std::string about{};  // P
        Location where{};
        std::string said{};  // B(P) as the file writes it
    };
    std::map<std::string, WaitingInertia> inertia_waiting_{};
    Location statement_where_{};
    std::map<std::string, int> extra_names_{};
    std::map<std::string, std::string> solved_{};  // X (with its primes) SOLVE assigned -> its value's name
    std::vector<std::string> extra_constants_{};
    std::string time_unit_{};  // the constant 1 s that Autolev's time T is divided by  // numbers given a place with a dimension
    bool resolved_numeric_ = false;
    std::map<std::string, std::string> parent_{};  // frame -> the frame it is oriented from
    std::string newtonian_{};
    std::vector<std::string> frames_lines_{};
    std::vector<std::vector<ConstantDecl>> constants_{};
    std::map<std::string, std::pair<std::size_t, std::size_t>> constant_index_{};
    std::optional<std::size_t> implicit_group_{};
    std::set<std::string> assigned_{};  // names the file assigns (upper case): no implicit constants  // the constants MASS and INERTIA declare
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
    std::vector<std::pair<std::string, Location>> odes_{};  // X of X'' = f, in the file's order
    std::set<std::string> ode_particles_{};
    std::string ode_mass_{};
    bool has_gravity_ = false;
    std::vector<std::string> constraints_{}, dependent_{};  // dependent_: U3, or Q1' (a rate)
    std::vector<Location> dependent_where_{};
    std::optional<Location> constraints_where_{};  // the first DEPENDENT[i] = ...
    // AUXILIARY[i] = E, CONSTRAIN(AUXILIARY[U, ...]) and KANE(F1, ...): constraints that hold in
    // the motion but not in the partial velocities of the speeds listed, and the load measures
    // their equations determine (Kane & Levinson 1985, sec. 5.7)
    std::vector<std::pair<std::string, Location>> aux_constraints_{};
    std::vector<std::string> aux_speeds_{};
    std::vector<std::pair<std::string, Location>> kane_forces_{};
    std::vector<std::string> aux_opened_{};  // the speeds that open a constraint E (not a speed itself)
    std::map<std::string, std::string> initial_{};
    std::vector<std::string> initial_order_{};
    std::vector<std::string> tail_inputs_{}, tail_outputs_{};
    std::vector<std::pair<Location, std::string>> tail_codegen_{};
    std::map<std::string, std::string> tail_settings_{};
    std::string abs_tol_{}, rel_tol_{};
    int outputs_ = 0;
    bool degrees_ = true;  // Autolev's DEGREES, ON unless the file says OFF
};

}  // namespace alembert::lang::autolev
