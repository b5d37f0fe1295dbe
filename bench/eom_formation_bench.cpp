// SPDX-License-Identifier: MIT
// Formation time and operation counts of the equations of n-link chains, by each method.
#include <benchmark/benchmark.h>

#include <alembert/alembert.hpp>
#include <alembert/eom/kane.hpp>
#include <alembert/eom/lagrange.hpp>
#include <alembert/eom/planner.hpp>
#include <alembert/lang/interpreter.hpp>

#include <fstream>
#include <sstream>

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

// the KUKA LBR iiwa 14 of examples/kuka_iiwa/model.alb: the road-map for its 7 motor torques
// and 35 joint reaction measures (42 rows), the model built by the script outside the timing
void BM_KukaIiwaRoadmap(benchmark::State& state) {
    std::ifstream file(ALEMBERT_SOURCE_DIR "/examples/kuka_iiwa/model.alb");
    std::stringstream source;
    source << file.rdbuf();
    std::ostringstream out, err;
    lang::Interpreter in(out, err, false);
    in.set_model_only(true);
    if (in.run(source.str(), "model.alb") != lang::RunStatus::ok || !in.system()) {
        state.SkipWithError(("examples/kuka_iiwa/model.alb: " + err.str()).c_str());
        return;
    }
    const System& sys = *in.system();
    const SymbolTable& st = sys.symbols();
    std::vector<TimeVariable> q;
    std::vector<ex> x;
    for (int i = 1; i <= 7; ++i) {
        const std::string n = std::to_string(i);
        q.push_back(st.variable("q" + n));
        x.push_back(st.symbol("T" + n));
    }
    for (int i = 1; i <= 7; ++i)
        for (const char* c : {"F%x", "F%y", "F%z", "M%x", "M%y"}) {
            std::string name = c;
            name.replace(1, 1, std::to_string(i));
            x.push_back(st.symbol(name));
        }
    std::size_t ops = 0, rows = 0;
    for (auto _ : state) {
        std::vector<RoadmapRow> R = plan_roadmap(sys, q, x);
        benchmark::DoNotOptimize(R);
        state.PauseTiming();
        rows = R.size();
        ops = 0;
        for (const RoadmapRow& r : R) ops += count_ops(r.equation);
        state.ResumeTiming();
    }
    state.counters["rows"] = static_cast<double>(rows);
    state.counters["ops"] = static_cast<double>(ops);
}

}  // namespace

BENCHMARK(BM_KukaIiwaRoadmap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarKane)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Arg(16)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarRoadmap)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarLagrange)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialKane)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Arg(10)->Arg(12)->Arg(16)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialRoadmap)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialLagrange)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_PlanarTree)->Arg(4)->Arg(8)->Arg(16)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialTree)->Arg(4)->Arg(8)->Arg(16)->Arg(30)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
