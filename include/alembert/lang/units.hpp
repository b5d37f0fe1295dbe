// SPDX-License-Identifier: MIT
// Units and dimensions: SI internally, dimension vectors (length, mass, time) for checking.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "alembert/lang/ast.hpp"

namespace alembert::lang {

/// A physical dimension as exponents of length, mass and time (angles are dimensionless, as
/// in SI), or an open dimension (`known == false`) for quantities declared without a unit,
/// which dimension checks let through.
struct Dimension {
    std::array<int, 3> exponent{0, 0, 0};  ///< length, mass, time
    bool known = true;

    static Dimension open() { return {{0, 0, 0}, false}; }
    static Dimension none() { return {}; }
    static Dimension length() { return {{1, 0, 0}, true}; }
    static Dimension mass() { return {{0, 1, 0}, true}; }
    static Dimension time() { return {{0, 0, 1}, true}; }
    static Dimension force() { return {{1, 1, -2}, true}; }
    static Dimension torque() { return {{2, 1, -2}, true}; }
    bool is_none() const { return known && exponent == std::array<int, 3>{0, 0, 0}; }
    /// True if both are known and differ.
    bool conflicts(const Dimension& o) const { return known && o.known && exponent != o.exponent; }
    friend bool operator==(const Dimension&, const Dimension&) = default;
};
Dimension operator*(const Dimension& a, const Dimension& b);
Dimension operator/(const Dimension& a, const Dimension& b);
Dimension pow(const Dimension& a, int n);

/// A readable name: "length", "force", "angle or number", "kg*m^2/s", "open".
std::string describe(const Dimension& d);

/// The SI unit text of a dimension for printing: "m", "N", "N*m", "kg*m^2", "m/s^2", "" for a
/// dimensionless quantity.
std::string si_unit(const Dimension& d);

/// A unit: how many SI units it is, its dimension and how it was written.
struct Unit {
    double scale = 1;
    Dimension dimension{};
    std::string text{};
};

/// The unit of one name (m, cm, kg, deg, N, ...), or nothing.
std::optional<Unit> find_unit(std::string_view name);

/// The unit a UnitText spells, e.g. kg*m^2 or m/s^2.
/// @throws ScriptError at an unknown unit name, listing the known ones.
Unit parse_unit(const UnitText& text);

/// The names of the known units, for messages.
std::string known_units();

}  // namespace alembert::lang
