// SPDX-License-Identifier: MIT
// Formation time and operation counts of the equations of n-link chains, by each method.
#include <benchmark/benchmark.h>

#include <alembert/alembert.hpp>
#include <alembert/eom/kane.hpp>
#include <alembert/eom/lagrange.hpp>
#include <alembert/eom/planner.hpp>

namespace {

using namespace alembert;

// tree: the recursive rows and the articulated-body accelerations (both formed; the rows are
// what the counters measure)
enum class Method { roadmap, kane, lagrange, tree };

std::vector<ex> form(const SampleModel& m, Method method) {
    std::vector<ex> acc;
    for (const TimeVariable& q : m.q) acc.push_back(q.d(2));
    switch (method) {
        case Method::roadmap: {
            std::vector<ex> E;
            for (const RoadmapRow& r : plan_roadmap(m.system, m.q, acc)) E.push_back(r.equation);
            return E;
        }
        case Method::kane: return form_kane_equations(m.system, m.q);
        case Method::lagrange: return form_lagrange_equations(m.system, m.q);
        case Method::tree: return form_tree_equations(m.system, m.q).residuals;
    }
    return {};
}

// formation only (the model is built outside the timed region), then the size of the result
void run(benchmark::State& state, ChainKind kind, Method method) {
    const int n = static_cast<int>(state.range(0));
    std::size_t ops = 0, ops_with_z = 0, ops_cse = 0;
    for (auto _ : state) {
        state.PauseTiming();
        SampleModel m = make_n_link_pendulum(n, kind);
        state.ResumeTiming();
        std::vector<ex> E = form(m, method);
        benchmark::DoNotOptimize(E);
        state.PauseTiming();
        ops = 0;
        for (const ex& e : E) ops += count_ops(e);
        ops_with_z = count_ops_with_intermediates(m.system.symbols(), E);
        introduce_intermediates(m.system.symbols(), E);
        ops_cse = count_ops_with_intermediates(m.system.symbols(), E);
        state.ResumeTiming();
    }
    state.counters["links"] = n;
    state.counters["ops"] = static_cast<double>(ops);
    state.counters["ops_z"] = static_cast<double>(ops_with_z);
    state.counters["ops_cse"] = static_cast<double>(ops_cse);
}

void BM_PlanarKane(benchmark::State& s) { run(s, ChainKind::planar, Method::kane); }
void BM_PlanarRoadmap(benchmark::State& s) { run(s, ChainKind::planar, Method::roadmap); }
void BM_PlanarLagrange(benchmark::State& s) { run(s, ChainKind::planar, Method::lagrange); }
void BM_SpatialKane(benchmark::State& s) { run(s, ChainKind::spatial, Method::kane); }
void BM_SpatialRoadmap(benchmark::State& s) { run(s, ChainKind::spatial, Method::roadmap); }
void BM_SpatialLagrange(benchmark::State& s) { run(s, ChainKind::spatial, Method::lagrange); }
void BM_PlanarTree(benchmark::State& s) { run(s, ChainKind::planar, Method::tree); }
void BM_SpatialTree(benchmark::State& s) { run(s, ChainKind::spatial, Method::tree); }

}  // namespace

BENCHMARK(BM_PlanarKane)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Arg(16)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarRoadmap)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarLagrange)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialKane)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Arg(16)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialRoadmap)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLagrange)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_PlanarTree)->Arg(4)->Arg(8)->Arg(16)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialTree)->Arg(4)->Arg(8)->Arg(16)->Arg(30)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
