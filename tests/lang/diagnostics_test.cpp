// SPDX-License-Identifier: MIT
// The corpus of malformed scripts: each gives its intended message at the right line and
// column; hostile inputs (a 1 MB line, deep nesting, huge statements, mutilated scripts) are
// refused or run, and never crash or hang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/script_dir.hpp"
#include "alembert/lang/diagnostic.hpp"
#include "alembert/lang/interpreter.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

const fs::path kScripts = fs::path(ALEMBERT_SOURCE_DIR) / "tests" / "lang" / "scripts";

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Expected {
    std::string script;
    bool ok = false;
    int line = 0, column = 0;
    std::string message;
};

std::vector<Expected> manifest() {
    std::vector<Expected> out;
    std::ifstream in(kScripts / "expected.tsv");
    std::string row;
    while (std::getline(in, row)) {
        if (row.empty() || row[0] == '#') continue;
        std::istringstream r(row);
        Expected e;
        std::string where;
        std::getline(r, e.script, '\t');
        std::getline(r, where, '\t');
        std::getline(r, e.message);
        if (where == "ok") {
            e.ok = true;
        } else {
            std::size_t colon = where.find(':');
            e.line = std::stoi(where.substr(0, colon));
            e.column = std::stoi(where.substr(colon + 1));
        }
        out.push_back(e);
    }
    return out;
}

struct Outcome {
    RunStatus status;
    std::optional<Diagnostic> error;
    std::string out, err;
};

Outcome run(const std::string& text, const std::string& name = "t.alb") {
    std::ostringstream out, err;
    Interpreter interp(out, err, true);
    RunStatus s = interp.run(text, name);
    return {s, interp.last_error(), out.str(), err.str()};
}

}  // namespace

TEST(Diagnostics, CorpusHasAtLeastFortyScriptsAndEachIsListed) {
    std::set<std::string> listed, present;
    for (const Expected& e : manifest()) listed.insert(e.script);
    for (const auto& f : fs::directory_iterator(kScripts))
        if (f.path().extension() == ".alb") present.insert(f.path().filename().string());
    EXPECT_GE(present.size(), 40u);
    EXPECT_EQ(listed, present) << "every script in tests/lang/scripts needs a row in expected.tsv";
}

TEST(Diagnostics, EachMalformedScriptGivesItsMessageAtItsLineAndColumn) {
    // run from a copy of the scripts' directory, so the data files they read (data/*.csv) are
    // found and named in messages by the same relative paths on every machine, and whatever a
    // script writes before its error lands in the copy, not in the sources
    struct InScriptsDirectory {
        alembert::test::TempDir copy{"alembert-corpus"};
        fs::path before = fs::current_path();
        InScriptsDirectory() {
            fs::copy(kScripts, copy.path / "scripts", fs::copy_options::recursive);
            fs::current_path(copy.path / "scripts");
        }
        ~InScriptsDirectory() { fs::current_path(before); }
    } in_scripts;
    for (const Expected& e : manifest()) {
        SCOPED_TRACE(e.script);
        Outcome o = run(read_bytes(kScripts / e.script), e.script);
        if (e.ok) {
            EXPECT_EQ(o.status, RunStatus::ok);
            EXPECT_EQ(o.err, "");
            continue;
        }
        ASSERT_EQ(o.status, RunStatus::script_error) << o.err;
        ASSERT_TRUE(o.error.has_value());
        EXPECT_EQ(o.error->location.line, e.line);
        EXPECT_EQ(o.error->location.column, e.column);
        EXPECT_EQ(o.error->message, e.message);
        // printed as file:line:col: error: message, then the line and a caret under the column
        std::string head = e.script + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) +
                           ": error: " + e.message + "\n";
        EXPECT_EQ(o.err.substr(0, head.size()), head);
        std::istringstream lines(o.err);
        std::string first, source, caret;
        std::getline(lines, first), std::getline(lines, source), std::getline(lines, caret);
        std::size_t bar = caret.find("| ");
        ASSERT_NE(bar, std::string::npos) << o.err;
        EXPECT_EQ(caret.find('^'), bar + 2 + static_cast<std::size_t>(e.column - 1)) << o.err;
    }
}

TEST(Diagnostics, FormatPutsTheCaretUnderTheColumnAndTheHintLast) {
    Diagnostic d{Severity::error, "m.alb", {2, 5}, "'Q' is not declared", "declare it"};
    EXPECT_EQ(format_diagnostic(d, "newtonian N\nz = Q\n"),
              "m.alb:2:5: error: 'Q' is not declared\n"
              "    2 | z = Q\n"
              "      |     ^\n"
              "hint: declare it\n");
}

TEST(Diagnostics, ColumnsCountCharactersNotBytes) {
    // the comment holds two-byte characters; the error column counts each as one
    Outcome o = run("newtonian N # Ñé\nz = é\n");
    ASSERT_EQ(o.status, RunStatus::script_error);
    EXPECT_EQ(o.error->location.line, 2);
    EXPECT_EQ(o.error->location.column, 5);
    EXPECT_NE(o.error->message.find("unexpected character 'é'"), std::string::npos) << o.error->message;
}

TEST(Diagnostics, AOneMegabyteLineIsRefusedAtTheLineLimit) {
    std::string text = "newtonian N\nconstant a = " + std::string(1 << 20, '1') + "\n";
    Outcome o = run(text);
    ASSERT_EQ(o.status, RunStatus::script_error);
    EXPECT_EQ(o.error->location.line, 2);
    EXPECT_EQ(o.error->location.column, 10001);
    EXPECT_EQ(o.error->message, "line 2 is longer than 10000 characters");
    EXPECT_LT(o.err.size(), 2000u) << "the diagnostic must not echo the whole line";
}

TEST(Diagnostics, DeepBracketsAreRefusedNotRecursedInto) {
    Outcome o = run("newtonian N\nz = " + std::string(100000, '(') + "1\n");
    ASSERT_EQ(o.status, RunStatus::script_error);
    EXPECT_EQ(o.error->location.column, 5 + 64);
    EXPECT_EQ(o.error->message, "brackets are nested more than 64 deep");
    Outcome p = run("newtonian N\nz = " + std::string(5000, '-') + "1\n");
    ASSERT_EQ(p.status, RunStatus::script_error);
    EXPECT_EQ(p.error->message, "the expression is nested too deeply (more than 64 levels)");
}

TEST(Diagnostics, LongFlatSumsRunWithoutDeepRecursion) {
    // 20,000 terms in one statement, over 20 lines inside parentheses: sums are n-ary
    std::string text = "newtonian N\nvariable q''\nz = (q";
    for (int line = 0; line < 20; ++line) {
        text += "\n";
        for (int i = 0; i < 1000; ++i) text += " + q";
    }
    text += ")\n";
    Outcome o = run(text);
    ASSERT_EQ(o.status, RunStatus::ok) << o.err;
    EXPECT_NE(o.out.find("z = 20001*q"), std::string::npos);
}

TEST(Diagnostics, AStatementOfTooManyTokensIsRefused) {
    std::string text = "newtonian N\nZ = [1";
    for (int line = 0; line < 60; ++line) {
        text += "\n";
        for (int i = 0; i < 1000; ++i) text += ",1";
    }
    text += "]\n";
    Outcome o = run(text);
    ASSERT_EQ(o.status, RunStatus::script_error);
    EXPECT_EQ(o.error->message, "the statement is too long (more than 100000 tokens)");
}

TEST(Diagnostics, MutilatedScriptsNeverCrash) {
    // every prefix of a real script, and the script with one byte replaced, either runs or
    // stops with a script error: never an internal error, a crash or a hang
    std::string text = read_bytes(fs::path(ALEMBERT_SOURCE_DIR) / "examples" / "double_pendulum" / "model.alb");
    const std::string bytes = "()[]=,;'>#\\\n\xff\xc3 -*/^0e";
    int runs = 0;
    for (std::size_t cut = 0; cut < text.size(); cut += 13) {
        Outcome o = run(text.substr(0, cut));
        EXPECT_NE(o.status, RunStatus::internal_error) << "prefix " << cut << ": " << o.err;
        std::string mutated = text;
        mutated[cut] = bytes[(cut / 13) % bytes.size()];
        Outcome m = run(mutated);
        EXPECT_NE(m.status, RunStatus::internal_error) << "byte " << cut << ": " << m.err;
        runs += 2;
    }
    EXPECT_GT(runs, 100);
}
