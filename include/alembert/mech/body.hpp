// SPDX-License-Identifier: MIT
// The common part of particles and rigid bodies: a name, a mass and a mass centre.
#pragma once

#include <optional>
#include <string>

#include "alembert/mech/point.hpp"
#include "alembert/vec/dyadic.hpp"

namespace alembert {

/// A body of a model: a particle or a rigid body. Holds a name, a mass and the mass centre.
class Body {
public:
    Body(std::string name, Point& cm) : name_(std::move(name)), cm_(&cm) {}
    Body(const Body&) = delete;
    Body& operator=(const Body&) = delete;
    virtual ~Body() = default;

    const std::string& name() const { return name_; }
    /// The mass centre (for a particle, the particle's point).
    const Point& cm() const { return *cm_; }
    Point& cm() { return *cm_; }

    /// Sets the mass.
    void set_mass(const ex& m) { mass_ = m; }
    /// True if the mass was set.
    bool has_mass() const { return mass_.has_value(); }
    /// The mass.
    /// @throws alembert::ModelError naming the body if it was never set.
    const ex& mass() const;

    /// The frame of a rigid body; nullptr for a particle.
    virtual const Frame* frame() const { return nullptr; }

    /// ^N L = m ^N v^{cm}.
    Vector calc_linear_momentum(const Frame& N) const;
    /// ^N H^{B/O}: for a particle r^{P/O} x m ^N v^P; for a rigid body
    /// I^{B/Bcm} . ^N w^B + r^{Bcm/O} x m ^N v^{Bcm} (Kane 1985, eq. 4.6 with the moving-point
    /// convention of Mitiguy, ch. 21: absolute velocity of the mass centre).
    virtual Vector calc_angular_momentum(const Point& O, const Frame& N) const;
    /// Kinetic energy in N: 1/2 m v.v (+ 1/2 w.I.w for a rigid body).
    virtual ex calc_kinetic_energy(const Frame& N) const;

private:
    std::string name_;
    Point* cm_;
    std::optional<ex> mass_;
};

}  // namespace alembert
