// SPDX-License-Identifier: MIT
// Force-plate records: a missing force sample is refused, never read as "no contact".
#include "alembert/biomech/force_plate.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "alembert/error.hpp"
#include "support/expect.hpp"

namespace alembert {
namespace {

// a plate "ground_force" in contact throughout (100 N up at x = 0.3 m), 5 samples 1 ms apart
Table contact_plate_table() {
    Table t;
    t.add_column("time", "s");
    for (const char* c : {"ground_force_vx", "ground_force_vy", "ground_force_vz",
                          "ground_force_px", "ground_force_py", "ground_force_pz",
                          "ground_torque_x", "ground_torque_y", "ground_torque_z"})
        t.add_column(c, "");
    for (int k = 0; k < 5; ++k) {
        t.columns[0].push_back(0.001 * k);
        const double row[9] = {0, 100, 0, 0.3, 0, 0, 0, 0, 0};
        for (int c = 0; c < 9; ++c) t.columns[1 + c].push_back(row[c]);
        t.lines.push_back(8 + k);
    }
    return t;
}

TEST(ForcePlate, AMissingForceDuringContactNamesTheFileColumnAndTime) {
    Table t = contact_plate_table();
    t.columns[2][3] = std::nan("");  // ground_force_vy at t = 0.003 s, line 11
    EXPECT_THROW_MSG(
        force_plate_from_table(t, "ground_force", 20, "walk_grf.mot"), ArgumentError,
        "walk_grf.mot:11: plate 'ground_force': column 'ground_force_vy' has no value (NaN) at "
        "t = 0.003 s, where a missing force would be read as no contact");
    // a centre of pressure missing in contact is refused too; out of contact it is not used
    t = contact_plate_table();
    t.columns[4][1] = std::nan("");
    EXPECT_THROW_MSG(
        force_plate_from_table(t, "ground_force", 20, "walk_grf.mot"), ArgumentError,
        "walk_grf.mot:9: plate 'ground_force': column 'ground_force_px' has no value (NaN) at "
        "t = 0.001 s, during contact");
    t.columns[2][1] = 5;  // 5 N: below the threshold, off the plate
    const ForcePlate plate = force_plate_from_table(t, "ground_force", 20, "walk_grf.mot");
    EXPECT_FALSE(plate.in_contact(1));
    EXPECT_TRUE(plate.in_contact(2));
}

TEST(ForcePlate, InContactRefusesAMissingForce) {
    ForcePlate plate = force_plate_from_table(contact_plate_table(), "ground_force");
    plate.F[1][2] = std::nan("");
    EXPECT_THROW_MSG(plate.in_contact(2), ArgumentError,
                     "plate 'ground_force' has no force (NaN) at sample 3 (t = 0.002 s)");
}

}  // namespace
}  // namespace alembert
