// SPDX-License-Identifier: MIT
// Sample model: a 15-segment human on a floating base (32 degrees of freedom), de Leva's
// segment parameters.
#include "alembert/mech/ball_joint.hpp"
#include "alembert/mech/free_joint.hpp"
#include "alembert/mech/sample_models.hpp"

#include <string>

namespace alembert {

namespace {

constexpr double kBodyMass = 73.0;  // kg, de Leva's male sample (stature 1.741 m)

// One segment as de Leva (1996), Table 4 (male), gives it: length between its endpoints [m],
// mass as a fraction of the body's, mass centre as a fraction of the length from the first
// (proximal, or cranial) endpoint, and radii of gyration as fractions of the length about the
// medio-lateral (flexion), antero-posterior (abduction) and longitudinal axes.
struct Segment {
    double length, mass, cm, r_flexion, r_abduction, r_long;
};
// J. Biomechanics 29(9):1223-1230 (1996), Table 4; the lengths are the table's male means
const Segment kHead{0.2033, 0.0694, 0.5976, 0.376, 0.362, 0.312};         // VERT-MIDG
const Segment kUpperTrunk{0.1707, 0.1596, 0.2999, 0.454, 0.716, 0.659};   // SUPR-XYPH
const Segment kMiddleTrunk{0.2155, 0.1633, 0.4502, 0.383, 0.482, 0.468};  // XYPH-OMPH
const Segment kLowerTrunk{0.1457, 0.1117, 0.6115, 0.551, 0.615, 0.587};   // OMPH-MIDH
const Segment kUpperArm{0.2817, 0.0271, 0.5772, 0.269, 0.285, 0.158};     // SJC-EJC
const Segment kForearm{0.2689, 0.0162, 0.4574, 0.265, 0.276, 0.121};      // EJC-WJC
const Segment kHand{0.0862, 0.0061, 0.7900, 0.513, 0.628, 0.401};         // WJC-MET3
const Segment kThigh{0.4222, 0.1416, 0.4095, 0.329, 0.329, 0.149};        // HJC-KJC
const Segment kShank{0.4340, 0.0433, 0.4395, 0.246, 0.251, 0.102};        // KJC-AJC
const Segment kFoot{0.2581, 0.0137, 0.4415, 0.245, 0.257, 0.124};         // HEEL-TTIP

// Not in de Leva's table: the joint centres' lateral offsets and the ankle's place over the
// foot, round values for an adult male of this size.
constexpr double kHipHalfWidth = 0.085, kShoulderHalfWidth = 0.175;
constexpr double kAnkleAboveSole = 0.06, kAnkleAheadOfHeel = 0.05;

struct MassProperties {
    double m, c[3], I[3];  // mass, mass centre from the body's origin, principal central inertia
};

// a segment hanging along -z from its origin (its first endpoint), or standing along +z
MassProperties along_z(const Segment& s, double sign) {
    const double m = s.mass * kBodyMass, L = s.length;
    return {m,
            {0, 0, sign * s.cm * L},
            {m * s.r_abduction * s.r_abduction * L * L, m * s.r_flexion * s.r_flexion * L * L,
             m * s.r_long * s.r_long * L * L}};
}

class Builder {
public:
    explicit Builder(SampleModel& m) : m_(m), sys_(m.system), st_(m.system.symbols()) {}

    RigidBody& segment(const std::string& name, const MassProperties& p) {
        RigidBody& B = sys_.add_rigid_body(name);
        const Frame& F = B.body_frame();
        B.set_mass(st_.add_constant("m_" + name, p.m));
        B.cm().set_pos(sys_.point(name + "_o"), p.c[0] * F.x() + p.c[1] * F.y() + p.c[2] * F.z());
        B.set_inertia(B.cm(), st_.add_constant("I_" + name + "_x", p.I[0]),
                      st_.add_constant("I_" + name + "_y", p.I[1]),
                      st_.add_constant("I_" + name + "_z", p.I[2]));
        m_.links.push_back(&B);
        return B;
    }

    // B joined to `parent` at `at` (in the parent's frame, from its origin) by a hinge about
    // the axis `a` shared by both frames, with the motor torque T_<B> about it; its speed is
    // its angle's rate
    void hinge(RigidBody& B, RigidBody& parent, const double at[3], Axis a) {
        const Frame& from = parent.body_frame();
        TimeVariable q = st_.add_variable("q_" + B.name(), 2);
        Frame& F = B.body_frame();
        F.orient_axis(from, a, q.d(0));
        ex T = st_.add_unknown("T_" + B.name());
        const Vector axis = a == Axis::x ? F.x() : a == Axis::y ? F.y() : F.z();
        sys_.add_torque_pair(B, from, T * axis, "T_" + B.name());
        m_.q.push_back(q);
        m_.speeds.push_back(q.d(1));
        m_.coordinate_rates.push_back(q.d(1));
        m_.unknowns.push_back(T);
        locate(B, parent, at);
    }

    // B joined to `parent` at `at` by a ball joint (add_ball_joint: Euler parameters
    // e0_<B>..e3_<B>, speeds w1_<B>..w3_<B> in B's axes) with the motor torque
    // T_<B>_x Bx> + T_<B>_y By> + T_<B>_z Bz> on B from the parent: the joint's partial angular
    // velocities are B's axes, so each component is exactly the generalized force of its speed
    void ball(RigidBody& B, RigidBody& parent, const double at[3]) {
        const BallJoint j = add_ball_joint(sys_, B, parent.body_frame());
        const Frame& F = B.body_frame();
        const Vector axes[3] = {F.x(), F.y(), F.z()};
        Vector T;
        for (int i = 0; i < 3; ++i) {
            const ex T_i = st_.add_unknown("T_" + B.name() + "_" + "xyz"[i]);
            T = T + T_i * axes[i];
            m_.unknowns.push_back(T_i);
        }
        sys_.add_torque_pair(B, parent.body_frame(), T, "T_" + B.name());
        const std::vector<TimeVariable> q = j.coordinates();
        const std::vector<ex> u = j.speeds(), rates = j.coordinate_rates();
        m_.q.insert(m_.q.end(), q.begin(), q.end());
        m_.speeds.insert(m_.speeds.end(), u.begin(), u.end());
        m_.coordinate_rates.insert(m_.coordinate_rates.end(), rates.begin(), rates.end());
        locate(B, parent, at);
    }

private:
    void locate(RigidBody& B, RigidBody& parent, const double at[3]) {
        const Frame& P = parent.body_frame();
        sys_.point(B.name() + "_o").set_pos(sys_.point(parent.name() + "_o"),
                                            at[0] * P.x() + at[1] * P.y() + at[2] * P.z());
    }

    SampleModel& m_;
    System& sys_;
    SymbolTable& st_;
};

// the middle and upper trunk as one body: mass centres on the trunk's axis above the lumbar
// joint (OMPH), central inertias moved to the common mass centre (parallel axes)
MassProperties torso() {
    const MassProperties mid = along_z(kMiddleTrunk, 1), up = along_z(kUpperTrunk, 1);
    // de Leva measures the trunk's mass centres from the cranial endpoint
    const double z_mid = kMiddleTrunk.length * (1 - kMiddleTrunk.cm);
    const double z_up = kMiddleTrunk.length + kUpperTrunk.length * (1 - kUpperTrunk.cm);
    MassProperties t{mid.m + up.m, {0, 0, 0}, {0, 0, 0}};
    t.c[2] = (mid.m * z_mid + up.m * z_up) / t.m;
    const double d_mid = z_mid - t.c[2], d_up = z_up - t.c[2];
    t.I[0] = mid.I[0] + up.I[0] + mid.m * d_mid * d_mid + up.m * d_up * d_up;
    t.I[1] = mid.I[1] + up.I[1] + mid.m * d_mid * d_mid + up.m * d_up * d_up;
    t.I[2] = mid.I[2] + up.I[2];
    return t;
}

}  // namespace

SampleModel make_humanoid() {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    const ex g = st.add_constant("g", 9.81);
    Builder b(m);

    // pelvis (de Leva's lower trunk): the floating base, its origin at the mid-hip point
    MassProperties pelvis_p = along_z(kLowerTrunk, 1);
    pelvis_p.c[2] = kLowerTrunk.length * (1 - kLowerTrunk.cm);
    RigidBody& pelvis = b.segment("pelvis", pelvis_p);
    FreeJoint free = add_free_joint(sys, pelvis);
    m.q = free.coordinates();
    for (const char* f : {"F_pelvis_x", "F_pelvis_y", "F_pelvis_z"}) m.unknowns.push_back(st.add_unknown(f));
    for (const char* t : {"T_pelvis_x", "T_pelvis_y", "T_pelvis_z"}) m.unknowns.push_back(st.add_unknown(t));
    const Frame& P = pelvis.body_frame();
    sys.add_force(sys.point("pelvis_o"),
                  m.unknowns[0] * N.x() + m.unknowns[1] * N.y() + m.unknowns[2] * N.z(), "F_pelvis");
    sys.add_torque(pelvis, m.unknowns[3] * P.x() + m.unknowns[4] * P.y() + m.unknowns[5] * P.z(),
                   "T_pelvis");
    m.speeds = free.speeds();
    m.coordinate_rates = free.coordinate_rates();

    // trunk and head
    RigidBody& trunk = b.segment("torso", torso());
    const double lumbar[3] = {0, 0, kLowerTrunk.length};
    b.ball(trunk, pelvis, lumbar);
    MassProperties head_p = along_z(kHead, 1);
    head_p.c[2] = kHead.length * (1 - kHead.cm);  // from the vertex: the neck at mid-gonion
    RigidBody& head = b.segment("head", head_p);
    const double neck[3] = {0, 0, kMiddleTrunk.length + kUpperTrunk.length};
    b.ball(head, trunk, neck);

    // arms, left (+y) then right, hanging
    for (const char* side : {"l", "r"}) {
        const double y = std::string(side) == "l" ? 1 : -1;
        const std::string s = std::string("_") + side;
        RigidBody& upper = b.segment("upper_arm" + s, along_z(kUpperArm, -1));
        const double shoulder[3] = {0, y * kShoulderHalfWidth, kMiddleTrunk.length + kUpperTrunk.length};
        b.ball(upper, trunk, shoulder);
        RigidBody& fore = b.segment("forearm" + s, along_z(kForearm, -1));
        const double elbow[3] = {0, 0, -kUpperArm.length};
        b.hinge(fore, upper, elbow, Axis::y);
        RigidBody& hand = b.segment("hand" + s, along_z(kHand, -1));
        const double wrist[3] = {0, 0, -kForearm.length};
        b.hinge(hand, fore, wrist, Axis::y);
    }
    // legs
    for (const char* side : {"l", "r"}) {
        const double y = std::string(side) == "l" ? 1 : -1;
        const std::string s = std::string("_") + side;
        RigidBody& thigh = b.segment("thigh" + s, along_z(kThigh, -1));
        const double hip[3] = {0, y * kHipHalfWidth, 0};
        b.ball(thigh, pelvis, hip);
        RigidBody& shank = b.segment("shank" + s, along_z(kShank, -1));
        const double knee[3] = {0, 0, -kThigh.length};
        b.hinge(shank, thigh, knee, Axis::y);
        // the foot's long axis is x (forward): inertia about x is the longitudinal one
        const double fm = kFoot.mass * kBodyMass, L = kFoot.length;
        MassProperties foot_p{fm,
                              {kFoot.cm * L - kAnkleAheadOfHeel, 0, -kAnkleAboveSole},
                              {fm * kFoot.r_long * kFoot.r_long * L * L,
                               fm * kFoot.r_flexion * kFoot.r_flexion * L * L,
                               fm * kFoot.r_abduction * kFoot.r_abduction * L * L}};
        RigidBody& foot = b.segment("foot" + s, foot_p);
        const double ankle[3] = {0, 0, -kShank.length};
        b.hinge(foot, shank, ankle, Axis::y);
    }
    sys.set_gravity(-g * N.z());
    return m;
}

}  // namespace alembert
