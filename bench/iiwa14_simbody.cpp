// SPDX-License-Identifier: MIT
// The iiwa 14 arm in Simbody, for spatial_peers_bench (compiled as C++17: Simbody 3.7's
// headers do not compile as C++20).
#include <Simbody.h>

#include "iiwa14_peers.hpp"

namespace alembert::bench {

namespace {

class SimbodyArmImpl final : public SimbodyArm {
public:
    SimbodyArmImpl()
        : matter_(system_), forces_(system_),
          gravity_(forces_, matter_, SimTK::Vec3(0, 0, -9.81)) {
        SimTK::MobilizedBody parent = matter_.Ground();
        for (const Link& l : kArm) {
            const SimTK::Vec3 com(l.com[0], l.com[1], l.com[2]);
            const SimTK::Inertia central(l.inertia[0], l.inertia[1], l.inertia[2]);
            SimTK::Body::Rigid body(
                SimTK::MassProperties(l.mass, com, central.shiftFromMassCenter(com, l.mass)));
            const SimTK::Rotation R(SimTK::BodyRotationSequence, l.rpy[2], SimTK::ZAxis,
                                    l.rpy[1], SimTK::YAxis, l.rpy[0], SimTK::XAxis);
            parent = SimTK::MobilizedBody::Pin(parent, SimTK::Transform(R, SimTK::Vec3(
                                                          l.xyz[0], l.xyz[1], l.xyz[2])),
                                               body, SimTK::Transform());
        }
        system_.realizeTopology();
        state_ = system_.getDefaultState();
        udot_.resize(kArmJoints);
        tau_.resize(kArmJoints);
    }
    void inverse(const double* q, const double* qd, const double* qdd, double* tau) override {
        set(q, qd);
        system_.realize(state_, SimTK::Stage::Dynamics);
        for (int i = 0; i < kArmJoints; ++i) udot_[i] = qdd[i];
        matter_.calcResidualForceIgnoringConstraints(
            state_, system_.getMobilityForces(state_, SimTK::Stage::Dynamics),
            system_.getRigidBodyForces(state_, SimTK::Stage::Dynamics), udot_, out_);
        for (int i = 0; i < kArmJoints; ++i) tau[i] = out_[i];
    }
    void forward(const double* q, const double* qd, const double* tau, double* qdd) override {
        set(q, qd);
        system_.realize(state_, SimTK::Stage::Dynamics);
        for (int i = 0; i < kArmJoints; ++i) tau_[i] = tau[i];
        applied_ = system_.getMobilityForces(state_, SimTK::Stage::Dynamics) + tau_;
        matter_.calcAccelerationIgnoringConstraints(
            state_, applied_, system_.getRigidBodyForces(state_, SimTK::Stage::Dynamics),
            out_, A_GB_);
        for (int i = 0; i < kArmJoints; ++i) qdd[i] = out_[i];
    }
    void mass_matrix(const double* q, double* M) override {
        for (int i = 0; i < kArmJoints; ++i) state_.updQ()[i] = q[i];
        system_.realize(state_, SimTK::Stage::Position);
        matter_.calcM(state_, M_);
        for (int i = 0; i < kArmJoints; ++i)
            for (int j = 0; j < kArmJoints; ++j) M[i * kArmJoints + j] = M_(i, j);
    }

private:
    void set(const double* q, const double* u) {
        for (int i = 0; i < kArmJoints; ++i) state_.updQ()[i] = q[i], state_.updU()[i] = u[i];
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

std::unique_ptr<SimbodyArm> make_simbody_arm() { return std::make_unique<SimbodyArmImpl>(); }

}  // namespace alembert::bench
