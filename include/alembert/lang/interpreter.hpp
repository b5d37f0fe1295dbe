// SPDX-License-Identifier: MIT
// The interpreter of the Alembert language: runs statements against an alembert::System.
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/diagnostic.hpp"

namespace alembert {
class System;
}

namespace alembert::lang {

/// The default of Interpreter::set_print_limit(): equations past this many operations (written
/// out, the intermediates they reach counted once) go to a file, abbreviated.
inline constexpr std::size_t kDefaultPrintLimit = 20000;

/// The default of Interpreter::set_max_terms().
inline constexpr std::size_t kDefaultMaxTerms = 100000;

/// The default of Interpreter::set_compile_limit(): GCC -O2 takes about 0.4 ms per operation of
/// generated C (3 s for the KUKA arm's 8,000 operations; bench/README.md), so a function this
/// large takes about ten seconds to compile, against about a nanosecond per operation saved
/// per call over the tape.
inline constexpr std::size_t kCompileByDefaultLimit = 25000;

/// How `simulate` and `inverse` evaluate their equations (Interpreter::set_evaluation, the
/// statements' `compiled` and `tape` clauses).
enum class Evaluation {
    /// Compiled C code where a C compiler is found (CC, else cc) for every function of at
    /// most Interpreter::set_compile_limit() operations, the tape otherwise. The choice does not
    /// depend on whether the code was compiled before: a library is cached by a hash of its
    /// source, so only the first run of a model pays the compiler. The transcript names the
    /// reason when the tape is used.
    automatic,
    /// Compiled C code, and the transcript says so (or why the tape is used instead).
    compiled,
    /// The interpreted tape (alembert::CompiledExpressions): no compiler is run.
    tape,
};

/// How a run ended, as the command-line tool maps it to its exit status.
enum class RunStatus {
    ok = 0,              ///< every statement ran
    script_error = 1,    ///< a mistake in the script, or a library error it caused
    internal_error = 3,  ///< a bug in Alembert (alembert::InternalError)
};

/// Runs Alembert scripts. Each statement is parsed and then carried out by one call of the
/// library (docs/language.md gives the call of each statement); the interpreter keeps the
/// model (an alembert::System) and the names the script gave, across runs, so an interactive
/// session can feed it one statement at a time.
///
/// The interpreter never throws at the user: an error in a statement (lexical, syntactic, a
/// dimension mismatch, or an alembert::Error from the library) becomes a Diagnostic printed to
/// the error stream with the offending line and a caret, and run() stops there.
/// What a report shows beyond the model (the `report` statement's clauses, `alembert report`'s
/// options).
struct ReportSettings {
    bool latex_only = false;            ///< write roadmap.tex alone (`latex`, --latex)
    bool check = false;                 ///< compare the methods and reactions (`check`, --check)
    bool matrices = false;              ///< show M q'' = f (`matrices`, --matrices)
    bool plots = true;                  ///< plot the histories (`plot none`, --no-plots)
    std::vector<std::string> plotted{};  ///< the columns plotted (`plot qA, T_A`); empty: all
};

class Interpreter {
public:
    /// Transcripts go to `out`, diagnostics to `err`. With `echo`, statements are echoed.
    Interpreter(std::ostream& out, std::ostream& err, bool echo = true);
    ~Interpreter();
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;

    /// Echo statements (batch transcripts) or not (--quiet, interactive sessions).
    void set_echo(bool echo);
    /// Significant digits of printed numbers, 1 to 17 (6 by default; the `digits` statement
    /// changes it from where it stands). CSV files always hold numbers that read back exactly.
    /// @throws alembert::ArgumentError if `digits` is outside 1..17.
    void set_digits(int digits);

    /// Runs the statements of `source` (named `file` in diagnostics, its first line numbered
    /// `first_line`) until the end or the first error, which is printed to `err`.
    RunStatus run(std::string_view source, const std::string& file, int first_line = 1);

    /// The diagnostic of the last failed run, if the last run failed.
    const std::optional<Diagnostic>& last_error() const;

    /// The road-map table of the model: the last road-map the script formed, or else the
    /// planner's road-map for the declared coordinates and unknowns (the accelerations of the
    /// coordinates when no unknowns are declared); as JSON with `json`.
    /// @throws ScriptError if there is no model or nothing to plan.
    std::string roadmap_text(bool json);

    /// Where `simulate`, `inverse` and `codegen` write their files (default: the current
    /// directory); a statement's `to "dir"` is relative to it. Paths a script reads (`from
    /// "motion.csv"`) are relative to the script's own directory.
    void set_output_dir(const std::string& dir);
    /// With `allow`, a statement's `to "dir"` may name an absolute path or leave the output
    /// directory through ".." (`--allow-outside-out`); by default such a statement is refused.
    void set_allow_outside_output(bool allow);
    /// The largest number of terms `expand()` and `simplify()` may form (an upper bound
    /// estimated before expanding: multinomial counts for powers of sums); a larger expansion
    /// is refused with a script error instead of exhausting memory (`--max-terms`).
    void set_max_terms(std::size_t max_terms);
    /// Equations (kane, lagrange, road-maps, printed arrays) of more operations than `ops`,
    /// the intermediates they reach counted once, are not printed whole in the transcript: they
    /// go to NAME.txt in the output directory as MotionGenesis prints long results (numbered
    /// intermediates, each defined before its first use, lines of at most 100 characters), and
    /// the transcript says how many there are, in which unknowns, and where (`--print-limit`).
    void set_print_limit(std::size_t ops);
    /// How `simulate` and `inverse` statements without a `compiled` or `tape` clause evaluate
    /// their equations (default: Evaluation::automatic; `alembert run --tape`: the tape).
    void set_evaluation(Evaluation evaluation);
    /// The largest function (in operations after common-subexpression elimination) that
    /// Evaluation::automatic compiles; a larger one is evaluated on the tape unless the
    /// statement says `compiled` (default kCompileByDefaultLimit).
    void set_compile_limit(std::size_t operations);
    /// With `model_only`, run() builds the model and skips `simulate`, `inverse` and `codegen`
    /// (the `alembert inverse` and `alembert codegen` commands run the script this way).
    void set_model_only(bool model_only);
    /// The trial `alembert inverse SCRIPT --motion TRIAL` reads: a plate's file written
    /// "{trial}_grf.mot" is TRIAL's path without its extension, then "_grf.mot", so each trial of
    /// a batch reads its own force record. Set before run().
    void set_trial(const std::string& motion_path);
    /// With `session` (the interactive session), declaring a constant again gives it a new
    /// value: symbolic results keep the symbol and stand, numbers computed from now on use the
    /// new value, and the session says so. In a script a second declaration is an error.
    void set_session(bool session);
    /// Inverse dynamics of the model over the motion table `motion_csv` (relative to the
    /// current directory) for every load measure the script declares, written to the output
    /// directory as torques.csv and its plot: `alembert inverse`; the script's own `inverse`
    /// statement (skipped in model-only runs) gives its `per kg mass` and `cycles` clauses.
    /// `cutoff_hz` 0 turns the
    /// filter off; `evaluation` is how the equations are evaluated; `unitless_unit` (deg,
    /// rad, m, mm; empty: none) is how to read coordinate columns without a unit in the header
    /// (MotionFilterOptions::unitless_unit). Errors go to `err`.
    RunStatus run_inverse(const std::string& motion_csv, double cutoff_hz,
                          Evaluation evaluation = Evaluation::automatic,
                          const std::string& unitless_unit = "");
    /// Code for the model in `language` (c, cpp, matlab, python) written to the output
    /// directory, named `name` (empty: the script's name): `alembert codegen`.
    RunStatus run_codegen(const std::string& language, const std::string& name);
    /// The HTML report of the model run so far (the `report` statement's work) written to
    /// `dir`/index.html: `alembert report`; with `settings.latex_only` only `dir`/roadmap.tex
    /// (the `latex` statement's work). Errors go to `err`.
    RunStatus write_report(const std::string& dir, const ReportSettings& settings = {});
    /// The model built so far, or nullptr before `newtonian`.
    const System* system() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace alembert::lang
