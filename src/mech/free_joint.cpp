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
    std::vector<ex> rates, e, w;
    for (const TimeVariable& x : position) rates.push_back(x.d(1));
    for (const TimeVariable& x : quaternion) e.push_back(x.d(0));
    for (const TimeVariable& x : angular) w.push_back(x.d(0));
    const std::vector<ex> e_dot = euler_parameter_rates(e, w);
    rates.insert(rates.end(), e_dot.begin(), e_dot.end());
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
    // the orientation and angular velocity in N: a ball joint to N
    const BallJoint ball = add_ball_joint(sys, B, N);
    j.quaternion = ball.quaternion;
    j.angular = ball.angular;
    sys.point(b + "_o").set_pos(sys.origin(), j.position[0].d(0) * N.x() +
                                                  j.position[1].d(0) * N.y() +
                                                  j.position[2].d(0) * N.z());
    return j;
}

}  // namespace alembert
