// SPDX-License-Identifier: MIT
// Recursive formation on a tree of bodies: road-map rows about successive joints, accumulated
// from the tip inward, and the articulated-body accelerations.
#include "alembert/eom/tree_dynamics.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "alembert/eom/zero_test.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

namespace {

using GiNaC::is_a;
using GiNaC::numeric;
using GiNaC::symbol;

const char* const kWho = "form_tree_equations()";

// ---- small spatial algebra on symbolic entries ------------------------------------------------
// A spatial vector (angular part, linear part) in one frame: a motion (angular acceleration,
// acceleration of the body's origin) or a force (moment about the origin, force).
struct Spatial {
    Col3 w, v;
};
// A 6 x 6 matrix in 3 x 3 blocks [[a, b], [c, d]].
struct Spatial6 {
    Mat3 a, b, c, d;
};

Spatial operator+(const Spatial& x, const Spatial& y) { return {x.w + y.w, x.v + y.v}; }
Spatial operator-(const Spatial& x, const Spatial& y) { return {x.w - y.w, x.v - y.v}; }
Spatial operator*(const ex& s, const Spatial& x) { return {s * x.w, s * x.v}; }
ex dot(const Spatial& x, const Spatial& y) { return dot(x.w, y.w) + dot(x.v, y.v); }
Spatial operator*(const Spatial6& M, const Spatial& x) {
    return {M.a * x.w + M.b * x.v, M.c * x.w + M.d * x.v};
}
Spatial6 operator+(const Spatial6& x, const Spatial6& y) {
    return {x.a + y.a, x.b + y.b, x.c + y.c, x.d + y.d};
}
Spatial6 operator-(const Spatial6& x, const Spatial6& y) {
    return {x.a - y.a, x.b - y.b, x.c - y.c, x.d - y.d};
}
Spatial6 operator*(const Spatial6& x, const Spatial6& y) {
    return {x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c,
            x.c * y.b + x.d * y.d};
}
Spatial6 transpose(const Spatial6& x) {
    return {x.a.transpose(), x.c.transpose(), x.b.transpose(), x.d.transpose()};
}
// x y^T
Spatial6 outer(const Spatial& x, const Spatial& y) {
    return {alembert::outer(x.w, y.w), alembert::outer(x.w, y.v), alembert::outer(x.v, y.w),
            alembert::outer(x.v, y.v)};
}
Mat3 skew(const Col3& r) {
    Mat3 m;
    m(0, 1) = -r[2], m(0, 2) = r[1];
    m(1, 0) = r[2], m(1, 2) = -r[0];
    m(2, 0) = -r[1], m(2, 1) = r[0];
    return m;
}

// The motion transform from a parent's frame and origin to a child's: classical accelerations
// (alpha, a^O) of the parent in its frame map to the child's frame and origin O' (r = r^{O'/O}
// in the parent's frame, R = R_PB) as (R^T alpha, R^T (a^O + alpha x r)); its transpose carries
// the child's forces to the parent: (R M + r x R F, R F).
Spatial6 motion_transform(const Mat3& R, const Col3& r) {
    Mat3 Rt = R.transpose();
    return {Rt, Mat3{}, ex(-1) * (Rt * skew(r)), Rt};
}

// X^T I X for a rigid-body inertia I = [[J, [h x]], [[h x]^T, m 1]] about a child's origin in its
// frame (J about the origin, h = m c its first moment): the same inertia about the parent's
// origin in the parent's frame, by a rotation (R J R^T, R h) and the parallel-axis shift by
// r = r^{O/O_P}: J' = R J R^T + m [r x][r x]^T + [r x][Rh x]^T + [Rh x][r x]^T, h' = R h + m r.
// Cheaper than the 6 x 6 product: the zero and repeated blocks are never formed.
Spatial6 inertia_to_parent(const Spatial6& I, const Mat3& R, const Col3& r) {
    const ex m = I.d(0, 0);
    const Col3 h = R * Col3{I.b(2, 1), I.b(0, 2), I.b(1, 0)};
    const Mat3 RJ = R * I.a, sr = skew(r), sh = skew(h);
    Mat3 J;
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            ex e = 0;
            for (int l = 0; l < 3; ++l) e += RJ(i, l) * R(j, l);
            J(i, j) = J(j, i) = e;
        }
    J = J + m * (sr * sr.transpose()) + sr * sh.transpose() + sh * sr.transpose();
    const Mat3 shp = skew(h + m * r);
    return {J, shp, shp.transpose(), m * Mat3::identity()};
}

// ---- the tree ------------------------------------------------------------------------------------
struct Node {
    TreeJoint joint;
    const Frame* frame = nullptr;  // the body's frame (a particle moves with its parent's)
    int parent = -1;               // index of the parent node, -1 for N
    std::vector<int> children{};
    Mat3 R = Mat3::identity();     // R_PB
    Col3 r{};                      // r^{O/O_P} in P
    Col3 v_rel{}, a_rel{};         // ^P v^O, ^P a^O in P
    Col3 w_rel{}, al_rel{};        // ^P w^B, ^P alpha^B in B
    Vector w_rel_v{}, v_rel_v{};   // ^P w^B and ^P v^O as formed (frames as declared)
    Col3 c{};                      // r^{Bcm/O} in B
    Mat3 I{};                      // I^{B/Bcm} in B
    ex m = 0;
};

struct Tree {
    std::vector<Node> nodes;  // parents before children
    std::string why_not;
};

// the index of b's node, or -1
int node_of(const std::vector<Node>& nodes, const Body* b) {
    for (std::size_t k = 0; k < nodes.size(); ++k)
        if (nodes[k].joint.body == b) return static_cast<int>(k);
    return -1;
}

const Point* topmost_own_point(const Body& b) {
    const Point* O = &b.cm();
    while (O->located_from() && O->located_from()->owner() == &b) O = O->located_from();
    return O;
}

// The speeds u and their rates u' the recursion forms its rows for.
struct Speeds {
    std::vector<ex> u, u_dot;
    bool rates = true;  // u = q' (the coordinates' rates) rather than chosen speeds
};

Speeds rates_of(const std::vector<TimeVariable>& q) {
    Speeds s;
    for (const TimeVariable& v : q) s.u.push_back(v.d(1)), s.u_dot.push_back(v.d(2));
    return s;
}

Tree extract_tree(const System& sys, const std::vector<TimeVariable>& q, const Speeds& sp) {
    Tree t;
    SymbolTable& st = sys.newtonian().symbols();
    const Frame& N = sys.newtonian();
    if (!sys.constraints().empty()) {
        t.why_not = "the model has constraints ('" + sys.constraints().front().name +
                    "'); the recursion covers open trees only";
        return t;
    }
    const BodySet bodies = sys.bodies();
    if (bodies.empty()) {
        t.why_not = "the model has no bodies";
        return t;
    }
    // parents by the point tree
    std::vector<const Body*> parent_of(bodies.size(), nullptr);
    std::vector<const Point*> origin(bodies.size(), nullptr);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = *bodies[i];
        origin[i] = b.frame() ? topmost_own_point(b) : &b.cm();
        const Point* p = origin[i]->located_from();
        while (p && (!p->owner() || p->owner() == &b)) {
            if (p == &sys.origin()) break;
            p = p->located_from();
        }
        if (!p) {
            if (origin[i] != &sys.origin()) {
                t.why_not = "the origin '" + origin[i]->name() + "' of '" + b.name() +
                            "' is not located from " + sys.origin().name();
                return t;
            }
        } else if (p->owner() && p->owner() != &b) {
            parent_of[i] = p->owner();
        }
        if (b.frame() && !b.frame()->parent() && b.frame() != &N) {
            t.why_not = "the frame of '" + b.name() + "' is not oriented";
            return t;
        }
    }
    // parents before children
    std::vector<int> index_of_body(bodies.size(), -1);
    auto body_index = [&](const Body* b) {
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (bodies[i] == b) return static_cast<int>(i);
        return -1;
    };
    std::vector<char> placed(bodies.size(), 0);
    while (t.nodes.size() < bodies.size()) {
        bool progress = false;
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (placed[i]) continue;
            int p = parent_of[i] ? body_index(parent_of[i]) : -1;
            if (p >= 0 && !placed[static_cast<std::size_t>(p)]) continue;
            Node n;
            n.joint.body = bodies[i];
            n.joint.parent = parent_of[i];
            n.joint.origin = origin[i];
            n.parent = p >= 0 ? index_of_body[static_cast<std::size_t>(p)] : -1;
            index_of_body[i] = static_cast<int>(t.nodes.size());
            if (n.parent >= 0) t.nodes[static_cast<std::size_t>(n.parent)].children.push_back(index_of_body[i]);
            t.nodes.push_back(std::move(n));
            placed[i] = 1;
            progress = true;
        }
        if (!progress) {
            t.why_not = "the bodies' origins are located from each other in a cycle";
            return t;
        }
    }
    // relative kinematics and the coordinates of each joint
    std::vector<int> owner_of(q.size(), -1), speed_owner(sp.u.size(), -1);
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
        Node& n = t.nodes[k];
        const Body& b = *n.joint.body;
        const Node* P = n.parent >= 0 ? &t.nodes[static_cast<std::size_t>(n.parent)] : nullptr;
        const Frame& FP = P ? *P->frame : N;
        const Point& OP = P ? *P->joint.origin : sys.origin();
        n.frame = b.frame() ? b.frame() : &FP;
        try {
            if (b.frame()) {
                n.R = b.frame()->rotation_in(FP);
                n.w_rel_v = b.frame()->ang_vel_in(FP);
                n.w_rel = n.w_rel_v.components_in(*n.frame);
                n.al_rel = b.frame()->ang_acc_in(FP).components_in(*n.frame);
            }
            const Vector r = n.joint.origin->pos_from(OP);
            n.r = r.components_in(FP);
            n.v_rel_v = r.dt_in(FP);
            n.v_rel = n.v_rel_v.components_in(FP);
        } catch (const Error& e) {
            t.why_not = "the motion of '" + b.name() + "' relative to its parent cannot be " +
                        "formed (" + e.what() + ")";
            return t;
        }
        for (int i = 0; i < 3; ++i) n.a_rel[i] = st.dt(n.v_rel[i]);
        // the coordinates that move the body relative to its parent
        for (std::size_t j = 0; j < q.size(); ++j) {
            bool moves = false;
            for (int i = 0; i < 3 && !moves; ++i)
                for (int l = 0; l < 3 && !moves; ++l)
                    moves = st.depends_on(n.R(i, l), q[j].d(0));
            for (int i = 0; i < 3 && !moves; ++i)
                moves = st.depends_on(n.r[i], q[j].d(0)) ||
                        (sp.rates && (st.depends_on(n.al_rel[i], q[j].d(2)) ||
                                      st.depends_on(n.a_rel[i], q[j].d(2))));
            if (!moves) continue;
            if (owner_of[j] >= 0) {
                t.why_not = "the coordinate '" + q[j].name() + "' moves both '" +
                            t.nodes[static_cast<std::size_t>(owner_of[j])].joint.body->name() +
                            "' and '" + b.name() + "' relative to their parents (the recursion " +
                            "needs relative coordinates, each moving one joint)";
                return t;
            }
            owner_of[j] = static_cast<int>(k);
            if (sp.rates) n.joint.coordinates.push_back(j);
        }
        // chosen speeds: those whose rates the body's relative accelerations hold
        for (std::size_t j = 0; j < sp.u.size() && !sp.rates; ++j) {
            bool moves = false;
            for (int i = 0; i < 3 && !moves; ++i)
                moves = st.depends_on(n.al_rel[i], sp.u_dot[j]) ||
                        st.depends_on(n.a_rel[i], sp.u_dot[j]);
            if (!moves) continue;
            if (speed_owner[j] >= 0) {
                t.why_not = "the speed '" + to_string(sp.u[j]) + "' moves both '" +
                            t.nodes[static_cast<std::size_t>(speed_owner[j])].joint.body->name() +
                            "' and '" + b.name() + "' relative to their parents (the recursion " +
                            "needs relative speeds, each moving one joint)";
                return t;
            }
            speed_owner[j] = static_cast<int>(k);
            n.joint.coordinates.push_back(j);
        }
        n.m = b.mass();
        if (b.frame()) {
            Vector c = b.cm().pos_from(*n.joint.origin);
            n.c = c.components_in(*n.frame);
            if (!c.dt_in(*n.frame).components_in(*n.frame).is_zero()) {
                t.why_not = "the mass centre of '" + b.name() + "' moves in its frame";
                return t;
            }
            if (const auto* rb = dynamic_cast<const RigidBody*>(&b); rb && rb->has_inertia())
                n.I = rb->inertia().components_in(*n.frame);
        }
    }
    for (std::size_t j = 0; j < q.size(); ++j)
        if (owner_of[j] < 0) {
            t.why_not = "the coordinate '" + q[j].name() + "' moves no body relative to its parent";
            return t;
        }
    for (std::size_t j = 0; j < sp.u.size() && !sp.rates; ++j)
        if (speed_owner[j] < 0) {
            t.why_not = "the speed '" + to_string(sp.u[j]) + "' moves no body relative to its " +
                        "parent (set the angular velocity with Frame::set_ang_vel in terms of it)";
            return t;
        }
    return t;
}

// Names every entry that is not a number or a symbol, so each step refers to the last.
class Namer {
public:
    explicit Namer(SymbolTable& st) : st_(st) {}
    ex operator()(const ex& e) const {
        if (is_a<numeric>(e) || is_a<symbol>(e)) return e;
        if (is_a<GiNaC::mul>(e) && e.nops() == 2 && is_a<numeric>(e.op(1)) && is_a<symbol>(e.op(0)))
            return e;
        return st_.name_subexpression(e);
    }
    Col3 operator()(const Col3& v) const { return v.map([&](const ex& e) { return (*this)(e); }); }
    Spatial operator()(const Spatial& s) const { return {(*this)(s.w), (*this)(s.v)}; }
    // a symmetric matrix: the upper triangle named, mirrored
    Spatial6 symmetric(const Spatial6& M) const {
        ex e[6][6];
        auto get = [&](int i, int j) -> ex {
            const Mat3& B = i < 3 ? (j < 3 ? M.a : M.b) : (j < 3 ? M.c : M.d);
            return B(i % 3, j % 3);
        };
        for (int i = 0; i < 6; ++i)
            for (int j = i; j < 6; ++j) e[i][j] = e[j][i] = (*this)(get(i, j));
        Spatial6 out;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                Mat3& B = i < 3 ? (j < 3 ? out.a : out.b) : (j < 3 ? out.c : out.d);
                B(i % 3, j % 3) = e[i][j];
            }
        return out;
    }

private:
    SymbolTable& st_;
};

// e with the symbols `xs` set to zero (they enter linearly and explicitly)
ex without(const ex& e, const std::vector<ex>& xs, const SymbolTable& st) {
    GiNaC::exmap zero;
    for (const ex& x : xs) zero[x] = 0;
    ex r = e.subs(zero);
    for (const ex& x : xs)
        if (st.depends_on(r, x)) return st.expand_intermediates(e).subs(zero);
    return r;
}

// The inverse of a small symmetric matrix D (k x k) by Gauss-Jordan, every step named.
std::vector<std::vector<ex>> named_inverse(std::vector<std::vector<ex>> D, const Namer& name) {
    const std::size_t k = D.size();
    std::vector<std::vector<ex>> X(k, std::vector<ex>(k, 0));
    for (std::size_t i = 0; i < k; ++i) X[i][i] = 1;
    for (std::size_t j = 0; j < k; ++j) {
        ex p = name(1 / D[j][j]);
        for (std::size_t l = 0; l < k; ++l) {
            D[j][l] = name(D[j][l] * p);
            X[j][l] = name(X[j][l] * p);
        }
        for (std::size_t i = 0; i < k; ++i) {
            if (i == j || D[i][j].is_zero()) continue;
            ex f = D[i][j];
            for (std::size_t l = 0; l < k; ++l) {
                D[i][l] = name(D[i][l] - f * D[j][l]);
                X[i][l] = name(X[i][l] - f * X[j][l]);
            }
        }
    }
    return X;
}

// The generalized active forces F_r of the loads (gravity is in the base acceleration). For a
// coordinate of joint J only the bodies beyond J move, all with J's partial angular velocity
// w_r, so a load on such a body contributes w_r . T (a torque) or (w_r x r^{P/O_J} + v_r) . F
// (a force at P), with v_r the partial velocity of J's origin. Torques exerted by a body beyond
// J on another are left out: with their reactions they contribute w_r . T - w_r . T = 0. So a
// joint's motor torque enters its own row with the coefficient of its axis, and no other
// row: the load coefficients stay exact numbers.
std::vector<ex> tree_active_forces(const System& sys, const Speeds& sp,
                                   const std::vector<Node>& nodes) {
    std::vector<ex> F(sp.u.size(), 0);
    auto beyond = [&](int k, int J) {  // k is J or a descendant of J
        for (; k >= 0; k = nodes[static_cast<std::size_t>(k)].parent)
            if (k == J) return true;
        return false;
    };
    for (const Load& l : sys.loads()) {
        const int on = node_of(nodes, l.on), from = l.from ? node_of(nodes, l.from) : -1;
        if (on < 0 || (l.kind == LoadKind::torque && !l.on->frame())) continue;
        for (int J = on; J >= 0; J = nodes[static_cast<std::size_t>(J)].parent) {
            const Node& n = nodes[static_cast<std::size_t>(J)];
            if (l.kind == LoadKind::torque && from >= 0 && beyond(from, J)) continue;
            if (n.joint.coordinates.empty()) continue;
            const Vector r = l.kind == LoadKind::force ? l.point->pos_from(*n.joint.origin) : Vector();
            for (std::size_t j : n.joint.coordinates) {
                const ex& u = sp.u[j];
                const Vector w_r = n.w_rel_v.diff(u);
                // each term is a few products of one joint's sines and cosines: simplified,
                // an axis dotted with itself is 1, not sin^2 + cos^2
                if (l.kind == LoadKind::torque)
                    F[j] += trig_simplify(dot(w_r, l.vector));
                else
                    F[j] += trig_simplify(dot(cross(w_r, r) + n.v_rel_v.diff(u), l.vector));
            }
        }
    }
    return F;
}

// The measures of declared joint reactions that do no work in the tree's motion: those no row
// of the generalized active forces F changes with (a reaction along the directions its joint
// prevents, at the joint's point; tested at random states, since the pair's two halves need
// not cancel symbolically), each mapped to 0. Neither the rows nor the articulated-body
// recursion then need their values (a program that computes the motor torques or the motion
// does not read them); a reaction that would do work stays in both.
GiNaC::exmap idle_reaction_measures(const System& sys, const std::vector<ex>& F) {
    std::vector<ex> measures;
    for (const JointReaction& r : sys.joint_reactions())
        for (const ReactionComponent& c : r.components) measures.push_back(c.measure);
    GiNaC::exmap idle;
    if (measures.empty()) return idle;
    std::vector<bool> works(measures.size(), false);
    for (const ex& row : F) {
        if (std::none_of(measures.begin(), measures.end(), [&](const ex& m) { return row.has(m); }))
            continue;
        const std::vector<bool> changes =
            calc_changes_with_at_random_states(sys.symbols(), row, measures);
        for (std::size_t i = 0; i < measures.size(); ++i) works[i] = works[i] || changes[i];
    }
    for (std::size_t i = 0; i < measures.size(); ++i)
        if (!works[i]) idle[measures[i]] = 0;
    return idle;
}

// The rows and the accelerations of a tree extract_tree found.
TreeEquations form_on_tree(const System& sys, const Speeds& sp, Tree& tree,
                           const TreeOptions& options) {
    SymbolTable& st = sys.newtonian().symbols();
    const Namer name(st);
    std::vector<Node>& nodes = tree.nodes;
    const std::size_t nb = nodes.size();
    // the base moves with -g: the weight of every body, as d'Alembert's inertia force of it
    const Spatial base{{}, ex(-1) * sys.gravity().components_in(sys.newtonian())};

    // ---- per joint: the partial motions S (the columns of q''_own) and the bias c -------------
    std::vector<Spatial6> X(nb);
    std::vector<std::vector<Spatial>> S(nb);
    std::vector<Col3> w(nb);  // ^N w^B in B
    for (std::size_t k = 0; k < nb; ++k) {
        Node& n = nodes[k];
        // a rotation's polynomial entries named (Euler parameters' quadratics): each is formed
        // once, not expanded into every product with a number; a hinge's sines and cosines stay
        for (ex& e : n.R.m)
            if (is_a<GiNaC::add>(e)) e = name(e);
        X[k] = motion_transform(n.R, n.r);
        Mat3 Rt = n.R.transpose();
        Col3 w_P = n.parent >= 0 ? w[static_cast<std::size_t>(n.parent)] : Col3{};
        w[k] = name(Rt * w_P + n.w_rel);
        for (std::size_t j : n.joint.coordinates) {
            const ex& qpp = sp.u_dot[j];
            Col3 sw = n.al_rel.map([&](const ex& e) { return st.diff(e, qpp); });
            Col3 sv = Rt * n.a_rel.map([&](const ex& e) { return st.diff(e, qpp); });
            S[k].push_back(name(Spatial{sw, sv}));
        }
    }
    auto bias = [&](std::size_t k) {  // c: the joint's acceleration at q''_own = 0 beyond X A_P
        const Node& n = nodes[k];
        std::vector<ex> own;
        for (std::size_t j : n.joint.coordinates) own.push_back(sp.u_dot[j]);
        Mat3 Rt = n.R.transpose();
        Col3 w_P = n.parent >= 0 ? w[static_cast<std::size_t>(n.parent)] : Col3{};
        Col3 al0 = n.al_rel.map([&](const ex& e) { return without(e, own, st); });
        Col3 a0 = n.a_rel.map([&](const ex& e) { return without(e, own, st); });
        Col3 cw = cross(Rt * w_P, n.w_rel) + al0;
        Col3 cv = Rt * (cross(w_P, cross(w_P, n.r)) + ex(2) * cross(w_P, n.v_rel) + a0);
        return name(Spatial{cw, cv});
    };
    std::vector<Spatial> c(nb);
    for (std::size_t k = 0; k < nb; ++k) c[k] = bias(k);

    // body inertia about its origin, and its velocity-product force
    std::vector<Spatial6> I(nb);
    std::vector<Spatial> b(nb);
    for (std::size_t k = 0; k < nb; ++k) {
        const Node& n = nodes[k];
        Mat3 cx = skew(n.c);
        I[k] = {n.I + n.m * (cx * cx.transpose()), n.m * cx, n.m * cx.transpose(),
                n.m * Mat3::identity()};
        Col3 Fb = n.m * cross(w[k], cross(w[k], n.c));
        b[k] = {cross(w[k], n.I * w[k]) + cross(n.c, Fb), Fb};
    }

    // ---- inverse dynamics: road-map rows about successive joints -------------------------------
    // the generalized active forces, less the joint reactions that do no work
    std::vector<ex> active = tree_active_forces(sys, sp, nodes);
    const GiNaC::exmap idle = idle_reaction_measures(sys, active);
    if (!idle.empty())
        for (ex& Fr : active) Fr = Fr.subs(idle);
    std::vector<ex> residuals(sp.u.size(), 0);
    {
        std::vector<Spatial> A(nb);  // (alpha, a^O) of each body, -g of the base folded in
        for (std::size_t k = 0; k < nb; ++k) {
            const Node& n = nodes[k];
            Spatial AP = n.parent >= 0 ? A[static_cast<std::size_t>(n.parent)] : base;
            Spatial a = X[k] * AP + c[k];
            for (std::size_t i = 0; i < n.joint.coordinates.size(); ++i)
                a = a + sp.u_dot[n.joint.coordinates[i]] * S[k][i];
            A[k] = name(a);
        }
        std::vector<Spatial> f(nb);  // inertia force of the subtree about its origin
        for (std::size_t k = nb; k-- > 0;) {
            Spatial fk = I[k] * A[k] + b[k];
            for (int ch : nodes[k].children)
                fk = fk + transpose(X[static_cast<std::size_t>(ch)]) * f[static_cast<std::size_t>(ch)];
            f[k] = name(fk);
        }
        for (std::size_t k = 0; k < nb; ++k)
            for (std::size_t i = 0; i < nodes[k].joint.coordinates.size(); ++i) {
                std::size_t j = nodes[k].joint.coordinates[i];
                residuals[j] = active[j] - dot(S[k][i], f[k]);
            }
    }

    // ---- forward dynamics: the articulated-body recursion --------------------------------------
    std::vector<ex> accelerations(sp.u.size(), 0);
    {
        // loads on each body about its origin, in its frame (gravity is in the base; the
        // joint reactions that do no work left out)
        std::vector<Spatial> fext(nb);
        for (const Load& l : sys.loads()) {
            const int on = node_of(nodes, l.on);
            if (on < 0) continue;
            const Vector v = idle.empty() ? l.vector : l.vector.map([&](const ex& e) { return e.subs(idle); });
            if (v.is_zero()) continue;
            const auto k = static_cast<std::size_t>(on);
            const Frame& B = *nodes[k].frame;
            if (l.kind == LoadKind::force) {
                Col3 F = v.components_in(B);
                Col3 r = l.point->pos_from(*nodes[k].joint.origin).components_in(B);
                fext[k] = fext[k] + Spatial{cross(r, F), F};
            } else if (l.on->frame()) {
                fext[k] = fext[k] + Spatial{v.components_in(B), {}};
            }
        }
        std::vector<Spatial6> IA = I;
        std::vector<Spatial> pA(nb);
        for (std::size_t k = 0; k < nb; ++k) pA[k] = b[k] - fext[k];
        struct Step {
            std::vector<Spatial> U;
            std::vector<std::vector<ex>> Dinv;
            std::vector<ex> u;
        };
        std::vector<Step> steps(nb);
        for (std::size_t k = nb; k-- > 0;) {
            const Spatial6 Ik = name.symmetric(IA[k]);
            const Spatial pk = name(pA[k]);
            const std::size_t dof = S[k].size();
            Step& s = steps[k];
            Spatial6 Ia = Ik;
            Spatial pa = pk;
            if (dof > 0) {
                for (const Spatial& Si : S[k]) s.U.push_back(name(Ik * Si));
                std::vector<std::vector<ex>> D(dof, std::vector<ex>(dof));
                for (std::size_t i = 0; i < dof; ++i) {
                    for (std::size_t j = i; j < dof; ++j) D[i][j] = D[j][i] = name(dot(S[k][i], s.U[j]));
                    s.u.push_back(name(-dot(S[k][i], pk)));
                }
                s.Dinv = named_inverse(D, name);
                // U D^-1 (6 x dof)
                std::vector<Spatial> UD(dof);
                for (std::size_t j = 0; j < dof; ++j) {
                    Spatial sum{};
                    for (std::size_t i = 0; i < dof; ++i) sum = sum + s.Dinv[i][j] * s.U[i];
                    UD[j] = name(sum);
                }
                for (std::size_t j = 0; j < dof; ++j) Ia = Ia - outer(UD[j], s.U[j]);
                Ia = name.symmetric(Ia);
                pa = Ia * c[k] + pk;
                for (std::size_t j = 0; j < dof; ++j) pa = pa + s.u[j] * UD[j];
                pa = name(pa);
            } else {
                pa = name(Ik * c[k] + pk);
            }
            if (nodes[k].parent >= 0) {
                const auto p = static_cast<std::size_t>(nodes[k].parent);
                Spatial6 Xt = transpose(X[k]);
                IA[p] = IA[p] + Xt * Ia * X[k];
                pA[p] = pA[p] + Xt * pa;
            }
        }
        std::vector<Spatial> A(nb);
        for (std::size_t k = 0; k < nb; ++k) {
            const Node& n = nodes[k];
            Spatial AP = n.parent >= 0 ? A[static_cast<std::size_t>(n.parent)] : base;
            Spatial a1 = name(X[k] * AP + c[k]);
            const Step& s = steps[k];
            const std::size_t dof = S[k].size();
            std::vector<ex> rhs(dof);
            for (std::size_t i = 0; i < dof; ++i) rhs[i] = s.u[i] - dot(s.U[i], a1);
            Spatial a = a1;
            for (std::size_t i = 0; i < dof; ++i) {
                ex x = 0;
                for (std::size_t j = 0; j < dof; ++j) x += s.Dinv[i][j] * rhs[j];
                x = name(x);
                accelerations[n.joint.coordinates[i]] = x;
                a = a + x * S[k][i];
            }
            A[k] = name(a);
        }
    }

    // ---- bias forces: the rows' recursion at u' = 0, no loads -----------------------------------
    std::vector<ex> bias_forces;
    if (options.mass_matrix) {
        bias_forces.assign(sp.u.size(), 0);
        std::vector<Spatial> A(nb);  // (alpha, a^O) at u' = 0, -g of the base folded in
        for (std::size_t k = 0; k < nb; ++k) {
            const Node& n = nodes[k];
            Spatial AP = n.parent >= 0 ? A[static_cast<std::size_t>(n.parent)] : base;
            A[k] = name(X[k] * AP + c[k]);
        }
        std::vector<Spatial> f(nb);
        for (std::size_t k = nb; k-- > 0;) {
            Spatial fk = I[k] * A[k] + b[k];
            for (int ch : nodes[k].children)
                fk = fk + transpose(X[static_cast<std::size_t>(ch)]) * f[static_cast<std::size_t>(ch)];
            f[k] = name(fk);
        }
        for (std::size_t k = 0; k < nb; ++k)
            for (std::size_t i = 0; i < nodes[k].joint.coordinates.size(); ++i)
                bias_forces[nodes[k].joint.coordinates[i]] = dot(S[k][i], f[k]);
    }

    // ---- mass matrix: the composite-rigid-body recursion ---------------------------------------
    const std::size_t nu = sp.u.size();
    std::vector<ex> mass_matrix;
    if (options.mass_matrix) {
        mass_matrix.assign(nu * nu, 0);
        // composite inertias of the subtrees about their origins, from the tip inward
        std::vector<Spatial6> Ic = I;
        for (std::size_t k = nb; k-- > 0;) {
            Ic[k] = name.symmetric(Ic[k]);
            if (nodes[k].parent >= 0) {
                const auto p = static_cast<std::size_t>(nodes[k].parent);
                Ic[p] = Ic[p] + inertia_to_parent(Ic[k], nodes[k].R, nodes[k].r);
            }
        }
        // per partial motion: its subtree's inertia force, carried towards the root
        for (std::size_t k = 0; k < nb; ++k) {
            const std::vector<std::size_t>& cols = nodes[k].joint.coordinates;
            for (std::size_t i = 0; i < cols.size(); ++i) {
                Spatial F = name(Ic[k] * S[k][i]);
                for (std::size_t l = i; l < cols.size(); ++l) {
                    ex m = name(dot(S[k][l], F));
                    mass_matrix[cols[l] * nu + cols[i]] = mass_matrix[cols[i] * nu + cols[l]] = m;
                }
                for (std::size_t j = k; nodes[j].parent >= 0;) {
                    const auto p = static_cast<std::size_t>(nodes[j].parent);
                    F = name(transpose(X[j]) * F);
                    j = p;
                    const std::vector<std::size_t>& rows = nodes[j].joint.coordinates;
                    for (std::size_t l = 0; l < rows.size(); ++l) {
                        ex m = name(dot(S[j][l], F));
                        mass_matrix[rows[l] * nu + cols[i]] = mass_matrix[cols[i] * nu + rows[l]] = m;
                    }
                }
            }
        }
    }

    TreeEquations out;
    for (const Node& n : nodes) out.joints.push_back(n.joint);
    out.speeds = sp.u;
    out.residuals = std::move(residuals);
    out.accelerations = std::move(accelerations);
    out.mass_matrix = std::move(mass_matrix);
    out.bias_forces = std::move(bias_forces);
    return out;
}

}  // namespace

std::string explain_not_tree(const System& sys, const std::vector<TimeVariable>& q) {
    return extract_tree(sys, q, rates_of(q)).why_not;
}

TreeEquations form_tree_equations(const System& sys, const std::vector<TimeVariable>& q,
                                  const TreeOptions& options) {
    Tree tree = extract_tree(sys, q, rates_of(q));
    if (!tree.why_not.empty())
        throw ModelError(std::string(kWho) + ": not a tree the recursion handles: " + tree.why_not +
                         "; form Kane's, Lagrange's or the road-map's equations instead");
    return form_on_tree(sys, rates_of(q), tree, options);
}

TreeEquations form_tree_equations(const System& sys, const std::vector<TimeVariable>& q,
                                  const std::vector<ex>& speeds, const TreeOptions& options) {
    SymbolTable& st = sys.newtonian().symbols();
    Speeds sp;
    sp.rates = false;
    for (const ex& u : speeds) {
        const ex u_dot = st.dt(u);
        if (!is_a<symbol>(u) || !is_a<symbol>(u_dot))
            throw ArgumentError(std::string(kWho) + ": the speed '" + to_string(u) +
                                "' is not a symbol with a declared derivative; declare it with "
                                "SymbolTable::add_variable(name, 1) or pass a coordinate's rate q'");
        sp.u.push_back(u);
        sp.u_dot.push_back(u_dot);
    }
    Tree tree = extract_tree(sys, q, sp);
    if (!tree.why_not.empty())
        throw ModelError(std::string(kWho) + ": not a tree the recursion handles: " + tree.why_not +
                         "; form Kane's equations with these speeds instead");
    return form_on_tree(sys, sp, tree, options);
}

std::optional<TreeEquations> form_tree_equations_if_tree(const System& sys,
                                                         const std::vector<TimeVariable>& q,
                                                         const TreeOptions& options) {
    Tree tree = extract_tree(sys, q, rates_of(q));
    if (!tree.why_not.empty()) return std::nullopt;
    return form_on_tree(sys, rates_of(q), tree, options);
}

}  // namespace alembert
