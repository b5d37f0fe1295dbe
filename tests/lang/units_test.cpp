// SPDX-License-Identifier: MIT
// Units: SI scales and dimensions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "alembert/lang/units.hpp"

using namespace alembert::lang;

namespace {

UnitText unit(std::initializer_list<std::pair<const char*, int>> factors) {
    UnitText u;
    for (auto [n, p] : factors) u.factors.push_back({{n, {}}, p});
    return u;
}

}  // namespace

TEST(Units, ScalesAreSI) {
    EXPECT_DOUBLE_EQ(parse_unit(unit({{"cm", 1}})).scale, 0.01);
    EXPECT_DOUBLE_EQ(parse_unit(unit({{"deg", 1}})).scale, std::numbers::pi / 180);
    EXPECT_DOUBLE_EQ(parse_unit(unit({{"rpm", 1}})).scale, 2 * std::numbers::pi / 60);
    EXPECT_DOUBLE_EQ(parse_unit(unit({{"g", 1}, {"cm", 2}})).scale, 1e-7);  // g*cm^2 in kg*m^2
    EXPECT_DOUBLE_EQ(parse_unit(unit({{"kN", 1}, {"mm", 1}})).scale, 1.0);
}

TEST(Units, DimensionsCombine) {
    Unit accel = parse_unit(unit({{"m", 1}, {"s", -2}}));
    EXPECT_EQ(accel.dimension, (Dimension{{1, 0, -2}, true}));
    EXPECT_EQ(accel.text, "m/s^2");
    EXPECT_EQ(parse_unit(unit({{"N", 1}, {"m", 1}})).dimension, Dimension::torque());
    EXPECT_EQ(parse_unit(unit({{"J", 1}})).dimension, Dimension::torque());
    EXPECT_TRUE(parse_unit(unit({{"rad", 1}})).dimension.is_none());
}

TEST(Units, OpenDimensionsNeverConflict) {
    EXPECT_FALSE(Dimension::open().conflicts(Dimension::length()));
    EXPECT_TRUE(Dimension::time().conflicts(Dimension::length()));
    EXPECT_FALSE((Dimension::open() * Dimension::mass()).known);
}

TEST(Units, PrintedNames) {
    EXPECT_EQ(si_unit(Dimension::force()), "N");
    EXPECT_EQ(si_unit(Dimension::torque()), "N*m");
    EXPECT_EQ(si_unit(Dimension{{2, 1, 0}, true}), "kg*m^2");
    EXPECT_EQ(si_unit(Dimension{{1, 0, -1}, true}), "m/s");
    EXPECT_EQ(describe(Dimension::length()), "a length (m)");
}

TEST(Units, UnknownNamesAreRefusedWithTheKnownOnes) {
    try {
        parse_unit(unit({{"furlong", 1}}));
        ADD_FAILURE();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), "unknown unit 'furlong'");
        EXPECT_NE(e.hint().find("kg"), std::string::npos);
    }
}
