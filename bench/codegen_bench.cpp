// SPDX-License-Identifier: MIT
// Generated C for the benchmark planar chain: operation counts beside the recursive
// algorithms, compiled ns per call of inverse and forward dynamics beside the hand-written
// O(n) recursion (measured in the same run), and generation time.
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <alembert/codegen/code_plan.hpp>
#include <alembert/codegen/codegen.hpp>
#include <alembert/eom/kane.hpp>
#include <alembert/eom/tree_dynamics.hpp>
#include <alembert/mech/sample_models.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "planar_chain_reference.hpp"

namespace {

using namespace alembert;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// How the equations the generator starts from are formed.
enum Formation {
    kane = 0,  // Kane's equations; forward dynamics by M, f and a Cholesky solve
    tree = 1,  // the recursive road-map rows and the articulated-body accelerations
};

// the chain's equations, formed once per size (formation is eom_formation_bench's subject),
// generated as C with the constants folded, compiled with cc -O2 and loaded
struct Generated {
    using Init = void (*)(void*, const void*);
    using Inverse = void (*)(const void*, double, const double*, const double*, const double*,
                             double*);
    using Forward = int (*)(const void*, double, const double*, const double*, const double*,
                            double*);

    Generated(int n, Formation formation) : n(n), model(make_planar_chain(n)) {
        if (formation == tree) {
            TreeEquations t = form_tree_equations(model.system, model.q);
            residuals = t.residuals;
            equations = {model.q, residuals, model.unknowns, std::nullopt, t.accelerations};
        } else {
            residuals = form_kane_equations(model.system, model.q);
            equations = {model.q, residuals, model.unknowns, std::nullopt};
        }
        options.name = "chain";
        options.source = "make_planar_chain(" + std::to_string(n) + "), " +
                         (formation == tree ? "recursive formation" : "Kane's equations");
        options.parameters = std::vector<ex>{};  // fold the constants: the fastest code
        CodePlan plan = plan_code(model.system.symbols(), equations, options);
        const StraightLineProgram& id = plan.inverse_dynamics.program;
        const StraightLineProgram& mf = plan.mass_forcing.program;
        id_ops = id.operation_count(id.body);
        id_calls = id.call_count(id.body);
        mf_ops = mf.operation_count(mf.body);
        mf_calls = mf.call_count(mf.body);
        if (!plan.accelerations.empty()) {
            const StraightLineProgram& fd = plan.accelerations.program;
            fd_ops = fd.operation_count(fd.body);
            fd_calls = fd.call_count(fd.body);
        }

        dir = fs::temp_directory_path() /
              ("alembert-codegen-bench-" + std::to_string(::getpid()) + "-" + std::to_string(n));
        fs::create_directories(dir);
        auto t0 = Clock::now();
        generate_code(model.system.symbols(), equations, Language::c, dir, options);
        generate_seconds = seconds_since(t0);
        std::ofstream(dir / "context.c")
            << "#include <stddef.h>\n#include \"chain.h\"\n"
               "size_t chain_context_size(void) { return sizeof(chain_context); }\n";
        const fs::path lib = dir / "chain.so";
        const std::string cc = std::getenv("CC") ? std::getenv("CC") : "cc";
        t0 = Clock::now();
        std::string cmd = "cd " + dir.string() + " && " + cc +
                          " -O2 -shared -fPIC -o chain.so chain.c context.c -lm";
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("compiling failed: " + cmd);
        compile_seconds = seconds_since(t0);
        handle = ::dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error(::dlerror());
        auto size = reinterpret_cast<std::size_t (*)()>(::dlsym(handle, "chain_context_size"));
        auto init = reinterpret_cast<Init>(::dlsym(handle, "chain_init"));
        inverse = reinterpret_cast<Inverse>(::dlsym(handle, "chain_inverse_dynamics"));
        forward = reinterpret_cast<Forward>(::dlsym(handle, "chain_forward_dynamics"));
        context.resize(size() / sizeof(double) + 1);
        init(context.data(), nullptr);

        // a random state, and the same answers as the hand-written recursion there
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> d(-1, 1);
        for (int i = 0; i < n; ++i) {
            q.push_back(d(rng));
            qd.push_back(d(rng));
            qdd.push_back(d(rng));
            tau.push_back(10 * d(rng));
        }
        bench::PlanarChainReference ref(n);
        std::vector<double> a(static_cast<std::size_t>(n)), b(a);
        ref.inverse_dynamics(q.data(), qd.data(), qdd.data(), a.data());
        inverse(context.data(), 0.0, q.data(), qd.data(), qdd.data(), b.data());
        for (int i = 0; i < n; ++i) max_diff_id = std::max(max_diff_id, std::fabs(a[i] - b[i]));
        ref.forward_dynamics(q.data(), qd.data(), tau.data(), a.data());
        if (forward(context.data(), 0.0, q.data(), qd.data(), tau.data(), b.data()) != 0)
            throw std::runtime_error("forward dynamics: singular mass matrix");
        for (int i = 0; i < n; ++i) max_diff_fd = std::max(max_diff_fd, std::fabs(a[i] - b[i]));
    }
    ~Generated() {
        if (handle) ::dlclose(handle);
        std::error_code ec;
        fs::remove_all(dir, ec);
    }

    int n;
    SampleModel model;
    std::vector<ex> residuals;
    DynamicsEquations equations;
    CodegenOptions options;
    std::size_t id_ops = 0, id_calls = 0, mf_ops = 0, mf_calls = 0, fd_ops = 0, fd_calls = 0;
    double generate_seconds = 0, compile_seconds = 0, max_diff_id = 0, max_diff_fd = 0;
    fs::path dir;
    void* handle = nullptr;
    Inverse inverse = nullptr;
    Forward forward = nullptr;
    std::vector<double> context;  // the generated chain_context, aligned for doubles
    std::vector<double> q, qd, qdd, tau;
};

Generated& generated(const benchmark::State& state) {
    static std::map<std::pair<int, int>, std::unique_ptr<Generated>> cache;
    const int n = static_cast<int>(state.range(0)), f = static_cast<int>(state.range(1));
    auto& g = cache[{n, f}];
    if (!g) g = std::make_unique<Generated>(n, static_cast<Formation>(f));
    return *g;
}

void counters(benchmark::State& state, const Generated& g) {
    const double n = g.n;
    state.counters["links"] = n;
    state.counters["ops_id"] = static_cast<double>(g.id_ops);
    state.counters["calls_id"] = static_cast<double>(g.id_calls);
    state.counters["ops_mf"] = static_cast<double>(g.mf_ops);
    state.counters["calls_mf"] = static_cast<double>(g.mf_calls);
    state.counters["ops_fd"] = static_cast<double>(g.fd_ops);  // explicit accelerations
    state.counters["calls_fd"] = static_cast<double>(g.fd_calls);
    state.counters["ops_rnea_3d"] = 174 * n;   // Featherstone's count for a general 3D chain
    state.counters["ops_planar_rec"] = 45 * n;  // the hand-written recursion, plus n sin/cos
    state.counters["max_diff_id"] = g.max_diff_id;
    state.counters["max_diff_fd"] = g.max_diff_fd;
}

void GeneratedInverseDynamics(benchmark::State& state) {
    Generated& g = generated(state);
    std::vector<double> u(static_cast<std::size_t>(g.n));
    for (auto _ : state) {
        g.inverse(g.context.data(), 0.0, g.q.data(), g.qd.data(), g.qdd.data(), u.data());
        benchmark::DoNotOptimize(u.data());
        benchmark::ClobberMemory();
    }
    counters(state, g);
    state.counters["compile_s"] = g.compile_seconds;
}

void ReferenceInverseDynamics(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    Generated& g = generated(state);
    bench::PlanarChainReference ref(n);
    std::vector<double> u(static_cast<std::size_t>(n));
    for (auto _ : state) {
        ref.inverse_dynamics(g.q.data(), g.qd.data(), g.qdd.data(), u.data());
        benchmark::DoNotOptimize(u.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = n;
}

void GeneratedForwardDynamics(benchmark::State& state) {
    Generated& g = generated(state);
    std::vector<double> a(static_cast<std::size_t>(g.n));
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            g.forward(g.context.data(), 0.0, g.q.data(), g.qd.data(), g.tau.data(), a.data()));
        benchmark::ClobberMemory();
    }
    counters(state, g);
}

void ReferenceForwardDynamics(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    Generated& g = generated(state);
    bench::PlanarChainReference ref(n);
    std::vector<double> a(static_cast<std::size_t>(n));
    for (auto _ : state) {
        ref.forward_dynamics(g.q.data(), g.qd.data(), g.tau.data(), a.data());
        benchmark::DoNotOptimize(a.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = n;
}

// generate_code alone (planning, printing, writing C), the equations formed beforehand
void GenerateC(benchmark::State& state) {
    Generated& g = generated(state);
    const fs::path dir = g.dir / "again";
    for (auto _ : state) {
        GeneratedCode code = generate_code(g.model.system.symbols(), g.equations, Language::c,
                                           dir, g.options);
        benchmark::DoNotOptimize(code.files.data());
    }
    counters(state, g);
}

}  // namespace

// arguments: links n, formation (0 Kane, 1 recursive); the references use the recursive
// formation's compiled code only for the shared random state
BENCHMARK(GeneratedInverseDynamics)->ArgsProduct({{3, 7, 15, 30}, {tree, kane}});
BENCHMARK(ReferenceInverseDynamics)->ArgsProduct({{3, 7, 15, 30}, {tree}});
BENCHMARK(GeneratedForwardDynamics)->ArgsProduct({{3, 7, 15, 30}, {tree, kane}});
BENCHMARK(ReferenceForwardDynamics)->ArgsProduct({{3, 7, 15, 30}, {tree}});
BENCHMARK(GenerateC)->ArgsProduct({{3, 7, 15, 30}, {tree, kane}})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
