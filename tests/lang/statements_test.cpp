// SPDX-License-Identifier: MIT
// The registry of statements: complete, its examples parse, and help is driven from it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "alembert/lang/parser.hpp"
#include "alembert/lang/statements.hpp"

using namespace alembert::lang;

namespace {

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
