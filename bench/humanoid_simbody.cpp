// SPDX-License-Identifier: MIT
// The humanoid in Simbody, for spatial_peers_bench (compiled as C++17: Simbody 3.7's headers
// do not compile as C++20).
#include <Simbody.h>

#include "humanoid_peers.hpp"

namespace alembert::bench {

namespace {

constexpr int kQ = kHumanoidCoordinates, kU = kHumanoidDofs;

class SimbodyHumanoidImpl final : public SimbodyHumanoid {
public:
    explicit SimbodyHumanoidImpl(const std::vector<HumanoidSegment>& segments)
        : matter_(system_), forces_(system_),
          gravity_(forces_, matter_, SimTK::Vec3(0, 0, -9.81)) {
        // a pin turns about z of its frames: turned so that z is the parent's y
        const SimTK::Rotation z_to_y(-SimTK::Pi / 2, SimTK::XAxis);
        std::vector<SimTK::MobilizedBody> made;
        for (const HumanoidSegment& s : segments) {
            const SimTK::Vec3 com(s.com[0], s.com[1], s.com[2]);
            const SimTK::Inertia central(s.inertia[0], s.inertia[1], s.inertia[2]);
            SimTK::Body::Rigid body(
                SimTK::MassProperties(s.mass, com, central.shiftFromMassCenter(com, s.mass)));
            SimTK::MobilizedBody parent =
                s.parent < 0 ? SimTK::MobilizedBody(matter_.Ground()) : made[s.parent];
            const SimTK::Vec3 at(s.at[0], s.at[1], s.at[2]);
            if (s.dofs == 6)
                made.push_back(SimTK::MobilizedBody::Free(parent, SimTK::Transform(at), body,
                                                          SimTK::Transform()));
            else if (s.dofs == 3)
                made.push_back(SimTK::MobilizedBody::Ball(parent, SimTK::Transform(at), body,
                                                          SimTK::Transform()));
            else
                made.push_back(SimTK::MobilizedBody::Pin(parent, SimTK::Transform(z_to_y, at), body,
                                                         SimTK::Transform(z_to_y)));
        }
        system_.realizeTopology();
        state_ = system_.getDefaultState();
        udot_.resize(kU);
        tau_.resize(kU);
    }
    void inverse(const double* q, const double* u, const double* udot, double* tau) override {
        set(q, u);
        system_.realize(state_, SimTK::Stage::Dynamics);
        for (int i = 0; i < kU; ++i) udot_[i] = udot[i];
        matter_.calcResidualForceIgnoringConstraints(
            state_, system_.getMobilityForces(state_, SimTK::Stage::Dynamics),
            system_.getRigidBodyForces(state_, SimTK::Stage::Dynamics), udot_, out_);
        for (int i = 0; i < kU; ++i) tau[i] = out_[i];
    }
    void forward(const double* q, const double* u, const double* tau, double* udot) override {
        set(q, u);
        system_.realize(state_, SimTK::Stage::Dynamics);
        for (int i = 0; i < kU; ++i) tau_[i] = tau[i];
        applied_ = system_.getMobilityForces(state_, SimTK::Stage::Dynamics) + tau_;
        matter_.calcAccelerationIgnoringConstraints(
            state_, applied_, system_.getRigidBodyForces(state_, SimTK::Stage::Dynamics),
            out_, A_GB_);
        for (int i = 0; i < kU; ++i) udot[i] = out_[i];
    }
    void mass_matrix(const double* q, double* M) override {
        for (int i = 0; i < kQ; ++i) state_.updQ()[i] = q[i];
        system_.realize(state_, SimTK::Stage::Position);
        matter_.calcM(state_, M_);
        for (int i = 0; i < kU; ++i)
            for (int j = 0; j < kU; ++j) M[i * kU + j] = M_(i, j);
    }

private:
    void set(const double* q, const double* u) {
        for (int i = 0; i < kQ; ++i) state_.updQ()[i] = q[i];
        for (int i = 0; i < kU; ++i) state_.updU()[i] = u[i];
    }
    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_;
    SimTK::GeneralForceSubsystem forces_;
    SimTK::Force::UniformGravity gravity_;
    SimTK::State state_;
    SimTK::Vector udot_, tau_, out_, applied_;
    SimTK::Vector_<SimTK::SpatialVec> A_GB_;
    SimTK::Matrix M_;
};

}  // namespace

std::unique_ptr<SimbodyHumanoid> make_simbody_humanoid(const std::vector<HumanoidSegment>& segments) {
    return std::make_unique<SimbodyHumanoidImpl>(segments);
}

}  // namespace alembert::bench
