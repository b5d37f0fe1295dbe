// SPDX-License-Identifier: MIT
// Writes the sit-to-stand motion sampled at 100 Hz as a motion table: t [s], qA, qB, qC [deg].
// Usage: sit_to_stand_make_motion [OUT.csv]   (default motion.csv)
#include <cstdio>
#include <exception>

#include "motion.hpp"

using namespace alembert;

int main(int argc, char** argv) try {
    const char* path = argc > 1 ? argv[1] : "motion.csv";
    SampleModel model = make_triple_pendulum();
    PrescribedMotion motion(model.system.symbols(), model.q,
                            sit_to_stand_motion(model.system.symbols().time()));
    Table table;
    table.add_column("t", "s");
    for (const TimeVariable& q : model.q) table.add_column(q.name(), "deg");
    const Unit deg = parse_unit("deg");
    for (int i = 0; i <= 150; ++i) {
        const double t = i / 100.0;
        double q[3], qd[3], qdd[3];
        motion.calc_state(t, q, qd, qdd);
        table.columns[0].push_back(t);
        for (int j = 0; j < 3; ++j)
            table.columns[static_cast<std::size_t>(j) + 1].push_back(q[j] / deg.factor);
    }
    // 12 significant digits, as a motion-capture export would have: the last bits of the
    // formula's value depend on the order GiNaC sums its terms in, which is fixed for one
    // program but may change when the program is rebuilt, and the shipped file is compared
    // byte for byte with a fresh one
    write_csv(table, path, 12);
    std::printf("wrote %zu samples at 100 Hz to %s\n", table.row_count(), path);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "sit_to_stand_make_motion: %s\n", e.what());
    return 1;
}
