// SPDX-License-Identifier: MIT
// The `alembert` command-line tool: argument parsing, batch runs and the interactive session.
// No mechanics here: scripts go to alembert::lang::Interpreter.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "alembert/cleanup.hpp"
#include "batch_inverse.hpp"
#include "alembert/error.hpp"
#include "alembert/lang/autolev_import.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/lang/lexer.hpp"
#include "alembert/lang/statements.hpp"

#ifdef ALEMBERT_HAVE_LIBEDIT
#include <editline/readline.h>
#endif

namespace {

using alembert::lang::Interpreter;
using alembert::lang::RunStatus;

// exit statuses: 0 success, 1 script error, 2 usage error, 3 internal error
constexpr int kOk = 0, kScriptError = 1, kUsageError = 2, kInternalError = 3;
constexpr std::size_t kMaxScriptBytes = 64u << 20;

int exit_status(RunStatus s) {
    switch (s) {
        case RunStatus::ok: return kOk;
        case RunStatus::script_error: return kScriptError;
        case RunStatus::internal_error: return kInternalError;
    }
    return kInternalError;
}

// reads FILE, or standard input for "-"; false (and a message) if it cannot
bool read_script(const std::string& path, std::string& text) {
    std::istream* in = &std::cin;
    std::ifstream file;
    if (path != "-") {
        if (std::filesystem::is_directory(path)) {
            std::cerr << "alembert: '" << path << "' is a directory, not a script\n";
            return false;
        }
        // a lab or motion file given where the script goes: say what reads it
        const std::string ext = std::filesystem::path(path).extension().string();
        if (ext == ".trc" || ext == ".mot" || ext == ".sto" || ext == ".csv" || ext == ".c3d") {
            std::cerr << "alembert: '" << path << "' is a data file (" << ext
                      << "), not a script; a script reads it: inverse for T_A from \"" << path
                      << "\" (or alembert inverse SCRIPT --motion " << path << ")\n";
            return false;
        }
        file.open(path, std::ios::binary);
        if (!file) {
            std::cerr << "alembert: cannot open '" << path << "': " << std::strerror(errno) << "\n";
            return false;
        }
        in = &file;
    }
    std::ostringstream buf;
    char chunk[65536];
    while (in->read(chunk, sizeof chunk) || in->gcount() > 0) {
        buf.write(chunk, in->gcount());
        if (static_cast<std::size_t>(buf.tellp()) > kMaxScriptBytes) {
            std::cerr << "alembert: '" << path << "' is larger than 64 MiB\n";
            return false;
        }
    }
    text = buf.str();
    return true;
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

// the output directory exists (or is created) and takes files; false (and a message) if not,
// before any work starts
bool check_output_dir(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        std::cerr << "alembert: --out '" << dir << "' is not a directory; name a directory to write into\n";
        return false;
    }
    fs::create_directories(dir, ec);
    if (ec) {
        std::cerr << "alembert: --out '" << dir << "': cannot create the directory (" << ec.message()
                  << "); choose a place you can write to\n";
        return false;
    }
    // a probe file, removed at once: permissions alone do not tell (root, read-only mounts)
    std::string probe = (fs::path(dir) / ".alembert-probe-XXXXXX").string();
    const int fd = ::mkstemp(probe.data());
    if (fd < 0) {
        std::cerr << "alembert: --out '" << dir << "': cannot write there (" << std::strerror(errno)
                  << "); choose a place you can write to\n";
        return false;
    }
    ::close(fd);
    ::unlink(probe.c_str());
    return true;
}

// a count of 1 or more, said in words (CLI::PositiveNumber prints the range of a double,
// 0.000000 to 1.8e308 written out in 309 digits)
CLI::Validator count_of_one_or_more() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            std::size_t used = 0;
            unsigned long long n = 0;
            try {
                n = std::stoull(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used == 0 || used != text.size() || text[0] == '-' || n < 1)
                return "'" + text + "' is not a count: give a whole number, 1 or more (e.g. 100000)";
            return "";
        },
        "COUNT >= 1");
}

// a number of 0 or more, said in words (CLI::NonNegativeNumber prints a 309-digit range)
CLI::Validator number_of_zero_or_more() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            std::size_t used = 0;
            double x = -1;
            try {
                x = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used == 0 || used != text.size() || !(x >= 0) || !std::isfinite(x))
                return "'" + text + "' is not a number of 0 or more (e.g. 6)";
            return "";
        },
        "NUMBER >= 0");
}

// the settings run, inverse and codegen share
struct LimitOptions {
    bool allow_outside_out = false;
    std::size_t max_terms = alembert::lang::kDefaultMaxTerms;
    std::size_t print_limit = alembert::lang::kDefaultPrintLimit;
};

void add_limit_options(CLI::App& c, LimitOptions& o) {
    c.add_flag("--allow-outside-out", o.allow_outside_out,
               "let a script's 'to \"dir\"' name an absolute path or leave --out through '..'");
    c.add_option("--max-terms", o.max_terms,
                 "largest expansion expand() and simplify() may form (default 100000)")
        ->check(count_of_one_or_more());
    c.add_option("--print-limit", o.print_limit,
                 "equations of more operations than this go to NAME.txt in --out, abbreviated "
                 "(numbered intermediates, short lines), and the transcript summarises them "
                 "(default 20000)")
        ->check(count_of_one_or_more());
}

void apply(const LimitOptions& o, Interpreter& interp) {
    interp.set_allow_outside_output(o.allow_outside_out);
    interp.set_max_terms(o.max_terms);
    interp.set_print_limit(o.print_limit);
}

// ---- subcommands ------------------------------------------------------------------------

struct RunOptions {
    std::string file;
    bool quiet = false;
    std::string out = ".";
    int digits = 6;
    bool tape = false;
    LimitOptions limits;
};

int run_script(const RunOptions& o) {
    std::string text;
    if (!read_script(o.file, text)) return kUsageError;
    if (!check_output_dir(o.out)) return kUsageError;
    Interpreter interp(std::cout, std::cerr, !o.quiet);
    interp.set_output_dir(o.out);
    interp.set_digits(o.digits);
    if (o.tape) interp.set_evaluation(alembert::lang::Evaluation::tape);
    apply(o.limits, interp);
    return exit_status(interp.run(text, display_name(o.file)));
}

// `alembert inverse` and `alembert codegen`: the script builds the model (its simulate,
// inverse and codegen statements skipped), then one library call does the work
struct ModelCommandOptions {
    std::string file;
    std::string out;
    std::string motion;
    double cutoff_hz = 6.0;
    bool compiled = false;
    bool tape = false;
    std::string unitless;
    std::string language;
    std::string name;
    LimitOptions limits;
    unsigned jobs = 1;
    std::string shard;
};

int run_model_command(const ModelCommandOptions& o, bool inverse) {
    // many trials (a pattern, several jobs or a shard): one child process per trial
    if (inverse && (o.motion.find_first_of("*?[") != std::string::npos || o.jobs != 1 || !o.shard.empty())) {
        std::error_code ec;
        const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
        if (!check_output_dir(o.out)) return kUsageError;
        return alembert::cli::run_inverse_batch({.model = o.file, .pattern = o.motion, .out = o.out,
                                                 .cutoff_hz = o.cutoff_hz, .compiled = o.compiled, .tape = o.tape,
                                                 .unitless = o.unitless, .jobs = o.jobs, .shard = o.shard},
                                                ec ? "/proc/self/exe" : self.c_str());
    }
    std::string text;
    if (!read_script(o.file, text)) return kUsageError;
    if (inverse && !std::filesystem::is_regular_file(o.motion)) {
        std::cerr << "alembert inverse: the motion table '" << o.motion << "' is not a file\n";
        return kUsageError;
    }
    if (!check_output_dir(o.out)) return kUsageError;
    Interpreter interp(std::cout, std::cerr, false);
    interp.set_model_only(true);
    interp.set_output_dir(o.out);
    if (inverse) interp.set_trial(o.motion);  // a plate's "{trial}_grf.mot"
    apply(o.limits, interp);
    RunStatus s = interp.run(text, display_name(o.file));
    if (s != RunStatus::ok) return exit_status(s);
    using alembert::lang::Evaluation;
    const Evaluation evaluation = o.compiled ? Evaluation::compiled : o.tape ? Evaluation::tape : Evaluation::automatic;
    return exit_status(inverse ? interp.run_inverse(o.motion, o.cutoff_hz, evaluation, o.unitless)
                               : interp.run_codegen(o.language, o.name));
}

struct RoadmapOptions {
    std::string file;
    bool json = false;
};

int print_roadmap(const RoadmapOptions& o) {
    std::string text;
    if (!read_script(o.file, text)) return kUsageError;
    std::ostringstream discard;  // the transcript is not wanted, only the table
    Interpreter interp(discard, std::cerr, false);
    interp.set_model_only(true);  // the model only: no simulate, inverse or codegen
    RunStatus s = interp.run(text, display_name(o.file));
    if (s != RunStatus::ok) return exit_status(s);
    try {
        std::cout << interp.roadmap_text(o.json);
        if (o.json) std::cout << "\n";
    } catch (const alembert::lang::ScriptError& e) {
        std::cerr << display_name(o.file) << ": error: " << e.what() << "\n";
        if (!e.hint().empty()) std::cerr << "hint: " << e.hint() << "\n";
        return kScriptError;
    }
    return kOk;
}

// `alembert report`: the whole script runs (its files go into DIR, its transcript is not
// printed), then the report of what it formed and computed is written to DIR/index.html
struct ReportOptions {
    std::string file;
    std::string out;
    alembert::lang::ReportSettings settings;
    bool no_plots = false;
};

int write_report_command(const ReportOptions& o) {
    std::string text;
    if (!read_script(o.file, text)) return kUsageError;
    std::ostringstream discard;
    Interpreter interp(discard, std::cerr, false);
    interp.set_output_dir(o.out);
    RunStatus s = interp.run(text, display_name(o.file));
    alembert::lang::ReportSettings settings = o.settings;
    settings.plots = !o.no_plots;
    if (s == RunStatus::ok) s = interp.write_report(o.out, settings);
    if (s == RunStatus::ok)
        std::cout << "wrote "
                  << (std::filesystem::path(o.out) / (settings.latex_only ? "roadmap.tex" : "index.html")).string()
                  << "\n";
    return exit_status(s);
}

// `alembert import`: an Autolev model translated into an Alembert script, written to a
// temporary beside the target and renamed; what could not be translated goes to stderr
struct ImportOptions {
    std::string file;
    std::string out;
};

int import_autolev(const ImportOptions& o) {
    namespace fs = std::filesystem;
    std::string text;
    if (!read_script(o.file, text)) return kUsageError;
    const std::string name = display_name(o.file);
    alembert::lang::AutolevTranslation t = alembert::lang::translate_autolev(text, name);
    for (const alembert::lang::Diagnostic& d : t.diagnostics)
        std::cerr << alembert::lang::format_diagnostic(d, text);
    if (!t.ok()) {
        std::cerr << "alembert: '" << name << "' was not translated: fix the errors above (" << o.out
                  << " is left as it was)\n";
        return kScriptError;
    }
    // statements without a counterpart were left out, each with a warning above: the script is
    // written, the exit status is 0, and the lines are summed up
    if (!t.left_out_lines.empty()) {
        std::cerr << "alembert: '" << name << "' imported with " << t.left_out_lines.size() << " statement"
                  << (t.left_out_lines.size() == 1 ? "" : "s") << " left out (line"
                  << (t.left_out_lines.size() == 1 ? " " : "s ");
        for (std::size_t i = 0; i < t.left_out_lines.size(); ++i) std::cerr << (i ? ", " : "") << t.left_out_lines[i];
        std::cerr << ")\n";
    }
    if (o.out == "-") {
        std::cout << t.script;
        return kOk;
    }
    const fs::path target(o.out);
    std::error_code ec;
    if (fs::is_directory(target, ec)) {
        std::cerr << "alembert: --out '" << o.out << "' is a directory; name the script to write\n";
        return kUsageError;
    }
    fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    alembert::TemporaryFile temporary(
        (dir / ("." + target.filename().string() + ".tmp" + std::to_string(static_cast<long>(::getpid())))).string());
    {
        std::ofstream f(temporary.path(), std::ios::binary);
        f << t.script;
        f.close();
        if (!f) {
            std::cerr << "alembert: cannot write '" << o.out << "' (" << std::strerror(errno)
                      << "); choose a writable path\n";
            std::remove(temporary.path().c_str());
            return kUsageError;
        }
    }
    fs::rename(temporary.path(), target, ec);
    if (ec) {
        std::cerr << "alembert: cannot replace '" << o.out << "' (" << ec.message() << ")\n";
        std::remove(temporary.path().c_str());
        return kUsageError;
    }
    temporary.release();
    std::size_t messages = t.diagnostics.size();  // warnings and notes: left out or renamed
    std::cout << "wrote " << o.out;
    if (messages) std::cout << " (" << messages << " message" << (messages == 1 ? "" : "s") << " above)";
    std::cout << "\n";
    return kOk;
}

// ---- the interactive session ------------------------------------------------------------

// Ctrl-C: while a line is typed, it is dropped and a new prompt shown; while a statement runs,
// the statement finishes (a second Ctrl-C ends the session)
volatile std::sig_atomic_t g_interrupted = 0;
volatile std::sig_atomic_t g_running = 0;

extern "C" void on_session_interrupt(int) {
    if (g_running) {
        if (g_interrupted) {
            std::signal(SIGINT, SIG_DFL);
            std::raise(SIGINT);
        }
        static const char note[] =
            "\nalembert: the statement runs to its end; Ctrl-C again ends the session\n";
        ssize_t ignored = write(STDERR_FILENO, note, sizeof note - 1);
        (void)ignored;
    }
    g_interrupted = 1;
}

#ifdef ALEMBERT_HAVE_LIBEDIT
// libedit's source of keys: a Ctrl-C ends the line being typed (it is then dropped)
int read_key(FILE*) {
    for (;;) {
        if (g_interrupted) return '\n';
        unsigned char c = 0;
        ssize_t n = read(STDIN_FILENO, &c, 1);
        if (n == 1) return c;
        if (n == 0 || errno != EINTR) return -1;
    }
}
#endif

enum class Input { line, cancelled, end };

// one line of input, with editing and history on a terminal
Input read_line(const char* prompt, bool terminal, std::string& line) {
    g_interrupted = 0;
#ifdef ALEMBERT_HAVE_LIBEDIT
    if (terminal) {
        char* got = readline(prompt);
        if (g_interrupted) {
            std::free(got);
            return Input::cancelled;
        }
        if (!got) return Input::end;
        line = got;
        std::free(got);
        if (!line.empty()) add_history(line.c_str());
        return Input::line;
    }
#else
    if (terminal) std::cout << prompt << std::flush;
#endif
    (void)prompt;
    if (!std::getline(std::cin, line)) return Input::end;
    return g_interrupted ? Input::cancelled : Input::line;
}

std::string history_path() {
    const char* home = std::getenv("HOME");
    return home ? std::string(home) + "/.alembert_history" : std::string();
}

// a line that speaks to the session rather than the interpreter: help [WORD], quit, exit
bool session_command(const std::string& line, bool& quit) {
    std::istringstream words(line);
    std::string first, topic, extra;
    words >> first >> topic >> extra;
    if ((first == "quit" || first == "exit") && topic.empty()) {
        quit = true;
        return true;
    }
    if (first == "help" && extra.empty()) {
        std::cout << alembert::lang::statement_help(topic) << std::flush;
        return true;
    }
    return false;
}

// Runs statements typed or piped in; errors are reported and the session goes on. Piped input
// that had an error ends with the status of the worst one (1 script error, 3 internal).
int interactive() {
    bool terminal = isatty(STDIN_FILENO) != 0;
    std::string history = history_path();
    if (terminal) {
        struct sigaction sa {};
        sa.sa_handler = on_session_interrupt;
        sa.sa_flags = SA_RESTART;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, nullptr);
    }
#ifdef ALEMBERT_HAVE_LIBEDIT
    if (terminal) {
        rl_catch_signals = 1;  // libedit restores the terminal and interrupts its read on Ctrl-C
        rl_getc_function = read_key;
        if (!history.empty()) {
            stifle_history(1000);
            read_history(history.c_str());
        }
    }
#endif
    if (terminal)
        std::cout << "alembert " << ALEMBERT_VERSION
                  << ": type statements (docs/language.md), help, or quit; Ctrl-C drops a line\n";
    Interpreter interp(std::cout, std::cerr, false);
    interp.set_session(true);
    std::string buffer, line;
    int line_number = 1, first_line = 1;
    int status = kOk;
    auto run = [&] {
        g_running = 1;
        g_interrupted = 0;
        int s = exit_status(interp.run(buffer, "<stdin>", first_line));
        g_running = 0;
        status = std::max(status, s);
        buffer.clear();
    };
    for (;;) {
        Input got = read_line(buffer.empty() ? "alembert> " : "      ... ", terminal, line);
        if (got == Input::end) break;
        if (got == Input::cancelled) {
            buffer.clear();  // an unfinished statement goes with its line
            continue;
        }
        if (buffer.empty()) {
            bool quit = false;
            if (session_command(line, quit)) {
                ++line_number;
                if (quit) break;
                continue;
            }
            first_line = line_number;
        }
        buffer += line + "\n";
        ++line_number;
        // a statement with an open bracket continues on the next line
        if (alembert::lang::statement_is_open(buffer)) continue;
        run();
    }
    if (!buffer.empty()) run();
#ifdef ALEMBERT_HAVE_LIBEDIT
    if (terminal && !history.empty()) {
        // written atomically: a temporary file renamed over the history
        std::string tmp = history + ".tmp" + std::to_string(getpid());
        if (write_history(tmp.c_str()) == 0) std::rename(tmp.c_str(), history.c_str());
        else std::remove(tmp.c_str());
    }
#endif
    if (terminal) {
        std::cout << "\n";
        return kOk;  // errors were seen as they happened
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Alembert: equations of motion of multibody systems by MG road-maps, "
                 "Kane's and Lagrange's methods.\nWithout a command, starts an interactive session.",
                 "alembert"};
    app.set_version_flag("--version", std::string("alembert ") + ALEMBERT_VERSION);
    app.require_subcommand(0, 1);

    RunOptions run_opts;
    RoadmapOptions roadmap_opts;
    ModelCommandOptions inverse_opts, codegen_opts;
    ReportOptions report_opts;
    ImportOptions import_opts;
    // The subcommand table. Each row adds one subcommand and the function that carries it out,
    // so main() stays a dispatcher.
    struct Subcommand {
        const char* name;
        const char* help;
        std::function<void(CLI::App&)> options;
        std::function<int()> action;
    };
    const std::vector<Subcommand> table{
        {"run", "Run a script (.alb) and print its transcript",
         [&](CLI::App& c) {
             c.add_option("FILE", run_opts.file, "the script; '-' reads standard input")->required();
             c.add_flag("-q,--quiet", run_opts.quiet, "print only results, not the statements");
             c.add_option("--out", run_opts.out,
                          "directory for the files of simulate, inverse and codegen (default: .)");
             c.add_option("--digits", run_opts.digits,
                          "significant digits of printed numbers, 1 to 17 (default: 6; a script's "
                          "digits statement changes it; CSV files always read back exactly)")
                 ->check(CLI::Range(1, 17));
             c.add_flag("--tape", run_opts.tape,
                        "evaluate simulate and inverse on the interpreted tape unless a statement says "
                        "compiled (default: compiled C code where a C compiler is found, cached)");
             add_limit_options(c, run_opts.limits);
         },
         [&] { return run_script(run_opts); }},
        {"roadmap", "Print the MG road-map table of the model in a script",
         [&](CLI::App& c) {
             c.add_option("FILE", roadmap_opts.file, "the script; '-' reads standard input")->required();
             c.add_flag("--json", roadmap_opts.json, "print the road-map as JSON");
         },
         [&] { return print_roadmap(roadmap_opts); }},
        {"inverse", "Inverse dynamics of a script's model over a motion table: DIR/torques.csv and its plot",
         [&](CLI::App& c) {
             c.add_option("MODEL", inverse_opts.file, "the script that builds the model")->required();
             c.add_option("--motion", inverse_opts.motion,
                          "CSV: a column t [s] and one per coordinate, units in the header (qA [deg]); "
                          "a quoted pattern ('trials/*.csv') runs a batch: DIR/<trial>/ and DIR/summary.csv")
                 ->required();
             c.add_option("--jobs", inverse_opts.jobs, "trials run at once in a batch (0: one per core; default 1)");
             c.add_option("--shard", inverse_opts.shard,
                          "I/N: run only task I's share of the trials (0 <= I < N), for cluster array jobs");
             c.add_option("--out", inverse_opts.out, "directory for torques.csv, .png and .svg")->required();
             c.add_option("--cutoff", inverse_opts.cutoff_hz,
                          "low-pass Butterworth cutoff in Hz before differentiating (0: no filter; default 6)")
                 ->check(number_of_zero_or_more());
             CLI::Option* compiled = c.add_flag("--compiled", inverse_opts.compiled,
                                                "evaluate through compiled C code and say so (the default where a "
                                                "C compiler is found, cached)");
             c.add_flag("--tape", inverse_opts.tape, "evaluate on the interpreted tape: run no compiler")
                 ->excludes(compiled);
             c.add_option("--unitless", inverse_opts.unitless,
                          "read coordinate columns without a unit in the header in this unit (deg, rad, m, mm)");
             add_limit_options(c, inverse_opts.limits);
         },
         [&] { return run_model_command(inverse_opts, true); }},
        {"codegen", "Generate C, C++, MATLAB/Octave or Python code for a script's model",
         [&](CLI::App& c) {
             c.add_option("MODEL", codegen_opts.file, "the script that builds the model")->required();
             c.add_option("--lang", codegen_opts.language, "c, cpp, matlab or python")
                 ->required()
                 ->check(CLI::IsMember({"c", "cpp", "c++", "matlab", "octave", "python"}));
             c.add_option("--out", codegen_opts.out, "directory for the generated files")->required();
             c.add_option("--name", codegen_opts.name, "prefix of the files and functions (default: the script's name)");
             add_limit_options(c, codegen_opts.limits);
         },
         [&] { return run_model_command(codegen_opts, false); }},
        {"report", "Run a script and write its HTML report: road-map with free-body diagrams, equations, plots, motion",
         [&](CLI::App& c) {
             c.add_option("MODEL", report_opts.file, "the script; '-' reads standard input")->required();
             c.add_option("--out", report_opts.out,
                          "directory for index.html (and the files of simulate and inverse)")->required();
             c.add_flag("--latex", report_opts.settings.latex_only,
                        "write only roadmap.tex: the road-map table, TikZ free-body diagrams and the equations");
             c.add_flag("--check", report_opts.settings.check,
                        "compare the road-map with Kane, Lagrange and Newton-Euler (and the joint reactions) in the checks");
             c.add_flag("--matrices", report_opts.settings.matrices,
                        "show the mass matrix and forcing, M q'' = f, as simulate forms them");
             c.add_flag("--no-plots", report_opts.no_plots, "leave the time histories unplotted");
             c.add_option("--plot", report_opts.settings.plotted,
                          "the columns to plot (repeat or separate by commas; default: all)")->delimiter(',');
         },
         [&] { return write_report_command(report_opts); }},
        {"import", "Translate an Autolev model (.al) into an Alembert script (.alb)",
         [&](CLI::App& c) {
             c.add_option("MODEL", import_opts.file, "the Autolev file; '-' reads standard input")->required();
             c.add_option("--out", import_opts.out, "the Alembert script to write ('-': standard output)")
                 ->required();
         },
         [&] { return import_autolev(import_opts); }},
    };
    std::vector<CLI::App*> commands;
    for (const Subcommand& s : table) {
        CLI::App* c = app.add_subcommand(s.name, s.help);
        s.options(*c);
        commands.push_back(c);
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? kOk : kUsageError;
    }
    try {
        for (std::size_t i = 0; i < table.size(); ++i)
            if (commands[i]->parsed()) {
                // an interrupted command removes its temporary files and child processes
                alembert::install_interrupt_cleanup();
                return table[i].action();
            }
        return interactive();
    } catch (const std::exception& e) {
        std::cerr << "alembert: internal error: " << e.what() << "\n";
        return kInternalError;
    }
}
