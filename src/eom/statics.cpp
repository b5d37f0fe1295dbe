// SPDX-License-Identifier: MIT
// Nonlinear statics: damped Newton iteration with a symbolic Jacobian, a line search on |E|,
// bounds and sign conditions for the branch.
#include "alembert/eom/statics.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// E and J with every symbol but the unknowns replaced by its value
class Problem {
public:
    Problem(const SymbolTable& st, const std::vector<ex>& residuals,
            const std::vector<ex>& unknowns, const exmap& values)
        : st_(st), x_(unknowns) {
        ALEMBERT_CHECK_ARG(residuals.size() >= unknowns.size(),
                           "solve_equilibrium(): " + std::to_string(residuals.size()) +
                               " residuals for " + std::to_string(unknowns.size()) +
                               " unknowns; give at least one residual per unknown");
        for (const ex& x : unknowns)
            ALEMBERT_CHECK_ARG(GiNaC::is_a<GiNaC::symbol>(x),
                               "solve_equilibrium(): unknown '" + to_string(x) +
                                   "' is not a symbol");
        fixed_ = st.constant_values();
        for (const auto& [s, v] : values) fixed_[s] = v;
        for (const ex& x : unknowns) fixed_.erase(x);
        for (const ex& r : residuals) {
            open_.push_back(st.expand_intermediates(r));
            E_.push_back(close_expanded(open_.back()));
        }
        J_ = GiNaC::matrix(static_cast<unsigned>(E_.size()), static_cast<unsigned>(x_.size()));
        for (std::size_t i = 0; i < E_.size(); ++i)
            for (std::size_t j = 0; j < x_.size(); ++j)
                J_(static_cast<unsigned>(i), static_cast<unsigned>(j)) =
                    E_[i].diff(GiNaC::ex_to<GiNaC::symbol>(x_[j]));
    }

    // e with intermediates expanded and every known symbol replaced; speeds and
    // accelerations not given are 0 (at rest)
    ex close(const ex& e) { return close_expanded(st_.expand_intermediates(e)); }

    // the same for e with its intermediates expanded
    ex close_expanded(const ex& f) {
        for (const ex& s : symbols_of(f)) {
            if (fixed_.count(s) || is_unknown(s)) continue;
            if (st_.owns(s) && st_.kind(s) == SymbolKind::variable && st_.derivative_order(s) >= 1) {
                fixed_[s] = 0;
                continue;
            }
            std::string name = st_.owns(s) ? st_.name(s) : GiNaC::ex_to<GiNaC::symbol>(s).get_name();
            throw ArgumentError("solve_equilibrium(): '" + name +
                                "' has no value; give it one in `values` (or a value in the "
                                "symbol table), or list it among the unknowns");
        }
        return f.subs(fixed_);
    }

    std::size_t equations() const { return E_.size(); }
    std::size_t size() const { return x_.size(); }

    Eigen::VectorXd residual(const Eigen::VectorXd& x) const {
        exmap m = at(x);
        Eigen::VectorXd r(static_cast<Eigen::Index>(E_.size()));
        for (std::size_t i = 0; i < E_.size(); ++i) r(static_cast<Eigen::Index>(i)) = number(E_[i], m);
        return r;
    }

    Eigen::MatrixXd jacobian(const Eigen::VectorXd& x) const {
        exmap m = at(x);
        Eigen::MatrixXd J(static_cast<Eigen::Index>(E_.size()), static_cast<Eigen::Index>(x_.size()));
        for (unsigned i = 0; i < J_.rows(); ++i)
            for (unsigned j = 0; j < J_.cols(); ++j) J(i, j) = number(J_(i, j), m);
        return J;
    }

    double value(const ex& closed, const Eigen::VectorXd& x) const { return number(closed, at(x)); }

    // J at x with the entries that are rounding errors set to 0: an entry whose terms, before
    // the known values are put in (a substitution adds like terms up), cancel to 1e-10 of
    // their size (psi' sin(phi) cos(phi) - psi' cos(phi) sin(phi) at 1e-19)
    Eigen::MatrixXd jacobian_without_rounding(const Eigen::VectorXd& x) const {
        exmap m = fixed_;
        for (const auto& [s, v] : at(x)) m[s] = v;
        Eigen::MatrixXd J = jacobian(x);
        for (std::size_t i = 0; i < open_.size(); ++i)
            for (std::size_t j = 0; j < x_.size(); ++j) {
                const auto r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(j);
                const ex d = open_[i].diff(GiNaC::ex_to<GiNaC::symbol>(x_[j]));
                double size = std::abs(J(r, c));
                if (GiNaC::is_a<GiNaC::add>(d))
                    for (std::size_t k = 0; k < d.nops(); ++k) size = std::max(size, std::abs(number(d.op(k), m)));
                if (!(std::abs(J(r, c)) > 1e-10 * size)) J(r, c) = 0;
            }
        return J;
    }

    // "q = 1.5708, T = 3"
    std::string describe(const Eigen::VectorXd& x) const {
        std::ostringstream os;
        os.precision(8);
        for (std::size_t i = 0; i < x_.size(); ++i)
            os << (i ? ", " : "") << to_string(x_[i]) << " = " << x(static_cast<Eigen::Index>(i));
        return os.str();
    }

    bool is_unknown(const ex& s) const {
        return std::any_of(x_.begin(), x_.end(), [&](const ex& x) { return x.is_equal(s); });
    }

private:
    exmap at(const Eigen::VectorXd& x) const {
        exmap m;
        for (std::size_t i = 0; i < x_.size(); ++i) m[x_[i]] = x(static_cast<Eigen::Index>(i));
        return m;
    }
    static double number(const ex& e, const exmap& m) {
        ex v = GiNaC::evalf(e.subs(m));
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return kNaN;  // outside the domain (a root of a negative number): rejected
        return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    }

    const SymbolTable& st_;
    std::vector<ex> x_;
    exmap fixed_;
    std::vector<ex> open_;  // the residuals with their intermediates expanded, no values put in
    std::vector<ex> E_;
    GiNaC::matrix J_;
};

double max_abs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

bool finite(const Eigen::VectorXd& v) { return v.allFinite(); }

}  // namespace

double Equilibrium::value(const ex& x) const {
    for (std::size_t i = 0; i < unknowns.size(); ++i)
        if (unknowns[i].is_equal(x)) return values[i];
    throw ArgumentError("Equilibrium::value(): '" + to_string(x) +
                        "' is not one of the unknowns solved for");
}

exmap Equilibrium::as_map() const {
    exmap m;
    for (std::size_t i = 0; i < unknowns.size(); ++i) m[unknowns[i]] = values[i];
    return m;
}

std::vector<ex> residuals_of(const std::vector<RoadmapRow>& rows) {
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    return E;
}

Equilibrium solve_equilibrium(const SymbolTable& table, const std::vector<ex>& residuals,
                              const std::vector<ex>& unknowns, const exmap& guess,
                              const exmap& values, const StaticsOptions& options) {
    Problem P(table, residuals, unknowns, values);
    const auto n = static_cast<Eigen::Index>(P.size());

    // bounds: a box per unknown (infinite where none is given)
    Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
    Eigen::VectorXd hi = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
    for (const Bound& b : options.bounds) {
        auto it = std::find_if(unknowns.begin(), unknowns.end(),
                               [&](const ex& x) { return x.is_equal(b.variable); });
        ALEMBERT_CHECK_ARG(it != unknowns.end(), "solve_equilibrium(): the bound on '" +
                                                     to_string(b.variable) +
                                                     "' names no unknown; bound an unknown");
        ALEMBERT_CHECK_ARG(b.lower <= b.upper, "solve_equilibrium(): the bound on '" +
                                                   to_string(b.variable) +
                                                   "' is empty (lower > upper)");
        auto i = it - unknowns.begin();
        lo(i) = std::max(lo(i), b.lower);
        hi(i) = std::min(hi(i), b.upper);
    }
    auto clip = [&](Eigen::VectorXd x) { return x.cwiseMax(lo).cwiseMin(hi); };
    std::vector<ex> conditions;
    for (const SignCondition& c : options.conditions) conditions.push_back(P.close(c.expression));

    // the start: the guess, 0 where none is given, inside the box
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const ex& xi = unknowns[static_cast<std::size_t>(i)];
        auto g = guess.find(xi);
        ex v = g == guess.end() ? ex(0) : GiNaC::evalf(g->second);
        ALEMBERT_CHECK_ARG(GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real(),
                           "solve_equilibrium(): the guess for '" + to_string(xi) +
                               "' is not a real number");
        x(i) = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    }
    x = clip(x);

    Equilibrium out;
    out.unknowns = unknowns;
    Eigen::VectorXd E = P.residual(x);
    if (!finite(E))
        throw ArgumentError("solve_equilibrium(): the residuals are not real at the guess " +
                            P.describe(x) + "; start inside their domain");
    const double E0 = max_abs(E);
    double J_scale = 0;  // the largest singular value met: what "singular" is relative to
    bool singular_here = false;
    auto fail = [&](const std::string& why) {
        std::ostringstream os;
        os.precision(6);
        os << "solve_equilibrium(): no equilibrium found: " << why
           << "; last residual max|E| = " << max_abs(E) << " at " << P.describe(x)
           << " (it was " << E0 << " at the guess)"
           << (singular_here ? ", where the Jacobian dE/dx is singular" : "")
           << "; the equations may have no solution near this guess: change the guess, move "
              "or widen the bounds, or check the model's loads and signs";
        throw SolveError(os.str());
    };

    for (;; ++out.iterations) {
        if (max_abs(E) <= options.tolerance) break;
        if (out.iterations >= options.max_iterations)
            fail("no convergence in " + std::to_string(options.max_iterations) + " iterations");

        // newton step J dx = -E (least squares when there are more residuals than unknowns),
        // with the unknowns held that sit on a bound the step would cross (active set)
        Eigen::MatrixXd J = P.jacobian(x);
        std::vector<bool> held(static_cast<std::size_t>(n), false);
        Eigen::VectorXd dx;
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<Eigen::Index> free;
            for (Eigen::Index i = 0; i < n; ++i)
                if (!held[static_cast<std::size_t>(i)]) free.push_back(i);
            Eigen::MatrixXd Jf(J.rows(), static_cast<Eigen::Index>(free.size()));
            for (std::size_t c = 0; c < free.size(); ++c) Jf.col(static_cast<Eigen::Index>(c)) = J.col(free[c]);
            Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jf, Eigen::ComputeThinU | Eigen::ComputeThinV);
            const Eigen::VectorXd& sv = svd.singularValues();
            if (pass == 0) J_scale = std::max(J_scale, sv.size() ? sv(0) : 0.0);
            // singular: a singular value negligible beside the largest met, or so small that
            // the Newton step would exceed the iterate's size a trillion times
            double tau = std::max(1e-12 * J_scale, max_abs(E) / (1e12 * std::max(1.0, max_abs(x))));
            bool singular = !finite(sv) || (sv.size() > 0 && sv(sv.size() - 1) <= tau);
            if (pass == 0) singular_here = singular;
            if (singular) {
                if (!options.least_squares) {
                    std::ostringstream os;
                    os << "solve_equilibrium(): the Jacobian dE/dx is singular at iteration "
                       << out.iterations << " (rank " << (sv.array() > tau).count() << " of "
                       << sv.size() << ") at " << P.describe(x)
                       << "; the equations do not fix every unknown there: start from another "
                          "guess, or allow least-squares steps (StaticsOptions::least_squares)";
                    throw SolveError(os.str());
                }
                if (pass == 0) ++out.least_squares_steps;
                if (sv.size() > 0 && sv(0) > 0) svd.setThreshold(tau / sv(0));
            }
            Eigen::VectorXd df = free.empty() ? Eigen::VectorXd() : Eigen::VectorXd(svd.solve(-E));
            dx = Eigen::VectorXd::Zero(n);
            for (std::size_t c = 0; c < free.size(); ++c) dx(free[c]) = df(static_cast<Eigen::Index>(c));
            bool again = false;
            for (Eigen::Index i = 0; i < n; ++i)
                if ((x(i) <= lo(i) && dx(i) < 0) || (x(i) >= hi(i) && dx(i) > 0))
                    held[static_cast<std::size_t>(i)] = again = true;
            if (!again) break;
        }

        // a direction shortened to the step limit and to the box
        auto admissible = [&](Eigen::VectorXd d) {
            for (Eigen::Index i = 0; i < n; ++i)
                if ((x(i) <= lo(i) && d(i) < 0) || (x(i) >= hi(i) && d(i) > 0)) d(i) = 0;
            double s = 1;
            for (Eigen::Index i = 0; i < n; ++i) {
                double cap = options.max_step * std::max(1.0, std::abs(x(i)));
                if (std::abs(d(i)) > cap) s = std::min(s, cap / std::abs(d(i)));
                if (x(i) + s * d(i) > hi(i)) s = (hi(i) - x(i)) / d(i);
                if (x(i) + s * d(i) < lo(i)) s = (lo(i) - x(i)) / d(i);
            }
            return Eigen::VectorXd(s * d);
        };

        // backtracking on |E|^2 along a direction
        double phi = E.squaredNorm();
        auto search = [&](const Eigen::VectorXd& d, double armijo, Eigen::VectorXd& x_new,
                          Eigen::VectorXd& E_new) {
            for (double t = 1; t > 1e-12; t /= 2) {
                x_new = clip(x + t * d);
                if (x_new == x) return false;
                E_new = P.residual(x_new);
                if (finite(E_new) && E_new.squaredNorm() <= (1 - armijo * t) * phi) return true;
            }
            return false;
        };
        Eigen::VectorXd x_new, E_new;
        bool moved = finite(dx) && search(admissible(dx), 1e-4, x_new, E_new);
        if (!moved) {
            // steepest descent of |E|^2 when no Newton step helps
            Eigen::VectorXd g = -J.transpose() * E;
            moved = finite(g) && search(admissible(g), 0.0, x_new, E_new);
        }
        if (!moved)
            fail("stalled after " + std::to_string(out.iterations) +
                 " iterations, no step decreases |E| (a local minimum of |E| that is not 0" +
                 std::string(options.bounds.empty() ? ")" : ", or a bound in the way)"));
        x = x_new;
        E = E_new;
    }

    if (options.require_determined && P.equations() == P.size() && n > 0) {
        // the equations must fix every unknown at the solution: a singular Jacobian leaves an
        // unknown (the largest part of the null direction) at whatever the guess gave
        Eigen::MatrixXd J = P.jacobian_without_rounding(x);
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
        const Eigen::VectorXd sv = svd.singularValues();
        // negligible beside the largest singular value met (all of them when J is 0)
        const double scale = std::max(J_scale, sv(0));
        auto negligible = [&](double v) { return !(v > 1e-12 * scale); };
        if (!finite(sv) || negligible(sv(n - 1))) {
            Eigen::Index j = 0;
            svd.matrixV().col(n - 1).cwiseAbs().maxCoeff(&j);
            auto name = [&](Eigen::Index i) {
                const auto k = static_cast<std::size_t>(i);
                return k < options.residual_names.size() ? options.residual_names[k]
                                                         : "E[" + std::to_string(k + 1) + "]";
            };
            std::string rows;
            for (Eigen::Index i = 0; i < J.rows(); ++i)
                if (negligible(std::abs(J(i, j))))
                    rows += (rows.empty() ? "" : ", ") + name(i);
            std::ostringstream os;
            os.precision(8);
            os << "solve_equilibrium(): the equations do not fix '" << to_string(unknowns[static_cast<std::size_t>(j)])
               << "' at the solution found (" << P.describe(x) << ", after " << out.iterations
               << " iterations): the Jacobian dE/dx is singular there (rank "
               << std::count_if(sv.data(), sv.data() + n, [&](double v) { return !negligible(v); })
               << " of " << n << ")"
               << (rows.empty() ? std::string() : ", and " + rows + (rows.find(',') == std::string::npos ? " does" : " do") +
                                                   " not change with it")
               << ", so its value is the guess's, not an answer; solve for an unknown the "
                  "equations depend on at this state, or from equations that hold it";
            throw SolveError(os.str());
        }
        // refined to rounding: full Newton steps while max|E| falls
        for (int polish = 0; polish < 3 && max_abs(E) > 0; ++polish) {
            Eigen::VectorXd x_new = clip(x + Eigen::VectorXd(P.jacobian(x).fullPivLu().solve(-E)));
            Eigen::VectorXd E_new = P.residual(x_new);
            if (!finite(E_new) || !(max_abs(E_new) < max_abs(E))) break;
            x = x_new;
            E = E_new;
        }
    }

    // the branch
    for (std::size_t c = 0; c < conditions.size(); ++c) {
        const SignCondition& sc = options.conditions[c];
        double v = P.value(conditions[c], x);
        if (sc.positive ? v > 0 : v < 0) continue;
        std::ostringstream os;
        os.precision(8);
        os << "solve_equilibrium(): the equilibrium found (" << P.describe(x) << ", after "
           << out.iterations << " iterations) lies outside the requested branch: condition "
           << (sc.label.empty() ? "" : "'" + sc.label + "' ") << "requires "
           << to_string(sc.expression) << (sc.positive ? " > 0" : " < 0") << " but it is " << v
           << " there; start from a guess in the wanted branch, or add bounds that exclude "
              "this solution";
        throw SolveError(os.str());
    }
    out.residual = max_abs(E);
    out.values.assign(x.data(), x.data() + n);
    return out;
}

}  // namespace alembert
