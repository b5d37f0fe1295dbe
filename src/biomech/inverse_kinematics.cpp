// SPDX-License-Identifier: MIT
// Inverse kinematics by Levenberg-Marquardt over compiled marker positions and their Jacobian.
#include "alembert/biomech/inverse_kinematics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {
namespace ik {

constexpr const char* kSolve = "InverseKinematics::solve()";
constexpr const char* kBuild = "InverseKinematics()";

std::string quoted_list(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", '" : "'") + names[i] + "'";
    return s;
}

std::string seconds(double t) { return format_csv_number(t) + " s"; }
std::string millimetres(double d) { return format_csv_number(1000 * d, 3) + " mm"; }

// true if `e` holds a trigonometric function whose argument depends on `q`
bool enters_trigonometrically(const ex& e, const ex& q) {
    if (GiNaC::is_exactly_a<GiNaC::function>(e) &&
        (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) ||
         GiNaC::is_the_function<GiNaC::cos_SERIAL>(e) ||
         GiNaC::is_the_function<GiNaC::tan_SERIAL>(e)) &&
        e.op(0).has(q))
        return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (enters_trigonometrically(e.op(i), q)) return true;
    return false;
}

// the coordinates (by name) along which the columns of J leave a combination free: those
// with a component in J's null space (numerically: singular values below tol * the largest)
std::vector<std::string> free_coordinates(const Eigen::MatrixXd& J,
                                          const std::vector<std::string>& names, double tol) {
    const auto n = static_cast<Eigen::Index>(names.size());
    if (J.rows() == 0) return names;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double s_max = s.size() ? s(0) : 0.0;
    Eigen::Index rank = 0;
    while (rank < s.size() && s(rank) > tol * s_max && s(rank) > 0) ++rank;
    std::vector<std::string> free;
    if (rank == n) return free;
    const Eigen::MatrixXd null = svd.matrixV().rightCols(n - rank);
    for (Eigen::Index k = 0; k < n; ++k)
        if (null.row(k).norm() > 1e-6) free.push_back(names[static_cast<std::size_t>(k)]);
    return free;
}

// free_coordinates, with a cheap screen first: the eigenvalues of J^T J (n x n) bound the
// singular values of J as sqrt(lambda) to within sqrt(eps lambda_max), so a ratio above 1e-6
// clears every tolerance below that without the singular value decomposition of J
std::vector<std::string> free_coordinates_screened(const Eigen::MatrixXd& J,
                                                   const std::vector<std::string>& names,
                                                   double tol) {
    if (J.rows() >= J.cols() && tol < 1e-6) {
        const Eigen::MatrixXd A = J.transpose() * J;
        const Eigen::VectorXd lambda =
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
        if (lambda(0) > 1e-12 * lambda(lambda.size() - 1)) return {};
    }
    return free_coordinates(J, names, tol);
}

// what one frame's fit needs, allocated once per solve
struct FrameProblem {
    const CompiledExpressions* tape = nullptr;
    std::size_t m = 0, n = 0;
    std::vector<double> sqrt_w;          // per marker
    std::vector<double> measured;        // 3 m, this frame
    std::vector<std::size_t> present;    // markers present in this frame
    std::vector<double> out, workspace;  // tape outputs and scratch
    Eigen::VectorXd r;                   // weighted residuals of the markers present
    Eigen::MatrixXd J;                   // their weighted Jacobian

    // evaluates r(q) and J(q) over the markers present; returns the cost 0.5 |r|^2
    double evaluate(const Eigen::VectorXd& q) {
        tape->evaluate(q.data(), out.data(), workspace.data());
        const auto rows = static_cast<Eigen::Index>(3 * present.size());
        r.resize(rows);
        J.resize(rows, static_cast<Eigen::Index>(n));
        Eigen::Index row = 0;
        for (std::size_t i : present)
            for (std::size_t a = 0; a < 3; ++a, ++row) {
                r(row) = sqrt_w[i] * (out[3 * i + a] - measured[3 * i + a]);
                const double* dp = out.data() + 3 * m + (3 * i + a) * n;
                for (std::size_t k = 0; k < n; ++k)
                    J(row, static_cast<Eigen::Index>(k)) = sqrt_w[i] * dp[k];
            }
        return 0.5 * r.squaredNorm();
    }
};

struct FitOutcome {
    bool converged = false;
    int iterations = 0;
    double last_step = 0;
};

// Levenberg-Marquardt from q (updated in place), damping mu I with Nielsen's update
// (Madsen, Nielsen and Tingleff 2004, algorithm 3.16) from mu = tau max diag(J^T J): tau
// small where q is believed close (a warm start); J and r are left at the solution
FitOutcome fit_frame(FrameProblem& p, Eigen::VectorXd& q, const InverseKinematicsOptions& o,
                     double tau) {
    FitOutcome res;
    const auto n = static_cast<Eigen::Index>(p.n);
    double F = p.evaluate(q);
    Eigen::MatrixXd A = p.J.transpose() * p.J;
    Eigen::VectorXd g = p.J.transpose() * p.r;
    if (F == 0 || g.lpNorm<Eigen::Infinity>() <= o.gradient_tolerance) {
        res.converged = true;
        return res;
    }
    // initial damping from the scale of J^T J
    double mu = tau * std::max(A.diagonal().maxCoeff(), std::numeric_limits<double>::min());
    double nu = 2;
    Eigen::VectorXd q_old = q, r_old = p.r, h(n), g_new(n);
    Eigen::MatrixXd J_old = p.J, A_mu(n, n);
    while (res.iterations < o.max_iterations) {
        ++res.iterations;
        // damped Gauss-Newton step: (J^T J + mu I) h = -J^T r
        A_mu = A;
        A_mu.diagonal().array() += mu;
        h = A_mu.llt().solve(-g);
        res.last_step = h.norm();
        const bool small_step = res.last_step <= o.step_tolerance * (1 + q.norm());
        // trial point
        q_old = q, r_old = p.r, J_old = p.J;
        q += h;
        const double F_new = p.evaluate(q);
        g_new.noalias() = p.J.transpose() * p.r;
        // accept when the cost falls as predicted; where the change in cost is lost in its
        // rounding (a few ulps of F, near a minimum with residuals), when the gradient falls
        const double predicted = 0.5 * h.dot(mu * h - g);
        const double rho = predicted > 0 ? (F - F_new) / predicted : -1;
        const bool in_rounding =
            std::abs(F - F_new) <= 64 * std::numeric_limits<double>::epsilon() * F;
        const bool accept = in_rounding ? g_new.squaredNorm() < g.squaredNorm() : rho > 0;
        if (accept) {
            F = F_new;
            A.noalias() = p.J.transpose() * p.J;
            g = g_new;
            mu *= in_rounding ? 1.0 / 3.0 : std::max(1.0 / 3.0, 1 - std::pow(2 * rho - 1, 3));
            nu = 2;
            if (small_step || F == 0 || g.lpNorm<Eigen::Infinity>() <= o.gradient_tolerance) {
                res.converged = true;
                break;
            }
        } else {
            // rejected: back to the last point, more damping
            q = q_old, p.r = r_old, p.J = J_old;
            if (small_step) {
                res.converged = true;  // no step this small lowers the cost or the gradient
                break;
            }
            mu *= nu;
            nu *= 2;
        }
    }
    // polish: undamped Gauss-Newton steps while they lower the gradient, so a stop on a step
    // that damping made small still ends at the minimum to rounding
    for (int k = 0; res.converged && k < 3 && F > 0; ++k) {
        h = A.ldlt().solve(-g);
        q_old = q, r_old = p.r, J_old = p.J;
        q += h;
        const double F_new = p.evaluate(q);
        g_new.noalias() = p.J.transpose() * p.r;
        ++res.iterations;
        if (!(g_new.squaredNorm() < g.squaredNorm())) {
            q = q_old, p.r = r_old, p.J = J_old;
            break;
        }
        F = F_new;
        A.noalias() = p.J.transpose() * p.J;
        g = g_new;
        if (h.norm() <= o.step_tolerance * (1 + q.norm())) break;
    }
    return res;
}

}  // namespace ik
}  // namespace

InverseKinematics::InverseKinematics(System& system, std::vector<ex> coordinates,
                                     std::vector<MarkerPoint> markers,
                                     InverseKinematicsOptions options)
    : markers_(std::move(markers)), options_(std::move(options)) {
    SymbolTable& table = system.symbols();
    // check the coordinates
    if (coordinates.empty())
        throw ArgumentError(std::string(ik::kBuild) +
                            ": no coordinates given; list the model's coordinates to solve for");
    for (const ex& q : coordinates) {
        if (!GiNaC::is_a<GiNaC::symbol>(q) || !table.owns(q))
            throw ArgumentError(std::string(ik::kBuild) + ": coordinate '" + to_string(q) +
                                "' is not a symbol of the model; pass the model's coordinates");
        const std::string& name = table.name(q);
        if (std::find(coordinate_names_.begin(), coordinate_names_.end(), name) !=
            coordinate_names_.end())
            throw ArgumentError(std::string(ik::kBuild) + ": coordinate '" + name +
                                "' is listed twice; list each coordinate once");
        coordinate_names_.push_back(name);
    }
    const std::size_t n = coordinates.size(), m = markers_.size();
    if (!options_.initial.empty() && options_.initial.size() != n)
        throw ArgumentError(std::string(ik::kBuild) + ": options.initial has " +
                            std::to_string(options_.initial.size()) + " values for " +
                            std::to_string(n) + " coordinates; give one per coordinate or none");
    // check the markers
    if (markers_.empty())
        throw ArgumentError(std::string(ik::kBuild) +
                            ": no model markers given; list the model's marker points");
    std::set<std::string> seen;
    for (const MarkerPoint& mk : markers_) {
        if (mk.name.empty())
            throw ArgumentError(
                std::string(ik::kBuild) +
                ": a model marker has an empty name; name it as the marker file does");
        if (!seen.insert(mk.name).second)
            throw ArgumentError(std::string(ik::kBuild) + ": model marker '" + mk.name +
                                "' is listed twice; list each marker once");
        if (mk.point == nullptr)
            throw ArgumentError(std::string(ik::kBuild) + ": model marker '" + mk.name +
                                "' has no point; give the model point it is stuck on");
        if (!(mk.weight > 0) || !std::isfinite(mk.weight))
            throw ArgumentError(std::string(ik::kBuild) + ": model marker '" + mk.name +
                                "' has weight " + format_csv_number(mk.weight) +
                                "; a weight must be positive and finite");
    }
    // positions p_i = r^{P_i/N_o} in N, and which symbols they use
    std::vector<ex> positions;
    positions.reserve(3 * m);
    for (const MarkerPoint& mk : markers_) {
        const Col3 p = mk.point->pos_from(system.origin()).components_in(system.newtonian());
        for (const ex& e : p.v) {
            for (const ex& s : table.calc_leaf_symbols(e)) {
                if (std::find(coordinates.begin(), coordinates.end(), s) != coordinates.end())
                    continue;
                if (table.kind(s) == SymbolKind::constant && table.value(s)) continue;
                throw ArgumentError(
                    std::string(ik::kBuild) + ": the position of model marker '" + mk.name +
                    "' (point '" + mk.point->name() + "') uses '" + table.name(s) + "', a " +
                    to_string(table.kind(s)) +
                    (table.kind(s) == SymbolKind::constant ? " with no value" : "") +
                    " that is not among the coordinates; list it as a coordinate or give it a "
                    "value");
            }
            positions.push_back(e);
        }
    }
    // units: a coordinate inside a trigonometric function is an angle
    for (const ex& q : coordinates) {
        bool angle = false;
        for (const ex& e : positions)
            if (ik::enters_trigonometrically(table.expand_intermediates(e), q)) {
                angle = true;
                break;
            }
        units_.push_back(angle ? "rad" : "m");
    }
    // analytic Jacobian dp/dq, row-major after the positions, compiled once with them
    std::vector<ex> outputs = positions;
    outputs.reserve(3 * m * (1 + n));
    for (const ex& e : positions)
        for (const ex& q : coordinates) outputs.push_back(table.diff(e, q));
    tape_ = CompiledExpressions(table, coordinates, outputs);
    // the markers must fix every coordinate: full column rank at a generic configuration
    std::mt19937 random(20240611);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double> q_generic(n), out(tape_.output_count());
    for (double& v : q_generic) v = uniform(random);
    tape_.evaluate(q_generic.data(), out.data());
    Eigen::MatrixXd J(static_cast<Eigen::Index>(3 * m), static_cast<Eigen::Index>(n));
    for (std::size_t row = 0; row < 3 * m; ++row)
        for (std::size_t k = 0; k < n; ++k)
            J(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(k)) =
                std::sqrt(markers_[row / 3].weight) * out[3 * m + row * n + k];
    const std::vector<std::string> free =
        ik::free_coordinates(J, coordinate_names_, options_.rank_tolerance);
    if (!free.empty()) {
        const std::string counts =
            std::to_string(m) + " markers give " + std::to_string(3 * m) + " measured coordinates";
        throw ModelError(
            std::string(ik::kBuild) + ": inverse kinematics is under-determined: " +
            (3 * m < n ? counts + ", fewer than the " + std::to_string(n) + " coordinates; "
                       : std::string("the markers' positions do not change along a combination "
                                     "of coordinates; ")) +
            "the markers do not fix " + ik::quoted_list(free) +
            "; add markers on the segments these coordinates move (at least three per segment, "
            "not on one line)");
    }
}

std::vector<double> InverseKinematics::calc_marker_positions(const std::vector<double>& q) const {
    if (q.size() != coordinate_names_.size())
        throw ArgumentError(
            "InverseKinematics::calc_marker_positions(): " + std::to_string(q.size()) +
            " values for " + std::to_string(coordinate_names_.size()) + " coordinates");
    std::vector<double> out = tape_.evaluate(std::span<const double>(q));
    out.resize(3 * markers_.size());
    return out;
}

InverseKinematicsResult InverseKinematics::solve(const MarkerTable& markers) const {
    const std::size_t n = coordinate_names_.size(), m = markers_.size();
    const std::size_t frames = markers.table.row_count();
    // every model marker must be in the file
    std::vector<std::array<std::size_t, 3>> columns;
    for (const MarkerPoint& mk : markers_) {
        if (std::find(markers.markers.begin(), markers.markers.end(), mk.name) ==
            markers.markers.end())
            throw ArgumentError(
                std::string(ik::kSolve) + ": model marker '" + mk.name +
                "' is not in the marker file (its markers: " + ik::quoted_list(markers.markers) +
                "); name the model marker as the file does");
        columns.push_back(
            {markers.column(mk.name, 0), markers.column(mk.name, 1), markers.column(mk.name, 2)});
    }
    if (frames == 0)
        throw ArgumentError(std::string(ik::kSolve) + ": the marker table has no frames");

    InverseKinematicsResult result;
    result.coordinates = coordinate_names_;
    result.units = units_;
    for (const MarkerPoint& mk : markers_) result.markers.push_back(mk.name);
    result.frames.reserve(frames);

    ik::FrameProblem p;
    p.tape = &tape_;
    p.m = m;
    p.n = n;
    for (const MarkerPoint& mk : markers_) p.sqrt_w.push_back(std::sqrt(mk.weight));
    p.measured.resize(3 * m);
    p.out.resize(tape_.output_count());
    p.workspace.resize(tape_.workspace_size());

    Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < options_.initial.size(); ++k)
        q(static_cast<Eigen::Index>(k)) = options_.initial[k];
    const std::vector<double>& time = markers.table.columns.front();

    for (std::size_t f = 0; f < frames; ++f) {
        InverseKinematicsFrame frame;
        frame.time = time[f];
        auto where = [&] {
            return "frame " + std::to_string(f + 1) + " (t = " + ik::seconds(frame.time) + ")";
        };
        // this frame's measured markers; a marker with a NaN coordinate is skipped
        p.present.clear();
        for (std::size_t i = 0; i < m; ++i) {
            bool seen = true;
            for (std::size_t a = 0; a < 3; ++a) {
                p.measured[3 * i + a] = markers.table.columns[columns[i][a]][f];
                seen = seen && std::isfinite(p.measured[3 * i + a]);
            }
            if (seen)
                p.present.push_back(i);
            else
                frame.missing.push_back(markers_[i].name);
        }
        // fit from the previous frame's coordinates
        const ik::FitOutcome fit = ik::fit_frame(p, q, options_, f == 0 ? 1e-3 : 1e-6);
        frame.iterations = fit.iterations;
        if (!fit.converged)
            throw SolveError(std::string(ik::kSolve) + ": " + where() + " did not converge in " +
                             std::to_string(fit.iterations) + " iterations (last step " +
                             format_csv_number(fit.last_step, 3) + ", RMS marker residual " +
                             ik::millimetres(p.present.empty()
                                                 ? 0.0
                                                 : p.r.norm() / std::sqrt(static_cast<double>(
                                                                    p.present.size()))) +
                             "); start the first frame nearer the subject's pose "
                             "(options.initial), allow more iterations, or check the marker "
                             "names and the model's dimensions");
        // the markers present must fix the coordinates here
        const std::vector<std::string> free =
            ik::free_coordinates_screened(p.J, coordinate_names_, options_.rank_tolerance);
        if (!free.empty())
            throw SolveError(
                std::string(ik::kSolve) + ": at " + where() + " the markers " +
                (frame.missing.empty()
                     ? std::string("")
                     : "present (" + ik::quoted_list(frame.missing) + " missing) ") +
                "do not fix " + ik::quoted_list(free) +
                "; fill the gaps first (regularize_time_base), trim the trial, or "
                "add markers" +
                (frame.missing.empty() ? " (the model may be at a singular pose)" : ""));
        // residual distances of the markers present (r holds sqrt(w_i) (p_i - m_i) at q)
        frame.q.assign(q.data(), q.data() + q.size());
        frame.residual.assign(m, std::numeric_limits<double>::quiet_NaN());
        double sum2 = 0;
        frame.max = -1;
        for (std::size_t j = 0; j < p.present.size(); ++j) {
            const std::size_t i = p.present[j];
            const double d2 =
                p.r.segment(static_cast<Eigen::Index>(3 * j), 3).squaredNorm() / markers_[i].weight;
            frame.residual[i] = std::sqrt(d2);
            sum2 += d2;
            if (frame.residual[i] > frame.max) {
                frame.max = frame.residual[i];
                frame.worst_marker = markers_[i].name;
            }
        }
        frame.rms = std::sqrt(sum2 / static_cast<double>(p.present.size()));
        result.frames.push_back(std::move(frame));
    }
    // stretches of frames where a marker was missing
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t f = 0; f < frames; ++f) {
            if (!std::isnan(result.frames[f].residual[i])) continue;
            Gap gap{markers_[i].name, time[f], time[f], 0};
            while (f < frames && std::isnan(result.frames[f].residual[i]))
                gap.t_last = time[f], ++gap.samples, ++f;
            result.gaps.push_back(gap);
        }
    }
    return result;
}

Table InverseKinematicsResult::calc_coordinate_table() const {
    Table t;
    t.add_column("time", "s");
    for (std::size_t k = 0; k < coordinates.size(); ++k)
        t.add_column(coordinates[k], k < units.size() ? units[k] : "");
    for (const InverseKinematicsFrame& f : frames) {
        t.columns[0].push_back(f.time);
        for (std::size_t k = 0; k < f.q.size(); ++k) t.columns[1 + k].push_back(f.q[k]);
    }
    return t;
}

Table InverseKinematicsResult::calc_residual_table() const {
    Table t;
    t.add_column("time", "s");
    for (const std::string& name : markers) t.add_column(name, "m");
    const std::size_t rms = t.add_column("rms", "m"), max = t.add_column("max", "m");
    for (const InverseKinematicsFrame& f : frames) {
        t.columns[0].push_back(f.time);
        for (std::size_t i = 0; i < f.residual.size(); ++i)
            t.columns[1 + i].push_back(f.residual[i]);
        t.columns[rms].push_back(f.rms);
        t.columns[max].push_back(f.max);
    }
    return t;
}

std::string InverseKinematicsResult::describe() const {
    std::string s = "inverse kinematics: " + std::to_string(frames.size()) + " frames, " +
                    std::to_string(coordinates.size()) + " coordinates, " +
                    std::to_string(markers.size()) +
                    " markers; Levenberg-Marquardt with the analytic Jacobian, each frame "
                    "started from the one before\n";
    if (frames.empty()) return s;
    // iterations and residuals over the trial
    int iterations = 0, most = 0;
    double rms_sum = 0;
    std::size_t worst_rms = 0, worst = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        iterations += frames[f].iterations;
        most = std::max(most, frames[f].iterations);
        rms_sum += frames[f].rms;
        if (frames[f].rms > frames[worst_rms].rms) worst_rms = f;
        if (frames[f].max > frames[worst].max) worst = f;
    }
    const auto count = static_cast<double>(frames.size());
    s += "iterations per frame: " + format_csv_number(iterations / count, 3) + " on average, " +
         std::to_string(most) + " at most\n";
    s += "RMS marker residual per frame: " + ik::millimetres(rms_sum / count) + " on average, " +
         ik::millimetres(frames[worst_rms].rms) +
         " at most (t = " + ik::seconds(frames[worst_rms].time) + ")\n";
    s += "largest marker residual: " + ik::millimetres(frames[worst].max) + ", '" +
         frames[worst].worst_marker + "' at t = " + ik::seconds(frames[worst].time) + "\n";
    // each marker's RMS over the frames where it was present
    s += "RMS residual per marker:";
    for (std::size_t i = 0; i < markers.size(); ++i) {
        double sum2 = 0;
        std::size_t present = 0;
        for (const InverseKinematicsFrame& f : frames)
            if (!std::isnan(f.residual[i])) sum2 += f.residual[i] * f.residual[i], ++present;
        s += (i ? ", '" : " '") + markers[i] + "' " +
             (present ? ik::millimetres(std::sqrt(sum2 / static_cast<double>(present)))
                      : std::string("never present"));
    }
    s += "\n";
    for (const Gap& g : gaps)
        s += "'" + g.name + "' is missing from t = " + ik::seconds(g.t_first) + " to " +
             ik::seconds(g.t_last) + " (" + std::to_string(g.samples) +
             (g.samples == 1 ? " frame" : " frames") + "), left out of those frames' fits\n";
    return s;
}

InverseKinematicsResult calc_inverse_kinematics(System& system, const std::vector<ex>& coordinates,
                                                const std::vector<MarkerPoint>& markers,
                                                const MarkerTable& table,
                                                const InverseKinematicsOptions& options) {
    return InverseKinematics(system, coordinates, markers, options).solve(table);
}

}  // namespace alembert
