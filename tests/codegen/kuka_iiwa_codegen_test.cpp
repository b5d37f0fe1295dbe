// SPDX-License-Identifier: MIT
// The KUKA LBR iiwa 14 arm: generated C for inverse dynamics of its 7 motor torques and 35
// joint reaction measures (from the road-map rows), compiled by the system C compiler, agrees
// with brute-force Newton–Euler at random states.
#include <cstdlib>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/newton_euler.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "drivers.hpp"
#include "eom/kuka_iiwa_model.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

using VectorXld = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
using MatrixXld = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

/// One state of the arm: q, q', q''.
struct ArmState {
    std::vector<double> q, qp, qpp;
};

std::vector<ArmState> arm_states(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(-2.5, 2.5), rate(-2, 2), acceleration(-3, 3);
    std::vector<ArmState> out;
    for (int k = 0; k < count; ++k) {
        ArmState s;
        for (int i = 0; i < 7; ++i) {
            s.q.push_back(angle(rng));
            s.qp.push_back(rate(rng));
            s.qpp.push_back(acceleration(rng));
        }
        out.push_back(s);
    }
    return out;
}

/// A C99 driver of NAME.h: reads the count, then per state t, q, q', q''; prints the loads of
/// inverse dynamics.
std::string inverse_dynamics_driver(const std::string& name) {
    return c_driver_frame(name, R"(        double t, q[NAME_NQ], qp[NAME_NQ], qpp[NAME_NQ], u[NAME_NU];
        if (!read(&t, 1) || !read(q, NAME_NQ) || !read(qp, NAME_NQ) || !read(qpp, NAME_NQ))
            return 1;
        NAME_inverse_dynamics(&c, t, q, qp, qpp, u);
        for (int i = 0; i < NAME_NU; ++i) printf("%.17g\n", u[i]);
)");
}

/// Brute-force Newton–Euler for inverse dynamics: the motor torques and the reactions of the
/// joints it infers from the model, solved in extended precision, then projected on the
/// model's declared reaction components as compare_reactions() projects them (a force
/// component d . F_NE, a torque component d . (T_NE + r^{J/P} x F_NE)).
class NewtonEulerLoads {
public:
    explicit NewtonEulerLoads(const KukaIiwa& m) {
        const System& sys = m.sys;
        const SymbolTable& st = sys.symbols();
        NewtonEulerEquations ne = form_newton_euler_equations(sys, m.q, m.torques);
        // the declared reaction loads are not Newton–Euler's: its own reactions carry the
        // whole joint load
        exmap zero;
        for (const ex& r : m.reactions) zero[r] = 0;
        std::vector<ex> E;
        for (const ex& e : ne.equations) E.push_back(e.subs(zero));
        unknowns_ = ne.unknowns.size();
        EXPECT_EQ(E.size(), unknowns_);
        LinearSystem L = form_linear_system(E, ne.unknowns);
        std::vector<ex> state, Ab;
        for (const TimeVariable& qi : m.q) state.push_back(qi.symbol());
        for (const TimeVariable& qi : m.q) state.push_back(qi.d(1));
        for (const TimeVariable& qi : m.q) state.push_back(qi.d(2));
        for (unsigned i = 0; i < L.A.rows(); ++i)
            for (unsigned j = 0; j < L.A.cols(); ++j) Ab.push_back(L.A(i, j));
        for (unsigned i = 0; i < L.b.rows(); ++i) Ab.push_back(L.b(i, 0));
        system_ = CompiledExpressions(st, state, Ab);

        // the declared measures, in the model's order, by Newton–Euler's joint loads
        std::map<ex, ex, GiNaC::ex_is_less> by_ne;
        for (const JointReaction& jr : sys.joint_reactions()) {
            auto j = std::find_if(ne.joints.begin(), ne.joints.end(),
                                  [&](const NewtonEulerJoint& nj) { return nj.body == jr.child; });
            EXPECT_NE(j, ne.joints.end()) << jr.name;
            if (j == ne.joints.end()) continue;
            for (const ReactionComponent& c : jr.components)
                by_ne[c.measure] =
                    c.kind == LoadKind::force
                        ? dot(c.direction, j->force)
                        : dot(c.direction, j->torque + cross(j->at->pos_from(*jr.at), j->force));
        }
        std::vector<ex> projections;
        for (const ex& r : m.reactions) projections.push_back(by_ne.at(r));
        std::vector<ex> inputs = ne.reactions;
        inputs.insert(inputs.end(), state.begin(), state.end());
        projections_ = CompiledExpressions(st, inputs, projections);
        reactions_ = ne.reactions.size();
        torques_ = ne.caller_unknowns;
    }

    /// The 7 motor torques, then the 35 declared reaction measures, at state s.
    std::vector<long double> at(const ArmState& s) const {
        std::vector<long double> x;
        for (const auto* v : {&s.q, &s.qp, &s.qpp}) x.insert(x.end(), v->begin(), v->end());
        const auto u = static_cast<Eigen::Index>(unknowns_);
        std::vector<long double> Ab(static_cast<std::size_t>(u * u + u));
        system_.evaluate_extended(x.data(), Ab.data());
        MatrixXld A(u, u);
        VectorXld b(u);
        for (Eigen::Index i = 0; i < u; ++i) {
            for (Eigen::Index j = 0; j < u; ++j) A(i, j) = Ab[static_cast<std::size_t>(i * u + j)];
            b(i) = Ab[static_cast<std::size_t>(u * u + i)];
        }
        Eigen::FullPivLU<MatrixXld> lu(A);
        EXPECT_TRUE(lu.isInvertible()) << "Newton–Euler's coefficient matrix is singular";
        VectorXld solution = lu.solve(b);
        std::vector<long double> out(solution.data(), solution.data() + torques_);
        std::vector<long double> in(solution.data() + torques_,
                                    solution.data() + torques_ + reactions_);
        in.insert(in.end(), x.begin(), x.end());
        std::vector<long double> p(projections_.output_count());
        projections_.evaluate_extended(in.data(), p.data());
        out.insert(out.end(), p.begin(), p.end());
        return out;
    }

private:
    std::size_t unknowns_ = 0, reactions_ = 0, torques_ = 0;
    CompiledExpressions system_, projections_;
};

}  // namespace

TEST(KukaIiwaCodegen, GeneratedCTorquesAndReactionsMatchNewtonEuler) {
    const char* cc_env = std::getenv("CC");
    const std::string cc = cc_env && *cc_env ? cc_env : "cc";
    std::string out;
    if (run(cc + " --version", out) != 0)
        GTEST_SKIP() << "no C compiler '" << cc << "' found (set CC or install gcc): the generated "
                     << "C cannot be compiled";

    KukaIiwa m = make_kuka_iiwa();
    std::vector<ex> loads = m.torques;
    loads.insert(loads.end(), m.reactions.begin(), m.reactions.end());
    ASSERT_EQ(loads.size(), 42u);
    // as `codegen c ... for` does it: the recursive formation for forward dynamics, the
    // road-map rows for the torques and reaction measures for inverse dynamics
    TreeEquations tree = form_tree_equations(m.sys, m.q);
    DynamicsEquations eq{
        m.q,          tree.residuals,     loads,
        std::nullopt, tree.accelerations, residuals_of(plan_roadmap(m.sys, m.q, loads))};
    ScratchDir dir("c-kuka-iiwa");
    CodegenOptions options;
    options.name = "kuka_iiwa";
    GeneratedCode g = generate_code(m.sys.symbols(), eq, Language::c, dir.path(), options);
    ASSERT_TRUE(g.inverse_dynamics);
    EXPECT_GT(g.inverse_dynamics_operations, 0u);

    write(dir.path() / "driver.c", inverse_dynamics_driver(options.name));
    ASSERT_EQ(run("cd " + dir.path().string() + " && " + cc +
                      " -std=c99 -pedantic -Wall -Wextra -Werror -O2 kuka_iiwa.c driver.c -lm "
                      "-o driver",
                  out),
              0)
        << "compiling the generated C failed:\n"
        << out;

    const std::vector<ArmState> states = arm_states(6, 14);
    std::ostringstream input;
    input.precision(17);
    input << states.size() << '\n';
    for (const ArmState& s : states) {
        input << 0.0;
        for (const auto* v : {&s.q, &s.qp, &s.qpp})
            for (double x : *v) input << ' ' << x;
        input << '\n';
    }
    write(dir.path() / "states.txt", input.str());
    ASSERT_EQ(run("cd " + dir.path().string() + " && ./driver < states.txt", out), 0) << out;
    const std::vector<double> got = numbers(out);
    ASSERT_EQ(got.size(), states.size() * loads.size()) << out;

    const NewtonEulerLoads reference(m);
    double largest = 0;  // the largest difference relative to the state's load scale
    for (std::size_t k = 0; k < states.size(); ++k) {
        const std::vector<long double> want = reference.at(states[k]);
        ASSERT_EQ(want.size(), loads.size());
        // the load scale: the largest torque or force measure at this state (the arm weighs
        // about 300 N, so it is never small)
        long double scale = 1;
        for (long double w : want) scale = std::max(scale, std::fabs(w));
        EXPECT_GT(scale, 100.0L);
        for (std::size_t i = 0; i < loads.size(); ++i) {
            const double d = static_cast<double>(
                std::fabs(static_cast<long double>(got[k * loads.size() + i]) - want[i]) / scale);
            largest = std::max(largest, d);
            EXPECT_LT(d, 1e-12) << loads[i] << " at state " << k << ": generated C "
                                << got[k * loads.size() + i] << ", Newton–Euler "
                                << static_cast<double>(want[i]);
        }
    }
    std::printf(
        "KUKA iiwa, generated C: 7 torques and 35 reaction measures at %zu states, "
        "largest difference %.2g of the load scale\n",
        states.size(), largest);
}
