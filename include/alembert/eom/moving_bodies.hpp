// SPDX-License-Identifier: MIT
// Which bodies a speed moves, told at random states once per model and speed.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "alembert/eom/zero_test.hpp"
#include "alembert/mech/system.hpp"

namespace alembert {

/// How one speed moves one body when that speed alone changes.
struct BodyMotion {
    bool turns = false;   ///< its angular velocity in N changes
    bool slides = false;  ///< its mass centre's velocity in N changes
    bool moves() const { return turns || slides; }
};

/// The bodies' velocities measured in N once, and for each speed asked, how it moves each body
/// of sys.bodies(), told at the zero tests' random states (MeasuresAtRandomStates: one walk of
/// the kinematics per speed, shared by every body) and remembered. The planner asks it for
/// each coordinate's S; a report asks it which coordinate moves exactly each row's S, once per
/// model instead of once per row.
class MovingBodies {
public:
    explicit MovingBodies(const System& sys);

    /// For each body of sys.bodies(), how `speed` alone moves it.
    /// @throws std::domain_error where a velocity cannot be evaluated at the random states.
    const std::vector<BodyMotion>& calc_motions(const ex& speed);
    /// The name of the first coordinate (in declaration order) whose speed alone moves exactly
    /// the bodies of S; "" if none does.
    /// @throws std::domain_error as calc_motions does.
    std::string calc_coordinate_moving(const BodySet& S);

    /// The random states the motions are told at (and their values, for further tests).
    MeasuresAtRandomStates& at() { return at_; }
    /// Body i's angular velocity and mass centre's velocity in N, measured in N ({} for a
    /// particle's angular velocity); every body's is measured at the first call.
    const Col3& w(std::size_t body) const { return measured().first[body]; }
    const Col3& v(std::size_t body) const { return measured().second[body]; }

private:
    const std::pair<std::vector<Col3>, std::vector<Col3>>& measured() const;

    const System& sys_;
    MeasuresAtRandomStates at_;
    mutable std::optional<std::pair<std::vector<Col3>, std::vector<Col3>>> wv_;
    std::map<ex, std::vector<BodyMotion>, GiNaC::ex_is_less> motions_;
};

}  // namespace alembert
