// SPDX-License-Identifier: MIT
// Small symbolic 3-vectors and 3x3 matrices (components of vectors and rotation matrices).
#pragma once

#include <ginac/ginac.h>

#include <array>
#include <functional>

namespace alembert {

using GiNaC::ex;

/// A column of three symbolic measures (the components of a vector in one frame).
struct Col3 {
    std::array<ex, 3> v{0, 0, 0};

    ex& operator[](int i) { return v[static_cast<std::size_t>(i)]; }
    const ex& operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
    bool is_zero() const { return v[0].is_zero() && v[1].is_zero() && v[2].is_zero(); }
    /// Applies `f` to each component.
    Col3 map(const std::function<ex(const ex&)>& f) const { return {{f(v[0]), f(v[1]), f(v[2])}}; }
};

Col3 operator+(const Col3& a, const Col3& b);
Col3 operator-(const Col3& a, const Col3& b);
Col3 operator-(const Col3& a);
Col3 operator*(const ex& s, const Col3& a);
/// a . b of two columns in the same basis.
ex dot(const Col3& a, const Col3& b);
/// a x b of two columns in the same right-handed basis.
Col3 cross(const Col3& a, const Col3& b);

/// A 3x3 symbolic matrix, row-major (rotation matrices, inertia matrices).
struct Mat3 {
    std::array<ex, 9> m{0, 0, 0, 0, 0, 0, 0, 0, 0};

    ex& operator()(int i, int j) { return m[static_cast<std::size_t>(3 * i + j)]; }
    const ex& operator()(int i, int j) const { return m[static_cast<std::size_t>(3 * i + j)]; }
    static Mat3 identity();
    /// The matrix with `a` as its columns.
    static Mat3 from_columns(const Col3& c0, const Col3& c1, const Col3& c2);
    Mat3 transpose() const;
    Col3 column(int j) const { return {{(*this)(0, j), (*this)(1, j), (*this)(2, j)}}; }
    Col3 row(int i) const { return {{(*this)(i, 0), (*this)(i, 1), (*this)(i, 2)}}; }
    bool is_zero() const;
    Mat3 map(const std::function<ex(const ex&)>& f) const;
};

Mat3 operator*(const Mat3& a, const Mat3& b);
Col3 operator*(const Mat3& a, const Col3& x);
Mat3 operator+(const Mat3& a, const Mat3& b);
Mat3 operator-(const Mat3& a, const Mat3& b);
Mat3 operator*(const ex& s, const Mat3& a);
/// The outer product a b^T.
Mat3 outer(const Col3& a, const Col3& b);

}  // namespace alembert
