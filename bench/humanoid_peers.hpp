// SPDX-License-Identifier: MIT
// The humanoid of make_humanoid() as the peers of spatial_peers_bench build it (its numbers
// read from Alembert's model), and the Simbody peer's interface (compiled apart: Simbody 3.7's
// headers need C++17).
#pragma once

#include <memory>
#include <vector>

namespace alembert::bench {

constexpr int kHumanoidDofs = 32;
// the free joint's position and unit quaternion, a unit quaternion per ball joint, 8 angles
constexpr int kHumanoidCoordinates = 39;

/// One segment of the humanoid and the joint to its parent, every frame parallel to its
/// parent's at zero angles.
struct HumanoidSegment {
    int parent = -1;  ///< index of the parent segment (-1: the ground)
    int dofs = 0;     ///< 6: free; 3: ball (speeds: angular velocity in the segment's axes);
                      ///< 1: hinge about y
    int speed = 0;    ///< the joint's first speed among the generated code's 32
    double at[3] = {0, 0, 0};  ///< the joint centre from the parent's origin, parent axes
    double mass = 0;
    double com[3] = {0, 0, 0};      ///< mass centre from the segment's origin (its joint centre)
    double inertia[3] = {0, 0, 0};  ///< principal central moments about the segment's axes
};

/// The humanoid in Simbody, in its own coordinates: a Free mobilizer for the pelvis (q: unit
/// quaternion w, x, y, z then position; u: angular velocity and velocity of the origin, both
/// in ground axes), Ball mobilizers for the balls (q: unit quaternion w, x, y, z of the
/// segment in its parent; u: its angular velocity in the parent, parent axes) and Pin
/// mobilizers about y for the hinges; uniform gravity -9.81 z. Every call sets q (and u), so
/// every stage is realized again.
class SimbodyHumanoid {
public:
    virtual ~SimbodyHumanoid() = default;
    virtual void inverse(const double* q, const double* u, const double* udot, double* tau) = 0;
    virtual void forward(const double* q, const double* u, const double* tau, double* udot) = 0;
    virtual void mass_matrix(const double* q, double* M) = 0;  // row by row
};
std::unique_ptr<SimbodyHumanoid> make_simbody_humanoid(const std::vector<HumanoidSegment>& segments);

}  // namespace alembert::bench
