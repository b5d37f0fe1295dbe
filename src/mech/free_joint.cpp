// SPDX-License-Identifier: MIT
// A free joint: Euler parameters and body-frame angular velocity.
#include "alembert/mech/free_joint.hpp"

#include "alembert/error.hpp"

namespace alembert {

std::vector<TimeVariable> FreeJoint::coordinates() const {
    std::vector<TimeVariable> q = position;
    q.insert(q.end(), quaternion.begin(), quaternion.end());
    return q;
}

std::vector<ex> FreeJoint::speeds() const {
    std::vector<ex> u;
    for (const TimeVariable& x : position) u.push_back(x.d(1));
    for (const TimeVariable& w : angular) u.push_back(w.d(0));
    return u;
}

std::vector<ex> FreeJoint::coordinate_rates() const {
    std::vector<ex> rates;
    for (const TimeVariable& x : position) rates.push_back(x.d(1));
    const ex e0 = quaternion[0].d(0), e1 = quaternion[1].d(0), e2 = quaternion[2].d(0),
             e3 = quaternion[3].d(0);
    const ex w1 = angular[0].d(0), w2 = angular[1].d(0), w3 = angular[2].d(0);
    // e' = 1/2 Q(e) w, w in body axes
    rates.push_back(ex(-1) / 2 * (e1 * w1 + e2 * w2 + e3 * w3));
    rates.push_back(ex(1) / 2 * (e0 * w1 + e2 * w3 - e3 * w2));
    rates.push_back(ex(1) / 2 * (e0 * w2 + e3 * w1 - e1 * w3));
    rates.push_back(ex(1) / 2 * (e0 * w3 + e1 * w2 - e2 * w1));
    return rates;
}

FreeJoint add_free_joint(System& sys, RigidBody& B) {
    SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    Frame& F = B.body_frame();
    if (F.parent())
        throw ModelError("add_free_joint(): the frame of '" + B.name() + "' is already oriented " +
                         "in '" + F.parent()->name() + "'; a free joint orients it in " + N.name());
    FreeJoint j;
    const std::string& b = B.name();
    for (const char* x : {"x_", "y_", "z_"}) j.position.push_back(st.add_variable(x + b, 2));
    for (const char* e : {"e0_", "e1_", "e2_", "e3_"}) j.quaternion.push_back(st.add_variable(e + b, 2));
    for (const char* w : {"w1_", "w2_", "w3_"}) j.angular.push_back(st.add_variable(w + b, 1));
    const ex e0 = j.quaternion[0].d(0), e1 = j.quaternion[1].d(0), e2 = j.quaternion[2].d(0),
             e3 = j.quaternion[3].d(0);
    // R_NB = (e0^2 - ev.ev) I + 2 ev ev^T + 2 e0 [ev]x
    Mat3 R;
    R(0, 0) = e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3;
    R(1, 1) = e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3;
    R(2, 2) = e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
    R(0, 1) = 2 * (e1 * e2 - e0 * e3), R(1, 0) = 2 * (e1 * e2 + e0 * e3);
    R(0, 2) = 2 * (e1 * e3 + e0 * e2), R(2, 0) = 2 * (e1 * e3 - e0 * e2);
    R(1, 2) = 2 * (e2 * e3 - e0 * e1), R(2, 1) = 2 * (e2 * e3 + e0 * e1);
    F.orient_dcm(N, R);
    F.set_ang_vel(N, j.angular[0].d(0) * F.x() + j.angular[1].d(0) * F.y() +
                         j.angular[2].d(0) * F.z());
    sys.point(b + "_o").set_pos(sys.origin(), j.position[0].d(0) * N.x() +
                                                  j.position[1].d(0) * N.y() +
                                                  j.position[2].d(0) * N.z());
    return j;
}

}  // namespace alembert
