// SPDX-License-Identifier: MIT
// The kinematics statements (orientations, positions, velocities, accelerations) and the
// constraints: each statement's grammar, meaning and help, and their tables.
#include <algorithm>

#include "alembert/mech/model_checks.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

Axis axis_of(const Word& w) {
    if (w.text == "x") return Axis::x;
    if (w.text == "y") return Axis::y;
    if (w.text == "z") return Axis::z;
    throw ScriptError(w.location, "'" + w.text + "' is not an axis", "write x, y or z (or -z)");
}

// ---- rotate ------------------------------------------------------------------------------

void parse_rotate(StatementParser& p, Statement& s) {
    s.words["target"] = p.name("the frame or body to orient");
    p.expect_word("from", "(rotate B from A ...)");
    s.words["from"] = p.name("the frame it is oriented from");
    if (p.accept_word("about")) {
        s.words["kind"] = {"about", p.peek().location};
        if (p.accept_punct("-")) s.flags["negative"] = true;
        s.words["axis"] = p.name("an axis: x, y or z");
        p.expect_word("by", "and the angle (rotate B from A about z by q)");
        s.expr_lists["angles"].push_back(p.expression());
    } else if (p.at_word("body") || p.at_word("space")) {
        s.words["kind"] = p.take_word();
        s.words["sequence"] = p.name("a rotation sequence such as XYZ or ZXZ");
        p.expect_word("by", "and three angles (rotate B from A body XYZ by q1, q2, q3)");
        s.expr_lists["angles"] = p.expression_list();
    } else if (p.accept_word("dcm")) {
        s.words["kind"] = {"dcm", p.peek().location};
        s.exprs["dcm"] = p.expression();
    } else {
        p.fail_expected("'about', 'body', 'space' or 'dcm'");
    }
}

void run_rotate(Interpreter::Impl& m, const Statement& s) {
    const Word& target = s.word("target");
    const Word& from = s.word("from");
    Frame& B = m.frame(target);
    Frame& A = m.frame(from);
    // one orientation per frame: a second would silently replace the first (and the
    // coordinates of the first would drop out of every equation)
    if (auto first = m.oriented.find(&B); first != m.oriented.end())
        throw ScriptError(target.location,
                          "'" + target.text + "' is already oriented from '" + first->second.text + "'" +
                              at_line(first->second.location) +
                              "; a frame has one orientation, and this rotate would replace it",
                          "remove one of the two rotate statements, or orient a new frame (frame " +
                              target.text + "2) from " + from.text);
    const std::string& kind = s.word("kind").text;
    auto angle = [&](const ExprPtr& e) { return m.scalar(*e, Dimension::none(), "the rotation angle"); };
    static const std::vector<ExprPtr> none;
    const auto& angles = s.expr_lists.count("angles") ? s.expr_lists.at("angles") : none;
    Location where = from.location;
    if (kind == "about") {
        Axis axis = axis_of(s.word("axis"));
        ex q = angle(angles.at(0));
        m.guard(where, [&] { B.orient_axis(A, axis, q, s.flag("negative") ? Sense::negative : Sense::positive); });
    } else if (kind == "body" || kind == "space") {
        const Word& seq = s.word("sequence");
        RotationSequence rs = m.guard(seq.location, [&] { return parse_rotation_sequence(seq.text); });
        if (angles.size() != 3)
            throw ScriptError(angles.size() > 3 ? angles[3]->location : s.word("sequence").location,
                              "a " + kind + "-fixed sequence takes 3 angles, not " +
                                  std::to_string(angles.size()),
                              "write: rotate " + target.text + " from " + from.text + " " + kind +
                                  " " + seq.text + " by q1, q2, q3");
        ex q1 = angle(angles[0]), q2 = angle(angles[1]), q3 = angle(angles[2]);
        m.guard(where, [&] {
            if (kind == "body") B.orient_body_fixed(A, rs, q1, q2, q3);
            else B.orient_space_fixed(A, rs, q1, q2, q3);
        });
    } else {
        Value v = m.eval(*s.exprs.at("dcm"));
        if (v.kind != Value::Kind::matrix || v.rows != 3 || v.cols != 3)
            throw ScriptError(s.exprs.at("dcm")->location,
                              "a direction-cosine matrix must be 3 by 3, written [a, b, c; d, e, f; g, h, i]",
                              "separate the rows with ';'");
        m.check_dimension(v.dim, Dimension::none(), "a direction-cosine matrix", s.exprs.at("dcm")->location);
        m.guard(where, [&] {
            check_direction_cosines(m.model(where).symbols(), v.m, target.text, from.text);
            B.orient_dcm(A, v.m);
        });
    }
    m.oriented[&B] = from;
}

// ---- translate ---------------------------------------------------------------------------

void parse_translate(StatementParser& p, Statement& s) {
    s.words["target"] = p.name("the point to locate");
    p.expect_word("from", "(translate P from O by r>)");
    s.words["from"] = p.name("the point it is located from");
    p.expect_word("by", "and the position vector (translate P from O by r>)");
    s.exprs["value"] = p.expression();
}

void run_translate(Interpreter::Impl& m, const Statement& s) {
    Point& P = m.point(s.word("target"));
    Point& O = m.point(s.word("from"));
    Vector r = m.vector(*s.exprs.at("value"), Dimension::length(), "the position of " + s.word("target").text);
    m.guard(s.word("from").location, [&] { P.set_pos(O, r); });
}

// ---- velocity, acceleration, angvel, angacc ----------------------------------------------

void parse_rate(StatementParser& p, Statement& s) {
    const std::string& k = s.keyword;
    s.words["target"] = p.name(k == "angvel" || k == "angacc" ? "a frame or body" : "a point");
    p.expect_word("in", "and the frame (" + k + " P in N = ...)");
    s.words["in"] = p.name("a frame");
    if ((k == "velocity" || k == "acceleration") && p.accept_word("from")) {
        s.words["from"] = p.name("a point fixed on the body");
        if (p.accept_word("fixed")) s.words["how"] = {"fixed", p.peek().location};
        else if (k == "velocity" && p.accept_word("moving")) s.words["how"] = {"moving", p.peek().location};
        else p.fail_expected(k == "velocity" ? "'fixed' or 'moving'" : "'fixed'");
        p.expect_word("on", "and the body (... fixed on B)");
        s.words["on"] = p.name("a frame or body");
    } else {
        p.expect_punct("=", "and the vector (" + k + " P in N = v>)");
        s.exprs["value"] = p.expression();
    }
}

void run_point_rate(Interpreter::Impl& m, const Statement& s) {
    const Dimension L = Dimension::length(), T = Dimension::time();
    Point& P = m.point(s.word("target"));
    Frame& N = m.frame(s.word("in"));
    bool acc = s.keyword == "acceleration";
    if (s.has_word("from")) {
        Point& O = m.point(s.word("from"));
        Frame& B = m.frame(s.word("on"));
        const std::string& how = s.word("how").text;
        m.guard(s.word("from").location, [&] {
            if (acc) P.set_acc_two_point(N, O, B);
            else if (how == "fixed") P.set_vel_two_point(N, O, B);
            else P.set_vel_one_point(N, O, B);
        });
        return;
    }
    Vector v = m.vector(*s.exprs.at("value"), acc ? L / pow(T, 2) : L / T,
                        acc ? "an acceleration" : "a velocity");
    m.guard(s.word("in").location, [&] { acc ? P.set_acc(N, v) : P.set_vel(N, v); });
}

void run_frame_rate(Interpreter::Impl& m, const Statement& s) {
    const Dimension T = Dimension::time();
    Frame& B = m.frame(s.word("target"));
    Frame& A = m.frame(s.word("in"));
    bool acc = s.keyword == "angacc";
    Vector w = m.vector(*s.exprs.at("value"), acc ? pow(T, -2) : pow(T, -1),
                        acc ? "an angular acceleration" : "an angular velocity");
    const Frame* P = B.parent();
    if (P == nullptr || P == &A) {
        m.guard(s.word("in").location, [&] { acc ? B.set_ang_acc(A, w) : B.set_ang_vel(A, w); });
        return;
    }
    // in a frame A other than the parent P, by the addition theorem:
    //   w_B_P = w_B_A - w_P_A,  alf_B_P = alf_B_A - alf_P_A - w_P_A x w_B_P
    // which needs P's motion in A not to pass through B
    for (const Frame* f = &A; f != nullptr; f = f->parent())
        if (f == &B)
            throw ScriptError(s.word("in").location,
                              "'" + A.name() + "' is oriented relative to '" + B.name() + "', so the " +
                                  (acc ? "angular acceleration" : "angular velocity") + " of " + B.name() +
                                  " in " + A.name() + " depends on itself",
                              "give it in " + P->name() + ", the frame " + B.name() + " is oriented relative to");
    m.guard(s.word("in").location, [&] {
        if (acc) B.set_ang_acc(*P, w - P->ang_acc_in(A) - cross(P->ang_vel_in(A), B.ang_vel_in(*P)));
        else B.set_ang_vel(*P, w - P->ang_vel_in(A));
    });
}

// ---- constraint --------------------------------------------------------------------------

void parse_constraint(StatementParser& p, Statement& s) {
    if (p.at_word("configuration") || p.at_word("motion")) s.words["kind"] = p.take_word();
    else p.fail_expected("'configuration' or 'motion'");
    s.words["name"] = p.name("a name for the constraint");
    p.expect_punct("=", "and the residual (constraint configuration c = expression)");
    s.exprs["value"] = p.expression();
    if (p.accept_word("in")) s.words["in"] = p.name("a frame");
}

void run_constraint(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& n = s.word("name");
    bool motion = s.word("kind").text == "motion";
    const Expr& e = *s.exprs.at("value");
    Value v = m.eval(e);
    std::vector<std::string> made;
    if (v.kind == Value::Kind::vector) {
        if (!s.has_word("in"))
            throw ScriptError(e.location, "a vector constraint needs the frame of its measures",
                              "add 'in N' after the vector");
        Frame& F = m.frame(s.word("in"));
        auto cs = m.guard(n.location, [&] {
            return motion ? sys.add_motion_constraint(n.text, v.v, F)
                          : sys.add_configuration_constraint(n.text, v.v, F);
        });
        for (const Constraint& c : cs) made.push_back(c.name);
    } else if (v.kind == Value::Kind::scalar) {
        if (s.has_word("in"))
            throw ScriptError(s.word("in").location, "'in' is for vector constraints; this one is a scalar",
                              "remove 'in " + s.word("in").text + "'");
        m.guard(n.location, [&] {
            motion ? sys.add_motion_constraint(n.text, v.s) : sys.add_configuration_constraint(n.text, v.s);
        });
        made.push_back(n.text);
    } else {
        throw ScriptError(e.location, "a constraint is a scalar or a vector expression", "");
    }
    std::string out;
    for (const Constraint& c : sys.constraints())
        if (std::find(made.begin(), made.end(), c.name) != made.end())
            out += c.name + ": 0 = " + to_string(c.residual) + "\n";
    m.transcript.result(out);
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> kinematics_statements() {
    const std::string_view family = "Kinematics";
    return {
        {.keyword = "rotate", .family = family, .help = "orients a frame or body from another",
         .forms = {{"`rotate` *B* `from` *A* `about` [`-`]*axis* `by` *angle*",
                    "rotate B from A about z by qB",
                    "`Frame::orient_axis` (`-z`: left-handed)"},
                   {"`rotate` *B* `from` *A* `body` *seq* `by` *q1, q2, q3*",
                    "rotate B from N body ZXY by q1, q2, q3",
                    "`Frame::orient_body_fixed`"},
                   {"`rotate` *B* `from` *A* `space` *seq* `by` *q1, q2, q3*",
                    "rotate B from N space XYZ by q1, q2, q3",
                    "`Frame::orient_space_fixed`"},
                   {"`rotate` *B* `from` *A* `dcm` *matrix*",
                    "rotate B from A dcm [cos(q), -sin(q), 0; sin(q), cos(q), 0; 0, 0, 1]",
                    "`Frame::orient_dcm` (columns: B's unit vectors in A)"}},
         .clauses = {"from", "about", "by", "dcm"}, .parse = parse_rotate, .run = run_rotate},
        {.keyword = "translate", .family = family, .help = "locates a point from another",
         .forms = {{"`translate` *P* `from` *O* `by` *vector*",
                    "translate B_o from A_o by L_A*Ay>",
                    "`Point::set_pos`"}},
         .clauses = {"from", "by"}, .parse = parse_translate, .run = run_translate},
        {.keyword = "velocity", .family = family, .help = "sets a point's velocity in a frame",
         .forms = {{"`velocity` *P* `in` *N* `=` *vector*",
                    "velocity P in N = r*u2*Lx>",
                    "`Point::set_vel`"},
                   {"`velocity` *P* `in` *N* `from` *O* `fixed on` *B*",
                    "velocity D_P in N from Dcm fixed on D",
                    "`Point::set_vel_two_point`"},
                   {"`velocity` *P* `in` *N* `from` *O* `moving on` *B*",
                    "velocity Q in N from B_o moving on B",
                    "`Point::set_vel_one_point`"}},
         .clauses = {"in", "from", "fixed", "moving", "on"}, .parse = parse_rate, .run = run_point_rate},
        {.keyword = "acceleration", .family = family, .help = "sets a point's acceleration in a frame",
         .forms = {{"`acceleration` *P* `in` *N* `=` *vector*",
                    "acceleration P in N = 0>",
                    "`Point::set_acc`"},
                   {"`acceleration` *P* `in` *N* `from` *O* `fixed on` *B*",
                    "acceleration D_P in N from Dcm fixed on D",
                    "`Point::set_acc_two_point`"}},
         .clauses = {"in", "from", "fixed", "on"}, .parse = parse_rate, .run = run_point_rate},
        {.keyword = "angvel", .family = family, .help = "sets a frame's angular velocity in another",
         .forms = {{"`angvel` *B* `in` *A* `=` *vector*",
                    "angvel B in N = wx*Bx> + wy*By>",
                    "`Frame::set_ang_vel` in B's parent P; in another frame A, w_B_P = w_B_A - w_P_A (addition theorem)"}},
         .clauses = {"in"}, .parse = parse_rate, .run = run_frame_rate},
        {.keyword = "angacc", .family = family, .help = "sets a frame's angular acceleration in another",
         .forms = {{"`angacc` *B* `in` *A* `=` *vector*",
                    "angacc B in N = 0>",
                    "`Frame::set_ang_acc` in B's parent P; in another frame A, alf_B_P = alf_B_A - alf_P_A - w_P_A x w_B_P"}},
         .clauses = {"in"}, .parse = parse_rate, .run = run_frame_rate},
    };
}

std::vector<StatementSpec> constraint_statements() {
    return {
        {.keyword = "constraint", .family = "Constraints",
         .help = "adds a configuration or motion constraint and prints its residuals",
         .forms = {{"`constraint configuration` *name* `=` *scalar*",
                    "constraint configuration c1 = x - L*sin(q)",
                    "`System::add_configuration_constraint`"},
                   {"`constraint configuration` *name* `=` *vector* `in` *F*",
                    "constraint configuration loop = pos(B_tip, C_tip) in N",
                    "the vector form: `loop_x`, `loop_y`, ..."},
                   {"`constraint motion` *name* `=` *scalar* or *vector* `in` *F*",
                    "constraint motion roll = vel(D_P, N) in N",
                    "`System::add_motion_constraint`"}},
         .clauses = {"configuration", "motion", "in"}, .parse = parse_constraint, .run = run_constraint},
    };
}

}  // namespace alembert::lang
