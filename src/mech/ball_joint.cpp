// SPDX-License-Identifier: MIT
// A ball joint: Euler parameters and body-frame angular velocity relative to the parent.
#include "alembert/mech/ball_joint.hpp"

#include "alembert/error.hpp"

namespace alembert {

Mat3 euler_parameter_rotation(const ex& e0, const ex& e1, const ex& e2, const ex& e3) {
    // R_PB = (e0^2 - ev.ev) I + 2 ev ev^T + 2 e0 [ev]x
    Mat3 R;
    R(0, 0) = e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3;
    R(1, 1) = e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3;
    R(2, 2) = e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
    R(0, 1) = 2 * (e1 * e2 - e0 * e3), R(1, 0) = 2 * (e1 * e2 + e0 * e3);
    R(0, 2) = 2 * (e1 * e3 + e0 * e2), R(2, 0) = 2 * (e1 * e3 - e0 * e2);
    R(1, 2) = 2 * (e2 * e3 - e0 * e1), R(2, 1) = 2 * (e2 * e3 + e0 * e1);
    return R;
}

std::vector<ex> euler_parameter_rates(const std::vector<ex>& e, const std::vector<ex>& w) {
    if (e.size() != 4 || w.size() != 3)
        throw ArgumentError("euler_parameter_rates(): got " + std::to_string(e.size()) +
                            " Euler parameters and " + std::to_string(w.size()) +
                            " angular velocity measures; pass e0..e3 and w1..w3");
    // e' = 1/2 Q(e) w, w in body axes
    return {ex(-1) / 2 * (e[1] * w[0] + e[2] * w[1] + e[3] * w[2]),
            ex(1) / 2 * (e[0] * w[0] + e[2] * w[2] - e[3] * w[1]),
            ex(1) / 2 * (e[0] * w[1] + e[3] * w[0] - e[1] * w[2]),
            ex(1) / 2 * (e[0] * w[2] + e[1] * w[1] - e[2] * w[0])};
}

std::vector<TimeVariable> BallJoint::coordinates() const { return quaternion; }

std::vector<ex> BallJoint::speeds() const {
    std::vector<ex> u;
    for (const TimeVariable& w : angular) u.push_back(w.d(0));
    return u;
}

std::vector<ex> BallJoint::coordinate_rates() const {
    std::vector<ex> e;
    for (const TimeVariable& x : quaternion) e.push_back(x.d(0));
    return euler_parameter_rates(e, speeds());
}

BallJoint add_ball_joint(System& sys, RigidBody& B, const Frame& parent) {
    SymbolTable& st = sys.symbols();
    Frame& F = B.body_frame();
    if (F.parent())
        throw ModelError("add_ball_joint(): the frame of '" + B.name() + "' is already oriented " +
                         "in '" + F.parent()->name() + "'; a ball joint orients it in '" +
                         parent.name() + "'");
    if (&parent == &F)
        throw ModelError("add_ball_joint(): '" + B.name() + "' cannot be joined to its own " +
                         "frame; pass the frame of the body it hangs from (or N)");
    BallJoint j;
    const std::string& b = B.name();
    for (const char* e : {"e0_", "e1_", "e2_", "e3_"})
        j.quaternion.push_back(st.add_variable(e + b, 2));
    for (const char* w : {"w1_", "w2_", "w3_"}) j.angular.push_back(st.add_variable(w + b, 1));
    // R_PB by the Euler parameters, ^P w^B in B's axes
    F.orient_dcm(parent, euler_parameter_rotation(j.quaternion[0].d(0), j.quaternion[1].d(0),
                                                  j.quaternion[2].d(0), j.quaternion[3].d(0)));
    F.set_ang_vel(
        parent, j.angular[0].d(0) * F.x() + j.angular[1].d(0) * F.y() + j.angular[2].d(0) * F.z());
    return j;
}

}  // namespace alembert
