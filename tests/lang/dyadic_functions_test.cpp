// SPDX-License-Identifier: MIT
// Dyadics in the language against hand results at random points: the central inertia dotted
// with the angular velocity (the angular momentum I w by hand), a dyad's measures in two frames,
// the unit dyadic, express(), dot(a>, D>>, b>), matrix() and vector(), sums and multiples and
// the parallel-axis transfer; their errors at the argument, with file:line:col and caret.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

#include "alembert/lang/interpreter.hpp"
#include "support/script_dir.hpp"

namespace dyadic_functions_test {

using namespace alembert::lang;

using DyadicRun = alembert::test::ScriptSession;
using alembert::test::digits17;
using alembert::test::has;

using Vec3 = std::array<double, 3>;
using Mat = std::array<Vec3, 3>;

void expect_close(double got, double want, const std::string& what) {
    EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(want))) << what;
}

Vec3 times(const Mat& m, const Vec3& v) {
    Vec3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i] += m[i][j] * v[j];
    return r;
}

const char* kAxes[3] = {"x", "y", "z"};

// C turned from N by q1 about z (B), then by q2 about B's x; C's inertia about its mass centre
// has products. In C's unit vectors w = (q2', q1' sin q2, q1' cos q2) (Bz> = sin q2 Cy> +
// cos q2 Cz>), and the angular momentum about the mass centre is H = I w, I the inertia matrix
// in C; the kinetic energy of rotation is w.I.w/2.
TEST(DyadicFunctions, CentralInertiaDottedWithAngularVelocityIsTheAngularMomentumByHand) {
    DyadicRun r;
    const std::string out = r.ok(
        "constant m, Ixx, Iyy, Izz, Ixy, Iyz, Izx\n"
        "variable q1', q2'\n"
        "newtonian N\n"
        "frame B\n"
        "body C\n"
        "rotate B from N about z by q1\n"
        "rotate C from B about x by q2\n"
        "mass C = m\n"
        "inertia C = Ixx, Iyy, Izz, Ixy, Iyz, Izx\n"
        "digits 17\n"
        "inertia(C)\n"
        "H> = dot(I_C_Ccm>>, angvel(C, N))\n"
        "Hl> = dot(angvel(C, N), inertia(C))\n"
        "KE = dot(angvel(C, N), inertia(C), angvel(C, N))/2\n");
    EXPECT_TRUE(has(out, "I_C_Ccm>> = ")) << out;
    std::mt19937 rng(2701);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double q2 = u(rng), q1d = u(rng), q2d = u(rng);
        const double ixx = 1 + u(rng) * u(rng), iyy = 2 + u(rng), izz = 3 + u(rng);
        const double ixy = u(rng) / 4, iyz = u(rng) / 4, izx = u(rng) / 4;
        const std::string at = "q1 = " + digits17(u(rng)) + ", q2 = " + digits17(q2) + ", q1' = " + digits17(q1d) +
                               ", q2' = " + digits17(q2d) + ", Ixx = " + digits17(ixx) + ", Iyy = " + digits17(iyy) +
                               ", Izz = " + digits17(izz) + ", Ixy = " + digits17(ixy) + ", Iyz = " + digits17(iyz) +
                               ", Izx = " + digits17(izx);
        const Mat I{{{ixx, ixy, izx}, {ixy, iyy, iyz}, {izx, iyz, izz}}};
        const Vec3 w{q2d, q1d * std::sin(q2), q1d * std::cos(q2)};
        const Vec3 H = times(I, w);
        for (int i = 0; i < 3; ++i) {
            expect_close(r.at("dot(H>, C" + std::string(kAxes[i]) + ">)", at), H[i], "H " + std::to_string(i) + at);
            expect_close(r.at("dot(Hl>, C" + std::string(kAxes[i]) + ">)", at), H[i], "w.I " + std::to_string(i));
        }
        expect_close(r.at("KE", at), (w[0] * H[0] + w[1] * H[1] + w[2] * H[2]) / 2, "KE " + at);
    }
}

// D = u> v>, u = a1 Nx> + a2 Ny> + a3 Nz>, v = c1 Bx> + c2 By> + c3 Bz> with B turned by q about
// Nz: v in N is (c1 cos q - c2 sin q, c1 sin q + c2 cos q, c3), so [D]_N[i][j] = u_i v_j; in B,
// u is (a1 cos q + a2 sin q, -a1 sin q + a2 cos q, a3) and [D]_B[i][j] = u_i c_j. D . w =
// u (v . w), w . D = (w . u) v, and express(D, B) is D (its measures in N unchanged).
TEST(DyadicFunctions, ADyadsMeasuresInTwoFramesAgreeWithTheHandResults) {
    DyadicRun r;
    r.ok("constant a1, a2, a3, c1, c2, c3\n"
         "variable q\n"
         "newtonian N\n"
         "frame B\n"
         "rotate B from N about z by q\n"
         "digits 17\n"
         "u> = a1*Nx> + a2*Ny> + a3*Nz>\n"
         "v> = c1*Bx> + c2*By> + c3*Bz>\n"
         "D>> = outer(u>, v>)\n"
         "DN = matrix(N, D>>)\n"
         "DB = matrix(B, express(D>>, N))\n"
         "E>> = express(D>>, B) - D>>\n"
         "Dw> = dot(D>>, Nx> + 2*By>)\n"
         "wD> = dot(Nx> + 2*By>, D>>)\n");
    std::mt19937 rng(2702);
    std::uniform_real_distribution<double> g(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double q = g(rng);
        const Vec3 a{g(rng), g(rng), g(rng)}, c{g(rng), g(rng), g(rng)};
        std::string at = "q = " + digits17(q);
        for (int i = 0; i < 3; ++i)
            at += ", a" + std::to_string(i + 1) + " = " + digits17(a[i]) + ", c" + std::to_string(i + 1) + " = " +
                  digits17(c[i]);
        const double cq = std::cos(q), sq = std::sin(q);
        const Vec3 vN{c[0] * cq - c[1] * sq, c[0] * sq + c[1] * cq, c[2]};
        const Vec3 uB{a[0] * cq + a[1] * sq, -a[0] * sq + a[1] * cq, a[2]};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const std::string ij = "[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]";
                expect_close(r.at("DN" + ij, at), a[i] * vN[j], "[D]_N" + ij + at);
                expect_close(r.at("DB" + ij, at), uB[i] * c[j], "[D]_B" + ij + at);
                expect_close(r.at("dot(N" + std::string(kAxes[i]) + ">, E>>, N" + kAxes[j] + ">)", at), 0,
                             "express changes no measure " + ij);
            }
        // w = Nx> + 2 By> = (1 - 2 sin q, 2 cos q, 0) in N
        const Vec3 wN{1 - 2 * sq, 2 * cq, 0};
        const double vw = vN[0] * wN[0] + vN[1] * wN[1], wu = wN[0] * a[0] + wN[1] * a[1];
        for (int i = 0; i < 3; ++i) {
            const std::string n = "N" + std::string(kAxes[i]) + ">";
            expect_close(r.at("dot(Dw>, " + n + ")", at), a[i] * vw, "D.w " + n);
            expect_close(r.at("dot(wD>, " + n + ")", at), wu * vN[i], "w.D " + n);
        }
        expect_close(r.at("dot(Ny>, D>>, Bz>)", at), a[1] * c[2], "Ny>.D.Bz> " + at);
    }
}

// The unit dyadic dotted with any vector, on either side, is the vector; its matrix in any frame
// is the identity. vector(F, matrix(F, v>)) is v>, and vector(B, [c1; c2; c3]) measured in N is
// R c with R the rotation by q about z. Sums and multiples: (2 U - u> u>/k) . w = 2 w - u (u.w)/k.
TEST(DyadicFunctions, UnitDyadicMatrixAndVectorAgreeWithTheHandResults) {
    DyadicRun r;
    r.ok("constant a1, a2, a3, c1, c2, c3, k\n"
         "variable q\n"
         "newtonian N\n"
         "frame B\n"
         "rotate B from N about z by q\n"
         "digits 17\n"
         "v> = c1*Bx> + c2*By> + c3*Bz>\n"
         "u> = a1*Nx> + a2*Ny> + a3*Nz>\n"
         "Uv> = dot(unitdyadic(N), v>) - v>\n"
         "vU> = dot(v>, unitdyadic(B)) - v>\n"
         "UB = matrix(B, unitdyadic(N))\n"
         "back> = vector(N, matrix(N, v>)) - v>\n"
         "cN = matrix(N, vector(B, [c1; c2; c3]))\n"
         "S>> = 2*unitdyadic(N) - outer(u>, u>)/k\n"
         "Sw> = dot(S>>, v>)\n");
    std::mt19937 rng(2703);
    std::uniform_real_distribution<double> g(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double q = g(rng), k = 1 + std::abs(g(rng));
        const Vec3 a{g(rng), g(rng), g(rng)}, c{g(rng), g(rng), g(rng)};
        std::string at = "q = " + digits17(q) + ", k = " + digits17(k);
        for (int i = 0; i < 3; ++i)
            at += ", a" + std::to_string(i + 1) + " = " + digits17(a[i]) + ", c" + std::to_string(i + 1) + " = " +
                  digits17(c[i]);
        const double cq = std::cos(q), sq = std::sin(q);
        const Vec3 vN{c[0] * cq - c[1] * sq, c[0] * sq + c[1] * cq, c[2]};
        const double uv = a[0] * vN[0] + a[1] * vN[1] + a[2] * vN[2];
        for (int i = 0; i < 3; ++i) {
            const std::string n = "N" + std::string(kAxes[i]) + ">";
            expect_close(r.at("dot(Uv>, " + n + ")", at), 0, "U.v - v " + n);
            expect_close(r.at("dot(vU>, " + n + ")", at), 0, "v.U - v " + n);
            expect_close(r.at("dot(back>, " + n + ")", at), 0, "vector(matrix(v)) - v " + n);
            expect_close(r.at("cN[" + std::to_string(i + 1) + ", 1]", at), vN[i], "R c " + n);
            expect_close(r.at("dot(Sw>, " + n + ")", at), 2 * vN[i] - a[i] * uv / k, "S.v " + n);
            for (int j = 0; j < 3; ++j)
                expect_close(r.at("UB[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", at), i == j ? 1 : 0,
                             "[U]_B");
        }
    }
}

// The inertia of a uniform rod of mass m and length L along Bx> about its end P, by hand
// m L^2/3 about By> and Bz>, 0 about Bx>: the central m L^2/12 plus the transfer
// m ((r.r) U - r r), r = (L/2) Bx> from the end.
TEST(DyadicFunctions, ParallelAxisTransferGivesTheRodsInertiaAboutItsEnd) {
    DyadicRun r;
    r.ok("constant m, L\n"
         "variable q\n"
         "newtonian N\n"
         "body B\n"
         "rotate B from N about z by q\n"
         "mass B = m\n"
         "inertia B = 0, m*L^2/12, m*L^2/12\n"
         "digits 17\n"
         "r> = L/2*Bx>\n"
         "IP>> = inertia(B) + m*(dot(r>, r>)*unitdyadic(N) - outer(r>, r>))\n"
         "IPB = matrix(B, IP>>)\n");
    std::mt19937 rng(2704);
    std::uniform_real_distribution<double> g(0.5, 2);
    for (int trial = 0; trial < 2; ++trial) {
        const double m = g(rng), L = g(rng);
        const std::string at = "q = " + digits17(g(rng)) + ", m = " + digits17(m) + ", L = " + digits17(L);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                expect_close(r.at("IPB[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]", at),
                             i == j && i > 0 ? m * L * L / 3 : 0, "I about the end " + at);
    }
}

// The dot product of two dyadics, by hand in N's unit vectors: [D . E]_N = [D]_N [E]_N. With B
// turned from N by q about z, Bx> = (c, s, 0) and By> = (-s, c, 0) in N, so D = a Nx> Bx> +
// b By> Nz> has [D]_N = a ex bx^T + b by ez^T and E = k Bx> Ny> + h Nz> Bz> has [E]_N =
// k bx ey^T + h ez ez^T; D . U = D for the unit dyadic.
TEST(DyadicFunctions, DotOfTwoDyadicsIsTheProductOfTheirMatricesByHand) {
    DyadicRun r;
    r.ok("constant a, b, k, h\n"
         "variable q\n"
         "newtonian N\n"
         "frame B\n"
         "rotate B from N about z by q\n"
         "digits 17\n"
         "D>> = a*outer(Nx>, Bx>) + b*outer(By>, Nz>)\n"
         "E>> = k*outer(Bx>, Ny>) + h*outer(Nz>, Bz>)\n"
         "DE = matrix(N, dot(D>>, E>>))\n"
         "ED = matrix(N, dot(E>>, D>>))\n"
         "DU = matrix(B, dot(D>>, unitdyadic(B)) - D>>)\n");
    std::mt19937 rng(2705);
    std::uniform_real_distribution<double> g(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double q = g(rng), a = g(rng), b = g(rng), k = g(rng), h = g(rng);
        const std::string at = "q = " + digits17(q) + ", a = " + digits17(a) + ", b = " + digits17(b) + ", k = " +
                               digits17(k) + ", h = " + digits17(h);
        const double c = std::cos(q), s = std::sin(q);
        const Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1}, bx{c, s, 0}, by{-s, c, 0};
        Mat D{}, E{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                D[i][j] = a * ex[i] * bx[j] + b * by[i] * ez[j];
                E[i][j] = k * bx[i] * ey[j] + h * ez[i] * ez[j];
            }
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                double de = 0, ed = 0;
                for (int l = 0; l < 3; ++l) de += D[i][l] * E[l][j], ed += E[i][l] * D[l][j];
                const std::string ij = "[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]";
                expect_close(r.at("DE" + ij, at), de, "[D.E]_N" + ij + " at " + at);
                expect_close(r.at("ED" + ij, at), ed, "[E.D]_N" + ij + " at " + at);
                expect_close(r.at("DU" + ij, at), 0, "D.U - D" + ij + " at " + at);
            }
    }
}

// The time derivative of the dyad Bx> Bx> with B turned from N by q about z, by hand: in N,
// Bx> = (cos q, sin q, 0) has the rate q' By>, so d/dt (Bx> Bx>) = q' (By> Bx> + Bx> By>), in B's
// unit vectors [0, q', 0; q', 0, 0; 0, 0, 0]; in B itself the dyad is constant. The rate of the
// inertia of a body spinning about its symmetry axis z in N is 0 in N.
TEST(DyadicFunctions, TimeDerivativeOfADyadicInAFrameIsTheHandRate) {
    DyadicRun r;
    r.ok("constant I1, I3\n"
         "variable q'\n"
         "newtonian N\n"
         "body B\n"
         "rotate B from N about z by q\n"
         "inertia B = I1, I1, I3\n"
         "digits 17\n"
         "DN = matrix(B, dt(outer(Bx>, Bx>), N))\n"
         "DB = matrix(N, dt(outer(Bx>, Bx>), B))\n"
         "IN = matrix(N, dt(inertia(B), N))\n");
    std::mt19937 rng(2706);
    std::uniform_real_distribution<double> g(-2, 2);
    for (int trial = 0; trial < 3; ++trial) {
        const double q = g(rng), u = g(rng), i1 = 1 + std::abs(g(rng)), i3 = 1 + std::abs(g(rng));
        const std::string at =
            "q = " + digits17(q) + ", q' = " + digits17(u) + ", I1 = " + digits17(i1) + ", I3 = " + digits17(i3);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const std::string ij = "[" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + "]";
                expect_close(r.at("DN" + ij, at), (i == 0 && j == 1) || (i == 1 && j == 0) ? u : 0, "d/dt in N" + ij);
                expect_close(r.at("DB" + ij, at), 0, "d/dt in B" + ij);
                expect_close(r.at("IN" + ij, at), 0, "inertia rate in N" + ij);
            }
    }
}

// Misuse is an error at the offending argument, naming what is wrong, with file:line:col and a
// caret; nothing is printed as a value.
TEST(DyadicFunctions, MisuseIsAnErrorAtTheArgument) {
    DyadicRun r;
    r.ok("newtonian N\nbody B\nvariable q\nD>> = unitdyadic(N)\n");
    struct Bad {
        std::string line;
        int column;
        std::string message;
    };
    const Bad bad[] = {
        {"dot(D>>, 2)", 10, "dot() takes a vector beside a dyadic, but this is a scalar"},
        {"sin(D>>)", 5, "sin() takes a scalar"},
        {"D>> + Nx>", 7, "cannot add a vector to a dyadic"},
        {"Nx>*D>>", 5, "cannot multiply a dyadic and a vector with '*'"},
        {"D>>*D>>", 5, "cannot multiply two dyadics with '*'"},
        {"Nx>*Ny>", 5, "cannot multiply two vectors with '*'"},
        {"x = D>>", 1, "a dyadic must be named with a trailing '>>': x>>"},
        {"v> = D>>", 6, "'v>' names a vector, but this is not a vector"},
        {"E>> = Nx>", 7, "'E>>' names a dyadic, but this is a vector"},
        {"G>>", 1, "the dyadic 'G>>' is not defined"},
        {"inertia(B)", 1, "the inertia of 'B' is not set"},
        {"inertia(N)", 9, "'N' is a frame"},
        {"matrix(N, 3)", 11, "matrix() takes a vector or a dyadic, but this is a scalar"},
        {"vector(N, [1, 2])", 11, "vector() takes three measures"},
        {"dot(Nx>, D>>, D>>)", 15, "dot() takes a vector here, but this is a dyadic"},
        {"evaluate D>> at q = 1", 10, "evaluate takes a scalar"},
        {"transpose(D>>)", 11, "transpose() takes a matrix, but this is a dyadic"},
        {"[1, 0, 0; 0, 1, 0; 0, 0, 1] + D>>", 31, "cannot add a dyadic to a matrix"},
        {"dt(D>>)", 4, "a dyadic's time derivative depends on the frame"},
        {"outer(Nx>, 2)", 12, "outer() takes a vector here, but this is a scalar"},
    };
    for (const Bad& b : bad) {
        const std::string e = r.fails(b.line + "\n");
        EXPECT_TRUE(has(e, "test.alb:1:" + std::to_string(b.column) + ": error: " + b.message)) << b.line << "\n" << e;
        EXPECT_TRUE(has(e, "   1 | " + b.line + "\n      | " + std::string(static_cast<std::size_t>(b.column - 1), ' ') + "^"))
            << b.line << "\n" << e;
    }
}

}  // namespace dyadic_functions_test
