// SPDX-License-Identifier: MIT
// Rotate rows of large systems (more than eight bodies), formed by accumulating moments along
// the tree of points: a spatial chain's rows about its joints against Newton-Euler by hand,
// a branched tree's rows against the textbook sums, their size on a 30-link chain, and the
// road-map's accelerations against Kane's, Lagrange's and Newton-Euler's on chains of 10 and 12.
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "alembert/eom/cross_check.hpp"
#include "alembert/eom/inertia_forces.hpp"
#include "alembert/eom/roadmap.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/cse.hpp"
#include "models.hpp"

using namespace alembert;

namespace {

constexpr double kExact = 1e-12;

// ---- numbers in N for the hand derivation ------------------------------------------------------
using V3 = std::array<double, 3>;
using M3 = std::array<V3, 3>;  // rows

V3 operator+(V3 a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 operator-(V3 a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 operator*(double s, const V3& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 operator*(const M3& R, const V3& x) { return {dot(R[0], x), dot(R[1], x), dot(R[2], x)}; }
M3 operator*(const M3& A, const M3& B) {
    M3 C{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) C[i][j] += A[i][k] * B[k][j];
    return C;
}
M3 transpose(const M3& A) {
    M3 T{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) T[i][j] = A[j][i];
    return T;
}
// R_PB of B turned from P about P's z (axis 2) or x (axis 0) by q: B's unit vectors in P are
// its columns (Bx = c Px + s Py for z)
M3 turn(int axis, double q) {
    const double c = std::cos(q), s = std::sin(q);
    if (axis == 2) return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}

// The chain of bench/pipeline/chain.py: link B_i turns about z (odd i) or x (even i) of the
// link before it (N for the first) by q_i, its joint B_i_o lies L below the joint before it
// (-L B_{i-1}y), its mass centre L/2 below its joint; mass m_i = 0.7 + 0.05 i, central inertia
// (1 + i/10) diag(0.01, 0.002, 0.012); motor torques T_i on B_i from B_{i-1} about the joint's
// axis; gravity -g Ny; at the tip (L below B_n_o) a known force F_k and an unknown force
// P Nz, both from N.
constexpr double kL = 0.3, kG = 9.81;
const V3 kForce{1.5, -0.4, 0.8};
double link_mass(int i) { return 0.7 + 0.05 * i; }
V3 link_inertia(int i) { return (1 + i / 10.0) * V3{0.01, 0.002, 0.012}; }
int link_axis(int i) { return i % 2 ? 2 : 0; }

struct Chain {
    System sys{"N"};
    std::vector<TimeVariable> q;
    std::vector<ex> T;
    ex P;
    std::vector<RigidBody*> B;
    std::vector<Point*> O;  // B_i_o
};

void build_chain(Chain& c, int n) {
    SymbolTable& st = c.sys.symbols();
    Frame& N = c.sys.newtonian();
    c.P = st.add_unknown("P");
    for (int i = 1; i <= n; ++i) {
        const std::string s = std::to_string(i);
        c.q.push_back(st.add_variable("q" + s));
        c.T.push_back(st.add_unknown("T" + s));
        RigidBody& b = c.sys.add_rigid_body("B" + s);
        const Frame& parent = i == 1 ? static_cast<const Frame&>(N) : c.B.back()->body_frame();
        b.body_frame().orient_axis(parent, link_axis(i) == 2 ? Axis::z : Axis::x, c.q.back().d(0));
        Point& O = c.sys.point("B" + s + "_o");
        if (i == 1)
            O.set_pos(c.sys.origin(), Vector());
        else
            O.set_pos(*c.O.back(), -kL * c.B.back()->body_frame().y());
        b.cm().set_pos(O, -(kL / 2) * b.body_frame().y());
        b.set_mass(link_mass(i));
        const V3 I = link_inertia(i);
        b.set_inertia(b.cm(), I[0], I[1], I[2]);
        const Vector axis = link_axis(i) == 2 ? b.body_frame().z() : b.body_frame().x();
        c.sys.add_torque_pair(b, parent, c.T.back() * axis, "T" + s);
        c.B.push_back(&b);
        c.O.push_back(&O);
    }
    Point& tip = c.sys.add_point("tip", c.B.back());
    tip.set_pos(*c.O.back(), -kL * c.B.back()->body_frame().y());
    c.sys.add_force(tip, Vector(N, Col3{{kForce[0], kForce[1], kForce[2]}}), "F");
    c.sys.add_force(tip, c.P * N.z(), "P");
    c.sys.set_gravity(-kG * N.y());
}

// The row about joint k (0-based): S = B_k and every link beyond, O = B_k_o, u = its axis.
RoadmapRow joint_row(const Chain& c, std::size_t k, Analysis analysis) {
    RoadmapRow r;
    r.variable = c.T[k];
    r.motion = Motion::rotate;
    const Frame& F = c.B[k]->body_frame();
    r.direction = link_axis(static_cast<int>(k) + 1) == 2 ? F.z() : F.x();
    for (std::size_t j = k; j < c.B.size(); ++j) r.system.push_back(c.B[j]);
    r.about = c.O[k];
    r.analysis = analysis;
    return r;
}

// The same rows by hand at one state, Newton-Euler in N: R_i = R_{i-1} R_axis(q_i),
// a_i = R_{i-1} e_axis; w_i = w_{i-1} + q_i' a_i; alpha_i = alpha_{i-1} + q_i'' a_i +
// w_{i-1} x q_i' a_i; O_i = O_{i-1} + R_{i-1} (0, -L, 0) with acceleration
// a^{O_i} = a^{O_{i-1}} + alpha_{i-1} x d + w_{i-1} x (w_{i-1} x d), d = O_i - O_{i-1}; the
// mass centre likewise from O_i with R_i (0, -L/2, 0) and w_i, alpha_i. Row k:
// E_k = a_k . [T_k a_k + sum_{j >= k} ((cm_j - O_k) x m_j (g - a^{cm_j}) - I_j alpha_j
//              - w_j x I_j w_j) + (tip - O_k) x (F + P Nz)]      (statics: no inertia terms)
// with I_j = R_j diag(I) R_j^T; the torque T_{k+1} on B_{k+1} and its reaction on B_k are
// both inside S, and the reaction -T_k acts on B_{k-1}, outside it.
std::vector<double> rows_by_hand(int n, const std::vector<double>& q, const std::vector<double>& qp,
                                 const std::vector<double>& qpp, const std::vector<double>& T,
                                 double P, bool dynamics) {
    const auto N = static_cast<std::size_t>(n);
    std::vector<V3> a(N), w(N), al(N), O(N), aO(N), cm(N), acm(N);
    std::vector<M3> R(N);
    M3 Rp{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    V3 wp{}, alp{}, Op{}, aOp{};
    for (std::size_t i = 0; i < N; ++i) {
        const int axis = link_axis(static_cast<int>(i) + 1);
        V3 e{};
        e[static_cast<std::size_t>(axis)] = 1;
        a[i] = Rp * e;
        R[i] = Rp * turn(axis, q[i]);
        if (i == 0) {
            O[i] = {0, 0, 0}, aO[i] = {0, 0, 0};
        } else {
            const V3 d = Rp * V3{0, -kL, 0};
            O[i] = Op + d;
            aO[i] = aOp + cross(alp, d) + cross(wp, cross(wp, d));
        }
        w[i] = wp + qp[i] * a[i];
        al[i] = alp + qpp[i] * a[i] + cross(wp, qp[i] * a[i]);
        const V3 c = R[i] * V3{0, -kL / 2, 0};
        cm[i] = O[i] + c;
        acm[i] = aO[i] + cross(al[i], c) + cross(w[i], cross(w[i], c));
        Rp = R[i], wp = w[i], alp = al[i], Op = O[i], aOp = aO[i];
    }
    const V3 tip = O[N - 1] + R[N - 1] * V3{0, -kL, 0};
    const V3 g{0, -kG, 0};
    std::vector<double> E(N);
    for (std::size_t k = 0; k < N; ++k) {
        V3 M = T[k] * a[k] + cross(tip - O[k], kForce + V3{0, 0, P});
        for (std::size_t j = k; j < N; ++j) {
            const double m = link_mass(static_cast<int>(j) + 1);
            if (!dynamics) {
                M = M + cross(cm[j] - O[k], m * g);
                continue;
            }
            const V3 Id = link_inertia(static_cast<int>(j) + 1);
            const M3 D{{{Id[0], 0, 0}, {0, Id[1], 0}, {0, 0, Id[2]}}};
            const M3 I = R[j] * D * transpose(R[j]);
            M = M + cross(cm[j] - O[k], m * (g - acm[j])) - I * al[j] - cross(w[j], I * w[j]);
        }
        E[k] = dot(a[k], M);
    }
    return E;
}

}  // namespace

// Every row about a joint of a 12-link spatial chain, dynamics and statics, equals the hand
// derivation at random states; the four rows whose S holds more than eight links are the
// accumulated ones, the rest are formed as written.
TEST(AccumulatedRows, SpatialChainRowsMatchNewtonEulerByHand) {
    constexpr int n = 12;
    Chain c;
    build_chain(c, n);
    const SymbolTable& st = c.sys.symbols();
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> draw(-1.5, 1.5);
    for (Analysis analysis : {Analysis::dynamics, Analysis::statics}) {
        const bool dynamics = analysis == Analysis::dynamics;
        std::vector<ex> E;
        for (std::size_t k = 0; k < n; ++k) E.push_back(form_roadmap_equation(c.sys, joint_row(c, k, analysis)));
        for (int state = 0; state < 3; ++state) {
            std::vector<double> q(n), qp(n), qpp(n), T(n);
            exmap at;
            for (std::size_t i = 0; i < n; ++i) {
                q[i] = draw(rng), qp[i] = draw(rng), qpp[i] = draw(rng), T[i] = draw(rng);
                at[c.q[i].d(0)] = q[i], at[c.q[i].d(1)] = qp[i], at[c.q[i].d(2)] = qpp[i];
                at[c.T[i]] = T[i];
            }
            const double P = draw(rng);
            at[c.P] = P;
            const std::vector<double> hand = rows_by_hand(n, q, qp, qpp, T, P, dynamics);
            for (std::size_t k = 0; k < n; ++k)
                EXPECT_NEAR(st.evaluate(E[k], at), hand[k], kExact * std::max(1.0, std::abs(hand[k])))
                    << (dynamics ? "dynamics" : "statics") << " row " << k + 1 << ", state " << state;
        }
    }
}

// A branched tree of eleven bodies: A turns about Nz at N_o; branch B1..B5 hangs from A's
// tip (L along Ax), branch C1..C5 from A's origin, each link turning about x or z of the one
// before; a torque pair at every joint, a known force pair between the two branches' tips, and
// an unknown force at B5's tip. Rows about A_o (every point is located from it), about a point
// of a branch for a system that leaves part of the other branch out (loads across the cut are
// external), and about a mass centre that locates no other body (every moment formed
// directly) equal u . (M^{S/O} - sum over S of (I alpha + w x I w + r^{cm/O} x m a)), the
// textbook sums of Mitiguy ch. 21, at random states.
TEST(AccumulatedRows, BranchedTreeRowsEqualTheTextbookSums) {
    System sys("N");
    SymbolTable& st = sys.symbols();
    Frame& N = sys.newtonian();
    const ex L = st.add_constant("L", 0.4), g = st.add_constant("g", 9.81);
    std::vector<TimeVariable> q;
    std::vector<RigidBody*> bodies;
    auto link = [&](const std::string& name, const Frame& parent, Axis axis, const Point& at,
                    const Vector& offset) {
        q.push_back(st.add_variable("q" + name));
        RigidBody& b = sys.add_rigid_body(name);
        b.body_frame().orient_axis(parent, axis, q.back().d(0));
        Point& O = sys.point(name + "_o");
        O.set_pos(at, offset);
        b.cm().set_pos(O, 0.5 * L * b.body_frame().y() + 0.1 * L * b.body_frame().z());
        b.set_mass(1 + 0.1 * static_cast<double>(bodies.size()));
        b.set_inertia(b.cm(), 0.02, 0.004, 0.021, 0.001, 0, 0.002);
        sys.add_torque_pair(b, parent, st.add_unknown("T" + name) * b.body_frame().z());
        bodies.push_back(&b);
        return &b;
    };
    RigidBody* A = link("A", N, Axis::z, sys.origin(), Vector());
    Point& A_tip = sys.add_point("A_tip", A);
    A_tip.set_pos(sys.point("A_o"), L * A->body_frame().x());
    const Frame* parent = &A->body_frame();
    const Point* at = &A_tip;
    Vector offset;
    for (int i = 1; i <= 5; ++i) {
        RigidBody* b = link("B" + std::to_string(i), *parent, i % 2 ? Axis::x : Axis::z, *at, offset);
        parent = &b->body_frame(), at = &sys.point(b->name() + "_o"), offset = L * b->body_frame().y();
    }
    Point& B_tip = sys.add_point("B_tip", bodies.back());
    B_tip.set_pos(sys.point("B5_o"), L * bodies.back()->body_frame().y());
    parent = &A->body_frame(), at = &sys.point("A_o"), offset = Vector();
    for (int i = 1; i <= 5; ++i) {
        RigidBody* b = link("C" + std::to_string(i), *parent, i % 2 ? Axis::z : Axis::x, *at, offset);
        parent = &b->body_frame(), at = &sys.point(b->name() + "_o"), offset = L * b->body_frame().y();
    }
    Point& C_tip = sys.add_point("C_tip", bodies.back());
    C_tip.set_pos(sys.point("C5_o"), L * bodies.back()->body_frame().y());
    sys.add_force_pair(B_tip, C_tip, Vector(N, Col3{{0.7, -1.1, 0.3}}), "pull");
    const ex R = st.add_unknown("R");
    sys.add_force(B_tip, R * N.x(), "R");
    sys.set_gravity(-g * N.y());

    BodySet all(bodies.begin(), bodies.end());
    BodySet cut(bodies.begin(), bodies.begin() + 9);  // A, B1..B5, C1..C3
    struct Case {
        BodySet S;
        const Point* O;
        Vector u;
    };
    const std::vector<Case> cases{{all, &sys.point("A_o"), N.z()},
                                  {cut, &sys.point("B1_o"), bodies[2]->body_frame().z()},
                                  {all, &bodies[8]->cm(), bodies[3]->body_frame().x()}};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> draw(-1.5, 1.5);
    for (Analysis analysis : {Analysis::dynamics, Analysis::statics})
        for (const Case& cs : cases) {
            RoadmapRow row;
            row.variable = R;
            row.motion = Motion::rotate;
            row.direction = cs.u, row.system = cs.S, row.about = cs.O, row.analysis = analysis;
            const ex E = form_roadmap_equation(sys, row);
            // the textbook sums, formed body by body with each mass centre's position from O
            Vector M = sys.calc_resultant(cs.S, *cs.O).moment;
            if (analysis == Analysis::dynamics) M -= calc_inertial_moment(cs.S, *cs.O, N);
            const ex textbook = dot(cs.u, M);
            for (int state = 0; state < 3; ++state) {
                exmap values;
                for (const TimeVariable& v : q)
                    for (int d = 0; d <= 2; ++d) values[v.d(d)] = draw(rng);
                for (const ex& x : st.symbols(SymbolKind::unknown)) values[x] = draw(rng);
                const double expected = st.evaluate(textbook, values);
                EXPECT_NEAR(st.evaluate(E, values), expected, kExact * std::max(1.0, std::abs(expected)))
                    << (analysis == Analysis::dynamics ? "dynamics" : "statics") << " about "
                    << cs.O->name();
            }
        }
}

// The rows' size: each row about a joint is a few terms per acceleration over intermediates
// the rows share, so the n rows of an n-link chain hold about n^2 operations (the textbook
// sums, r^{cm/O} a sum of link vectors for every body beyond the joint, hold n^3: 8 times as
// many for twice the links). From 15 to 30 links the operations (intermediates counted once)
// grow by less than 5 times.
TEST(AccumulatedRows, RowsOfALongChainGrowAsTheSquareOfItsLength) {
    std::vector<std::size_t> ops;
    for (int n : {15, 30}) {
        Chain c;
        build_chain(c, n);
        std::vector<ex> E;
        for (std::size_t k = static_cast<std::size_t>(n); k-- > 0;)
            E.push_back(form_roadmap_equation(c.sys, joint_row(c, k, Analysis::dynamics)));
        ops.push_back(count_ops_with_intermediates(c.sys.symbols(), E));
    }
    EXPECT_LT(ops[1], 5 * ops[0]) << ops[0] << " operations at 15 links, " << ops[1] << " at 30";
}

// The planned road-map's accelerations agree with Kane's, Lagrange's, Newton-Euler's and the
// recursive formations' on chains whose root rows are accumulated (cross_check.hpp).
TEST(AccumulatedRows, RoadmapOfLongChainsAgreesWithTheOtherMethods) {
    for (int n : {10, 12}) {
        SampleModel m = make_n_link_pendulum(n, ChainKind::planar);
        const MethodComparison c = compare_methods(m.system, m.q, 2);
        EXPECT_EQ(c.methods.size(), 6u);
        for (std::size_t k = 0; k < c.methods.size(); ++k)
            EXPECT_LT(c.differences[k], test::kAgree) << c.methods[k] << ", " << n << " links";
    }
}
