// SPDX-License-Identifier: MIT
// Particles: a point with a mass.
#pragma once

#include "alembert/mech/body.hpp"

namespace alembert {

/// A particle: a mass concentrated at a point.
class Particle : public Body {
public:
    Particle(std::string name, Point& P) : Body(std::move(name), P) {}
    /// The particle's point (its mass centre).
    const Point& point() const { return cm(); }
    Point& point() { return cm(); }
};

}  // namespace alembert
