// SPDX-License-Identifier: MIT
// Autolev dyadics to the script's: D>> assigned, 1>> and 0>>, I_B_P>> (inertia dyadics), the
// dyad A1>*A2>, sums and scalar multiples, DOT with a vector or of two dyadics, and MATRIX and VECTOR between
// measures and vectors or dyadics.
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

namespace {

const char* text_kind(const Text& t) {
    return t.dyadic ? "a dyadic" : t.vector ? "a vector" : t.matrix() ? "a matrix" : "a scalar";
}

Text dyadic_text(std::string s, int prec, bool numeric = false) {
    Text t{std::move(s), false, prec, numeric};
    t.dyadic = true;
    return t;
}

}  // namespace

std::string Translator::unit_dyadic(const Expr& e) {
    // the unit dyadic is the same in every frame: the script names it in the Newtonian frame
    std::string F = newtonian_;
    for (const auto& [key, en] : objects_)
        if (F.empty() && (en.kind == Kind::frame || en.kind == Kind::body)) F = en.name;
    if (F.empty()) fail(e.where, "the unit dyadic needs a frame", "declare one: NEWTONIAN N");
    return "unitdyadic(" + F + ")";
}

Text Translator::inertia_about(const Expr& e, const std::string& b, const std::string& p) {
    const bool body = find_object(b) && find_object(b)->kind == Kind::body;
    if (body) need_placed_inertia(e.where, "the inertia of '" + b + "'", b);
    const std::string cm = body ? b + "cm" : b;
    if (body && p == cm) return dyadic_text("inertia(" + b + ")", 5);
    const std::string r = "pos(" + cm + ", " + p + ")";
    const std::string transfer =
        "mass(" + b + ")*(dot(" + r + ", " + r + ")*" + unit_dyadic(e) + " - outer(" + r + ", " + r + "))";
    return body ? dyadic_text("(inertia(" + b + ") + " + transfer + ")", 5) : dyadic_text(transfer, 2);
}

Text Translator::dyadic_name(const Expr& e) {
    if (e.primes) fail(e.where, "a prime on a dyadic", "the derivative of a dyadic is not translated");
    if (e.text == "1") return dyadic_text(unit_dyadic(e), 5, true);
    if (e.text == "0") return dyadic_text("0*" + unit_dyadic(e), 2, true);
    if (const Entry* en = find(e.text); en && en->kind == Kind::dyadic) return dyadic_text(en->name + ">>", 5, en->numeric);
    // I_B_P>>: the inertia dyadic of body B about P (its mass centre BO: inertia(B)), or of a
    // particle about P; about another point the parallel-axis term m (r.r 1 - r r), r from P to
    // the mass centre
    const std::string key = upper(e.text);
    if (key.rfind("I_", 0) == 0) {
        auto massive = [this](std::string_view n) -> std::optional<std::string> {
            const Entry* en = find_object(n);
            if (en && (en->kind == Kind::body || en->kind == Kind::particle)) return en->name;
            return std::nullopt;
        };
        auto pt = [this](std::string_view n) { return point_of(n); };
        if (auto s = split(std::string_view(e.text).substr(2), massive, pt)) return inertia_about(e, s->first, s->second);
    }
    fail(e.where, "the dyadic '" + e.text + ">>' is not defined",
         "dyadics are assigned before they are used (D>> = A1>*A2>); 1>> is the unit dyadic and I_B_BO>> "
         "the inertia of body B about its mass centre BO (I_B_P>> about a point P)");
}

void Translator::dyadic_assignment(const Statement& st) {
    const Expr& lhs = st.lhs;
    if (lhs.primes) fail(lhs.where, "a prime on a dyadic name", "assign the dyadic itself");
    const std::string key = upper(lhs.text);
    if (lhs.text == "0" || lhs.text == "1") fail(lhs.where, lhs.text + ">> cannot be assigned", "give the dyadic a name: D>> = ...");
    const Entry* existing = find(lhs.text);
    if (existing && existing->kind != Kind::dyadic)
        fail(lhs.where, "'" + lhs.text + "' is " + kind_word(existing->kind) + ", not a dyadic",
             "give the dyadic another name");
    if (!existing && key.rfind("I_", 0) == 0) {
        auto massive = [this](std::string_view n) -> std::optional<std::string> {
            const Entry* en = find_object(n);
            if (en && (en->kind == Kind::body || en->kind == Kind::particle)) return en->name;
            return std::nullopt;
        };
        auto pt = [this](std::string_view n) { return point_of(n); };
        if (split(std::string_view(lhs.text).substr(2), massive, pt))
            leave_out(lhs.where, "'" + lhs.text + ">>' is an inertia dyadic, which the model's masses and inertias "
                                 "give; an inertia assigned as a dyadic has no counterpart",
                      "give the body's inertia with INERTIA B, I11, I22, I33, or name the dyadic otherwise");
    }
    Text r = expr(st.rhs);
    if (!r.dyadic)
        fail(st.rhs.where, std::string(text_kind(r)) + " where a dyadic is expected",
             "form a dyadic: A1>*A2> (a dyad), 1>> (the unit dyadic), I_B_BO>> (an inertia), their sums and multiples");
    const Entry& e = existing ? *existing : add(lhs.text, Kind::dyadic, lhs.where);
    names_[e.key].numeric = r.numeric;
    emit(e.name + ">> = " + r.s);
}

Text Translator::dyadic_combine(const Expr& e, Text a, Text b) {
    const std::string& op = e.text;
    auto wrapped = [](Text& t, bool wrap) { return wrap ? "(" + std::move(t.s) + ")" : std::move(t.s); };
    if (op == "+" || op == "-") {
        if (!a.dyadic || !b.dyadic)
            fail(e.where, std::string("'") + op + "' between " + text_kind(a) + " and " + text_kind(b),
                 "both sides must be dyadics (A1>*A2>, 1>>, D>>)");
        bool wrap = b.prec == 3 || (op == "-" && b.prec <= 1);
        std::string s = std::move(a.s);
        s += " " + op + " ";
        s += wrapped(b, wrap);
        return dyadic_text(std::move(s), 1);
    }
    if (op == "*" && a.vector && b.vector) return dyadic_text("outer(" + a.s + ", " + b.s + ")", 5);
    if (op == "*" || op == "/") {
        if (a.dyadic && b.dyadic)
            leave_out(e.where, std::string("'") + op + "' between two dyadics has no counterpart",
                 "DOT(D>>, E>>) is their dot product, a dyadic; '*' between two vectors makes their dyad, and "
                 "between two dyadics a product the script has no counterpart of");
        const Text& other = a.dyadic ? b : a;
        if (op == "/" && b.dyadic) fail(e.where, "division by a dyadic", "divide the dyadic by a scalar instead");
        if (other.vector)
            fail(e.where, std::string("'") + op + "' between a dyadic and a vector",
                 "dot them: DOT(D>>, v>) or DOT(v>, D>>)");
        if (other.matrix())
            fail(e.where, std::string("'") + op + "' between a dyadic and a matrix",
                 "MATRIX(A, D>>) is the dyadic's matrix in frame A");
        std::string s = wrapped(a, a.prec < 2);
        s += op;
        s += wrapped(b, b.prec <= 3);
        return dyadic_text(std::move(s), 2);
    }
    fail(e.where, "a power of a dyadic", "dot the dyadic with vectors: DOT(D>>, v>)");
}

Text Translator::dyadic_dot(const Expr& e, const Text& a, const Text& b) {
    // D>> . E>> is a dyadic: (a b) . (c d) = (b.c) a d
    if (a.dyadic && b.dyadic) return dyadic_text("dot(" + a.s + ", " + b.s + ")", 5, a.numeric && b.numeric);
    const Text& other = a.dyadic ? b : a;
    if (!other.vector)
        fail(e.args[a.dyadic ? 1 : 0].where, std::string("DOT() takes a vector beside a dyadic, not ") + text_kind(other),
             "write DOT(D>>, v>) or DOT(v>, D>>)");
    return {"dot(" + a.s + ", " + b.s + ")", true, 5};
}

std::optional<Text> Translator::dyadic_call(const Expr& e, const std::string& f, bool& numeric) {
    if (f == "INERTIA") {
        // INERTIA(O): the inertia of every body and particle about O; INERTIA(O, B, P): of those
        if (e.args.empty()) fail(e.where, "INERTIA() takes the point first", "write INERTIA(O) or INERTIA(O, B, P)");
        const std::string p = point_name(e.args[0]);
        std::vector<const Entry*> of;
        if (e.args.size() == 1) {
            for (const auto& [key, en] : objects_)
                if (en.kind == Kind::body || en.kind == Kind::particle) of.push_back(&en);
            std::sort(of.begin(), of.end(), [](const Entry* a, const Entry* b) {
                return std::make_pair(a->where.line, a->where.column) < std::make_pair(b->where.line, b->where.column);
            });
        }
        for (std::size_t i = 1; i < e.args.size(); ++i) {
            const Expr& x = e.args[i];
            const Entry* en = x.kind == Expr::Kind::name && !x.vector && x.primes == 0 ? find_object(x.text) : nullptr;
            if (!en || (en->kind != Kind::body && en->kind != Kind::particle))
                fail(x.where, "INERTIA() takes bodies and particles after the point", "write INERTIA(O, B, P)");
            if (std::find(of.begin(), of.end(), en) != of.end())
                fail(x.where, "INERTIA(): '" + x.text + "' is listed twice", "list each body once");
            of.push_back(en);
        }
        if (of.empty()) fail(e.where, "INERTIA(): the model has no bodies or particles", "declare them: BODIES B");
        numeric = false;
        std::string s;
        for (const Entry* en : of) s += (s.empty() ? "" : " + ") + inertia_about(e, en->name, p).s;
        return dyadic_text(s, of.size() > 1 ? 1 : 5);
    }
    if (f != "MATRIX" && f != "VECTOR") return std::nullopt;
    if (e.args.size() != 2)
        fail(e.where, e.text + "() takes 2 arguments, not " + std::to_string(e.args.size()),
             f == "MATRIX" ? "write MATRIX(A, v>) or MATRIX(A, D>>)" : "write VECTOR(A, [X; Y; Z])");
    const std::string F = frame_name(e.args[0]);
    Text x = expr(e.args[1]);
    numeric = numeric && x.numeric;
    if (f == "MATRIX") {
        // the measures in F: of a vector a column, of a dyadic a 3 by 3 matrix
        if (!x.vector && !x.dyadic)
            fail(e.args[1].where, "MATRIX() takes a vector or a dyadic after the frame, not " + std::string(text_kind(x)),
                 "write MATRIX(A, v>) or MATRIX(A, D>>); a matrix of scalars is written by its elements [A, B; C, D]");
        const int cols = x.dyadic ? 3 : 1;
        return Text{"matrix(" + F + ", " + x.s + ")", false, 5, false, 3, cols};
    }
    // VECTOR(A, M): M's three elements as measures in A
    const bool three = x.matrix() && ((x.rows == 3 && x.cols == 1) || (x.rows == 1 && x.cols == 3) || x.rows < 0);
    if (!three)
        fail(e.args[1].where,
             "VECTOR() takes a matrix of three elements (a row or a column) after the frame, not " +
                 (x.matrix() ? "a " + std::to_string(x.rows) + " by " + std::to_string(x.cols) + " matrix"
                             : std::string(text_kind(x))),
             "write VECTOR(A, [X; Y; Z])");
    return Text{"vector(" + F + ", " + x.s + ")", true, 5};
}

}  // namespace alembert::lang::autolev
