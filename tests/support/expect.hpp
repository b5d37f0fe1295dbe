// SPDX-License-Identifier: MIT
// Test helpers: exception text checks, semantic equality of expressions, vectors and columns,
// numeric agreement.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/vec/frame.hpp"

/// Expects `statement` to throw `exception_type` whose what() contains `substring`.
#define EXPECT_THROW_MSG(statement, exception_type, substring)                              \
    do {                                                                                    \
        try {                                                                               \
            statement;                                                                      \
            ADD_FAILURE() << "expected " #exception_type " from: " #statement;              \
        } catch (const exception_type& e_) {                                                \
            EXPECT_NE(std::string(e_.what()).find(substring), std::string::npos)            \
                << "message was: " << e_.what() << "\nexpected to contain: " << (substring); \
        } catch (const std::exception& e_) {                                                \
            ADD_FAILURE() << "expected " #exception_type ", got another exception: "        \
                          << e_.what();                                                     \
        }                                                                                   \
    } while (false)

namespace alembert::test {

/// Semantic equality of two expressions, with both printed on failure.
inline ::testing::AssertionResult same(const ex& a, const ex& b, double tol = 1e-10) {
    if (alembert::equal(a, b, tol)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "\n  " << alembert::to_string(a) << "\n!=\n  " << alembert::to_string(b)
           << "\n  (largest numeric difference " << alembert::max_numeric_difference(a, b)
           << ")";
}

/// Semantic equality of two vectors: their measures in frame F agree.
inline ::testing::AssertionResult same(const Vector& a, const Vector& b, const Frame& F,
                                       double tol = 1e-10) {
    Col3 ca = a.components_in(F), cb = b.components_in(F);
    for (int i = 0; i < 3; ++i)
        if (!alembert::equal(ca[i], cb[i], tol))
            return ::testing::AssertionFailure()
                   << "component " << i << " in " << F.name() << " differs:\n  "
                   << alembert::to_string(ca[i]) << "\n!=\n  " << alembert::to_string(cb[i])
                   << "\n  vectors: " << a << "\n      vs " << b;
    return ::testing::AssertionSuccess();
}

/// Semantic equality of two columns of measures, component by component.
inline ::testing::AssertionResult same_col(const Col3& a, const Col3& b) {
    for (int i = 0; i < 3; ++i) {
        auto r = same(a[i], b[i]);
        if (!r) return r << " (component " << i << ")";
    }
    return ::testing::AssertionSuccess();
}

/// |a - b| within 1e-10 relative to max(1, |b|).
inline ::testing::AssertionResult near(double a, double b) {
    if (std::abs(a - b) <= 1e-10 * std::max(1.0, std::abs(b))) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a << " != " << b << " (difference " << a - b << ")";
}

}  // namespace alembert::test
