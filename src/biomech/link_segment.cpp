// SPDX-License-Identifier: MIT
// Planar link-segment inverse dynamics, bottom-up, and plate loads in the plane.
#include "alembert/biomech/link_segment.hpp"

#include <cmath>
#include <numbers>

#include "alembert/error.hpp"
#include "alembert/sim/filter.hpp"

namespace alembert {

namespace {

double cross(double ah, double av, double bh, double bv) { return ah * bv - av * bh; }

// each segment's kinematics: G, its acceleration, the angle of D->P and its derivatives
struct SegmentKinematics {
    std::vector<double> g_h, g_v, a_h, a_v, omega, alpha;
};

std::vector<SegmentKinematics> calc_kinematics(const std::vector<ChainSegment>& chain, double dt) {
    const std::size_t n = chain.front().p_h.size();
    std::vector<SegmentKinematics> kin;
    for (const auto& s : chain) {
        SegmentKinematics k;
        std::vector<double> theta(n);
        for (std::size_t i = 0; i < n; ++i) {
            k.g_h.push_back(s.p_h[i] + s.com_fraction * (s.d_h[i] - s.p_h[i]));
            k.g_v.push_back(s.p_v[i] + s.com_fraction * (s.d_v[i] - s.p_v[i]));
            theta[i] = std::atan2(s.p_v[i] - s.d_v[i], s.p_h[i] - s.d_h[i]);
            if (i) theta[i] -= 2 * std::numbers::pi * std::round((theta[i] - theta[i - 1]) / (2 * std::numbers::pi));
        }
        k.a_h = differentiate_twice(k.g_h, dt);
        k.a_v = differentiate_twice(k.g_v, dt);
        k.omega = differentiate(theta, dt);
        k.alpha = differentiate_twice(theta, dt);
        kin.push_back(std::move(k));
    }
    return kin;
}

// the chain's samples agree in number, and the load's too
void check_chain(const std::vector<ChainSegment>& chain, const PlanarLoad* load, const char* caller) {
    if (chain.empty()) throw ArgumentError(std::string(caller) + ": the chain has no segments");
    const std::size_t n = chain.front().p_h.size();
    for (const auto& s : chain)
        if (s.p_h.size() != n || s.p_v.size() != n || s.d_h.size() != n || s.d_v.size() != n)
            throw ArgumentError(std::string(caller) + ": segment '" + s.name +
                                "' has joint positions of another number of samples than '" +
                                chain.front().name + "' (" + std::to_string(n) + "); give every segment the same samples");
    if (n < 4)
        throw ArgumentError(std::string(caller) + ": " + std::to_string(n) + " samples; accelerations need at least 4");
    if (load && load->F_h.size() != n)
        throw ArgumentError(std::string(caller) + ": the external load has " + std::to_string(load->F_h.size()) +
                            " samples, the segments " + std::to_string(n) + "; resample the plate to the markers' times");
}

}  // namespace

PlanarLoad planar_load_from_plate(const ForcePlate& plate, SagittalPlane plane) {
    const int h = plane.horizontal, v = plane.vertical, z = 3 - h - v;
    // the free moment about h x v: +T_z when (h, v, z) is in cyclic order
    const double sign = ((v - h + 3) % 3 == 1) ? 1.0 : -1.0;
    PlanarLoad load;
    for (std::size_t k = 0; k < plate.t.size(); ++k) {
        const bool on = plate.in_contact(k);
        load.F_h.push_back(on ? plate.F[h][k] : 0.0);
        load.F_v.push_back(on ? plate.F[v][k] : 0.0);
        load.p_h.push_back(on ? plate.p_CoP[h][k] : 0.0);
        load.p_v.push_back(on ? plate.p_CoP[v][k] : 0.0);
        load.M.push_back(on ? sign * plate.T_free[z][k] : 0.0);
    }
    return load;
}

PlanarLoad combine_loads(const std::vector<PlanarLoad>& loads) {
    PlanarLoad sum;
    if (loads.empty()) return sum;
    const std::size_t n = loads.front().F_h.size();
    for (const auto& l : loads)
        if (l.F_h.size() != n)
            throw ArgumentError("combine_loads(): loads of " + std::to_string(n) + " and " +
                                std::to_string(l.F_h.size()) + " samples; resample the plates to one time base");
    for (std::size_t k = 0; k < n; ++k) {
        double Fh = 0, Fv = 0, M_O = 0;
        // total force and moment about the origin
        for (const auto& l : loads) {
            Fh += l.F_h[k], Fv += l.F_v[k];
            M_O += l.M[k] + cross(l.p_h[k], l.p_v[k], l.F_h[k], l.F_v[k]);
        }
        // a point on the line of action at the height of the first plate's surface
        double ph = 0, pv = loads.front().p_v[k];
        if (Fv != 0) ph = (M_O + pv * Fh) / Fv;  // M_O = ph Fv - pv Fh when the moment is all force
        const double M = M_O - cross(ph, pv, Fh, Fv);
        sum.F_h.push_back(Fh), sum.F_v.push_back(Fv), sum.p_h.push_back(ph), sum.p_v.push_back(pv);
        sum.M.push_back(M);
    }
    return sum;
}

std::vector<JointLoads> calc_inverse_dynamics_bottom_up(const std::vector<ChainSegment>& chain,
                                                        double dt, const PlanarLoad* external,
                                                        double gravity) {
    check_chain(chain, external, "calc_inverse_dynamics_bottom_up()");
    const std::size_t n = chain.front().p_h.size();
    const std::vector<SegmentKinematics> kin = calc_kinematics(chain, dt);

    // segment by segment from the distal end
    std::vector<JointLoads> joints;
    for (std::size_t j = 0; j < chain.size(); ++j) {
        const ChainSegment& s = chain[j];
        const SegmentKinematics& k = kin[j];
        JointLoads out;
        out.joint = s.proximal_joint;
        for (std::size_t i = 0; i < n; ++i) {
            // the load at the distal end: external, or the reaction of the joint below
            double FD_h = 0, FD_v = 0, MD = 0, rD_h = s.d_h[i], rD_v = s.d_v[i];
            if (j == 0) {
                if (external) {
                    FD_h = external->F_h[i], FD_v = external->F_v[i], MD = external->M[i];
                    rD_h = external->p_h[i], rD_v = external->p_v[i];
                }
            } else {
                FD_h = -joints[j - 1].F_h[i], FD_v = -joints[j - 1].F_v[i], MD = -joints[j - 1].M[i];
            }
            // Newton: F_P = m a_G - m g - F_D
            const double FP_h = s.mass * k.a_h[i] - FD_h;
            const double FP_v = s.mass * k.a_v[i] + s.mass * gravity - FD_v;
            // Euler about G: M_P = I alpha - M_D - (r_D - r_G) x F_D - (r_P - r_G) x F_P
            const double MP = s.inertia * k.alpha[i] - MD -
                              cross(rD_h - k.g_h[i], rD_v - k.g_v[i], FD_h, FD_v) -
                              cross(s.p_h[i] - k.g_h[i], s.p_v[i] - k.g_v[i], FP_h, FP_v);
            out.F_h.push_back(FP_h), out.F_v.push_back(FP_v), out.M.push_back(MP);
        }
        joints.push_back(std::move(out));
    }
    // powers of the joints between two segments of the chain
    for (std::size_t j = 0; j + 1 < chain.size(); ++j)
        for (std::size_t i = 0; i < n; ++i)
            joints[j].power.push_back(joints[j].M[i] * (kin[j].omega[i] - kin[j + 1].omega[i]));
    return joints;
}

std::vector<JointLoads> calc_inverse_dynamics_top_down(const std::vector<ChainSegment>& chain,
                                                       double dt, const PlanarLoad* top,
                                                       double gravity) {
    check_chain(chain, top, "calc_inverse_dynamics_top_down()");
    const std::size_t n = chain.front().p_h.size();
    const std::vector<SegmentKinematics> kin = calc_kinematics(chain, dt);
    // joints[j]: the load on segment j at its proximal joint; joints[size]: at the ground
    std::vector<JointLoads> joints(chain.size() + 1);
    for (std::size_t j = 0; j < chain.size(); ++j) joints[j].joint = chain[j].proximal_joint;
    joints.back().joint = "ground";
    for (std::size_t i = 0; i < n; ++i) {
        // the load on the top segment at its proximal joint
        double FP_h = top ? top->F_h[i] : 0.0, FP_v = top ? top->F_v[i] : 0.0, MP = top ? top->M[i] : 0.0;
        // segment by segment from the proximal end
        for (std::size_t jj = chain.size(); jj-- > 0;) {
            const ChainSegment& s = chain[jj];
            const SegmentKinematics& k = kin[jj];
            joints[jj].F_h.push_back(FP_h), joints[jj].F_v.push_back(FP_v), joints[jj].M.push_back(MP);
            // Newton: F_D = m a_G - m g - F_P
            const double FD_h = s.mass * k.a_h[i] - FP_h;
            const double FD_v = s.mass * k.a_v[i] + s.mass * gravity - FP_v;
            // Euler about G: M_D = I alpha - M_P - (r_P - r_G) x F_P - (r_D - r_G) x F_D
            const double MD = s.inertia * k.alpha[i] - MP -
                              cross(s.p_h[i] - k.g_h[i], s.p_v[i] - k.g_v[i], FP_h, FP_v) -
                              cross(s.d_h[i] - k.g_h[i], s.d_v[i] - k.g_v[i], FD_h, FD_v);
            if (jj == 0) {
                joints.back().F_h.push_back(FD_h), joints.back().F_v.push_back(FD_v), joints.back().M.push_back(MD);
            } else {
                FP_h = -FD_h, FP_v = -FD_v, MP = -MD;
            }
        }
    }
    // powers of the joints between two segments of the chain
    for (std::size_t j = 0; j + 1 < chain.size(); ++j)
        for (std::size_t i = 0; i < n; ++i)
            joints[j].power.push_back(joints[j].M[i] * (kin[j].omega[i] - kin[j + 1].omega[i]));
    return joints;
}

JointLoads calc_top_down_residual(const std::vector<JointLoads>& top_down,
                                  const ChainSegment& distal_segment, const PlanarLoad* measured) {
    const JointLoads& ground = top_down.back();
    const std::size_t n = ground.F_h.size();
    if (distal_segment.d_h.size() != n || (measured && measured->F_h.size() != n))
        throw ArgumentError("calc_top_down_residual(): the top-down solution has " + std::to_string(n) +
                            " samples, the segment or the measured load another number; use the same samples");
    JointLoads r;
    r.joint = "residual";
    for (std::size_t i = 0; i < n; ++i) {
        double Fh = 0, Fv = 0, M = 0;
        if (measured) {
            // the measured load moved to the segment's distal point D
            Fh = measured->F_h[i], Fv = measured->F_v[i];
            M = measured->M[i] + cross(measured->p_h[i] - distal_segment.d_h[i],
                                       measured->p_v[i] - distal_segment.d_v[i], Fh, Fv);
        }
        r.F_h.push_back(ground.F_h[i] - Fh), r.F_v.push_back(ground.F_v[i] - Fv), r.M.push_back(ground.M[i] - M);
    }
    return r;
}

void normalize_by_body_mass(std::vector<JointLoads>& loads, double body_mass) {
    if (!(body_mass > 0))
        throw ArgumentError("normalize_by_body_mass(): body mass " + std::to_string(body_mass) +
                            " kg; it must be positive");
    for (auto& j : loads)
        for (auto* v : {&j.F_h, &j.F_v, &j.M, &j.power})
            for (double& x : *v) x /= body_mass;
}

}  // namespace alembert
