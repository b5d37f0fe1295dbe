// SPDX-License-Identifier: MIT
// A spatial leg with markers, shared by the inverse kinematics tests and benchmark.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "alembert/biomech/inverse_kinematics.hpp"

namespace alembert::test {

inline constexpr double kThigh = 0.42, kShank = 0.40;  // segment lengths, m

// marker offsets in each segment's frame, from its proximal joint (3 per segment, not on a line)
inline const std::array<Eigen::Vector3d, 3> kThighMarkers = {Eigen::Vector3d(0.06, -0.12, 0.02),
                                                             Eigen::Vector3d(-0.03, -0.25, 0.07),
                                                             Eigen::Vector3d(0.04, -0.33, -0.06)};
inline const std::array<Eigen::Vector3d, 3> kShankMarkers = {Eigen::Vector3d(0.05, -0.10, 0.03),
                                                             Eigen::Vector3d(-0.04, -0.20, 0.06),
                                                             Eigen::Vector3d(0.03, -0.30, -0.05)};
inline const std::array<Eigen::Vector3d, 3> kFootMarkers = {Eigen::Vector3d(0.12, -0.05, 0.03),
                                                            Eigen::Vector3d(-0.05, -0.06, 0.02),
                                                            Eigen::Vector3d(0.08, -0.04, -0.05)};

// A spatial leg of 9 coordinates: the hip centre H translated by (tx, ty, tz) from N_o; the
// thigh T turned at the hip's ball joint by the body-fixed ZXY sequence qH1 (flexion), qH2
// (adduction), qH3 (rotation); the shank S at the knee hinge K = H - L_T T_y by qK about T_z;
// the foot F at the ankle's universal joint A = K - L_S S_y by qA1 about S_z, then qA2 about
// the new x. Markers T1-T3, S1-S3, F1-F3, three per segment.
struct Leg {
    System system;
    std::vector<ex> q;
    std::vector<MarkerPoint> markers;
};

inline std::unique_ptr<Leg> make_leg() {
    auto leg = std::make_unique<Leg>();
    System& sys = leg->system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    const ex L_T = s.add_constant("L_T", kThigh), L_S = s.add_constant("L_S", kShank);
    for (const char* name : {"tx", "ty", "tz", "qH1", "qH2", "qH3", "qK", "qA1", "qA2"})
        leg->q.push_back(s.add_variable(name, 2));
    const auto& q = leg->q;
    RigidBody& T = sys.add_rigid_body("T");
    RigidBody& S = sys.add_rigid_body("S");
    RigidBody& F = sys.add_rigid_body("F");
    Frame& Tf = T.body_frame();
    Frame& Sf = S.body_frame();
    Frame& Ff = F.body_frame();
    Frame& S1 = sys.add_frame("S1");
    Tf.orient_body_fixed(N, RotationSequence::ZXY, q[3], q[4], q[5]);
    Sf.orient_axis(Tf, Axis::z, q[6]);
    S1.orient_axis(Sf, Axis::z, q[7]);
    Ff.orient_axis(S1, Axis::x, q[8]);
    Point& H = sys.add_point("H", &T);
    H.set_pos(sys.origin(), q[0] * N.x() + q[1] * N.y() + q[2] * N.z());
    Point& K = sys.add_point("K", &S);
    K.set_pos(H, -L_T * Tf.y());
    Point& A = sys.add_point("A", &F);
    A.set_pos(K, -L_S * Sf.y());
    auto stick = [&](const std::string& name, const RigidBody& B, const Point& from,
                     const Eigen::Vector3d& r) {
        const Frame& Bf = *B.frame();
        Point& P = sys.add_point(name, &B);
        P.set_pos(from, ex(r.x()) * Bf.x() + ex(r.y()) * Bf.y() + ex(r.z()) * Bf.z());
        leg->markers.push_back({name, &P, 1.0});
    };
    for (int i = 0; i < 3; ++i) stick("T" + std::to_string(i + 1), T, H, kThighMarkers[i]);
    for (int i = 0; i < 3; ++i) stick("S" + std::to_string(i + 1), S, K, kShankMarkers[i]);
    for (int i = 0; i < 3; ++i) stick("F" + std::to_string(i + 1), F, A, kFootMarkers[i]);
    return leg;
}

inline Eigen::Matrix3d leg_rotation(double angle, const Eigen::Vector3d& axis) {
    return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

// the leg's nine marker positions at coordinates q, from rotation matrices composed by hand
inline std::vector<Eigen::Vector3d> leg_markers_by_hand(const std::vector<double>& q) {
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                          Z = Eigen::Vector3d::UnitZ();
    const Eigen::Matrix3d R_NT =
        leg_rotation(q[3], Z) * leg_rotation(q[4], X) * leg_rotation(q[5], Y);
    const Eigen::Matrix3d R_NS = R_NT * leg_rotation(q[6], Z);
    const Eigen::Matrix3d R_NF = R_NS * leg_rotation(q[7], Z) * leg_rotation(q[8], X);
    const Eigen::Vector3d p_H(q[0], q[1], q[2]);
    const Eigen::Vector3d p_K = p_H + R_NT * Eigen::Vector3d(0, -kThigh, 0);
    const Eigen::Vector3d p_A = p_K + R_NS * Eigen::Vector3d(0, -kShank, 0);
    std::vector<Eigen::Vector3d> p;
    for (const auto& r : kThighMarkers) p.push_back(p_H + R_NT * r);
    for (const auto& r : kShankMarkers) p.push_back(p_K + R_NS * r);
    for (const auto& r : kFootMarkers) p.push_back(p_A + R_NF * r);
    return p;
}

// a smooth stride-like motion of the leg at time t, away from the ZXY sequence's singularity
inline std::vector<double> leg_motion(double t) {
    const double w = 2 * std::numbers::pi;
    return {0.3 * t + 0.02 * std::sin(w * t),
            0.9 + 0.03 * std::sin(2 * w * t),
            0.01 * std::cos(w * t),
            0.4 * std::sin(w * t),
            0.1 * std::sin(w * t + 1),
            0.15 * std::sin(w * t + 2),
            -0.6 + 0.5 * std::sin(w * t + 0.5),
            0.2 * std::sin(w * t + 1.5),
            0.1 * std::sin(w * t + 2.5)};
}

inline const std::vector<std::string> kLegMarkerNames = {"T1", "T2", "T3", "S1", "S2",
                                                         "S3", "F1", "F2", "F3"};

}  // namespace alembert::test
