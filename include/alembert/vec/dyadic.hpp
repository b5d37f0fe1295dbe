// SPDX-License-Identifier: MIT
// Dyadics (inertia): sums of measures times pairs of unit vectors.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "alembert/vec/vector.hpp"

namespace alembert {

/// A dyadic: a sum over frame pairs (A, B) of sum_ij m_ij A_i> B_j>.
class Dyadic {
public:
    using Component = std::tuple<const Frame*, const Frame*, Mat3>;

    /// The zero dyadic.
    Dyadic() = default;
    /// The dyadic sum_ij m_ij A_i> B_j>.
    Dyadic(const Frame& A, const Frame& B, const Mat3& m);
    /// The unit dyadic U = F_x>F_x> + F_y>F_y> + F_z>F_z> (the same in every frame).
    static Dyadic unit(const Frame& F);

    const std::vector<Component>& components() const { return parts_; }
    bool is_zero() const { return parts_.empty(); }

    Dyadic& operator+=(const Dyadic& b);
    Dyadic& operator-=(const Dyadic& b);
    friend Dyadic operator+(Dyadic a, const Dyadic& b) { return a += b; }
    friend Dyadic operator-(Dyadic a, const Dyadic& b) { return a -= b; }
    friend Dyadic operator*(const ex& s, const Dyadic& d);

    /// The matrix of this dyadic in frame F: [D]_F with D = sum_ij [D]_F(i,j) F_i> F_j>.
    Mat3 components_in(const Frame& F) const;
    Dyadic express_in(const Frame& F) const { return Dyadic(F, F, components_in(F)); }
    Dyadic map(const std::function<ex(const ex&)>& f) const;
    std::string to_string() const;

private:
    void add_part(const Frame* A, const Frame* B, const Mat3& m);
    std::vector<Component> parts_;
};

/// The outer product a b (a dyad).
Dyadic outer(const Vector& a, const Vector& b);
/// D . v (v dotted from the right).
Vector dot(const Dyadic& D, const Vector& v);
/// v . D (v dotted from the left).
Vector dot(const Vector& v, const Dyadic& D);

std::ostream& operator<<(std::ostream& os, const Dyadic& d);

}  // namespace alembert
