// SPDX-License-Identifier: MIT
// Arithmetic of the small symbolic columns and matrices.
#include "alembert/sym/matrix.hpp"

namespace alembert {

Col3 operator+(const Col3& a, const Col3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
Col3 operator-(const Col3& a, const Col3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
Col3 operator-(const Col3& a) { return {{-a[0], -a[1], -a[2]}}; }
Col3 operator*(const ex& s, const Col3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
ex dot(const Col3& a, const Col3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Col3 cross(const Col3& a, const Col3& b) {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

Mat3 Mat3::identity() {
    Mat3 r;
    r(0, 0) = r(1, 1) = r(2, 2) = 1;
    return r;
}

Mat3 Mat3::from_columns(const Col3& c0, const Col3& c1, const Col3& c2) {
    Mat3 r;
    for (int i = 0; i < 3; ++i) r(i, 0) = c0[i], r(i, 1) = c1[i], r(i, 2) = c2[i];
    return r;
}

Mat3 Mat3::transpose() const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = (*this)(j, i);
    return r;
}

bool Mat3::is_zero() const {
    for (const ex& e : m)
        if (!e.is_zero()) return false;
    return true;
}

Mat3 Mat3::map(const std::function<ex(const ex&)>& f) const {
    Mat3 r;
    for (std::size_t k = 0; k < 9; ++k) r.m[k] = f(m[k]);
    return r;
}

Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            ex s = 0;
            for (int k = 0; k < 3; ++k)
                if (!a(i, k).is_zero() && !b(k, j).is_zero()) s += a(i, k) * b(k, j);
            r(i, j) = s;
        }
    return r;
}

Col3 operator*(const Mat3& a, const Col3& x) {
    Col3 r;
    for (int i = 0; i < 3; ++i) {
        ex s = 0;
        for (int k = 0; k < 3; ++k)
            if (!a(i, k).is_zero() && !x[k].is_zero()) s += a(i, k) * x[k];
        r[i] = s;
    }
    return r;
}

Mat3 operator+(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (std::size_t k = 0; k < 9; ++k) r.m[k] = a.m[k] + b.m[k];
    return r;
}

Mat3 operator-(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (std::size_t k = 0; k < 9; ++k) r.m[k] = a.m[k] - b.m[k];
    return r;
}

Mat3 operator*(const ex& s, const Mat3& a) {
    Mat3 r;
    for (std::size_t k = 0; k < 9; ++k) r.m[k] = s * a.m[k];
    return r;
}

Mat3 outer(const Col3& a, const Col3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = a[i] * b[j];
    return r;
}

}  // namespace alembert
