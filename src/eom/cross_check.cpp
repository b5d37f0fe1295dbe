// SPDX-License-Identifier: MIT
// Road-map, Kane, Lagrange and brute-force Newton–Euler side by side at random states.
#include "alembert/eom/cross_check.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/lagrange.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {

// one method's residuals E, linear in the unknowns x (E = b - A x), compiled once as functions
// of x and the state; A and b come from evaluations at x = 0 and x = s e_j
class CompiledMethod {
public:
    CompiledMethod(std::string name, const SymbolTable& st, const std::vector<ex>& residuals,
                   std::vector<ex> x, const std::vector<ex>& state)
        : name_(std::move(name)), x_(std::move(x)) {
        if (residuals.size() != x_.size())
            throw ModelError("compare_methods(): the " + name_ + " method gives " +
                             std::to_string(residuals.size()) + " equations in " +
                             std::to_string(x_.size()) + " unknowns");
        std::vector<ex> inputs = x_;
        inputs.insert(inputs.end(), state.begin(), state.end());
        E_ = CompiledExpressions(st, std::move(inputs), residuals);
    }

    const std::string& name() const { return name_; }

    // x at the state (values in the order of the `state` symbols), evaluated and solved in
    // extended precision so that the comparison sees the methods, not rounding in long sums
    // and in the LU of an ill-conditioned mass matrix
    Eigen::VectorXd solve(const std::vector<double>& state) const {
        using Real = long double;
        // a power of two: A_j = (b - E(s e_j)) / s exactly scaled, b's rounding divided by s
        constexpr Real s = 1 << 20;
        const auto n = static_cast<Eigen::Index>(x_.size());
        std::vector<Real> in(x_.size(), 0.0L);
        in.insert(in.end(), state.begin(), state.end());
        VectorXld b(n), e(n), e2(n);
        MatrixXld A(n, n);
        E_.evaluate_extended(in.data(), b.data());
        for (Eigen::Index j = 0; j < n; ++j) {
            in[static_cast<std::size_t>(j)] = s;
            E_.evaluate_extended(in.data(), e.data());
            in[static_cast<std::size_t>(j)] = 2 * s;
            E_.evaluate_extended(in.data(), e2.data());
            in[static_cast<std::size_t>(j)] = 0;
            A.col(j) = (b - e) / s;
            // linear: E(2 s e_j) = b - 2 s A_j
            Real scale = 1 + b.cwiseAbs().maxCoeff() + 2 * s * A.col(j).cwiseAbs().maxCoeff();
            if (!((e2 - (b - 2 * s * A.col(j))).cwiseAbs().maxCoeff() <= 1e-9L * scale))
                throw SolveError("compare_methods(): the " + name_ +
                                 " equations are not linear in '" +
                                 to_string(x_[static_cast<std::size_t>(j)]) + "'");
        }
        return solve_extended(A, b,
                              "compare_methods(): the " + name_ +
                                  " coefficient matrix at a drawn state",
                              "; the configuration may be singular");
    }

private:
    std::string name_;
    std::vector<ex> x_;
    CompiledExpressions E_;
};

// accelerations given explicitly (the articulated-body recursion), evaluated at the state
class ExplicitMethod {
public:
    ExplicitMethod(std::string name, const SymbolTable& st, const std::vector<ex>& accelerations,
                   const std::vector<ex>& state)
        : name_(std::move(name)), x_(st, state, accelerations) {}
    const std::string& name() const { return name_; }
    Eigen::VectorXd solve(const std::vector<double>& state) const {
        std::vector<long double> in(state.begin(), state.end());
        VectorXld x(static_cast<Eigen::Index>(x_.output_count()));
        x_.evaluate_extended(in.data(), x.data());
        return x.cast<double>();
    }

private:
    std::string name_;
    CompiledExpressions x_;
};

// the symbols a random state gives values to (coordinates, speeds, with_accelerations: the
// accelerations too, specified inputs, unknown loads not excluded, constants without a value,
// the time) and the draws: the varying ones from [-1, 1], constants and the time from
// [0.5, 1.5], in the order of symbols(); deterministic for a seed
class StateSampler {
public:
    StateSampler(const SymbolTable& st, const std::vector<ex>& excluded, bool with_accelerations,
                 unsigned seed)
        : rng_(seed) {
        auto is_excluded = [&](const ex& s) {
            return std::any_of(excluded.begin(), excluded.end(),
                               [&](const ex& x) { return x.is_equal(s); });
        };
        for (SymbolKind kind : {SymbolKind::variable, SymbolKind::specified, SymbolKind::unknown})
            for (const ex& s : st.symbols(kind))
                if (!(kind == SymbolKind::variable && st.derivative_order(s) >= 2 &&
                      !with_accelerations) &&
                    !is_excluded(s))
                    symbols_.push_back(s);
        varying_ = symbols_.size();
        for (const ex& c : st.symbols(SymbolKind::constant))
            if (!st.value(c)) symbols_.push_back(c);
        symbols_.push_back(st.time());
    }

    const std::vector<ex>& symbols() const { return symbols_; }

    std::vector<double> draw() {
        std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 1.5);
        std::vector<double> values;
        for (std::size_t i = 0; i < symbols_.size(); ++i)
            values.push_back(i < varying_ ? unit(rng_) : positive(rng_));
        return values;
    }

private:
    std::vector<ex> symbols_;
    std::size_t varying_ = 0;
    std::mt19937 rng_;
};

// makes a drawn state satisfy the model's constraints: Newton's method on dependent
// coordinates for the configuration constraints, then the dependent speeds from the
// constraints at the velocity level and, when the state holds the accelerations (inverse
// dynamics), the dependent accelerations from the acceleration level; both levels are linear
// in their unknowns. The dependent ones are chosen at each state by a column-pivoted QR
// decomposition of the constraints' coefficient matrix, so any independent set serves.
class ConstraintProjector {
public:
    ConstraintProjector(const System& sys, const std::vector<TimeVariable>& q,
                        const std::vector<ex>& state, bool accelerations) {
        if (sys.constraints().empty()) return;
        // the model's own table: differentiating names z' intermediates there
        SymbolTable& st = sys.newtonian().symbols();
        std::vector<ex> f, g, h;
        for (const Constraint& c : sys.constraints()) {
            ex e = c.residual;
            if (c.kind == ConstraintKind::configuration) {
                f.push_back(e);
                e = st.dt(e);
            }
            g.push_back(e);
            if (accelerations) h.push_back(st.dt(e));
        }
        auto index_of = [&](const ex& s) {
            for (std::size_t i = 0; i < state.size(); ++i)
                if (state[i].is_equal(s)) return i;
            throw InternalError("compare_reactions(): '" + to_string(s) +
                                "' is not among the drawn state's symbols");
        };
        for (const TimeVariable& qi : q) {
            at_[0].push_back(index_of(qi.symbol()));
            at_[1].push_back(index_of(qi.d(1)));
            if (accelerations) at_[2].push_back(index_of(qi.d(2)));
        }
        // the configuration residuals, then their Jacobian row by row
        std::vector<ex> fJ = f;
        for (const ex& fk : f) {
            ex plain = st.expand_intermediates(fk);
            for (const TimeVariable& qi : q)
                fJ.push_back(plain.diff(GiNaC::ex_to<GiNaC::symbol>(qi.symbol())));
        }
        configurations_ = f.size();
        if (!f.empty()) f_ = CompiledExpressions(st, state, fJ);
        g_ = CompiledExpressions(st, state, g);
        if (accelerations) h_ = CompiledExpressions(st, state, h);
    }

    // false when Newton's method does not converge from this draw (draw again)
    bool project(std::vector<double>& values) const {
        if (g_.output_count() == 0) return true;
        std::vector<long double> v(values.begin(), values.end());
        const auto n = static_cast<Eigen::Index>(at_[0].size());
        if (configurations_ > 0) {
            const auto m = static_cast<Eigen::Index>(configurations_);
            std::vector<long double> out(static_cast<std::size_t>(m + m * n));
            bool converged = false;
            for (int iteration = 0; iteration < 60 && !converged; ++iteration) {
                f_.evaluate_extended(v.data(), out.data());
                VectorXld r(m);
                MatrixXld J(m, n);
                for (Eigen::Index k = 0; k < m; ++k) {
                    r(k) = out[static_cast<std::size_t>(k)];
                    for (Eigen::Index j = 0; j < n; ++j)
                        J(k, j) = out[static_cast<std::size_t>(m + k * n + j)];
                }
                if (!r.allFinite() || !J.allFinite()) return false;
                if (r.cwiseAbs().maxCoeff() < 1e-16L) {
                    converged = true;
                    break;
                }
                std::vector<Eigen::Index> dep = pick_dependent(J);
                if (dep.empty()) return false;
                VectorXld dx = columns(J, dep).fullPivLu().solve(r);
                for (std::size_t k = 0; k < dep.size(); ++k)
                    v[at_[0][static_cast<std::size_t>(dep[k])]] -= dx(static_cast<Eigen::Index>(k));
            }
            if (!converged) return false;
        }
        if (!solve_linear_level(g_, at_[1], v)) return false;
        if (h_.output_count() > 0 && !solve_linear_level(h_, at_[2], v)) return false;
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(v[i]);
        return true;
    }

private:
    // the columns a pivoted QR decomposition takes first, as many as the rank
    static std::vector<Eigen::Index> pick_dependent(const MatrixXld& B) {
        Eigen::ColPivHouseholderQR<MatrixXld> qr(B);
        qr.setThreshold(1e-10L);
        if (qr.rank() < B.rows()) return {};
        std::vector<Eigen::Index> dep;
        for (Eigen::Index k = 0; k < B.rows(); ++k) dep.push_back(qr.colsPermutation().indices()(k));
        return dep;
    }
    static MatrixXld columns(const MatrixXld& B, const std::vector<Eigen::Index>& dep) {
        MatrixXld C(B.rows(), static_cast<Eigen::Index>(dep.size()));
        for (std::size_t k = 0; k < dep.size(); ++k)
            C.col(static_cast<Eigen::Index>(k)) = B.col(dep[k]);
        return C;
    }
    // residuals linear in the variables at `at`: their coefficients by unit steps, then the
    // dependent ones solved for so that every residual vanishes
    static bool solve_linear_level(const CompiledExpressions& E, const std::vector<std::size_t>& at,
                                   std::vector<long double>& v) {
        const auto m = static_cast<Eigen::Index>(E.output_count());
        const auto n = static_cast<Eigen::Index>(at.size());
        VectorXld r0(m), r1(m);
        E.evaluate_extended(v.data(), r0.data());
        MatrixXld B(m, n);
        for (Eigen::Index j = 0; j < n; ++j) {
            long double& x = v[at[static_cast<std::size_t>(j)]];
            const long double saved = x;
            x = saved + 1;
            E.evaluate_extended(v.data(), r1.data());
            x = saved;
            B.col(j) = r1 - r0;
        }
        if (!B.allFinite() || !r0.allFinite()) return false;
        std::vector<Eigen::Index> dep = pick_dependent(B);
        if (dep.empty()) return false;
        VectorXld dx = columns(B, dep).fullPivLu().solve(r0);
        for (std::size_t k = 0; k < dep.size(); ++k)
            v[at[static_cast<std::size_t>(dep[k])]] -= dx(static_cast<Eigen::Index>(k));
        return true;
    }

    std::array<std::vector<std::size_t>, 3> at_;  // state positions of q, q', q''
    std::size_t configurations_ = 0;
    CompiledExpressions f_, g_, h_;
};

}  // namespace

MethodComparison compare_methods(const System& sys, const std::vector<TimeVariable>& q,
                                 int states, unsigned seed) {
    const SymbolTable& st = sys.symbols();
    std::vector<ex> acc;
    for (const TimeVariable& qi : q) acc.push_back(qi.d(2));
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, acc)) roadmap.push_back(r.equation);
    // Newton–Euler solves for the accelerations and every joint reaction together
    NewtonEulerEquations ne = form_newton_euler_equations(sys, q, acc);

    // what a state gives values to: coordinates, speeds, specified inputs, unknown loads,
    // constants without a value, the time
    StateSampler sampler(st, ne.reactions, false, seed);
    const std::vector<ex>& state = sampler.symbols();

    std::vector<CompiledMethod> methods;
    methods.emplace_back("road-map", st, roadmap, acc, state);
    methods.emplace_back("Kane", st, form_kane_equations(sys, q), acc, state);
    methods.emplace_back("Lagrange", st, form_lagrange_equations(sys, q), acc, state);
    methods.emplace_back("Newton–Euler", st, ne.equations, ne.unknowns, state);
    // trees: the road-map rows accumulated from the tip inward, and the articulated-body
    // accelerations
    std::vector<ExplicitMethod> explicit_methods;
    if (std::optional<TreeEquations> tree = form_tree_equations_if_tree(sys, q)) {
        methods.emplace_back("recursive road-map", st, tree->residuals, acc, state);
        explicit_methods.emplace_back("articulated body", st, tree->accelerations, state);
    }
    const std::size_t count = methods.size() + explicit_methods.size();
    MethodComparison out{{}, states, 0, std::vector<double>(count, 0.0)};
    for (const CompiledMethod& m : methods) out.methods.push_back(m.name());
    for (const ExplicitMethod& m : explicit_methods) out.methods.push_back(m.name());

    for (int k = 0; k < states; ++k) {
        const std::vector<double> values = sampler.draw();
        Eigen::VectorXd ref = methods[0].solve(values);
        for (std::size_t m = 1; m < count; ++m) {
            Eigen::VectorXd x = m < methods.size()
                                    ? methods[m].solve(values)
                                    : explicit_methods[m - methods.size()].solve(values);
            for (Eigen::Index i = 0; i < ref.size(); ++i)
                out.differences[m] = std::max(out.differences[m], std::abs(x(i) - ref(i)) /
                                                                      std::max(1.0, std::abs(ref(i))));
            out.max_difference = std::max(out.max_difference, out.differences[m]);
        }
    }
    return out;
}

ReactionComparison compare_reactions(const System& sys, const std::vector<TimeVariable>& q,
                                     int states, unsigned seed, const std::vector<ex>& loads,
                                     const std::vector<ex>& constraint_forces) {
    const SymbolTable& st = sys.symbols();
    if (sys.joint_reactions().empty() && constraint_forces.empty())
        throw ModelError(
            "compare_reactions(): the model declares no joint reaction and no constraint force "
            "is given; declare one with System::add_joint_reaction");
    std::vector<ex> measures;
    for (const JointReaction& jr : sys.joint_reactions())
        for (const ReactionComponent& c : jr.components) measures.push_back(c.measure);
    auto among = [](const std::vector<ex>& xs, const ex& s) {
        return std::any_of(xs.begin(), xs.end(), [&](const ex& x) { return x.is_equal(s); });
    };
    std::vector<ex> given = loads;
    given.insert(given.end(), constraint_forces.begin(), constraint_forces.end());
    for (const ex& l : given)
        if (among(measures, l))
            throw ArgumentError("compare_reactions(): the load '" + to_string(l) +
                                "' is a measure of a declared joint reaction; give only loads "
                                "that are not reactions (motor torques, applied forces, the "
                                "forces the model's constraints hold)");
    // forward dynamics: the accelerations are the method's own unknowns; inverse dynamics:
    // the given loads, the accelerations drawn with the state
    const bool inverse = !loads.empty();
    std::vector<ex> own = loads;
    if (!inverse)
        for (const TimeVariable& qi : q) own.push_back(qi.d(2));
    // the forces the constraints hold are solved for in both, with the constraint rows
    own.insert(own.end(), constraint_forces.begin(), constraint_forces.end());

    // the road-map: its own unknowns and the declared measures together
    std::vector<ex> x_rm = own;
    x_rm.insert(x_rm.end(), measures.begin(), measures.end());
    std::vector<ex> roadmap;
    for (const RoadmapRow& r : plan_roadmap(sys, q, x_rm)) roadmap.push_back(r.equation);

    // Newton–Euler with the declared reaction loads set to zero
    NewtonEulerEquations ne = form_newton_euler_equations(sys, q, own);
    exmap zero;
    for (const ex& m : measures) zero[m] = 0;
    std::vector<ex> ne_equations;
    for (const ex& e : ne.equations) ne_equations.push_back(e.subs(zero));
    for (const Constraint& c : sys.constraints()) {
        // the constraint at the acceleration level, as the road-map's constraint rows hold it
        RoadmapRow row;
        row.constraint = c.name;
        row.analysis = Analysis::dynamics;
        form_constraint_row(sys, row, own);
        ne_equations.push_back(row.equation);
    }

    // the state: as compare_methods() draws it (with the accelerations for inverse dynamics),
    // less the loads solved for and every reaction measure
    std::vector<ex> excluded = ne.reactions;
    excluded.insert(excluded.end(), measures.begin(), measures.end());
    excluded.insert(excluded.end(), given.begin(), given.end());
    StateSampler sampler(st, excluded, inverse, seed);
    const std::vector<ex>& state = sampler.symbols();
    const ConstraintProjector projector(sys, q, state, inverse);

    // per declared component: its projection by the road-map and by Newton–Euler
    std::vector<ex> by_roadmap, by_ne;
    for (const JointReaction& jr : sys.joint_reactions()) {
        auto j = std::find_if(ne.joints.begin(), ne.joints.end(),
                              [&](const NewtonEulerJoint& nj) { return nj.body == jr.child; });
        const std::string parent = jr.parent ? jr.parent->name() : sys.newtonian().name();
        if (j == ne.joints.end())
            throw ModelError("compare_reactions(): Newton–Euler infers no joint of '" +
                             jr.child->name() + "', the child of the reaction '" + jr.name + "'");
        Vector F, T;
        for (const ReactionComponent& c : jr.components)
            (c.kind == LoadKind::force ? F : T) += c.measure * c.direction;
        for (const ReactionComponent& c : jr.components) {
            const Body* ne_parent = c.kind == LoadKind::force ? j->parent : j->torque_parent;
            if (ne_parent != jr.parent)
                throw ModelError("compare_reactions(): Newton–Euler joins '" + jr.child->name() +
                                 "' to '" +
                                 (ne_parent ? ne_parent->name() : sys.newtonian().name()) +
                                 "', but the reaction '" + jr.name + "' is declared from '" +
                                 parent + "'; declare it from the body the child is placed from");
            if (c.kind == LoadKind::force) {
                by_roadmap.push_back(dot(c.direction, F));
                by_ne.push_back(dot(c.direction, j->force));
            } else {
                by_roadmap.push_back(dot(c.direction, T));
                by_ne.push_back(
                    dot(c.direction, j->torque + cross(j->at->pos_from(*jr.at), j->force)));
            }
        }
    }
    std::vector<ex> inputs = measures;
    inputs.insert(inputs.end(), ne.reactions.begin(), ne.reactions.end());
    inputs.insert(inputs.end(), state.begin(), state.end());
    std::vector<ex> outputs = by_roadmap;
    outputs.insert(outputs.end(), by_ne.begin(), by_ne.end());
    CompiledExpressions projections(st, inputs, outputs);

    CompiledMethod rm("road-map", st, roadmap, x_rm, state);
    CompiledMethod brute("Newton–Euler", st, ne_equations, ne.unknowns, state);
    ReactionComparison out{given, states, 0,
                           std::vector<double>(given.size() + measures.size(), 0.0)};
    out.measures.insert(out.measures.end(), measures.begin(), measures.end());
    auto record = [&](std::size_t i, long double a, long double b) {
        double d = static_cast<double>(std::abs(a - b) / std::max(1.0L, std::abs(b)));
        out.differences[i] = std::max(out.differences[i], d);
        out.max_difference = std::max(out.max_difference, d);
    };
    for (int k = 0; k < states; ++k) {
        std::vector<double> values = sampler.draw();
        for (int draw = 1; !projector.project(values); ++draw) {
            if (draw == 50)
                throw SolveError(
                    "compare_reactions(): no state satisfying the model's constraints was found "
                    "from 50 random draws; check that the constraints can be met");
            values = sampler.draw();
        }
        Eigen::VectorXd a = rm.solve(values), b = brute.solve(values);
        // the loads and constraint forces solved for: the same unknowns in both
        const std::size_t skip = inverse ? 0 : q.size();
        for (std::size_t i = 0; i < given.size(); ++i) {
            const auto j = static_cast<Eigen::Index>(i < loads.size() ? i : skip + i);
            record(i, a(j), b(j));
        }
        // the inputs of the projections: declared measures, Newton–Euler's, the state
        std::vector<long double> in;
        for (std::size_t i = 0; i < measures.size(); ++i)
            in.push_back(a(static_cast<Eigen::Index>(own.size() + i)));
        for (std::size_t i = 0; i < ne.reactions.size(); ++i)
            in.push_back(b(static_cast<Eigen::Index>(own.size() + i)));
        in.insert(in.end(), values.begin(), values.end());
        VectorXld p(static_cast<Eigen::Index>(outputs.size()));
        if (!outputs.empty()) projections.evaluate_extended(in.data(), p.data());
        const auto m = static_cast<Eigen::Index>(measures.size());
        for (Eigen::Index i = 0; i < m; ++i)
            record(given.size() + static_cast<std::size_t>(i), p(i), p(m + i));
    }
    return out;
}

}  // namespace alembert
