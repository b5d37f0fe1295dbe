// SPDX-License-Identifier: MIT
// Sample model: the KUKA LBR iiwa 14, a 7-joint spatial arm, from its public URDF.
#include "alembert/mech/sample_models.hpp"

namespace alembert {

namespace {

// one joint and the link it moves, as the URDF states them: the joint origin in the parent
// link's frame (xyz, and rpy: R = Rz(yaw) Ry(pitch) Rx(roll), in multiples of pi/2), the
// link's mass, mass centre and principal central inertia in its own frame
struct IiwaLink {
    double xyz[3];
    int rpy_quarters[3];  // roll, pitch, yaw in quarter turns
    double mass;
    double com[3];
    double inertia[3];  // Ixx, Iyy, Izz
};

// RobotLocomotion/drake, manipulation/models/iiwa_description/urdf/iiwa14_no_collision.urdf
const IiwaLink kIiwa14[7] = {
    {{0, 0, 0.1575}, {0, 0, 0}, 5.76, {0, -0.03, 0.12}, {0.033, 0.0333, 0.0123}},
    {{0, 0, 0.2025}, {1, 0, 2}, 6.35, {0.0003, 0.059, 0.042}, {0.0305, 0.0304, 0.011}},
    {{0, 0.2045, 0}, {1, 0, 2}, 3.5, {0, 0.03, 0.13}, {0.025, 0.0238, 0.0076}},
    {{0, 0, 0.2155}, {1, 0, 0}, 3.5, {0, 0.067, 0.034}, {0.017, 0.0164, 0.006}},
    {{0, 0.1845, 0}, {-1, 2, 0}, 3.5, {0.0001, 0.021, 0.076}, {0.01, 0.0087, 0.00449}},
    {{0, 0, 0.2155}, {1, 0, 0}, 1.8, {0, 0.0006, 0.0004}, {0.0049, 0.0047, 0.0036}},
    {{0, 0.081, 0}, {-1, 2, 0}, 1.2, {0, 0, 0.02}, {0.001, 0.001, 0.001}},
};

}  // namespace

SampleModel make_kuka_iiwa14() {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex g = s.add_constant("g", 9.81);
    const Frame* parent = &N;  // link 0, the base, is fixed in N
    const Point* parent_origin = &sys.origin();
    for (int i = 1; i <= 7; ++i) {
        const IiwaLink& d = kIiwa14[i - 1];
        const std::string k = std::to_string(i);
        // the joint frame J_i, fixed in the parent link, then the link turning about J_iz
        Frame& J = sys.add_frame("J" + k);
        J.orient_body_fixed(*parent, RotationSequence::ZYX, d.rpy_quarters[2] * GiNaC::Pi / 2,
                            d.rpy_quarters[1] * GiNaC::Pi / 2, d.rpy_quarters[0] * GiNaC::Pi / 2);
        TimeVariable q = s.add_variable("q" + k, 2);
        RigidBody& B = sys.add_rigid_body("B" + k);
        Frame& F = B.body_frame();
        F.orient_axis(J, Axis::z, q);
        Point& Bo = sys.point("B" + k + "_o");
        Bo.set_pos(*parent_origin,
                   d.xyz[0] * parent->x() + d.xyz[1] * parent->y() + d.xyz[2] * parent->z());
        ex mass = s.add_constant("m" + k, d.mass);
        B.set_mass(mass);
        B.cm().set_pos(Bo, d.com[0] * F.x() + d.com[1] * F.y() + d.com[2] * F.z());
        B.set_inertia(B.cm(), d.inertia[0], d.inertia[1], d.inertia[2]);
        ex T = s.add_unknown("T" + k);
        sys.add_torque_pair(B, *parent, T * F.z(), "T" + k);
        m.q.push_back(q);
        m.unknowns.push_back(T);
        m.links.push_back(&B);
        parent = &F;
        parent_origin = &Bo;
    }
    sys.set_gravity(-g * N.z());
    return m;
}

}  // namespace alembert
