// SPDX-License-Identifier: MIT
// Rigid bodies: a frame, a mass centre, a mass and an inertia dyadic.
#pragma once

#include <optional>

#include "alembert/mech/body.hpp"

namespace alembert {

/// A rigid body: a frame fixed in the body, its mass centre, mass and central inertia.
class RigidBody : public Body {
public:
    RigidBody(std::string name, Frame& B, Point& Bcm) : Body(std::move(name), Bcm), frame_(&B) {}

    const Frame* frame() const override { return frame_; }
    Frame& body_frame() const { return *frame_; }

    /// Sets the inertia from its moments and products in the body frame, about point `about`
    /// (the mass centre, or any point: then it is transferred to the mass centre by the
    /// parallel-axis theorem, which needs the mass). Products are inertia-matrix elements
    /// (see alembert::inertia_dyadic).
    /// @throws alembert::ModelError if `about` is not the mass centre and the mass is not set.
    void set_inertia(const Point& about, const ex& Ixx, const ex& Iyy, const ex& Izz,
                     const ex& Ixy = 0, const ex& Iyz = 0, const ex& Izx = 0);
    /// Sets the inertia dyadic about `about` (transferred to the mass centre if needed).
    void set_inertia(const Point& about, const Dyadic& I);
    /// True if an inertia was set.
    bool has_inertia() const { return I_cm_.has_value(); }
    /// I^{B/Bcm}, the inertia dyadic about the mass centre.
    /// @throws alembert::ModelError naming the body if it was never set.
    const Dyadic& inertia() const;
    /// I^{B/O} = I^{B/Bcm} + m ((r.r) U - r r), r = r^{Bcm/O} (parallel-axis theorem).
    Dyadic calc_inertia_about(const Point& O) const;

    Vector calc_angular_momentum(const Point& O, const Frame& N) const override;
    ex calc_kinetic_energy(const Frame& N) const override;

private:
    Frame* frame_;
    std::optional<Dyadic> I_cm_;
};

}  // namespace alembert
