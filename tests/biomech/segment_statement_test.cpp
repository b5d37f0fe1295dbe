// SPDX-License-Identifier: MIT
// The `segment` statement: constants scaled from a published table, usable with their units.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

namespace {

using namespace alembert::lang;

struct SegmentSession {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    RunStatus run(const std::string& text) {
        out.str("");
        err.str("");
        return interp.run(text, "segments.alb");
    }
};

TEST(SegmentStatement, DeclaresTheScaledConstantsAndPrintsTheRowAndSource) {
    SegmentSession s;
    ASSERT_EQ(s.run("newtonian N\nbody B\n"
                    "segment m_B, d_B, I_B from winter thigh mass 56.7 kg length 40 cm\n"),
              RunStatus::ok)
        << s.err.str();
    const std::string text = s.out.str();
    // 0.100 * 56.7 kg; 0.433 * 0.40 m; 5.67 (0.323 * 0.40)^2 kg m^2
    EXPECT_NE(text.find("segment thigh (greater trochanter-femoral condyles) from winter: "
                        "m_B = 5.67 kg, d_B = 0.1732 m, I_B = 0.0946473 kg*m^2"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("source: Winter, D. A. (2009)"), std::string::npos) << text;
    // the holding moment of the thigh held horizontal, m g d = 5.67 * 9.81 * 0.1732 N m
    ASSERT_EQ(s.run("variable q\nevaluate m_B*9.81*d_B*cos(q) at q = 0\n"), RunStatus::ok) << s.err.str();
    EXPECT_NE(s.out.str().find("9.63385"), std::string::npos) << s.out.str();
}

TEST(SegmentStatement, MistakesPointAtTheWord) {
    SegmentSession s;
    EXPECT_EQ(s.run("newtonian N\nsegment m, d, I from winter shin mass 60 kg length 0.4 m\n"),
              RunStatus::script_error);
    EXPECT_NE(s.err.str().find("segments.alb:2:29"), std::string::npos) << s.err.str();
    EXPECT_NE(s.err.str().find("has no segment 'shin'"), std::string::npos) << s.err.str();
    EXPECT_EQ(s.run("segment m, d from de_leva_male thigh mass 60 kg length 0.4 m\n"),
              RunStatus::script_error);
    EXPECT_NE(s.err.str().find("2 name(s) given; a segment gives three"), std::string::npos) << s.err.str();
    EXPECT_EQ(s.run("segment m, d, I from winter thorax mass 60 kg length 0.4 m\n"),
              RunStatus::script_error);
    EXPECT_NE(s.err.str().find("gives no radius of gyration for 'thorax'"), std::string::npos) << s.err.str();
    EXPECT_EQ(s.run("segment m, d, I from winter thigh mass 60 m length 0.4 m\n"),
              RunStatus::script_error);
    EXPECT_NE(s.err.str().find("mass"), std::string::npos) << s.err.str();
}

}  // namespace
