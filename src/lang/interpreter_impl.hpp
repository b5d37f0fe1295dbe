// SPDX-License-Identifier: MIT
// The interpreter's state and the helpers its statement files share (private to src/lang).
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "alembert/alembert.hpp"
#include "alembert/biomech/model_markers.hpp"
#include "alembert/biomech/plate_load.hpp"
#include "alembert/lang/ast.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/lang/transcript.hpp"
#include "alembert/lang/units.hpp"

namespace alembert::lang {

/// A value of an expression: a scalar, a vector, a dyadic, an array of scalars or a matrix,
/// with the dimension of its measures.
struct Value {
    enum class Kind { scalar, vector, array, matrix, dyadic };
    Kind kind = Kind::scalar;
    ex s{};
    Vector v{};
    Dyadic d{};
    std::vector<ex> a{};
    Mat3 m{};  ///< a 3 by 3 matrix's entries (rotation, direction cosines), mirroring `a`
    int rows = 0, cols = 0;  ///< a matrix's size; its entries are `a`, row by row
    Dimension dim = Dimension::open();
};

/// The kind of a value as messages name it: "a scalar", "a vector", "an array", "a matrix",
/// "a dyadic".
const char* kind_name(Value::Kind k);

/// A matrix value of `rows` by `cols` entries given row by row (`m` set too when 3 by 3).
Value matrix_value(int rows, int cols, std::vector<ex> entries, Dimension dim);

/// True if a number in `e` is written with a unit (`2 kg * 9.81 m/s^2`).
bool carries_unit(const Expr& e);

/// A constant, variable, specified or unknown declared before `newtonian`, declared in the
/// model's symbol table when the model is made.
struct PendingSymbol {
    std::string keyword{};  ///< constant, positive, variable, specified or unknown
    Word name{};
    int primes = 0;
    std::optional<double> value{};
};

/// What a name of the script stands for.
enum class NameKind { frame, body, particle, point, system, symbol, value };

struct NameInfo {
    NameKind kind = NameKind::value;
    Location declared{};
};

/// The dimension and display unit of a declared symbol (by base name).
struct SymbolUnits {
    Dimension dim = Dimension::open();
    std::optional<Unit> display{};
};

/// A road-map of the script: its rows and the unknowns they were formed for.
struct ScriptRoadmap {
    std::vector<RoadmapRow> rows{};
};

/// What the simulation statements have set so far (initial, input, motion, final time,
/// output step, tolerance, output, stop).
struct NumberSettings {
    exmap initial{};                       ///< coordinate or rate -> SI value
    exmap inputs{};                        ///< load measure -> formula of t, q, q'
    std::map<std::string, ex> motion{};    ///< coordinate name -> formula of t (SI)
    exmap specified{};                     ///< specified symbol -> formula of t (q, q' for input)
    SimulationOptions options{};
    std::vector<OutputSpec> outputs{};
    std::vector<std::string> output_si_units{};  ///< per output: its SI unit ("" if open)
    std::vector<EventSpec> events{};
};

/// Equations of motion formed by `kane` or `lagrange`, kept for `linearize`: Kane's with
/// chosen speeds whole, or second-order residuals with their coordinates.
struct FormedEquations {
    std::vector<ex> residuals{};  ///< what the name holds (to detect a later reassignment)
    std::vector<TimeVariable> coordinates{};
    std::optional<KaneEquations> kane{};  ///< set for Kane's equations with chosen speeds
};

/// Inverse dynamics over a motion: from a `inverse` statement or `alembert inverse`.
struct InverseRequest {
    std::vector<ex> loads{};
    std::string motion_file{};  ///< a motion table; empty: the prescribed motion
    double cutoff_hz = 6.0;
    std::string unitless_unit{};  ///< how to read coordinate columns without a unit ("": refuse non-SI)
    Evaluation evaluation = Evaluation::automatic;
    std::string dir{};
    int line = 0;                 ///< the statement's line; 0: run from the command line
    std::vector<Word> plotted{};  ///< `plot` names; `plot none` is the single word none
    double body_mass_kg = 0;      ///< `per kg mass M`: loads and powers per kg of M (0: not asked)
    std::vector<ForcePlate> cycle_plates{};  ///< `cycles P, ...`: one foot's plates (none: no cycles)
};

/// What `inverse` wrote: the loads (per kg when asked) and the files, by name.
struct InverseOutputs {
    InverseAnalysisReport report{};
    std::vector<std::string> files{};  ///< beyond report's CSV and plot: .sto, kinematics, powers
    std::string power_note{};          ///< why powers were not written, if they were not
    Table results{};                   ///< every result column over time: loads, kinematics, powers
};

/// A model marker declared by `marker NAME on B at P`: its name in marker files, its body and
/// point.
struct ScriptMarker {
    Word name{};
    std::string body{};
    std::string point{};
    double weight = 1;  ///< w of w |p_model - p_measured|^2 in the inverse-kinematics fit
};

/// A force plate's record applied to a body by `plate NAME on B from "file.mot"`: the record
/// and the model's symbols it gives values to.
struct ScriptPlate {
    Word name{};
    ForcePlate record{};
    PlateSymbols symbols{};
};

/// A load along the line between two points (`spring`, `damper`, `attraction`): its direction
/// is P - Q over its length, undefined where the points coincide.
struct ScriptLineLoad {
    std::string kind{};  ///< the statement's keyword
    Word label{};
    const Point* P = nullptr;
    const Point* Q = nullptr;
};

/// Code generation: from a `codegen` statement or `alembert codegen`.
struct CodegenRequest {
    Word language{};
    std::vector<ex> loads{};  ///< empty: every load measure of the model
    std::string name{};       ///< empty: the script's name
    std::string dir{};
    std::vector<Word> jacobians{};  ///< points and bodies whose Jacobians are generated
    std::optional<Word> derivatives{};  ///< `derivatives`: of inverse and forward dynamics
};

struct Interpreter::Impl {
    Impl(std::ostream& out, std::ostream& err, bool echo) : transcript(out, echo), err(&err) {}

    Transcript transcript;
    std::ostream* err;
    std::optional<Diagnostic> last_error{};

    std::unique_ptr<System> sys{};
    std::map<std::string, NameInfo> names{};
    std::map<std::string, SymbolUnits> units{};
    std::map<std::string, Value> values{};  // scalars and arrays by name, vectors by "name>"
    std::map<std::string, BodySet> systems{};
    std::map<std::string, ScriptRoadmap> roadmaps{};
    std::map<std::string, FormedEquations> formed{};  ///< by name, from kane and lagrange
    std::vector<TimeVariable> coordinates{};
    bool coordinates_given = false;
    std::string last_roadmap{};
    NumberSettings numbers{};
    std::string output_dir = ".";     ///< where simulate, inverse and codegen write
    std::string base_dir{};           ///< the script's directory: paths it reads are relative to it
    std::string script_file{};        ///< as named in diagnostics
    std::string script_name = "model";  ///< the script's stem, naming the model in messages and files
    std::vector<std::string> including{};  ///< the files `include` is running, outermost first
    bool model_only = false;          ///< skip simulate, inverse and codegen
    std::string trial{};              ///< the trial of `alembert inverse --motion`, for "{trial}"
    /// The clauses of the script's `inverse` statement a model-only run keeps for run_inverse:
    /// per kg and cycles.
    InverseRequest script_inverse{};
    Evaluation evaluation = Evaluation::automatic;  ///< simulate's and inverse's without a clause
    std::size_t compile_limit = kCompileByDefaultLimit;  ///< the largest function compiled by default
    bool session = false;             ///< an interactive session: a constant may be given a new value
    std::vector<PendingSymbol> pending_symbols{};  ///< declared before newtonian
    /// What simulate and inverse computed, in run order, for the report.
    std::vector<ReportHistory> histories{};
    /// The equations kane and lagrange formed, in run order (a name formed again replaces its
    /// earlier set), for the report.
    std::vector<ReportEquationSet> formed_sets{};
    /// What solve, evaluate and linearize printed, in run order, for the report.
    std::vector<ReportResult> results{};
    /// What the sweep of the statement running computed (record_sweep), for its result.
    std::optional<ReportSweep> running_sweep{};
    /// The coordinates the last solve found or was given (its `at` values and the
    /// coordinates solved for) with the rates and specified quantities its `at` gives, where it
    /// was, and how many histories were recorded before it: the report draws its diagrams
    /// there unless a later motion or the report's `at` says otherwise.
    exmap solved_configuration{};
    int solved_line = 0;
    std::size_t solved_after_histories = 0;
    bool allow_outside_output = false;  ///< `to` may leave output_dir (--allow-outside-out)
    std::size_t max_terms = kDefaultMaxTerms;  ///< largest expansion expand/simplify may form
    std::size_t print_limit = kDefaultPrintLimit;  ///< larger equations go to a file, abbreviated
    std::vector<ScriptMarker> markers{};  ///< `marker` statements, in order
    std::vector<ScriptPlate> plates{};    ///< `plate` statements, in order
    std::vector<ScriptLineLoad> line_loads{};  ///< `spring`, `damper`, `attraction`, in order
    /// Where each frame was oriented (the `rotate` statement's target): a frame has one
    /// orientation, and a second `rotate` of it is refused rather than replacing the first.
    std::map<const Frame*, Word> oriented{};

    // ---- statements ------------------------------------------------------------------------
    /// Runs one parsed statement: its StatementSpec::run from the registry (statements.hpp),
    /// or an assignment or a printed expression.
    void execute(const Statement& s);
    // interpreter_equations.cpp
    void assign(const Statement& s);
    void show(const Statement& s);
    void roadmap(const Statement& s);
    void row(const Statement& s);
    void methods(const Statement& s);
    void solve(const Statement& s);
    void evaluate_statement(const Statement& s);

    // ---- numbers (interpreter_numbers.cpp) -------------------------------------------------
    void set_initial(const Statement& s);
    void set_inputs(const Statement& s);
    void set_prescribed_motion(const Statement& s);
    void set_times_and_tolerances(const Statement& s);
    void add_outputs(const Statement& s);
    void add_event(const Statement& s);
    void simulate(const Statement& s);
    /// The Kane's equations in generalized speeds (a kane statement with speeds and
    /// kinematics) that simulate and codegen take, with their name; nullptr when the script
    /// formed none. @throws ScriptError at `where` when it formed more than one.
    const KaneEquations* speed_equations(Location where, const char* statement, std::string* name = nullptr);
    void inverse(const Statement& s);
    void codegen(const Statement& s);
    void run_inverse(const InverseRequest& r, Location where);
    void run_codegen(const CodegenRequest& r, Location where);
    // inverse_results.cpp
    /// The loads of `samples` (calc_inverse_dynamics), each load's power (LoadRates), per kg
    /// when r.body_mass_kg is set, written to r.dir: the loads' CSV, plot and .sto, the
    /// coordinates with their rates and accelerations (kinematics.csv, .sto), the powers
    /// (powers.csv, .sto), and for a marker trial each marker's distance from the model's per
    /// frame (`marker_residuals`, not null: marker_residuals.csv, .sto).
    InverseOutputs write_inverse_results(const InverseDynamics& id, const MotionSamples& samples,
                                         const InverseRequest& r, const InverseAnalysisOptions& opts,
                                         const std::vector<TimeVariable>& q, Location where,
                                         const Table* marker_residuals = nullptr);
    /// The gait events of r.cycle_plates, and each complete cycle inside the results resampled
    /// onto 0-100 % (calc_cycle_table) as r.dir/cycle_K.csv, the events as gait_events.csv; the
    /// transcript's lines saying so.
    std::string write_gait_cycles(const InverseRequest& r, const Table& results, Location where);
    // inverse_motion.cpp
    /// The extension of a motion file `inverse` reads (".csv", ".mot", ".sto", ".trc").
    /// @throws alembert::ArgumentError naming the file and the formats it reads otherwise.
    std::string motion_format(const std::string& path) const;
    /// Per coordinate, the quantity its kinematics gives it where the script declares no unit:
    /// "angle" if it turns a frame of the model (a rotation), "length" if it turns none (a
    /// translation); "" where its declared unit says.
    std::vector<std::string> coordinate_quantities(const std::vector<TimeVariable>& q, Location where);
    std::vector<ReportUnitCheck> row_unit_checks(const System& sys, const std::vector<RoadmapRow>& rows,
                                                 const std::vector<TimeVariable>& q, Location where);
    /// The motion table of an OpenSim storage file (.mot, .sto) for the coordinates q: time and
    /// the coordinates' columns, inDegrees applied to the rotational ones only, short gaps filled
    /// and the time base checked (regularize_time_base); `note` says what was done, if anything.
    Table storage_motion_table(const std::string& path, const std::vector<TimeVariable>& q, Location where,
                               std::string& note);
    // statements_lab.cpp
    /// The coordinates over a marker trial (.trc) from the script's markers, and a note for
    /// the transcript (time base, fit to the model).
    MarkerCoordinates coordinates_from_markers(const std::string& path, const std::vector<TimeVariable>& q,
                                               Location where, std::string& note);
    /// coordinates_from_markers for a model whose markers move out of a plane: inverse
    /// kinematics over the markers' points (lab axes = N's axes, lab origin = N_o).
    MarkerCoordinates spatial_coordinates_from_markers(const MarkerTable& trial, const TimeBaseReport& base,
                                                       const std::vector<TimeVariable>& q, Location where,
                                                       std::string& note);
    /// The plates' records for the plate symbols of compiled equations (empty without plates).
    std::shared_ptr<PlateInputs> plate_inputs() const;
    // interpreter_report.cpp
    void report(const Statement& s);
    void latex(const Statement& s);
    exmap report_configuration(const Statement& s);
    /// Writes the report of the model so far into `dir`; returns the path of its index.html
    /// (of roadmap.tex with settings.latex_only).
    std::string write_report_to(const std::string& dir, const exmap& configuration, Location where,
                                const ReportSettings& settings = {});
    /// Records a table simulate or inverse wrote, with the motion behind it when known: the
    /// statement (`simulate`), its line (0: run from the command line) and the file written
    /// (named relative to the output directory in the history's title).
    void record_history(const std::string& statement, int line, const std::string& file,
                        const Table& table, const MotionSamples* motion,
                        const exmap& first_row_data = {});
    /// Keeps what a sweep computed (`table`: the swept value, then the series, one axis name
    /// each in `axes`) for the result of the statement running (`statement` at `line`) and the
    /// file written (empty: none), to be plotted under its text on the report's page.
    void record_sweep(const std::string& statement, int line, const std::string& file, const Table& table,
                      std::vector<std::string> axes);
    /// The file as the report names it: relative to the output directory when inside it.
    std::string report_file_name(const std::string& file) const;
    /// Keeps the coordinates a solve was given (`at`) or found (`xs`, `values`) for the
    /// report's diagrams, with the rates and specified quantities its `at` gives (symbols of
    /// `st`).
    void remember_solved_configuration(const SymbolTable& st, const exmap& at,
                                       const std::vector<ex>& xs,
                                       const std::vector<double>& values, int line);
    ex quantity_expression(const Quantity& q, const Dimension& expected, const std::string& what);
    bool is_coordinate(const ex& x, int order);
    std::string output_path(const Statement& s) const;
    /// Refuses a spring, damper or attraction whose end points coincide at the initial state
    /// (`at`: every coordinate and speed, t): its direction is 0/0 there.
    void check_line_loads_apart(const exmap& at, const std::vector<TimeVariable>& q) const;
    std::string input_path(const std::string& written) const;
    /// How statement `s` evaluates: its `compiled` or `tape` clause, else the run's default.
    Evaluation evaluation_of(const Statement& s) const;
    /// Native code through the codegen layer unless `e` is the tape; `why_not` gets the reason
    /// when it falls back to the tape.
    FunctionMaker function_maker(Evaluation e, std::string* why_not) const;
    /// What the transcript says of the evaluation ("" when there is nothing to say).
    static std::string evaluator_note(Evaluation e, const std::string& why_not);

    // ---- names and objects -----------------------------------------------------------------
    System& model(Location where);
    void declare_name(const Word& w, NameKind kind);
    /// Throws at the second of two equal names in a list ("'q' is listed twice"), with the
    /// hint "list each <what> once".
    static void require_each_once(const std::vector<Word>& list, const std::string& what);
    [[noreturn]] void undeclared(const Word& w, const std::string& wanted) const;
    Frame& frame(const Word& w);
    Point& point(const Word& w);
    Body& body(const Word& w);
    RigidBody& rigid_body(const Word& w);
    BodySet body_set(const Word& w);
    ex symbol(const Word& w, const std::string& wanted);
    TimeVariable variable(const Word& w);
    std::vector<TimeVariable> default_coordinates();
    Dimension symbol_dimension(const std::string& printed) const;
    std::optional<Unit> display_unit(const std::string& printed) const;
    std::string format_value(const std::string& printed, double si) const;
    exmap bindings(const std::vector<Binding>& list, const std::string& purpose);
    /// The value of `name = value` in SI; a value without a unit for a symbol declared in a
    /// unit that is not SI (qA in deg) is refused unless it is 0, never read as SI silently.
    double binding_value(const Binding& b, const std::string& what);
    double number_of(const Quantity& q, const Dimension& expected, const std::string& what,
                     Location where, Dimension* got = nullptr);

    // ---- expressions (interpreter_expr.cpp) ------------------------------------------------
    Value eval(const Expr& e);
    Value eval_call(const Expr& e);
    // ---- algebra in expressions (interpreter_algebra.cpp) ----------------------------------
    /// coef(), replace(), taylor(), factor(), floor(), exclude() and include().
    Value eval_algebra(const Expr& e);
    /// The declared symbol `e` names, or an error "f(): <role> must be a declared symbol".
    ex algebra_symbol(const Expr& e, const std::string& f, const std::string& role, Dimension* dim);
    // ---- matrices and polynomials (interpreter_matrix.cpp, interpreter_polynomial.cpp) -----
    /// transpose(), inv(), det(), diagmat(), element(), rows() and cols().
    Value eval_matrix(const Expr& e);
    /// eig() and eigvec() (interpreter_eigen.cpp).
    Value eval_eigen(const Expr& e);
    /// polynomial() and roots().
    Value eval_polynomial(const Expr& e);
    /// acc + v (acc - v when `subtract`), one of them a matrix: both matrices of one size.
    Value matrix_sum(Value acc, const Value& v, bool subtract, Location where);
    /// acc * v (acc / v when `divide`), one of them a matrix: a scalar times a matrix, a
    /// matrix divided by a scalar, or the product of matrices whose sizes fit.
    Value matrix_product(Value acc, const Value& v, bool divide, Location where);
    /// m^p, m a square matrix and p a whole number: m times itself p times (by squaring), the
    /// identity for 0, the inverse's power for p < 0 (m must not be singular).
    Value matrix_power(const Value& m, const Value& p, const Expr& base, const Expr& exponent);
    Value eval_name(const Expr& e);
    Value number_with_unit(const Expr& e, const ex& n);  ///< `0.1575 m`: n in SI, with its dimension
    Value eval_vector_name(const Expr& e);
    // ---- dyadics (interpreter_dyadic.cpp) --------------------------------------------------
    Value eval_dyadic_name(const Expr& e);
    /// outer(), unitdyadic(), inertia(), matrix(), vector(), and dot() of three arguments.
    Value eval_dyadic(const Expr& e);
    /// dot(x, y) with x or y a dyadic: D . v, v . D (a vector), or D . E (a dyadic).
    Value dyadic_dot(const Expr& e, const Value& x, const Value& y);
    /// dt(D>>, F): the time derivative of dyadic x in frame F.
    Value dyadic_dt(const Expr& e, const Value& x, Frame& F);
    /// acc + v (acc - v when `subtract`), one of them a dyadic: both dyadics.
    Value dyadic_sum(Value acc, const Value& v, bool subtract, Location where);
    /// acc * v (acc / v when `divide`), one of them a dyadic: a dyadic times or divided by a
    /// scalar.
    Value dyadic_product(Value acc, const Value& v, bool divide, Location where);
    ex scalar(const Expr& e, const Dimension& expected, const std::string& what);
    Vector vector(const Expr& e, const Dimension& expected, const std::string& what);
    std::vector<ex> array(const Expr& e, const std::string& what);
    void check_dimension(const Dimension& got, const Dimension& expected, const std::string& what,
                         Location where) const;
    /// The first number or name in `e` written in a unit that counts revolutions (Hz, rpm,
    /// rev), or nullptr: with pi beside it, a trigonometric argument would count 2*pi twice.
    const Expr* revolution_rate_in(const Expr& e) const;
    /// The monogram name of a kinematic call such as vel(Bcm, N) (v_Bcm_N>), or "".
    std::string monogram(const Expr& call) const;

    // ---- output ----------------------------------------------------------------------------
    std::string print(const Value& v) const;
    void print_equations(const std::string& name, const std::vector<ex>& eqs,
                         const std::vector<ex>& unknowns = {});
    /// Equations past print_limit: written abbreviated to NAME.txt in the output directory,
    /// labelled `labels[i]`; returns the transcript's summary. Empty when they are short
    /// enough to print whole.
    std::string format_readable_roadmap(const std::string& name, const System& m,
                                        std::vector<RoadmapRow> rows);
    std::string print_large(const std::string& name, const std::vector<std::string>& labels,
                            const std::vector<ex>& eqs, const std::vector<ex>& unknowns);
    std::string definitions_for(const Value& v) const;

    /// Runs `f`, turning library and GiNaC exceptions into a ScriptError at `where`.
    template <class F>
    auto guard(Location where, F&& f, const std::string& hint = "") -> decltype(f());
};

/// A library error's message as a script's user reads it: C++ function prefixes
/// ("Frame::orient_axis(): ") dropped, API advice ("call A.set_inertia(...)") written as the
/// statement to write ("inertia A = Ixx, Iyy, Izz"), option names as their statements.
std::string in_script_words(const std::string& library_message);

// ---- helpers of simulate and inverse (interpreter_numbers.cpp) ----------------------------
/// A table as transcripts print it: at most `max_rows` rows spread evenly, the last included.
std::string format_table(const Table& t, int digits, std::size_t max_rows = 11);
/// The `plot` clause of simulate and inverse: `plot none`, or columns of the table (its first,
/// the time, excepted).
PlotOptions plot_options_of(const Statement& s, const std::vector<std::string>& columns);
/// The files written, by name: the CSV, then the plot's.
std::string file_list(const PlotResult& plot, const std::string& csv);
/// The dimension of a constraint's residual from the dimensions of its symbols (open where a
/// symbol has none or a power is not an integer).
Dimension residual_dimension_of(const ex& e, const std::function<Dimension(const std::string&)>& of_symbol);

/// The hint for a unit of the wrong dimension: the units that fit, "write it in m/s^2 ...".
std::string unit_of_dimension_hint(const Dimension& expected);

/// The eigenvalues of the n by n matrix of `entries` (row by row), ascending, by Eigen; an
/// error at `where` saying "<what> are complex: 1 + 2i, ..." when any is not real.
std::vector<double> real_eigenvalues(const std::vector<double>& entries, int n, Location where,
                                     const std::string& what, const std::string& hint);
/// The real roots, ascending, of the polynomial k[0] x^n + ... + k[n] (k[0] != 0, n >= 1): the
/// eigenvalues of its companion matrix, each polished by Newton steps, a root next to a whole
/// number that is a root exactly taken as that number; complex roots are an error as in
/// real_eigenvalues.
std::vector<double> real_polynomial_roots(const std::vector<double>& k, Location where, const std::string& what,
                                          const std::string& hint);
/// Numbers as values: a whole number exact (2, not 2.0), others as doubles.
std::vector<ex> number_values(const std::vector<double>& xs);
/// A complex number as a transcript prints it: 1.5 + 2i, -1 - 0.5i (6 significant digits).
std::string format_complex(double re, double im);

/// What a kind of name is, for messages: "a frame", "a rigid body", ...
const char* kind_word(NameKind k);
/// " (line N)": where a name was declared, for messages.
std::string at_line(Location l);

/// A name as monograms print it: A_o -> Ao.
std::string monogram_part(const std::string& name);

template <class F>
auto Interpreter::Impl::guard(Location where, F&& f, const std::string& hint) -> decltype(f()) {
    try {
        return f();
    } catch (const ScriptError&) {
        throw;
    } catch (const InternalError&) {
        throw;
    } catch (const Error& e) {
        throw ScriptError(where, in_script_words(e.what()), hint);
    } catch (const std::exception& e) {
        throw ScriptError(where, "the computation failed: " + in_script_words(e.what()),
                          "check for a division by zero or a singular configuration at this point");
    }
}

}  // namespace alembert::lang
