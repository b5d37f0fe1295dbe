// SPDX-License-Identifier: MIT
// Vector arithmetic across frames, re-expression, time and partial derivatives, printing.
#include "alembert/vec/vector.hpp"

#include <algorithm>
#include <sstream>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/vec/frame.hpp"

namespace alembert {

Vector::Vector(const Frame& F, const Col3& c) { add_part(&F, c); }

void Vector::add_part(const Frame* F, const Col3& c) {
    if (c.is_zero()) return;
    auto it = std::lower_bound(parts_.begin(), parts_.end(), F, [](const Component& p, const Frame* f) {
        return p.first->id() < f->id();
    });
    if (it != parts_.end() && it->first == F) {
        it->second = it->second + c;
        if (it->second.is_zero()) parts_.erase(it);
    } else {
        parts_.insert(it, {F, c});
    }
}

Vector& Vector::operator+=(const Vector& b) {
    for (const auto& [F, c] : b.parts_) add_part(F, c);
    return *this;
}

Vector& Vector::operator-=(const Vector& b) {
    for (const auto& [F, c] : b.parts_) add_part(F, -c);
    return *this;
}

Vector operator*(const ex& s, const Vector& a) {
    Vector r;
    if (s.is_zero()) return r;
    for (const auto& [F, c] : a.parts_) r.add_part(F, s * c);
    return r;
}

Col3 Vector::components_in(const Frame& F) const {
    Col3 sum;
    for (const auto& [B, c] : parts_) sum = sum + (B == &F ? c : B->rotation_in(F) * c);
    return sum;
}

Vector Vector::dt_in(const Frame& F) const {
    Vector r;
    SymbolTable& st = F.symbols();
    for (const auto& [B, c] : parts_) {
        r.add_part(B, c.map([&](const ex& e) { return st.dt(e); }));
        if (B != &F) r += cross(B->ang_vel_in(F), Vector(*B, c));
    }
    return r;
}

Vector Vector::diff(const ex& s) const {
    Vector r;
    for (const auto& [B, c] : parts_) {
        SymbolTable& st = B->symbols();
        r.add_part(B, c.map([&](const ex& e) { return st.diff(e, s); }));
    }
    return r;
}

Vector Vector::map(const std::function<ex(const ex&)>& f) const {
    Vector r;
    for (const auto& [B, c] : parts_) r.add_part(B, c.map(f));
    return r;
}

Vector Vector::simplify() const {
    return map([](const ex& e) { return alembert::simplify(e); });
}

ex Vector::magnitude() const { return GiNaC::sqrt(alembert::simplify(dot(*this, *this))); }

Vector Vector::unit() const {
    auto zero = [] {
        return ArgumentError(
            "Vector::unit(): the vector is zero, so it has no direction; check that the points "
            "or vectors that define it are distinct, or give the direction explicitly");
    };
    Vector s = simplify();
    if (s.is_zero()) throw zero();
    if (s.parts_.size() == 1) {
        const Col3& c = s.parts_[0].second;
        int nz = 0, k = 0;
        for (int i = 0; i < 3; ++i)
            if (!c[i].is_zero()) ++nz, k = i;
        if (nz == 1 && GiNaC::is_a<GiNaC::numeric>(c[k])) {  // a multiple of a unit vector
            Col3 u;
            u[k] = GiNaC::ex_to<GiNaC::numeric>(c[k]).is_positive() ? 1 : -1;
            return Vector(*s.parts_[0].first, u);
        }
    }
    // parts in several frames can cancel, so a zero vector may show only in its magnitude
    ex m = s.magnitude();
    if (m.is_zero()) throw zero();
    return s / m;
}

ex dot(const Vector& a, const Vector& b) {
    const auto& pa = a.components();
    const auto& pb = b.components();
    if (pa.size() > 1 && pb.size() > 1) {
        // both span several frames: pairwise products would cost |a| |b| rotated terms;
        // expressed in one frame (the last of b's, usually the most distal body) the dot is
        // three products of sums, linear in the number of parts
        const Frame& F = *pb.back().first;
        return dot(a.components_in(F), b.components_in(F));
    }
    ex sum = 0;
    for (const auto& [A, ca] : a.components())
        for (const auto& [B, cb] : b.components())
            sum += dot(ca, A == B ? cb : B->rotation_in(*A) * cb);
    return sum;
}

Vector cross(const Vector& a, const Vector& b) {
    Vector r;
    if (a.is_zero()) return r;
    if (a.components().size() > 1 && b.components().size() > 1) {
        // as for dot: one frame keeps the result linear in the number of parts
        const Frame& F = *b.components().back().first;
        return Vector(F, cross(a.components_in(F), b.components_in(F)));
    }
    for (const auto& [B, cb] : b.components()) r += Vector(*B, cross(a.components_in(*B), cb));
    return r;
}

ex angle_between(const Vector& a, const Vector& b) {
    // a magnitude, not only the parts, shows a vector whose parts in several frames cancel
    ex ma = a.simplify().is_zero() ? ex(0) : a.magnitude();
    ex mb = b.simplify().is_zero() ? ex(0) : b.magnitude();
    if (ma.is_zero() || mb.is_zero())
        throw ArgumentError("angle_between(): one of the vectors is zero, so the angle is not "
                            "defined");
    return GiNaC::acos(simplify(dot(a, b)) / (ma * mb));
}

std::string Vector::to_string() const {
    std::string s;
    for (const auto& [F, c] : parts_) {
        for (int i = 0; i < 3; ++i) {
            if (c[i].is_zero()) continue;
            std::string unit = F->name() + static_cast<char>('x' + i) + ">";
            std::string m = alembert::to_string(c[i]);
            bool neg = !m.empty() && m[0] == '-';
            std::string term;
            if (c[i].is_equal(1)) term = unit;
            else if (c[i].is_equal(-1)) term = "-" + unit;
            else if (GiNaC::is_a<GiNaC::add>(c[i])) term = "(" + m + ")*" + unit, neg = false;
            else term = m + "*" + unit;
            if (term[0] == '-') neg = true;
            if (s.empty()) s = term;
            else s += neg ? " - " + term.substr(1) : " + " + term;
        }
    }
    return s.empty() ? "0>" : s;
}

std::ostream& operator<<(std::ostream& os, const Vector& v) { return os << v.to_string(); }

}  // namespace alembert
