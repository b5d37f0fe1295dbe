// SPDX-License-Identifier: MIT
// Winter's walking trial (Table A.1): segment angles, residual-analysis filtering, and the knee
// and hip moments of the swing phase by bottom-up link-segment inverse dynamics.
#include <cmath>
#include <cstdio>
#include <string>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/link_segment.hpp"
#include "alembert/biomech/residual_analysis.hpp"
#include "alembert/biomech/segment_angles.hpp"
#include "alembert/biomech/segment_parameters.hpp"
#include "alembert/biomech/time_base.hpp"
#include "alembert/sim/filter.hpp"
#include "alembert/sim/plot.hpp"
#include "alembert/error.hpp"

using namespace alembert;

int run(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : WALKING_WINTER_TRC;
    const double body_mass = 55.7;  // kg, the subject of Table A.1
    MarkerTable m = read_trc(path);
    std::printf("%s", regularize_time_base(m.table, 0, "winter_table_a1.trc").describe().c_str());
    const double rate = m.data_rate_hz, dt = 1 / rate;

    // residual analysis of each coordinate used; all are filtered at the mean cutoff
    const char* used[] = {"HIP", "KNEE", "ANKLE", "MT5"};
    double sum = 0;
    for (const char* name : used)
        for (int axis = 0; axis < 2; ++axis) {
            ResidualAnalysis r = calc_residual_analysis(m.table.columns[m.column(name, axis)], rate);
            std::printf("residual analysis %-5s %c: noise %.2f mm, cutoff %.2f Hz\n", name, "XY"[axis],
                        r.noise_rms * 1000, r.cutoff_hz);
            sum += r.cutoff_hz;
        }
    const double cutoff = sum / 8;
    std::printf("filter: zero-lag Butterworth, 4th order, cutoff %.2f Hz\n", cutoff);
    for (std::size_t c = 1; c < m.table.columns.size(); ++c)
        m.table.columns[c] = filter_lowpass(m.table.columns[c], rate, cutoff);

    // segments (Winter's table scaled by the mean marker distances), distal first
    const SegmentTable& winter = segment_table("winter");
    auto segment = [&](const char* name, const char* joint, const char* P, const char* D) {
        ChainSegment s;
        s.name = name, s.proximal_joint = joint;
        s.p_h = m.table.columns[m.column(P, 0)], s.p_v = m.table.columns[m.column(P, 1)];
        s.d_h = m.table.columns[m.column(D, 0)], s.d_v = m.table.columns[m.column(D, 1)];
        double L = 0;
        for (std::size_t k = 0; k < s.p_h.size(); ++k) L += std::hypot(s.p_h[k] - s.d_h[k], s.p_v[k] - s.d_v[k]);
        L /= static_cast<double>(s.p_h.size());
        const SegmentParameters p = calc_segment_parameters(winter, name, body_mass, L);
        s.mass = p.mass, s.com_fraction = p.com_distance / L, s.inertia = p.inertia_flexion;
        std::printf("%-5s %s-%s: L %.4f m, m %.3f kg, I %.5f kg m^2\n", name, P, D, L, p.mass, p.inertia_flexion);
        return s;
    };
    const std::vector<ChainSegment> chain = {segment("foot", "ankle", "ANKLE", "MT5"),
                                             segment("leg", "knee", "KNEE", "ANKLE"),
                                             segment("thigh", "hip", "HIP", "KNEE")};
    std::vector<JointLoads> j = calc_inverse_dynamics_bottom_up(chain, dt, nullptr);

    // angles, Winter's conventions: segments from distal to proximal marker, knee flexion positive
    const auto thigh = calc_segment_angle(m, "KNEE", "HIP"), leg = calc_segment_angle(m, "ANKLE", "KNEE");
    const auto knee = calc_joint_angle(thigh, leg, -1);

    // the swing phase of the second stride: right toe-off at frame 70 to heel contact at 97
    std::printf("frame  t [s]   thigh [deg]  knee flex [deg]  M_knee [N m]  M_hip [N m]  P_knee [W]\n");
    constexpr double deg = 180 / 3.141592653589793;
    double peak_knee = 0, peak_hip = 0;
    Table swing;
    for (const char* c : {"t", "knee_flexion", "M_knee", "M_hip", "P_knee"}) swing.add_column(c, "");
    swing.units = {"s", "deg", "N m", "N m", "W"};
    for (std::size_t k = 69; k <= 96; ++k) {
        swing.columns[0].push_back(m.table.columns[0][k]), swing.columns[1].push_back(knee[k] * deg);
        swing.columns[2].push_back(j[1].M[k]), swing.columns[3].push_back(j[2].M[k]);
        swing.columns[4].push_back(j[1].power[k]);
        std::printf("%5zu  %.4f  %11.2f  %15.2f  %12.3f  %11.3f  %10.3f\n", k + 1, m.table.columns[0][k],
                    thigh[k] * deg, knee[k] * deg, j[1].M[k], j[2].M[k], j[1].power[k]);
        if (std::fabs(j[1].M[k]) > std::fabs(peak_knee)) peak_knee = j[1].M[k];
        if (std::fabs(j[2].M[k]) > std::fabs(peak_hip)) peak_hip = j[2].M[k];
    }
    // with an output directory: the swing phase as CSV and .sto, and a plot
    if (argc > 2) {
        const std::string out = std::string(argv[2]) + "/swing_moments";
        write_csv(swing, out + ".csv");
        write_storage(swing, out + ".sto", "swing phase, Winter Table A.1");
        PlotResult plot = plot_csv(swing, out + ".csv", out, {.title = "Winter Table A.1, swing", .y = {"M_knee", "M_hip"}});
        if (!plot.drawn) std::fprintf(stderr, "%s\n", plot.message.c_str());
    }
    std::printf("largest knee moment %.3f N m (%.4f N m/kg), hip %.3f N m (%.4f N m/kg)\n", peak_knee,
                peak_knee / body_mass, peak_hip, peak_hip / body_mass);
    return 0;
}

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const Error& e) {
        std::fprintf(stderr, "walking_winter: %s\n", e.what());
        return 1;
    }
}
