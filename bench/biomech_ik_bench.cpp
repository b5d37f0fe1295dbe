// SPDX-License-Identifier: MIT
// Frames per second of inverse kinematics from markers: the test leg and spatial chains.
#include <benchmark/benchmark.h>

#include <alembert/biomech/inverse_kinematics.hpp>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>

#include "biomech/spatial_leg.hpp"

namespace {

using namespace alembert;

constexpr std::size_t kFrames = 200;  // 2 s at 100 Hz

// a spatial chain of `segments` segments hanging from a translated root: root (tx, ty, tz),
// each segment turned from the one before by a ball joint (body-fixed ZXY), 0.4 m long, three
// markers on each: 3 + 3 segments coordinates, 3 segments markers
struct Chain {
    System system;
    std::vector<ex> q;
    std::vector<MarkerPoint> markers;
};

std::unique_ptr<Chain> make_chain(int segments) {
    auto c = std::make_unique<Chain>();
    System& sys = c->system;
    SymbolTable& s = sys.symbols();
    for (const char* name : {"tx", "ty", "tz"}) c->q.push_back(s.add_variable(name, 2));
    Point& root = sys.add_point("J1");
    const Frame& N = sys.newtonian();
    root.set_pos(sys.origin(), c->q[0] * N.x() + c->q[1] * N.y() + c->q[2] * N.z());
    const Frame* parent = &N;
    const Point* joint = &root;
    for (int i = 1; i <= segments; ++i) {
        const std::string id = std::to_string(i);
        for (const char* a : {"a", "b", "c"}) c->q.push_back(s.add_variable(a + id, 2));
        RigidBody& B = sys.add_rigid_body("B" + id);
        Frame& Bf = B.body_frame();
        const std::size_t k = c->q.size();
        Bf.orient_body_fixed(*parent, RotationSequence::ZXY, c->q[k - 3], c->q[k - 2], c->q[k - 1]);
        for (int m = 0; m < 3; ++m) {
            const Eigen::Vector3d& r = test::kThighMarkers[static_cast<std::size_t>(m)];
            Point& P = sys.add_point("M" + id + "_" + std::to_string(m + 1), &B);
            P.set_pos(*joint, ex(r.x()) * Bf.x() + ex(r.y()) * Bf.y() + ex(r.z()) * Bf.z());
            c->markers.push_back({P.name(), &P, 1.0});
        }
        Point& next = sys.add_point("J" + std::to_string(i + 1), &B);
        next.set_pos(*joint, ex(-0.4) * Bf.y());
        parent = &Bf;
        joint = &next;
    }
    return c;
}

// markers of `ik` along a smooth motion (each coordinate a sinusoid within +-0.3, away from
// the ZXY sequence's singularity) with Gaussian noise `sigma` per marker coordinate
MarkerTable synthetic_trial(const InverseKinematics& ik, const std::vector<MarkerPoint>& markers,
                            double sigma) {
    MarkerTable m;
    m.table.add_column("time", "s");
    for (const MarkerPoint& mk : markers) {
        m.markers.push_back(mk.name);
        for (const char* a : {".X", ".Y", ".Z"}) m.table.add_column(mk.name + a, "m");
    }
    std::mt19937 random(5);
    std::normal_distribution<double> noise(0, sigma > 0 ? sigma : 1);
    const std::size_t n = ik.coordinate_names().size();
    for (std::size_t f = 0; f < kFrames; ++f) {
        const double t = static_cast<double>(f) / 100.0;
        std::vector<double> q(n);
        for (std::size_t j = 0; j < n; ++j)
            q[j] = 0.3 * std::sin(2 * 3.141592653589793 * t + static_cast<double>(j));
        const std::vector<double> p = ik.calc_marker_positions(q);
        m.table.columns[0].push_back(t);
        for (std::size_t i = 0; i < p.size(); ++i)
            m.table.columns[1 + i].push_back(p[i] + (sigma > 0 ? noise(random) : 0.0));
    }
    return m;
}

struct Fixture {
    std::unique_ptr<InverseKinematics> ik;
    MarkerTable trial;
    std::size_t coordinates = 0, markers = 0;
};

void run(benchmark::State& state, const Fixture& f) {
    double iterations = 0;
    for (auto _ : state) {
        InverseKinematicsResult r = f.ik->solve(f.trial);
        iterations = 0;
        for (const auto& frame : r.frames) iterations += frame.iterations;
        benchmark::DoNotOptimize(r);
    }
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(kFrames) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate);
    state.counters["n"] = static_cast<double>(f.coordinates);
    state.counters["markers"] = static_cast<double>(f.markers);
    state.counters["ops"] = static_cast<double>(f.ik->operation_count());
    state.counters["iter_per_frame"] = iterations / static_cast<double>(kFrames);
}

// the test leg (tests/biomech/spatial_leg.hpp): 9 coordinates, 9 markers; range(0) is the
// noise in micrometres (0: exact markers)
void BM_IkLeg(benchmark::State& state) {
    static std::map<int, std::pair<std::unique_ptr<test::Leg>, Fixture>> cache;
    const int noise_um = static_cast<int>(state.range(0));
    auto& entry = cache[noise_um];
    if (!entry.first) {
        entry.first = test::make_leg();
        test::Leg& leg = *entry.first;
        Fixture& f = entry.second;
        InverseKinematicsOptions options;
        options.initial = test::leg_motion(0);
        f.ik = std::make_unique<InverseKinematics>(leg.system, leg.q, leg.markers, options);
        // the test's stride-like motion
        std::vector<std::vector<double>> p;
        f.trial.table.add_column("time", "s");
        for (const auto& mk : leg.markers) {
            f.trial.markers.push_back(mk.name);
            for (const char* a : {".X", ".Y", ".Z"}) f.trial.table.add_column(mk.name + a, "m");
        }
        std::mt19937 random(5);
        std::normal_distribution<double> noise(0, 1e-6 * std::max(noise_um, 1));
        for (std::size_t k = 0; k < kFrames; ++k) {
            const double t = static_cast<double>(k) / 100.0;
            const std::vector<Eigen::Vector3d> markers =
                test::leg_markers_by_hand(test::leg_motion(t));
            f.trial.table.columns[0].push_back(t);
            for (std::size_t i = 0; i < markers.size(); ++i)
                for (int a = 0; a < 3; ++a)
                    f.trial.table.columns[1 + 3 * i + static_cast<std::size_t>(a)].push_back(
                        markers[i](a) + (noise_um > 0 ? noise(random) : 0.0));
        }
        f.coordinates = leg.q.size();
        f.markers = leg.markers.size();
    }
    run(state, entry.second);
}
BENCHMARK(BM_IkLeg)->Arg(0)->Arg(1000)->Unit(benchmark::kMillisecond);

// spatial chains of range(0) segments, 1 mm of noise
void BM_IkChain(benchmark::State& state) {
    static std::map<int, std::pair<std::unique_ptr<Chain>, Fixture>> cache;
    const int segments = static_cast<int>(state.range(0));
    auto& entry = cache[segments];
    if (!entry.first) {
        entry.first = make_chain(segments);
        Chain& c = *entry.first;
        Fixture& f = entry.second;
        InverseKinematicsOptions options;
        options.initial.assign(c.q.size(), 0.0);
        for (std::size_t j = 0; j < c.q.size(); ++j)
            options.initial[j] = 0.3 * std::sin(static_cast<double>(j));
        f.ik = std::make_unique<InverseKinematics>(c.system, c.q, c.markers, options);
        f.trial = synthetic_trial(*f.ik, c.markers, 1e-3);
        f.coordinates = c.q.size();
        f.markers = c.markers.size();
    }
    run(state, entry.second);
}
BENCHMARK(BM_IkChain)->DenseRange(1, 4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

// forming and compiling the positions and Jacobian (once per model), model building included
void BM_IkCompile(benchmark::State& state) {
    const int segments = static_cast<int>(state.range(0));
    std::size_t ops = 0;
    for (auto _ : state) {
        std::unique_ptr<Chain> c = make_chain(segments);
        InverseKinematics ik(c->system, c->q, c->markers);
        ops = ik.operation_count();
        benchmark::DoNotOptimize(ops);
    }
    state.counters["ops"] = static_cast<double>(ops);
}
BENCHMARK(BM_IkCompile)->Arg(1)->Arg(3)->Arg(8)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
