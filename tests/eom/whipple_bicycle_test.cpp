// SPDX-License-Identifier: MIT
// The Whipple bicycle (Meijaard, Papadopoulos, Ruina & Schwab 2007, Proc. R. Soc. A 463,
// 1955-1982): formed with Kane's method, three motion constraints solved for dependent
// speeds, linearized about upright straight running, and checked against the published
// eigenvalues (Table 2) and the weave and capsize speeds.
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/linearize.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"
#include "support/meijaard2007.hpp"

using namespace alembert;
using alembert::test::kMeijaardTable2, alembert::test::kMeijaardWeaveSpeed,
    alembert::test::kMeijaardCapsizeSpeed, alembert::test::MeijaardTable2Row;

namespace {

std::vector<std::complex<double>> sorted(std::vector<std::complex<double>> z) {
    std::sort(z.begin(), z.end(), [](auto a, auto b) {
        return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
    });
    return z;
}

// the model formed and linearized once for the whole suite
struct Bicycle {
    SampleNonholonomicModel model = make_whipple_bicycle();
    KaneEquations kane{};
    LinearizedEquations lin{};
    GiNaC::symbol v{"v"};
    double form_seconds = 0, linearize_seconds = 0;
    // lean, steer, lean rate, steer rate among the states (q1..q6, u2, u3, u5)
    std::vector<unsigned> lean_steer{1, 4, 6, 8};

    Bicycle() {
        SampleNonholonomicModel& m = model;
        std::vector<ex> u;
        for (const TimeVariable& ui : m.u) u.push_back(ui.symbol());
        KaneOptions o{.coordinates = m.q,
                      .speeds = u,
                      .kinematic_equations = m.kinematic_equations,
                      .motion_constraints = m.motion_constraints,
                      .dependent_speeds = m.dependent_speeds,
                      .simplify = false};
        auto t0 = std::chrono::steady_clock::now();
        kane = form_kane_equations(m.system, o);
        auto t1 = std::chrono::steady_clock::now();
        const SymbolTable& st = m.system.symbols();
        exmap op = st.constant_values();
        for (const TimeVariable& q : m.q) op[q.symbol()] = 0;
        op[m.u[1]] = 0, op[m.u[4]] = 0;
        op[m.u[2]] = v / *st.value(st.symbol("r_R"));
        lin = linearize(st, to_first_order(kane), {.operating_point = op, .simplify = false});
        auto t2 = std::chrono::steady_clock::now();
        form_seconds = std::chrono::duration<double>(t1 - t0).count();
        linearize_seconds = std::chrono::duration<double>(t2 - t1).count();
    }
    Eigen::Matrix4d A_at(double speed) const {
        Eigen::Matrix4d A;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                ex e = GiNaC::evalf(lin.A(lean_steer[i], lean_steer[j]).subs(v == speed));
                A(i, j) = GiNaC::ex_to<GiNaC::numeric>(e).to_double();
            }
        return A;
    }
    std::vector<std::complex<double>> eigenvalues(double speed) const {
        Eigen::EigenSolver<Eigen::Matrix4d> es(A_at(speed));
        std::vector<std::complex<double>> z;
        for (int i = 0; i < 4; ++i) z.push_back(es.eigenvalues()(i));
        return sorted(z);
    }
};

Bicycle& bicycle() {
    static Bicycle b;
    return b;
}

}  // namespace

TEST(WhippleBicycle, FormsWithThreeDependentSpeeds) {
    Bicycle& b = bicycle();
    std::printf("Whipple bicycle: formed in %.3f s, linearized in %.3f s\n", b.form_seconds,
                b.linearize_seconds);
    ASSERT_EQ(b.kane.independent_speeds.size(), 3u);
    ASSERT_EQ(b.kane.dependent_speed_values.size(), 3u);
    // the dependent speeds solved satisfy the motion constraints at random states
    SampleNonholonomicModel& m = b.model;
    const SymbolTable& st = m.system.symbols();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> angle(-0.6, 0.6), speed(-3, 3);
    exmap dep;
    for (std::size_t s = 0; s < 3; ++s)
        dep[b.kane.dependent_speeds[s]] = b.kane.dependent_speed_values[s];
    for (int trial = 0; trial < 5; ++trial) {
        exmap at;
        for (const TimeVariable& q : m.q) at[q.symbol()] = angle(rng);
        for (const ex& u : b.kane.independent_speeds) at[u] = speed(rng);
        for (std::size_t s = 0; s < 3; ++s) at[b.kane.dependent_speeds[s]] =
            st.evaluate(b.kane.dependent_speed_values[s], at);
        for (std::size_t i = 0; i < 3; ++i) {
            ex c = st.expand_intermediates(m.motion_constraints[i]);
            ex kin = c.subs(exmap{{m.q[0].d(1), m.u[0]}, {m.q[1].d(1), m.u[1]},
                                  {m.q[2].d(1), m.u[2]}, {m.q[3].d(1), m.u[3]},
                                  {m.q[4].d(1), m.u[4]}, {m.q[5].d(1), m.u[5]}});
            EXPECT_LT(std::abs(st.evaluate(kin, at)), 1e-12) << "constraint " << i;
        }
    }
}

TEST(WhippleBicycle, DefaultOptionsFormTheSameEquations) {
    // with simplification asked for (the default), the large constraint solve still takes the
    // elimination path and nothing past it is simplified: the same M and f at random states
    Bicycle& b = bicycle();
    SampleNonholonomicModel m = make_whipple_bicycle();
    std::vector<ex> u;
    for (const TimeVariable& ui : m.u) u.push_back(ui.symbol());
    KaneEquations k = form_kane_equations(
        m.system, {.coordinates = m.q,
                   .speeds = u,
                   .kinematic_equations = m.kinematic_equations,
                   .motion_constraints = m.motion_constraints,
                   .dependent_speeds = m.dependent_speeds});
    const SymbolTable& st = m.system.symbols();
    const SymbolTable& st0 = b.model.system.symbols();
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> angle(-0.6, 0.6), speed(-3, 3);
    for (int trial = 0; trial < 3; ++trial) {
        // the two models have their own symbols: the same values by name
        exmap at, at0;
        for (std::size_t i = 0; i < 6; ++i) {
            const double qi = angle(rng), ui = speed(rng);
            at[m.q[i].symbol()] = qi, at0[b.model.q[i].symbol()] = qi;
            at[m.u[i].symbol()] = ui, at0[b.model.u[i].symbol()] = ui;
        }
        for (unsigned i = 0; i < 3; ++i) {
            const double f = st.evaluate(k.dynamics.b(i, 0), at);
            EXPECT_NEAR(f, st0.evaluate(b.kane.dynamics.b(i, 0), at0), 1e-10 * std::max(1.0, std::abs(f)));
            for (unsigned j = 0; j < 3; ++j) {
                const double M = st.evaluate(k.dynamics.A(i, j), at);
                EXPECT_NEAR(M, st0.evaluate(b.kane.dynamics.A(i, j), at0), 1e-10 * std::max(1.0, std::abs(M)));
            }
        }
    }
}

TEST(WhippleBicycle, EigenvaluesMatchMeijaardTable2) {
    Bicycle& b = bicycle();
    double worst = 0;
    for (const MeijaardTable2Row& row : kMeijaardTable2) {
        std::vector<std::complex<double>> got = b.eigenvalues(row.v);
        std::vector<std::complex<double>> want =
            sorted({row.eig[0], row.eig[1], row.eig[2], row.eig[3]});
        for (int i = 0; i < 4; ++i) {
            worst = std::max(worst, std::abs(got[i] - want[i]));
            EXPECT_LT(std::abs(got[i] - want[i]), 1e-10)
                << "v = " << row.v << ": eigenvalue " << got[i] << ", published " << want[i];
        }
    }
    std::printf("largest difference from Table 2: %.2e\n", worst);
}

TEST(WhippleBicycle, WeaveAndCapsizeSpeedsMatchMeijaard) {
    Bicycle& b = bicycle();
    // the largest real part of the weave pair (complex) and of the capsize mode (the real
    // eigenvalue nearest zero), found by bisection where each crosses zero
    auto weave = [&](double v) {
        double re = -1e300;
        for (auto z : b.eigenvalues(v))
            if (std::abs(z.imag()) > 1e-9) re = std::max(re, z.real());
        return re;
    };
    auto capsize = [&](double v) {
        double re = -1e300;
        for (auto z : b.eigenvalues(v))
            if (std::abs(z.imag()) <= 1e-9 && z.real() > -5) re = std::max(re, z.real());
        return re;
    };
    auto crossing = [](auto f, double lo, double hi) {
        double flo = f(lo);
        for (int i = 0; i < 60; ++i) {
            double mid = 0.5 * (lo + hi), fm = f(mid);
            if ((fm > 0) == (flo > 0)) lo = mid, flo = fm;
            else hi = mid;
        }
        return 0.5 * (lo + hi);
    };
    const double vw = crossing(weave, 4, 5), vc = crossing(capsize, 5.5, 7);
    std::printf("weave speed %.14f m/s, capsize speed %.14f m/s\n", vw, vc);
    EXPECT_NEAR(vw, kMeijaardWeaveSpeed, 1e-10);
    EXPECT_NEAR(vc, kMeijaardCapsizeSpeed, 1e-10);
}
