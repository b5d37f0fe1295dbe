// SPDX-License-Identifier: MIT
// Generated C for constrained models (a four-bar and a slider-crank, closed loops; a rolling
// disk, motion constraints): its accelerations and constraint forces against Alembert's own
// road-map solved numerically, at random states that satisfy the constraints; its simulation
// keeps the constraints and the energy.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sym/evaluator.hpp"
#include "drivers.hpp"

namespace alembert::test {
namespace {

/// A constrained model: coordinates, driving loads (inputs) and constraint forces.
struct Constrained {
    std::string name;
    std::unique_ptr<System> owned{};
    std::unique_ptr<SampleModel> sample{};
    System* sys = nullptr;
    std::vector<TimeVariable> q{};
    std::vector<ex> loads{}, forces{};
};

Constrained four_bar() {
    Constrained c{"four_bar"};
    c.sample = std::make_unique<SampleModel>(make_four_bar());
    c.sys = &c.sample->system;
    c.q = c.sample->q;
    c.loads = {c.sample->unknowns[0]};
    c.forces = {c.sample->unknowns[1], c.sample->unknowns[2]};
    return c;
}

// A slider-crank in the vertical plane: crank A (L_A) about Nz at N_o by qA, connecting rod B
// (L_B) pinned at the crank's tip, turning by qB relative to A; slider C (a particle of mass
// m_C) at x Nx. The rod's tip meets the slider (constraints loop_x, loop_y; pin force F_x, F_y
// on B from C); crank torque T.
Constrained slider_crank() {
    Constrained c{"slider_crank"};
    c.owned = std::make_unique<System>("N");
    System& sys = *c.owned;
    c.sys = &sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex g = s.add_constant("g", 9.81);
    ex LA = s.add_constant("L_A", 0.3), LB = s.add_constant("L_B", 1.0);
    ex mA = s.add_constant("m_A", 1.0), mB = s.add_constant("m_B", 2.0), mC = s.add_constant("m_C", 3.0);
    TimeVariable qA = s.add_variable("qA", 2), qB = s.add_variable("qB", 2), x = s.add_variable("x", 2);
    RigidBody& A = sys.add_rigid_body("A");
    RigidBody& B = sys.add_rigid_body("B");
    Particle& C = sys.add_particle("C");
    A.body_frame().orient_axis(N, Axis::z, qA.symbol());
    B.body_frame().orient_axis(A.body_frame(), Axis::z, qB.symbol());
    sys.point("A_o").set_pos(sys.origin(), Vector());
    A.cm().set_pos(sys.point("A_o"), (LA / 2) * A.body_frame().x());
    Point& A_tip = sys.add_point("A_tip", &A);
    A_tip.set_pos(sys.point("A_o"), LA * A.body_frame().x());
    sys.point("B_o").set_pos(A_tip, Vector());
    B.cm().set_pos(sys.point("B_o"), (LB / 2) * B.body_frame().x());
    Point& B_tip = sys.add_point("B_tip", &B);
    B_tip.set_pos(sys.point("B_o"), LB * B.body_frame().x());
    C.point().set_pos(sys.origin(), x.symbol() * N.x());
    A.set_mass(mA);
    B.set_mass(mB);
    C.set_mass(mC);
    A.set_inertia(A.cm(), 0, 0, mA * LA * LA / 12);
    B.set_inertia(B.cm(), 0, 0, mB * LB * LB / 12);
    sys.add_configuration_constraint("loop", B_tip.pos_from(C.point()), N);
    ex T = s.add_unknown("T"), Fx = s.add_unknown("F_x"), Fy = s.add_unknown("F_y");
    sys.add_torque(A, T * N.z(), "T");
    sys.add_force_pair(B_tip, C.point(), Fx * N.x() + Fy * N.y(), "F_BC");
    sys.set_gravity(-g * N.y());
    c.q = {qA, qB, x};
    c.loads = {T};
    c.forces = {Fx, Fy};
    return c;
}

// A thin disk D (m, r) rolling without slip on the plane of Nx, Ny (Nz up): heading q1, lean
// q2, spin q3, contact point P at x Nx + y Ny; the no-slip constraints slip_x, slip_y (the
// velocity of D's point at the contact) held by the friction force F_x Nx + F_y Ny there.
Constrained rolling_disk() {
    Constrained c{"rolling_disk"};
    c.owned = std::make_unique<System>("N");
    System& sys = *c.owned;
    c.sys = &sys;
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();
    ex m = s.add_constant("m", 2.0), r = s.add_constant("r", 0.3), g = s.add_constant("g", 9.81);
    std::vector<TimeVariable> q{};
    for (const char* n : {"q1", "q2", "q3", "x", "y"}) q.push_back(s.add_variable(n, 2));
    Frame& Y = sys.add_frame("Y");
    Frame& L = sys.add_frame("L");
    RigidBody& D = sys.add_rigid_body("D");
    Y.orient_axis(N, Axis::z, q[0].symbol());
    L.orient_axis(Y, Axis::x, q[1].symbol());
    D.body_frame().orient_axis(L, Axis::y, q[2].symbol());
    Point& P = sys.add_point("P");
    P.set_pos(sys.origin(), q[3].symbol() * N.x() + q[4].symbol() * N.y());
    D.cm().set_pos(P, r * L.z());
    Point& DP = sys.add_point("D_P", &D);
    DP.set_pos(D.cm(), -r * L.z());
    DP.set_vel_two_point(N, D.cm(), D.body_frame());
    D.set_mass(m);
    D.set_inertia(D.cm(), m * r * r / 4, m * r * r / 2, m * r * r / 4);
    sys.set_gravity(-g * N.z());
    sys.add_motion_constraint("slip_x", dot(DP.vel_in(N), N.x()));
    sys.add_motion_constraint("slip_y", dot(DP.vel_in(N), N.y()));
    ex Fx = s.add_unknown("F_x"), Fy = s.add_unknown("F_y");
    sys.add_force(DP, Fx * N.x() + Fy * N.y(), "friction");
    c.q = q;
    c.forces = {Fx, Fy};
    return c;
}

/// The generator's input: Kane's equations (constraint forces among their loads) and the
/// constraints differentiated.
DynamicsEquations equations_of(Constrained& c) {
    KaneEquations k = form_kane_equations(*c.sys, KaneOptions{.coordinates = c.q});
    DynamicsEquations e{c.q, k.residuals, c.loads};
    e.constraints = differentiate_constraints(c.sys->symbols(), c.sys->constraints());
    e.constraint_forces = c.forces;
    return e;
}

std::vector<ex> joined(std::initializer_list<const std::vector<ex>*> lists) {
    std::vector<ex> out;
    for (const auto* l : lists) out.insert(out.end(), l->begin(), l->end());
    return out;
}

/// Random states (t, q, q', loads) that satisfy the constraints: the configuration
/// constraints by Newton's method with minimum-norm steps, then q' projected onto the speeds
/// the constraints allow. Jacobians are exact: the velocity-level constraints are linear in
/// q', so their columns are differences of evaluations at q' = e_j and q' = 0.
class ConstrainedSampler {
public:
    ConstrainedSampler(Constrained& c, const std::vector<CodegenConstraint>& k, unsigned seed)
        : n_(c.q.size()), rng_(seed) {
        const SymbolTable& T = c.sys->symbols();
        std::vector<ex> in{T.time()}, pos, vel;
        for (const TimeVariable& v : c.q) in.push_back(v.d(0));
        for (const TimeVariable& v : c.q) in.push_back(v.d(1));
        for (const CodegenConstraint& x : k) {
            if (x.kind == ConstraintKind::configuration) pos.push_back(x.value);
            vel.push_back(x.kind == ConstraintKind::configuration ? x.rate : x.value);
        }
        m_pos_ = pos.size();
        m_vel_ = vel.size();
        pos_ = CompiledExpressions(T, in, pos);
        vel_ = CompiledExpressions(T, in, vel);
        loads_ = c.loads.size();
    }

    // fills s; false if Newton's method did not converge from this draw
    bool draw(State& s) {
        std::uniform_real_distribution<double> d(-1.5, 1.5);
        s = State{d(rng_), {}, {}, {}, {}};
        for (std::size_t i = 0; i < n_; ++i) s.q.push_back(d(rng_));
        for (std::size_t i = 0; i < n_; ++i) s.qp.push_back(d(rng_));
        for (std::size_t i = 0; i < loads_; ++i) s.u.push_back(10 * d(rng_));
        for (int it = 0; m_pos_ > 0; ++it) {
            if (it == 60) return false;
            Eigen::VectorXd c = vector(pos_.evaluate(inputs(s.t, s.q, s.qp)));
            if (c.norm() < 1e-15) break;
            Eigen::MatrixXd J = jacobian(s).topRows(static_cast<long>(m_pos_));
            Eigen::VectorXd step = J.transpose() * (J * J.transpose()).partialPivLu().solve(c);
            for (std::size_t i = 0; i < n_; ++i) s.q[i] -= step(static_cast<long>(i));
        }
        Eigen::MatrixXd G = jacobian(s);
        for (int pass = 0; pass < 2; ++pass) {
            Eigen::VectorXd g = vector(vel_.evaluate(inputs(s.t, s.q, s.qp)));
            Eigen::VectorXd step = G.transpose() * (G * G.transpose()).partialPivLu().solve(g);
            for (std::size_t i = 0; i < n_; ++i) s.qp[i] -= step(static_cast<long>(i));
        }
        return true;
    }

    // the largest |c| and |c'| (|g|) at a state
    double violation(double t, const std::vector<double>& q, const std::vector<double>& qp) const {
        double worst = 0;
        for (const CompiledExpressions* f : {&pos_, &vel_})
            if (f->output_count())
                for (double v : f->evaluate(inputs(t, q, qp))) worst = std::max(worst, std::fabs(v));
        return worst;
    }

private:
    static Eigen::VectorXd vector(const std::vector<double>& v) {
        return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<long>(v.size()));
    }
    std::vector<double> inputs(double t, const std::vector<double>& q,
                               const std::vector<double>& qp) const {
        std::vector<double> x{t};
        x.insert(x.end(), q.begin(), q.end());
        x.insert(x.end(), qp.begin(), qp.end());
        return x;
    }
    // d(velocity-level constraints)/dq' at s.q
    Eigen::MatrixXd jacobian(const State& s) const {
        std::vector<double> zero(n_, 0.0);
        Eigen::VectorXd g0 = vector(vel_.evaluate(inputs(s.t, s.q, zero)));
        Eigen::MatrixXd J(static_cast<long>(m_vel_), static_cast<long>(n_));
        for (std::size_t j = 0; j < n_; ++j) {
            std::vector<double> e(n_, 0.0);
            e[j] = 1;
            J.col(static_cast<long>(j)) = vector(vel_.evaluate(inputs(s.t, s.q, e))) - g0;
        }
        return J;
    }

    std::size_t n_, m_pos_ = 0, m_vel_ = 0, loads_ = 0;
    std::mt19937 rng_;
    CompiledExpressions pos_, vel_;
};

/// Alembert's own forward dynamics of a constrained model: the planned road-map with its
/// constraint rows at the acceleration level, unknowns (q'', constraint forces), solved by
/// Eigen's LU. E = b - A x is compiled with x as inputs; b = E(0), A's columns E(0) - E(e_j).
class RoadmapReference {
public:
    explicit RoadmapReference(Constrained& c) : k_(c.q.size() + c.forces.size()) {
        const SymbolTable& T = c.sys->symbols();
        std::vector<ex> acc, in{T.time()};
        for (const TimeVariable& v : c.q) acc.push_back(v.d(2));
        for (const TimeVariable& v : c.q) in.push_back(v.d(0));
        for (const TimeVariable& v : c.q) in.push_back(v.d(1));
        in.insert(in.end(), c.loads.begin(), c.loads.end());
        std::vector<ex> x = joined({&acc, &c.forces});
        in.insert(in.end(), x.begin(), x.end());
        E_ = CompiledExpressions(T, in, residuals_of(plan_roadmap(*c.sys, c.q, x)));
    }

    // q'' then the constraint forces
    std::vector<double> at(const State& s) const {
        std::vector<double> in{s.t};
        for (const auto* v : {&s.q, &s.qp, &s.u}) in.insert(in.end(), v->begin(), v->end());
        const std::size_t at_x = in.size();
        in.resize(at_x + k_, 0.0);
        const auto k = static_cast<long>(k_);
        std::vector<double> e0 = E_.evaluate(in);
        Eigen::MatrixXd A(k, k);
        for (std::size_t j = 0; j < k_; ++j) {
            in[at_x + j] = 1;
            std::vector<double> ej = E_.evaluate(in);
            in[at_x + j] = 0;
            for (std::size_t i = 0; i < k_; ++i) A(static_cast<long>(i), static_cast<long>(j)) = e0[i] - ej[i];
        }
        Eigen::VectorXd x = A.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(e0.data(), k));
        return {x.data(), x.data() + k};
    }

private:
    std::size_t k_;
    CompiledExpressions E_;
};

// reads states (t, q, q', u) and prints q'' and the constraint forces of constrained_dynamics
std::string constrained_driver(const std::string& name) {
    std::string s = R"(#include <stdio.h>
#include "NAME.h"
static int read(double* x, int n) {
    for (int i = 0; i < n; ++i)
        if (scanf("%lf", &x[i]) != 1) return 0;
    return 1;
}
int main(void) {
    NAME_context c;
    NAME_init(&c, 0);
    int count = 0;
    if (scanf("%d", &count) != 1) return 1;
    for (int k = 0; k < count; ++k) {
        double t, q[NAME_NQ], qp[NAME_NQ], u[NAME_NU + 1], qpp[NAME_NQ], lambda[NAME_NC];
        if (!read(&t, 1) || !read(q, NAME_NQ) || !read(qp, NAME_NQ) || !read(u, NAME_NU)) return 1;
        if (NAME_constrained_dynamics(&c, t, q, qp, u, qpp, lambda) != 0) return 2;
        for (int i = 0; i < NAME_NQ; ++i) printf("%.17g\n", qpp[i]);
        for (int i = 0; i < NAME_NC; ++i) printf("%.17g\n", lambda[i]);
    }
    return 0;
}
)";
    return replace_all(s, "NAME", name);
}

// the same in C++ on NAME.hpp
std::string constrained_cpp_driver(const std::string& name) {
    std::string s = R"(#include <cstdio>
#include <iostream>
#include "NAME.hpp"
using namespace NAME;
static bool read(double* x, int n) {
    for (int i = 0; i < n; ++i)
        if (!(std::cin >> x[i])) return false;
    return true;
}
int main() {
    const Model model;
    int count = 0;
    if (!(std::cin >> count)) return 1;
    for (int k = 0; k < count; ++k) {
        double t, q[nq], qp[nq], u[nu + 1], qpp[nq], lambda[nc];
        if (!read(&t, 1) || !read(q, nq) || !read(qp, nq) || !read(u, nu)) return 1;
        if (!model.constrained_dynamics(t, q, qp, u, qpp, lambda)) return 2;
        for (int i = 0; i < nq; ++i) std::printf("%.17g\n", qpp[i]);
        for (int i = 0; i < nc; ++i) std::printf("%.17g\n", lambda[i]);
    }
    return 0;
}
)";
    return replace_all(s, "NAME", name);
}

// the same in Python on NAME.py
std::string constrained_python_driver(const std::string& name, const std::string& dir) {
    return replace_all(replace_all(R"(import sys
sys.path.insert(0, "DIR")
import numpy as np
import NAME as m

ctx = m.Context()
data = sys.stdin.read().split()
count, values, at = int(data[0]), [float(x) for x in data[1:]], 0


def take(k):
    global at
    at += k
    return np.array(values[at - k:at])


for _ in range(count):
    t = take(1)[0]
    q, qp, u = take(m.NQ), take(m.NQ), take(m.NU)
    qpp, lam = m.constrained_dynamics(t, q, qp, u, ctx)
    print("\n".join(repr(float(x)) for x in list(qpp) + list(lam)))
)",
                                   "NAME", name),
                       "DIR", dir);
}

// Debian's interpreter (a pyenv shim may come first on PATH without NumPy)
const char* kPython = "/usr/bin/python3";

bool python_with_numpy() {
    std::string out;
    return run(std::string(kPython) + " -c 'import numpy, scipy'", out) == 0;
}

// generated C (or C++) against the road-map at 20 constraint-satisfying states; returns the
// largest difference relative to each quantity group's largest magnitude (at least 1)
double agreement(Constrained c, Language language = Language::c) {
    DynamicsEquations eq = equations_of(c);
    ScratchDir dir("constrained-" + c.name + "-" + to_string(language));
    CodegenOptions o;
    o.name = c.name;
    GeneratedCode g = generate_code(c.sys->symbols(), eq, language, dir.path(), o);
    EXPECT_EQ(g.constraint_count, c.forces.size());
    EXPECT_FALSE(g.inverse_dynamics);
    const bool cpp = language == Language::cpp;
    std::string out;
    const std::string exe = (dir.path() / "driver").string();
    if (language == Language::python) {
        write(dir.path() / "driver", "#!/bin/sh\nexec " + std::string(kPython) + " " +
                                         (dir.path() / "driver.py").string() + "\n");
        write(dir.path() / "driver.py", constrained_python_driver(c.name, dir.path().string()));
        fs::permissions(dir.path() / "driver", fs::perms::owner_all);
    }
    write(dir.path() / (cpp ? "driver.cpp" : "driver.c"),
          cpp ? constrained_cpp_driver(c.name) : constrained_driver(c.name));
    int status = language == Language::python ? 0 : run((cpp ? "c++ -std=c++17" : "cc -std=c99") + std::string(" -O1 -Wall -Wextra -Werror -o ") +
                         exe + " " + (dir.path() / (cpp ? "driver.cpp" : "driver.c")).string() + " " +
                         (dir.path() / (c.name + (cpp ? ".cpp" : ".c"))).string() + " -I" +
                         dir.path().string() + " -lm",
                     out);
    EXPECT_EQ(status, 0) << out;
    if (status != 0) return 1;

    ConstrainedSampler sampler(c, eq.constraints, 11);
    std::vector<State> states;
    while (states.size() < 20) {
        State s;
        if (sampler.draw(s)) states.push_back(s);
    }
    std::string input = std::to_string(states.size()) + "\n";
    {
        std::ostringstream os;
        os.precision(17);
        for (const State& s : states) {
            os << s.t;
            for (const auto* v : {&s.q, &s.qp, &s.u})
                for (double x : *v) os << ' ' << x;
            os << '\n';
        }
        input += os.str();
    }
    write(dir.path() / "states.txt", input);
    EXPECT_EQ(run(exe + " < " + (dir.path() / "states.txt").string(), out), 0) << out;
    std::vector<double> got = numbers(out);
    const std::size_t n = c.q.size(), k = n + c.forces.size();
    EXPECT_EQ(got.size(), states.size() * k);
    if (got.size() != states.size() * k) return 1;
    RoadmapReference reference(c);
    double worst = 0, largest = 0;
    for (std::size_t s = 0; s < states.size(); ++s) {
        EXPECT_LT(sampler.violation(states[s].t, states[s].q, states[s].qp), 1e-12);
        std::vector<double> r = reference.at(states[s]);
        for (auto [lo, hi] : {std::pair<std::size_t, std::size_t>{0, n}, {n, k}}) {
            double scale = 1;
            for (std::size_t i = lo; i < hi; ++i) scale = std::max(scale, std::fabs(r[i]));
            largest = std::max(largest, scale);
            for (std::size_t i = lo; i < hi; ++i) {
                double d = std::fabs(got[s * k + i] - r[i]) / scale;
                worst = std::max(worst, d);
                EXPECT_LT(d, 1e-12) << c.name << (i < n ? ": q''[" : ": constraint force[")
                                    << (i < n ? i : i - n) << "] at state " << s;
            }
        }
    }
    // the states exercise the model: accelerations or forces well away from zero
    EXPECT_GT(largest, 1.0) << c.name;
    return worst;
}

void record(double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", d);
    ::testing::Test::RecordProperty("max_relative_difference", text);
}

TEST(ConstrainedCodegen, FourBarAgreesWithTheRoadmap) {
    double d = agreement(four_bar());
    record(d);
    EXPECT_LT(d, 1e-12);
}

TEST(ConstrainedCodegen, SliderCrankAgreesWithTheRoadmap) {
    double d = agreement(slider_crank());
    record(d);
    EXPECT_LT(d, 1e-12);
}

TEST(ConstrainedCodegen, FourBarAndRollingDiskInCppAgreeWithTheRoadmap) {
    double d = std::max(agreement(four_bar(), Language::cpp), agreement(rolling_disk(), Language::cpp));
    record(d);
    EXPECT_LT(d, 1e-12);
}

TEST(ConstrainedCodegen, FourBarAndRollingDiskInPythonAgreeWithTheRoadmap) {
    if (!python_with_numpy())
        GTEST_SKIP() << kPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    double d = std::max(agreement(four_bar(), Language::python),
                        agreement(rolling_disk(), Language::python));
    record(d);
    EXPECT_LT(d, 1e-12);
}

TEST(ConstrainedCodegen, RollingDiskAgreesWithTheRoadmap) {
    double d = agreement(rolling_disk());
    record(d);
    EXPECT_LT(d, 1e-12);
}

// The generated simulation of the unpowered four-bar (T = 0) from a state on the constraints:
// Baumgarte's stabilisation keeps the loop closed, and the pin force does no work, so the
// mechanical energy stays as it was.
void four_bar_simulation(Language language) {
    const bool cpp = language == Language::cpp;
    Constrained c = four_bar();
    DynamicsEquations eq = equations_of(c);
    ConstrainedSampler sampler(c, eq.constraints, 5);
    State s0;
    while (!sampler.draw(s0)) {
    }
    ScratchDir dir(std::string("constrained-sim-") + to_string(language));
    CodegenOptions o;
    o.name = "four_bar_sim";
    o.simulation = true;
    o.simulation_spec.final_time = 2;
    o.simulation_spec.output_step = 0.1;
    o.simulation_spec.absolute_tolerance = 1e-11;
    o.simulation_spec.relative_tolerance = 1e-11;
    o.simulation_spec.initial_q = s0.q;
    o.simulation_spec.initial_qp = s0.qp;
    System& sys = *c.sys;
    o.outputs = {{"E", sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy(), "J"}};
    generate_code(sys.symbols(), eq, language, dir.path(), o);
    std::string out;
    const std::string exe = (dir.path() / "sim").string();
    const std::string ext = cpp ? ".cpp" : ".c";
    if (language == Language::python) {
        // the module's main runs the simulation: a shell script in place of the program
        write(exe, "#!/bin/sh\nexec " + std::string(kPython) + " " +
                       (dir.path() / "four_bar_sim.py").string() + " \"$@\"\n");
        fs::permissions(exe, fs::perms::owner_all);
    } else
    ASSERT_EQ(run((cpp ? "c++ -std=c++17" : "cc -std=c99") + std::string(" -O1 -Wall -Wextra -Werror -o ") +
                      exe + " " + (dir.path() / ("four_bar_sim" + ext)).string() + " " +
                      (dir.path() / ("four_bar_sim_main" + ext)).string() + " -I" +
                      dir.path().string() + " -lm",
                  out),
              0)
        << out;
    const fs::path csv = dir.path() / "out.csv";
    ASSERT_EQ(run(exe + " " + csv.string(), out), 0) << out;
    std::vector<std::vector<double>> rows = csv_rows(csv);
    ASSERT_EQ(rows.size(), 21u);
    const std::size_t n = c.q.size();
    const double E0 = rows.front().back();
    for (const std::vector<double>& r : rows) {
        ASSERT_EQ(r.size(), 1 + 2 * n + 1 + 1);  // t, q, q', T, E
        std::vector<double> q(r.begin() + 1, r.begin() + 1 + static_cast<long>(n));
        std::vector<double> qp(r.begin() + 1 + static_cast<long>(n), r.begin() + 1 + 2 * static_cast<long>(n));
        EXPECT_LT(sampler.violation(r[0], q, qp), 1e-8) << "at t = " << r[0];
        EXPECT_NEAR(r.back(), E0, 1e-7 * std::max(1.0, std::fabs(E0))) << "at t = " << r[0];
    }
}

TEST(ConstrainedCodegen, FourBarSimulationKeepsTheLoopClosedAndTheEnergy) {
    four_bar_simulation(Language::c);
}

TEST(ConstrainedCodegen, FourBarSimulationInCppKeepsTheLoopClosedAndTheEnergy) {
    four_bar_simulation(Language::cpp);
}

TEST(ConstrainedCodegen, FourBarSimulationInPythonKeepsTheLoopClosedAndTheEnergy) {
    if (!python_with_numpy())
        GTEST_SKIP() << kPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    four_bar_simulation(Language::python);
}

TEST(ConstrainedCodegen, OtherLanguagesRefuseConstrainedModelsClearly) {
    Constrained c = four_bar();
    DynamicsEquations eq = equations_of(c);
    ScratchDir dir("constrained-lang");
    try {
        generate_code(c.sys->symbols(), eq, Language::matlab, dir.path());
        ADD_FAILURE() << "MATLAB accepted a constrained model";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("C, C++ and Python only"), std::string::npos) << e.what();
    }
    // one constraint force too few
    eq.constraint_forces.pop_back();
    EXPECT_THROW(generate_code(c.sys->symbols(), eq, Language::c, dir.path()), ArgumentError);
}

}  // namespace
}  // namespace alembert::test
