// SPDX-License-Identifier: MIT
// The parser: one statement's tokens to a Statement, expressions by precedence climbing.
#include "alembert/lang/parser.hpp"

#include "alembert/lang/units.hpp"

#include <algorithm>
#include <set>

namespace alembert::lang {

namespace {

const std::set<std::string, std::less<>>& clause_words() {
    static const std::set<std::string, std::less<>> w{
        "from", "about", "by", "on", "in", "to", "and", "between", "stiffness", "length",
        "coefficient", "linear", "quadratic", "normal", "along", "configuration", "motion",
        "for", "statics", "rotate", "translate", "speeds", "kinematics", "constraints",
        "dependent", "auxiliary", "at", "guess", "fixed", "moving", "dcm", "t", "when", "rising",
        "falling", "cutoff", "compiled", "rel"};
    return w;
}

const std::set<std::string, std::less<>>& function_words() {
    static const std::set<std::string, std::less<>> w{
        "sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "exp", "log", "abs", "dot", "cross",
        "express", "dt", "mag", "unit", "simplify", "expand", "angvel", "angacc", "vel", "acc",
        "pos", "rotation", "mass", "momentum", "angmomentum", "kinetic", "potential",
        "resultant", "moment", "pi", "minimum_jerk"};
    return w;
}

// walks the tokens of one statement
class Parser {
public:
    Parser(const std::vector<Token>& tokens, std::string_view source) : t_(tokens), src_(source) {}

    Statement parse();

private:
    const Token& peek(std::size_t ahead = 0) const {
        return t_[std::min(i_ + ahead, t_.size() - 1)];
    }
    const Token& next() {
        const Token& t = peek();
        if (i_ + 1 < t_.size()) ++i_;
        return t;
    }
    bool at_end() const { return peek().kind == TokenKind::end; }
    bool at_word(std::string_view w) const { return peek().kind == TokenKind::name && peek().text == w; }
    bool accept_punct(std::string_view p) {
        if (!peek().is(p)) return false;
        next();
        return true;
    }
    bool accept_word(std::string_view w) {
        if (!at_word(w)) return false;
        next();
        return true;
    }
    [[noreturn]] void fail_expected(const std::string& what) const;
    void expect_punct(std::string_view p, const std::string& context);
    void expect_word(std::string_view w, const std::string& context);
    void expect_end(const std::string& context);
    Word name(const std::string& what);
    Word text(const std::string& what);
    std::vector<Word> name_list(const std::string& what);
    UnitText unit();
    Quantity quantity();
    std::vector<Binding> bindings(const std::string& what);
    std::vector<Declared> declarations(const std::string& keyword);

    ExprPtr expression();
    ExprPtr sum();
    ExprPtr term();
    ExprPtr unary();
    ExprPtr power();
    ExprPtr primary();
    std::vector<ExprPtr> expression_list(const std::string& context);

    void statement_body(Statement& s);

    const std::vector<Token>& t_;
    std::string_view src_;
    std::size_t i_ = 0;
    int depth_ = 0;
    std::string keyword_;
};

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::end: return "the end of the statement";
        case TokenKind::number: return "the number " + t.text;
        case TokenKind::string: return "the text \"" + t.text + "\"";
        case TokenKind::vector_name: return "the vector " + t.text + ">";
        case TokenKind::zero_vector: return "0>";
        case TokenKind::punct: return "'" + t.text + "'";
        default: return "'" + t.text + "'";
    }
}

void Parser::fail_expected(const std::string& what) const {
    std::string hint;
    if (!keyword_.empty() && keyword_ != "=")
        hint = "see docs/language.md for the form of '" + keyword_ + "' statements";
    throw ScriptError(peek().location, "expected " + what + ", found " + describe(peek()), hint);
}

void Parser::expect_punct(std::string_view p, const std::string& context) {
    if (!accept_punct(p)) fail_expected("'" + std::string(p) + "' " + context);
}

void Parser::expect_word(std::string_view w, const std::string& context) {
    if (!accept_word(w)) fail_expected("'" + std::string(w) + "' " + context);
}

void Parser::expect_end(const std::string& context) {
    if (!at_end() && i_ > 0 && t_[i_ - 1].kind == TokenKind::number && peek().kind == TokenKind::name &&
        find_unit(peek().text))
        throw ScriptError(peek().location,
                          "a unit may follow a number only in a constant's declaration or after 'at' "
                          "or 'guess'",
                          "declare a constant with the value and unit, e.g. constant I_A = 0.1 kg*m^2");
    if (!at_end()) {
        throw ScriptError(peek().location,
                          "unexpected " + describe(peek()) + " after " + context,
                          "one statement per line, or separate statements with ';'");
    }
}

Word Parser::name(const std::string& what) {
    if (peek().kind != TokenKind::name) fail_expected(what);
    const Token& t = next();
    return {t.text, t.location};
}

Word Parser::text(const std::string& what) {
    if (peek().kind != TokenKind::string) fail_expected(what + " in double quotes");
    const Token& t = next();
    if (t.text.empty()) throw ScriptError(t.location, "the " + what + " is empty", "write a path such as \"out\"");
    return {t.text, t.location};
}

std::vector<Word> Parser::name_list(const std::string& what) {
    std::vector<Word> out{name(what)};
    while (accept_punct(",")) out.push_back(name(what));
    return out;
}

UnitText Parser::unit() {
    UnitText u;
    u.location = peek().location;
    bool divide = false;
    for (;;) {
        if (peek().kind != TokenKind::name) fail_expected("a unit name (m, kg, s, N, deg, ...)");
        UnitText::Factor f;
        const Token& n = next();
        f.name = {n.text, n.location};
        if (accept_punct("^")) {
            bool minus = accept_punct("-");
            if (peek().kind != TokenKind::number || peek().text.find_first_not_of("0123456789") != std::string::npos ||
                peek().text.size() > 2)
                fail_expected("a small whole number as the power of a unit");
            f.power = std::stoi(next().text) * (minus ? -1 : 1);
        }
        if (divide) f.power = -f.power;
        u.factors.push_back(f);
        if (peek().is("*") && peek(1).kind == TokenKind::name) {
            next();
            continue;
        }
        if (peek().is("/") && peek(1).kind == TokenKind::name) {
            next();
            divide = true;
            continue;
        }
        return u;
    }
}

Quantity Parser::quantity() {
    Quantity q;
    q.value = expression();
    if (peek().kind == TokenKind::name && !clause_words().count(peek().text)) q.unit = unit();
    return q;
}

std::vector<Binding> Parser::bindings(const std::string& what) {
    std::vector<Binding> out;
    do {
        Binding b;
        b.name = name(what);
        expect_punct("=", "after '" + b.name.text + "' (give its value: name = value)");
        b.quantity = quantity();
        out.push_back(std::move(b));
    } while (accept_punct(","));
    return out;
}

std::vector<Declared> Parser::declarations(const std::string& keyword) {
    std::vector<Declared> out;
    do {
        Declared d;
        Word w = name("a name to declare");
        std::size_t primes = w.text.size() - std::min(w.text.size(), w.text.find('\''));
        if (w.text.find('\'') == std::string::npos) primes = 0;
        d.primes = static_cast<int>(primes);
        d.name = {w.text.substr(0, w.text.size() - primes), w.location};
        if (accept_punct("=")) {
            d.quantity = quantity();
        } else if (peek().kind == TokenKind::name) {
            d.quantity.unit = unit();
        }
        (void)keyword;
        out.push_back(std::move(d));
    } while (accept_punct(","));
    return out;
}

std::vector<ExprPtr> Parser::expression_list(const std::string& context) {
    std::vector<ExprPtr> out;
    (void)context;
    out.push_back(expression());
    while (accept_punct(",")) out.push_back(expression());
    return out;
}

// ---- expressions -----------------------------------------------------------------------

struct DepthGuard {
    int& depth;
    DepthGuard(int& d, Location where) : depth(d) {
        if (++depth > Limits::max_nesting)
            throw ScriptError(where, "the expression is nested too deeply (more than " +
                                         std::to_string(Limits::max_nesting) + " levels)",
                              "name parts of it with assignments");
    }
    ~DepthGuard() { --depth; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
};

ExprPtr Parser::expression() { return sum(); }

ExprPtr Parser::sum() {
    Location where = peek().location;
    ExprPtr first = term();
    if (!peek().is("+") && !peek().is("-")) return first;
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::sum;
    node->location = where;
    node->args.push_back(std::move(first));
    node->inverted.push_back(false);
    while (peek().is("+") || peek().is("-")) {
        bool minus = next().text == "-";
        node->args.push_back(term());
        node->inverted.push_back(minus);
    }
    return node;
}

ExprPtr Parser::term() {
    Location where = peek().location;
    ExprPtr first = unary();
    if (!peek().is("*") && !peek().is("/")) return first;
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::product;
    node->location = where;
    node->args.push_back(std::move(first));
    node->inverted.push_back(false);
    while (peek().is("*") || peek().is("/")) {
        bool divide = next().text == "/";
        node->args.push_back(unary());
        node->inverted.push_back(divide);
    }
    return node;
}

ExprPtr Parser::unary() {
    if (peek().is("-") || peek().is("+")) {
        Location where = peek().location;
        DepthGuard guard(depth_, where);
        bool minus = next().text == "-";
        ExprPtr operand = unary();
        if (!minus) return operand;
        auto node = std::make_unique<Expr>();
        node->kind = Expr::Kind::negate;
        node->location = where;
        node->args.push_back(std::move(operand));
        return node;
    }
    return power();
}

ExprPtr Parser::power() {
    ExprPtr base = primary();
    if (!peek().is("^")) return base;
    Location where = peek().location;
    next();
    DepthGuard guard(depth_, where);
    auto node = std::make_unique<Expr>();
    node->kind = Expr::Kind::power;
    node->location = where;
    node->args.push_back(std::move(base));
    node->args.push_back(unary());
    return node;
}

ExprPtr Parser::primary() {
    const Token& t = peek();
    auto node = std::make_unique<Expr>();
    node->location = t.location;
    switch (t.kind) {
        case TokenKind::number:
            node->kind = Expr::Kind::number;
            node->number = t.number;
            node->number_text = t.text;
            next();
            return node;
        case TokenKind::zero_vector:
            node->kind = Expr::Kind::zero_vector;
            next();
            return node;
        case TokenKind::vector_name:
            node->kind = Expr::Kind::vector_name;
            node->text = t.text;
            next();
            return node;
        case TokenKind::name: {
            node->text = t.text;
            next();
            if (peek().is("(")) {
                DepthGuard guard(depth_, peek().location);
                next();
                node->kind = Expr::Kind::call;
                if (!peek().is(")")) node->args = expression_list("as arguments");
                expect_punct(")", "to close the arguments of " + node->text + "(...)");
                return node;
            }
            if (peek().is("[")) {
                DepthGuard guard(depth_, peek().location);
                next();
                node->kind = Expr::Kind::index;
                node->args.push_back(expression());
                expect_punct("]", "after the index of " + node->text);
                return node;
            }
            node->kind = Expr::Kind::name;
            return node;
        }
        case TokenKind::punct:
            if (t.is("(")) {
                DepthGuard guard(depth_, t.location);
                next();
                ExprPtr inner = expression();
                expect_punct(")", "to close '(' at " + std::to_string(node->location.line) + ":" +
                                      std::to_string(node->location.column));
                return inner;
            }
            if (t.is("[")) {
                DepthGuard guard(depth_, t.location);
                next();
                node->kind = Expr::Kind::list;
                int rows = 1;
                std::size_t per_row = 0;
                if (!peek().is("]")) {
                    for (;;) {
                        node->args.push_back(expression());
                        if (accept_punct(",")) continue;
                        if (peek().is(";")) {
                            Location semi = peek().location;
                            next();
                            if (per_row == 0) per_row = node->args.size();
                            if (node->args.size() != per_row * static_cast<std::size_t>(rows))
                                throw ScriptError(semi, "the rows of the matrix have different lengths",
                                                  "give every row the same number of entries");
                            ++rows;
                            continue;
                        }
                        break;
                    }
                }
                Location close = peek().location;
                expect_punct("]", "to close the list");
                if (rows > 1) {
                    if (node->args.size() != per_row * static_cast<std::size_t>(rows))
                        throw ScriptError(close, "the rows of the matrix have different lengths",
                                          "give every row the same number of entries");
                    node->kind = Expr::Kind::matrix;
                    node->rows = rows;
                }
                return node;
            }
            break;
        default: break;
    }
    fail_expected("a value (a number, a name, a vector such as Ax>, or '(')");
}

// ---- statements ------------------------------------------------------------------------

void Parser::statement_body(Statement& s) {
    const std::string& k = s.keyword;
    auto lists_of = [&](const char* role, const std::string& what) { s.lists[role] = name_list(what); };
    if (k == "newtonian") {
        s.words["name"] = name("the name of the Newtonian frame");
    } else if (k == "frame" || k == "body" || k == "particle" || k == "point") {
        lists_of("names", "a name for the new " + k);
        if (k == "point" && accept_word("on")) s.words["on"] = name("the body the points are on");
    } else if (k == "constant" || k == "variable" || k == "specified" || k == "unknown") {
        s.declared = declarations(k);
    } else if (k == "coordinates") {
        lists_of("names", "a variable");
    } else if (k == "system") {
        s.words["name"] = name("a name for the system");
        expect_punct("=", "after the system's name (system S = A, B, C)");
        lists_of("bodies", "a body or particle");
    } else if (k == "rotate") {
        s.words["target"] = name("the frame or body to orient");
        expect_word("from", "(rotate B from A ...)");
        s.words["from"] = name("the frame it is oriented from");
        if (accept_word("about")) {
            s.words["kind"] = {"about", peek().location};
            if (accept_punct("-")) s.flags["negative"] = true;
            s.words["axis"] = name("an axis: x, y or z");
            expect_word("by", "and the angle (rotate B from A about z by q)");
            s.expr_lists["angles"].push_back(expression());
        } else if (at_word("body") || at_word("space")) {
            s.words["kind"] = {next().text, peek().location};
            s.words["sequence"] = name("a rotation sequence such as XYZ or ZXZ");
            expect_word("by", "and three angles (rotate B from A body XYZ by q1, q2, q3)");
            s.expr_lists["angles"] = expression_list("angles");
        } else if (accept_word("dcm")) {
            s.words["kind"] = {"dcm", peek().location};
            s.exprs["dcm"] = expression();
        } else {
            fail_expected("'about', 'body', 'space' or 'dcm'");
        }
    } else if (k == "translate") {
        s.words["target"] = name("the point to locate");
        expect_word("from", "(translate P from O by r>)");
        s.words["from"] = name("the point it is located from");
        expect_word("by", "and the position vector (translate P from O by r>)");
        s.exprs["value"] = expression();
    } else if (k == "velocity" || k == "acceleration" || k == "angvel" || k == "angacc") {
        s.words["target"] = name(k == "angvel" || k == "angacc" ? "a frame or body" : "a point");
        expect_word("in", "and the frame (" + k + " P in N = ...)");
        s.words["in"] = name("a frame");
        if ((k == "velocity" || k == "acceleration") && accept_word("from")) {
            s.words["from"] = name("a point fixed on the body");
            if (accept_word("fixed")) s.words["how"] = {"fixed", peek().location};
            else if (k == "velocity" && accept_word("moving")) s.words["how"] = {"moving", peek().location};
            else fail_expected(k == "velocity" ? "'fixed' or 'moving'" : "'fixed'");
            expect_word("on", "and the body (... fixed on B)");
            s.words["on"] = name("a frame or body");
        } else {
            expect_punct("=", "and the vector (" + k + " P in N = v>)");
            s.exprs["value"] = expression();
        }
    } else if (k == "mass") {
        s.words["target"] = name("a body or particle");
        expect_punct("=", "and the mass (mass A = m_A)");
        s.exprs["value"] = expression();
    } else if (k == "inertia") {
        s.words["target"] = name("a rigid body");
        expect_punct("=", "and the moments (inertia A = Ixx, Iyy, Izz)");
        s.expr_lists["moments"] = expression_list("moments");
        if (accept_word("about")) s.words["about"] = name("a point");
        if (accept_word("in")) s.words["in"] = name("a frame");
    } else if (k == "gravity") {
        s.exprs["value"] = expression();
    } else if (k == "force" || k == "torque") {
        s.words["label"] = name("a label for the " + k);
        expect_word("on", "and what it acts on (" + k + " F on P = ...)");
        s.words["on"] = name(k == "force" ? "a point" : "a body");
        if (accept_word("from")) s.words["from"] = name(k == "force" ? "a point" : "a frame or body");
        expect_punct("=", "and the " + k + " vector");
        s.exprs["value"] = expression();
    } else if (k == "spring" || k == "damper" || k == "attraction") {
        s.words["label"] = name("a label");
        expect_word("between", "(" + k + " label between P and Q ...)");
        s.words["P"] = name("a point");
        expect_word("and", "between the two points");
        s.words["Q"] = name("a point");
        if (k == "spring") {
            expect_word("stiffness", "(spring k1 between P and Q stiffness k length L0)");
            s.exprs["stiffness"] = expression();
            expect_word("length", "and the natural length");
            s.exprs["length"] = expression();
        } else if (k == "damper") {
            expect_word("coefficient", "(damper c1 between P and Q coefficient c)");
            s.exprs["coefficient"] = expression();
        } else {
            expect_word("constant", "(attraction G1 between P and Q constant G)");
            s.exprs["constant"] = expression();
        }
    } else if (k == "drag") {
        s.words["label"] = name("a label");
        expect_word("on", "(drag air on P linear c)");
        s.words["on"] = name("a point");
        if (at_word("linear") || at_word("quadratic")) s.words["law"] = {next().text, peek().location};
        else fail_expected("'linear' or 'quadratic'");
        s.exprs["coefficient"] = expression();
    } else if (k == "friction") {
        s.words["label"] = name("a label");
        expect_word("on", "(friction f on P from Q coefficient mu normal Fn along u>)");
        s.words["on"] = name("a point");
        expect_word("from", "and the point it slides on");
        s.words["from"] = name("a point");
        expect_word("coefficient", "and the friction coefficient");
        s.exprs["coefficient"] = expression();
        expect_word("normal", "and the normal force");
        s.exprs["normal"] = expression();
        expect_word("along", "and the sliding direction");
        s.exprs["along"] = expression();
    } else if (k == "constraint") {
        if (at_word("configuration") || at_word("motion")) s.words["kind"] = {next().text, peek().location};
        else fail_expected("'configuration' or 'motion'");
        s.words["name"] = name("a name for the constraint");
        expect_punct("=", "and the residual (constraint configuration c = expression)");
        s.exprs["value"] = expression();
        if (accept_word("in")) s.words["in"] = name("a frame");
    } else if (k == "roadmap") {
        s.words["name"] = name("a name for the road-map's equations");
        if (accept_word("for")) {
            lists_of("unknowns", "an unknown");
            if (accept_word("statics")) s.flags["statics"] = true;
        }
    } else if (k == "row") {
        s.words["name"] = name("the road-map the row belongs to");
        expect_word("for", "and the unknown (row E for T_A rotate S about A_o along Nz>)");
        s.words["variable"] = name("the unknown of the row");
        if (accept_word("rotate")) {
            s.words["motion"] = {"rotate", peek().location};
            s.words["system"] = name("a system or body");
            expect_word("about", "and the about point");
            s.words["about"] = name("a point");
            expect_word("along", "and the direction");
            s.exprs["direction"] = expression();
        } else if (accept_word("translate")) {
            s.words["motion"] = {"translate", peek().location};
            s.words["system"] = name("a system or body");
            expect_word("along", "and the direction");
            s.exprs["direction"] = expression();
        } else if (accept_word("constraint")) {
            s.words["motion"] = {"constraint", peek().location};
            s.words["constraint"] = name("a declared constraint");
        } else {
            fail_expected("'rotate', 'translate' or 'constraint'");
        }
        if (accept_word("statics")) s.flags["statics"] = true;
    } else if (k == "kane" || k == "lagrange") {
        s.words["name"] = name("a name for the equations");
        expect_word("for", "and the coordinates (" + k + " K for q1, q2)");
        lists_of("coordinates", "a coordinate");
        while (k == "kane" && !at_end()) {
            if (accept_word("speeds")) lists_of("speeds", "a speed");
            else if (accept_word("kinematics")) s.exprs["kinematics"] = expression();
            else if (accept_word("constraints")) s.exprs["constraints"] = expression();
            else if (accept_word("dependent")) lists_of("dependent", "a speed");
            else if (accept_word("auxiliary")) lists_of("auxiliary", "a speed");
            else fail_expected("'speeds', 'kinematics', 'constraints', 'dependent' or 'auxiliary'");
        }
    } else if (k == "solve") {
        s.words["name"] = name("the equations to solve");
        expect_word("for", "and the unknowns (solve E for x, y)");
        lists_of("unknowns", "an unknown");
        while (!at_end()) {
            if (accept_word("guess")) s.bindings["guess"] = bindings("an unknown");
            else if (accept_word("at")) s.bindings["at"] = bindings("a symbol");
            else fail_expected("'at' or 'guess'");
        }
    } else if (k == "evaluate") {
        s.exprs["value"] = expression();
        if (accept_word("at")) s.bindings["at"] = bindings("a symbol");
    } else if (k == "initial") {
        s.bindings["values"] = bindings("a coordinate or its rate (initial qA = 30 deg, qA' = 0)");
    } else if (k == "input") {
        s.bindings["values"] = bindings("a load measure (input T_A = -k*qA)");
    } else if (k == "motion") {
        s.bindings["values"] = bindings("a coordinate (motion qA = 30*sin(t) deg)");
    } else if (k == "final") {
        expect_word("time", "(final time 5 s)");
        s.quantities["time"] = quantity();
    } else if (k == "tolerance") {
        if (at_end())
            throw ScriptError(s.location, "a tolerance statement needs 'abs' or 'rel' and a number",
                              "write tolerance abs 1e-10 rel 1e-10");
        while (!at_end()) {
            if (accept_word("abs")) s.quantities["abs"] = quantity();
            else if (accept_word("rel")) s.quantities["rel"] = quantity();
            else fail_expected("'abs' or 'rel' and a number (tolerance abs 1e-10 rel 1e-10)");
        }
    } else if (k == "output") {
        if (at_word("step") && peek(1).kind == TokenKind::number) {
            next();
            s.quantities["step"] = quantity();
        } else {
            do {
                Word label{};
                if (peek().kind == TokenKind::name && peek(1).is("=")) {
                    label = name("a column name");
                    next();
                }
                s.lists["labels"].push_back(label);
                s.expr_lists["values"].push_back(expression());
                s.units.push_back(accept_word("in") ? unit() : UnitText{});
            } while (accept_punct(","));
        }
    } else if (k == "stop") {
        expect_word("when", "(stop when qA = 0 [rising | falling])");
        s.exprs["lhs"] = expression();
        expect_punct("=", "and the value it crosses (stop when qA = 0)");
        s.quantities["rhs"] = quantity();
        if (at_word("rising") || at_word("falling")) s.words["direction"] = {peek().text, peek().location}, next();
    } else if (k == "simulate" || k == "inverse" || k == "codegen") {
        if (k == "codegen") s.words["language"] = name("a language: c, cpp, matlab or python");
        while (!at_end()) {
            if (k == "inverse" && accept_word("for")) lists_of("loads", "a load measure");
            else if (k == "codegen" && accept_word("for")) lists_of("loads", "a load measure");
            else if (k == "inverse" && accept_word("from")) {
                s.words["from"] = text("the motion table's path");
                if (accept_word("cutoff")) s.quantities["cutoff"] = quantity();
            } else if (k == "codegen" && accept_word("name")) s.words["name"] = name("an identifier for the files");
            else if (k != "codegen" && accept_word("compiled")) s.flags["compiled"] = true;
            else if (accept_word("to")) s.words["to"] = text("the output directory");
            else fail_expected(k == "simulate" ? "'compiled' or 'to'"
                               : k == "inverse" ? "'for', 'from', 'compiled' or 'to'"
                                                : "'for', 'name' or 'to'");
        }
        if (k == "inverse" && !s.lists.count("loads"))
            throw ScriptError(s.location, "inverse dynamics needs the load measures to solve for",
                              "write inverse for T_A, T_B");
    }
    expect_end("the '" + k + "' statement");
}

Statement Parser::parse() {
    Statement s;
    const Token& first = peek();
    s.location = first.location;
    std::size_t last = t_.size() >= 2 ? t_.size() - 2 : 0;
    // the statement's text, with a comment that ends its line
    std::size_t end = t_[last].end;
    std::size_t k = end;
    while (k < src_.size() && (src_[k] == ' ' || src_[k] == '\t')) ++k;
    if (k < src_.size() && src_[k] == '#') {
        end = src_.find('\n', k);
        if (end == std::string_view::npos) end = src_.size();
        while (end > k && src_[end - 1] == '\r') --end;
    }
    s.source = std::string(src_.substr(first.begin, end - first.begin));
    if (first.kind == TokenKind::comment) {
        s.keyword = "#";
        s.source = first.text;
        return s;
    }
    const auto& kw = statement_keywords();
    bool keyword = first.kind == TokenKind::name &&
                   std::find(kw.begin(), kw.end(), first.text) != kw.end() &&
                   !peek(1).is("(") && !peek(1).is("=");
    if (keyword) {
        s.keyword = first.text;
        keyword_ = s.keyword;
        next();
        statement_body(s);
        return s;
    }
    if ((first.kind == TokenKind::name || first.kind == TokenKind::vector_name) && peek(1).is("=")) {
        s.keyword = "=";
        s.words["target"] = {first.text, first.location};
        if (first.kind == TokenKind::vector_name) s.flags["vector"] = true;
        next();
        next();
        s.exprs["value"] = expression();
        expect_end("the assignment");
        return s;
    }
    if (first.kind == TokenKind::name && !peek(1).is("(") && !peek(1).is("[") &&
        peek(1).kind == TokenKind::name && clause_words().count(first.text) == 0)
        throw ScriptError(first.location, "unknown statement '" + first.text + "'",
                          "statements start with a word such as body, rotate, kane or solve "
                          "(docs/language.md), or are assignments name = value");
    s.exprs["value"] = expression();
    expect_end("the expression");
    return s;
}

}  // namespace

const std::vector<std::string>& statement_keywords() {
    static const std::vector<std::string> k{
        "newtonian", "frame", "body", "particle", "point", "constant", "variable", "specified",
        "unknown", "coordinates", "system", "rotate", "translate", "velocity", "acceleration",
        "angvel", "angacc", "mass", "inertia", "gravity", "force", "torque", "spring", "damper",
        "drag", "friction", "attraction", "constraint", "roadmap", "row", "kane", "lagrange",
        "solve", "evaluate", "initial", "input", "motion", "final", "tolerance", "output", "stop",
        "simulate", "inverse", "codegen"};
    return k;
}

bool is_reserved(std::string_view name) {
    const auto& kw = statement_keywords();
    return std::find(kw.begin(), kw.end(), name) != kw.end() || clause_words().count(name) != 0 ||
           function_words().count(name) != 0;
}

Statement parse_statement(const std::vector<Token>& tokens, std::string_view source) {
    if (tokens.empty() || tokens.back().kind != TokenKind::end)
        throw ScriptError({}, "internal: a statement must end with an end token");
    return Parser(tokens, source).parse();
}

}  // namespace alembert::lang
