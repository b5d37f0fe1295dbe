// SPDX-License-Identifier: MIT
// The statements of mass and loads: masses, inertias, gravity, forces, torques, springs,
// dampers, drag, friction and attraction. Each statement's grammar, meaning and help.
#include "alembert/mech/model_checks.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// ---- mass and inertia --------------------------------------------------------------------

void parse_mass(StatementParser& p, Statement& s) {
    s.words["target"] = p.name("a body or particle");
    p.expect_punct("=", "and the mass (mass A = m_A)");
    s.exprs["value"] = p.expression();
}

void run_mass(Interpreter::Impl& m, const Statement& s) {
    Body& B = m.body(s.word("target"));
    ex mass = m.scalar(*s.exprs.at("value"), Dimension::mass(), "the mass of " + s.word("target").text);
    // a second `mass A = ...` used to replace the first in silence
    if (B.has_mass())
        throw ScriptError(s.word("target").location,
                          "'" + s.word("target").text + "' already has a mass (" +
                              to_string(B.mass()) + ")",
                          "a body has one mass: remove one of the two `mass " +
                              s.word("target").text +
                              " = ...` statements (to vary it, give it a constant: constant m" +
                              s.word("target").text + " = 2 kg, then mass " +
                              s.word("target").text + " = m" + s.word("target").text + ")");
    m.guard(s.word("target").location, [&] {
        check_mass(m.model(s.location).symbols(), mass, s.word("target").text);
        B.set_mass(mass);
    });
}

void parse_inertia(StatementParser& p, Statement& s) {
    s.words["target"] = p.name("a rigid body");
    p.expect_punct("=", "and the moments (inertia A = Ixx, Iyy, Izz)");
    s.expr_lists["moments"] = p.expression_list();
    if (p.accept_word("about")) s.words["about"] = p.name("a point");
    if (p.accept_word("in")) s.words["in"] = p.name("a frame");
}

void run_inertia(Interpreter::Impl& m, const Statement& s) {
    RigidBody& B = m.rigid_body(s.word("target"));
    const auto& list = s.expr_lists.at("moments");
    if (list.size() != 3 && list.size() != 6)
        throw ScriptError(list.size() > 6 ? list[6]->location : list.back()->location,
                          "inertia takes 3 moments (Ixx, Iyy, Izz) or 6 (and Ixy, Iyz, Izx), not " +
                              std::to_string(list.size()),
                          "write: inertia " + s.word("target").text + " = Ixx, Iyy, Izz");
    std::vector<ex> I;
    for (const ExprPtr& e : list) I.push_back(m.scalar(*e, Dimension{{2, 1, 0}, true}, "a moment of inertia"));
    while (I.size() < 6) I.push_back(0);
    const Point& about = s.has_word("about") ? m.point(s.word("about")) : B.cm();
    Location where = s.word("target").location;
    // the moments and products as a matrix, about `about` in the frame they are given in
    Mat3 J;
    J(0, 0) = I[0], J(1, 1) = I[1], J(2, 2) = I[2];
    J(0, 1) = J(1, 0) = I[3];
    J(1, 2) = J(2, 1) = I[4];
    J(2, 0) = J(0, 2) = I[5];
    m.guard(where, [&] { check_inertia_matrix(m.model(s.location).symbols(), J, B.name()); });
    if (s.has_word("in")) {
        Frame& F = m.frame(s.word("in"));
        m.guard(where, [&] { B.set_inertia(about, inertia_dyadic(F, I[0], I[1], I[2], I[3], I[4], I[5])); });
    } else {
        m.guard(where, [&] { B.set_inertia(about, I[0], I[1], I[2], I[3], I[4], I[5]); });
    }
}

// ---- gravity, force, torque --------------------------------------------------------------

void parse_gravity(StatementParser& p, Statement& s) { s.exprs["value"] = p.expression(); }

void run_gravity(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    Vector g = m.vector(*s.exprs.at("value"), Dimension::length() / pow(Dimension::time(), 2),
                        "gravity (an acceleration)");
    m.guard(s.location, [&] { sys.set_gravity(g); });
}

// force and torque: on one point or body, or a pair with another
void parse_force_or_torque(StatementParser& p, Statement& s) {
    const std::string& k = s.keyword;
    s.words["label"] = p.name("a label for the " + k);
    p.expect_word("on", "and what it acts on (" + k + " F on P = ...)");
    s.words["on"] = p.name(k == "force" ? "a point" : "a body");
    if (p.accept_word("from")) s.words["from"] = p.name(k == "force" ? "a point" : "a frame or body");
    p.expect_punct("=", "and the " + k + " vector");
    s.exprs["value"] = p.expression();
}

void run_force(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& label = s.word("label");
    Point& P = m.point(s.word("on"));
    Vector F = m.vector(*s.exprs.at("value"), Dimension::force(), "the force " + label.text);
    if (s.has_word("from")) {
        Point& Q = m.point(s.word("from"));
        m.guard(label.location, [&] { sys.add_force_pair(P, Q, F, label.text); });
    } else {
        m.guard(label.location, [&] { sys.add_force(P, F, label.text); });
    }
}

void run_torque(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& label = s.word("label");
    Body& B = m.body(s.word("on"));
    Vector T = m.vector(*s.exprs.at("value"), Dimension::torque(), "the torque " + label.text);
    if (s.has_word("from")) {
        Frame& A = m.frame(s.word("from"));
        m.guard(label.location, [&] { sys.add_torque_pair(B, A, T, label.text); });
    } else {
        m.guard(label.location, [&] { sys.add_torque(B, T, label.text); });
    }
}

// ---- reaction: a joint's constraint force and torque, components as unknowns -------------

void parse_reaction(StatementParser& p, Statement& s) {
    s.words["label"] = p.name("a name for the joint reaction");
    p.expect_word("between", "(reaction knee between A and B at B_o force F_x along Bx>)");
    s.words["parent"] = p.name("the parent body (or the Newtonian frame)");
    p.expect_word("and", "and the child body");
    s.words["child"] = p.name("the child body");
    p.expect_word("at", "and the joint point (reaction knee between A and B at B_o ...)");
    s.words["at"] = p.name("a point");
    bool any = false;
    for (const std::string kind : {"force", "torque"}) {
        if (!p.accept_word(kind)) continue;
        any = true;
        const std::string along = kind == "force" ? "along" : "about";
        do {
            s.lists[kind].push_back(p.name("an unknown " + kind + " measure"));
            p.expect_word(along, "and its direction (" + kind + " F_x " + along + " Bx>)");
            s.expr_lists[kind].push_back(p.expression());
        } while (p.accept_punct(","));
    }
    if (!any) p.fail_expected("'force' or 'torque' and the components (force F_x along Bx>)");
}

void run_reaction(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& label = s.word("label");
    const Word& pw = s.word("parent");
    const Body* parent = pw.text == sys.newtonian().name() ? nullptr : &m.body(pw);
    Body& child = m.body(s.word("child"));
    Point& at = m.point(s.word("at"));
    std::vector<ReactionComponent> forces, torques;
    for (const std::string kind : {"force", "torque"}) {
        if (!s.lists.count(kind)) continue;
        const std::vector<Word>& measures = s.lists.at(kind);
        const auto& directions = s.expr_lists.at(kind);
        Interpreter::Impl::require_each_once(measures, "measure");
        for (std::size_t i = 0; i < measures.size(); ++i) {
            const Word& w = measures[i];
            ex x = m.symbol(w, "an unknown " + kind + " measure");
            m.check_dimension(m.symbol_dimension(w.text),
                              kind == "force" ? Dimension::force() : Dimension::torque(),
                              "the " + kind + " measure " + w.text, w.location);
            Vector d = m.vector(*directions[i], Dimension::none(), "the direction of " + w.text);
            (kind == "force" ? forces : torques).push_back({x, d});
        }
    }
    m.guard(label.location,
            [&] { sys.add_joint_reaction(label.text, parent, child, at, forces, torques); });
}

// ---- spring, damper, attraction: between two points --------------------------------------

void parse_between(StatementParser& p, Statement& s) {
    const std::string& k = s.keyword;
    s.words["label"] = p.name("a label");
    p.expect_word("between", "(" + k + " label between P and Q ...)");
    s.words["P"] = p.name("a point");
    p.expect_word("and", "between the two points");
    s.words["Q"] = p.name("a point");
    if (k == "spring") {
        p.expect_word("stiffness", "(spring k1 between P and Q stiffness k length L0)");
        s.exprs["stiffness"] = p.expression();
        p.expect_word("length", "and the natural length");
        s.exprs["length"] = p.expression();
    } else if (k == "damper") {
        p.expect_word("coefficient", "(damper c1 between P and Q coefficient c)");
        s.exprs["coefficient"] = p.expression();
    } else {
        p.expect_word("constant", "(attraction G1 between P and Q constant G)");
        s.exprs["constant"] = p.expression();
    }
}

void run_between(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const std::string& k = s.keyword;
    const Dimension L = Dimension::length(), M = Dimension::mass(), T = Dimension::time();
    const Word& label = s.word("label");
    Point& P = m.point(s.word("P"));
    Point& Q = m.point(s.word("Q"));
    if (k == "spring") {
        ex kk = m.scalar(*s.exprs.at("stiffness"), M / pow(T, 2), "a stiffness");
        ex L0 = m.scalar(*s.exprs.at("length"), L, "a natural length");
        m.guard(label.location, [&] { sys.add_spring(P, Q, kk, L0, label.text); });
    } else if (k == "damper") {
        ex c = m.scalar(*s.exprs.at("coefficient"), M / T, "a damping coefficient");
        m.guard(label.location, [&] { sys.add_damper(P, Q, c, label.text); });
    } else {
        ex G = m.scalar(*s.exprs.at("constant"), pow(L, 3) / M / pow(T, 2), "a gravitational constant");
        m.guard(label.location, [&] { sys.add_inverse_square_gravity(P, Q, G, label.text); });
    }
    m.line_loads.push_back({k, label, &P, &Q});
}

// ---- drag, friction ----------------------------------------------------------------------

void parse_drag(StatementParser& p, Statement& s) {
    s.words["label"] = p.name("a label");
    p.expect_word("on", "(drag air on P linear c)");
    s.words["on"] = p.name("a point");
    if (p.at_word("linear") || p.at_word("quadratic")) s.words["law"] = p.take_word();
    else p.fail_expected("'linear' or 'quadratic'");
    s.exprs["coefficient"] = p.expression();
}

void run_drag(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Dimension L = Dimension::length(), M = Dimension::mass(), T = Dimension::time();
    const Word& label = s.word("label");
    Point& P = m.point(s.word("on"));
    bool linear = s.word("law").text == "linear";
    ex c = m.scalar(*s.exprs.at("coefficient"), linear ? M / T : M / L, "a drag coefficient");
    m.guard(label.location, [&] { sys.add_drag(P, c, linear ? DragLaw::linear : DragLaw::quadratic, label.text); });
}

void parse_friction(StatementParser& p, Statement& s) {
    s.words["label"] = p.name("a label");
    p.expect_word("on", "(friction f on P from Q coefficient mu normal Fn along u>)");
    s.words["on"] = p.name("a point");
    p.expect_word("from", "and the point it slides on");
    s.words["from"] = p.name("a point");
    p.expect_word("coefficient", "and the friction coefficient");
    s.exprs["coefficient"] = p.expression();
    p.expect_word("normal", "and the normal force");
    s.exprs["normal"] = p.expression();
    p.expect_word("along", "and the sliding direction");
    s.exprs["along"] = p.expression();
}

void run_friction(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const Word& label = s.word("label");
    Point& P = m.point(s.word("on"));
    Point& Q = m.point(s.word("from"));
    ex mu = m.scalar(*s.exprs.at("coefficient"), Dimension::none(), "a friction coefficient");
    ex Fn = m.scalar(*s.exprs.at("normal"), Dimension::force(), "a normal force");
    Vector u = m.vector(*s.exprs.at("along"), Dimension::none(), "a direction");
    m.guard(label.location, [&] { sys.add_coulomb_friction(P, Q, mu, Fn, u, label.text); });
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> load_statements() {
    const std::string_view family = "Mass and loads";
    return {
        {.keyword = "mass", .family = family, .help = "sets the mass of a body or particle",
         .forms = {{"`mass` *body* `=` *m*",
                    "mass A = m_A",
                    "`Body::set_mass`"}},
         .parse = parse_mass, .run = run_mass},
        {.keyword = "inertia", .family = family, .help = "sets the inertia of a rigid body",
         .forms = {{"`inertia` *body* `=` *Ixx, Iyy, Izz* [*, Ixy, Iyz, Izx*] [`about` *P*] [`in` *F*]",
                    "inertia A = 0, 0, I_A",
                    "`RigidBody::set_inertia` (about the mass centre unless `about`; in the body frame unless `in`: `inertia_dyadic`)"}},
         .clauses = {"about", "in"}, .parse = parse_inertia, .run = run_inertia},
        {.keyword = "gravity", .family = family, .help = "uniform gravity on every mass",
         .forms = {{"`gravity` *vector*",
                    "gravity -g*Ny>",
                    "`System::set_gravity`"}},
         .parse = parse_gravity, .run = run_gravity},
        {.keyword = "force", .family = family,
         .help = "a force on a point, or an action-reaction pair between two points",
         .forms = {{"`force` *label* `on` *P* `=` *vector*",
                    "force F on Q = F*Nx>",
                    "`System::add_force` (from the surroundings)"},
                   {"`force` *label* `on` *P* `from` *Q* `=` *vector*",
                    "force pin on B_tip from C_tip = F_x*Nx> + F_y*Ny>",
                    "`System::add_force_pair` (and the opposite on Q)"}},
         .clauses = {"on", "from"}, .parse = parse_force_or_torque, .run = run_force},
        {.keyword = "torque", .family = family,
         .help = "a torque on a body, or an action-reaction pair between two bodies",
         .forms = {{"`torque` *label* `on` *B* `=` *vector*",
                    "torque T on A = T*Nz>",
                    "`System::add_torque`"},
                   {"`torque` *label* `on` *B* `from` *A* `=` *vector*",
                    "torque T_B on B from A = T_B*Nz>",
                    "`System::add_torque_pair` (and the opposite on A)"}},
         .clauses = {"on", "from"}, .parse = parse_force_or_torque, .run = run_torque},
        {.keyword = "reaction", .family = family,
         .help = "a joint reaction: its force and torque components as unknowns a road-map solves for",
         .forms = {{"`reaction` *label* `between` *A* `and` *B* `at` *P* [`force` *F* `along` *u*, ...] "
                    "[`torque` *M* `about` *u*, ...]",
                    "reaction knee between A and B at B_o force F_Kc along Ay>, F_Ks along Ax>",
                    "`System::add_joint_reaction` (on B from A at P, the opposite on A; A may be "
                    "the Newtonian frame)"}},
         .clauses = {"between", "and", "at", "force", "along", "torque", "about"}, .parse = parse_reaction,
         .run = run_reaction},
        {.keyword = "spring", .family = family, .help = "a linear spring between two points",
         .forms = {{"`spring` *label* `between` *P* `and` *Q* `stiffness` *k* `length` *L0*",
                    "spring k1 between Q and N_o stiffness k length 0",
                    "`System::add_spring`"}},
         .clauses = {"between", "and", "stiffness", "length"}, .parse = parse_between, .run = run_between},
        {.keyword = "damper", .family = family, .help = "a linear damper between two points",
         .forms = {{"`damper` *label* `between` *P* `and` *Q* `coefficient` *c*",
                    "damper c1 between Q and N_o coefficient c",
                    "`System::add_damper`"}},
         .clauses = {"between", "and", "coefficient"}, .parse = parse_between, .run = run_between},
        {.keyword = "drag", .family = family,
         .help = "air drag on a point, linear or quadratic in its speed",
         .forms = {{"`drag` *label* `on` *P* `linear`/`quadratic` *c*",
                    "drag air on Q quadratic c_d",
                    "`System::add_drag`"}},
         .clauses = {"on", "linear", "quadratic"}, .parse = parse_drag, .run = run_drag},
        {.keyword = "friction", .family = family,
         .help = "Coulomb friction on a point sliding on another",
         .forms = {{"`friction` *label* `on` *P* `from` *Q* `coefficient` *mu* `normal` *Fn* `along` *u*",
                    "friction f on Q from N_o coefficient mu normal m*g along Nx>",
                    "`System::add_coulomb_friction`"}},
         .clauses = {"on", "from", "coefficient", "normal", "along"}, .parse = parse_friction,
         .run = run_friction},
        {.keyword = "attraction", .family = family,
         .help = "inverse-square attraction between two points",
         .forms = {{"`attraction` *label* `between` *P* `and` *Q* `constant` *G*",
                    "attraction grav between S and E constant G",
                    "`System::add_inverse_square_gravity`"}},
         .clauses = {"between", "and"}, .parse = parse_between, .run = run_between},
    };
}

}  // namespace alembert::lang
