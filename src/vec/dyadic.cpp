// SPDX-License-Identifier: MIT
// Dyadic arithmetic: sums, dot products with vectors, re-expression, printing.
#include "alembert/vec/dyadic.hpp"

#include <algorithm>

#include "alembert/sym/print.hpp"
#include "alembert/vec/frame.hpp"

namespace alembert {

Dyadic::Dyadic(const Frame& A, const Frame& B, const Mat3& m) { add_part(&A, &B, m); }

Dyadic Dyadic::unit(const Frame& F) { return Dyadic(F, F, Mat3::identity()); }

void Dyadic::add_part(const Frame* A, const Frame* B, const Mat3& m) {
    if (m.is_zero()) return;
    for (auto it = parts_.begin(); it != parts_.end(); ++it) {
        if (std::get<0>(*it) == A && std::get<1>(*it) == B) {
            std::get<2>(*it) = std::get<2>(*it) + m;
            if (std::get<2>(*it).is_zero()) parts_.erase(it);
            return;
        }
    }
    auto key = [](const Component& c) {
        return std::make_pair(std::get<0>(c)->id(), std::get<1>(c)->id());
    };
    Component c{A, B, m};
    auto pos = std::lower_bound(parts_.begin(), parts_.end(), c,
                                [&](const Component& x, const Component& y) { return key(x) < key(y); });
    parts_.insert(pos, c);
}

Dyadic& Dyadic::operator+=(const Dyadic& b) {
    for (const auto& [A, B, m] : b.parts_) add_part(A, B, m);
    return *this;
}

Dyadic& Dyadic::operator-=(const Dyadic& b) {
    for (const auto& [A, B, m] : b.parts_) add_part(A, B, ex(-1) * m);
    return *this;
}

Dyadic operator*(const ex& s, const Dyadic& d) {
    Dyadic r;
    if (s.is_zero()) return r;
    for (const auto& [A, B, m] : d.parts_) r.add_part(A, B, s * m);
    return r;
}

Mat3 Dyadic::components_in(const Frame& F) const {
    Mat3 sum;
    for (const auto& [A, B, m] : parts_) {
        // [D]_F = R_FA m R_FB^T
        Mat3 t = m;
        if (A != &F) t = A->rotation_in(F) * t;
        if (B != &F) t = t * B->rotation_in(F).transpose();
        sum = sum + t;
    }
    return sum;
}

Dyadic Dyadic::map(const std::function<ex(const ex&)>& f) const {
    Dyadic r;
    for (const auto& [A, B, m] : parts_) r.add_part(A, B, m.map(f));
    return r;
}

Dyadic outer(const Vector& a, const Vector& b) {
    Dyadic r;
    for (const auto& [A, ca] : a.components())
        for (const auto& [B, cb] : b.components()) r += Dyadic(*A, *B, outer(ca, cb));
    return r;
}

Vector dot(const Dyadic& D, const Vector& v) {
    Vector r;
    for (const auto& [A, B, m] : D.components()) r += Vector(*A, m * v.components_in(*B));
    return r;
}

Vector dot(const Vector& v, const Dyadic& D) {
    Vector r;
    for (const auto& [A, B, m] : D.components())
        r += Vector(*B, m.transpose() * v.components_in(*A));
    return r;
}

std::string Dyadic::to_string() const {
    std::string s;
    for (const auto& [A, B, m] : parts_) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const ex& c = m(i, j);
                if (c.is_zero()) continue;
                std::string units = A->name() + static_cast<char>('x' + i) + ">*" + B->name() +
                                    static_cast<char>('x' + j) + ">";
                std::string t = alembert::to_string(c);
                std::string term = c.is_equal(1)    ? units
                                   : c.is_equal(-1) ? "-" + units
                                   : GiNaC::is_a<GiNaC::add>(c) ? "(" + t + ")*" + units
                                                                 : t + "*" + units;
                if (s.empty()) s = term;
                else if (term[0] == '-') s += " - " + term.substr(1);
                else s += " + " + term;
            }
    }
    return s.empty() ? "0>>" : s;
}

std::ostream& operator<<(std::ostream& os, const Dyadic& d) { return os << d.to_string(); }

}  // namespace alembert
