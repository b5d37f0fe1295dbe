// SPDX-License-Identifier: MIT
// Generated C for Kane's equations in generalized speeds with motion constraints (a rolling
// disk; the Whipple bicycle): forward dynamics, kinematics and dependent speeds against
// Alembert's own evaluation of the same equations at random states; the simulation of the
// rolling disk keeps its energy and its contact at rest; the bicycle's generated right-hand
// side, differenced about upright straight running, has Meijaard et al.'s eigenvalues.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <random>
#include <string>
#include <vector>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "drivers.hpp"
#include "support/meijaard2007.hpp"
#include "support/expect.hpp"

namespace alembert::test {
namespace {

// The rolling disk of examples/rolling_disk/model.alb in speeds (make_rolling_disk), with a
// torque T Ly on D about its axle as the load.
SampleNonholonomicModel rolling_disk_in_speeds() { return make_rolling_disk(2.0, 0.3, 9.81, true); }

KaneEquations kane_of(const SampleNonholonomicModel& m, bool simplify) {
    std::vector<ex> u;
    for (const TimeVariable& ui : m.u) u.push_back(ui.symbol());
    return form_kane_equations(m.system, KaneOptions{.coordinates = m.q,
                                                     .speeds = u,
                                                     .kinematic_equations = m.kinematic_equations,
                                                     .motion_constraints = m.motion_constraints,
                                                     .dependent_speeds = m.dependent_speeds,
                                                     .simplify = simplify});
}

// reads states (t, q, ur, u) and prints urp, qp and us per state
std::string speed_driver(const std::string& name) {
    return c_driver_frame(name, R"(        double t, q[NAME_NQ], ur[NAME_NUR], u[NAME_NU + 1], urp[NAME_NUR], qp[NAME_NQ];
        double us[NAME_NUS + 1];
        if (!read(&t, 1) || !read(q, NAME_NQ) || !read(ur, NAME_NUR) || !read(u, NAME_NU)) return 1;
        if (NAME_forward_dynamics(&c, t, q, ur, u, urp) != 0) return 2;
        NAME_kinematics(&c, t, q, ur, qp);
#if NAME_NUS > 0
        NAME_dependent_speeds(&c, t, q, ur, us);
#endif
        print(urp, NAME_NUR);
        print(qp, NAME_NQ);
        print(us, NAME_NUS);
)");
}

// the same driver in C++ on NAME.hpp
std::string speed_cpp_driver(const std::string& name) {
    return cpp_driver_frame(name, R"(        double t, q[nq], ur[nur], u[nu + 1], urp[nur], qp[nq], us[nus + 1];
        if (!read(&t, 1) || !read(q, nq) || !read(ur, nur) || !read(u, nu)) return 1;
        if (!model.forward_dynamics(t, q, ur, u, urp)) return 2;
        model.kinematics(t, q, ur, qp);
        if (nus > 0) model.dependent_speeds(t, q, ur, us);
        print(urp, nur);
        print(qp, nq);
        print(us, nus);
)");
}

// the same driver in Python on NAME.py (states on standard input)
std::string speed_python_driver(const std::string& name, const std::string& dir) {
    return python_driver_frame(name, dir, R"(    t = take(1)[0]
    q, ur, u = take(m.NQ), take(m.NUR), take(m.NU)
    out = list(m.forward_dynamics(t, q, ur, u, ctx)) + list(m.kinematics(t, q, ur, ctx))
    if m.NUS:
        out += list(m.dependent_speeds(t, q, ur, ctx))
    print("\n".join(repr(float(x)) for x in out))
)");
}

// Debian's interpreter (a pyenv shim may come first on PATH without NumPy)
const char* kDebianPython = "/usr/bin/python3";

bool debian_python_with_numpy() {
    std::string out;
    return run(std::string(kDebianPython) + " -c 'import numpy, scipy'", out) == 0;
}

// reads states x = (q, ur) and prints the right-hand side x' per state
std::string rhs_driver(const std::string& name) {
    return replace_all(R"(#include <stdio.h>
#include "NAME.h"
int main(void) {
    NAME_context c;
    NAME_init(&c, 0);
    int count = 0;
    if (scanf("%d", &count) != 1) return 1;
    for (int k = 0; k < count; ++k) {
        double x[NAME_NQ + NAME_NUR], dx[NAME_NQ + NAME_NUR];
        for (int i = 0; i < NAME_NQ + NAME_NUR; ++i)
            if (scanf("%lf", &x[i]) != 1) return 1;
        if (NAME_rhs(&c, 0.0, x, dx) != 0) return 2;
        for (int i = 0; i < NAME_NQ + NAME_NUR; ++i) printf("%.17g\n", dx[i]);
    }
    return 0;
}
)",
                       "NAME", name);
}

// compiles the generated NAME.c with a driver; false (and a failure) if it does not compile
bool build(const fs::path& dir, const std::string& name, const std::string& driver,
           const std::string& exe, const std::string& extra = "") {
    write(dir / (exe + ".c"), driver);
    std::string out;
    int status = run("cc -std=c99 -O1 -Wall -Wextra -Werror -o " + (dir / exe).string() + " " +
                         (dir / (exe + ".c")).string() + " " + (dir / (name + ".c")).string() +
                         " " + extra + " -I" + dir.string() + " -lm",
                     out);
    EXPECT_EQ(status, 0) << out;
    return status == 0;
}

// runs a driver on `input`; the numbers it printed
std::vector<double> run_driver(const fs::path& dir, const std::string& exe, const std::string& input) {
    write(dir / (exe + ".in"), input);
    std::string out;
    EXPECT_EQ(run((dir / exe).string() + " < " + (dir / (exe + ".in")).string(), out), 0) << out;
    return numbers(out);
}

struct SpeedState {
    double t;
    std::vector<double> q, ur, u;
};

struct Agreement {
    double worst = 0;    // largest difference relative to each group's largest magnitude
    double largest = 0;  // largest magnitude of the reference values
    double constraint = 0;  // largest |motion constraint| with the generated q'
};

// Generated forward dynamics, kinematics and dependent speeds against Alembert's evaluation
// of the same Kane equations (SymbolTable::evaluate, through GiNaC, not the compiled tape
// the generator prints): M u_r' = f solved by Eigen, q' = k(q, u_r), u_s = A u_r + B. The
// states are random (q, u_r, loads); every such state satisfies the motion constraints, which
// are checked with the generated q'.
Agreement agreement(const SampleNonholonomicModel& m, const KaneEquations& K,
                    const std::vector<ex>& loads, const std::string& name, int count,
                    double angle_range, double speed_range, Language language = Language::c) {
    const SymbolTable& st = m.system.symbols();
    ScratchDir dir("speeds-" + name + "-" + to_string(language));
    CodegenOptions o;
    o.name = name;
    GeneratedCode g = generate_code(st, K, loads, language, dir.path(), o);
    EXPECT_EQ(g.files.size(), language == Language::python ? 1u : 2u);
    Agreement a;
    if (language == Language::python) {
        write(dir.path() / "driver", "#!/bin/sh\nexec " + std::string(kDebianPython) + " " +
                                         (dir.path() / "driver.py").string() + "\n");
        write(dir.path() / "driver.py", speed_python_driver(name, dir.path().string()));
        fs::permissions(dir.path() / "driver", fs::perms::owner_all);
    } else if (language == Language::cpp) {
        write(dir.path() / "driver.cpp", speed_cpp_driver(name));
        std::string out;
        int status = run("c++ -std=c++17 -O1 -Wall -Wextra -Werror -o " + (dir.path() / "driver").string() +
                             " " + (dir.path() / "driver.cpp").string() + " " +
                             (dir.path() / (name + ".cpp")).string() + " -I" + dir.path().string(),
                         out);
        EXPECT_EQ(status, 0) << out;
        if (status != 0) return {1, 0, 1};
    } else if (!build(dir.path(), name, speed_driver(name), "driver")) {
        return {1, 0, 1};
    }
    const std::size_t n = K.coordinates.size(), nr = K.independent_speeds.size(),
                      ns = K.dependent_speeds.size();
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> angle(-angle_range, angle_range),
        speed(-speed_range, speed_range), load(-10, 10);
    std::vector<SpeedState> states;
    std::ostringstream in;
    in.precision(17);
    in << count << '\n';
    for (int k = 0; k < count; ++k) {
        SpeedState s{angle(rng), {}, {}, {}};
        for (std::size_t i = 0; i < n; ++i) s.q.push_back(angle(rng));
        for (std::size_t r = 0; r < nr; ++r) s.ur.push_back(speed(rng));
        for (std::size_t j = 0; j < loads.size(); ++j) s.u.push_back(load(rng));
        in << s.t;
        for (const auto* v : {&s.q, &s.ur, &s.u})
            for (double x : *v) in << ' ' << x;
        in << '\n';
        states.push_back(s);
    }
    std::vector<double> got = run_driver(dir.path(), "driver", in.str());
    const std::size_t per = nr + n + ns;
    EXPECT_EQ(got.size(), states.size() * per);
    if (got.size() != states.size() * per) return {1, 0, 1};
    for (std::size_t k = 0; k < states.size(); ++k) {
        const SpeedState& s = states[k];
        exmap at{{st.time(), s.t}};
        for (std::size_t i = 0; i < n; ++i) at[K.coordinates[i]] = s.q[i];
        for (std::size_t r = 0; r < nr; ++r) at[K.independent_speeds[r]] = s.ur[r];
        for (std::size_t j = 0; j < loads.size(); ++j) at[loads[j]] = s.u[j];
        // Alembert's values: u_r' from M and f, q', u_s
        Eigen::MatrixXd M(nr, nr);
        Eigen::VectorXd f(nr);
        for (unsigned i = 0; i < nr; ++i) {
            f(i) = st.evaluate(K.dynamics.b(i, 0), at);
            for (unsigned j = 0; j < nr; ++j) M(i, j) = st.evaluate(K.dynamics.A(i, j), at);
        }
        Eigen::VectorXd urp = M.partialPivLu().solve(f);
        std::vector<double> want(urp.data(), urp.data() + nr);
        for (std::size_t i = 0; i < n; ++i) want.push_back(st.evaluate(K.coordinate_rates[i], at));
        for (std::size_t j = 0; j < ns; ++j) want.push_back(st.evaluate(K.dependent_speed_values[j], at));
        for (auto [lo, hi] : {std::pair<std::size_t, std::size_t>{0, nr}, {nr, nr + n}, {nr + n, per}}) {
            double scale = 1;
            for (std::size_t i = lo; i < hi; ++i) scale = std::max(scale, std::fabs(want[i]));
            a.largest = std::max(a.largest, scale);
            for (std::size_t i = lo; i < hi; ++i) {
                double d = std::fabs(got[k * per + i] - want[i]) / scale;
                a.worst = std::max(a.worst, d);
                EXPECT_LT(d, 1e-12) << name << ": value " << i << " at state " << k << ": generated "
                                    << got[k * per + i] << ", Alembert " << want[i];
            }
        }
        // the motion constraints (in q') at the generated q'
        exmap with_rates = at;
        for (std::size_t i = 0; i < n; ++i) with_rates[K.coordinate_rate_symbols[i]] = got[k * per + nr + i];
        for (const ex& c : m.motion_constraints)
            a.constraint = std::max(a.constraint,
                                    std::fabs(st.evaluate(st.expand_intermediates(c), with_rates)));
    }
    return a;
}

void record(const char* key, double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", d);
    ::testing::Test::RecordProperty(key, text);
}

TEST(SpeedCodegen, RollingDiskAgreesWithAlembertsEvaluation) {
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    Agreement a = agreement(m, K, {m.system.symbols().symbol("T")}, "rolling_disk", 20, 1.5, 3);
    record("max_relative_difference", a.worst);
    EXPECT_LT(a.worst, 1e-12);
    EXPECT_GT(a.largest, 1.0);  // the states exercise the model
    EXPECT_LT(a.constraint, 1e-13);
}

// The unpowered disk rolls and turns: no force does work (the contact point is at rest, the
// normal and friction forces act there), so KE + PE stays constant; the contact point's
// velocity, evaluated by Alembert from D's full velocity with the q' of the generated
// kinematics, stays zero.
TEST(SpeedCodegen, RollingDiskInCppAgreesWithAlembertsEvaluation) {
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    Agreement a = agreement(m, K, {m.system.symbols().symbol("T")}, "rolling_disk", 20, 1.5, 3,
                            Language::cpp);
    record("max_relative_difference", a.worst);
    EXPECT_LT(a.worst, 1e-12);
    EXPECT_GT(a.largest, 1.0);
    EXPECT_LT(a.constraint, 1e-13);
}

TEST(SpeedCodegen, RollingDiskInPythonAgreesWithAlembertsEvaluation) {
    if (!debian_python_with_numpy())
        GTEST_SKIP() << kDebianPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    Agreement a = agreement(m, K, {m.system.symbols().symbol("T")}, "rolling_disk", 20, 1.5, 3,
                            Language::python);
    record("max_relative_difference", a.worst);
    EXPECT_LT(a.worst, 1e-12);
    EXPECT_GT(a.largest, 1.0);
    EXPECT_LT(a.constraint, 1e-13);
}

// The generated Python's simulation (solve_ivp) of the rolling disk keeps its energy.
TEST(SpeedCodegen, RollingDiskPythonSimulationKeepsEnergy) {
    if (!debian_python_with_numpy())
        GTEST_SKIP() << kDebianPython << " with numpy and scipy is missing (python3-numpy, python3-scipy)";
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    System& sys = m.system;
    ScratchDir dir("speeds-py-sim");
    CodegenOptions o;
    o.name = "rolling_disk_sim";
    o.simulation = true;
    o.simulation_spec = {.final_time = 1,
                         .output_step = 0.1,
                         .absolute_tolerance = 1e-11,
                         .relative_tolerance = 1e-11,
                         .initial_q = {0, 0.4, 0, 0, 0},
                         .initial_qp = {0.8, 6.0, -0.5}};
    o.outputs = {{"E", sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy(), "J"}};
    generate_code(sys.symbols(), K, {sys.symbols().symbol("T")}, Language::python, dir.path(), o);
    std::string out;
    const fs::path csv = dir.path() / "out.csv";
    ASSERT_EQ(run(std::string(kDebianPython) + " " + (dir.path() / "rolling_disk_sim.py").string() + " " +
                      csv.string(),
                  out),
              0)
        << out;
    std::string header;
    std::vector<std::vector<double>> rows = csv_rows(csv, &header);
    EXPECT_EQ(header, "t [s],q1,q2,q3,x,y,u1,u2,u3,T,E [J]");
    ASSERT_EQ(rows.size(), 11u);
    const double E0 = rows.front().back();
    for (const std::vector<double>& r : rows)
        EXPECT_NEAR(r.back(), E0, 1e-8 * std::fabs(E0)) << "at t = " << r[0];
}

TEST(SpeedCodegen, RollingDiskSimulationKeepsEnergyAndRolling) {
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    System& sys = m.system;
    const SymbolTable& st = sys.symbols();
    ScratchDir dir("speeds-sim");
    CodegenOptions o;
    o.name = "rolling_disk_sim";
    o.simulation = true;
    o.simulation_spec = {.final_time = 3,
                         .output_step = 0.1,
                         .absolute_tolerance = 1e-11,
                         .relative_tolerance = 1e-11,
                         .initial_q = {0, 0.4, 0, 0, 0},
                         .initial_qp = {0.8, 6.0, -0.5}};
    Frame& N = sys.newtonian();
    const Vector v_NDP = sys.point("D_P").vel_in(N);
    o.outputs = {{"E", sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy(), "J"}};
    GeneratedCode g = generate_code(st, K, {st.symbol("T")}, Language::c, dir.path(), o);
    ASSERT_EQ(g.files.size(), 3u);
    std::string out;
    const std::string exe = (dir.path() / "sim").string();
    ASSERT_EQ(run("cc -std=c99 -O1 -Wall -Wextra -Werror -o " + exe + " " +
                      (dir.path() / "rolling_disk_sim.c").string() + " " +
                      (dir.path() / "rolling_disk_sim_main.c").string() + " -I" +
                      dir.path().string() + " -lm",
                  out),
              0)
        << out;
    const fs::path csv = dir.path() / "out.csv";
    ASSERT_EQ(run(exe + " " + csv.string(), out), 0) << out;
    std::string header;
    std::vector<std::vector<double>> rows = csv_rows(csv, &header);
    EXPECT_EQ(header, "t [s],q1,q2,q3,x,y,u1,u2,u3,T,E [J]");
    ASSERT_EQ(rows.size(), 31u);
    const double E0 = rows.front().back();
    double energy = 0, contact = 0, travelled = 0;
    for (const std::vector<double>& r : rows) {
        ASSERT_EQ(r.size(), 1u + 5 + 3 + 1 + 1);
        exmap at{{st.time(), r[0]}};
        for (std::size_t i = 0; i < 5; ++i) at[K.coordinates[i]] = r[1 + i];
        for (std::size_t j = 0; j < 3; ++j) at[K.independent_speeds[j]] = r[6 + j];
        exmap rates = at;
        for (std::size_t i = 0; i < 5; ++i)
            rates[K.coordinate_rate_symbols[i]] = st.evaluate(K.coordinate_rates[i], at);
        for (const Vector& e : {N.x(), N.y(), N.z()})
            contact = std::max(contact, std::fabs(st.evaluate(dot(v_NDP, e), rates)));
        energy = std::max(energy, std::fabs(r.back() - E0) / std::fabs(E0));
        travelled = std::max(travelled, std::hypot(r[4], r[5]));
    }
    record("energy_drift", energy);
    record("contact_speed", contact);
    EXPECT_LT(energy, 1e-8);
    EXPECT_LT(contact, 1e-12);  // [m/s]
    EXPECT_GT(travelled, 0.5);  // it rolled somewhere
}

// The Whipple bicycle (Meijaard et al. 2007): 6 coordinates, 3 independent speeds (lean rate
// u2, rear wheel rate u3, steer rate u5), the yaw, pitch and front wheel rates dependent.
struct GeneratedBicycle {
    SampleNonholonomicModel model = make_whipple_bicycle();
    KaneEquations K = kane_of(model, false);
};

GeneratedBicycle& bicycle() {
    static GeneratedBicycle b;
    return b;
}

TEST(SpeedCodegen, WhippleBicycleAgreesWithAlembertsEvaluation) {
    GeneratedBicycle& b = bicycle();
    ASSERT_EQ(b.K.independent_speeds.size(), 3u);
    Agreement a = agreement(b.model, b.K, {}, "whipple", 10, 0.6, 3);
    record("max_relative_difference", a.worst);
    EXPECT_LT(a.worst, 1e-12);
    EXPECT_LT(a.constraint, 1e-12);
}

// The state matrix of the generated right-hand side about upright straight running, by finite
// differences, against Table 2 at every speed it lists (v = 5 m/s asked for; 0..10 checked).
TEST(SpeedCodegen, WhippleBicycleRightHandSideGivesMeijaardsEigenvalues) {
    GeneratedBicycle& b = bicycle();
    const SymbolTable& st = b.model.system.symbols();
    ScratchDir dir("speeds-whipple-rhs");
    CodegenOptions o;
    o.name = "whipple";
    GeneratedCode g = generate_code(st, b.K, {}, Language::c, dir.path(), o);
    std::printf("Whipple bicycle, generated C, operations per call: mass matrix and forcing %zu, "
                "kinematics %zu, dependent speeds %zu; once per parameter set %zu; %s\n",
                g.mass_forcing_operations, g.kinematics_operations, g.dependent_speeds_operations,
                g.prelude_operations, g.symmetric_mass_matrix ? "Cholesky" : "LU");
    ASSERT_TRUE(build(dir.path(), "whipple", rhs_driver("whipple"), "rhs"));
    // x = (q1..q6, u2, u3, u5) about upright straight running at v: u3 = v / r_R; each
    // column of the state matrix by central differences, (f(x0 + h e_j) - f(x0 - h e_j)) / 2h
    const double h = 1e-5, r_R = *st.value(st.symbol("r_R"));
    std::ostringstream in;
    in.precision(17);
    in << std::size(kMeijaardTable2) * 18 << '\n';
    for (const MeijaardTable2Row& row : kMeijaardTable2)
        for (int j = 0; j < 9; ++j)
            for (double sign : {1.0, -1.0}) {
                std::vector<double> x(9, 0.0);
                x[7] = row.v / r_R;
                x[j] += sign * h;
                for (double xi : x) in << xi << ' ';
                in << '\n';
            }
    std::vector<double> dx = run_driver(dir.path(), "rhs", in.str());
    ASSERT_EQ(dx.size(), std::size(kMeijaardTable2) * 18 * 9);
    auto by_parts = [](auto p, auto q) {
        return p.real() != q.real() ? p.real() < q.real() : p.imag() < q.imag();
    };
    double worst = 0;
    for (std::size_t k = 0; k < std::size(kMeijaardTable2); ++k) {
        const double* d = dx.data() + k * 18 * 9;
        Eigen::MatrixXd A(9, 9);
        for (int j = 0; j < 9; ++j)
            for (int i = 0; i < 9; ++i) A(i, j) = (d[(2 * j) * 9 + i] - d[(2 * j + 1) * 9 + i]) / (2 * h);
        // lean q2, steer q5, lean rate u2, steer rate u5
        const int ls[4] = {1, 4, 6, 8};
        Eigen::Matrix4d A4;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) A4(i, j) = A(ls[i], ls[j]);
        Eigen::EigenSolver<Eigen::Matrix4d> es(A4);
        std::vector<std::complex<double>> got, want(kMeijaardTable2[k].eig, kMeijaardTable2[k].eig + 4);
        for (int i = 0; i < 4; ++i) got.push_back(es.eigenvalues()(i));
        std::sort(got.begin(), got.end(), by_parts);
        std::sort(want.begin(), want.end(), by_parts);
        for (int i = 0; i < 4; ++i) {
            worst = std::max(worst, std::abs(got[i] - want[i]));
            EXPECT_LT(std::abs(got[i] - want[i]), 1e-6)
                << "v = " << kMeijaardTable2[k].v << ": eigenvalue " << got[i] << ", published " << want[i];
        }
    }
    record("max_eigenvalue_difference", worst);
    std::printf("v = 0..10 m/s: largest difference from Meijaard's Table 2: %.2e\n", worst);
}

TEST(SpeedCodegen, RefusesWhatItCannotGenerateClearly) {
    SampleNonholonomicModel m = rolling_disk_in_speeds();
    KaneEquations K = kane_of(m, true);
    const SymbolTable& st = m.system.symbols();
    ScratchDir dir("speeds-refuse");
    EXPECT_THROW_MSG(generate_code(st, K, {}, Language::matlab, dir.path()), ArgumentError,
                     "C, C++ and Python only");
    // Kane's equations without chosen speeds
    SampleModel pendulum = make_triple_pendulum();
    KaneEquations plain =
        form_kane_equations(pendulum.system, KaneOptions{.coordinates = pendulum.q});
    EXPECT_THROW_MSG(generate_code(st, plain, {}, Language::c, dir.path()), ArgumentError,
                     "without chosen speeds");
}

}  // namespace
}  // namespace alembert::test
