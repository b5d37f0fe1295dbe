// SPDX-License-Identifier: MIT
// Tests of the model registry, loads and their resultants, the textbook force models, and the
// energy of a system; all against hand derivations and physics.
#include "alembert/mech/system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "alembert/error.hpp"
#include "support/expect.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

using GiNaC::cos;
using GiNaC::ex_to;
using GiNaC::pow;
using GiNaC::sin;
using GiNaC::sqrt;
using GiNaC::symbol;
using alembert::test::same;

// d e / d s for a symbol s of the table.
ex partial(const ex& e, const ex& s) { return e.diff(ex_to<symbol>(s)); }

using alembert::test::near;

// ---- registry ------------------------------------------------------------------------------

TEST(System, StartsWithTheNewtonianFrameAndItsFixedOrigin) {
    System sys;
    EXPECT_EQ(sys.newtonian().name(), "N");
    EXPECT_EQ(sys.origin().name(), "N_o");
    EXPECT_EQ(&sys.frame("N"), &sys.newtonian());
    EXPECT_EQ(&sys.point("N_o"), &sys.origin());
    EXPECT_EQ(sys.origin().owner(), nullptr);
    EXPECT_TRUE(sys.origin().vel_in(sys.newtonian()).is_zero());
    EXPECT_TRUE(sys.origin().acc_in(sys.newtonian()).is_zero());
    EXPECT_TRUE(sys.bodies().empty());
    EXPECT_TRUE(sys.gravity().is_zero());

    System earth("E");
    EXPECT_EQ(earth.newtonian().name(), "E");
    EXPECT_EQ(earth.origin().name(), "E_o");
}

TEST(System, RigidBodyBringsItsFrameOriginAndMassCentreFixedOnIt) {
    System sys;
    RigidBody& B = sys.add_rigid_body("B");
    EXPECT_EQ(B.name(), "B");
    EXPECT_EQ(&sys.frame("B"), &B.body_frame());
    EXPECT_EQ(B.frame(), &B.body_frame());
    EXPECT_EQ(&sys.point("Bcm"), &B.cm());
    EXPECT_EQ(sys.point("B_o").owner(), &B);
    EXPECT_EQ(sys.point("Bcm").owner(), &B);
    EXPECT_EQ(&sys.body("B"), &B);
    EXPECT_EQ(&sys.rigid_body("B"), &B);
    EXPECT_EQ(sys.body_of(B.body_frame()), &B);
    EXPECT_EQ(sys.body_of(sys.newtonian()), nullptr);
    EXPECT_EQ(sys.body_of(sys.add_frame("F")), nullptr);
}

TEST(System, ParticleBringsAPointOfItsNameFixedOnIt) {
    System sys;
    Particle& Q = sys.add_particle("Q");
    EXPECT_EQ(&sys.point("Q"), &Q.point());
    EXPECT_EQ(Q.point().owner(), &Q);
    EXPECT_EQ(Q.frame(), nullptr);
    EXPECT_EQ(&sys.body("Q"), &Q);
    Point& P = sys.add_point("P", &Q);
    EXPECT_EQ(P.owner(), &Q);
}

TEST(System, BodiesAreListedInDeclarationOrderOrAsNamed) {
    System sys;
    RigidBody& A = sys.add_rigid_body("A");
    Particle& Q = sys.add_particle("Q");
    RigidBody& B = sys.add_rigid_body("B");
    EXPECT_EQ(sys.bodies(), (BodySet{&A, &Q, &B}));
    EXPECT_EQ(sys.bodies({"B", "Q"}), (BodySet{&B, &Q}));
    EXPECT_EQ(sys.points(), (std::vector<const Point*>{&sys.origin(), &sys.point("A_o"), &A.cm(),
                                                       &Q.point(), &sys.point("B_o"), &B.cm()}));
}

TEST(System, MovingASystemKeepsWhatItHandedOut) {
    System sys;
    RigidBody& B = sys.add_rigid_body("B");
    Frame& F = sys.add_frame("F");
    System moved = std::move(sys);
    EXPECT_EQ(&moved.rigid_body("B"), &B);
    EXPECT_EQ(&moved.frame("F"), &F);
    EXPECT_EQ(moved.point("Bcm").owner(), &B);
}

TEST(System, LookUpOfAnUnknownNameIsAnErrorListingTheDeclaredOnes) {
    System sys;
    sys.add_frame("A");
    sys.add_rigid_body("B");
    sys.add_particle("Q");
    EXPECT_THROW_MSG(sys.frame("X"), ModelError, "unknown frame 'X'; declared frames: N, A, B");
    EXPECT_THROW_MSG(sys.point("X"), ModelError,
                     "unknown point 'X'; declared points: N_o, B_o, Bcm, Q");
    EXPECT_THROW_MSG(sys.body("X"), ModelError, "unknown body or particle 'X'; declared: B, Q");
    EXPECT_THROW_MSG(sys.rigid_body("X"), ModelError, "unknown body or particle 'X'");
    EXPECT_THROW_MSG(sys.rigid_body("Q"), ModelError, "'Q' is a particle, not a rigid body");
    EXPECT_THROW_MSG(sys.bodies({"B", "X"}), ModelError, "unknown body or particle 'X'");

    System empty;
    EXPECT_THROW_MSG(empty.body("B"), ModelError, "unknown body or particle 'B'; declared: (none)");
}

TEST(System, DuplicateNamesAreErrorsNamingTheName) {
    System sys;
    sys.add_frame("A");
    sys.add_point("P");
    sys.add_rigid_body("B");
    sys.add_particle("Q");
    EXPECT_THROW_MSG(sys.add_frame("A"), ModelError, "a frame named 'A' exists already");
    EXPECT_THROW_MSG(sys.add_frame("N"), ModelError, "a frame named 'N' exists already");
    EXPECT_THROW_MSG(sys.add_point("P"), ModelError, "a point named 'P' exists already");
    EXPECT_THROW_MSG(sys.add_point("Bcm"), ModelError, "a point named 'Bcm' exists already");
    EXPECT_THROW_MSG(sys.add_rigid_body("B"), ModelError, "a body named 'B' exists already");
    EXPECT_THROW_MSG(sys.add_rigid_body("Q"), ModelError, "a body named 'Q' exists already");
    EXPECT_THROW_MSG(sys.add_particle("B"), ModelError, "a body named 'B' exists already");
    EXPECT_THROW_MSG(sys.add_particle("P"), ModelError, "a point named 'P' exists already");
    EXPECT_THROW_MSG(sys.add_rigid_body("A"), ModelError, "a frame named 'A' exists already");
    EXPECT_THROW_MSG(sys.add_point(""), ArgumentError, "a point needs a non-empty name");
    EXPECT_THROW_MSG(sys.add_frame(""), ArgumentError, "a frame needs a non-empty name");
    EXPECT_THROW_MSG(sys.add_rigid_body(""), ArgumentError, "a frame needs a non-empty name");
    EXPECT_THROW_MSG(sys.add_particle(""), ArgumentError, "a point needs a non-empty name");
    EXPECT_THROW_MSG(sys.frame(""), ModelError, "unknown frame ''");
}

TEST(System, AFailedRigidBodyDeclarationLeavesNothingBehind) {
    System sys;
    sys.add_point("C_o");
    EXPECT_THROW_MSG(sys.add_rigid_body("C"), ModelError, "a point named 'C_o' exists already");
    // no frame C, no point Ccm and no body C were left half-declared
    EXPECT_THROW_MSG(sys.frame("C"), ModelError, "unknown frame 'C'");
    EXPECT_THROW_MSG(sys.point("Ccm"), ModelError, "unknown point 'Ccm'");
    EXPECT_THROW_MSG(sys.body("C"), ModelError, "unknown body or particle 'C'");
    EXPECT_THROW_MSG(sys.add_rigid_body("C"), ModelError,
                     "rigid body 'C' needs that name for its origin");

    sys.add_point("Dcm");
    EXPECT_THROW_MSG(sys.add_rigid_body("D"), ModelError,
                     "a point named 'Dcm' exists already, and rigid body 'D' needs that name");
    EXPECT_THROW_MSG(sys.frame("D"), ModelError, "unknown frame 'D'");
    EXPECT_THROW_MSG(sys.point("D_o"), ModelError, "unknown point 'D_o'");
}

// ---- loads and resultants ------------------------------------------------------------------

// Two rigid bodies: A turns about Nz by qA at N_o, B turns about Az by qB at B_o, L along Ay;
// point P is fixed on A at a along Ax, point Q on B at b along Bx.
class SystemOfTwoBodies : public ::testing::Test {
protected:
    SystemOfTwoBodies() {
        Af.orient_axis(N, Axis::z, qA);
        Bf.orient_axis(Af, Axis::z, qB);
        sys.point("A_o").set_pos(sys.origin(), Vector());
        sys.point("B_o").set_pos(sys.point("A_o"), L * Af.y());
        A.cm().set_pos(sys.point("A_o"), d * Af.y());
        B.cm().set_pos(sys.point("B_o"), Vector());
        P.set_pos(sys.point("A_o"), a * Af.x());
        Q.set_pos(sys.point("B_o"), b * Bf.x());
        A.set_mass(mA), B.set_mass(mB);
    }

    // positions from N_o written out in N
    Vector p_P() const { return a * cos(qA) * N.x() + a * sin(qA) * N.y(); }
    Vector p_Q() const {
        return (-L * sin(qA) + b * cos(qA + qB)) * N.x() + (L * cos(qA) + b * sin(qA + qB)) * N.y();
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable qA = s.add_variable("qA"), qB = s.add_variable("qB");
    ex L = s.add_constant("L"), d = s.add_constant("d"), a = s.add_constant("a"),
       b = s.add_constant("b"), mA = s.add_constant("mA"), mB = s.add_constant("mB");
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    Frame& Af = A.body_frame();
    Frame& Bf = B.body_frame();
    Point& P = sys.add_point("P", &A);
    Point& Q = sys.add_point("Q", &B);
    const Point& O = sys.origin();
};

TEST_F(SystemOfTwoBodies, TorquePairIsInternalToBothBodiesAndActsWithOppositeSignsOnEach) {
    ex T = s.add_unknown("T");
    sys.add_torque_pair(B, Af, T * Af.z(), "T");
    ASSERT_EQ(sys.loads().size(), 2u);
    EXPECT_EQ(sys.loads()[0].kind, LoadKind::torque);
    EXPECT_EQ(sys.loads()[0].on, &B);
    EXPECT_EQ(sys.loads()[0].from, &A);
    EXPECT_EQ(sys.loads()[1].on, &A);
    EXPECT_EQ(sys.loads()[1].from, &B);
    EXPECT_EQ(sys.loads()[1].label, "T");

    LoadResultant R_AB = sys.calc_resultant(sys.bodies({"A", "B"}), O);
    EXPECT_TRUE(same(R_AB.force, Vector(), N));
    EXPECT_TRUE(same(R_AB.moment, Vector(), N));
    LoadResultant R_B = sys.calc_resultant(sys.bodies({"B"}), O);
    EXPECT_TRUE(same(R_B.force, Vector(), N));
    EXPECT_TRUE(same(R_B.moment, T * N.z(), N));
    // a couple has the same moment about every point
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies({"B"}), Q).moment, T * N.z(), N));
    LoadResultant R_A = sys.calc_resultant(sys.bodies({"A"}), O);
    EXPECT_TRUE(same(R_A.moment, -T * N.z(), N));
}

TEST_F(SystemOfTwoBodies, TorqueFromTheNewtonianFrameHasNoReactionInTheModel) {
    ex T = s.add_unknown("T");
    sys.add_torque_pair(A, N, T * N.z(), "T_A");
    ASSERT_EQ(sys.loads().size(), 1u);
    EXPECT_EQ(sys.loads()[0].from, nullptr);
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies({"A", "B"}), O).moment, T * N.z(), N));
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies({"B"}), O).moment, Vector(), N));
}

TEST_F(SystemOfTwoBodies, TorqueOnABodyFromItsOwnFrameIsAnErrorNamingIt) {
    EXPECT_THROW_MSG(sys.add_torque_pair(A, Af, N.z(), "T_self"), ModelError,
                     "the torque 'T_self' acts on 'A' from its own frame");
    EXPECT_TRUE(sys.loads().empty());
}

TEST_F(SystemOfTwoBodies, ForcePairAlongTheLineIsInternalToBothBodies) {
    ex f = s.add_constant("f");
    // f r^{P/Q}, the force on P (at P, on A); -f r^{P/Q} on Q (on B)
    Vector F = f * (p_P() - p_Q());
    sys.add_force_pair(P, Q, f * P.pos_from(Q), "link");
    ASSERT_EQ(sys.loads().size(), 2u);
    EXPECT_EQ(sys.loads()[0].point, &P);
    EXPECT_EQ(sys.loads()[1].point, &Q);

    LoadResultant R_AB = sys.calc_resultant(sys.bodies({"A", "B"}), O);
    EXPECT_TRUE(same(R_AB.force, Vector(), N));
    EXPECT_TRUE(same(R_AB.moment, Vector(), N));
    LoadResultant R_A = sys.calc_resultant(sys.bodies({"A"}), O);
    EXPECT_TRUE(same(R_A.force, F, N));
    EXPECT_TRUE(same(R_A.moment, cross(p_P(), F), N));
    LoadResultant R_B = sys.calc_resultant(sys.bodies({"B"}), O);
    EXPECT_TRUE(same(R_B.force, -F, N));
    EXPECT_TRUE(same(R_B.moment, cross(p_Q(), -F), N));
    // along the line, the two moments cancel as well (the strong form of the third law)
    EXPECT_TRUE(same(R_A.moment + R_B.moment, Vector(), N));
}

TEST_F(SystemOfTwoBodies, ForcePairBetweenMembersIsLeftOutEvenWhenItIsNotAlongTheLine) {
    // a pair declared between A and B is internal to any system holding both (load.hpp), so
    // {A, B} sees neither force, although the two separate moments do not cancel here
    ex Fx = s.add_constant("Fx");
    Vector F = Fx * N.x();
    sys.add_force_pair(P, Q, F, "shear");
    LoadResultant R_AB = sys.calc_resultant(sys.bodies({"A", "B"}), O);
    EXPECT_TRUE(same(R_AB.force, Vector(), N));
    EXPECT_TRUE(same(R_AB.moment, Vector(), N));
    LoadResultant R_A = sys.calc_resultant(sys.bodies({"A"}), O);
    LoadResultant R_B = sys.calc_resultant(sys.bodies({"B"}), O);
    EXPECT_TRUE(same(R_A.moment, cross(p_P(), F), N));
    EXPECT_TRUE(same(R_B.moment, cross(p_Q(), -F), N));
    EXPECT_TRUE(same(R_A.moment + R_B.moment, cross(p_P() - p_Q(), F), N));
}

TEST_F(SystemOfTwoBodies, ForceFromTheSurroundingsActsOnTheOwnerOfItsPoint) {
    ex Fx = s.add_constant("Fx"), Fy = s.add_constant("Fy");
    Load l = sys.add_force(Q, Fx * N.x() + Fy * N.y(), "push");
    EXPECT_EQ(l.on, &B);
    EXPECT_EQ(l.from, nullptr);
    EXPECT_EQ(l.label, "push");
    // moment about N_o: (x Fy - y Fx) Nz with Q at (x, y)
    Col3 q = p_Q().components_in(N);
    LoadResultant R = sys.calc_resultant(sys.bodies({"A", "B"}), O);
    EXPECT_TRUE(same(R.force, Fx * N.x() + Fy * N.y(), N));
    EXPECT_TRUE(same(R.moment, (q[0] * Fy - q[1] * Fx) * N.z(), N));
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies({"A"}), O).force, Vector(), N));
}

TEST_F(SystemOfTwoBodies, GravityActsAtEachMassCentreNowAndOnBodiesAddedLater) {
    ex g = s.add_constant("g"), mC = s.add_constant("mC");
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y");
    sys.set_gravity(-g * N.y());
    Particle& C = sys.add_particle("C");
    C.set_mass(mC);
    C.cm().set_pos(O, x * N.x() + y * N.y());

    // Acm = d (-sin qA, cos qA), Bcm = L (-sin qA, cos qA), C = (x, y); the moment about N_o
    // of -m g Ny applied at (px, py) is -m g px Nz
    LoadResultant R = sys.calc_resultant(sys.bodies(), O);
    EXPECT_TRUE(same(R.force, -(mA + mB + mC) * g * N.y(), N));
    EXPECT_TRUE(
        same(R.moment, (mA * g * d * sin(qA) + mB * g * L * sin(qA) - mC * g * x) * N.z(), N));
    LoadResultant R_C = sys.calc_resultant(sys.bodies({"C"}), C.point());
    EXPECT_TRUE(same(R_C.force, -mC * g * N.y(), N));
    EXPECT_TRUE(same(R_C.moment, Vector(), N));
    // potential energy m g h, zero at N_o
    EXPECT_TRUE(same(sys.calc_potential_energy(),
                     mA * g * d * cos(qA) + mB * g * L * cos(qA) + mC * g * y));
}

TEST_F(SystemOfTwoBodies, ForceAtAPointOfNoBodyIsAnErrorNamingThePoint) {
    Point& X = sys.add_point("X");
    X.set_pos(O, N.x());
    EXPECT_THROW_MSG(sys.add_force(X, N.y(), "F"), ModelError,
                     "point 'X' is not fixed on a body or particle");
    EXPECT_THROW_MSG(sys.add_force(sys.origin(), N.y()), ModelError,
                     "point 'N_o' is not fixed on a body or particle");
    EXPECT_THROW_MSG(sys.add_drag(X, 1, DragLaw::linear), ModelError,
                     "System::add_drag(): point 'X' is not fixed");
    EXPECT_THROW_MSG(sys.add_force_pair(X, sys.origin(), N.y(), "tie"), ModelError,
                     "neither 'X' nor 'N_o' is fixed on a body or particle, so the load 'tie'");
    EXPECT_THROW_MSG(sys.add_inverse_square_gravity(P, X, 1, "G"), ModelError,
                     "point 'X' is not fixed on a body or particle");
    EXPECT_TRUE(sys.loads().empty());
}

TEST_F(SystemOfTwoBodies, ForceModelBetweenCoincidentPointsIsAnErrorNamingThem) {
    Point& Pc = sys.add_point("Pc", &B);
    Pc.set_pos(sys.point("B_o"), Vector());
    EXPECT_THROW_MSG(sys.add_spring(Pc, sys.point("B_o"), 1, 0, "k"), ModelError,
                     "points 'Pc' and 'B_o' coincide");
    EXPECT_THROW_MSG(sys.add_damper(Pc, sys.point("B_o"), 1, "c"), ModelError,
                     "points 'Pc' and 'B_o' coincide");
}

// ---- force models between two particles ----------------------------------------------------

// Particles P1 at (x1, y1) and P2 at (x2, 0) in the Nx-Ny plane.
class SystemOfTwoParticles : public ::testing::Test {
protected:
    SystemOfTwoParticles() {
        P1.set_mass(m1), P2.set_mass(m2);
        P1.cm().set_pos(sys.origin(), x1 * N.x() + y1 * N.y());
        P2.cm().set_pos(sys.origin(), x2 * N.x());
    }

    ex dx() const { return x1 - x2; }
    ex dy() const { return y1; }
    ex length() const { return sqrt(pow(dx(), 2) + pow(dy(), 2)); }
    Vector force_on(const char* name) {
        return sys.calc_resultant(sys.bodies({name}), sys.origin()).force;
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable x1 = s.add_variable("x1"), y1 = s.add_variable("y1"), x2 = s.add_variable("x2");
    ex m1 = s.add_constant("m1"), m2 = s.add_constant("m2");
    Particle& P1 = sys.add_particle("P1");
    Particle& P2 = sys.add_particle("P2");
};

TEST_F(SystemOfTwoParticles, SpringPullsAlongTheLineWithHookesLawAndStoresHalfKStretchSquared) {
    ex k = s.add_constant("k"), L0 = s.add_constant("L0");
    sys.add_spring(P1.point(), P2.point(), k, L0, "spring");
    // its force derives from the potential below
    ASSERT_EQ(sys.loads().size(), 2u);
    EXPECT_TRUE(sys.loads()[0].conservative && sys.loads()[1].conservative);

    // on P1: -k (L - L0) (dx, dy) / L; on P2 the opposite; none on the pair
    Vector F1 = -k * (length() - L0) / length() * (dx() * N.x() + dy() * N.y());
    EXPECT_TRUE(same(force_on("P1"), F1, N));
    EXPECT_TRUE(same(force_on("P2"), -F1, N));
    LoadResultant R = sys.calc_resultant(sys.bodies(), sys.origin());
    EXPECT_TRUE(same(R.force, Vector(), N));
    EXPECT_TRUE(same(R.moment, Vector(), N));
    // magnitude k |L - L0|, along the line P2 -> P1
    EXPECT_TRUE(same(dot(force_on("P1"), force_on("P1")), pow(k * (length() - L0), 2)));
    EXPECT_TRUE(same(cross(force_on("P1"), P1.point().pos_from(P2.point())), Vector(), N));

    // V = 1/2 k (L - L0)^2, and the force on each particle is minus its gradient
    ex V = sys.calc_potential_energy();
    EXPECT_TRUE(same(V, k * pow(length() - L0, 2) / 2));
    EXPECT_TRUE(same(-partial(V, x1), F1.components_in(N)[0]));
    EXPECT_TRUE(same(-partial(V, y1), F1.components_in(N)[1]));
    EXPECT_TRUE(same(-partial(V, x2), -F1.components_in(N)[0]));
}

TEST_F(SystemOfTwoParticles, DamperOpposesTheRateOfExtensionAndDissipates) {
    ex c = s.add_constant("c");
    sys.add_damper(P1.point(), P2.point(), c, "damper");
    ASSERT_EQ(sys.loads().size(), 2u);
    EXPECT_FALSE(sys.loads()[0].conservative || sys.loads()[1].conservative);

    // v_rel = (x1' - x2', y1'), u = (dx, dy)/L: on P1 -c (v_rel.u) u
    ex vr_dot_u = ((x1.d(1) - x2.d(1)) * dx() + y1.d(1) * dy()) / length();
    Vector u = (dx() * N.x() + dy() * N.y()) / length();
    Vector F1 = -c * vr_dot_u * u;
    EXPECT_TRUE(same(force_on("P1"), F1, N));
    EXPECT_TRUE(same(force_on("P2"), -F1, N));
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies(), sys.origin()).force, Vector(), N));
    // power on both: -c (v_rel.u)^2 <= 0; no potential energy
    ex power =
        dot(force_on("P1"), P1.point().vel_in(N)) + dot(force_on("P2"), P2.point().vel_in(N));
    EXPECT_TRUE(same(power, -c * pow(vr_dot_u, 2)));
    EXPECT_TRUE(same(sys.calc_potential_energy(), 0));
}

TEST_F(SystemOfTwoParticles, LinearDragIsProportionalToVelocity) {
    ex c = s.add_constant("c");
    sys.add_drag(P1.point(), c, DragLaw::linear, "air");
    ASSERT_EQ(sys.loads().size(), 1u);
    EXPECT_EQ(sys.loads()[0].from, nullptr);
    EXPECT_TRUE(same(force_on("P1"), -c * (x1.d(1) * N.x() + y1.d(1) * N.y()), N));
    EXPECT_TRUE(same(force_on("P2"), Vector(), N));
}

TEST_F(SystemOfTwoParticles, QuadraticDragIsProportionalToSpeedTimesVelocity) {
    ex c = s.add_constant("c");
    sys.add_drag(P1.point(), c, DragLaw::quadratic, "air");
    ex speed = sqrt(pow(x1.d(1), 2) + pow(y1.d(1), 2));
    EXPECT_TRUE(same(force_on("P1"), -c * speed * (x1.d(1) * N.x() + y1.d(1) * N.y()), N));
    // its power is -c |v|^3
    EXPECT_TRUE(same(dot(force_on("P1"), P1.point().vel_in(N)), -c * pow(speed, 3)));
}

TEST_F(SystemOfTwoParticles, CoulombFrictionOpposesTheSlidingVelocity) {
    ex mu = s.add_constant("mu", 0.3), Fn = s.add_constant("Fn", -20.0);
    // P1 slides on the ground (N_o, the surroundings) along Nx
    sys.add_coulomb_friction(P1.point(), sys.origin(), mu, Fn, N.x(), "ground");
    ASSERT_EQ(sys.loads().size(), 1u);
    ex Fx = force_on("P1").components_in(N)[0];
    // mu |Fn| = 6, against the sliding direction
    EXPECT_TRUE(near(s.evaluate(Fx, {{x1.d(1), 0.5}, {y1.d(1), 0.2}}), -6.0));
    EXPECT_TRUE(near(s.evaluate(Fx, {{x1.d(1), -0.5}, {y1.d(1), 0.2}}), 6.0));
    EXPECT_TRUE(same(force_on("P1").components_in(N)[1], 0));
}

TEST_F(SystemOfTwoParticles, CoulombFrictionBetweenParticlesFollowsTheRelativeSlidingVelocity) {
    ex mu = s.add_constant("mu", 0.3), Fn = s.add_constant("Fn", 20.0);
    sys.add_coulomb_friction(P1.point(), P2.point(), mu, Fn, N.x(), "contact");
    ex F1 = force_on("P1").components_in(N)[0], F2 = force_on("P2").components_in(N)[0];
    // P1 slower than P2 (slides backwards on it): pushed forwards, P2 backwards
    EXPECT_TRUE(near(s.evaluate(F1, {{x1.d(1), 1.0}, {x2.d(1), 2.0}}), 6.0));
    EXPECT_TRUE(near(s.evaluate(F2, {{x1.d(1), 1.0}, {x2.d(1), 2.0}}), -6.0));
    // P1 faster: held back
    EXPECT_TRUE(near(s.evaluate(F1, {{x1.d(1), 3.0}, {x2.d(1), 2.0}}), -6.0));
    EXPECT_TRUE(near(s.evaluate(F2, {{x1.d(1), 3.0}, {x2.d(1), 2.0}}), 6.0));
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies(), sys.origin()).force, Vector(), N));
}

TEST(System, InverseSquareGravityBeforeTheMassesIsAnErrorNamingTheBody) {
    System sys;
    Particle& E = sys.add_particle("E");
    Particle& S = sys.add_particle("S");
    S.set_mass(1);
    S.cm().set_pos(sys.origin(), sys.newtonian().x());
    E.cm().set_pos(sys.origin(), Vector());
    EXPECT_THROW_MSG(sys.add_inverse_square_gravity(S.point(), E.point(), 1, "G"), ModelError,
                     "mass of 'E' is not set");
    EXPECT_TRUE(sys.loads().empty());
}

TEST(System, InverseSquareGravityIsMinusTheGradientOfItsPotential) {
    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable x = s.add_variable("x"), y = s.add_variable("y"), z = s.add_variable("z");
    ex G = s.add_constant("G", 1.0), mE = s.add_constant("mE", 2.0), mS = s.add_constant("mS", 3.0);
    Particle& E = sys.add_particle("E");
    Particle& S = sys.add_particle("S");
    E.set_mass(mE), S.set_mass(mS);
    E.cm().set_pos(sys.origin(), Vector());
    S.cm().set_pos(sys.origin(), x * N.x() + y * N.y() + z * N.z());
    sys.add_inverse_square_gravity(S.point(), E.point(), G, "gravity");
    ASSERT_EQ(sys.loads().size(), 2u);
    EXPECT_TRUE(sys.loads()[0].conservative && sys.loads()[1].conservative);

    // F on S = -G mE mS r / |r|^3, V = -G mE mS / |r|
    ex r = sqrt(x * x + y * y + z * z);
    Vector F_S = -G * mE * mS / pow(r, 3) * (x * N.x() + y * N.y() + z * N.z());
    Vector F_S_model = sys.calc_resultant(sys.bodies({"S"}), sys.origin()).force;
    EXPECT_TRUE(same(F_S_model, F_S, N));
    EXPECT_TRUE(same(sys.calc_resultant(sys.bodies({"E"}), sys.origin()).force, -F_S, N));
    ex V = sys.calc_potential_energy();
    EXPECT_TRUE(same(V, -G * mE * mS / r));
    Col3 F = F_S_model.components_in(N);
    EXPECT_TRUE(same(-partial(V, x), F[0]));
    EXPECT_TRUE(same(-partial(V, y), F[1]));
    EXPECT_TRUE(same(-partial(V, z), F[2]));

    // at (3, 4, 12), |r| = 13: |F| = G mE mS / 169 = 6/169, pointing back to E
    GiNaC::exmap at{{x, 3.0}, {y, 4.0}, {z, 12.0}};
    EXPECT_TRUE(near(s.evaluate(F[0], at), -6.0 * 3 / 2197));
    EXPECT_TRUE(near(s.evaluate(F[2], at), -6.0 * 12 / 2197));
    EXPECT_TRUE(near(s.evaluate(V, at), -6.0 / 13));
}

// ---- energy of a double pendulum of two particles ------------------------------------------

// Particles P1 (m1) and P2 (m2) on massless rods l1 from N_o and l2 from P1, at absolute angles
// th1, th2 from the downward vertical (frames A, B turn about Nz by th1, th2; the rods lie
// along -Ay and -By); gravity -g Ny.
class SystemDoublePendulum : public ::testing::Test {
protected:
    SystemDoublePendulum() {
        A.orient_axis(N, Axis::z, th1);
        B.orient_axis(N, Axis::z, th2);
        P1.set_mass(m1), P2.set_mass(m2);
        P1.cm().set_pos(sys.origin(), -l1 * A.y());
        P2.cm().set_pos(P1.point(), -l2 * B.y());
        sys.set_gravity(-g * N.y());
    }

    struct State {
        double th1, th2, w1, w2;
    };
    // the constants' values, for numbers
    static constexpr double kM1 = 1.3, kM2 = 0.7, kL1 = 0.9, kL2 = 1.1, kG = 9.81, kC = 0.25,
                            kF0 = 2.0;

    // th1'', th2'' from Lagrange's equations with generalized forces Q1, Q2:
    //   (m1+m2) l1^2 th1'' + m2 l1 l2 cos(D) th2'' = Q1 - m2 l1 l2 sin(D) th2'^2
    //                                                - (m1+m2) g l1 sin th1
    //   m2 l1 l2 cos(D) th1'' + m2 l2^2 th2''      = Q2 + m2 l1 l2 sin(D) th1'^2
    //                                                - m2 g l2 sin th2,      D = th1 - th2
    static std::pair<double, double> accelerations(const State& x, double Q1, double Q2) {
        double D = x.th1 - x.th2;
        double M11 = (kM1 + kM2) * kL1 * kL1, M12 = kM2 * kL1 * kL2 * std::cos(D),
               M22 = kM2 * kL2 * kL2;
        double f1 = Q1 - kM2 * kL1 * kL2 * std::sin(D) * x.w2 * x.w2 -
                    (kM1 + kM2) * kG * kL1 * std::sin(x.th1);
        double f2 =
            Q2 + kM2 * kL1 * kL2 * std::sin(D) * x.w1 * x.w1 - kM2 * kG * kL2 * std::sin(x.th2);
        double det = M11 * M22 - M12 * M12;
        return {(f1 * M22 - M12 * f2) / det, (M11 * f2 - M12 * f1) / det};
    }
    static std::vector<State> random_states() {
        std::mt19937 rng(20261121);
        std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-2.0, 2.0);
        std::vector<State> states;
        for (int i = 0; i < 6; ++i)
            states.push_back({angle(rng), angle(rng), rate(rng), rate(rng)});
        return states;
    }
    GiNaC::exmap values(const State& x, double a1, double a2) const {
        return {{th1, x.th1},     {th2, x.th2},   {th1.d(1), x.w1},
                {th2.d(1), x.w2}, {th1.d(2), a1}, {th2.d(2), a2}};
    }

    System sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    TimeVariable th1 = s.add_variable("th1"), th2 = s.add_variable("th2");
    ex m1 = s.add_constant("m1", kM1), m2 = s.add_constant("m2", kM2),
       l1 = s.add_constant("l1", kL1), l2 = s.add_constant("l2", kL2), g = s.add_constant("g", kG);
    Frame& A = sys.add_frame("A");
    Frame& B = sys.add_frame("B");
    Particle& P1 = sys.add_particle("P1");
    Particle& P2 = sys.add_particle("P2");
};

TEST_F(SystemDoublePendulum, KineticAndPotentialEnergyMatchTheTextbook) {
    // K = 1/2 (m1+m2) l1^2 th1'^2 + 1/2 m2 l2^2 th2'^2 + m2 l1 l2 th1' th2' cos(th1 - th2)
    ex K = (m1 + m2) * l1 * l1 * pow(th1.d(1), 2) / 2 + m2 * l2 * l2 * pow(th2.d(1), 2) / 2 +
           m2 * l1 * l2 * th1.d(1) * th2.d(1) * cos(th1 - th2);
    // V = -(m1+m2) g l1 cos th1 - m2 g l2 cos th2
    ex V = -(m1 + m2) * g * l1 * cos(th1) - m2 * g * l2 * cos(th2);
    EXPECT_TRUE(same(sys.calc_kinetic_energy(sys.bodies()), K));
    EXPECT_TRUE(same(sys.calc_potential_energy(), V));
}

TEST_F(SystemDoublePendulum, EnergyIsConservedWithoutNonConservativeLoads) {
    ex E = sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy();
    ex dE = s.dt(E);
    for (const State& x : random_states()) {
        auto [a1, a2] = accelerations(x, 0, 0);
        EXPECT_TRUE(near(s.evaluate(dE, values(x, a1, a2)), 0.0))
            << "at th1 = " << x.th1 << ", th2 = " << x.th2;
    }
}

TEST_F(SystemDoublePendulum, EnergyRateEqualsThePowerOfNonConservativeLoads) {
    ex c = s.add_constant("c", kC), F0 = s.add_constant("F0", kF0);
    sys.add_force(P1.point(), F0 * N.x(), "push");
    sys.add_drag(P2.point(), c, DragLaw::linear, "air");
    ex E = sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy();
    ex dE = s.dt(E);
    ex load_power = 0;
    for (const Load& l : sys.loads()) load_power += dot(l.vector, l.point->vel_in(N));

    for (const State& x : random_states()) {
        // v1 = l1 th1' (cos th1, sin th1), v2 = v1 + l2 th2' (cos th2, sin th2):
        // power = F0 v1x - c |v2|^2;
        // Q1 = F0 l1 cos th1 - c l1 (l1 th1' + l2 th2' cos D), Q2 = -c l2 (l2 th2' + l1 th1' cos D)
        double D = x.th1 - x.th2;
        double power = kF0 * kL1 * x.w1 * std::cos(x.th1) -
                       kC * (kL1 * kL1 * x.w1 * x.w1 + kL2 * kL2 * x.w2 * x.w2 +
                             2 * kL1 * kL2 * x.w1 * x.w2 * std::cos(D));
        double Q1 =
            kF0 * kL1 * std::cos(x.th1) - kC * kL1 * (kL1 * x.w1 + kL2 * x.w2 * std::cos(D));
        double Q2 = -kC * kL2 * (kL2 * x.w2 + kL1 * x.w1 * std::cos(D));
        auto [a1, a2] = accelerations(x, Q1, Q2);
        EXPECT_TRUE(near(s.evaluate(load_power, values(x, a1, a2)), power));
        EXPECT_TRUE(near(s.evaluate(dE, values(x, a1, a2)), power))
            << "at th1 = " << x.th1 << ", th2 = " << x.th2;
    }
}

}  // namespace
}  // namespace alembert

TEST(System, ATorqueOnAParticleIsAnErrorNamingIt) {
    using namespace alembert;
    System sys("N");
    Particle& P = sys.add_particle("P");
    const Frame& N = sys.newtonian();
    EXPECT_THROW_MSG(sys.add_torque(P, N.z(), "T"), ModelError,
                     "the torque 'T' acts on 'P', a particle: a particle does not turn");
    EXPECT_THROW_MSG(sys.add_torque_pair(P, N, N.z(), "T2"), ModelError,
                     "the torque 'T2' acts on 'P', a particle");
    EXPECT_TRUE(sys.loads().empty());
}
