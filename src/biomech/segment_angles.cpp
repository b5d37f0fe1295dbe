// SPDX-License-Identifier: MIT
// Segment angles from two markers or a least-squares fit of several; joint angles.
#include "alembert/biomech/segment_angles.hpp"

#include <cmath>
#include <numbers>

#include "alembert/error.hpp"

namespace alembert {

namespace {

// unwraps angles in place: steps larger than pi are taken as a turn the other way
void unwrap(std::vector<double>& theta) {
    for (std::size_t k = 1; k < theta.size(); ++k) {
        const double d = theta[k] - theta[k - 1];
        theta[k] -= 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
    }
}

struct PlanarTrack {
    std::vector<double> h, v;
};

// the marker's in-plane coordinates at every sample, refusing missing samples
PlanarTrack planar_track(const MarkerTable& m, const std::string& name, SagittalPlane plane,
                         const char* caller) {
    if (plane.horizontal < 0 || plane.horizontal > 2 || plane.vertical < 0 || plane.vertical > 2 ||
        plane.horizontal == plane.vertical)
        throw ArgumentError(std::string(caller) + ": the plane's axes " +
                            std::to_string(plane.horizontal) + " and " + std::to_string(plane.vertical) +
                            " must be two different axes among 0 (X), 1 (Y), 2 (Z)");
    PlanarTrack p{m.table.columns[m.column(name, plane.horizontal)],
                  m.table.columns[m.column(name, plane.vertical)]};
    for (std::size_t k = 0; k < p.h.size(); ++k)
        if (std::isnan(p.h[k]) || std::isnan(p.v[k]))
            throw ArgumentError(std::string(caller) + ": marker '" + name + "' is missing at t = " +
                                format_csv_number(m.table.columns[0][k]) +
                                " s; fill its gaps first (regularize_time_base) or trim the trial");
    return p;
}

}  // namespace

std::vector<double> calc_segment_angle(const MarkerTable& markers, const std::string& from,
                                       const std::string& to, SagittalPlane plane) {
    const char* caller = "calc_segment_angle()";
    const PlanarTrack P = planar_track(markers, from, plane, caller);
    const PlanarTrack D = planar_track(markers, to, plane, caller);
    std::vector<double> theta(P.h.size());
    for (std::size_t k = 0; k < theta.size(); ++k) {
        // direction of p_PD in the plane
        const double dh = D.h[k] - P.h[k], dv = D.v[k] - P.v[k];
        if (dh == 0 && dv == 0)
            throw ArgumentError(std::string(caller) + ": markers '" + from + "' and '" + to +
                                "' are at the same place at t = " +
                                format_csv_number(markers.table.columns[0][k]) +
                                " s, so the segment has no direction; check the marker names");
        theta[k] = std::atan2(dv, dh);
    }
    unwrap(theta);
    return theta;
}

std::vector<double> calc_segment_angle_fit(const MarkerTable& markers,
                                           const std::vector<std::string>& names,
                                           SagittalPlane plane) {
    if (names.size() < 2)
        throw ArgumentError("calc_segment_angle_fit(): " + std::to_string(names.size()) +
                            " marker(s) given; a segment's angle needs at least two");
    std::vector<PlanarTrack> tracks;
    for (const auto& name : names)
        tracks.push_back(planar_track(markers, name, plane, "calc_segment_angle_fit()"));
    const std::size_t n = tracks.front().h.size(), count = names.size();
    // centred positions of the markers at sample k
    auto centred = [&](std::size_t k) {
        double ch = 0, cv = 0;
        for (const auto& t : tracks) ch += t.h[k], cv += t.v[k];
        ch /= static_cast<double>(count), cv /= static_cast<double>(count);
        std::vector<std::pair<double, double>> c;
        for (const auto& t : tracks) c.emplace_back(t.h[k] - ch, t.v[k] - cv);
        return c;
    };
    const auto r = centred(0);
    // the reference direction: first to second marker at the first sample
    const std::vector<double> theta0 = calc_segment_angle(markers, names[0], names[1], plane);
    std::vector<double> theta(n);
    for (std::size_t k = 0; k < n; ++k) {
        // best planar rotation from sample 0 to sample k
        const auto c = centred(k);
        double cross = 0, dot = 0;
        for (std::size_t i = 0; i < count; ++i) {
            cross += r[i].first * c[i].second - r[i].second * c[i].first;
            dot += r[i].first * c[i].first + r[i].second * c[i].second;
        }
        theta[k] = theta0[0] + std::atan2(cross, dot);
    }
    unwrap(theta);
    return theta;
}

std::vector<double> calc_joint_angle(const std::vector<double>& theta_proximal,
                                     const std::vector<double>& theta_distal, int sign) {
    if (theta_proximal.size() != theta_distal.size())
        throw ArgumentError("calc_joint_angle(): " + std::to_string(theta_proximal.size()) +
                            " proximal and " + std::to_string(theta_distal.size()) +
                            " distal angles; give both segments over the same samples");
    if (sign != 1 && sign != -1)
        throw ArgumentError("calc_joint_angle(): sign " + std::to_string(sign) + "; use +1 or -1");
    std::vector<double> q(theta_distal.size());
    for (std::size_t k = 0; k < q.size(); ++k) q[k] = sign * (theta_distal[k] - theta_proximal[k]);
    return q;
}

}  // namespace alembert
