// SPDX-License-Identifier: MIT
// Joint torques of rising from a chair, from a motion table: the sit-to-stand triple pendulum's
// inverse dynamics over motion.csv (filtered at 6 Hz and differentiated), written to
// torques.csv and plotted, with the peak knee and hip extensor moments, and checked against the
// torques of the exact minimum-jerk formulas.
// Usage: sit_to_stand_inverse [MOTION.csv] [OUT_DIR]   (defaults: the shipped motion.csv, out)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "motion.hpp"

using namespace alembert;

int main(int argc, char** argv) try {
    const std::string motion_csv = argc > 1 ? argv[1] : ALEMBERT_EXAMPLE_DIR "/motion.csv";
    const std::string out_dir = argc > 2 ? argv[2] : "out";
    const double body_mass = 70.0;

    // the model (Winter's segment data) and its inverse dynamics, one road-map row per torque
    SampleModel model = make_triple_pendulum();
    InverseDynamics id =
        compile_inverse_dynamics(model.system, model.q, model.unknowns, "sit_to_stand");
    std::printf("inverse dynamics of 'sit_to_stand': %zu torques, %zu operations per sample%s\n",
                id.load_count(), id.function().operation_count,
                id.solved() ? " (solved form)" : "");

    // what `alembert inverse sit_to_stand --motion motion.csv --out DIR` runs
    InverseAnalysisOptions options{.filter = {.cutoff_hz = 6.0}};
    InverseAnalysisReport report = run_inverse_dynamics(id, motion_csv, out_dir, options);
    // the plot needs gnuplot; without it the CSV is written all the same
    if (!report.plot.drawn) std::fprintf(stderr, "%s\n", report.plot.message.c_str());
    const Table& T = report.loads;
    std::printf("wrote torques.csv (%zu samples)\n\n", T.row_count());

    // the torques every 0.1 s
    std::printf("  t [s]   TA [N m]   TB [N m]   TC [N m]\n");
    for (std::size_t r = 0; r < T.row_count(); r += 10)
        std::printf("  %4.2f  %9.2f  %9.2f  %9.2f\n", T.columns[0][r], T.columns[1][r],
                    T.columns[2][r], T.columns[3][r]);

    // peaks: knee extension turns the thigh B back (-z on B from A), hip extension lifts the
    // trunk C (+z on C from B), plantarflexion pulls the shank A back (+z on A from N)
    auto peak = [&](std::size_t column, double sign, const char* what) {
        std::size_t at = 0;
        for (std::size_t r = 0; r < T.row_count(); ++r)
            if (sign * T.columns[column][r] > sign * T.columns[column][at]) at = r;
        const double both = sign * T.columns[column][at];
        std::printf("  %-22s %6.1f N m at t = %.2f s: %5.1f N m per leg, %.2f N m/kg per leg\n",
                    what, both, T.columns[0][at], both / 2, both / 2 / body_mass);
    };
    std::printf("\npeak moments (both legs lumped; per leg = half; per kg of the %.0f kg body):\n",
                body_mass);
    peak(2, -1, "knee extensor (-TB)");
    peak(3, +1, "hip extensor (TC)");
    peak(1, +1, "ankle plantarflexor (TA)");

    // the same analysis from the exact formulas (no filtering): how close the data come
    PrescribedMotion exact(model.system.symbols(), model.q,
                           sit_to_stand_motion(model.system.symbols().time()));
    Table E = calc_inverse_dynamics(id, exact.sample(T.columns[0]), options);
    std::printf("\nfiltered data vs exact formulas, largest difference over [0.2, 1.3] s:\n");
    for (std::size_t j = 1; j <= 3; ++j) {
        double worst = 0;
        for (std::size_t r = 0; r < T.row_count(); ++r)
            if (T.columns[0][r] >= 0.2 - 1e-9 && T.columns[0][r] <= 1.3 + 1e-9)
                worst = std::max(worst, std::abs(T.columns[j][r] - E.columns[j][r]));
        std::printf("  %s %.3f N m\n", T.names[j].c_str(), worst);
    }
    const std::size_t last = E.row_count() - 1;
    std::printf("exact torques at rest, seat-off (t = 0):  TA %.2f, TB %.2f, TC %.2f N m\n",
                E.columns[1][0], E.columns[2][0], E.columns[3][0]);
    std::printf("exact torques at rest, standing (t = 1.5): TA %.2f, TB %.2f, TC %.2f N m\n",
                E.columns[1][last], E.columns[2][last], E.columns[3][last]);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "sit_to_stand_inverse: %s\n", e.what());
    return 1;
}
