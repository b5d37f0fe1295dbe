// SPDX-License-Identifier: MIT
// The KUKA LBR iiwa 14 R820 arm built in C++, as examples/kuka_iiwa/model.alb states it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "alembert/mech/system.hpp"
#include "models.hpp"

namespace alembert::test {

/// The arm with its loads: motor torques T1..T7 and every joint's reaction measures.
struct KukaIiwa {
    System sys{"N"};
    std::vector<TimeVariable> q;
    std::vector<RigidBody*> links;
    std::vector<ex> torques;    ///< T_i on L_i from L_{i-1} about L_i z>
    std::vector<ex> reactions;  ///< per joint F_ix, F_iy, F_iz (along L_i's axes), M_ix, M_iy
    ex g;
};

/// Masses, mass centres, central inertias, joint origins and axes from the URDF
/// RobotLocomotion/drake manipulation/models/iiwa_description/urdf/iiwa14_no_collision.urdf
/// (commit 966464ebfb524ca78d7b360bb7ef50cc3c47b818). Base iiwa_link_0 = N (z up); link i is
/// body L_i turning by q_i about the z axis of the frame J_i, whose fixed orientation in link
/// i-1 is the joint origin's rpy (a matrix of 0 and +-1); joint origin d_i along an axis of
/// link i-1; gravity -g Nz>.
inline KukaIiwa make_kuka_iiwa() {
    KukaIiwa m;
    System& sys = m.sys;
    SymbolTable& s = sys.symbols();
    struct Link {
        double mass;
        std::array<double, 3> cm, inertia;
        Axis origin_axis;
        double origin;
        int turn;  // fixed rotation of the joint origin: 0 none, 1 rpy (pi/2, 0, pi) or
                   // (-pi/2, pi, 0), 2 rpy (pi/2, 0, 0)
    };
    const std::array<Link, 7> L{{
        {5.76, {0, -0.03, 0.12}, {0.033, 0.0333, 0.0123}, Axis::z, 0.1575, 0},
        {6.35, {0.0003, 0.059, 0.042}, {0.0305, 0.0304, 0.011}, Axis::z, 0.2025, 1},
        {3.5, {0, 0.03, 0.13}, {0.025, 0.0238, 0.0076}, Axis::y, 0.2045, 1},
        {3.5, {0, 0.067, 0.034}, {0.017, 0.0164, 0.006}, Axis::z, 0.2155, 2},
        {3.5, {0.0001, 0.021, 0.076}, {0.01, 0.0087, 0.00449}, Axis::y, 0.1845, 1},
        {1.8, {0, 0.0006, 0.0004}, {0.0049, 0.0047, 0.0036}, Axis::z, 0.2155, 2},
        {1.2, {0, 0, 0.02}, {0.001, 0.001, 0.001}, Axis::y, 0.081, 1},
    }};
    // columns: J_i's axes in link i-1
    Mat3 half_turn_quarter, quarter;
    half_turn_quarter(0, 0) = -1, half_turn_quarter(1, 2) = 1, half_turn_quarter(2, 1) = 1;
    quarter(0, 0) = 1, quarter(1, 2) = -1, quarter(2, 1) = 1;
    m.g = s.add_constant("g", 9.81);
    sys.set_gravity(-m.g * sys.newtonian().z());
    const Frame* parent = &sys.newtonian();
    const Point* parent_o = &sys.origin();
    for (int i = 0; i < 7; ++i) {
        const Link& l = L[static_cast<std::size_t>(i)];
        const std::string n = std::to_string(i + 1);
        TimeVariable qi = s.add_variable("q" + n);
        RigidBody& B = sys.add_rigid_body("L" + n);
        const Frame* joint = parent;
        if (l.turn) {
            Frame& J = sys.add_frame("J" + n);
            J.orient_dcm(*parent, l.turn == 1 ? half_turn_quarter : quarter);
            joint = &J;
        }
        B.body_frame().orient_axis(*joint, Axis::z, qi);
        Point& Bo = sys.point("L" + n + "_o");
        Bo.set_pos(*parent_o, s.add_constant("d" + n, l.origin) * parent->unit(l.origin_axis));
        const Frame& F = B.body_frame();
        Vector r;
        const char* axes = "xyz";
        for (int k = 0; k < 3; ++k)
            if (l.cm[static_cast<std::size_t>(k)] != 0)
                r += s.add_constant("c" + n + axes[k], l.cm[static_cast<std::size_t>(k)]) *
                     F.unit(static_cast<Axis>(k));
        B.cm().set_pos(Bo, r);
        B.set_mass(s.add_constant("m" + n, l.mass));
        B.set_inertia(B.cm(), s.add_constant("I" + n + "x", l.inertia[0]),
                      s.add_constant("I" + n + "y", l.inertia[1]),
                      s.add_constant("I" + n + "z", l.inertia[2]));
        ex T = s.add_unknown("T" + n);
        const Body* parent_body = i ? m.links.back() : nullptr;
        sys.add_torque_pair(B, *parent, T * F.z(), "T" + n);
        std::vector<ReactionComponent> forces{{s.add_unknown("F" + n + "x"), F.x()},
                                              {s.add_unknown("F" + n + "y"), F.y()},
                                              {s.add_unknown("F" + n + "z"), F.z()}};
        std::vector<ReactionComponent> torques{{s.add_unknown("M" + n + "x"), F.x()},
                                               {s.add_unknown("M" + n + "y"), F.y()}};
        const JointReaction& jr =
            sys.add_joint_reaction("joint" + n, parent_body, B, Bo, forces, torques);
        for (const ReactionComponent& c : jr.components) m.reactions.push_back(c.measure);
        m.q.push_back(qi);
        m.links.push_back(&B);
        m.torques.push_back(T);
        parent = &F;
        parent_o = &Bo;
    }
    return m;
}

}  // namespace alembert::test
