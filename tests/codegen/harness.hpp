// SPDX-License-Identifier: MIT
// Shared by the codegen tests: sample models with their equations, reference values computed
// by Alembert's own evaluator, scratch directories and running programs.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"

namespace alembert::test {

namespace fs = std::filesystem;

/// A sample model, its equations for the generator and the requested outputs.
struct CodegenCase {
    std::unique_ptr<SampleModel> model;
    DynamicsEquations equations;
    std::vector<CodegenOutput> outputs;
    std::string name;
    /// The residuals the reference is formed from when they are not `equations.residuals`
    /// (equations whose q'' sit inside named intermediates: another method's instead).
    std::vector<ex> reference_residuals{};

    const SymbolTable& table() const { return model->system.symbols(); }
    std::size_t n() const { return equations.coordinates.size(); }
    std::size_t m() const { return equations.loads.size(); }
};

/// The triple pendulum by its planned road-map (no mass matrix given: the generator forms
/// it), with the mechanical energy and the potential energy as outputs.
inline CodegenCase triple_pendulum_case() {
    CodegenCase c;
    c.name = "triple_pendulum";
    c.model = std::make_unique<SampleModel>(make_triple_pendulum());
    System& sys = c.model->system;
    std::vector<RoadmapRow> rows = plan_roadmap(sys, c.model->q, c.model->unknowns);
    c.equations = {c.model->q, residuals_of(rows), c.model->unknowns, std::nullopt};
    ex PE = sys.calc_potential_energy(), KE = sys.calc_kinetic_energy(sys.bodies());
    c.outputs = {{"E", KE + PE, "J"}, {"PE", PE, "J"}};
    return c;
}

/// An n-link planar chain by Kane's method, with Kane's mass matrix given.
inline CodegenCase planar_chain_case(int n) {
    CodegenCase c;
    c.name = "chain" + std::to_string(n);
    c.model = std::make_unique<SampleModel>(make_n_link_pendulum(n));
    System& sys = c.model->system;
    KaneEquations k = form_kane_equations(sys, KaneOptions{.coordinates = c.model->q});
    c.equations = {c.model->q, k.residuals, c.model->unknowns, k.dynamics};
    ex PE = sys.calc_potential_energy(), KE = sys.calc_kinetic_energy(sys.bodies());
    c.outputs = {{"E", KE + PE, "J"}};
    return c;
}

/// An n-link chain (planar or spatial) by the recursive formation: the road-map rows about
/// successive joints, the articulated-body accelerations, M alone and the bias forces alone;
/// the reference is formed from Kane's equations, an independent method.
inline CodegenCase tree_chain_case(int n, ChainKind kind) {
    CodegenCase c;
    c.name = std::string(kind == ChainKind::planar ? "tree" : "spatial_tree") + std::to_string(n);
    c.model = std::make_unique<SampleModel>(make_n_link_pendulum(n, kind));
    System& sys = c.model->system;
    TreeEquations tree = form_tree_equations(sys, c.model->q, TreeOptions{.mass_matrix = true});
    c.equations = {c.model->q, tree.residuals, c.model->unknowns, std::nullopt, tree.accelerations};
    c.equations.mass_matrix = tree.mass_matrix;  // emitted in every language too
    c.equations.bias_forces = tree.bias_forces;
    c.reference_residuals = form_kane_equations(sys, c.model->q);
    ex PE = sys.calc_potential_energy(), KE = sys.calc_kinetic_energy(sys.bodies());
    c.outputs = {{"E", KE + PE, "J"}};
    return c;
}

/// The triple pendulum with its joint reactions (forces along each link's x and y axes) by
/// Kane's method for forward dynamics; inverse dynamics for the 3 torques and the 6 reaction
/// measures from the planned road-map rows.
inline CodegenCase triple_pendulum_reactions_case() {
    CodegenCase c;
    c.name = "triple_pendulum_reactions";
    c.model = std::make_unique<SampleModel>(make_triple_pendulum());
    System& sys = c.model->system;
    std::vector<ex> loads = c.model->unknowns;
    for (std::size_t i = 0; i < c.model->links.size(); ++i) {
        RigidBody& L = *c.model->links[i];
        SymbolTable& s = sys.symbols();
        ex Rx = s.add_unknown("R_" + L.name() + "_x"), Ry = s.add_unknown("R_" + L.name() + "_y");
        sys.add_joint_reaction("joint " + L.name(), i ? c.model->links[i - 1] : nullptr, L,
                               sys.point(L.name() + "_o"),
                               {{Rx, L.body_frame().x()}, {Ry, L.body_frame().y()}});
        loads.push_back(Rx);
        loads.push_back(Ry);
    }
    KaneEquations k = form_kane_equations(sys, KaneOptions{.coordinates = c.model->q});
    c.equations = {c.model->q, k.residuals, loads,
                   k.dynamics, {},          residuals_of(plan_roadmap(sys, c.model->q, loads))};
    return c;
}

/// Generates `lang` for the case into `dir`, named after the case and with its outputs (the
/// other options from `o`).
inline GeneratedCode generate_case(const CodegenCase& c, Language lang, const fs::path& dir,
                                   CodegenOptions o = {}) {
    o.name = c.name;
    o.outputs = c.outputs;
    return generate_code(c.table(), c.equations, lang, dir, o);
}

/// One state: t, q, q', q'' and loads u.
struct State {
    double t;
    std::vector<double> q, qp, qpp, u;
};

/// Pseudo-random states (deterministic seed), angles in [-1.5, 1.5].
inline std::vector<State> random_states(const CodegenCase& c, int count, unsigned seed = 7) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1.5, 1.5);
    std::vector<State> out;
    for (int k = 0; k < count; ++k) {
        State s{d(rng), {}, {}, {}, {}};
        for (std::size_t i = 0; i < c.n(); ++i) {
            s.q.push_back(d(rng));
            s.qp.push_back(d(rng));
            s.qpp.push_back(d(rng));
        }
        for (std::size_t i = 0; i < c.m(); ++i) s.u.push_back(10 * d(rng));
        out.push_back(s);
    }
    return out;
}

/// What every generated program prints per state, in this order: M (row by row), f, the
/// accelerations of forward dynamics at (q, q', u), the loads of inverse dynamics at
/// (q, q', q''), and the outputs at (q, q', q'', u).
struct Values {
    std::vector<double> M, f, fd, id, y;
    std::vector<double> flat() const {
        std::vector<double> v;
        for (const auto* x : {&M, &f, &fd, &id, &y}) v.insert(v.end(), x->begin(), x->end());
        return v;
    }
};

/// Reference values by Alembert's evaluator, with the constants folded: M and f compiled from
/// form_linear_system(residuals, q''), forward dynamics by Eigen's LU solve of them, inverse
/// dynamics by an LU solve of the residuals' coefficients of the loads (not the generator's
/// symbolic solution), outputs compiled. Compiled once per case, evaluated per state.
class Reference {
public:
    explicit Reference(const CodegenCase& c) : n_(c.n()), m_(c.m()) {
        const SymbolTable& T = c.table();
        std::vector<ex> q, qp, qpp;
        for (const TimeVariable& v : c.equations.coordinates) {
            q.push_back(v.d(0));
            qp.push_back(v.d(1));
            qpp.push_back(v.d(2));
        }
        auto inputs = [&](std::initializer_list<const std::vector<ex>*> arrays) {
            std::vector<ex> in{T.time()};
            for (const auto* a : arrays) in.insert(in.end(), a->begin(), a->end());
            return in;
        };
        auto flat = [&](const LinearSystem& L) {
            std::vector<ex> out;
            for (unsigned i = 0; i < L.A.rows(); ++i)
                for (unsigned j = 0; j < L.A.cols(); ++j) out.push_back(L.A(i, j));
            for (unsigned i = 0; i < L.b.rows(); ++i) out.push_back(L.b(i, 0));
            return out;
        };
        const std::vector<ex>& E =
            c.reference_residuals.empty() ? c.equations.residuals : c.reference_residuals;
        mf_ = CompiledExpressions(T, inputs({&q, &qp, &c.equations.loads}),
                                  flat(form_linear_system(E, qpp)));
        if (m_ == n_ || !c.equations.inverse_residuals.empty())
            id_ = CompiledExpressions(
                T, inputs({&q, &qp, &qpp}),
                flat(form_linear_system(
                    c.equations.inverse_residuals.empty() ? E : c.equations.inverse_residuals,
                    c.equations.loads)));
        std::vector<ex> y;
        for (const CodegenOutput& o : c.outputs) y.push_back(o.expression);
        y_ = CompiledExpressions(T, inputs({&q, &qp, &qpp, &c.equations.loads}), y);
    }

    Values at(const State& s) const {
        using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;
        const auto n = static_cast<long>(n_);
        auto join = [&](std::initializer_list<const std::vector<double>*> arrays) {
            std::vector<double> x{s.t};
            for (const auto* a : arrays) x.insert(x.end(), a->begin(), a->end());
            return x;
        };
        Values v;
        std::vector<double> mf = mf_.evaluate(join({&s.q, &s.qp, &s.u}));
        v.M.assign(mf.begin(), mf.begin() + n * n);
        v.f.assign(mf.begin() + n * n, mf.end());
        Eigen::MatrixXd M = Eigen::Map<const RowMajor>(v.M.data(), n, n);
        Eigen::VectorXd x = M.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(v.f.data(), n));
        v.fd.assign(x.data(), x.data() + n);
        if (id_.output_count()) {
            const auto m = static_cast<long>(m_);
            std::vector<double> ab = id_.evaluate(join({&s.q, &s.qp, &s.qpp}));
            Eigen::MatrixXd A = Eigen::Map<const RowMajor>(ab.data(), m, m);
            Eigen::VectorXd u =
                A.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(ab.data() + m * m, m));
            v.id.assign(u.data(), u.data() + m);
        }
        v.y = y_.evaluate(join({&s.q, &s.qp, &s.qpp, &s.u}));
        return v;
    }

private:
    std::size_t n_, m_;
    CompiledExpressions mf_, id_, y_;
};

/// The states as the drivers read them: the count, then per state t, q, q', q'', u.
inline std::string driver_input(const std::vector<State>& states) {
    std::ostringstream os;
    os.precision(17);
    os << states.size() << '\n';
    for (const State& s : states) {
        os << s.t;
        for (const auto* v : {&s.q, &s.qp, &s.qpp, &s.u})
            for (double x : *v) os << ' ' << x;
        os << '\n';
    }
    return os.str();
}

/// Expects `got` (all states' values, flat) to agree with the reference to `tol` relative to
/// each quantity's largest magnitude (at least 1).
inline void expect_agreement(const CodegenCase& c, const std::vector<State>& states,
                             const std::vector<double>& got, double tol, const std::string& who) {
    std::size_t at = 0;
    const Reference reference(c);
    for (std::size_t k = 0; k < states.size(); ++k) {
        Values r = reference.at(states[k]);
        const char* names[] = {"M", "f", "forward dynamics", "inverse dynamics", "outputs"};
        int which = 0;
        for (const auto* x : {&r.M, &r.f, &r.fd, &r.id, &r.y}) {
            double scale = 1;
            for (double v : *x) scale = std::max(scale, std::fabs(v));
            for (std::size_t i = 0; i < x->size(); ++i, ++at) {
                ASSERT_LT(at, got.size()) << who << ": too few values printed";
                EXPECT_NEAR(got[at], (*x)[i], tol * scale)
                    << who << ": " << names[which] << "[" << i << "] at state " << k;
            }
            ++which;
        }
    }
    EXPECT_EQ(at, got.size()) << who << ": more values printed than expected";
}

/// A fresh directory for one test, removed afterwards.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& tag) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("alembert-test-" + tag + "-" + (info ? std::string(info->name()) : "x") + "-" +
                 std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        if (!::testing::Test::HasFailure()) fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

/// Runs a shell command; returns its exit status and fills `output` with stdout and stderr.
inline int run(const std::string& command, std::string& output) {
    output.clear();
    FILE* p = ::popen((command + " 2>&1").c_str(), "r");
    if (!p) return -1;
    char buf[4096];
    std::size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, p)) > 0) output.append(buf, got);
    int status = ::pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The command that runs this test program again for the one test case `test_case` (a
/// DISABLED_ one too). GoogleTest's sharding variables are not passed on: under sharding
/// (ALEMBERT_TEST_SHARDS) the child would run the case only if it fell in this process's share.
inline std::string this_program_for(const std::string& test_case) {
    return "env -u GTEST_TOTAL_SHARDS -u GTEST_SHARD_INDEX " + fs::read_symlink("/proc/self/exe").string() +
           " --gtest_also_run_disabled_tests --gtest_filter=" + test_case;
}

/// The numbers of a text (whitespace or comma separated).
inline std::vector<double> numbers(const std::string& text) {
    std::string t = text;
    std::replace(t.begin(), t.end(), ',', ' ');
    std::istringstream in(t);
    std::vector<double> v;
    double x;
    while (in >> x) v.push_back(x);
    return v;
}

inline void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

/// The rows of a CSV file after its header.
inline std::vector<std::vector<double>> csv_rows(const fs::path& p, std::string* header = nullptr) {
    std::ifstream in(p);
    std::string line;
    std::vector<std::vector<double>> rows;
    if (std::getline(in, line) && header) *header = line;
    while (std::getline(in, line))
        if (!line.empty()) rows.push_back(numbers(line));
    return rows;
}

}  // namespace alembert::test
