// SPDX-License-Identifier: MIT
// The parser: precedence, statement forms, declarations with units.
#include <gtest/gtest.h>

#include <string>

#include "alembert/lang/parser.hpp"

using namespace alembert::lang;

namespace {

Statement parse(const std::string& text) {
    Lexer lx(text);
    return parse_statement(lx.next_statement(), text);
}

}  // namespace

TEST(Parser, UnaryMinusBindsLooserThanPower) {
    Statement s = parse("z = -x^2\n");
    const Expr* e = s.expr("value");
    ASSERT_EQ(e->kind, Expr::Kind::negate);
    EXPECT_EQ(e->args[0]->kind, Expr::Kind::power);
}

TEST(Parser, SumsAndProductsAreFlat) {
    Statement s = parse("z = a + b - c*d/e\n");
    const Expr* e = s.expr("value");
    ASSERT_EQ(e->kind, Expr::Kind::sum);
    EXPECT_EQ(e->args.size(), 3u);
    EXPECT_EQ(e->inverted, (std::vector<bool>{false, false, true}));
    EXPECT_EQ(e->args[2]->kind, Expr::Kind::product);
    EXPECT_EQ(e->args[2]->inverted, (std::vector<bool>{false, false, true}));
}

TEST(Parser, AStatementWordBeforeParenthesesIsACall) {
    EXPECT_EQ(parse("mass A = m\n").keyword, "mass");
    EXPECT_EQ(parse("mass(S)\n").keyword, "");
    EXPECT_EQ(parse("simplify(x)\n").keyword, "");
    EXPECT_EQ(parse("inertia(C)\n").keyword, "");  // the central inertia dyadic
}

TEST(Parser, AStatementWordThatNamesNoFunctionStartsItsStatementBeforeParentheses) {
    Statement e = parse("evaluate (a + q) at q = 1\n");
    ASSERT_EQ(e.keyword, "evaluate");
    EXPECT_EQ(e.expr("value")->kind, Expr::Kind::sum);
    EXPECT_EQ(e.bindings.at("at").size(), 1u);
    // the parenthesis opens the statement's expression, not an argument list
    Statement p = parse("evaluate (a + q)*(a - q)\n");
    ASSERT_EQ(p.keyword, "evaluate");
    EXPECT_EQ(p.expr("value")->kind, Expr::Kind::product);
    Statement g = parse("gravity (-g*Ny>)\n");  // the parenthesised value, not a call
    ASSERT_EQ(g.keyword, "gravity");
    EXPECT_NE(g.expr("value")->kind, Expr::Kind::call);
    EXPECT_EQ(parse("digits (3 + 1)\n").keyword, "digits");
}

TEST(Parser, DeclarationsTakePrimesValuesAndUnits) {
    Statement s = parse("variable qA'', x' m/s\n");
    ASSERT_EQ(s.declared.size(), 2u);
    EXPECT_EQ(s.declared[0].name.text, "qA");
    EXPECT_EQ(s.declared[0].primes, 2);
    EXPECT_EQ(s.declared[1].primes, 1);
    EXPECT_EQ(s.declared[1].quantity.unit.factors.size(), 2u);
    EXPECT_EQ(s.declared[1].quantity.unit.factors[1].power, -1);
    Statement c = parse("constant g = 9.81 m/s^2, k\n");
    EXPECT_DOUBLE_EQ(c.declared[0].quantity.value->number, 9.81);
    EXPECT_EQ(c.declared[0].quantity.unit.factors[1].power, -2);
    EXPECT_FALSE(c.declared[1].quantity.value);
}

TEST(Parser, RotateFormsCarryTheirParts) {
    Statement a = parse("rotate B from A about -z by q\n");
    EXPECT_EQ(a.word("kind").text, "about");
    EXPECT_TRUE(a.flag("negative"));
    Statement b = parse("rotate B from A body ZXZ by p, q, r\n");
    EXPECT_EQ(b.word("sequence").text, "ZXZ");
    EXPECT_EQ(b.expr_lists.at("angles").size(), 3u);
    Statement c = parse("rotate B from A dcm [1, 0, 0; 0, 1, 0; 0, 0, 1]\n");
    EXPECT_EQ(c.expr("dcm")->kind, Expr::Kind::matrix);
    EXPECT_EQ(c.expr("dcm")->rows, 3);
}

TEST(Parser, SolveTakesAtAndGuessClauses) {
    Statement s = parse("solve E for x, y guess x = 1 m at z = 20 deg\n");
    EXPECT_EQ(s.lists.at("unknowns").size(), 2u);
    EXPECT_EQ(s.bindings.at("guess").size(), 1u);
    EXPECT_EQ(s.bindings.at("at")[0].quantity.unit.factors[0].name.text, "deg");
}

TEST(Parser, ErrorsSayWhatWasExpectedWhere) {
    try {
        parse("translate P to O by r>\n");
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), "expected 'from' (translate P from O by r>), found 'to'");
        EXPECT_EQ(e.where().column, 13);
    }
}

TEST(Parser, ReservedWordsIncludeStatementsClausesAndFunctions) {
    EXPECT_TRUE(is_reserved("body"));
    EXPECT_TRUE(is_reserved("from"));
    EXPECT_TRUE(is_reserved("cos"));
    EXPECT_FALSE(is_reserved("qA"));
}
