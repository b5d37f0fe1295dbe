// SPDX-License-Identifier: MIT
// Scripts in several files: `include "file.alb"` runs another script's statements where it
// stands: its meaning, then its grammar and table (include_statements()).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/lang/lexer.hpp"
#include "alembert/lang/parser.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

namespace fs = std::filesystem;

std::string canonical_text(const fs::path& p) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(p, ec);
    return (ec ? p : c).string();
}

// include "file.alb": the file's statements, run as if written here; paths in it (further
// includes, motion tables) are relative to its own directory
void run_include(Interpreter::Impl& m, const Statement& s) {
    const Word& w = s.word("file");
    const fs::path path = m.input_path(w.text);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw ScriptError(w.location, "the included file '" + w.text + "' is not a file (looked for " + path.string() + ")",
                          "paths a script includes are relative to the including script's directory");
    // ---- cycles: the file is already being run (the top script or an include around us)
    const std::string me = canonical_text(path);
    std::vector<std::string> chain;
    if (!m.script_file.empty()) chain.push_back(canonical_text(m.script_file));
    chain.insert(chain.end(), m.including.begin(), m.including.end());
    for (std::size_t i = 0; i < chain.size(); ++i)
        if (chain[i] == me) {
            std::string loop;
            for (std::size_t j = i; j < chain.size(); ++j) loop += fs::path(chain[j]).filename().string() + " -> ";
            throw ScriptError(w.location, "including '" + w.text + "' here makes a cycle: " + loop +
                                              fs::path(me).filename().string(),
                              "include each file once, from one place (a model, then the studies that include it)");
        }
    if (m.including.size() >= 32)
        throw ScriptError(w.location, "includes are nested more than 32 deep", "include fewer levels of files");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof())
        throw ScriptError(w.location, "the included file '" + w.text + "' cannot be read", "check its permissions");
    const std::string source = text.str();

    // ---- run its statements; an error in it is reported at its own file:line:col, then here
    const std::string saved_base = m.base_dir;
    m.including.push_back(me);
    m.base_dir = path.parent_path().string();
    auto restore = [&] {
        m.including.pop_back();
        m.base_dir = saved_base;
    };
    try {
        Lexer lexer(source);
        for (;;) {
            std::vector<Token> tokens = lexer.next_statement();
            if (tokens.empty()) break;
            Statement inner = parse_statement(tokens, source);
            if (inner.keyword == "#") {
                m.transcript.comment(inner.source);
                continue;
            }
            m.transcript.statement(inner.source);
            m.execute(inner);
        }
    } catch (const ScriptError& e) {
        restore();
        m.transcript.flush();
        *m.err << format_diagnostic(Diagnostic{Severity::error, path.string(), e.where(), e.what(), e.hint()}, source);
        throw ScriptError(w.location, "the included file '" + w.text + "' stopped at the error above",
                          "fix it there; the statements before it ran");
    } catch (...) {
        restore();
        throw;
    }
    restore();
}

void parse_include(StatementParser& p, Statement& s) { s.words["file"] = p.text("the path of the script to include"); }

}  // namespace

std::vector<StatementSpec> include_statements() {
    return {
        {.keyword = "include", .family = "Scripts in several files",
         .help = "runs the statements of another script file here (a model, then studies of it)",
         .forms = {{"`include` *\"file.alb\"*",
                    "include \"model.alb\"",
                    "`Interpreter` runs the file's statements where the statement stands (paths relative to the including script; cycles are errors)"}},
         .parse = parse_include, .run = run_include, .needs_model = false},
    };
}

}  // namespace alembert::lang
