// SPDX-License-Identifier: MIT
// Accuracy against work of the integrators: the chaotic double pendulum over 10 s at a range
// of tolerances, each run's error against a converged reference, its steps and evaluations
// of the dynamics (bench/README.md, "Integrators").
#include <benchmark/benchmark.h>

#include <alembert/mech/sample_models.hpp>
#include <alembert/sim/simulation.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace alembert;

// make_n_link_pendulum(2) released from q = (1.1, 1.4) rad: the lower link turns over and a
// change of 1e-9 rad at the start grows about 4e3-fold by 10 s (tests/sim/integrator_test.cpp)
struct DoublePendulum {
    SampleModel model = make_n_link_pendulum(2);
    ForwardDynamics fd =
        compile_forward_dynamics(model.system, model.q, model.unknowns, "double_pendulum");
    OutputFunction outputs =
        compile_outputs(model.system.symbols(), fd.layout(), {{"q1", model.q[0], "rad"}});
    std::vector<double> q0{1.1, 1.4}, qd0{0.0, 0.0};

    // one run; `evaluations` counts the calls of the dynamics
    SimulationResult run(Integrator method, double tol, std::size_t* evaluations = nullptr) const {
        NumericFunction f = fd.function();
        if (evaluations) {
            auto inner = f.evaluate;
            f.evaluate = [inner, evaluations](const double* in, double* out) {
                ++*evaluations;
                inner(in, out);
            };
        }
        ForwardDynamics counted(fd.model(), fd.layout(), f);
        SimulationOptions o{.t_final = 10.0, .integrator = method, .output_step = 10.0,
                            .abs_tol = tol, .rel_tol = tol, .progress = false};
        return simulate(counted, q0, qd0, o, outputs);
    }
};

const DoublePendulum& pendulum() {
    static const auto* p = new DoublePendulum();
    return *p;
}

const std::vector<double>& reference() {
    static const std::vector<double> q = pendulum().run(Integrator::rkf78, 1e-15).q_end;
    return q;
}

void BM_DoublePendulum10s(benchmark::State& state) {
    const auto method = static_cast<Integrator>(state.range(0));
    const double tol = std::pow(10.0, -static_cast<double>(state.range(1)));
    const DoublePendulum& p = pendulum();
    const std::vector<double>& ref = reference();
    SimulationResult r;
    for (auto _ : state) {
        r = p.run(method, tol);
        benchmark::DoNotOptimize(r.q_end.data());
    }
    std::size_t evaluations = 0;
    r = p.run(method, tol, &evaluations);
    double error = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) error = std::max(error, std::abs(r.q_end[i] - ref[i]));
    state.SetLabel(std::string(to_string(method)) + " tol 1e-" + std::to_string(state.range(1)));
    state.counters["error_rad"] = error;
    state.counters["steps"] = static_cast<double>(r.steps);
    state.counters["evaluations"] = static_cast<double>(evaluations);
}

void integrator_arguments(benchmark::internal::Benchmark* b) {
    for (int method = 0; method < 4; ++method)
        for (int digits = 8; digits <= 14; digits += 2) b->Args({method, digits});
}

BENCHMARK(BM_DoublePendulum10s)->Apply(integrator_arguments)->Unit(benchmark::kMillisecond);

// the stiff spring-damper of the tests (time constants 1 s and 1 us) over 1 s at 1e-8
struct StiffSpringDamper {
    SampleModel model = [] {
        SampleModel m = make_mass_spring_damper();
        SymbolTable& s = m.system.symbols();
        s.set_value(s.symbol("k"), 1e6);
        s.set_value(s.symbol("c"), 1e6 + 1);
        return m;
    }();
    ForwardDynamics fd = compile_forward_dynamics(model.system, model.q, {}, "stiff");
    OutputFunction outputs =
        compile_outputs(model.system.symbols(), fd.layout(), {{"x", model.q[0], "m"}});
};

void BM_StiffSpringDamper1s(benchmark::State& state) {
    static const auto* p = new StiffSpringDamper();
    const auto method = static_cast<Integrator>(state.range(0));
    SimulationOptions o{.t_final = 1.0, .integrator = method, .output_step = 1.0,
                        .abs_tol = 1e-8, .rel_tol = 1e-8, .progress = false};
    SimulationResult r;
    for (auto _ : state) {
        r = simulate(p->fd, {1.0}, {0.0}, o, p->outputs);
        benchmark::DoNotOptimize(r.q_end.data());
    }
    const double A = 1 / (1 - 1e-6), B = 1 - A;
    state.SetLabel(std::string(to_string(method)));
    state.counters["error_m"] = std::abs(r.q_end[0] - (A * std::exp(-1.0) + B * std::exp(-1e6)));
    state.counters["steps"] = static_cast<double>(r.steps);
}

BENCHMARK(BM_StiffSpringDamper1s)
    ->Arg(static_cast<int>(Integrator::dopri5))
    ->Arg(static_cast<int>(Integrator::rkf78))
    ->Arg(static_cast<int>(Integrator::bdf))
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
