// SPDX-License-Identifier: MIT
// Vectors as sums of measures times the unit vectors of several frames.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "alembert/sym/matrix.hpp"

namespace alembert {

class Frame;

/// A vector: a sum over frames F_i of c_i1 F_ix> + c_i2 F_iy> + c_i3 F_iz>.
///
/// Components stay in the frames they were written in (a link's length along its own axis
/// stays one term), and are only re-expressed when an operation needs a common basis. The
/// frames involved must live in one frame tree and outlive the vector.
class Vector {
public:
    using Component = std::pair<const Frame*, Col3>;

    /// The zero vector.
    Vector() = default;
    /// The vector with measures `c` in frame `F`.
    Vector(const Frame& F, const Col3& c);

    /// Components per frame, ordered by frame creation; no frame repeats and none is zero.
    const std::vector<Component>& components() const { return parts_; }
    /// True if every measure is identically zero as written (no simplification is tried).
    bool is_zero() const { return parts_.empty(); }

    Vector& operator+=(const Vector& b);
    Vector& operator-=(const Vector& b);
    friend Vector operator+(Vector a, const Vector& b) { return a += b; }
    friend Vector operator-(Vector a, const Vector& b) { return a -= b; }
    friend Vector operator-(const Vector& a) { return ex(-1) * a; }
    friend Vector operator*(const ex& s, const Vector& a);
    friend Vector operator*(const Vector& a, const ex& s) { return s * a; }
    friend Vector operator/(const Vector& a, const ex& s) { return a * GiNaC::pow(s, -1); }

    /// The measures of this vector in frame F: [v]_F.
    /// @throws alembert::ModelError if a frame of the vector has no orientation path to F.
    Col3 components_in(const Frame& F) const;
    /// The same vector written entirely in frame F.
    Vector express_in(const Frame& F) const { return Vector(F, components_in(F)); }
    /// The time derivative in frame F: for each part in frame B,
    /// ^F d/dt (c B>) = (dc/dt) B> + ^F w^B x (c B>) (Kane 1985, eq. 2.1.2); parts already in
    /// F are differentiated directly, so F = the frame the vector is written in is cheapest.
    Vector dt_in(const Frame& F) const;
    /// Partial derivative of every measure with respect to the symbol `s` (partial velocity of
    /// a velocity with respect to a speed), through intermediates.
    Vector diff(const ex& s) const;
    /// Applies `f` to every measure (simplify, substitute, expand ...).
    Vector map(const std::function<ex(const ex&)>& f) const;
    /// Every measure simplified with alembert::simplify.
    Vector simplify() const;
    /// sqrt(v . v).
    ex magnitude() const;
    /// v / |v|.
    /// @throws alembert::ArgumentError if the vector is zero.
    Vector unit() const;

    /// Readable text: 'L_A*sin(qA)*Nx> + L_A*cos(qA)*Ny>'; "0>" for the zero vector.
    std::string to_string() const;

private:
    void add_part(const Frame* F, const Col3& c);
    std::vector<Component> parts_;
};

/// a . b, summing over the frames of both (each pair expressed in a common frame).
ex dot(const Vector& a, const Vector& b);
/// a x b; the result is written in the frames of b.
Vector cross(const Vector& a, const Vector& b);
/// The angle between two non-zero vectors, acos(a . b / (|a| |b|)).
/// @throws alembert::ArgumentError if either is zero.
ex angle_between(const Vector& a, const Vector& b);

std::ostream& operator<<(std::ostream& os, const Vector& v);

}  // namespace alembert
