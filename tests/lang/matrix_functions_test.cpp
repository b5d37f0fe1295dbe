// SPDX-License-Identifier: MIT
// Matrices, polynomials and mass functions of the language against hand results: transpose,
// inv, det, diagmat, element, rows, cols, eig, eigvec and matrix arithmetic; polynomial and roots;
// mass(A, B) and cm(O, ...), each evaluated at random points beside the hand formula; their
// errors at the argument, with file:line:col and caret.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/lang/interpreter.hpp"
#include "support/script_dir.hpp"

namespace matrix_functions_test {

using namespace alembert::lang;

using MatrixRun = alembert::test::ScriptSession;
using alembert::test::digits17;
using alembert::test::has;

void expect_close(double got, double want, const std::string& what) {
    EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(want))) << what;
}

using Mat = std::array<std::array<double, 3>, 3>;

// the inverse by cofactors: inv[i][j] = C[j][i]/det
Mat hand_inverse(const Mat& m, double& det) {
    auto c = [&](int i, int j) {
        const int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
        return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    };
    det = m[0][0] * c(0, 0) + m[0][1] * c(0, 1) + m[0][2] * c(0, 2);
    Mat inv{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inv[i][j] = c(j, i) / det;
    return inv;
}

const char* kMatrixHead =
    "newtonian N\n"
    "constant a, b, c, d, f, g, h, k, L\n"
    "digits 17\n"
    "M = [a, b, c; d, f, g; h, k, L]\n"
    "N2 = [a, b; c, d; f, g]\n"
    "Mt = transpose(M)\n"
    "Mi = inv(M)\n"
    "D = det(M)\n"
    "P = M*N2\n"
    "S = 2*M - Mt/L + diagmat(3, g)\n"
    "I3 = simplify(Mi*M)\n"
    "R2 = rows(M, 3, 1)\n"
    "C2 = cols(M, 2)\n";

TEST(MatrixFunctions, TransposeInverseDeterminantAndArithmeticAgreeWithTheHandResults) {
    MatrixRun r;
    r.ok(kMatrixHead);
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        Mat m{};
        for (auto& row : m)
            for (double& x : row) x = u(rng);
        const char* names[9] = {"a", "b", "c", "d", "f", "g", "h", "k", "L"};
        std::string at;
        for (int i = 0; i < 9; ++i) at += (i ? ", " : "") + std::string(names[i]) + " = " + digits17(m[i / 3][i % 3]);
        double det = 0;
        const Mat inv = hand_inverse(m, det);
        expect_close(r.at("D", at), det, "det " + at);
        expect_close(r.at("det(N2*transpose(N2))", at), 0, "a rank-2 3 by 3 product");
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const std::string ij = "[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]";
                expect_close(r.at("Mi" + ij, at), inv[i][j], "inv " + ij + " " + at);
                expect_close(r.at("Mt" + ij, at), m[j][i], "transpose " + ij);
                expect_close(r.at("I3" + ij, at), i == j ? 1 : 0, "inv(M)*M " + ij);
                expect_close(r.at("S" + ij, at), 2 * m[i][j] - m[j][i] / m[2][2] + (i == j ? m[1][2] : 0), "S " + ij);
                expect_close(r.at("element(M, " + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")", at),
                             m[i][j], "element " + ij);
            }
        // N2 = [a, b; c, d; f, g]: P = M N2, 3 by 2
        const double n2[3][2] = {{m[0][0], m[0][1]}, {m[0][2], m[1][0]}, {m[1][1], m[1][2]}};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 2; ++j) {
                double want = 0;
                for (int s = 0; s < 3; ++s) want += m[i][s] * n2[s][j];
                expect_close(r.at("P[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", at), want, "M*N2");
            }
        for (int j = 0; j < 3; ++j) {
            expect_close(r.at("R2[1, " + std::to_string(j + 1) + "]", at), m[2][j], "rows(M, 3, 1) row 1");
            expect_close(r.at("R2[2, " + std::to_string(j + 1) + "]", at), m[0][j], "rows(M, 3, 1) row 2");
            expect_close(r.at("C2[" + std::to_string(j + 1) + ", 1]", at), m[j][1], "cols(M, 2)");
        }
    }
    EXPECT_EQ(r.ok("rows(N2)\ncols(N2)\n"), "= 3\n= 2\n");
    EXPECT_EQ(r.ok("diagmat(2, 3, L)\ndiagmat([a, b])\n"), "= [L, 0, 0; 0, L, 0]\n= [a, 0; 0, b]\n");
}

// M^k of a square matrix: products by hand at random points for k = 2, 3 and 5, the identity for
// 0, the inverse's powers for -1 and -2 (inv(M)^2 by hand cofactors, times M^2 the identity); a
// rotation about z cubed is the rotation by three times the angle; the errors at their column.
TEST(MatrixFunctions, PowersOfASquareMatrixAreItsProductsAndItsInversesProducts) {
    MatrixRun r;
    r.ok("newtonian N\nconstant a, b, c, d, f, g, h, k, L, th\ndigits 17\nM = [a, b, c; d, f, g; h, k, L]\n"
         "M2 = M^2\nM3 = M^3\nM5 = M^5\nM0 = M^0\nMm1 = M^-1\nMm2 = M^(-2)\n"
         "Rz = [cos(th), -sin(th), 0; sin(th), cos(th), 0; 0, 0, 1]\nR3 = Rz^3\n");
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> u(-2, 2);
    const auto product = [](const Mat& x, const Mat& y) {
        Mat z{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int s = 0; s < 3; ++s) z[i][j] += x[i][s] * y[s][j];
        return z;
    };
    for (int trial = 0; trial < 3; ++trial) {
        Mat m{};
        for (auto& row : m)
            for (double& x : row) x = u(rng);
        const char* names[9] = {"a", "b", "c", "d", "f", "g", "h", "k", "L"};
        std::string at;
        for (int i = 0; i < 9; ++i) at += (i ? ", " : "") + std::string(names[i]) + " = " + digits17(m[i / 3][i % 3]);
        const double th = u(rng);
        at += ", th = " + digits17(th);
        double det = 0;
        const Mat inv = hand_inverse(m, det);
        const Mat m2 = product(m, m), m3 = product(m2, m), m5 = product(m3, m2), inv2 = product(inv, inv);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const std::string ij = "[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]";
                expect_close(r.at("M2" + ij, at), m2[i][j], "M^2 " + ij);
                expect_close(r.at("M3" + ij, at), m3[i][j], "M^3 " + ij);
                EXPECT_NEAR(r.at("M5" + ij, at), m5[i][j], 1e-10 * std::max(1.0, std::abs(m5[i][j]))) << "M^5 " << ij;
                expect_close(r.at("M0" + ij, at), i == j ? 1 : 0, "M^0 " + ij);
                expect_close(r.at("Mm1" + ij, at), inv[i][j], "M^-1 " + ij);
                EXPECT_NEAR(r.at("Mm2" + ij, at), inv2[i][j], 1e-10 * std::max(1.0, std::abs(inv2[i][j]))) << "M^-2 " << ij;
                const double r3[3][3] = {{std::cos(3 * th), -std::sin(3 * th), 0}, {std::sin(3 * th), std::cos(3 * th), 0}, {0, 0, 1}};
                expect_close(r.at("R3" + ij, at), r3[i][j], "Rz^3 " + ij);
            }
    }
    std::string e = r.fails("X = [a, b; c, d; f, g]^2\n");
    EXPECT_TRUE(has(e, "test.alb:1:5: error: a power of a matrix takes a square matrix, and the matrix is 3 by 2")) << e;
    e = r.fails("X = M^th\n");
    EXPECT_TRUE(has(e, "test.alb:1:7: error: a power of a matrix takes a whole number, not th")) << e;
    e = r.fails("X = [1, 2; 2, 4]^-1\n");
    EXPECT_TRUE(has(e, "needs its inverse, and it is singular")) << e;
}

// eig of [2, 1, 0; 1, 2, 1; 0, 1, 2]: 2 - sqrt 2, 2, 2 + sqrt 2; of [p, r; r, s] with values:
// (p + s)/2 -+ sqrt(((p - s)/2)^2 + r^2)
TEST(MatrixFunctions, EigIsTheEigenvaluesOfAMatrixOfNumbers) {
    MatrixRun r;
    r.ok("newtonian N\ndigits 17\nE = eig([2, 1, 0; 1, 2, 1; 0, 1, 2])\n");
    expect_close(r.at("E[1, 1]", ""), 2 - std::sqrt(2.0), "smallest");
    expect_close(r.at("E[2, 1]", ""), 2, "middle");
    expect_close(r.at("E[3, 1]", ""), 2 + std::sqrt(2.0), "largest");
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int trial = 0; trial < 3; ++trial) {
        const double p = u(rng), q = u(rng), s = u(rng);
        MatrixRun w;
        w.ok("newtonian N\ndigits 17\nconstant p = " + digits17(p) + ", r = " + digits17(q) + ", s = " + digits17(s) +
             "\nE = eig([p, r; r, s])\n");
        const double mid = (p + s) / 2, half = std::sqrt((p - s) * (p - s) / 4 + q * q);
        expect_close(w.at("E[1, 1]", ""), mid - half, "lower eigenvalue");
        expect_close(w.at("E[2, 1]", ""), mid + half, "upper eigenvalue");
    }
    // a triangular matrix's eigenvalues are its diagonal
    EXPECT_EQ(r.ok("eig([1, 5, 7; 0, -2, 4; 0, 0, 3])\n"), "= [-2; 1; 3]\n");
    std::string e = r.fails("eig([0, -1; 1, 0])\n");
    EXPECT_TRUE(has(e, "test.alb:1:5: error: eig(): the eigenvalues of the matrix are complex: 0 - 1i, 0 + 1i")) << e;
    e = r.fails("constant z\neig([z, 1; 1, 0])\n");
    EXPECT_TRUE(has(e, "test.alb:2:5: error: 'z' has no value")) << e;
    EXPECT_TRUE(has(e, "hint: eig() takes a matrix of numbers")) << e;
}

// The eigenvectors by hand. [2, 1; 1, 2]: (1, -1)/sqrt 2 for 1, (1, 1)/sqrt 2 for 3.
// [2, 1, 1; 1, 2, 1; 1, 1, 2]: 1 twice, on the plane x + y + z = 0, whose reduced echelon basis
// (1, 0, -1), (0, 1, -1) made orthonormal is (1, 0, -1)/sqrt 2, (-1, 2, -1)/sqrt 6; 4 on
// (1, 1, 1)/sqrt 3. diag(2, 2, 5): the unit vectors. [2, 1; 0, 3]: (1, 0) for 2, (1, 1)/sqrt 2
// for 3. [4, 1; 2, 3]: (1, -2) for 2, its largest component made positive, (-1, 2)/sqrt 5;
// (1, 1)/sqrt 2 for 5.
TEST(MatrixFunctions, EigvecIsTheUnitEigenvectorsOfTheHandDerivation) {
    MatrixRun r;
    r.ok("newtonian N\ndigits 17\n");
    const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0), s5 = std::sqrt(5.0), s6 = std::sqrt(6.0);
    auto expect_matrix = [&](const std::string& m, const std::vector<std::vector<double>>& want) {
        r.ok("V = eigvec(" + m + ")\n");
        for (std::size_t i = 0; i < want.size(); ++i)
            for (std::size_t j = 0; j < want.size(); ++j)
                expect_close(r.at("V[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", ""), want[i][j],
                             "eigvec(" + m + ")[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]");
    };
    expect_matrix("[2, 1; 1, 2]", {{1 / s2, 1 / s2}, {-1 / s2, 1 / s2}});
    expect_matrix("[2, 1, 1; 1, 2, 1; 1, 1, 2]", {{1 / s2, -1 / s6, 1 / s3}, {0, 2 / s6, 1 / s3}, {-1 / s2, -1 / s6, 1 / s3}});
    expect_matrix("[2, 0, 0; 0, 2, 0; 0, 0, 5]", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    expect_matrix("[2, 1; 0, 3]", {{1, 1 / s2}, {0, 1 / s2}});
    expect_matrix("[4, 1; 2, 3]", {{-1 / s5, 1 / s2}, {2 / s5, 1 / s2}});
    // exact unit components print as whole numbers
    EXPECT_EQ(r.ok("eigvec([2, 0, 0; 0, 2, 0; 0, 0, 5])\neigvec([7])\n"), "= [1, 0, 0; 0, 1, 0; 0, 0, 1]\n= [1]\n");
}

// M = S diag(d) S^-1 with S and d drawn at random (d apart, ascending): the eigenvalues are d,
// the eigenvectors S's columns; eigvec's column j is S's column j over its length, its
// largest component positive. A symmetric M = Q diag(d) Q^T with constants given values: an
// orthonormal V with M V = V diag(eig(M)).
TEST(MatrixFunctions, EigvecOfMatricesOfKnownEigenvectors) {
    std::mt19937 rng(45);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 4; ++trial) {
        // a well-conditioned basis: 1.5 on the diagonal and at most 0.5 off it
        Mat S{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) S[i][j] = (i == j ? 1.5 : 0) + 0.25 * u(rng);
        double det = 0;
        const Mat Si = hand_inverse(S, det);
        const std::array<double, 3> d{-1.5 + 0.2 * trial, 0.5, 2 + 0.3 * trial};
        Mat M{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) M[i][j] += S[i][k] * d[static_cast<std::size_t>(k)] * Si[k][j];
        std::string m = "[";
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m += digits17(M[i][j]) + (j < 2 ? ", " : i < 2 ? "; " : "]");
        MatrixRun r;
        r.ok("newtonian N\ndigits 17\nE = eig(" + m + ")\nV = eigvec(" + m + ")\n");
        for (int j = 0; j < 3; ++j) {
            EXPECT_NEAR(r.at("E[" + std::to_string(j + 1) + ", 1]", ""), d[static_cast<std::size_t>(j)], 1e-9);
            double length = 0;
            int largest = 0;
            for (int i = 0; i < 3; ++i) {
                length += S[i][j] * S[i][j];
                if (std::abs(S[i][j]) > std::abs(S[largest][j])) largest = i;
            }
            const double sign = S[largest][j] < 0 ? -1 : 1;
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(r.at("V[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", ""),
                            sign * S[i][j] / std::sqrt(length), 1e-9)
                    << m << " column " << j + 1;
        }
    }
    // symmetric, of constants with values: p, r, s on the diagonal, k off it
    for (int trial = 0; trial < 3; ++trial) {
        const double p = u(rng), q = u(rng), s = u(rng), k = u(rng);
        MatrixRun r;
        r.ok("newtonian N\ndigits 17\nconstant p = " + digits17(p) + ", r = " + digits17(q) + ", s = " + digits17(s) +
             ", k = " + digits17(k) + "\nM = [p, k, 0; k, r, k; 0, k, s]\nE = eig(M)\nV = eigvec(M)\n");
        const double m[3][3] = {{p, k, 0}, {k, q, k}, {0, k, s}};
        double v[3][3], e[3];
        for (int i = 0; i < 3; ++i) {
            e[i] = r.at("E[" + std::to_string(i + 1) + ", 1]", "");
            for (int j = 0; j < 3; ++j) v[i][j] = r.at("V[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", "");
        }
        for (int j = 0; j < 3; ++j) {
            for (int i = 0; i < 3; ++i) {
                double mv = 0;
                for (int c = 0; c < 3; ++c) mv += m[i][c] * v[c][j];
                EXPECT_NEAR(mv, e[j] * v[i][j], 1e-12) << "M v = lambda v, column " << j + 1;
            }
            for (int c = 0; c < 3; ++c) {
                double dot = 0;
                for (int i = 0; i < 3; ++i) dot += v[i][j] * v[i][c];
                EXPECT_NEAR(dot, j == c ? 1 : 0, 1e-12) << "V^T V, " << j + 1 << ", " << c + 1;
            }
            int largest = 0;
            for (int i = 1; i < 3; ++i)
                if (std::abs(v[i][j]) > std::abs(v[largest][j]) + 1e-12) largest = i;
            EXPECT_GT(v[largest][j], 0) << "the largest component of column " << j + 1;
        }
    }
}

TEST(MatrixFunctions, EigvecRefusesDefectiveAndComplexMatrices) {
    MatrixRun r;
    r.ok("newtonian N\nconstant z\nJ = [1, 1; 0, 1]\n");
    std::string e = r.fails("eigvec(J)\n");
    EXPECT_TRUE(has(e, "test.alb:1:8: error: eigvec(): 'J' is defective: its eigenvalue 1, repeated 2 times, has fewer "
                       "than 2 independent eigenvectors")) << e;
    e = r.fails("eigvec([3, 1, 0; 0, 3, 1; 0, 0, 3])\n");
    EXPECT_TRUE(has(e, "eigvec(): the matrix is defective: its eigenvalue 3, repeated 3 times")) << e;
    // a double eigenvalue 1 of a matrix that is not triangular: (x - 1)^2 = x^2 - 2x + 1
    e = r.fails("eigvec([2, 1; -1, 0])\n");
    EXPECT_TRUE(has(e, "eigvec(): the matrix is defective: its eigenvalue 1")) << e;
    e = r.fails("eigvec([0, -1; 1, 0])\n");
    EXPECT_TRUE(has(e, "test.alb:1:8: error: eigvec(): the eigenvalues of the matrix are complex: 0 - 1i, 0 + 1i")) << e;
    e = r.fails("eigvec([z, 1; 1, 0])\n");
    EXPECT_TRUE(has(e, "'z' has no value")) << e;
    EXPECT_TRUE(has(e, "hint: eigvec() takes a matrix of numbers")) << e;
    e = r.fails("eigvec([1, 2])\n");
    EXPECT_TRUE(has(e, "eigvec() takes a square matrix, and the matrix is 1 by 2")) << e;
    e = r.fails("eigvec(z)\n");
    EXPECT_TRUE(has(e, "eigvec() takes a matrix, but this is a scalar")) << e;
    e = r.fails("eigvec(J, J)\n");
    EXPECT_TRUE(has(e, "eigvec() takes 1 argument, not 2")) << e;
}

// polynomial([A, B, C], x) = A x^2 + B x + C and back; roots of (x - r1)(x - r2)(x - r3)
TEST(MatrixFunctions, PolynomialAndRootsAgreeWithTheHandPolynomial) {
    MatrixRun r;
    r.ok("newtonian N\nconstant A, B, C\nvariable x''\ndigits 17\nP = polynomial([A, B, C], x)\n"
         "K = polynomial((A*x - B)^2*x + C, x)\n");
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int trial = 0; trial < 3; ++trial) {
        const double a = u(rng), b = u(rng), c = u(rng), x = u(rng);
        const std::string at = "A = " + digits17(a) + ", B = " + digits17(b) + ", C = " + digits17(c) + ", x = " + digits17(x);
        expect_close(r.at("P", at), a * x * x + b * x + c, "polynomial " + at);
        // (A x - B)^2 x + C = A^2 x^3 - 2AB x^2 + B^2 x + C
        expect_close(r.at("K[1, 1]", at), a * a, "x^3");
        expect_close(r.at("K[1, 2]", at), -2 * a * b, "x^2");
        expect_close(r.at("K[1, 3]", at), b * b, "x");
        expect_close(r.at("K[1, 4]", at), c, "1");
        std::array<double, 3> z{u(rng), u(rng), u(rng)};
        const std::string p = "(x - " + digits17(z[0]) + ")*(x - " + digits17(z[1]) + ")*(x - " + digits17(z[2]) + ")";
        r.ok("Z = roots(" + p + ", x)\n");
        std::sort(z.begin(), z.end());
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.at("Z[" + std::to_string(i + 1) + ", 1]", ""), z[static_cast<std::size_t>(i)], 1e-9) << p;
    }
    EXPECT_EQ(r.ok("roots([1, -6, 11, -6])\nroots(2*x - 3, x)\n"), "= [1; 2; 3]\n= [1.5]\n");
    std::string e = r.fails("roots([1, 0, 1])\n");
    EXPECT_TRUE(has(e, "test.alb:1:7: error: roots(): the roots are complex: 0 - 1i, 0 + 1i")) << e;
    EXPECT_TRUE(has(e, "    1 | roots([1, 0, 1])\n      |       ^")) << e;
    e = r.fails("roots(A*x^2 - 1, x)\n");
    EXPECT_TRUE(has(e, "test.alb:1:7: error: 'A' has no value")) << e;
    EXPECT_TRUE(has(e, "the coefficient of x^2 is A")) << e;
    e = r.fails("roots(sin(x), x)\n");
    EXPECT_TRUE(has(e, "roots(): the expression is not a polynomial in 'x'")) << e;
    e = r.fails("roots([0, 0, 3])\n");
    EXPECT_TRUE(has(e, "roots(): the polynomial has no roots to find")) << e;
    e = r.fails("polynomial(1/x, x)\n");
    EXPECT_TRUE(has(e, "test.alb:1:12: error: polynomial(): the expression is not a polynomial in 'x'")) << e;
    e = r.fails("Pn = sin(x)*A\npolynomial(Pn, x)\n");
    EXPECT_TRUE(has(e, "test.alb:2:12: error: polynomial(): 'Pn' is not a polynomial in 'x'")) << e;
    e = r.fails("polynomial([1, 2], 3)\n");
    EXPECT_TRUE(has(e, "polynomial(): the second argument must be a declared symbol")) << e;
}

TEST(MatrixFunctions, MatrixErrorsNameTheMatrixAndTheArgument) {
    MatrixRun r;
    r.ok("newtonian N\nconstant a, b\nZ = [1, 2; 2, 4]\nM = [a, b; b, a]\nR = [1, 2, 3]\n");
    std::string e = r.fails("W = inv(Z)\n");
    EXPECT_TRUE(has(e, "test.alb:1:9: error: inv(): 'Z' is singular (its determinant is 0), so it has no inverse")) << e;
    EXPECT_TRUE(has(e, "    1 | W = inv(Z)\n      |         ^")) << e;
    e = r.fails("inv([a, a; b, b])\n");
    EXPECT_TRUE(has(e, "inv(): the matrix is singular")) << e;
    e = r.fails("det(R)\n");
    EXPECT_TRUE(has(e, "test.alb:1:5: error: det() takes a square matrix, and 'R' is 1 by 3")) << e;
    e = r.fails("M + R\n");
    EXPECT_TRUE(has(e, "test.alb:1:5: error: cannot add a 1 by 3 matrix to a 2 by 2 matrix")) << e;
    e = r.fails("M + 1\n");
    EXPECT_TRUE(has(e, "cannot add a scalar to a matrix")) << e;
    e = r.fails("M*R\n");
    EXPECT_TRUE(has(e, "cannot multiply a 2 by 2 matrix by a 1 by 3 matrix")) << e;
    e = r.fails("M*Nx>\n");
    EXPECT_TRUE(has(e, "cannot multiply a matrix and a vector")) << e;
    e = r.fails("1/M\n");
    EXPECT_TRUE(has(e, "cannot divide by a matrix")) << e;
    e = r.fails("element(M, 3, 1)\n");
    EXPECT_TRUE(has(e, "test.alb:1:12: error: element(): the row of 'M' must be a whole number from 1 to 2")) << e;
    e = r.fails("cols(M, 0)\n");
    EXPECT_TRUE(has(e, "cols(): the column of 'M' must be a whole number from 1 to 2")) << e;
    e = r.fails("transpose(a)\n");
    EXPECT_TRUE(has(e, "test.alb:1:11: error: transpose() takes a matrix, but this is a scalar")) << e;
    e = r.fails("diagmat(0, a)\n");
    EXPECT_TRUE(has(e, "diagmat(): the number of rows must be a whole number from 1 to 100")) << e;
    e = r.fails("inv(M, M)\n");
    EXPECT_TRUE(has(e, "inv() takes 1 argument, not 2")) << e;
}

// two particles: mass(A, B) = m1 + m2; the mass centre from N_o, (m1 r1 + m2 r2)/(m1 + m2)
TEST(MatrixFunctions, MassAndMassCentreOfSeveralBodies) {
    MatrixRun r;
    r.ok("newtonian N\nparticle A, B, C\nconstant m1, m2, m3, L\nvariable q''\ndigits 17\n"
         "translate A from N_o by L*cos(q)*Nx> + L*sin(q)*Ny>\ntranslate B from N_o by 2*L*Ny>\n"
         "translate C from A by L*Nx>\nmass A = m1\nmass B = m2\nmass C = m3\nsystem S = A, C\n");
    std::mt19937 rng(44);
    std::uniform_real_distribution<double> u(0.5, 3);
    for (int trial = 0; trial < 3; ++trial) {
        const double m1 = u(rng), m2 = u(rng), m3 = u(rng), l = u(rng), q = u(rng);
        const std::string at = "m1 = " + digits17(m1) + ", m2 = " + digits17(m2) + ", m3 = " + digits17(m3) + ", L = " + digits17(l) +
                               ", q = " + digits17(q);
        expect_close(r.at("mass(A, B)", at), m1 + m2, "mass(A, B)");
        expect_close(r.at("mass(S, B)", at), m1 + m2 + m3, "mass(S, B)");
        const double xa = l * std::cos(q), ya = l * std::sin(q), yb = 2 * l, xc = xa + l, yc = ya;
        expect_close(r.at("dot(cm(N_o, A, B), Nx>)", at), m1 * xa / (m1 + m2), "x of cm(N_o, A, B)");
        expect_close(r.at("dot(cm(N_o, A, B), Ny>)", at), (m1 * ya + m2 * yb) / (m1 + m2), "y of cm(N_o, A, B)");
        const double all = m1 + m2 + m3;
        expect_close(r.at("dot(cm(B), Nx>)", at), (m1 * xa + m3 * xc) / all, "x of cm(B)");
        expect_close(r.at("dot(cm(B), Ny>)", at), (m1 * ya + m2 * yb + m3 * yc) / all - yb, "y of cm(B)");
    }
    std::string e = r.fails("cm(N_o, S, A)\n");
    EXPECT_TRUE(has(e, "test.alb:1:12: error: cm(): 'A' is counted twice")) << e;
    e = r.fails("cm()\n");
    EXPECT_TRUE(has(e, "cm() takes the point first")) << e;
    e = r.fails("mass(A, Q)\n");
    EXPECT_TRUE(has(e, "test.alb:1:9:")) << e;
}

}  // namespace matrix_functions_test
