// SPDX-License-Identifier: MIT
// Compile time, tape length and time per call of compiled Kane equations of n-link chains.
#include <benchmark/benchmark.h>

#include <alembert/eom/kane.hpp>
#include <alembert/mech/sample_models.hpp>
#include <alembert/sym/cse.hpp>
#include <alembert/sym/evaluator.hpp>
#include <alembert/sym/simplify.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

namespace {

using namespace alembert;

// an n-link pendulum and its Kane equations, formed once per size (formation time is
// eom_formation_bench's subject); inputs are q, q', q'' of each joint and the joint torques
struct Fixture {
    Fixture(ChainKind kind, int n) : model(make_n_link_pendulum(n, kind)) {
        equations = form_kane_equations(model.system, model.q);
        for (const ex& e : equations) tree_ops += count_ops(e);
        for (const TimeVariable& q : model.q)
            for (int k = 0; k <= 2; ++k) inputs.push_back(q.d(k));
        inputs.insert(inputs.end(), model.unknowns.begin(), model.unknowns.end());
        for (std::size_t i = 0; i < inputs.size(); ++i)
            state.push_back(0.3 + 0.1 * static_cast<double>(i % 7) - 0.05 * static_cast<double>(i));
        // the same equations with repeated subexpressions named (adds intermediates to the table)
        equations_cse = equations;
        introduce_intermediates(model.system.symbols(), equations_cse);
        cse_ops = count_ops_with_intermediates(model.system.symbols(), equations_cse);
    }
    SampleModel model;
    std::vector<ex> equations, equations_cse, inputs;
    std::vector<double> state;
    std::size_t tree_ops = 0, cse_ops = 0;
};

const Fixture& fixture(ChainKind kind, const benchmark::State& state) {
    static std::map<std::pair<ChainKind, int>, std::unique_ptr<Fixture>> cache;
    const int n = static_cast<int>(state.range(0));
    auto& f = cache[{kind, n}];
    if (!f) f = std::make_unique<Fixture>(kind, n);
    return *f;
}

const SymbolTable& table(const Fixture& f) { return f.model.system.symbols(); }

void counters(benchmark::State& state, const Fixture& f, const CompiledExpressions& c) {
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["ops_tree"] = static_cast<double>(f.tree_ops);
    state.counters["ops_cse"] = static_cast<double>(f.cse_ops);
    state.counters["ops_tape"] = static_cast<double>(c.operation_count());
}

// compilation of the raw equations (hash-consing finds the sharing)
void compile_raw(benchmark::State& state, ChainKind kind) {
    const Fixture& f = fixture(kind, state);
    std::size_t ops = 0;
    for (auto _ : state) {
        CompiledExpressions c(table(f), f.inputs, f.equations);
        ops = c.operation_count();
        benchmark::DoNotOptimize(ops);
    }
    counters(state, f, CompiledExpressions(table(f), f.inputs, f.equations));
}

// compilation of the equations after naming repeated subexpressions
void compile_cse(benchmark::State& state, ChainKind kind) {
    const Fixture& f = fixture(kind, state);
    for (auto _ : state) {
        CompiledExpressions c(table(f), f.inputs, f.equations_cse);
        benchmark::DoNotOptimize(c);
    }
    counters(state, f, CompiledExpressions(table(f), f.inputs, f.equations_cse));
}

// one evaluation of all residuals at a state
void evaluate(benchmark::State& state, ChainKind kind) {
    const Fixture& f = fixture(kind, state);
    const CompiledExpressions c(table(f), f.inputs, f.equations);
    std::vector<double> out(c.output_count());
    for (auto _ : state) {
        c.evaluate(f.state.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, f, c);
}

// the reference: SymbolTable::evaluate (GiNaC subs + evalf) of each residual; the counter
// max_diff is the largest difference from the compiled values
void evaluate_by_symbol_table(benchmark::State& state, ChainKind kind) {
    const Fixture& f = fixture(kind, state);
    GiNaC::exmap at;
    for (std::size_t i = 0; i < f.inputs.size(); ++i) at[f.inputs[i]] = f.state[i];
    std::vector<double> out(f.equations.size());
    for (auto _ : state) {
        for (std::size_t k = 0; k < f.equations.size(); ++k)
            out[k] = table(f).evaluate(f.equations[k], at);
        benchmark::DoNotOptimize(out.data());
    }
    const CompiledExpressions c(table(f), f.inputs, f.equations);
    std::vector<double> compiled = c.evaluate(f.state);
    double diff = 0;
    for (std::size_t k = 0; k < out.size(); ++k)
        diff = std::max(diff, std::fabs(out[k] - compiled[k]));
    counters(state, f, c);
    state.counters["max_diff"] = diff;
}

void BM_PlanarCompile(benchmark::State& s) { compile_raw(s, ChainKind::planar); }
void BM_PlanarCompileCse(benchmark::State& s) { compile_cse(s, ChainKind::planar); }
void BM_PlanarEvaluate(benchmark::State& s) { evaluate(s, ChainKind::planar); }
void BM_PlanarSymbolTableEvaluate(benchmark::State& s) {
    evaluate_by_symbol_table(s, ChainKind::planar);
}
void BM_SpatialCompile(benchmark::State& s) { compile_raw(s, ChainKind::spatial); }
void BM_SpatialEvaluate(benchmark::State& s) { evaluate(s, ChainKind::spatial); }

}  // namespace

BENCHMARK(BM_PlanarCompile)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarCompileCse)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanarEvaluate)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlanarSymbolTableEvaluate)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SpatialCompile)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpatialEvaluate)->Arg(4)->Arg(6)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
