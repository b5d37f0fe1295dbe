// SPDX-License-Identifier: MIT
// A hand-specialised O(n) dynamics of the benchmark planar chain: the reference beside ours.
#pragma once

#include <cmath>
#include <vector>

namespace alembert::bench {

/// Inverse and forward dynamics of exactly the planar chain of `make_planar_chain(n)` and of
/// the dynamics benchmarks, written by hand for that model only: n uniform rods (L = 1 m,
/// m = 1 kg, mass centre at L/2, central inertia 1/12 kg m^2), relative angles q_i about z,
/// q = 0 all links upright along +y, gravity 9.81 m/s^2 along -y, joint torque tau_i on link i
/// from link i-1 (the ground for i = 1).
///
/// Both algorithms work in the world frame at the joint points, with the absolute angle
/// theta_i = q_1 + ... + q_i (one sin/cos per joint) and the link direction
/// e_i = (-sin theta_i, cos theta_i). Gravity enters as an upward acceleration g of the base
/// (Featherstone 2008, sec. 5.3). Planar cross products are scalars, a x b = a_x b_y - a_y b_x,
/// and w x (w x r) = -w^2 r.
///
/// Allocation happens in the constructor only; one object serves one thread at a time.
class PlanarChainReference {
public:
    static constexpr double kLength = 1.0;
    static constexpr double kMass = 1.0;
    static constexpr double kHalf = 0.5;               // joint to mass centre
    static constexpr double kInertia = 1.0 / 12.0;     // about the mass centre
    static constexpr double kGravity = 9.81;

    explicit PlanarChainReference(int n) : n_(n), link_(static_cast<std::size_t>(n)) {}

    /// Number of links.
    int size() const { return n_; }

    /// Recursive Newton-Euler inverse dynamics (Luh, Walker & Paul 1980), world frame:
    ///   outward:  w_i = w_{i-1} + q_i',  alpha_i = alpha_{i-1} + q_i'',
    ///             a_Ci = a_Pi + alpha_i x (h e_i) - w_i^2 h e_i,
    ///             a_P(i+1) = a_Pi + alpha_i x (L e_i) - w_i^2 L e_i,  a_P1 = (0, g);
    ///   inward:   tau_i = I alpha_i + h e_i x m a_Ci + L e_i x f_(i+1) + tau_(i+1),
    ///             f_i = m a_Ci + f_(i+1)  (force on link i from link i-1).
    void inverse_dynamics(const double* q, const double* qd, const double* qdd, double* tau) {
        double theta = 0, w = 0, alpha = 0, ax = 0, ay = kGravity;
        for (int i = 0; i < n_; ++i) {
            Link& k = link_[static_cast<std::size_t>(i)];
            theta += q[i];
            w += qd[i];
            alpha += qdd[i];
            const double ex = -std::sin(theta), ey = std::cos(theta), w2 = w * w;
            // tangential and centripetal acceleration per unit length along the link
            const double tx = -alpha * ey - w2 * ex, ty = alpha * ex - w2 * ey;
            k.ex = ex, k.ey = ey, k.alpha = alpha;
            k.acx = ax + kHalf * tx, k.acy = ay + kHalf * ty;
            ax += kLength * tx, ay += kLength * ty;
        }
        double fx = 0, fy = 0, moment = 0;
        for (int i = n_ - 1; i >= 0; --i) {
            const Link& k = link_[static_cast<std::size_t>(i)];
            const double mx = kMass * k.acx, my = kMass * k.acy;
            moment += kInertia * k.alpha + kHalf * (k.ex * my - k.ey * mx) +
                      kLength * (k.ex * fy - k.ey * fx);
            fx += mx, fy += my;
            tau[i] = moment;
        }
    }

    /// Articulated-body forward dynamics (Featherstone 2008, ch. 7) in planar form: motion
    /// (alpha, a_P) and force (moment about P, force) 3-vectors at each link's joint point P
    /// in world axes, with classical accelerations, so a link's bias force is the centripetal
    /// (0, -m w^2 h e) and a joint adds kappa_i = (0, -w_(i-1)^2 L e_(i-1)); the joint axis is
    /// S = (1, 0, 0), so U_i is the first column of the articulated inertia, D_i its corner and
    /// the articulated inertia passed to the parent has a zero first row and column.
    void forward_dynamics(const double* q, const double* qd, const double* tau, double* qdd) {
        // outward: directions, velocities, rigid inertias and bias forces at the joints
        double theta = 0, w = 0, kx = 0, ky = 0;
        for (int i = 0; i < n_; ++i) {
            Link& k = link_[static_cast<std::size_t>(i)];
            theta += q[i];
            k.kx = kx, k.ky = ky;
            w += qd[i];
            const double ex = -std::sin(theta), ey = std::cos(theta), w2 = w * w;
            k.ex = ex, k.ey = ey;
            k.i00 = kInertia + kMass * kHalf * kHalf;
            k.i01 = -kMass * kHalf * ey, k.i02 = kMass * kHalf * ex;
            k.i11 = kMass, k.i12 = 0, k.i22 = kMass;
            k.p0 = 0, k.p1 = -kMass * w2 * kHalf * ex, k.p2 = -kMass * w2 * kHalf * ey;
            kx = -w2 * kLength * ex, ky = -w2 * kLength * ey;
        }
        // inward: articulated inertias and bias forces, passed to the parent's joint point
        for (int i = n_ - 1; i >= 0; --i) {
            Link& k = link_[static_cast<std::size_t>(i)];
            k.u = tau[i] - k.p0;
            if (i == 0) break;
            const double inv_d = 1.0 / k.i00;
            const double b11 = k.i11 - k.i01 * k.i01 * inv_d;
            const double b12 = k.i12 - k.i01 * k.i02 * inv_d;
            const double b22 = k.i22 - k.i02 * k.i02 * inv_d;
            const double ud = k.u * inv_d;
            const double p1 = k.p1 + b11 * k.kx + b12 * k.ky + k.i01 * ud;
            const double p2 = k.p2 + b12 * k.kx + b22 * k.ky + k.i02 * ud;
            Link& parent = link_[static_cast<std::size_t>(i - 1)];
            const double rx = kLength * parent.ex, ry = kLength * parent.ey;
            const double c1 = -ry * b11 + rx * b12, c2 = -ry * b12 + rx * b22;
            parent.i00 += -ry * c1 + rx * c2;
            parent.i01 += c1, parent.i02 += c2;
            parent.i11 += b11, parent.i12 += b12, parent.i22 += b22;
            parent.p0 += tau[i] - ry * p1 + rx * p2;  // moment about P_i is tau_i
            parent.p1 += p1, parent.p2 += p2;
        }
        // outward: accelerations, base accelerating upward at g
        double alpha = 0, ax = 0, ay = kGravity, rx = 0, ry = 0;
        for (int i = 0; i < n_; ++i) {
            Link& k = link_[static_cast<std::size_t>(i)];
            const double bx = ax - ry * alpha + k.kx, by = ay + rx * alpha + k.ky;
            const double qddi = (k.u - k.i00 * alpha - k.i01 * bx - k.i02 * by) / k.i00;
            qdd[i] = qddi;
            alpha += qddi, ax = bx, ay = by;
            rx = kLength * k.ex, ry = kLength * k.ey;
        }
    }

private:
    struct Link {
        double ex, ey;                      // direction of the link
        double alpha, acx, acy;             // inverse dynamics: accelerations
        double kx, ky;                      // forward: joint bias acceleration
        double i00, i01, i02, i11, i12, i22;  // forward: articulated inertia at the joint
        double p0, p1, p2;                  // forward: articulated bias force at the joint
        double u;                           // forward: tau - S^T p
    };

    int n_;
    std::vector<Link> link_;
};

}  // namespace alembert::bench
