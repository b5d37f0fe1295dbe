// SPDX-License-Identifier: MIT
// A segment's length from a static trial: the mean distance between its two joint-centre markers.
#include "alembert/biomech/static_trial.hpp"

#include <cmath>
#include <vector>

#include "alembert/error.hpp"

namespace alembert {

StaticLength calc_static_length(const MarkerTable& trial, const std::string& from, const std::string& to,
                                const StaticLengthOptions& options) {
    const std::string what = "calc_static_length(" + from + ", " + to + "): ";
    if (from == to)
        throw ArgumentError(what + "the marker '" + from + "' is given twice; a length is between two markers");
    std::size_t cf[3], ct[3];
    for (int a = 0; a < 3; ++a) {
        try {
            cf[a] = trial.column(from, a), ct[a] = trial.column(to, a);
        } catch (const ArgumentError& e) {
            throw ArgumentError(what + e.what());
        }
    }
    // the distance at each frame where both markers are seen
    const Table& t = trial.table;
    std::vector<double> d, time;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        double s = 0;
        for (int a = 0; a < 3; ++a) {
            const double delta = t.columns[ct[a]][k] - t.columns[cf[a]][k];
            s += delta * delta;
        }
        if (std::isnan(s)) continue;
        d.push_back(std::sqrt(s));
        time.push_back(t.columns[0][k]);
    }
    if (d.empty())
        throw ArgumentError(what + "no frame of the trial (" + std::to_string(t.row_count()) + " frames) sees both '" +
                            from + "' and '" + to + "'; record a static trial where both are seen");
    // mean, standard deviation and the largest deviation
    StaticLength out;
    out.from = from, out.to = to, out.frames = d.size();
    double sum = 0;
    for (double x : d) sum += x;
    out.length_m = sum / static_cast<double>(d.size());
    double ss = 0;
    for (std::size_t k = 0; k < d.size(); ++k) {
        const double dev = d[k] - out.length_m;
        ss += dev * dev;
        if (std::abs(dev) > out.max_deviation_m) out.max_deviation_m = std::abs(dev), out.max_deviation_t = time[k];
    }
    out.sd_m = d.size() > 1 ? std::sqrt(ss / static_cast<double>(d.size() - 1)) : 0.0;
    if (!(out.length_m > 0))
        throw ArgumentError(what + "the markers '" + from + "' and '" + to + "' are at one place; a segment's length "
                            "is between two distinct joint centres");
    if (out.max_deviation_m > options.max_deviation_m)
        throw ArgumentError(what + "the distance between '" + from + "' and '" + to + "' is " +
                            format_csv_number(out.length_m) + " m on average but departs from it by " +
                            format_csv_number(out.max_deviation_m) + " m at t = " +
                            format_csv_number(out.max_deviation_t) + " s (more than " +
                            format_csv_number(options.max_deviation_m) + " m): they are not two points of one "
                            "segment, or a marker was swapped or slid; check the labels of the trial");
    return out;
}

StaticPlace calc_static_place(const MarkerTable& trial, const std::string& from, const std::string& to,
                              const std::string& marker, SagittalPlane plane) {
    const std::string what = "calc_static_place(" + from + ", " + to + ", " + marker + "): ";
    if (from == to || marker == from || marker == to)
        throw ArgumentError(what + "a marker is given twice; a place is measured from two joint-centre markers to a third");
    std::size_t c[3][2];  // P, D, M: horizontal and vertical columns
    const std::string names[3] = {from, to, marker};
    for (int i = 0; i < 3; ++i) {
        try {
            c[i][0] = trial.column(names[i], plane.horizontal), c[i][1] = trial.column(names[i], plane.vertical);
        } catch (const ArgumentError& e) {
            throw ArgumentError(what + e.what());
        }
    }
    const Table& t = trial.table;
    std::vector<double> along, across;
    for (std::size_t k = 0; k < t.row_count(); ++k) {
        const double P[2] = {t.columns[c[0][0]][k], t.columns[c[0][1]][k]};
        const double D[2] = {t.columns[c[1][0]][k], t.columns[c[1][1]][k]};
        const double M[2] = {t.columns[c[2][0]][k], t.columns[c[2][1]][k]};
        const double ux = D[0] - P[0], uy = D[1] - P[1], len = std::hypot(ux, uy);
        if (std::isnan(len + M[0] + M[1])) continue;
        if (!(len > 0))
            throw ArgumentError(what + "'" + from + "' and '" + to + "' are at one place at t = " +
                                format_csv_number(t.columns[0][k]) + " s; a segment's axis needs two distinct points");
        // u = (ux, uy) / len, n = (-uy, ux) / len
        const double rx = M[0] - P[0], ry = M[1] - P[1];
        along.push_back((rx * ux + ry * uy) / len);
        across.push_back((-rx * uy + ry * ux) / len);
    }
    if (along.empty())
        throw ArgumentError(what + "no frame of the trial (" + std::to_string(t.row_count()) + " frames) sees '" + from +
                            "', '" + to + "' and '" + marker + "' together; record a static trial where all are seen");
    auto mean_sd = [](const std::vector<double>& x, double& mean, double& sd) {
        double sum = 0, ss = 0;
        for (double v : x) sum += v;
        mean = sum / static_cast<double>(x.size());
        for (double v : x) ss += (v - mean) * (v - mean);
        sd = x.size() > 1 ? std::sqrt(ss / static_cast<double>(x.size() - 1)) : 0.0;
    };
    StaticPlace out;
    out.marker = marker, out.frames = along.size();
    mean_sd(along, out.along_m, out.sd_along_m);
    mean_sd(across, out.across_m, out.sd_across_m);
    return out;
}

}  // namespace alembert
