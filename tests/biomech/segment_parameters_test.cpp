// SPDX-License-Identifier: MIT
// Segment tables: the published tables' own sums, and scaling to a subject by hand.
#include "alembert/biomech/segment_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

double mass_of(const SegmentTable& t, std::string_view name) {
    for (const auto& r : t.rows)
        if (r.name == name) return r.mass_fraction;
    ADD_FAILURE() << "no row " << name;
    return 0;
}

TEST(SegmentTable, WintersCompositeSegmentsAreTheSumsOfTheirParts) {
    // a typing error in one fraction breaks one of these published identities
    const SegmentTable& w = segment_table("winter");
    auto m = [&](std::string_view n) { return mass_of(w, n); };
    EXPECT_NEAR(m("forearm_hand"), m("forearm") + m("hand"), 1e-12);
    EXPECT_NEAR(m("total_arm"), m("upper_arm") + m("forearm") + m("hand"), 1e-12);
    EXPECT_NEAR(m("foot_leg"), m("foot") + m("leg"), 1e-12);
    EXPECT_NEAR(m("total_leg"), m("thigh") + m("leg") + m("foot"), 1e-12);
    EXPECT_NEAR(m("thorax_abdomen"), m("thorax") + m("abdomen"), 1e-12);
    EXPECT_NEAR(m("abdomen_pelvis"), m("abdomen") + m("pelvis"), 1e-12);
    EXPECT_NEAR(m("trunk"), m("thorax") + m("abdomen") + m("pelvis"), 1e-12);
    EXPECT_NEAR(m("trunk_head_neck"), m("trunk") + m("head_neck"), 1e-12);
    EXPECT_NEAR(m("hat"), m("trunk_head_neck") + 2 * m("total_arm"), 1e-12);
    // the whole body: HAT and two legs
    EXPECT_NEAR(m("hat") + 2 * m("total_leg"), 1.0, 1e-12);
}

TEST(SegmentTable, DeLevasSegmentsMakeTheWholeBody) {
    for (std::string_view key : {"de_leva_male", "de_leva_female"}) {
        const SegmentTable& t = segment_table(key);
        auto m = [&](std::string_view n) { return mass_of(t, n); };
        const double limbs = m("upper_arm") + m("forearm") + m("hand") + m("thigh") + m("shank") + m("foot");
        // de Leva's percentages are rounded to 0.01 %: the female ones sum to 99.99 %
        EXPECT_NEAR(m("head") + m("trunk") + 2 * limbs, 1.0, 1.5e-4) << key;
        EXPECT_NEAR(m("upper_trunk") + m("middle_trunk") + m("lower_trunk"), m("trunk"), 1e-12) << key;
    }
}

TEST(SegmentParameters, ScalesAWinterThighByHand) {
    // 56.7 kg, thigh 0.40 m: m = 0.100 * 56.7 = 5.67 kg, CM 0.433 * 0.40 = 0.1732 m from the
    // hip, I = 5.67 (0.323 * 0.40)^2 = 0.0946472688 kg m^2
    SegmentParameters p = calc_segment_parameters(segment_table("winter"), "thigh", 56.7, 0.40);
    EXPECT_NEAR(p.mass, 5.67, 1e-12);
    EXPECT_NEAR(p.com_distance, 0.1732, 1e-12);
    EXPECT_NEAR(p.inertia_flexion, 0.0946472688, 1e-12);
    // de Leva female shank to the lateral malleolus, 60 kg, 0.38 m: m = 2.886 kg,
    // CM 0.4416 * 0.38 = 0.167808 m, I = 2.886 (0.267 * 0.38)^2 = 0.0296109... kg m^2
    SegmentParameters s =
        calc_segment_parameters(segment_table("de_leva_female"), "shank_kjc_lmal", 60, 0.38);
    EXPECT_NEAR(s.mass, 2.886, 1e-12);
    EXPECT_NEAR(s.com_distance, 0.167808, 1e-12);
    EXPECT_NEAR(s.inertia_flexion, 2.886 * 0.10146 * 0.10146, 1e-12);
}

TEST(SegmentParameters, UnknownTablesSegmentsAndBadSizesAreNamed) {
    EXPECT_THROW_MSG(segment_table("dempster"), ArgumentError,
                     "no table 'dempster'; use winter, de_leva_male or de_leva_female");
    EXPECT_THROW_MSG(calc_segment_parameters(segment_table("winter"), "shin", 70, 0.4), ArgumentError,
                     "the table 'winter' has no segment 'shin'; its segments are: hand, forearm");
    EXPECT_THROW_MSG(calc_segment_parameters(segment_table("winter"), "leg", -70, 0.4), ArgumentError,
                     "segment 'leg' with body mass -70 kg and length 0.4 m; both must be positive");
}

TEST(SegmentTable, PrintsItsSourceAndRows) {
    const std::string text = format_segment_table(segment_table("de_leva_male"));
    EXPECT_NE(text.find("source: de Leva, P. (1996)"), std::string::npos);
    EXPECT_NE(text.find("  thigh (HJC-KJC): 0.1416, 0.4095, 0.329, 0.329, 0.149\n"), std::string::npos) << text;
    EXPECT_NE(format_segment_table(segment_table("winter")).find("  thorax (C7-T1-T12-L1 and diaphragm): 0.216, 0.82, -, -, -\n"),
              std::string::npos);
}

}  // namespace
}  // namespace alembert
