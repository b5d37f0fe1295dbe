// SPDX-License-Identifier: MIT
// The lexer: tokens, statement ends, brackets across lines, UTF-8.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "alembert/lang/lexer.hpp"

using namespace alembert::lang;

namespace {

std::vector<std::vector<std::string>> statements(const std::string& text) {
    Lexer lx(text);
    std::vector<std::vector<std::string>> out;
    for (auto t = lx.next_statement(); !t.empty(); t = lx.next_statement()) {
        out.emplace_back();
        for (const Token& k : t)
            if (k.kind != TokenKind::end)
                out.back().push_back(k.kind == TokenKind::vector_name   ? k.text + ">"
                                     : k.kind == TokenKind::dyadic_name ? k.text + ">>"
                                                                        : k.text);
    }
    return out;
}

}  // namespace

TEST(Lexer, NamesKeepTheirPrimesAndVectorsTheirArrow) {
    auto s = statements("z = qA'' * Ax> + 0>\n");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0], (std::vector<std::string>{"z", "=", "qA''", "*", "Ax>", "+", "0"}));
}

TEST(Lexer, DyadicsEndInTwoArrows) {
    Lexer lx("I_B>> = outer(Ax>, By>)\n");
    auto t = lx.next_statement();
    ASSERT_GE(t.size(), 3u);
    EXPECT_EQ(t[0].kind, TokenKind::dyadic_name);
    EXPECT_EQ(t[0].text, "I_B");
    EXPECT_EQ(t[4].kind, TokenKind::vector_name);
    auto s = statements("D>> = 2*E>> - F>>\n");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0], (std::vector<std::string>{"D>>", "=", "2", "*", "E>>", "-", "F>>"}));
}

TEST(Lexer, StatementsEndAtNewlinesAndSemicolonsButNotInsideBrackets) {
    auto s = statements("a = 1; b = 2\nZ = [1,\n  2]  # two\n\n# note\n");
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[2], (std::vector<std::string>{"Z", "=", "[", "1", ",", "2", "]"}));
    EXPECT_EQ(s[3], (std::vector<std::string>{"# note"}));
}

TEST(Lexer, BackslashContinuesALine) {
    auto s = statements("a = 1 + \\\n 2\n");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].size(), 5u);
}

TEST(Lexer, LocationsAreOneBasedLinesAndCharacterColumns) {
    Lexer lx("# é\n  zz = 1\n");
    lx.next_statement();
    auto t = lx.next_statement();
    EXPECT_EQ(t[0].location.line, 2);
    EXPECT_EQ(t[0].location.column, 3);
    EXPECT_EQ(t[2].location.column, 8);
}

TEST(Lexer, NumbersParseWithExponents) {
    Lexer lx("x = 1.5e-3 .25\n");
    auto t = lx.next_statement();
    EXPECT_DOUBLE_EQ(t[2].number, 1.5e-3);
    EXPECT_DOUBLE_EQ(t[3].number, 0.25);
}

TEST(Lexer, InvalidUtf8IsRefusedAtItsByte) {
    for (const char* bad : {"a\xc3(", "\xed\xa0\x80", "\xc0\xaf", "ok\n\xf5\x80\x80\x80"}) {
        try {
            validate_utf8(bad);
            ADD_FAILURE() << "accepted invalid UTF-8";
        } catch (const ScriptError& e) {
            EXPECT_NE(std::string(e.what()).find("not valid UTF-8"), std::string::npos);
        }
    }
    EXPECT_NO_THROW(validate_utf8("Ñ € 𝄞"));
}

TEST(Lexer, OpenStatementsWaitForMoreInput) {
    EXPECT_TRUE(statement_is_open("Z = [1,\n"));
    EXPECT_TRUE(statement_is_open("z = sin(q\n"));
    EXPECT_FALSE(statement_is_open("z = sin(q)\n"));
    EXPECT_FALSE(statement_is_open("z = sin(q))\n"));  // an error, reported when run
    EXPECT_TRUE(statement_is_open("z = 1 + \\\n"));
}
