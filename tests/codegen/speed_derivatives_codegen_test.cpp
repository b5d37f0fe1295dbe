// SPDX-License-Identifier: MIT
// Derivatives of inverse and forward dynamics for a model whose equations are in generalized
// speeds u (a free-floating base and a ball joint by Euler parameters, body-axis angular
// velocities as speeds, q' = N(q) u): the model formed in coordinates whose rates are the
// speeds (each unit quaternion by its vector part), so the generated derivatives are
// d tau/d q and d u'/d q at fixed u, and d tau/d u, d u'/d u at fixed q. Checked against
// central differences of the compiled generated inverse and forward dynamics at random states,
// and against Euler's equations of a lone free body written out by hand.
#include <array>
#include <cstdlib>
#include <optional>

#include "alembert/codegen/codegen.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/mech/ball_joint.hpp"
#include "alembert/mech/free_joint.hpp"
#include "drivers.hpp"
#include "harness.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// A free-floating chain: base P free in N (force F_P along N at P_o, torque T_P in P's axes),
// body B on a ball joint to P (torque T_B in B's axes on B from P), body C on a hinge about
// B's y axis (torque T_C); mass centres off the joint axes; gravity -g Nz. With `lone`, P alone
// with its mass centre at P_o.
SampleModel floating_chain(bool lone) {
    SampleModel m{System("N"), {}, {}, {}};
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    auto body = [&](const std::string& name, double mass, std::array<double, 3> c, std::array<double, 3> I)
        -> RigidBody& {
        RigidBody& B = sys.add_rigid_body(name);
        const Frame& F = B.body_frame();
        B.set_mass(st.add_constant("m_" + name, mass));
        B.cm().set_pos(sys.point(name + "_o"), c[0] * F.x() + c[1] * F.y() + c[2] * F.z());
        B.set_inertia(B.cm(), st.add_constant("I_" + name + "_x", I[0]), st.add_constant("I_" + name + "_y", I[1]),
                      st.add_constant("I_" + name + "_z", I[2]));
        m.links.push_back(&B);
        return B;
    };
    RigidBody& P = body("P", 10, lone ? std::array<double, 3>{0, 0, 0} : std::array<double, 3>{0.05, -0.02, 0.1},
                        {0.3, 0.5, 0.7});
    const FreeJoint free = add_free_joint(sys, P);
    m.q = free.coordinates();
    m.speeds = free.speeds();
    const Frame& FP = P.body_frame();
    for (const char* f : {"F_P_x", "F_P_y", "F_P_z", "T_P_x", "T_P_y", "T_P_z"}) m.unknowns.push_back(st.add_unknown(f));
    sys.add_force(sys.point("P_o"), m.unknowns[0] * N.x() + m.unknowns[1] * N.y() + m.unknowns[2] * N.z(), "F_P");
    sys.add_torque(P, m.unknowns[3] * FP.x() + m.unknowns[4] * FP.y() + m.unknowns[5] * FP.z(), "T_P");
    if (!lone) {
        RigidBody& B = body("B", 3, {0.02, 0.01, -0.2}, {0.04, 0.05, 0.02});
        const BallJoint ball = add_ball_joint(sys, B, FP);
        sys.point("B_o").set_pos(sys.point("P_o"), 0.1 * FP.y() - 0.05 * FP.z());
        const Frame& FB = B.body_frame();
        for (const char* t : {"T_B_x", "T_B_y", "T_B_z"}) m.unknowns.push_back(st.add_unknown(t));
        const Vector T = m.unknowns[6] * FB.x() + m.unknowns[7] * FB.y() + m.unknowns[8] * FB.z();
        sys.add_torque_pair(B, FP, T, "T_B");
        for (const TimeVariable& v : ball.coordinates()) m.q.push_back(v);
        for (const ex& u : ball.speeds()) m.speeds.push_back(u);
        RigidBody& C = body("C", 1.5, {0, 0.03, -0.15}, {0.01, 0.012, 0.004});
        const TimeVariable qC = st.add_variable("q_C", 2);
        C.body_frame().orient_axis(FB, Axis::y, qC.d(0));
        sys.point("C_o").set_pos(sys.point("B_o"), -0.3 * FB.z());
        m.unknowns.push_back(st.add_unknown("T_C"));
        sys.add_torque_pair(C, FB, m.unknowns.back() * FB.y(), "T_C");
        m.q.push_back(qC);
        m.speeds.push_back(qC.d(1));
    }
    sys.set_gravity(-st.add_constant("g", 9.81) * N.z());
    return m;
}

// The model in coordinates whose rates are its speeds: each unit quaternion e0_B..e3_B by its
// vector part ev1_B..ev3_B (e0 = +sqrt(1 - ev.ev), every orientation having Euler parameters
// with e0 >= 0), and B's angular velocity in its parent set in the rates: ev_B' stands for
// B's body-axis angular velocity w_B, the speed, not for the rate of ev_B. Positions and
// hinge angles keep their coordinates, whose rates are their speeds already.
std::vector<TimeVariable> coordinates_with_speeds_as_rates(SampleModel& m) {
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    std::vector<TimeVariable> q;
    for (std::size_t i = 0; i < m.q.size(); ++i) {
        const std::string& name = m.q[i].name();
        if (name.rfind("e0_", 0) != 0) {
            q.push_back(m.q[i]);
            continue;
        }
        Frame& B = sys.frame(name.substr(3));
        std::vector<TimeVariable> ev;
        for (const char* e : {"ev1_", "ev2_", "ev3_"}) ev.push_back(st.add_variable(e + B.name(), 2));
        const ex e1 = ev[0].d(0), e2 = ev[1].d(0), e3 = ev[2].d(0);
        B.orient_dcm(*B.parent(), euler_parameter_rotation(GiNaC::sqrt(1 - e1 * e1 - e2 * e2 - e3 * e3), e1, e2, e3));
        B.set_ang_vel(*B.parent(), ev[0].d(1) * B.x() + ev[1].d(1) * B.y() + ev[2].d(1) * B.z());
        q.insert(q.end(), ev.begin(), ev.end());
        i += 3;
    }
    return q;
}

// the recursive formation in those coordinates, with the derivatives
CodegenCase speed_case(std::unique_ptr<SampleModel> model, const std::string& name) {
    CodegenCase c;
    c.name = name;
    c.model = std::move(model);
    const std::vector<TimeVariable> q = coordinates_with_speeds_as_rates(*c.model);
    TreeEquations t = form_tree_equations(c.model->system, q, TreeOptions{.mass_matrix = true});
    c.equations = {q, t.residuals, c.model->unknowns, std::nullopt, t.accelerations};
    c.equations.mass_matrix = t.mass_matrix;
    c.equations.bias_forces = t.bias_forces;
    add_dynamics_derivatives(c.model->system.symbols(), c.equations);
    return c;
}

CodegenCase floating_case(bool lone) {
    return speed_case(std::make_unique<SampleModel>(floating_chain(lone)), lone ? "free_body" : "floating");
}

// random states with each quaternion's vector part inside the unit ball (|ev| < 0.87)
std::vector<State> floating_states(const CodegenCase& c, int count, unsigned seed) {
    std::vector<State> states = random_states(c, count, seed);
    for (State& s : states)
        for (std::size_t i = 0; i < c.n(); ++i)
            if (c.equations.coordinates[i].name().rfind("ev", 0) == 0) s.q[i] /= 3;
    return states;
}

// per state: d tau/d q, d tau/d u of inverse_dynamics_derivatives and their central
// differences of inverse_dynamics; u', d u'/d q, d u'/d u of forward_dynamics_derivatives, u'
// of forward_dynamics and the central differences of forward_dynamics (q' read as u)
std::string speed_derivatives_driver(const std::string& name) {
    return c_driver_frame(name, R"(        enum { N = NAME_NQ };
        double t, q[N], u[N], ud[N], tau[N], Dq[N * N], Du[N * N], a[N], b[N], x[N], fud[N];
        double Fq[N * N], Fu[N * N], dq[N * N], du[N * N];
        if (!read(&t, 1) || !read(q, N) || !read(u, N) || !read(ud, N) || !read(tau, N)) return 1;
        NAME_inverse_dynamics_derivatives(&c, t, q, u, ud, Dq, Du);
        print(Dq, N * N);
        print(Du, N * N);
        for (int s = 0; s < 2; ++s) {
            double* y = s == 0 ? q : u;
            for (int j = 0; j < N; ++j) {
                const double y0 = y[j], h = 1e-5 * (1.0 + (y0 < 0 ? -y0 : y0));
                y[j] = y0 + h;
                NAME_inverse_dynamics(&c, t, q, u, ud, a);
                y[j] = y0 - h;
                NAME_inverse_dynamics(&c, t, q, u, ud, b);
                y[j] = y0;
                for (int i = 0; i < N; ++i) (s == 0 ? dq : du)[i * N + j] = (a[i] - b[i]) / (2 * h);
            }
        }
        print(dq, N * N);
        print(du, N * N);
        if (NAME_forward_dynamics_derivatives(&c, t, q, u, tau, x, Fq, Fu) != 0) return 2;
        print(x, N);
        print(Fq, N * N);
        print(Fu, N * N);
        if (NAME_forward_dynamics(&c, t, q, u, tau, fud) != 0) return 2;
        print(fud, N);
        for (int s = 0; s < 2; ++s) {
            double* y = s == 0 ? q : u;
            for (int j = 0; j < N; ++j) {
                const double y0 = y[j], h = 1e-5 * (1.0 + (y0 < 0 ? -y0 : y0));
                y[j] = y0 + h;
                if (NAME_forward_dynamics(&c, t, q, u, tau, a) != 0) return 2;
                y[j] = y0 - h;
                if (NAME_forward_dynamics(&c, t, q, u, tau, b) != 0) return 2;
                y[j] = y0;
                for (int i = 0; i < N; ++i) (s == 0 ? dq : du)[i * N + j] = (a[i] - b[i]) / (2 * h);
            }
        }
        print(dq, N * N);
        print(du, N * N);
)");
}

struct SpeedPrinted {
    std::vector<double> Dq, Du, fd_Dq, fd_Du, ud, Fq, Fu, fd_ud, fd_Fq, fd_Fu;
};

// generated, compiled and run at `states`: the printed values per state
std::vector<SpeedPrinted> run_speed_derivatives(const CodegenCase& c, const std::vector<State>& states,
                                                const std::string& tag, GeneratedCode* generated = nullptr,
                                                const std::string& optimization = "-O2") {
    ScratchDir dir(tag);
    const GeneratedCode g = generate_case(c, Language::c, dir.path());
    if (generated) *generated = g;
    const std::optional<std::vector<double>> v =
        compile_and_run_c_driver(dir.path(), c.name, speed_derivatives_driver(c.name), driver_input(states),
                                 optimization);
    if (!v) return {};
    const std::size_t n = c.n(), nn = n * n;
    if (v->size() != states.size() * (8 * nn + 2 * n)) {
        ADD_FAILURE() << "the driver printed " << v->size() << " numbers";
        return {};
    }
    std::vector<SpeedPrinted> out;
    std::size_t at = 0;
    auto take = [&](std::size_t k) {
        std::vector<double> x(v->begin() + static_cast<long>(at), v->begin() + static_cast<long>(at + k));
        at += k;
        return x;
    };
    for (std::size_t s = 0; s < states.size(); ++s) {
        SpeedPrinted p;
        p.Dq = take(nn), p.Du = take(nn), p.fd_Dq = take(nn), p.fd_Du = take(nn);
        p.ud = take(n), p.Fq = take(nn), p.Fu = take(nn);
        p.fd_ud = take(n), p.fd_Fq = take(nn), p.fd_Fu = take(nn);
        out.push_back(std::move(p));
    }
    return out;
}

// |got - want| <= tol * max(1, max |want|), entry by entry
void expect_entries_close(const std::vector<double>& got, const std::vector<double>& want, double tol,
                          const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    double scale = 1;
    for (double w : want) scale = std::max(scale, std::fabs(w));
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tol * scale) << what << " entry " << i;
}

}  // namespace

TEST(SpeedDerivativesCodegen, FloatingChainDerivativesAtFixedSpeedsMatchCentralDifferences) {
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    const CodegenCase c = floating_case(false);
    ASSERT_EQ(c.n(), 10u);  // 6 of the free base, 3 of the ball, 1 of the hinge
    const std::vector<State> states = floating_states(c, 4, 31);
    const std::vector<SpeedPrinted> got = run_speed_derivatives(c, states, "c-speed-derivatives");
    ASSERT_EQ(got.size(), states.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        const std::string at = "state " + std::to_string(k) + ": ";
        expect_entries_close(got[k].Dq, got[k].fd_Dq, 1e-7, at + "d tau/d q at fixed u");
        expect_entries_close(got[k].Du, got[k].fd_Du, 1e-7, at + "d tau/d u");
        expect_entries_close(got[k].ud, got[k].fd_ud, 1e-12, at + "u'");
        expect_entries_close(got[k].Fq, got[k].fd_Fq, 1e-7, at + "d u'/d q at fixed u");
        expect_entries_close(got[k].Fu, got[k].fd_Fu, 1e-7, at + "d u'/d u");
    }
}

TEST(SpeedDerivativesCodegen, HumanoidDerivativesAtFixedSpeedsMatchCentralDifferences) {
    // make_humanoid: 15 segments, a free base, 5 ball joints and 8 hinges, 32 speeds
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    const CodegenCase c = speed_case(std::make_unique<SampleModel>(make_humanoid()), "humanoid");
    ASSERT_EQ(c.n(), 32u);
    const std::vector<State> states = floating_states(c, 2, 41);
    GeneratedCode g;
    // compiled at -O0: gcc -O2 took 98 of the test's 99 s on its 100,000 operations (the
    // smaller models above are compiled at -O2, as users build)
    const std::vector<SpeedPrinted> got =
        run_speed_derivatives(c, states, "c-speed-derivatives-humanoid", &g, "-O0");
    ASSERT_EQ(got.size(), states.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        const std::string at = "state " + std::to_string(k) + ": ";
        expect_entries_close(got[k].Dq, got[k].fd_Dq, 1e-7, at + "d tau/d q at fixed u");
        expect_entries_close(got[k].Du, got[k].fd_Du, 1e-7, at + "d tau/d u");
        expect_entries_close(got[k].ud, got[k].fd_ud, 1e-12, at + "u'");
        expect_entries_close(got[k].Fq, got[k].fd_Fq, 1e-7, at + "d u'/d q at fixed u");
        expect_entries_close(got[k].Fu, got[k].fd_Fu, 1e-7, at + "d u'/d u");
    }
    // the operation counts bench/README.md quotes
    RecordProperty("inverse_dynamics_operations", std::to_string(g.inverse_dynamics_operations));
    RecordProperty("derivatives_operations", std::to_string(g.inverse_dynamics_derivatives_operations));
    RecordProperty("accelerations_operations", std::to_string(g.accelerations_operations));
    RecordProperty("mass_matrix_operations", std::to_string(g.mass_matrix_operations));
    EXPECT_GT(g.inverse_dynamics_derivatives_operations, g.inverse_dynamics_operations);
}

TEST(SpeedDerivativesCodegen, LoneFreeBodyDerivativesAreThoseOfEulersEquations) {
    // P alone, mass centre at P_o, speeds (x', y', z', w) with w in P's axes. Newton in N:
    //   F = m (x'', y'', z'') + m g Nz, no orientation and no w in it;
    // Euler in P's axes: T = I w' + w x I w, free of q as well, so d tau/d q = 0 and
    //   d T_x/d w_y = (I_z - I_y) w_z,  d T_x/d w_z = (I_z - I_y) w_y,
    //   d T_y/d w_x = (I_x - I_z) w_z,  d T_y/d w_z = (I_x - I_z) w_x,
    //   d T_z/d w_x = (I_y - I_x) w_y,  d T_z/d w_y = (I_y - I_x) w_x.
    if (!have_c_compiler()) GTEST_SKIP() << "no C compiler '" << c_compiler() << "' found (set CC or install gcc)";
    const CodegenCase c = floating_case(true);
    ASSERT_EQ(c.n(), 6u);
    const std::vector<State> states = floating_states(c, 3, 5);
    const std::vector<SpeedPrinted> got = run_speed_derivatives(c, states, "c-speed-derivatives-lone");
    ASSERT_EQ(got.size(), states.size());
    const double I[3] = {0.3, 0.5, 0.7};
    for (std::size_t k = 0; k < states.size(); ++k) {
        SCOPED_TRACE("state " + std::to_string(k));
        const double* w = &states[k].qp[3];
        for (std::size_t i = 0; i < 36; ++i) EXPECT_NEAR(got[k].Dq[i], 0, 1e-12) << "d tau/d q entry " << i;
        std::vector<double> want(36, 0);
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3, l = (i + 2) % 3;  // T_i = I_i w_i' + (I_l - I_j) w_j w_l
            want[(3 + i) * 6 + 3 + j] = (I[l] - I[j]) * w[l];
            want[(3 + i) * 6 + 3 + l] = (I[l] - I[j]) * w[j];
        }
        for (std::size_t i = 0; i < 36; ++i) EXPECT_NEAR(got[k].Du[i], want[i], 1e-12) << "d tau/d u entry " << i;
    }
}
