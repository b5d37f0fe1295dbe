// SPDX-License-Identifier: MIT
// Declared constraints: what each kind accepts, vector constraints, and the errors.
#include <gtest/gtest.h>

#include "alembert/error.hpp"
#include "alembert/mech/system.hpp"
#include "support/expect.hpp"

using namespace alembert;
using alembert::test::same;

namespace {
struct Disk {
    System sys{"N"};
    TimeVariable q = sys.symbols().add_variable("q", 2), x = sys.symbols().add_variable("x", 2);
    ex r = sys.symbols().add_constant("r", 0.3);
};
}  // namespace

TEST(Constraint, ConfigurationAndMotionConstraintsAreKeptInOrder) {
    Disk d;
    ex L = d.sys.symbols().add_constant("L", 1.0);
    d.sys.add_configuration_constraint("rod", d.x - L * GiNaC::cos(d.q));
    d.sys.add_motion_constraint("roll", d.x.d(1) - d.r * d.q.d(1));
    ASSERT_EQ(d.sys.constraints().size(), 2u);
    EXPECT_EQ(d.sys.constraints()[0].name, "rod");
    EXPECT_EQ(d.sys.constraints()[0].kind, ConstraintKind::configuration);
    EXPECT_EQ(d.sys.constraints()[1].kind, ConstraintKind::motion);
    EXPECT_TRUE(same(d.sys.constraints()[1].residual, d.x.d(1) - d.r * d.q.d(1)));
    EXPECT_STREQ(to_string(ConstraintKind::motion), "motion");
}

TEST(Constraint, VectorConstraintGivesOneScalarPerNonZeroMeasure) {
    // a point P on a rod of length L turning by q must meet a slider at x Nx: r^{P/Q} = 0
    System sys("N");
    SymbolTable& s = sys.symbols();
    TimeVariable q = s.add_variable("q", 2), x = s.add_variable("x", 2);
    ex L = s.add_constant("L", 1.0);
    Frame& N = sys.newtonian();
    Frame& A = sys.add_frame("A");
    A.orient_axis(N, Axis::z, q);
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), L * A.x());
    Point& Q = sys.add_point("Q");
    Q.set_pos(sys.origin(), x * N.x());
    std::vector<Constraint> c = sys.add_configuration_constraint("loop", P.pos_from(Q), N);
    ASSERT_EQ(c.size(), 2u);  // no z measure
    EXPECT_EQ(c[0].name, "loop_x");
    EXPECT_EQ(c[1].name, "loop_y");
    EXPECT_TRUE(same(c[0].residual, L * GiNaC::cos(q) - x));
    EXPECT_TRUE(same(c[1].residual, L * GiNaC::sin(q)));
    // rolling of the slider-driven point: its velocity along Ny is zero
    std::vector<Constraint> m = sys.add_motion_constraint("slip", dot(P.vel_in(N), N.y()) * N.y(), N);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].name, "slip_y");
    EXPECT_TRUE(same(m[0].residual, L * GiNaC::cos(q) * q.d(1)));
}

TEST(Constraint, ErrorsNameTheConstraintAndSayWhatToDo) {
    Disk d;
    System& sys = d.sys;
    EXPECT_THROW_MSG(sys.add_configuration_constraint("c", d.x.d(1)), ArgumentError,
                     "is a motion constraint (add_motion_constraint)");
    EXPECT_THROW_MSG(sys.add_motion_constraint("m", d.x), ArgumentError,
                     "holds no speed");
    EXPECT_THROW_MSG(sys.add_motion_constraint("m", d.x.d(1) * d.q.d(1)), ArgumentError,
                     "not linear in the speeds");
    EXPECT_THROW_MSG(sys.add_configuration_constraint("c", d.x.d(2)), ArgumentError,
                     "Alembert takes their time derivatives");
    EXPECT_THROW_MSG(sys.add_configuration_constraint("c", ex(0)), ArgumentError,
                     "identically zero");
    EXPECT_THROW_MSG(sys.add_configuration_constraint("", d.x), ArgumentError, "non-empty name");
    sys.add_configuration_constraint("c", d.x - 1);
    EXPECT_THROW_MSG(sys.add_configuration_constraint("c", d.q), ArgumentError,
                     "'c' is declared already");
    // a vector constraint whose second measure fails leaves nothing behind
    Frame& N = sys.newtonian();
    EXPECT_THROW_MSG(sys.add_configuration_constraint("v", d.x * N.x() + d.q.d(1) * N.y(), N),
                     ArgumentError, "'v_y'");
    EXPECT_EQ(sys.constraints().size(), 1u);
    EXPECT_THROW_MSG(sys.add_motion_constraint("z", Vector(), N), ArgumentError, "zero vector");
}
