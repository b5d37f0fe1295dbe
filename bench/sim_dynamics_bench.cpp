// SPDX-License-Identifier: MIT
// Nanoseconds per call of inverse and forward dynamics of the planar chain: Alembert's compiled
// tape beside a hand-written O(n) recursion for exactly that model (bench/README.md).
#include <benchmark/benchmark.h>

#include <alembert/eom/kane.hpp>
#include <alembert/mech/sample_models.hpp>
#include <alembert/sim/forward_dynamics.hpp>
#include <alembert/sim/inverse_dynamics.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "planar_chain_reference.hpp"

#ifdef ALEMBERT_BENCH_MUJOCO
#include <mujoco/mujoco.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#endif

namespace {

using namespace alembert;

// make_planar_chain(n): upright 1 m / 1 kg rods, relative angles, gravity 9.81 along -y.
// Inverse dynamics from Kane's equations solved for the torques (each equation holds one
// torque, so the solved form is compiled); forward dynamics from Kane's mass-matrix form,
// solved by LDLT. Formation and compilation happen once per size, outside the timed region.
struct Fixture {
    explicit Fixture(int n)
        : model(make_planar_chain(n)),
          id(compile_inverse_dynamics(
              model.system.symbols(),
              form_linear_system(form_kane_equations(model.system, model.q), model.unknowns),
              model.q, "planar_chain")),
          fd(compile_forward_dynamics(model.system, model.q, model.unknowns, "planar_chain")),
          reference(n) {
        const auto un = static_cast<std::size_t>(n);
        for (std::size_t i = 0; i < un; ++i) {
            const double k = static_cast<double>(i);
            q.push_back(0.3 - 0.07 * k), qd.push_back(0.5 - 0.05 * k);
            qdd.push_back(0.2 + 0.03 * k), tau.push_back(1.0 - 0.1 * k);
        }
        out.resize(un);
        mf.resize(fd.function().output_count);
        in.assign(fd.function().input_count, 0.1);
    }
    SampleModel model;
    InverseDynamics id;
    ForwardDynamics fd;
    alembert::bench::PlanarChainReference reference;
    std::vector<double> q, qd, qdd, tau, out, mf, in;
};

Fixture& fixture(const benchmark::State& state) {
    static std::map<int, std::unique_ptr<Fixture>> cache;
    const int n = static_cast<int>(state.range(0));
    auto& f = cache[n];
    if (!f) f = std::make_unique<Fixture>(n);
    return *f;
}

void BM_InverseReference(benchmark::State& state) {
    Fixture& f = fixture(state);
    for (auto _ : state) {
        f.reference.inverse_dynamics(f.q.data(), f.qd.data(), f.qdd.data(), f.out.data());
        benchmark::DoNotOptimize(f.out.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
}

void BM_InverseTape(benchmark::State& state) {
    Fixture& f = fixture(state);
    for (auto _ : state) {
        f.id.calc_loads(0.0, f.q.data(), f.qd.data(), f.qdd.data(), f.out.data());
        benchmark::DoNotOptimize(f.out.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["ops"] = static_cast<double>(f.id.function().operation_count);
}

// inverse dynamics from the planned MG road-map (one row per torque about its joint)
void BM_InverseTapeRoadmap(benchmark::State& state) {
    Fixture& f = fixture(state);
    static std::map<int, std::unique_ptr<InverseDynamics>> cache;
    auto& id = cache[static_cast<int>(state.range(0))];
    if (!id)
        id = std::make_unique<InverseDynamics>(
            compile_inverse_dynamics(f.model.system, f.model.q, f.model.unknowns, "planar_chain"));
    for (auto _ : state) {
        id->calc_loads(0.0, f.q.data(), f.qd.data(), f.qdd.data(), f.out.data());
        benchmark::DoNotOptimize(f.out.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["ops"] = static_cast<double>(id->function().operation_count);
}

void BM_ForwardReference(benchmark::State& state) {
    Fixture& f = fixture(state);
    for (auto _ : state) {
        f.reference.forward_dynamics(f.q.data(), f.qd.data(), f.tau.data(), f.out.data());
        benchmark::DoNotOptimize(f.out.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
}

// M, f by the tape, then the LDLT solve (with the symmetry and condition checks)
void BM_ForwardTape(benchmark::State& state) {
    Fixture& f = fixture(state);
    for (auto _ : state) {
        f.fd.calc_accelerations(0.0, f.q.data(), f.qd.data(), f.tau.data(), f.out.data());
        benchmark::DoNotOptimize(f.out.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["ops"] = static_cast<double>(f.fd.function().operation_count);
}

// the evaluation of M and f alone (the rest of BM_ForwardTape is the solve)
void BM_ForwardTapeEvaluateOnly(benchmark::State& state) {
    Fixture& f = fixture(state);
    for (auto _ : state) {
        f.fd.function().evaluate(f.in.data(), f.mf.data());
        benchmark::DoNotOptimize(f.mf.data());
        benchmark::ClobberMemory();
    }
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["ops"] = static_cast<double>(f.fd.function().operation_count);
}

#ifdef ALEMBERT_BENCH_MUJOCO
// MuJoCo's mj_inverse on the same chain (built only where Debian's libmujoco-dev is installed):
// nested bodies with hinges about z, inertial frames at mid-length (the rod's own axis gets a
// negligible inertia, which planar motion never uses), gravity along -y, no geoms, no damping
struct MujocoChain {
    explicit MujocoChain(int n) {
        std::string xml = "<mujoco><option gravity=\"0 -9.81 0\"/><worldbody>";
        for (int i = 0; i < n; ++i)
            xml += std::string("<body pos=\"0 ") + (i == 0 ? "0" : "1") +
                   " 0\"><joint type=\"hinge\" axis=\"0 0 1\"/><inertial pos=\"0 0.5 0\" "
                   "mass=\"1\" diaginertia=\"0.0833333333333333 1e-9 0.0833333333333333\"/>";
        for (int i = 0; i < n; ++i) xml += "</body>";
        xml += "</worldbody></mujoco>";
        const std::string path = "/tmp/alembert_bench_chain_" + std::to_string(n) + ".xml";
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(xml.c_str(), f);
        std::fclose(f);
        char error[1000] = "";
        model = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
        if (!model) throw std::runtime_error(std::string("MuJoCo: ") + error);
        data = mj_makeData(model);
    }
    ~MujocoChain() {
        mj_deleteData(data);
        mj_deleteModel(model);
    }
    mjModel* model = nullptr;
    mjData* data = nullptr;
};

void BM_InverseMujoco(benchmark::State& state) {
    Fixture& f = fixture(state);
    static std::map<int, std::unique_ptr<MujocoChain>> cache;
    auto& mj = cache[static_cast<int>(state.range(0))];
    if (!mj) mj = std::make_unique<MujocoChain>(static_cast<int>(state.range(0)));
    for (std::size_t i = 0; i < f.q.size(); ++i)
        mj->data->qpos[i] = f.q[i], mj->data->qvel[i] = f.qd[i], mj->data->qacc[i] = f.qdd[i];
    for (auto _ : state) {
        mj_inverse(mj->model, mj->data);
        benchmark::DoNotOptimize(mj->data->qfrc_inverse);
        benchmark::ClobberMemory();
    }
    // the largest difference from the hand-written recursion, so the models are known equal
    f.reference.inverse_dynamics(f.q.data(), f.qd.data(), f.qdd.data(), f.out.data());
    double diff = 0;
    for (std::size_t i = 0; i < f.q.size(); ++i)
        diff = std::max(diff, std::abs(mj->data->qfrc_inverse[i] - f.out[i]));
    state.counters["links"] = static_cast<double>(state.range(0));
    state.counters["max_diff"] = diff;
}
BENCHMARK(BM_InverseMujoco)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
#endif

}  // namespace

BENCHMARK(BM_InverseReference)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
BENCHMARK(BM_InverseTape)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
BENCHMARK(BM_InverseTapeRoadmap)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
BENCHMARK(BM_ForwardReference)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
BENCHMARK(BM_ForwardTape)->Arg(3)->Arg(7)->Arg(15)->Arg(30);
BENCHMARK(BM_ForwardTapeEvaluateOnly)->Arg(3)->Arg(7)->Arg(15)->Arg(30);

BENCHMARK_MAIN();
