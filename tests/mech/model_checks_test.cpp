// SPDX-License-Identifier: MIT
// Tests of the physical checks of stated rotations, masses and inertias: rotations of every
// angle pass, reflections and skewed matrices fail, and inertias that no mass distribution
// has (a negative moment, a broken triangle inequality) fail with the body's name.
#include "alembert/mech/model_checks.hpp"

#include <gtest/gtest.h>

#include "alembert/error.hpp"
#include "alembert/vec/rotation.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

// [[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]]
Mat3 inertia_matrix(double xx, double yy, double zz, double xy = 0, double yz = 0, double zx = 0) {
    Mat3 m;
    m(0, 0) = xx, m(1, 1) = yy, m(2, 2) = zz;
    m(0, 1) = m(1, 0) = xy;
    m(1, 2) = m(2, 1) = yz;
    m(2, 0) = m(0, 2) = zx;
    return m;
}

TEST(ModelChecks, RotationsOfAnyAnglePassAndReflectionsOrSkewsFail) {
    SymbolTable st;
    TimeVariable q = st.add_variable("q"), p = st.add_variable("p");
    ex a = st.add_constant("a", 0.3);
    // products of simple rotations are rotations for every q and p
    Mat3 R = simple_rotation(Axis::z, q.symbol()) * simple_rotation(Axis::x, p.symbol() + a);
    EXPECT_NO_THROW(check_direction_cosines(st, R, "B", "A"));
    // a reflection: one column's sign flipped
    Mat3 F = R;
    for (int i = 0; i < 3; ++i) F(i, 2) = -R(i, 2);
    EXPECT_THROW_MSG(check_direction_cosines(st, F, "B", "A"), ModelError,
                     "the direction-cosine matrix of 'B' in 'A' has determinant -1");
    // a matrix whose columns are unit vectors only at q = 0: not orthonormal
    Mat3 S = Mat3::identity();
    S(0, 1) = GiNaC::sin(q.symbol());
    EXPECT_THROW_MSG(check_direction_cosines(st, S, "B", "A"), ModelError,
                     "the direction-cosine matrix of 'B' in 'A' is not orthonormal");
    // constant entries that are 1e-3 off
    Mat3 C = Mat3::identity();
    C(0, 0) = ex(1.001);
    EXPECT_THROW_MSG(check_direction_cosines(st, C, "B", "A"), ModelError, "differs from the unit matrix by 0.002");
}

TEST(ModelChecks, NegativeMassesFailAndSymbolicOnesAreLeftAlone) {
    SymbolTable st;
    ex m = st.add_constant("m", -6.5), M = st.add_constant("M");
    EXPECT_THROW_MSG(check_mass(st, m, "A"), ModelError, "the mass of 'A' is -6.5 kg; a mass cannot be negative");
    EXPECT_NO_THROW(check_mass(st, 2 * M, "A"));  // no value: nothing to check
    EXPECT_NO_THROW(check_mass(st, -m, "A"));
    EXPECT_NO_THROW(check_mass(st, 0, "A"));      // a massless body is allowed
}

TEST(ModelChecks, InertiasMustBeThoseOfSomeMassDistribution) {
    SymbolTable st;
    // a thin rod (0, I, I), a disk (I, I, 2I), a box: physical
    EXPECT_NO_THROW(check_inertia_matrix(st, inertia_matrix(0, 1, 1), "rod"));
    EXPECT_NO_THROW(check_inertia_matrix(st, inertia_matrix(1, 1, 2), "disk"));
    EXPECT_NO_THROW(check_inertia_matrix(st, inertia_matrix(2, 3, 4, 0.5, -0.2, 0.1), "box"));
    // the planar convention: only the moment about the plane's normal is given
    EXPECT_NO_THROW(check_inertia_matrix(st, inertia_matrix(0, 0, 1), "planar"));
    EXPECT_THROW_MSG(check_inertia_matrix(st, inertia_matrix(0, 0, -1), "planar"), ModelError,
                     "negative principal moment");
    EXPECT_THROW_MSG(check_inertia_matrix(st, inertia_matrix(1, -2, 1), "A"), ModelError,
                     "the inertia of 'A' has a negative principal moment");
    EXPECT_THROW_MSG(check_inertia_matrix(st, inertia_matrix(1, 1, 3), "A"), ModelError,
                     "principal moments 1, 1, 3 kg*m^2 break the triangle inequality");
    // moments that look fine but a product of inertia too large for them
    EXPECT_THROW_MSG(check_inertia_matrix(st, inertia_matrix(1, 1, 1.5, 1.2), "A"), ModelError,
                     "the inertia of 'A' has a negative principal moment");
    // constants with values are checked, without values skipped
    ex I = st.add_constant("I", 0.25), J = st.add_constant("J");
    Mat3 K;
    K(0, 0) = I, K(1, 1) = I, K(2, 2) = 3 * I;
    EXPECT_THROW_MSG(check_inertia_matrix(st, K, "B"), ModelError, "the inertia of 'B' is not physical");
    K(2, 2) = 3 * J;
    EXPECT_NO_THROW(check_inertia_matrix(st, K, "B"));
}

}  // namespace
}  // namespace alembert
