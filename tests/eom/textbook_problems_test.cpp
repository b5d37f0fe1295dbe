// SPDX-License-Identifier: MIT
// Textbook problems solved by the planner's road-maps, each stated as a textbook would and
// derived by hand in its comment (virtual work, free-body diagrams, Lagrange, Newton-Euler):
// the road-map's S, O and u as a textbook would choose them, and every number to 1e-12.
#include <Eigen/Dense>

#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;

// a named namespace: the unity build joins this file with others that have their own helpers
namespace textbook {

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

// the rows (all but the constraint rows when `balance_only`) solved numerically for xs
Eigen::VectorXd solve_rows(const System& sys, const std::vector<RoadmapRow>& rows,
                           const std::vector<ex>& xs, const exmap& values,
                           bool balance_only = false) {
    std::vector<ex> E;
    for (const RoadmapRow& r : rows)
        if (!balance_only || r.motion != Motion::constraint) E.push_back(r.equation);
    return solve_numeric(sys.symbols(), form_linear_system(E, xs), values);
}

void expect_close(double got, double hand, const char* what) {
    EXPECT_NEAR(got, hand, 1e-12 * std::max(1.0, std::fabs(hand))) << what;
}

// z component of a x b in the plane
double cross_z(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

// ==========================================================================================
// (1) Slider-crank. A crank A (length a, mass m_A, uniform) turns about the fixed pin N_o
// (angle qA from Nx>); a connecting rod B (length b, mass m_B, uniform) is pinned to the
// crank's tip A_t (angle qB from the crank); its tip B_t is pinned to a slider C (mass m_C, a
// particle) that slides on the frictionless horizontal guide y = 0 at x. Gravity -g Ny>. A
// motor torque T Nz> drives the crank, a known load P Nx> pushes the slider, the guide pushes
// it up with N_n Ny>, and the rod's pin pushes it with F = F_x Nx> + F_y Ny> (-F on the rod).
// The model keeps qA, qB and x and declares the loop B_t = C (loop_x, loop_y).
//
// Geometry, with the rod's absolute angle phi = qA + qB and th = qA:
//   a sin th + b sin phi = 0, x = a cos th + b cos phi (cos phi > 0: slider to the right);
//   phi' = -a cos th th' / (b cos phi),
//   phi'' = (a sin th th'^2 - a cos th th'' + b sin phi phi'^2) / (b cos phi),
//   x' = -a sin th th' - b sin phi phi',
//   x'' = -a cos th th'^2 - a sin th th'' - b cos phi phi'^2 - b sin phi phi''.
// Statics by virtual work (N_n and the pins do none; y of both mass centres is
// (a/2) sin th, since b sin phi = -a sin th):
//   T dth + P dx - (m_A + m_B) g (a/2) cos th dth = 0, dx/dth = -a sin(th - phi) / cos phi,
//   T = (m_A + m_B) g (a/2) cos th + P a sin(th - phi) / cos phi.
// Statics of the slider and the rod: along Nx>, F_x + P = 0; the rod about A_t:
//   b (F_x sin phi - F_y cos phi) = m_B g (b/2) cos phi, so F_y = F_x tan phi - m_B g / 2;
//   the slider along Ny>: N_n = m_C g - F_y = m_C g + m_B g / 2 + P tan phi.
// Dynamics by the free-body diagram of each link (e = (cos phi, sin phi), e_t = (-sin phi,
// cos phi), the same with th for the crank):
//   slider: F_x = m_C x'' - P, N_n = m_C g - F_y;
//   rod about A_t: b (e x (-F))_z - m_B g (b/2) cos phi = I_B phi'' + (b/2) (e x m_B a_Bcm)_z,
//     a_Bcm = a (th'' e_t(th) - th'^2 e(th)) + (b/2)(phi'' e_t - phi'^2 e), I_B = m_B b^2/12;
//   the pin force on the rod from the crank R = m_B a_Bcm + m_B g Ny> + F;
//   crank about N_o: T - a (e(th) x R)_z - m_A g (a/2) cos th = (m_A a^2/3) th''.
// ==========================================================================================

namespace {

struct SliderCrank {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable qA = s.add_variable("qA"), qB = s.add_variable("qB"), x = s.add_variable("x");
    ex a = s.add_constant("a"), b = s.add_constant("b"), g = s.add_constant("g");
    ex m_A = s.add_constant("m_A"), m_B = s.add_constant("m_B"), m_C = s.add_constant("m_C");
    ex P = s.add_constant("P");
    ex T = s.add_unknown("T"), N_n = s.add_unknown("N_n");
    ex F_x = s.add_unknown("F_x"), F_y = s.add_unknown("F_y");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    Particle& C = sys.add_particle("C");
    Point& A_t = sys.add_point("A_t", &A);
    Point& B_t = sys.add_point("B_t", &B);
    explicit SliderCrank(bool pin_force = true) {
        A.body_frame().orient_axis(N, Axis::z, qA);
        B.body_frame().orient_axis(A.body_frame(), Axis::z, qB);
        sys.point("A_o").set_pos(sys.origin(), Vector());
        A.cm().set_pos(sys.point("A_o"), a / 2 * A.body_frame().x());
        A_t.set_pos(sys.point("A_o"), a * A.body_frame().x());
        sys.point("B_o").set_pos(A_t, Vector());
        B.cm().set_pos(sys.point("B_o"), b / 2 * B.body_frame().x());
        B_t.set_pos(sys.point("B_o"), b * B.body_frame().x());
        C.cm().set_pos(sys.origin(), x * N.x());
        A.set_mass(m_A);
        A.set_inertia(A.cm(), 0, 0, m_A * a * a / 12);
        B.set_mass(m_B);
        B.set_inertia(B.cm(), 0, 0, m_B * b * b / 12);
        C.set_mass(m_C);
        sys.set_gravity(-g * N.y());
        sys.add_torque(A, T * N.z(), "T");
        sys.add_force(C.cm(), P * N.x(), "P");
        sys.add_force(C.cm(), N_n * N.y(), "Nn");
        if (pin_force) sys.add_force_pair(C.cm(), B_t, F_x * N.x() + F_y * N.y(), "pin");
        sys.add_configuration_constraint("loop", B_t.pos_from(C.cm()), N);
    }
};

constexpr double kA = 0.3, kB = 1.1, kG = 9.81, kmA = 1.4, kmB = 2.3, kmC = 3.1;

// the slider-crank's pose, speeds and accelerations from the crank's, by hand (above)
struct SliderCrankMotion {
    double th, thd, thdd, phi, phid, phidd, x, xd, xdd;
    SliderCrankMotion(double th_, double thd_, double thdd_)
        : th(th_), thd(thd_), thdd(thdd_) {
        phi = std::asin(-kA / kB * std::sin(th));
        phid = -kA * std::cos(th) * thd / (kB * std::cos(phi));
        phidd = (kA * std::sin(th) * thd * thd - kA * std::cos(th) * thdd +
                 kB * std::sin(phi) * phid * phid) / (kB * std::cos(phi));
        x = kA * std::cos(th) + kB * std::cos(phi);
        xd = -kA * std::sin(th) * thd - kB * std::sin(phi) * phid;
        xdd = -kA * std::cos(th) * thd * thd - kA * std::sin(th) * thdd -
              kB * std::cos(phi) * phid * phid - kB * std::sin(phi) * phidd;
    }
};

exmap slider_crank_values(const SliderCrank& m, const SliderCrankMotion& k, double P) {
    return {{m.qA.symbol(), k.th}, {m.qB.symbol(), k.phi - k.th}, {m.x.symbol(), k.x},
            {m.qA.d(1), k.thd},    {m.qB.d(1), k.phid - k.thd},   {m.x.d(1), k.xd},
            {m.qA.d(2), k.thdd},   {m.a, kA}, {m.b, kB}, {m.g, kG}, {m.m_A, kmA},
            {m.m_B, kmB},          {m.m_C, kmC}, {m.P, P}};
}

}  // namespace

// Statics with a load on the slider: the guide's normal force needs a free-body row of the
// slider in a model with declared constraints (the pin force F is the loop's force, declared).
TEST(TextbookProblems, SliderCrankStaticsTorqueAndGuideForce) {
    SliderCrank m;
    const std::vector<ex> xs{m.T, m.N_n, m.F_x, m.F_y, m.qB.symbol(), m.x.symbol()};
    std::vector<RoadmapRow> rows = plan_roadmap(m.sys, {m.qA, m.qB, m.x}, xs, Analysis::statics);
    ASSERT_EQ(rows.size(), 6u);
    // the textbook's choices: the slider alone along the guide's normal for N_n, what turns
    // with the crank about the fixed pin for T, the loop's equations for the dependent pose
    const RoadmapRow& rn = row_for(rows, m.N_n);
    EXPECT_EQ(rn.motion, Motion::translate);
    EXPECT_TRUE(along(rn.direction, m.N.y()));
    EXPECT_EQ(body_names(rn.system), "C");
    const RoadmapRow& rt = row_for(rows, m.T);
    EXPECT_EQ(rt.motion, Motion::rotate);
    EXPECT_TRUE(along(rt.direction, m.N.z()));
    EXPECT_EQ(body_names(rt.system), "A,B");
    ASSERT_NE(rt.about, nullptr);
    EXPECT_EQ(rt.about->name(), "A_o");
    EXPECT_EQ(row_for(rows, m.qB.symbol()).motion, Motion::constraint);
    EXPECT_EQ(row_for(rows, m.x.symbol()).motion, Motion::constraint);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), load(-50.0, 50.0);
    for (int k = 0; k < 5; ++k) {
        const double P = load(rng);
        SliderCrankMotion pose(angle(rng), 0, 0);
        const exmap at = slider_crank_values(m, pose, P);
        // the hand pose meets the loop's rows
        for (const RoadmapRow& r : rows)
            if (r.motion == Motion::constraint) {
                EXPECT_NEAR(m.s.evaluate(r.equation, at), 0, 1e-12);
            }
        Eigen::VectorXd v = solve_rows(m.sys, rows, {m.T, m.N_n, m.F_x, m.F_y}, at, true);
        const double th = pose.th, phi = pose.phi;
        expect_close(v(0), (kmA + kmB) * kG * kA / 2 * std::cos(th) +
                               P * kA * std::sin(th - phi) / std::cos(phi), "T (virtual work)");
        expect_close(v(1), kmC * kG + kmB * kG / 2 + P * std::tan(phi), "N_n");
        expect_close(v(2), -P, "F_x");
        expect_close(v(3), -P * std::tan(phi) - kmB * kG / 2, "F_y");
    }
}

// Inverse dynamics at a given crank motion (qA, qA', qA''): the motor torque, the guide's
// force, the pin force and the dependent accelerations, against each link's free-body diagram.
TEST(TextbookProblems, SliderCrankInverseDynamicsAgainstEachLinksFreeBody) {
    SliderCrank m;
    const std::vector<ex> xs{m.T, m.N_n, m.F_x, m.F_y, m.qB.d(2), m.x.d(2)};
    std::vector<RoadmapRow> rows = plan_roadmap(m.sys, {m.qA, m.qB, m.x}, xs);
    ASSERT_EQ(rows.size(), 6u);
    const RoadmapRow& rn = row_for(rows, m.N_n);
    EXPECT_EQ(rn.motion, Motion::translate);
    EXPECT_TRUE(along(rn.direction, m.N.y()));
    EXPECT_EQ(body_names(rn.system), "C");
    // the slider does not accelerate along Ny>: its row holds N_n and the pin's F_y only
    ASSERT_EQ(rn.additional_unknowns.size(), 1u);
    EXPECT_TRUE(rn.additional_unknowns[0].is_equal(m.F_y));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0), load(-50.0, 50.0);
    for (int k = 0; k < 5; ++k) {
        const double P = load(rng);
        SliderCrankMotion h(angle(rng), rate(rng), rate(rng));
        Eigen::VectorXd v = solve_rows(m.sys, rows, xs, slider_crank_values(m, h, P));
        // the free-body diagrams of slider, rod and crank (above)
        const double F_x = kmC * h.xdd - P;
        const Eigen::Vector2d e(std::cos(h.phi), std::sin(h.phi)), e_t(-std::sin(h.phi), std::cos(h.phi));
        const Eigen::Vector2d c(std::cos(h.th), std::sin(h.th)), c_t(-std::sin(h.th), std::cos(h.th));
        const Eigen::Vector2d a_At = kA * (h.thdd * c_t - h.thd * h.thd * c);
        const Eigen::Vector2d a_Bcm = a_At + kB / 2 * (h.phidd * e_t - h.phid * h.phid * e);
        const double I_B = kmB * kB * kB / 12;
        // b (F_x sin phi - F_y cos phi) = I_B phi'' + (b/2) m_B (e x a_Bcm)_z + m_B g (b/2) cos phi
        const double F_y = (kB * F_x * std::sin(h.phi) - I_B * h.phidd -
                            kB / 2 * kmB * cross_z(e, a_Bcm) - kmB * kG * kB / 2 * std::cos(h.phi)) /
                           (kB * std::cos(h.phi));
        const Eigen::Vector2d R = kmB * a_Bcm + Eigen::Vector2d(0, kmB * kG) + Eigen::Vector2d(F_x, F_y);
        const double T = kmA * kA * kA / 3 * h.thdd + kA * cross_z(c, R) + kmA * kG * kA / 2 * std::cos(h.th);
        expect_close(v(0), T, "T");
        expect_close(v(1), kmC * kG - F_y, "N_n");
        expect_close(v(2), F_x, "F_x");
        expect_close(v(3), F_y, "F_y");
        expect_close(v(4), h.phidd - h.thdd, "qB''");
        expect_close(v(5), h.xdd, "x''");
    }
}

// With the loop declared but its pin force not, the loop's force is nowhere in the model: a
// free-body row of the slider would miss it, so N_n stays refused, and the message says why.
TEST(TextbookProblems, SliderCrankWithoutThePinForceIsRefusedSayingWhy) {
    SliderCrank m(false);
    EXPECT_THROW_MSG(plan_roadmap(m.sys, {m.qA, m.qB, m.x},
                                  {m.T, m.N_n, m.qB.symbol(), m.x.symbol()}, Analysis::statics),
                     ModelError, "the forces of the constraints loop_x, loop_y are no declared loads");
}

// The same slider-crank in minimal coordinates: the crank angle qA alone, the rod turned from
// the crank by qB(qA) = asin(-(a/b) sin qA) - qA, the slider pinned at the rod's tip (no pin
// force declared: a joint). A textbook takes the rod and slider {B, C} about the crank pin
// B_o, where the pin's force drops out (N_n, P, gravity and the inertia of B and C remain),
// then the whole linkage about N_o for T (N_n known). Both numbers agree with the model
// above, by the same hand derivations, in statics and at a given crank motion.
TEST(TextbookProblems, SliderCrankInMinimalCoordinatesAgrees) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable qA = s.add_variable("qA");
    ex a = s.add_constant("a"), b = s.add_constant("b"), g = s.add_constant("g");
    ex m_A = s.add_constant("m_A"), m_B = s.add_constant("m_B"), m_C = s.add_constant("m_C");
    ex P = s.add_constant("P");
    ex T = s.add_unknown("T"), N_n = s.add_unknown("N_n");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    Particle& C = sys.add_particle("C");
    A.body_frame().orient_axis(N, Axis::z, qA);
    B.body_frame().orient_axis(A.body_frame(), Axis::z,
                               GiNaC::asin(-a / b * GiNaC::sin(qA.symbol())) - qA.symbol());
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), a / 2 * A.body_frame().x());
    Point& A_t = sys.add_point("A_t", &A);
    A_t.set_pos(sys.point("A_o"), a * A.body_frame().x());
    sys.point("B_o").set_pos(A_t, Vector());
    B.cm().set_pos(sys.point("B_o"), b / 2 * B.body_frame().x());
    Point& B_t = sys.add_point("B_t", &B);
    B_t.set_pos(sys.point("B_o"), b * B.body_frame().x());
    C.cm().set_pos(B_t, Vector());
    A.set_mass(m_A);
    A.set_inertia(A.cm(), 0, 0, m_A * a * a / 12);
    B.set_mass(m_B);
    B.set_inertia(B.cm(), 0, 0, m_B * b * b / 12);
    C.set_mass(m_C);
    sys.set_gravity(-g * N.y());
    sys.add_torque(A, T * N.z(), "T");
    sys.add_force(C.cm(), P * N.x(), "P");
    sys.add_force(C.cm(), N_n * N.y(), "Nn");
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0), load(-50.0, 50.0);
    for (Analysis analysis : {Analysis::statics, Analysis::dynamics}) {
        std::vector<RoadmapRow> rows = plan_roadmap(sys, {qA}, {T, N_n}, analysis);
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_TRUE(rows[0].variable.is_equal(N_n));
        EXPECT_EQ(rows[0].motion, Motion::rotate);
        EXPECT_TRUE(along(rows[0].direction, N.z()) || along(rows[0].direction, -N.z()));
        EXPECT_EQ(body_names(rows[0].system), "B,C");
        ASSERT_NE(rows[0].about, nullptr);
        EXPECT_EQ(rows[0].about->name(), "B_o");
        EXPECT_TRUE(rows[0].additional_unknowns.empty());
        EXPECT_TRUE(rows[1].variable.is_equal(T));
        EXPECT_EQ(rows[1].motion, Motion::rotate);
        EXPECT_EQ(body_names(rows[1].system), "A,B,C");
        ASSERT_NE(rows[1].about, nullptr);
        EXPECT_EQ(rows[1].about->name(), "A_o");
        for (int k = 0; k < 4; ++k) {
            const double Pv = load(rng);
            const bool still = analysis == Analysis::statics;
            SliderCrankMotion h(angle(rng), still ? 0 : rate(rng), still ? 0 : rate(rng));
            Eigen::VectorXd v = solve_rows(sys, rows, {T, N_n},
                                           {{qA.symbol(), h.th}, {qA.d(1), h.thd}, {qA.d(2), h.thdd},
                                            {a, kA}, {b, kB}, {g, kG}, {m_A, kmA}, {m_B, kmB},
                                            {m_C, kmC}, {P, Pv}});
            // the full model's rows at the same state (checked against the hand derivation above)
            SliderCrank full;
            std::vector<RoadmapRow> full_rows =
                still ? plan_roadmap(full.sys, {full.qA, full.qB, full.x},
                                     {full.T, full.N_n, full.F_x, full.F_y, full.qB.symbol(), full.x.symbol()},
                                     Analysis::statics)
                      : plan_roadmap(full.sys, {full.qA, full.qB, full.x},
                                     {full.T, full.N_n, full.F_x, full.F_y, full.qB.d(2), full.x.d(2)});
            Eigen::VectorXd w =
                still ? solve_rows(full.sys, full_rows, {full.T, full.N_n, full.F_x, full.F_y},
                                   slider_crank_values(full, h, Pv), true)
                      : solve_rows(full.sys, full_rows,
                                   {full.T, full.N_n, full.F_x, full.F_y, full.qB.d(2), full.x.d(2)},
                                   slider_crank_values(full, h, Pv));
            expect_close(v(0), w(0), "T");
            expect_close(v(1), w(1), "N_n");
            if (still) {
                const double phi = h.phi, th = h.th;
                expect_close(v(0), (kmA + kmB) * kG * kA / 2 * std::cos(th) +
                                       Pv * kA * std::sin(th - phi) / std::cos(phi), "T (virtual work)");
                expect_close(v(1), kmC * kG + kmB * kG / 2 + Pv * std::tan(phi), "N_n");
            }
        }
    }
}

// ==========================================================================================
// (2) Bead on a hoop. A hoop H (mass M, radius R, a thin ring: I = M R^2 / 2 about a
// diameter, M R^2 about its axis Hy) turns freely about its vertical diameter Nz> = Hz>
// (angle psi; no motor); a bead Q (mass m, a particle) slides without friction on it at the
// angle th from the bottom: r^Q = R (sin th Hx> - cos th Hz>). The hoop pushes the bead
// with N_1 Hy> (normal to the hoop's plane) and N_2 e_r (e_r = sin th Hx> - cos th Hz>, out
// from the centre). Gravity -g Nz>.
// Lagrange: T = (1/2) I psi'^2 + (1/2) m R^2 (th'^2 + sin^2 th psi'^2),
// V = -m g R cos th, I = M R^2 / 2:
//   th:  m R^2 th'' - m R^2 sin th cos th psi'^2 + m g R sin th = 0,
//   psi: (I + m R^2 sin^2 th) psi'' + 2 m R^2 sin th cos th th' psi' = 0.
// The bead's acceleration in N (e_t = cos th Hx> + sin th Hz>, w = psi' Nz>):
//   a = R th'' e_t - R th'^2 e_r + psi'' R sin th Hy> - psi'^2 R sin th Hx>
//       + 2 psi' R th' cos th Hy>,
// so F = m a along Hy> and e_r (Nz> . e_r = -cos th, Hx> . e_r = sin th):
//   N_1 = m R (psi'' sin th + 2 psi' th' cos th),
//   N_2 = -m g cos th - m R th'^2 - m R psi'^2 sin^2 th.
// The road-map a textbook writes: psi'' about the axis for hoop and bead (the pair force is
// internal), th'' along e_t for the bead alone (N_1 and N_2 are normal to it), N_1 and N_2
// along their own directions for the bead.
// ==========================================================================================
TEST(TextbookProblems, BeadOnAFreelyTurningHoopAgainstLagrangeAndNewton) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable psi = s.add_variable("psi"), th = s.add_variable("th");
    ex M = s.add_constant("M"), R = s.add_constant("R", std::nullopt, true), m = s.add_constant("m");
    ex g = s.add_constant("g");
    ex N_1 = s.add_unknown("N_1"), N_2 = s.add_unknown("N_2");
    const Frame& N = sys.newtonian();
    RigidBody& H = sys.add_rigid_body("H");
    H.body_frame().orient_axis(N, Axis::z, psi);
    const Frame& Hf = H.body_frame();
    sys.point("H_o").set_pos(sys.origin(), Vector());
    H.cm().set_pos(sys.point("H_o"), Vector());
    H.set_mass(M);
    H.set_inertia(H.cm(), M * R * R / 2, M * R * R, M * R * R / 2);
    Particle& Q = sys.add_particle("Q");
    const Vector e_r = GiNaC::sin(th) * Hf.x() - GiNaC::cos(th) * Hf.z();
    Q.cm().set_pos(sys.point("H_o"), R * e_r);
    Q.set_mass(m);
    Point& H_Q = sys.add_point("H_Q", &H);  // the hoop's point under the bead
    H_Q.set_pos(sys.point("H_o"), R * e_r);
    sys.set_gravity(-g * N.z());
    sys.add_force_pair(Q.cm(), H_Q, N_1 * Hf.y() + N_2 * e_r, "hoop");
    const std::vector<ex> xs{psi.d(2), th.d(2), N_1, N_2};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, {psi, th}, xs);
    ASSERT_EQ(rows.size(), 4u);
    const RoadmapRow& rp = row_for(rows, psi.d(2));
    EXPECT_EQ(rp.motion, Motion::rotate);
    EXPECT_TRUE(along(rp.direction, N.z()));
    EXPECT_EQ(body_names(rp.system), "H,Q");
    ASSERT_NE(rp.about, nullptr);
    EXPECT_EQ(rp.about->name(), "H_o");
    const RoadmapRow& rt = row_for(rows, th.d(2));
    EXPECT_EQ(rt.motion, Motion::translate);
    EXPECT_TRUE(along(rt.direction, GiNaC::cos(th) * Hf.x() + GiNaC::sin(th) * Hf.z()));
    EXPECT_EQ(body_names(rt.system), "Q");
    const RoadmapRow& r1 = row_for(rows, N_1);
    EXPECT_EQ(r1.motion, Motion::translate);
    EXPECT_TRUE(along(r1.direction, Hf.y()));
    EXPECT_EQ(body_names(r1.system), "Q");
    const RoadmapRow& r2 = row_for(rows, N_2);
    EXPECT_EQ(r2.motion, Motion::translate);
    EXPECT_TRUE(along(r2.direction, e_r) || along(r2.direction, -e_r)) << format_roadmap_table(sys, rows);
    EXPECT_EQ(body_names(r2.system), "Q");
    for (const RoadmapRow& r : rows) EXPECT_TRUE(r.note.empty() || r.note.find("solve") == 0) << r.note;
    const double kM = 0.8, kR = 0.45, km = 0.15, g0 = 9.81;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-5.0, 5.0);
    for (int k = 0; k < 6; ++k) {
        const double q = angle(rng), qd = rate(rng), wd = rate(rng);
        Eigen::VectorXd v = solve_rows(sys, rows, xs,
                                       {{psi.symbol(), angle(rng)}, {th.symbol(), q},
                                        {psi.d(1), wd}, {th.d(1), qd}, {M, kM}, {R, kR},
                                        {m, km}, {g, g0}});
        const double I = kM * kR * kR / 2, sq = std::sin(q), cq = std::cos(q);
        const double thdd = sq * cq * wd * wd - g0 / kR * sq;
        const double psidd = -2 * km * kR * kR * sq * cq * qd * wd / (I + km * kR * kR * sq * sq);
        expect_close(v(0), psidd, "psi'' (Lagrange)");
        expect_close(v(1), thdd, "th'' (Lagrange)");
        expect_close(v(2), km * kR * (psidd * sq + 2 * wd * qd * cq), "N_1");
        expect_close(v(3), -km * g0 * cq - km * kR * qd * qd - km * kR * wd * wd * sq * sq, "N_2");
    }
}

// ==========================================================================================
// (3) A 3D two-link arm. The shoulder at N_o turns the upper arm U by a yaw q1 about Nz> (an
// intermediate massless yoke Y) and a pitch q2 about Yx> (U = Y turned about x); the elbow
// turns the forearm F by q3 about Ux>. Each link lies along its y axis: U's mass centre at
// (L1/2) Uy>, the elbow E = F_o at L1 Uy>, F's mass centre at (L2/2) Fy> from E; central
// inertias diag(Ixx, Iyy, Izz) in the link's axes. Motors: T1 Nz> and T2 Yx> on U from the
// ground (through the yoke), T3 Ux> on F from U. Gravity -g Nz>. Declared reactions: the
// shoulder's force S_x Nx> + S_y Ny> + S_z Nz> and torque S_m Yy> (the one direction the
// yoke's two axes do not turn about) on U from the ground at N_o; the elbow's force
// E_x Ux> + E_y Uy> + E_z Uz> and torques E_my Uy>, E_mz Uz> on F from U at E.
// Newton-Euler summed from the tip (the test's own, with Eigen matrices):
//   w_U = q1' z + q2' x_Y, alpha_U = q1'' z + q2'' x_Y + (q1' z) x (q2' x_Y),
//   w_F = w_U + q3' x_U, alpha_F = alpha_U + q3'' x_U + w_U x (q3' x_U),
//   a_P = alpha x r + w x (w x r) for points of U (N_o fixed), a_Fcm from a_E likewise;
//   forearm: F_E = m2 (a_Fcm + g z), Tq_E = I_F alpha_F + w_F x I_F w_F + r^{Fcm/E} x F_E
//            (the force and torque on F from U at E);
//   upper arm: F_S = m1 (a_Ucm + g z) + F_E,
//              Tq_S = I_U alpha_U + w_U x I_U w_U + r^{Ucm} x m1 (a_Ucm + g z) + Tq_E + r^E x F_E
//            (about N_o; the force and torque on U from the ground).
// Each measure is that force or torque along its direction: T3 = Tq_E . x_U, E_my = Tq_E . y_U,
// T1 = Tq_S . z, T2 = Tq_S . x_Y, S_m = Tq_S . y_Y, and so on.
// A textbook's rows: a force measure translates what lies beyond its joint along it, a torque
// measure turns it about the joint, about the joint point.
// ==========================================================================================
TEST(TextbookProblems, SpatialTwoLinkArmReactionsAgainstNewtonEulerFromTheTip) {
    System sys;
    SymbolTable& s = sys.symbols();
    TimeVariable q1 = s.add_variable("q1"), q2 = s.add_variable("q2"), q3 = s.add_variable("q3");
    ex L1 = s.add_constant("L1"), L2 = s.add_constant("L2"), g = s.add_constant("g");
    ex m1 = s.add_constant("m1"), m2 = s.add_constant("m2");
    ex I1x = s.add_constant("I1x"), I1y = s.add_constant("I1y"), I1z = s.add_constant("I1z");
    ex I2x = s.add_constant("I2x"), I2y = s.add_constant("I2y"), I2z = s.add_constant("I2z");
    ex T1 = s.add_unknown("T1"), T2 = s.add_unknown("T2"), T3 = s.add_unknown("T3");
    ex S_x = s.add_unknown("S_x"), S_y = s.add_unknown("S_y"), S_z = s.add_unknown("S_z");
    ex S_m = s.add_unknown("S_m");
    ex E_x = s.add_unknown("E_x"), E_y = s.add_unknown("E_y"), E_z = s.add_unknown("E_z");
    ex E_my = s.add_unknown("E_my"), E_mz = s.add_unknown("E_mz");
    const Frame& N = sys.newtonian();
    Frame& Y = sys.add_frame("Y");
    Y.orient_axis(N, Axis::z, q1);
    RigidBody& U = sys.add_rigid_body("U");
    RigidBody& F = sys.add_rigid_body("F");
    const Frame &Uf = U.body_frame(), &Ff = F.body_frame();
    U.body_frame().orient_axis(Y, Axis::x, q2);
    F.body_frame().orient_axis(Uf, Axis::x, q3);
    Point& U_o = sys.point("U_o");
    U_o.set_pos(sys.origin(), Vector());
    U.cm().set_pos(U_o, L1 / 2 * Uf.y());
    Point& E = sys.point("F_o");
    E.set_pos(U_o, L1 * Uf.y());
    F.cm().set_pos(E, L2 / 2 * Ff.y());
    U.set_mass(m1);
    U.set_inertia(U.cm(), I1x, I1y, I1z);
    F.set_mass(m2);
    F.set_inertia(F.cm(), I2x, I2y, I2z);
    sys.set_gravity(-g * N.z());
    sys.add_torque(U, T1 * N.z() + T2 * Y.x(), "shoulder motors");
    sys.add_torque_pair(F, Uf, T3 * Uf.x(), "elbow motor");
    sys.add_joint_reaction("shoulder", nullptr, U, U_o,
                           {{S_x, N.x()}, {S_y, N.y()}, {S_z, N.z()}}, {{S_m, Y.y()}});
    sys.add_joint_reaction("elbow", &U, F, E, {{E_x, Uf.x()}, {E_y, Uf.y()}, {E_z, Uf.z()}},
                           {{E_my, Uf.y()}, {E_mz, Uf.z()}});
    const std::vector<ex> xs{T1, T2, T3, S_x, S_y, S_z, S_m, E_x, E_y, E_z, E_my, E_mz};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, {q1, q2, q3}, xs);
    ASSERT_EQ(rows.size(), xs.size());
    // S, O, u as a textbook chooses them
    struct Choice {
        ex x;
        Motion motion;
        Vector u;
        const char* S;
        const char* O;
    };
    const Choice choices[] = {
        {T1, Motion::rotate, N.z(), "U,F", "U_o"},     {T2, Motion::rotate, Y.x(), "U,F", "U_o"},
        {T3, Motion::rotate, Uf.x(), "F", "F_o"},      {S_x, Motion::translate, N.x(), "U,F", "U_o"},
        {S_y, Motion::translate, N.y(), "U,F", "U_o"}, {S_z, Motion::translate, N.z(), "U,F", "U_o"},
        {S_m, Motion::rotate, Y.y(), "U,F", "U_o"},    {E_x, Motion::translate, Uf.x(), "F", "F_o"},
        {E_y, Motion::translate, Uf.y(), "F", "F_o"},  {E_z, Motion::translate, Uf.z(), "F", "F_o"},
        {E_my, Motion::rotate, Uf.y(), "F", "F_o"},    {E_mz, Motion::rotate, Uf.z(), "F", "F_o"}};
    for (const Choice& c : choices) {
        const RoadmapRow& r = row_for(rows, c.x);
        EXPECT_EQ(r.motion, c.motion) << to_string(c.x);
        EXPECT_TRUE(along(r.direction, c.u)) << to_string(c.x);
        EXPECT_EQ(body_names(r.system), c.S) << to_string(c.x);
        if (c.motion == Motion::rotate || r.about) {
            ASSERT_NE(r.about, nullptr) << to_string(c.x);
            EXPECT_EQ(r.about->name(), c.O) << to_string(c.x);
        }
    }
    const double kL1 = 0.35, kL2 = 0.3, kg = 9.81, km1 = 2.1, km2 = 1.3;
    const Eigen::Vector3d I1(0.031, 0.004, 0.029), I2(0.012, 0.002, 0.011);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0);
    using Eigen::AngleAxisd, Eigen::Matrix3d, Eigen::Vector3d;
    for (int k = 0; k < 5; ++k) {
        double q[3], qd[3], qdd[3];
        for (int i = 0; i < 3; ++i) q[i] = angle(rng), qd[i] = rate(rng), qdd[i] = rate(rng);
        exmap at{{L1, kL1}, {L2, kL2}, {g, kg}, {m1, km1}, {m2, km2}, {I1x, I1(0)},
                 {I1y, I1(1)}, {I1z, I1(2)}, {I2x, I2(0)}, {I2y, I2(1)}, {I2z, I2(2)}};
        const TimeVariable* qs[3] = {&q1, &q2, &q3};
        for (int i = 0; i < 3; ++i) {
            at[qs[i]->symbol()] = q[i];
            at[qs[i]->d(1)] = qd[i];
            at[qs[i]->d(2)] = qdd[i];
        }
        Eigen::VectorXd v = solve_rows(sys, rows, xs, at);
        // Newton-Euler by hand, from the tip
        const Vector3d z = Vector3d::UnitZ(), x = Vector3d::UnitX(), y = Vector3d::UnitY();
        const Matrix3d R_Y = AngleAxisd(q[0], z).toRotationMatrix();
        const Matrix3d R_U = R_Y * AngleAxisd(q[1], x).toRotationMatrix();
        const Matrix3d R_F = R_U * AngleAxisd(q[2], x).toRotationMatrix();
        const Vector3d xY = R_Y * x, yY = R_Y * y, xU = R_U * x, yU = R_U * y, zU = R_U * z;
        const Vector3d w_Y = qd[0] * z, w_U = w_Y + qd[1] * xY, w_F = w_U + qd[2] * xU;
        const Vector3d al_U = qdd[0] * z + qdd[1] * xY + w_Y.cross(qd[1] * xY);
        const Vector3d al_F = al_U + qdd[2] * xU + w_U.cross(qd[2] * xU);
        const Vector3d r_Ucm = kL1 / 2 * yU, r_E = kL1 * yU, r_FcmE = kL2 / 2 * (R_F * y);
        auto acc = [](const Vector3d& al, const Vector3d& w, const Vector3d& r) {
            return Vector3d(al.cross(r) + w.cross(w.cross(r)));
        };
        const Vector3d a_Ucm = acc(al_U, w_U, r_Ucm), a_E = acc(al_U, w_U, r_E);
        const Vector3d a_Fcm = a_E + acc(al_F, w_F, r_FcmE);
        const Matrix3d I_U = R_U * I1.asDiagonal() * R_U.transpose();
        const Matrix3d I_F = R_F * I2.asDiagonal() * R_F.transpose();
        const Vector3d F_E = km2 * (a_Fcm + kg * z);
        const Vector3d Tq_E = I_F * al_F + w_F.cross(I_F * w_F) + r_FcmE.cross(F_E);
        const Vector3d F_U = km1 * (a_Ucm + kg * z);
        const Vector3d F_S = F_U + F_E;
        const Vector3d Tq_S =
            I_U * al_U + w_U.cross(I_U * w_U) + r_Ucm.cross(F_U) + Tq_E + r_E.cross(F_E);
        const double hand[] = {Tq_S.dot(z),  Tq_S.dot(xY), Tq_E.dot(xU), F_S.x(),     F_S.y(),    F_S.z(),
                               Tq_S.dot(yY), F_E.dot(xU), F_E.dot(yU), F_E.dot(zU), Tq_E.dot(yU), Tq_E.dot(zU)};
        for (std::size_t i = 0; i < xs.size(); ++i)
            expect_close(v(static_cast<Eigen::Index>(i)), hand[i], to_string(xs[i]).c_str());
    }
}

// ==========================================================================================
// (4) Four-bar linkage in statics with a load on the coupler. The crank A (length L_A,
// angle qA from Nx> about N_o), the coupler B (L_B, pinned at A's tip, angle qB from the
// crank) and the rocker C (L_C, angle qC about N_c = L_N Nx>) close a loop (make_four_bar:
// masses m_A, m_B, m_C, uniform, gravity -g Ny>), with the crank torque T and the loop's pin
// force F_x, F_y unknown. A known force P = P_x Nx> + P_y Ny> acts at the coupler's mass
// centre. By virtual work along the loop (th_B = qA + qB the coupler's absolute angle):
//   T = sum m g dy_cm/dqA - P . dr^{Bcm}/dqA,
//   dy_Acm/dqA = (L_A/2) cos qA, dy_Bcm/dqA = L_A cos qA + (L_B/2) cos th_B th_B',
//   dy_Ccm/dqA = (L_C/2) cos qC qC', dr^{Bcm}/dqA = L_A e_t(qA) + (L_B/2) e_t(th_B) th_B',
// with the rates per unit qA' from the loop's velocity equation
//   L_A e_t(qA) + L_B e_t(th_B) th_B' = L_C e_t(qC) qC'   (e_t(a) = (-sin a, cos a)),
// solved by Cramer's rule: th_B' = L_A sin(qA - qC) / (L_B sin(qC - th_B)),
//                          qC' = L_A sin(qA - th_B) / (L_C sin(qC - th_B)).
// The pose: the crank tip A_t = L_A e(qA), the rocker pin P on both circles |P - A_t| = L_B,
// |P - N_c| = L_C (the branch above the line from A_t to N_c).
// ==========================================================================================
TEST(TextbookProblems, FourBarWithCouplerLoadCrankTorqueByVirtualWork) {
    SampleModel fb = make_four_bar();
    System& sys = fb.system;
    SymbolTable& s = sys.symbols();
    ex P_x = s.add_constant("P_x"), P_y = s.add_constant("P_y");
    sys.add_force(fb.links[1]->cm(), P_x * sys.newtonian().x() + P_y * sys.newtonian().y(), "P");
    const ex T = fb.unknowns[0];
    const std::vector<ex> xs{T, fb.unknowns[1], fb.unknowns[2], fb.q[1].symbol(), fb.q[2].symbol()};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, fb.q, xs, Analysis::statics);
    ASSERT_EQ(rows.size(), 5u);
    const RoadmapRow& rt = row_for(rows, T);
    EXPECT_EQ(rt.motion, Motion::rotate);
    EXPECT_EQ(body_names(rt.system), "A,B");
    EXPECT_EQ(rt.about->name(), "A_o");
    const double LN = 1.0, LA = 0.4, LB = 1.2, LC = 0.8, mA = 1.0, mB = 2.0, mC = 1.5, g = 9.81;
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> angle(-3.1, 3.1), load(-20.0, 20.0);
    for (int k = 0; k < 6; ++k) {
        const double qA = angle(rng), Px = load(rng), Py = load(rng);
        // the pose by circle intersection
        const Eigen::Vector2d At(LA * std::cos(qA), LA * std::sin(qA)), Nc(LN, 0);
        const double d = (Nc - At).norm(), a = (LB * LB - LC * LC + d * d) / (2 * d);
        const Eigen::Vector2d ed = (Nc - At) / d, en(-ed.y(), ed.x());
        const Eigen::Vector2d Pp = At + a * ed + std::sqrt(LB * LB - a * a) * en;
        const double thB = std::atan2(Pp.y() - At.y(), Pp.x() - At.x());
        const double qC = std::atan2(Pp.y(), Pp.x() - LN);
        const double thBd = LA * std::sin(qA - qC) / (LB * std::sin(qC - thB));
        const double qCd = LA * std::sin(qA - thB) / (LC * std::sin(qC - thB));
        const Eigen::Vector2d et_A(-std::sin(qA), std::cos(qA)), et_B(-std::sin(thB), std::cos(thB));
        const Eigen::Vector2d dr_Bcm = LA * et_A + LB / 2 * et_B * thBd;
        const double dV = g * (mA * LA / 2 * std::cos(qA) +
                               mB * (LA * std::cos(qA) + LB / 2 * std::cos(thB) * thBd) +
                               mC * LC / 2 * std::cos(qC) * qCd);
        const double T_hand = dV - (Px * dr_Bcm.x() + Py * dr_Bcm.y());
        const exmap at{{fb.q[0].symbol(), qA}, {fb.q[1].symbol(), thB - qA},
                       {fb.q[2].symbol(), qC}, {P_x, Px}, {P_y, Py}};
        for (const RoadmapRow& r : rows)
            if (r.motion == Motion::constraint) {
                EXPECT_NEAR(s.evaluate(r.equation, at), 0, 1e-12);
            }
        Eigen::VectorXd v = solve_rows(sys, rows, fb.unknowns, at, true);
        expect_close(v(0), T_hand, "T");
    }
}

}  // namespace textbook
