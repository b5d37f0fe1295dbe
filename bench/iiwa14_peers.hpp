// SPDX-License-Identifier: MIT
// The KUKA LBR iiwa 14 as its URDF states it, for the peers of spatial_peers_bench, and the
// Simbody peer's interface (compiled apart: Simbody 3.7's headers need C++17).
#pragma once

#include <array>
#include <cmath>
#include <memory>

namespace alembert::bench {

constexpr int kArmJoints = 7;

// The iiwa 14 as its URDF states it (RobotLocomotion/drake,
// manipulation/models/iiwa_description/urdf/iiwa14_no_collision.urdf); the same numbers as
// make_kuka_iiwa14(), which builds Alembert's model from them.
struct Link {
    std::array<double, 3> xyz, rpy;  // joint origin in the parent link: R = Rz Ry Rx
    double mass;
    std::array<double, 3> com, inertia;  // in the link frame; principal central moments
};
inline const double kHalfPi = M_PI / 2;
inline const Link kArm[kArmJoints] = {
    {{0, 0, 0.1575}, {0, 0, 0}, 5.76, {0, -0.03, 0.12}, {0.033, 0.0333, 0.0123}},
    {{0, 0, 0.2025}, {kHalfPi, 0, M_PI}, 6.35, {0.0003, 0.059, 0.042}, {0.0305, 0.0304, 0.011}},
    {{0, 0.2045, 0}, {kHalfPi, 0, M_PI}, 3.5, {0, 0.03, 0.13}, {0.025, 0.0238, 0.0076}},
    {{0, 0, 0.2155}, {kHalfPi, 0, 0}, 3.5, {0, 0.067, 0.034}, {0.017, 0.0164, 0.006}},
    {{0, 0.1845, 0}, {-kHalfPi, M_PI, 0}, 3.5, {0.0001, 0.021, 0.076}, {0.01, 0.0087, 0.00449}},
    {{0, 0, 0.2155}, {kHalfPi, 0, 0}, 1.8, {0, 0.0006, 0.0004}, {0.0049, 0.0047, 0.0036}},
    {{0, 0.081, 0}, {-kHalfPi, M_PI, 0}, 1.2, {0, 0, 0.02}, {0.001, 0.001, 0.001}},
};


/// The arm in Simbody: pin mobilizers about z at the joint origins, uniform gravity -9.81 z.
/// Every call sets q (and u), so every stage is realized again.
class SimbodyArm {
public:
    virtual ~SimbodyArm() = default;
    virtual void inverse(const double* q, const double* qd, const double* qdd, double* tau) = 0;
    virtual void forward(const double* q, const double* qd, const double* tau, double* qdd) = 0;
    virtual void mass_matrix(const double* q, double* M) = 0;  // row by row
};
std::unique_ptr<SimbodyArm> make_simbody_arm();

}  // namespace alembert::bench
