// SPDX-License-Identifier: MIT
// Printing against the size of the expression (bench/README.md, "Printing and planning at
// scale"): wide sums of products, nested trees, and DAGs whose shared nodes are reached many
// times. Counters: nodes (distinct subexpressions), chars (printed length).
#include <benchmark/benchmark.h>

#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "alembert/sym/print.hpp"

namespace {

using namespace GiNaC;

std::vector<symbol> symbols(const char* stem, int n) {
    std::vector<symbol> out;
    for (int i = 0; i < n; ++i) out.emplace_back(stem + std::to_string(i));
    return out;
}

// sum of n distinct terms c*x_i*y_j*z_k*sin(q_l - q_m): what a long equation of motion looks
// like
ex wide(int n) {
    auto x = symbols("x", 100), y = symbols("y", 100), z = symbols("z", 10), q = symbols("q", 7);
    ex s = 0;
    for (int i = 0; i < n; ++i)
        s += (i % 7 + 1) * x[i % 100] * y[(i / 100) % 100] * z[(i / 10000) % 10] * sin(q[i % 7] - q[(i / 7) % 7]);
    return s;
}

// a tree n levels deep: e_{k+1} = a_k*(e_k - b_k) + cos(q_k)*c_k, every level a sum inside a
// product (where the printer decides signs)
ex deep(int n) {
    auto a = symbols("a", 50), q = symbols("q", 50);
    ex e = a[0];
    for (int k = 0; k < n; ++k)
        e = a[k % 50] * (e - a[(k + 1) % 50]) + cos(q[k % 50]) * a[(k + 2) % 50];
    return e;
}

// a balanced tree of products of sums, fan-out 2, 2^depth leaves
ex balanced(int depth, int& next) {
    static const std::vector<symbol> x = symbols("y", 64);
    if (depth == 0) return x[static_cast<std::size_t>(next++ % 64)];
    ex l = balanced(depth - 1, next), r = balanced(depth - 1, next);
    return (depth % 2) ? ex(l * (r - x[static_cast<std::size_t>(depth)])) : ex(l + r);
}

std::size_t distinct_nodes(const ex& e) {
    exset seen;
    std::vector<ex> stack{e};
    while (!stack.empty()) {
        ex x = stack.back();
        stack.pop_back();
        if (!seen.insert(x).second) continue;
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
    }
    return seen.size();
}

// prints e once per iteration; counters: its distinct nodes and the characters printed
void time_printing(benchmark::State& state, const ex& e) {
    std::size_t chars = 0;
    for (auto _ : state) {
        std::string s = alembert::to_string(e);
        chars = s.size();
        benchmark::DoNotOptimize(s);
    }
    const std::size_t nodes = distinct_nodes(e);
    state.counters["nodes"] = static_cast<double>(nodes);
    state.counters["chars"] = static_cast<double>(chars);
    state.SetComplexityN(static_cast<benchmark::IterationCount>(nodes));
}

void BM_PrintWideSum(benchmark::State& state) { time_printing(state, wide(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_PrintWideSum)->RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond)->Complexity();

void BM_PrintDeepTree(benchmark::State& state) { time_printing(state, deep(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_PrintDeepTree)->RangeMultiplier(4)->Range(64, 1024)->Unit(benchmark::kMillisecond)->Complexity();

void BM_PrintBalancedTree(benchmark::State& state) {
    int next = 0;
    time_printing(state, balanced(static_cast<int>(state.range(0)), next));
}
BENCHMARK(BM_PrintBalancedTree)->DenseRange(8, 18, 2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
