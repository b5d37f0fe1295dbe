// SPDX-License-Identifier: MIT
// Small symbolic matrices: products, transposes, cross products.
#include "alembert/sym/matrix.hpp"

#include "alembert/sym/symbol_table.hpp"
#include "support/expect.hpp"

using namespace alembert;

TEST(Mat3, ProductAndTransposeFollowTheDefinitions) {
    SymbolTable s;
    Mat3 A, B;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            A(i, j) = s.add_constant("a" + std::to_string(i) + std::to_string(j));
            B(i, j) = s.add_constant("b" + std::to_string(i) + std::to_string(j));
        }
    Mat3 C = A * B;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_TRUE(alembert::equal(
                C(i, j), A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j)));
    // (A B)^T = B^T A^T
    Mat3 D = B.transpose() * A.transpose(), Ct = C.transpose();
    for (std::size_t k = 0; k < 9; ++k) EXPECT_TRUE(alembert::equal(D.m[k], Ct.m[k]));
    EXPECT_TRUE((Mat3::identity() * A).m == A.m);
}

TEST(Col3, CrossProductIsRightHanded) {
    Col3 x{{1, 0, 0}}, y{{0, 1, 0}}, z{{0, 0, 1}};
    Col3 c = cross(x, y);
    for (int i = 0; i < 3; ++i) EXPECT_TRUE((c[i] - z[i]).is_zero());
    EXPECT_TRUE(dot(cross(y, z), x).is_equal(1));
    EXPECT_TRUE(cross(x, x).is_zero());
}
