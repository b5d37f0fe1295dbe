// SPDX-License-Identifier: MIT
// Formation of the Whipple bicycle (make_whipple_bicycle: 6 speeds, 3 motion constraints
// solved for dependent speeds) by Kane's method, with and without simplification, and its
// linearization about upright straight running (bench/README.md).
#include <benchmark/benchmark.h>

#include <alembert/eom/kane.hpp>
#include <alembert/eom/linearize.hpp>
#include <alembert/mech/sample_models.hpp>
#include <alembert/sym/simplify.hpp>

namespace {

using namespace alembert;

KaneOptions options_of(const SampleNonholonomicModel& m, bool simplify) {
    std::vector<ex> u;
    for (const TimeVariable& ui : m.u) u.push_back(ui.symbol());
    return {.coordinates = m.q,
            .speeds = u,
            .kinematic_equations = m.kinematic_equations,
            .motion_constraints = m.motion_constraints,
            .dependent_speeds = m.dependent_speeds,
            .simplify = simplify};
}

// the operations of the residuals and of every intermediate they reach, each once
double full_ops(const SymbolTable& st, const std::vector<ex>& es) {
    GiNaC::exset seen;
    std::vector<ex> todo(es.begin(), es.end());
    double ops = 0;
    while (!todo.empty()) {
        ex e = todo.back();
        todo.pop_back();
        ops += static_cast<double>(count_ops(e));
        for (const ex& s : symbols_of(e))
            if (st.owns(s) && st.kind(s) == SymbolKind::intermediate && seen.insert(s).second)
                todo.push_back(st.definition(s));
    }
    return ops;
}

void BicycleKane(benchmark::State& state) {
    const bool simplify = state.range(0) != 0;
    double ops = 0;
    for (auto _ : state) {
        state.PauseTiming();
        SampleNonholonomicModel m = make_whipple_bicycle();
        state.ResumeTiming();
        KaneEquations k = form_kane_equations(m.system, options_of(m, simplify));
        state.PauseTiming();
        ops = full_ops(m.system.symbols(), k.residuals);
        state.ResumeTiming();
    }
    state.counters["ops_z"] = ops;
}

void BicycleLinearize(benchmark::State& state) {
    for (auto _ : state) {
        state.PauseTiming();
        SampleNonholonomicModel m = make_whipple_bicycle();
        KaneEquations k = form_kane_equations(m.system, options_of(m, false));
        const SymbolTable& st = m.system.symbols();
        exmap op = st.constant_values();
        for (const TimeVariable& q : m.q) op[q.symbol()] = 0;
        op[m.u[1]] = 0, op[m.u[4]] = 0, op[m.u[2]] = 5 / *st.value(st.symbol("r_R"));
        FirstOrderEquations f = to_first_order(k);
        state.ResumeTiming();
        LinearizedEquations lin = linearize(st, f, {.operating_point = op, .simplify = false});
        benchmark::DoNotOptimize(lin.A);
    }
}

}  // namespace

BENCHMARK(BicycleKane)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BicycleLinearize)->Unit(benchmark::kSecond)->Iterations(1);

BENCHMARK_MAIN();
