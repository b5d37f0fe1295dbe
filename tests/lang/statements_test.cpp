// SPDX-License-Identifier: MIT
// The registry of statements: complete, its examples parse, and what is driven from it (help,
// docs/language.md's tables, the fuzzer's dictionary) agrees with it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "alembert/lang/parser.hpp"
#include "alembert/lang/statements.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

fs::path source_path(const std::string& relative) { return fs::path(ALEMBERT_SOURCE_DIR) / relative; }

std::string read_source(const std::string& relative) {
    std::ifstream in(source_path(relative), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool updating_generated_files() { return std::getenv("ALEMBERT_UPDATE_GOLDEN") != nullptr; }

// the block of docs/language.md between `<!-- statements: FAMILY ...-->` and its end marker
struct DocBlock {
    std::size_t begin = std::string::npos;  // first byte after the opening marker's line
    std::size_t end = std::string::npos;    // first byte of the closing marker
};

DocBlock find_doc_block(const std::string& doc, std::string_view family) {
    DocBlock b;
    std::string open = "<!-- statements: " + std::string(family) + " -->\n";
    std::size_t at = doc.find(open);
    if (at == std::string::npos) return b;
    b.begin = at + open.size();
    b.end = doc.find("<!-- end of statements -->", b.begin);
    if (b.end == std::string::npos) b.begin = std::string::npos;
    return b;
}

Statement parse_example(std::string_view example) {
    std::string text(example);
    text += "\n";
    Lexer lx(text);
    return parse_statement(lx.next_statement(), text);
}

}  // namespace

TEST(Statements, EachKeywordIsRegisteredOnceWithHelpFormsGrammarAndMeaning) {
    std::set<std::string_view> seen;
    ASSERT_GE(statements().size(), 44u);
    for (const StatementSpec& s : statements()) {
        EXPECT_TRUE(seen.insert(s.keyword).second) << "'" << s.keyword << "' is registered twice";
        EXPECT_FALSE(s.help.empty()) << s.keyword;
        EXPECT_FALSE(s.family.empty()) << s.keyword;
        EXPECT_FALSE(s.forms.empty()) << s.keyword;
        EXPECT_NE(s.parse, nullptr) << s.keyword;
        EXPECT_NE(s.run, nullptr) << s.keyword;
        EXPECT_EQ(find_statement(s.keyword), &s);
        EXPECT_TRUE(is_reserved(s.keyword)) << s.keyword;
    }
    EXPECT_EQ(find_statement("frobnicate"), nullptr);
    EXPECT_EQ(statement_keywords().size(), statements().size());
}

TEST(Statements, EveryFormsExampleParsesAsItsStatement) {
    for (const StatementSpec& s : statements())
        for (const StatementForm& f : s.forms) {
            try {
                EXPECT_EQ(parse_example(f.example).keyword, s.keyword) << f.example;
            } catch (const ScriptError& e) {
                ADD_FAILURE() << "the example '" << f.example << "' of '" << s.keyword
                              << "' does not parse: " << e.what();
            }
        }
}

TEST(Statements, ClauseWordsAreReservedAndStopAUnit) {
    for (const std::string& w : statement_clause_words()) EXPECT_TRUE(is_reserved(w)) << w;
    EXPECT_TRUE(is_reserved("stiffness"));
    EXPECT_TRUE(is_reserved("guess"));
    EXPECT_FALSE(is_reserved("time"));  // `final time` reads the word, but it may name things
    // `at` ends the quantity 20 deg: it is a clause, not a unit
    Statement s = parse_example("evaluate q at q = 20 deg");
    EXPECT_EQ(s.bindings.at("at")[0].quantity.unit.factors.size(), 1u);
}

TEST(Statements, HelpListsEveryStatementWithItsLine) {
    std::string all = statement_help();
    for (const StatementSpec& s : statements()) {
        EXPECT_NE(all.find("  " + std::string(s.keyword) + " "), std::string::npos) << s.keyword;
        EXPECT_NE(all.find(std::string(s.help) + "\n"), std::string::npos) << s.keyword;
    }
    for (std::string_view family : statement_families())
        EXPECT_NE(all.find("\n" + std::string(family) + "\n"), std::string::npos) << family;
}

TEST(Statements, HelpOfOneStatementShowsItsFormsAsPlainTextWithExamples) {
    std::string rotate = statement_help("rotate");
    EXPECT_EQ(rotate.rfind("rotate: orients a frame or body from another\n", 0), 0u) << rotate;
    EXPECT_NE(rotate.find("  rotate B from A about [-]axis by angle\n"), std::string::npos) << rotate;
    EXPECT_NE(rotate.find("      e.g. rotate B from A about z by qB\n"), std::string::npos) << rotate;
    EXPECT_NE(rotate.find("      calls Frame::orient_axis (-z: left-handed)\n"), std::string::npos) << rotate;
    EXPECT_EQ(rotate.find('`'), std::string::npos) << rotate;
    EXPECT_NE(statement_help("codegen").find("codegen c|cpp|matlab|python"), std::string::npos);
    EXPECT_EQ(statement_help("frobnicate"),
              "'frobnicate' is not a statement; type help for the list of statements\n");
}

TEST(Statements, DocsLanguageTablesAreGeneratedFromTheRegistry) {
    const std::string relative = "docs/language.md";
    std::string doc = read_source(relative);
    ASSERT_FALSE(doc.empty()) << relative;
    std::string updated = doc;
    for (std::string_view family : statement_families()) {
        DocBlock b = find_doc_block(updated, family);
        ASSERT_NE(b.begin, std::string::npos)
            << relative << " has no block '<!-- statements: " << family
            << " -->' ... '<!-- end of statements -->' for the table of these statements";
        // a blank line on each side of the table, so Markdown sees it apart from the markers
        std::string want = "\n" + statement_table_markdown(family) + "\n";
        std::string have = updated.substr(b.begin, b.end - b.begin);
        if (have == want) continue;
        if (updating_generated_files()) {
            updated.replace(b.begin, b.end - b.begin, want);
            continue;
        }
        ADD_FAILURE() << relative << ": the table of '" << family
                      << "' statements differs from the registry (src/lang/statements*.cpp, "
                         "interpreter_equations.cpp, interpreter_numbers.cpp); refresh it with "
                         "ALEMBERT_UPDATE_GOLDEN=1 ctest -R Statements and review the diff.\nIt "
                         "should read:\n"
                      << want << "\nIt reads:\n"
                      << have;
    }
    if (updated != doc) std::ofstream(source_path(relative), std::ios::binary) << updated;
}

TEST(Statements, FuzzDictionaryIsGeneratedFromTheRegistry) {
    const std::string relative = "tests/fuzz/alembert.dict";
    std::string want = fuzz_dictionary();
    if (read_source(relative) == want) return;
    if (updating_generated_files()) {
        std::ofstream(source_path(relative), std::ios::binary) << want;
        return;
    }
    ADD_FAILURE() << relative << " differs from fuzz_dictionary() of the statement registry; refresh "
                  << "it with ALEMBERT_UPDATE_GOLDEN=1 ctest -R Statements and review the diff";
}

TEST(Statements, FuzzDictionaryHoldsKeywordsClausesAndFunctions) {
    std::string dict = fuzz_dictionary();
    EXPECT_NE(dict.find("\"rotate \"\n"), std::string::npos);
    EXPECT_NE(dict.find("\" stiffness \"\n"), std::string::npos);
    EXPECT_NE(dict.find("\"minimum_jerk(\"\n"), std::string::npos);
    EXPECT_NE(dict.find("\"simulate \"\n"), std::string::npos);
}

TEST(Statements, ASyntaxErrorsHintShowsTheStatementsForms) {
    try {
        parse_example("translate P to O by r>");
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), "expected 'from' (translate P from O by r>), found 'to'");
        EXPECT_EQ(e.hint(),
                  "'translate' takes this form (docs/language.md; help translate in a session):\n"
                  "    translate P from O by vector");
    }
    try {
        parse_example("rotate B from A around z by q");
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(e.hint(), "'rotate' takes one of these forms (docs/language.md; help rotate in a session):\n" +
                                statement_forms("rotate", "    ").substr(0, statement_forms("rotate", "    ").size() - 1));
        EXPECT_NE(e.hint().find("\n    rotate B from A dcm matrix"), std::string::npos) << e.hint();
    }
}

TEST(Statements, AnUnknownStatementsHintNamesTheNearestOne) {
    try {
        parse_example("bodie A, B");
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), "unknown statement 'bodie'");
        EXPECT_EQ(e.hint().rfind("did you mean 'body'? statements start with", 0), 0u) << e.hint();
    }
    try {
        parse_example("frobnicate A, B");
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(e.hint().rfind("statements start with", 0), 0u) << e.hint();
    }
}
