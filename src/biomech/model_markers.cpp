// SPDX-License-Identifier: MIT
// A planar model's coordinates from its markers' trajectories, checked against the model.
#include "alembert/biomech/model_markers.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"

namespace alembert {

namespace {

constexpr double kPi = std::numbers::pi;

// an angle brought into (-pi, pi]
double wrap(double a) { return a - 2 * kPi * std::round(a / (2 * kPi)); }

std::string cm(double metres) { return format_csv_number(std::round(metres * 1e4) / 1e2) + " cm"; }
std::string deg(double rad) {
    return format_csv_number(std::round(rad * 180 / kPi * 100) / 100) + " deg";
}

// the model's marker positions at q: x_N, y_N of marker i at 2i, 2i + 1
struct ModelPositions {
    CompiledExpressions f;
    std::vector<double> out;
    const std::vector<double>& at(const std::vector<double>& q) {
        f.evaluate(q.data(), out.data());
        return out;
    }
};

}  // namespace

MarkerCoordinates calc_coordinates_from_markers(const SymbolTable& table,
                                                const std::vector<TimeVariable>& q,
                                                const std::vector<ModelMarker>& markers,
                                                const MarkerTable& trial,
                                                const MarkerCoordinatesOptions& options) {
    const std::string caller = "calc_coordinates_from_markers(): ";
    const std::size_t n = q.size(), n_markers = markers.size();
    // the segments: bodies with two or more markers, in the order their first marker is given
    std::vector<std::string> bodies;
    std::map<std::string, std::vector<std::size_t>> of_body;
    for (std::size_t i = 0; i < n_markers; ++i) {
        trial.column(markers[i].name, 0);  // the file has it
        if (!of_body.count(markers[i].body)) bodies.push_back(markers[i].body);
        of_body[markers[i].body].push_back(i);
    }
    MarkerCoordinates r;
    for (const std::string& b : bodies)
        if (of_body[b].size() >= 2) r.segments.push_back(b);
    const std::size_t n_seg = r.segments.size();
    if (n_seg == 0)
        throw ModelError(
            caller +
            "no body has two markers, so no segment angle is known; declare two markers on each "
            "segment (marker KNEE on A at B_o)");

    // the model's marker positions as a compiled function of q
    std::vector<ex> inputs, outputs;
    for (const TimeVariable& v : q) inputs.push_back(v.symbol());
    for (const ModelMarker& m : markers) {
        outputs.push_back(m.x_N);
        outputs.push_back(m.y_N);
    }
    ModelPositions model{CompiledExpressions(table, inputs, outputs),
                         std::vector<double>(2 * n_markers)};
    auto model_angle = [&](const std::vector<double>& p, std::size_t s) {
        const std::vector<std::size_t>& ids = of_body[r.segments[s]];
        return std::atan2(p[2 * ids[1] + 1] - p[2 * ids[0] + 1], p[2 * ids[1]] - p[2 * ids[0]]);
    };

    // the model's sign conventions: d theta_B / d q_j at a reference configuration, +-1 or 0
    std::vector<double> q0(n);
    for (std::size_t j = 0; j < n; ++j) q0[j] = 0.1 * static_cast<double>(j + 1);
    std::vector<double> theta0(n_seg);
    {
        const std::vector<double>& p = model.at(q0);
        for (std::size_t s = 0; s < n_seg; ++s) theta0[s] = model_angle(p, s);
    }
    Eigen::MatrixXd C =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n_seg), static_cast<Eigen::Index>(n));
    r.turns.assign(n_seg, std::vector<int>(n, 0));
    constexpr double h = 1e-4;
    for (std::size_t j = 0; j < n; ++j) {
        std::vector<double> qj = q0;
        qj[j] += h;
        const std::vector<double>& p = model.at(qj);
        for (std::size_t s = 0; s < n_seg; ++s) {
            const double rate = wrap(model_angle(p, s) - theta0[s]) / h;
            const double c = std::round(rate);
            if (!std::isfinite(rate) || std::abs(rate - c) > 1e-5 || std::abs(c) > 1)
                throw ModelError(caller + "coordinate '" + q[j].name() + "' turns segment " +
                                 r.segments[s] + " by " +
                                 format_csv_number(std::round(rate * 1000) / 1000) +
                                 " rad per rad, not +-1 or 0: segment angles from markers give the "
                                 "joint angles of "
                                 "planar chains turning about Nz> (rotate B from A about z by q); "
                                 "check the markers "
                                 "declared on " +
                                 r.segments[s]);
            C(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(j)) = c;
            r.turns[s][j] = static_cast<int>(c);
        }
    }
    // every coordinate determined by the segments' angles
    for (std::size_t j = 0; j < n; ++j)
        if (C.col(static_cast<Eigen::Index>(j)).isZero())
            throw ModelError(caller + "coordinate '" + q[j].name() +
                             "' turns no segment with two markers, so the marker file does not "
                             "determine it; declare "
                             "two markers on a body it turns (a length coordinate cannot be read "
                             "from segment angles)");
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C);
    if (qr.rank() < static_cast<Eigen::Index>(n)) {
        // the coordinates that can change together without turning any segment with markers
        const Eigen::MatrixXd kernel = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
        std::string together;
        for (std::size_t j = 0; j < n; ++j)
            if (kernel.row(static_cast<Eigen::Index>(j)).cwiseAbs().maxCoeff() > 1e-9)
                together += (together.empty() ? "'" : ", '") + q[j].name() + "'";
        throw ModelError(caller + "the segments' angles determine only " +
                         std::to_string(qr.rank()) + " of the " + std::to_string(n) +
                         " coordinates: " + together +
                         " can change together without turning a segment with two markers; declare "
                         "two markers on "
                         "every segment a joint turns");
    }
    // the most distal coordinate turning each segment names it in messages
    auto coordinate_of = [&](std::size_t s) {
        std::size_t best = n;
        Eigen::Index fewest = 0;
        for (std::size_t j = 0; j < n; ++j) {
            if (r.turns[s][j] == 0) continue;
            const Eigen::Index turned = (C.col(static_cast<Eigen::Index>(j)).array() != 0).count();
            if (best == n || turned < fewest) best = j, fewest = turned;
        }
        return q[best].name();
    };

    // the file's segment angles, theta_B(t)
    std::vector<std::vector<double>> theta(n_seg);
    for (std::size_t s = 0; s < n_seg; ++s) {
        std::vector<std::string> names;
        for (std::size_t i : of_body[r.segments[s]]) names.push_back(markers[i].name);
        theta[s] = names.size() == 2 ? calc_segment_angle(trial, names[0], names[1], options.plane)
                                     : calc_segment_angle_fit(trial, names, options.plane);
    }
    const std::vector<double>& t = trial.table.columns[0];
    const std::size_t n_t = t.size();

    // q(t): least squares of C (q - q0) = theta(t) - theta0, a whole turn taken out at the start
    std::vector<double> turn(n_seg);
    for (std::size_t s = 0; s < n_seg; ++s)
        turn[s] = theta[s][0] - wrap(theta[s][0] - theta0[s]) - theta0[s];
    r.motion.add_column("t", "s");
    for (const TimeVariable& v : q) r.motion.add_column(v.name(), "rad");
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(n_seg));
    std::vector<std::vector<double>> q_t(n_t, std::vector<double>(n));
    for (std::size_t k = 0; k < n_t; ++k) {
        for (std::size_t s = 0; s < n_seg; ++s)
            rhs(static_cast<Eigen::Index>(s)) = theta[s][k] - turn[s] - theta0[s];
        const Eigen::VectorXd dq = qr.solve(rhs);
        r.motion.columns[0].push_back(t[k]);
        for (std::size_t j = 0; j < n; ++j) {
            q_t[k][j] = q0[j] + dq(static_cast<Eigen::Index>(j));
            r.motion.columns[j + 1].push_back(q_t[k][j]);
        }
    }

    // check: the model's segment angles at q(t) are the file's
    auto state = [&](std::size_t k) {
        std::string s;
        for (std::size_t j = 0; j < n; ++j)
            s += (j ? ", " : "") + q[j].name() + " = " + deg(q_t[k][j]);
        return s;
    };
    for (std::size_t k = 0; k < n_t; ++k) {
        const std::vector<double>& p = model.at(q_t[k]);
        for (std::size_t s = 0; s < n_seg; ++s) {
            const double d = wrap(model_angle(p, s) - theta[s][k]);
            if (std::abs(d) > options.angle_tolerance_rad)
                throw ModelError(
                    caller + "at t = " + format_csv_number(t[k]) + " s the markers of " +
                    r.segments[s] + " are at " + deg(theta[s][k]) + " but the model puts them at " +
                    deg(model_angle(p, s)) + " (" + state(k) + "); check the sign and offset of '" +
                    coordinate_of(s) + "' and of the markers declared on " + r.segments[s]);
        }
    }
    // check: every marker where the model puts it, after one shift of origin
    auto measured = [&](std::size_t i, std::size_t k, int axis) {
        return trial.table.columns[trial.column(markers[i].name, axis)][k];
    };
    const int ah = options.plane.horizontal, av = options.plane.vertical;
    double sum_h = 0, sum_v = 0;
    for (std::size_t k = 0; k < n_t; ++k) {
        const std::vector<double>& p = model.at(q_t[k]);
        for (std::size_t i = 0; i < n_markers; ++i) {
            sum_h += measured(i, k, ah) - p[2 * i];
            sum_v += measured(i, k, av) - p[2 * i + 1];
        }
    }
    const double count = static_cast<double>(n_t * n_markers);
    r.origin_h = sum_h / count;
    r.origin_v = sum_v / count;
    r.marker_residual_m.assign(n_markers, 0);
    std::vector<std::size_t> worst_at(n_markers, 0);
    // the per-frame table: each marker name once (a joint's marker may serve two bodies)
    std::vector<std::size_t> column(n_markers, 0);
    r.residuals.add_column("time", "s");
    for (std::size_t i = 0; i < n_markers; ++i) {
        const auto& names = r.residuals.names;
        const auto it = std::find(names.begin() + 1, names.end(), markers[i].name);
        column[i] = it != names.end() ? static_cast<std::size_t>(it - names.begin())
                                      : r.residuals.add_column(markers[i].name, "m");
    }
    const std::size_t rms = r.residuals.add_column("rms", "m"), max = r.residuals.add_column("max", "m");
    for (std::size_t k = 0; k < n_t; ++k) {
        const std::vector<double>& p = model.at(q_t[k]);
        std::vector<double> row(r.residuals.names.size(), 0.0);
        for (std::size_t i = 0; i < n_markers; ++i) {
            const double d = std::hypot(measured(i, k, ah) - r.origin_h - p[2 * i],
                                        measured(i, k, av) - r.origin_v - p[2 * i + 1]);
            if (d > r.marker_residual_m[i]) r.marker_residual_m[i] = d, worst_at[i] = k;
            row[column[i]] = d;
        }
        double ss = 0, largest = 0;
        for (std::size_t c = 1; c < rms; ++c) ss += row[c] * row[c], largest = std::max(largest, row[c]);
        row[0] = trial.table.columns[0][k];
        row[rms] = std::sqrt(ss / static_cast<double>(rms - 1));
        row[max] = largest;
        for (std::size_t c = 0; c < row.size(); ++c) r.residuals.columns[c].push_back(row[c]);
    }
    // the marker farthest from the model, if beyond the tolerance
    const std::size_t i = static_cast<std::size_t>(
        std::max_element(r.marker_residual_m.begin(), r.marker_residual_m.end()) -
        r.marker_residual_m.begin());
    if (r.marker_residual_m[i] > options.position_tolerance_m) {
        const std::size_t k = worst_at[i];
        const auto it = std::find(r.segments.begin(), r.segments.end(), markers[i].body);
        const std::string who =
            it != r.segments.end()
                ? "'" + coordinate_of(static_cast<std::size_t>(it - r.segments.begin())) + "'"
                : "the coordinates";
        throw ModelError(
            caller + "at t = " + format_csv_number(t[k]) + " s marker '" + markers[i].name +
            "' (on " + markers[i].body + ") is " + cm(r.marker_residual_m[i]) +
            " from where the model puts it (" + state(k) + "), more than " +
            cm(options.position_tolerance_m) + "; check the sign and offset of " + who +
            ", the point the marker is declared at, and the model's lengths against the file's");
    }
    return r;
}

}  // namespace alembert
