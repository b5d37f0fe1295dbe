// SPDX-License-Identifier: MIT
// Contact forces as unknowns in minimal coordinates: free-body rows about points chosen to
// eliminate unknowns (off the bodies too), each problem checked against a hand derivation.
#include <cmath>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace contact_rows {

namespace {

std::string body_names(const BodySet& S) {
    std::string s;
    for (const Body* b : S) s += (s.empty() ? "" : ",") + b->name();
    return s;
}

// the row whose variable is x
const RoadmapRow& row_for(const std::vector<RoadmapRow>& rows, const ex& x) {
    for (const RoadmapRow& r : rows)
        if (r.variable.is_equal(x)) return r;
    throw std::runtime_error("no row for " + to_string(x));
}

// u is the unit vector e (same direction), checked by meaning
::testing::AssertionResult along(const Vector& u, const Vector& e) {
    return alembert::test::same(dot(u, e), 1);
}

// the rows solved numerically at the values given, in the order of `xs`
std::vector<double> solve_rows(const System& sys, const std::vector<RoadmapRow>& rows,
                               const std::vector<ex>& xs, const exmap& values) {
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    Eigen::VectorXd v = solve_numeric(sys.symbols(), form_linear_system(E, xs), values);
    return {v.data(), v.data() + v.size()};
}

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

// a rod of mass m and length L, angle q from the wall (x = 0) with its foot on the floor
// (y = 0): foot A_o at L sin q Nx>, top A_w at L Ay> from it, Ay> = -sin q Nx> + cos q Ny>
struct Rod {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m"), L = s.add_constant("L"), g = s.add_constant("g");
    ex N_w = s.add_unknown("N_w"), N_f = s.add_unknown("N_f");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    Point& A_w = sys.add_point("A_w", &A);
    explicit Rod(bool friction = false) {
        A.body_frame().orient_axis(N, Axis::z, q);
        sys.point("A_o").set_pos(sys.origin(), L * GiNaC::sin(q) * N.x());
        A.cm().set_pos(sys.point("A_o"), L / 2 * A.body_frame().y());
        A_w.set_pos(sys.point("A_o"), L * A.body_frame().y());
        A.set_mass(m);
        A.set_inertia(A.cm(), 0, 0, m * L * L / 12);
        sys.set_gravity(-g * N.y());
        sys.add_force(A_w, N_w * N.x(), "Nw");
        sys.add_force(sys.point("A_o"), N_f * N.y(), "Nf");
        if (friction) F_f = s.add_unknown("F_f"), sys.add_force(sys.point("A_o"), F_f * N.x(), "Ff");
    }
    ex F_f{};
};

}  // namespace

// (1) The rod slides down a frictionless wall and floor, described by its angle alone.
// By hand: the lines of N_w (horizontal through the top) and N_f (vertical through the foot)
// meet at C = (L sin q, L cos q), the instantaneous centre; about C only gravity has a moment:
//   m g (L/2) sin q = (m L^2/12) q'' + m (L/2)^2 q'' = (m L^2/3) q''  =>  q'' = 3 g sin q / (2 L).
// The mass centre is at (L/2)(sin q, cos q), so along Nx> and Ny>:
//   N_w = m (L/2)(q'' cos q - q'^2 sin q),   N_f = m g - m (L/2)(q'' sin q + q'^2 cos q).
TEST(ContactRows, RodSlidingOnWallAndFloorAngleOnly) {
    Rod rod;
    const ex qdd = rod.q.d(2);
    std::vector<RoadmapRow> rows = plan_roadmap(rod.sys, {rod.q}, {qdd, rod.N_w, rod.N_f});
    ASSERT_EQ(rows.size(), 3u);
    // the road-map a textbook writes: about the instantaneous centre for q'', then F = m a
    // along each unknown force, one new unknown per row
    EXPECT_TRUE(rows[0].variable.is_equal(qdd));
    EXPECT_EQ(rows[0].motion, Motion::rotate);
    EXPECT_TRUE(along(rows[0].direction, rod.N.z()));
    EXPECT_EQ(body_names(rows[0].system), "A");
    ASSERT_NE(rows[0].about, nullptr);
    EXPECT_EQ(rows[0].about->name(), "IC_q");
    EXPECT_TRUE(alembert::test::same(rows[0].about->pos_from(rod.sys.origin()),
                                     rod.L * GiNaC::sin(rod.q) * rod.N.x() +
                                         rod.L * GiNaC::cos(rod.q) * rod.N.y(),
                                     rod.N));
    EXPECT_TRUE(rows[0].additional_unknowns.empty());
    EXPECT_TRUE(rows[1].variable.is_equal(rod.N_w));
    EXPECT_EQ(rows[1].motion, Motion::translate);
    EXPECT_TRUE(along(rows[1].direction, rod.N.x()));
    ASSERT_EQ(rows[1].additional_unknowns.size(), 1u);
    EXPECT_TRUE(rows[1].additional_unknowns[0].is_equal(qdd));
    EXPECT_TRUE(rows[2].variable.is_equal(rod.N_f));
    EXPECT_EQ(rows[2].motion, Motion::translate);
    EXPECT_TRUE(along(rows[2].direction, rod.N.y()));
    for (const RoadmapRow& r : rows) EXPECT_TRUE(r.note.empty()) << r.note;
    // no joint at the foot: it only slides on the floor, whose force is N_f
    for (const std::string& line : rows[0].fbd)
        EXPECT_EQ(line.find("joint force"), std::string::npos) << line;
    EXPECT_EQ(rows[0].fbd[0], "Nw at A_w from N (unknown, drops out)");
    // the numbers, at chosen states
    const double m = 2.5, L = 1.3, g = 9.81;
    for (auto [q, qd] : {std::pair{0.4, 0.0}, std::pair{0.9, 1.7}, std::pair{-0.3, -0.8}}) {
        std::vector<double> x = solve_rows(rod.sys, rows, {qdd, rod.N_w, rod.N_f},
                                           {{rod.q.symbol(), q}, {rod.q.d(1), qd}, {rod.m, m},
                                            {rod.L, L}, {rod.g, g}});
        const double a = 3 * g * std::sin(q) / (2 * L);
        expect_close(x[0], a, "q''");
        expect_close(x[1], m * L / 2 * (a * std::cos(q) - qd * qd * std::sin(q)), "N_w");
        expect_close(x[2], m * g - m * L / 2 * (a * std::sin(q) + qd * qd * std::cos(q)), "N_f");
    }
}

// The same rod as a free body with x, y, q and the two contacts as configuration constraints
// (the path that worked before): the same q'', N_w and N_f at states that meet them.
TEST(ContactRows, RodAgreesWithAllCoordinatesPlusConstraints) {
    Rod rod;
    const double m = 2.5, L = 1.3, g = 9.81;
    std::vector<RoadmapRow> rows =
        plan_roadmap(rod.sys, {rod.q}, {rod.q.d(2), rod.N_w, rod.N_f});
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y"), q = s.add_variable("q");
    ex mm = s.add_constant("m"), LL = s.add_constant("L"), gg = s.add_constant("g");
    ex N_w = s.add_unknown("N_w"), N_f = s.add_unknown("N_f");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    A.body_frame().orient_axis(N, Axis::z, q);
    A.cm().set_pos(sys.origin(), x * N.x() + y * N.y());
    Point& top = sys.add_point("A_w", &A);
    top.set_pos(A.cm(), LL / 2 * A.body_frame().y());
    sys.point("A_o").set_pos(A.cm(), -LL / 2 * A.body_frame().y());
    A.set_mass(mm);
    A.set_inertia(A.cm(), 0, 0, mm * LL * LL / 12);
    sys.set_gravity(-gg * N.y());
    sys.add_force(top, N_w * N.x(), "Nw");
    sys.add_force(sys.point("A_o"), N_f * N.y(), "Nf");
    sys.add_configuration_constraint("wall", dot(top.pos_from(sys.origin()), N.x()));
    sys.add_configuration_constraint("floor", dot(sys.point("A_o").pos_from(sys.origin()), N.y()));
    std::vector<ex> xs{x.d(2), y.d(2), q.d(2), N_w, N_f};
    std::vector<RoadmapRow> full = plan_roadmap(sys, {x, y, q}, xs);
    for (auto [qv, qd] : {std::pair{0.4, 0.3}, std::pair{1.1, -1.2}}) {
        std::vector<double> a = solve_rows(rod.sys, rows, {rod.q.d(2), rod.N_w, rod.N_f},
                                           {{rod.q.symbol(), qv}, {rod.q.d(1), qd}, {rod.m, m},
                                            {rod.L, L}, {rod.g, g}});
        std::vector<double> b = solve_rows(
            sys, full, xs,
            {{x.symbol(), L / 2 * std::sin(qv)}, {y.symbol(), L / 2 * std::cos(qv)},
             {q.symbol(), qv}, {x.d(1), L / 2 * std::cos(qv) * qd},
             {y.d(1), -L / 2 * std::sin(qv) * qd}, {q.d(1), qd}, {mm, m}, {LL, L}, {gg, g}});
        expect_close(a[0], b[2], "q''");
        expect_close(a[1], b[3], "N_w");
        expect_close(a[2], b[4], "N_f");
    }
}

// (2) A ladder held still by a frictionless wall and a rough floor, angle q given (statics).
// By hand, about the foot: N_w L cos q = m g (L/2) sin q, so N_w = (m g / 2) tan q; along Ny>:
// N_f = m g; about C = (L sin q, L cos q), where the lines of N_w and N_f meet, only F_f and gravity have moments:
// F_f L cos q + m g (L/2) sin q = 0, so F_f = -(m g / 2) tan q (towards the wall).
TEST(ContactRows, LadderInStaticEquilibriumOneCoordinate) {
    Rod ladder(true);
    std::vector<RoadmapRow> rows = plan_roadmap(ladder.sys, {ladder.q},
                                                {ladder.N_w, ladder.N_f, ladder.F_f},
                                                Analysis::statics);
    ASSERT_EQ(rows.size(), 3u);
    const RoadmapRow& w = row_for(rows, ladder.N_w);
    EXPECT_EQ(w.motion, Motion::rotate);
    EXPECT_TRUE(along(w.direction, ladder.N.z()));
    ASSERT_NE(w.about, nullptr);
    EXPECT_EQ(w.about->name(), "A_o");  // the foot: N_f and F_f drop out
    const RoadmapRow& f = row_for(rows, ladder.N_f);
    EXPECT_EQ(f.motion, Motion::translate);
    EXPECT_TRUE(along(f.direction, ladder.N.y()));
    const RoadmapRow& fr = row_for(rows, ladder.F_f);
    EXPECT_EQ(fr.motion, Motion::rotate);
    ASSERT_NE(fr.about, nullptr);
    // off the ladder, where the lines of N_w and N_f meet (the instantaneous centre of the
    // ladder's motion when q changes): N_w and N_f drop out
    EXPECT_EQ(fr.about->name(), "IC_q");
    EXPECT_TRUE(alembert::test::same(fr.about->pos_from(ladder.sys.origin()),
                                     ladder.L * GiNaC::sin(ladder.q) * ladder.N.x() +
                                         ladder.L * GiNaC::cos(ladder.q) * ladder.N.y(),
                                     ladder.N));
    for (const RoadmapRow& r : rows) {
        EXPECT_TRUE(r.additional_unknowns.empty()) << to_string(r.variable);
        EXPECT_EQ(body_names(r.system), "A");
        EXPECT_EQ(r.analysis, Analysis::statics);
    }
    const double m = 12.0, L = 4.0, g = 9.81;
    for (double q : {0.2, 0.55, 1.0}) {
        std::vector<double> x =
            solve_rows(ladder.sys, rows, {ladder.N_w, ladder.N_f, ladder.F_f},
                       {{ladder.q.symbol(), q}, {ladder.m, m}, {ladder.L, L}, {ladder.g, g}});
        expect_close(x[0], m * g / 2 * std::tan(q), "N_w");
        expect_close(x[1], m * g, "N_f");
        expect_close(x[2], -m * g / 2 * std::tan(q), "F_f");
    }
}

namespace {
// a block (particle Q) at x along an incline B (B = N turned by beta about Nz), normal force
// N_n along By>; `hold`: an unknown force P along Bx> (statics), else kinetic friction
// mu N_n Bx> (sliding down, x' < 0)
struct Incline {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable x = s.add_variable("x");
    ex m = s.add_constant("m"), g = s.add_constant("g"), beta = s.add_constant("beta");
    ex mu = s.add_constant("mu");
    ex N_n = s.add_unknown("N_n"), P = s.add_unknown("P");
    const Frame& N = sys.newtonian();
    Frame& B = sys.add_frame("B");
    Particle& Q = sys.add_particle("Q");
    explicit Incline(bool hold) {
        B.orient_axis(N, Axis::z, beta);
        Q.cm().set_pos(sys.origin(), x * B.x());
        Q.set_mass(m);
        sys.set_gravity(-g * N.y());
        sys.add_force(Q.cm(), N_n * B.y(), "Nn");
        if (hold) sys.add_force(Q.cm(), P * B.x(), "P");
        else sys.add_force(Q.cm(), mu * N_n * B.x(), "friction");
    }
};
}  // namespace

// (3a) Held on the incline by P (statics). By hand: along Bx>, P - m g sin beta = 0; along
// By>, N_n - m g cos beta = 0.
TEST(ContactRows, BlockHeldOnInclineStatics) {
    Incline b(true);
    std::vector<RoadmapRow> rows = plan_roadmap(b.sys, {b.x}, {b.P, b.N_n}, Analysis::statics);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_TRUE(rows[0].variable.is_equal(b.P));
    EXPECT_EQ(rows[0].motion, Motion::translate);
    EXPECT_TRUE(along(rows[0].direction, b.B.x()));
    EXPECT_TRUE(rows[1].variable.is_equal(b.N_n));
    EXPECT_EQ(rows[1].motion, Motion::translate);
    EXPECT_TRUE(along(rows[1].direction, b.B.y()));
    for (const RoadmapRow& r : rows) {
        EXPECT_EQ(body_names(r.system), "Q");
        EXPECT_TRUE(r.additional_unknowns.empty());
    }
    for (double beta : {0.3, 0.7}) {
        std::vector<double> v = solve_rows(b.sys, rows, {b.P, b.N_n},
                                           {{b.x.symbol(), 0.4}, {b.m, 3.0}, {b.g, 9.81},
                                            {b.beta, beta}, {b.mu, 0.2}});
        expect_close(v[0], 3.0 * 9.81 * std::sin(beta), "P");
        expect_close(v[1], 3.0 * 9.81 * std::cos(beta), "N_n");
    }
}

// (3b) Sliding down the rough incline (dynamics). By hand: along By>, N_n = m g cos beta;
// along Bx>, m x'' = mu N_n - m g sin beta, so x'' = g (mu cos beta - sin beta). The row of
// x'' holds N_n, solved first from its own row: triangular.
TEST(ContactRows, BlockSlidingDownRoughInclineDynamics) {
    Incline b(false);
    std::vector<RoadmapRow> rows = plan_roadmap(b.sys, {b.x}, {b.x.d(2), b.N_n});
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_TRUE(rows[0].variable.is_equal(b.N_n));  // solved first
    EXPECT_TRUE(along(rows[0].direction, b.B.y()));
    EXPECT_TRUE(rows[0].additional_unknowns.empty());
    EXPECT_TRUE(rows[1].variable.is_equal(b.x.d(2)));
    EXPECT_TRUE(along(rows[1].direction, b.B.x()));
    ASSERT_EQ(rows[1].additional_unknowns.size(), 1u);
    EXPECT_TRUE(rows[1].additional_unknowns[0].is_equal(b.N_n));
    for (double beta : {0.3, 0.7}) {
        std::vector<double> v = solve_rows(b.sys, rows, {b.x.d(2), b.N_n},
                                           {{b.x.symbol(), 0.4}, {b.x.d(1), -1.5}, {b.m, 3.0},
                                            {b.g, 9.81}, {b.beta, beta}, {b.mu, 0.2}});
        expect_close(v[0], 9.81 * (0.2 * std::cos(beta) - std::sin(beta)), "x''");
        expect_close(v[1], 3.0 * 9.81 * std::cos(beta), "N_n");
    }
}

// (4) A particle Q in a horizontal tube B turned about the vertical Nz> by a prescribed angle
// theta(t), at r along Bx>; the tube pushes it with N_y By> and N_z Bz>. By hand, with
// a^Q = (r'' - r theta'^2) Bx> + (r theta'' + 2 r' theta') By>:
//   r'' = r theta'^2,  N_y = m (r theta'' + 2 r' theta'),  N_z = m g.
TEST(ContactRows, ParticleInTurningTube) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable r = s.add_variable("r"), th = s.add_specified("theta");
    ex m = s.add_constant("m"), g = s.add_constant("g");
    ex N_y = s.add_unknown("N_y"), N_z = s.add_unknown("N_z");
    const Frame& N = sys.newtonian();
    Frame& B = sys.add_frame("B");
    B.orient_axis(N, Axis::z, th);
    Particle& Q = sys.add_particle("Q");
    Q.cm().set_pos(sys.origin(), r * B.x());
    Q.set_mass(m);
    sys.set_gravity(-g * N.z());
    sys.add_force(Q.cm(), N_y * B.y() + N_z * B.z(), "tube");
    std::vector<RoadmapRow> rows = plan_roadmap(sys, {r}, {r.d(2), N_y, N_z});
    ASSERT_EQ(rows.size(), 3u);
    const Vector dirs[] = {B.x(), B.y(), N.z()};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(rows[i].motion, Motion::translate);
        EXPECT_TRUE(along(rows[i].direction, dirs[i])) << i;
        EXPECT_EQ(body_names(rows[i].system), "Q");
        EXPECT_TRUE(rows[i].additional_unknowns.empty()) << i;
    }
    EXPECT_TRUE(rows[0].variable.is_equal(r.d(2)));
    EXPECT_TRUE(rows[1].variable.is_equal(N_y));
    EXPECT_TRUE(rows[2].variable.is_equal(N_z));
    for (auto [rv, rd, w, wd] : {std::tuple{0.5, 0.2, 3.0, 0.0}, std::tuple{1.2, -0.7, 1.5, 2.5}}) {
        std::vector<double> v = solve_rows(sys, rows, {r.d(2), N_y, N_z},
                                           {{r.symbol(), rv}, {r.d(1), rd}, {th.symbol(), 0.3},
                                            {th.d(1), w}, {th.d(2), wd}, {m, 0.2}, {g, 9.81}});
        expect_close(v[0], rv * w * w, "r''");
        expect_close(v[1], 0.2 * (rv * wd + 2 * rd * w), "N_y");
        expect_close(v[2], 0.2 * 9.81, "N_z");
    }
}

// (5) A uniform disk (mass m, radius R, I = m R^2 / 2) rolls without slip down an incline B
// (Bx> down the slope: B = N turned by -beta about Nz>), described by its angle q alone: its
// centre at -R q Bx> + R By>, the contact point D_P at -R By> from it, friction F along Bx>
// and normal force N_n along By> there. By hand, about the contact point (F and N_n drop
// out): -m g R sin beta = (I + m R^2) q'', so q'' = -2 g sin beta / (3 R); about the centre
// I q'' = R F, so F = -(m g / 3) sin beta (up the slope); along By>, N_n = m g cos beta.
TEST(ContactRows, DiskRollingDownInclineAngleOnly) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q");
    ex m = s.add_constant("m"), R = s.add_constant("R"), g = s.add_constant("g");
    ex beta = s.add_constant("beta");
    ex F = s.add_unknown("F"), N_n = s.add_unknown("N_n");
    const Frame& N = sys.newtonian();
    Frame& B = sys.add_frame("B");
    B.orient_axis(N, Axis::z, -beta);
    RigidBody& D = sys.add_rigid_body("D");
    D.body_frame().orient_axis(N, Axis::z, q);
    sys.point("D_o").set_pos(sys.origin(), -R * q * B.x() + R * B.y());
    D.cm().set_pos(sys.point("D_o"), Vector());
    Point& D_P = sys.add_point("D_P", &D);
    D_P.set_pos(sys.point("D_o"), -R * B.y());
    D.set_mass(m);
    D.set_inertia(D.cm(), m * R * R / 4, m * R * R / 4, m * R * R / 2);
    sys.set_gravity(-g * N.y());
    sys.add_force(D_P, F * B.x(), "F");
    sys.add_force(D_P, N_n * B.y(), "Nn");
    std::vector<RoadmapRow> rows = plan_roadmap(sys, {q}, {q.d(2), F, N_n});
    ASSERT_EQ(rows.size(), 3u);
    const RoadmapRow& rq = row_for(rows, q.d(2));
    EXPECT_EQ(rq.motion, Motion::rotate);
    EXPECT_TRUE(along(rq.direction, N.z()));
    ASSERT_NE(rq.about, nullptr);
    EXPECT_EQ(rq.about->name(), "D_P");  // the contact point: the instantaneous centre
    EXPECT_TRUE(rq.additional_unknowns.empty());
    const RoadmapRow& rf = row_for(rows, F);
    EXPECT_EQ(rf.motion, Motion::translate);
    EXPECT_TRUE(along(rf.direction, B.x()));
    ASSERT_EQ(rf.additional_unknowns.size(), 1u);
    EXPECT_TRUE(rf.additional_unknowns[0].is_equal(q.d(2)));
    const RoadmapRow& rn = row_for(rows, N_n);
    EXPECT_EQ(rn.motion, Motion::translate);
    EXPECT_TRUE(along(rn.direction, B.y()));
    EXPECT_TRUE(rn.additional_unknowns.empty());
    EXPECT_TRUE(rows[0].variable.is_equal(q.d(2)) || rows[0].variable.is_equal(N_n));
    // the disk's centre is placed, not pinned: no joint force there
    for (const std::string& line : rq.fbd)
        EXPECT_EQ(line.find("joint force"), std::string::npos) << line;
    for (double b : {0.25, 0.6}) {
        std::vector<double> v = solve_rows(sys, rows, {q.d(2), F, N_n},
                                           {{q.symbol(), 0.8}, {q.d(1), -2.0}, {m, 1.5},
                                            {R, 0.3}, {g, 9.81}, {beta, b}});
        expect_close(v[0], -2 * 9.81 * std::sin(b) / (3 * 0.3), "q''");
        expect_close(v[1], -1.5 * 9.81 / 3 * std::sin(b), "F");
        expect_close(v[2], 1.5 * 9.81 * std::cos(b), "N_n");
    }
}

// Refused: two unknown forces along one line of action (N_w and a second wall force N_v at
// the top, both along Nx>) appear in every row together, so no rows tell them apart; the
// message names them and says what to change.
TEST(ContactRows, ForcesOnOneLineStayRefusedWithTheFix) {
    Rod rod;
    ex N_v = rod.s.add_unknown("N_v");
    rod.sys.add_force(rod.A_w, N_v * rod.N.x(), "Nv");
    EXPECT_THROW_MSG(plan_roadmap(rod.sys, {rod.q}, {rod.q.d(2), rod.N_w, rod.N_f, N_v}),
                     ModelError, "no choice of S, direction and about point determines N_w, N_v");
    EXPECT_THROW_MSG(plan_roadmap(rod.sys, {rod.q}, {rod.q.d(2), rod.N_w, rod.N_f, N_v}),
                     ModelError, "declare each contact force on the body it acts on");
}

}  // namespace contact_rows
