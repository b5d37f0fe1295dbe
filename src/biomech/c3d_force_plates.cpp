// SPDX-License-Identifier: MIT
// A C3D file's force plates (types 1-4) as ground reactions on the body at the marker frames.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "alembert/biomech/c3d_file.hpp"
#include "alembert/error.hpp"

namespace alembert {

namespace {

using PlateVec = std::array<double, 3>;

PlateVec plate_sub(const PlateVec& a, const PlateVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
PlateVec plate_cross(const PlateVec& a, const PlateVec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
PlateVec plate_unit(const PlateVec& a) {
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return {a[0] / n, a[1] / n, a[2] / n};
}

// the factor to N m of a moment channel's unit, or 0 if the unit does not say
double moment_factor(std::string u) {
    u.erase(std::remove_if(u.begin(), u.end(), [](char c) { return c == ' ' || c == '.' || c == '*'; }), u.end());
    for (char& c : u) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (u == "nmm") return 1e-3;
    if (u == "nm") return 1;
    if (u == "ncm") return 1e-2;
    return 0;
}

}  // namespace

Table calc_c3d_ground_forces(const C3dFile& file, const std::string& source, std::vector<std::string>& notes) {
    const std::size_t frames = file.markers.table.row_count(), n = file.analog_per_frame;
    const Table& analog = file.analog;
    const double length_factor = parse_unit(file.markers.file_unit).factor;
    Table out;
    out.add_column("time", "s");
    out.columns[0] = file.markers.table.columns[0];
    for (std::size_t i = 0; i < file.plates.size(); ++i) {
        const C3dForcePlate& fp = file.plates[i];
        const std::string plate = "force plate " + std::to_string(i + 1);
        const std::string prefix = (i == 0 ? std::string() : std::to_string(i) + "_") + "ground_force";
        const std::string torque = (i == 0 ? std::string() : std::to_string(i) + "_") + "ground_torque";
        const std::size_t count = fp.type == 3 ? 8 : 6;
        if (fp.type < 1 || fp.type > 4)
            throw ArgumentError(source + ": " + plate + " is of type " + std::to_string(fp.type) +
                                "; types 1, 2, 3 and 4 are read");
        if (fp.channels.size() < count)
            throw ArgumentError(source + ": " + plate + " has " + std::to_string(fp.channels.size()) +
                                " channels; a type " + std::to_string(fp.type) + " plate has " + std::to_string(count));
        if (fp.type == 4 && fp.cal_matrix.size() != 36)
            throw ArgumentError(source + ": " + plate + " is of type 4 without its 6 x 6 CAL_MATRIX");

        // the plate's axes and surface centre from its corners
        PlateVec c[4];
        for (int k = 0; k < 4; ++k) c[k] = {fp.corners[k][0], fp.corners[k][1], fp.corners[k][2]};
        PlateVec S{};
        for (int a = 0; a < 3; ++a) S[a] = (c[0][a] + c[1][a] + c[2][a] + c[3][a]) / 4;
        const PlateVec x_dir = plate_sub(PlateVec{c[0][0] + c[3][0], c[0][1] + c[3][1], c[0][2] + c[3][2]},
                             PlateVec{c[1][0] + c[2][0], c[1][1] + c[2][1], c[1][2] + c[2][2]});
        const PlateVec y_dir = plate_sub(PlateVec{c[0][0] + c[1][0], c[0][1] + c[1][1], c[0][2] + c[1][2]},
                             PlateVec{c[2][0] + c[3][0], c[2][1] + c[3][1], c[2][2] + c[3][2]});
        const PlateVec e_x = plate_unit(x_dir), e_z = plate_unit(plate_cross(x_dir, y_dir)), e_y = plate_cross(e_z, e_x);
        if (!std::isfinite(e_x[0] + e_x[1] + e_x[2] + e_z[0] + e_z[1] + e_z[2]))
            throw ArgumentError(source + ": " + plate + "'s FORCE_PLATFORM:CORNERS do not span a plane (its corners "
                                "coincide or lie on a line); the file's plate geometry is damaged: export it again");
        auto to_lab = [&](const PlateVec& v) {
            PlateVec r{};
            for (int a = 0; a < 3; ++a) r[a] = e_x[a] * v[0] + e_y[a] * v[1] + e_z[a] * v[2];
            return r;
        };
        PlateVec origin{fp.origin[0], fp.origin[1], fp.origin[2]};
        if (fp.type != 1 && origin[2] > 0) {
            for (double& v : origin) v = -v;
            notes.push_back(source + ": " + plate + "'s FORCE_PLATFORM:ORIGIN has z > 0 (the plate's origin above "
                            "its surface); read as the vector from the origin below the surface, negated");
        }

        // the channels' units: forces in N, moments in N m, centre of pressure in m
        std::vector<double> factor(count, 1.0);
        for (std::size_t k = 0; k < count; ++k) {
            const std::string& u = analog.units[fp.channels[k]];
            const bool is_moment = (fp.type != 1 && fp.type != 3 && k >= 3) || (fp.type == 1 && k == 5);
            const bool is_length = fp.type == 1 && (k == 3 || k == 4);
            std::string quantity;
            double f = 0;
            try {
                const Unit parsed = parse_unit(u);
                quantity = parsed.quantity, f = parsed.factor;
            } catch (const ArgumentError&) {
            }
            if (is_moment) {
                factor[k] = moment_factor(u) > 0 ? moment_factor(u) : quantity == "torque" ? f : 0;
                if (factor[k] == 0) {
                    factor[k] = length_factor;
                    notes.push_back(source + ": " + plate + "'s channel '" + analog.names[fp.channels[k]] + "' has the unit '" +
                                    u + "', read as N " + file.markers.file_unit + " (N times POINT:UNITS)");
                }
            } else if (is_length) {
                factor[k] = quantity == "length" ? f : length_factor;
            } else if (quantity == "force") {
                factor[k] = f;
            } else if (!u.empty()) {
                notes.push_back(source + ": " + plate + "'s channel '" + analog.names[fp.channels[k]] + "' has the unit '" +
                                u + "', read as N");
            }
        }

        // each channel averaged over one frame period centred on each frame's time, baseline
        // (ZERO) subtracted
        std::vector<std::vector<double>> ch(count, std::vector<double>(frames, 0.0));
        for (std::size_t k = 0; k < count; ++k) {
            const std::vector<double>& v = analog.columns[fp.channels[k]];
            double baseline = 0;
            if (fp.zero[0] >= 1 && fp.zero[1] >= fp.zero[0] && static_cast<std::size_t>(fp.zero[1]) <= frames && n > 0) {
                const std::size_t a = static_cast<std::size_t>(fp.zero[0] - 1) * n, b = static_cast<std::size_t>(fp.zero[1]) * n;
                for (std::size_t s = a; s < b; ++s) baseline += v[s];
                baseline /= static_cast<double>(b - a);
            }
            for (std::size_t f = 0; f < frames; ++f) {
                if (n == 0) continue;
                const long centre = static_cast<long>(f * n), half = static_cast<long>(n / 2);
                double sum = 0, weight = 0;
                for (long s = centre - half; s <= centre + half; ++s) {
                    if (s < 0 || s >= static_cast<long>(v.size())) continue;
                    const double w = (n % 2 == 0 && (s == centre - half || s == centre + half)) ? 0.5 : 1.0;
                    sum += w * v[static_cast<std::size_t>(s)], weight += w;
                }
                // type 4: the units apply to the calibration matrix's outputs (below)
                ch[k][f] = (sum / weight - baseline) * (fp.type == 4 ? 1.0 : factor[k]);
            }
        }
        if (fp.zero[0] >= 1 && fp.zero[1] >= fp.zero[0]) {
            if (static_cast<std::size_t>(fp.zero[1]) <= frames && n > 0)
                notes.push_back(source + ": " + plate + ": each channel's mean over frames " + std::to_string(fp.zero[0]) +
                                " to " + std::to_string(fp.zero[1]) + " (FORCE_PLATFORM:ZERO) subtracted as its baseline");
            else
                notes.push_back(source + ": " + plate + ": FORCE_PLATFORM:ZERO names frames " + std::to_string(fp.zero[0]) +
                                " to " + std::to_string(fp.zero[1]) + ", beyond the trial's " + std::to_string(frames) +
                                "; no baseline subtracted");
        }

        const std::size_t col = out.columns.size();
        for (const char* s : {"_vx", "_vy", "_vz"}) out.add_column(prefix + s, "N");
        for (const char* s : {"_px", "_py", "_pz"}) out.add_column(prefix + s, "m");
        for (const char* s : {"_x", "_y", "_z"}) out.add_column(torque + s, "N m");
        for (std::size_t f = 0; f < frames; ++f) {
            PlateVec F{}, P{}, T{};  // in the plate's axes: the reaction on the body, its centre of pressure, free moment
            PlateVec base = S;      // the point P is measured from
            if (fp.type == 1) {
                F = {ch[0][f], ch[1][f], ch[2][f]};
                P = {ch[3][f], ch[4][f], 0};
                T = {0, 0, ch[5][f]};
            } else {
                PlateVec M{};
                PlateVec o = origin;
                if (fp.type == 3) {
                    // four sensors at (±a, ±b): 1 (+a, +b), 2 (-a, +b), 3 (-a, -b), 4 (+a, -b)
                    const double a = origin[0], b = origin[1];
                    const double fx12 = ch[0][f], fx34 = ch[1][f], fy14 = ch[2][f], fy23 = ch[3][f];
                    const double fz1 = ch[4][f], fz2 = ch[5][f], fz3 = ch[6][f], fz4 = ch[7][f];
                    F = {fx12 + fx34, fy14 + fy23, fz1 + fz2 + fz3 + fz4};
                    M = {b * (fz1 + fz2 - fz3 - fz4), a * (fz2 + fz3 - fz1 - fz4), b * (fx34 - fx12) + a * (fy14 - fy23)};
                    o = {0, 0, origin[2]};
                } else {
                    double raw[6], cal[6];
                    for (int k = 0; k < 6; ++k) raw[k] = ch[static_cast<std::size_t>(k)][f];
                    for (int r = 0; r < 6; ++r) {
                        cal[r] = raw[r];
                        if (fp.type == 4) {
                            cal[r] = 0;
                            for (int k = 0; k < 6; ++k) cal[r] += fp.cal_matrix[static_cast<std::size_t>(r + 6 * k)] * raw[k];
                            cal[r] *= factor[static_cast<std::size_t>(r)];
                        }
                    }
                    F = {cal[0], cal[1], cal[2]};
                    M = {cal[3], cal[4], cal[5]};
                }
                // the line of F meets the surface z = oz (from O): M = P x F + T e_z
                const double oz = o[2];
                const double px = F[2] != 0 ? (oz * F[0] - M[1]) / F[2] : std::numeric_limits<double>::quiet_NaN();
                const double py = F[2] != 0 ? (M[0] + oz * F[1]) / F[2] : std::numeric_limits<double>::quiet_NaN();
                P = {px, py, oz};
                T = {0, 0, M[2] - (px * F[1] - py * F[0])};
                base = plate_sub(S, to_lab(o));  // O in the lab
            }
            const PlateVec F_lab = to_lab(F), T_lab = to_lab(T), P_rel = to_lab(P);
            for (int a = 0; a < 3; ++a) {
                out.columns[col + static_cast<std::size_t>(a)].push_back(F_lab[a]);
                out.columns[col + 3 + static_cast<std::size_t>(a)].push_back(base[a] + P_rel[a]);
                out.columns[col + 6 + static_cast<std::size_t>(a)].push_back(F[2] != 0 || fp.type == 1 ? T_lab[a]
                                                                                       : std::numeric_limits<double>::quiet_NaN());
            }
        }
    }
    return out;
}

}  // namespace alembert
