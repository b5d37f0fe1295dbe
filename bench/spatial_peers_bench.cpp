// SPDX-License-Identifier: MIT
// Generated inverse dynamics, forward dynamics and mass matrix of a 7-joint spatial arm (the
// KUKA LBR iiwa 14 of its public URDF) beside MuJoCo, DART and Simbody on the same model,
// measured in one run; every peer is checked against the generated code at a random state
// before it is timed (bench/README.md, "Spatial arm beside MuJoCo, DART and Simbody"); the
// generated derivatives of inverse and forward dynamics beside MuJoCo's finite differences
// ("Derivatives of the dynamics"). The generated code is compiled with the flags of
// ALEMBERT_BENCH_CFLAGS (default -O2; "Compiler flags for the generated code").
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <unistd.h>

#include <alembert/codegen/code_plan.hpp>
#include <alembert/codegen/codegen.hpp>
#include <alembert/eom/jacobians.hpp>
#include <alembert/eom/tree_dynamics.hpp>
#include <alembert/mech/sample_models.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef ALEMBERT_BENCH_MUJOCO
#include <mujoco/mujoco.h>
#endif
#ifdef ALEMBERT_BENCH_DART
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#endif

#include "iiwa14_peers.hpp"

namespace {

using namespace alembert;
namespace fs = std::filesystem;
constexpr int kJoints = bench::kArmJoints;
constexpr double kAgree = 1e-10;  // a peer farther than this from the generated code fails

using bench::kArm;
using bench::Link;

Eigen::Matrix3d rotation(const std::array<double, 3>& rpy) {
    using Eigen::AngleAxisd, Eigen::Vector3d;
    return (AngleAxisd(rpy[2], Vector3d::UnitZ()) * AngleAxisd(rpy[1], Vector3d::UnitY()) *
            AngleAxisd(rpy[0], Vector3d::UnitX()))
        .toRotationMatrix();
}

// ---- the generated code: recursive formation, C with constants folded, cc -O2 (or
// $ALEMBERT_BENCH_CFLAGS), loaded
struct Generated {
    using Init = void (*)(void*, const void*);
    using Inverse = void (*)(const void*, double, const double*, const double*, const double*,
                             double*);
    using Forward = int (*)(const void*, double, const double*, const double*, const double*,
                            double*);
    using MassForcing = void (*)(const void*, double, const double*, const double*,
                                 const double*, double*, double*);
    using MassMatrix = void (*)(const void*, double, const double*, double*);
    using Bias = void (*)(const void*, double, const double*, const double*, double*);
    using Jacobian = void (*)(const void*, double, const double*, double*);
    using InverseDerivatives = void (*)(const void*, double, const double*, const double*,
                                        const double*, double*, double*);
    using ForwardDerivatives = int (*)(const void*, double, const double*, const double*,
                                       const double*, double*, double*, double*);
    Generated() : model(make_kuka_iiwa14()) {
        TreeEquations t =
            form_tree_equations(model.system, model.q, TreeOptions{.mass_matrix = true});
        DynamicsEquations eq{model.q, t.residuals, model.unknowns, std::nullopt, t.accelerations};
        eq.mass_matrix = t.mass_matrix;
        eq.bias_forces = t.bias_forces;
        add_dynamics_derivatives(model.system.symbols(), eq);
        CodegenOptions options;
        options.name = "arm";
        options.source = "make_kuka_iiwa14(), recursive formation";
        options.parameters = std::vector<ex>{};
        // the last link's frame Jacobian at its origin (MuJoCo's body Jacobian of link 7)
        options.jacobians = {{"link7", form_frame_jacobian(model.system, model.q,
                                                           model.links.back()->body_frame(),
                                                           model.system.point("B7_o"))}};
        CodePlan plan = plan_code(model.system.symbols(), eq, options);
        const StraightLineProgram& id = plan.inverse_dynamics.program;
        const StraightLineProgram& mf = plan.mass_forcing.program;
        const StraightLineProgram& fd = plan.accelerations.program;
        ops_id = id.operation_count(id.body), calls_id = id.call_count(id.body);
        ops_mf = mf.operation_count(mf.body), calls_mf = mf.call_count(mf.body);
        ops_fd = fd.operation_count(fd.body), calls_fd = fd.call_count(fd.body);
        const StraightLineProgram& mm = plan.mass_matrix.program;
        const StraightLineProgram& bf = plan.bias_forces.program;
        ops_mm = mm.operation_count(mm.body), calls_mm = mm.call_count(mm.body);
        ops_bf = bf.operation_count(bf.body), calls_bf = bf.call_count(bf.body);
        const StraightLineProgram& jp = plan.jacobian_functions[1].program;
        const StraightLineProgram& jd = plan.jacobian_functions[2].program;
        ops_j = jp.operation_count(jp.body), calls_j = jp.call_count(jp.body);
        ops_jd = jd.operation_count(jd.body), calls_jd = jd.call_count(jd.body);
        const StraightLineProgram& idd = plan.inverse_dynamics_derivatives.program;
        ops_idd = idd.operation_count(idd.body), calls_idd = idd.call_count(idd.body);
        dir = fs::temp_directory_path() / ("alembert-spatial-bench-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        generate_code(model.system.symbols(), eq, Language::c, dir, options);
        std::ofstream(dir / "context.c")
            << "#include <stddef.h>\n#include \"arm.h\"\n"
               "size_t arm_context_size(void) { return sizeof(arm_context); }\n";
        // the flags the generated code is compiled with: ALEMBERT_BENCH_CFLAGS, -O2 by default
        const char* flags_env = std::getenv("ALEMBERT_BENCH_CFLAGS");
        flags = flags_env && *flags_env ? flags_env : "-O2";
        handle = compile_and_load(flags, "arm.so");
        bind(handle);
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> d(-1, 1);
        for (int i = 0; i < kJoints; ++i)
            q[i] = d(rng), qd[i] = d(rng), qdd[i] = d(rng), tau[i] = 10 * d(rng);
        check_results();
        // other flags than -O2: how far their results are from -O2's, at 100 random states
        if (flags != "-O2") {
            void* reference = compile_and_load("-O2", "arm_reference.so");
            diff_vs_O2 = compare_with(reference, rng);
            ::dlclose(reference);
            std::fprintf(stderr, "generated code at %s: results within %.3g (relative) of -O2's\n",
                         flags.c_str(), diff_vs_O2);
        }
    }
    void* compile_and_load(const std::string& cflags, const std::string& library) const {
        const std::string cc = std::getenv("CC") ? std::getenv("CC") : "cc";
        const std::string cmd = "cd " + dir.string() + " && " + cc + " " + cflags +
                                " -shared -fPIC -o " + library + " arm.c context.c -lm";
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("compiling failed: " + cmd);
        void* h = ::dlopen((dir / library).c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) throw std::runtime_error(::dlerror());
        return h;
    }
    // ID, FD, M alone and both derivatives at random states from the library `other` against
    // this one's: the largest difference relative to each result's largest magnitude
    double compare_with(void* other, std::mt19937& rng) {
        struct {
            Inverse inverse;
            Forward forward;
            MassMatrix mass_matrix;
            InverseDerivatives inverse_derivatives;
            ForwardDerivatives forward_derivatives;
        } o{reinterpret_cast<Inverse>(::dlsym(other, "arm_inverse_dynamics")),
            reinterpret_cast<Forward>(::dlsym(other, "arm_forward_dynamics")),
            reinterpret_cast<MassMatrix>(::dlsym(other, "arm_mass_matrix")),
            reinterpret_cast<InverseDerivatives>(::dlsym(other, "arm_inverse_dynamics_derivatives")),
            reinterpret_cast<ForwardDerivatives>(::dlsym(other, "arm_forward_dynamics_derivatives"))};
        std::uniform_real_distribution<double> d(-1, 1);
        std::array<double, kJoints> x{}, y{}, z{}, w{}, a{}, b{};
        std::array<double, kJoints * kJoints> A1{}, A2{}, B1{}, B2{};
        double worst = 0;
        auto rel = [&](const double* p, const double* r, int n) {
            double diff = 0, scale = 1;
            for (int i = 0; i < n; ++i)
                diff = std::max(diff, std::abs(p[i] - r[i])), scale = std::max(scale, std::abs(r[i]));
            worst = std::max(worst, diff / scale);
        };
        for (int k = 0; k < 100; ++k) {
            for (int i = 0; i < kJoints; ++i) x[i] = d(rng), y[i] = d(rng), z[i] = d(rng), w[i] = 10 * d(rng);
            const void* c = context.data();
            o.inverse(c, 0, x.data(), y.data(), z.data(), a.data());
            inverse(c, 0, x.data(), y.data(), z.data(), b.data());
            rel(a.data(), b.data(), kJoints);
            o.forward(c, 0, x.data(), y.data(), w.data(), a.data());
            forward(c, 0, x.data(), y.data(), w.data(), b.data());
            rel(a.data(), b.data(), kJoints);
            o.mass_matrix(c, 0, x.data(), A1.data());
            mass_matrix(c, 0, x.data(), A2.data());
            rel(A1.data(), A2.data(), kJoints * kJoints);
            o.inverse_derivatives(c, 0, x.data(), y.data(), z.data(), A1.data(), B1.data());
            inverse_derivatives(c, 0, x.data(), y.data(), z.data(), A2.data(), B2.data());
            rel(A1.data(), A2.data(), kJoints * kJoints);
            rel(B1.data(), B2.data(), kJoints * kJoints);
            o.forward_derivatives(c, 0, x.data(), y.data(), w.data(), a.data(), A1.data(), B1.data());
            forward_derivatives(c, 0, x.data(), y.data(), w.data(), b.data(), A2.data(), B2.data());
            rel(A1.data(), A2.data(), kJoints * kJoints);
            rel(B1.data(), B2.data(), kJoints * kJoints);
        }
        return worst;
    }
    // the entry points of the library h, and the context it initialises
    void bind(void* h) {
        auto size = reinterpret_cast<std::size_t (*)()>(::dlsym(h, "arm_context_size"));
        auto init = reinterpret_cast<Init>(::dlsym(h, "arm_init"));
        inverse = reinterpret_cast<Inverse>(::dlsym(h, "arm_inverse_dynamics"));
        forward = reinterpret_cast<Forward>(::dlsym(h, "arm_forward_dynamics"));
        mass_forcing = reinterpret_cast<MassForcing>(::dlsym(h, "arm_mass_forcing"));
        mass_matrix = reinterpret_cast<MassMatrix>(::dlsym(h, "arm_mass_matrix"));
        bias = reinterpret_cast<Bias>(::dlsym(h, "arm_bias_forces"));
        jacobian = reinterpret_cast<Jacobian>(::dlsym(h, "arm_link7_jacobian"));
        jacobian_dot = reinterpret_cast<Bias>(::dlsym(h, "arm_link7_jacobian_dot_rates"));
        inverse_derivatives =
            reinterpret_cast<InverseDerivatives>(::dlsym(h, "arm_inverse_dynamics_derivatives"));
        forward_derivatives =
            reinterpret_cast<ForwardDerivatives>(::dlsym(h, "arm_forward_dynamics_derivatives"));
        context.resize(size() / sizeof(double) + 1);
        init(context.data(), nullptr);
    }
    // the results at the state, M alone and the bias forces checked against M and f
    void check_results() {
        inverse(context.data(), 0, q.data(), qd.data(), qdd.data(), id_out.data());
        if (forward(context.data(), 0, q.data(), qd.data(), tau.data(), fd_out.data()) != 0)
            throw std::runtime_error("generated forward dynamics failed");
        std::array<double, kJoints> f{}, no_loads{};
        mass_forcing(context.data(), 0, q.data(), qd.data(), tau.data(), M.data(), f.data());
        // M alone and the bias forces alone agree with M and f (no loads: f = -bias)
        std::array<double, kJoints * kJoints> M_alone{}, M0{};
        mass_matrix(context.data(), 0, q.data(), M_alone.data());
        bias(context.data(), 0, q.data(), qd.data(), bias_out.data());
        mass_forcing(context.data(), 0, q.data(), qd.data(), no_loads.data(), M0.data(), f.data());
        double d_M = 0, d_b = 0, scale = 1;
        for (int i = 0; i < kJoints * kJoints; ++i)
            d_M = std::max(d_M, std::abs(M_alone[i] - M[i])), scale = std::max(scale, std::abs(M[i]));
        for (int i = 0; i < kJoints; ++i)
            d_b = std::max(d_b, std::abs(bias_out[i] + f[i])), scale = std::max(scale, std::abs(f[i]));
        if (d_M > 1e-12 * scale || d_b > 1e-12 * scale)
            throw std::runtime_error("generated M alone or bias forces disagree with M and f");
        jacobian(context.data(), 0, q.data(), J.data());
        inverse_derivatives(context.data(), 0, q.data(), qd.data(), qdd.data(), dtau_dq.data(),
                            dtau_dqp.data());
        if (forward_derivatives(context.data(), 0, q.data(), qd.data(), tau.data(), fd_out2.data(),
                                dqpp_dq.data(), dqpp_dqp.data()) != 0)
            throw std::runtime_error("generated forward dynamics' derivatives failed");
    }
    ~Generated() {
        if (handle) ::dlclose(handle);
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    SampleModel model;
    std::size_t ops_id = 0, calls_id = 0, ops_mf = 0, calls_mf = 0, ops_fd = 0, calls_fd = 0;
    std::size_t ops_mm = 0, calls_mm = 0, ops_bf = 0, calls_bf = 0;
    std::size_t ops_j = 0, calls_j = 0, ops_jd = 0, calls_jd = 0, ops_idd = 0, calls_idd = 0;
    std::string flags;       // of the generated code's compilation
    double diff_vs_O2 = 0;   // the largest relative difference of its results from -O2's
    fs::path dir;
    void* handle = nullptr;
    Inverse inverse = nullptr;
    Forward forward = nullptr;
    MassForcing mass_forcing = nullptr;
    MassMatrix mass_matrix = nullptr;
    Bias bias = nullptr;
    Jacobian jacobian = nullptr;
    Bias jacobian_dot = nullptr;
    InverseDerivatives inverse_derivatives = nullptr;
    ForwardDerivatives forward_derivatives = nullptr;
    std::vector<double> context;
    std::array<double, kJoints> q{}, qd{}, qdd{}, tau{}, id_out{}, fd_out{}, bias_out{}, fd_out2{};
    std::array<double, kJoints * kJoints> M{};  // row by row
    // d u/d q, d u/d q' at (q, qd, qdd); d qpp/d q, d qpp/d q' at (q, qd, tau); row by row
    std::array<double, kJoints * kJoints> dtau_dq{}, dtau_dqp{}, dqpp_dq{}, dqpp_dqp{};
    std::array<double, 6 * kJoints> J{};        // link 7: angular rows, then linear, in N
};

Generated& generated() {
    static Generated g;
    return g;
}

template <class A, class B>
double max_diff(const A& a, const B& b, int n) {
    double d = 0;
    for (int i = 0; i < n; ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
}

// A peer that disagrees with the generated code is not timed. Agreement is to kAgree relative
// to the largest magnitude of the generated result (at least 1): the accelerations reach a
// few thousand rad/s^2 where the wrist's small inertias meet torques of 10 N m.
template <class R>
bool agrees(benchmark::State& state, double diff, const R& reference, int n,
            double tolerance = kAgree) {
    double scale = 1;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(reference[i]));
    state.counters["max_diff"] = diff;
    state.counters["rel_diff"] = diff / scale;
    if (diff <= tolerance * scale) return true;
    char message[120];
    std::snprintf(message, sizeof message,
                  "disagrees with the generated code by %.3g (relative %.3g)", diff, diff / scale);
    state.SkipWithError(message);
    return false;
}

void counters(benchmark::State& state, std::size_t ops, std::size_t calls) {
    if (generated().flags != "-O2") state.counters["diff_vs_O2"] = generated().diff_vs_O2;
    state.counters["joints"] = kJoints;
    state.counters["ops"] = static_cast<double>(ops);
    state.counters["ops_per_joint"] = static_cast<double>(ops) / kJoints;
    state.counters["calls"] = static_cast<double>(calls);
}

void GeneratedInverse(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> out{};
    for (auto _ : state) {
        g.inverse(g.context.data(), 0, g.q.data(), g.qd.data(), g.qdd.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_id, g.calls_id);
}

void GeneratedForward(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> out{};
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            g.forward(g.context.data(), 0, g.q.data(), g.qd.data(), g.tau.data(), out.data()));
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_fd, g.calls_fd);
}

// M together with the forcing f (the generated function computes both)
void GeneratedMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints * kJoints> M{};
    std::array<double, kJoints> f{};
    for (auto _ : state) {
        g.mass_forcing(g.context.data(), 0, g.q.data(), g.qd.data(), g.tau.data(), M.data(),
                       f.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_mf, g.calls_mf);
}

// M alone (composite-rigid-body recursion)
void GeneratedMassMatrixAlone(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints * kJoints> M{};
    for (auto _ : state) {
        g.mass_matrix(g.context.data(), 0, g.q.data(), M.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_mm, g.calls_mm);
}

// C(q, q') q' + g(q) alone
void GeneratedBiasForces(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> out{};
    for (auto _ : state) {
        g.bias(g.context.data(), 0, g.q.data(), g.qd.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_bf, g.calls_bf);
}

// the last link's frame Jacobian (6 x 7) at its origin, and J' q'
void GeneratedJacobian(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, 6 * kJoints> J{};
    for (auto _ : state) {
        g.jacobian(g.context.data(), 0, g.q.data(), J.data());
        benchmark::DoNotOptimize(J.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_j, g.calls_j);
}

void GeneratedJacobianDotRates(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, 6> out{};
    for (auto _ : state) {
        g.jacobian_dot(g.context.data(), 0, g.q.data(), g.qd.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_jd, g.calls_jd);
}

// d u/d q and d u/d q' of inverse dynamics (7 x 7 each), through the intermediates
void GeneratedInverseDerivatives(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints * kJoints> Dq{}, Dqp{};
    for (auto _ : state) {
        g.inverse_derivatives(g.context.data(), 0, g.q.data(), g.qd.data(), g.qdd.data(), Dq.data(),
                              Dqp.data());
        benchmark::DoNotOptimize(Dq.data());
        benchmark::DoNotOptimize(Dqp.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_idd, g.calls_idd);
}

// q'' with d q''/d q and d q''/d q': the articulated-body accelerations, M alone, the
// derivatives of inverse dynamics at q'', then -M^-1 on the 14 columns (Cholesky once); ops
// counts the three straight-line programs, solve_ops the dense factorization and solves
void GeneratedForwardDerivatives(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> qpp{};
    std::array<double, kJoints * kJoints> Dq{}, Dqp{};
    for (auto _ : state) {
        benchmark::DoNotOptimize(g.forward_derivatives(g.context.data(), 0, g.q.data(), g.qd.data(),
                                                       g.tau.data(), qpp.data(), Dq.data(),
                                                       Dqp.data()));
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_fd + g.ops_mm + g.ops_idd, g.calls_fd + g.calls_mm + g.calls_idd);
    // Cholesky n^3/3 multiply-adds, 2n solves of 2 n^2 each, the negation
    state.counters["solve_ops"] = kJoints * kJoints * kJoints / 3.0 + 4.0 * kJoints * kJoints * kJoints +
                                  2.0 * kJoints * kJoints;
}

BENCHMARK(GeneratedInverse);
BENCHMARK(GeneratedForward);
BENCHMARK(GeneratedInverseDerivatives);
BENCHMARK(GeneratedForwardDerivatives);
BENCHMARK(GeneratedMassMatrix);
BENCHMARK(GeneratedMassMatrixAlone);
BENCHMARK(GeneratedBiasForces);
BENCHMARK(GeneratedJacobian);
BENCHMARK(GeneratedJacobianDotRates);

#ifdef ALEMBERT_BENCH_MUJOCO
// ---- MuJoCo: nested bodies at the joint origins (quat from the URDF rpy), a hinge about z,
// the inertial at the mass centre with the principal moments; no geoms, damping or armature.
// Timed: only the stages each quantity needs (kinematics, com positions and velocities, RNE
// for inverse dynamics; plus CRB, factorisation and solve for forward dynamics; CRB for M).
struct MujocoArm {
    MujocoArm() {
        std::string xml = "<mujoco><option gravity=\"0 0 -9.81\"/><worldbody>";
        char buf[512];
        for (const Link& l : kArm) {
            Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R = rotation(l.rpy);
            mjtNum quat[4];
            mju_mat2Quat(quat, R.data());
            std::snprintf(buf, sizeof buf,
                          "<body pos=\"%.17g %.17g %.17g\" quat=\"%.17g %.17g %.17g %.17g\">"
                          "<joint type=\"hinge\" axis=\"0 0 1\"/><inertial pos=\"%.17g %.17g "
                          "%.17g\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/>",
                          l.xyz[0], l.xyz[1], l.xyz[2], quat[0], quat[1], quat[2], quat[3],
                          l.com[0], l.com[1], l.com[2], l.mass, l.inertia[0], l.inertia[1],
                          l.inertia[2]);
            xml += buf;
        }
        for (int i = 0; i < kJoints; ++i) xml += "</body>";
        xml += "</worldbody></mujoco>";
        const std::string path = "/tmp/alembert_bench_iiwa14_" + std::to_string(::getpid()) + ".xml";
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(xml.c_str(), f);
        std::fclose(f);
        char error[1000] = "";
        m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
        std::remove(path.c_str());
        if (!m) throw std::runtime_error(std::string("MuJoCo: ") + error);
        d = mj_makeData(m);
    }
    ~MujocoArm() {
        mj_deleteData(d);
        mj_deleteModel(m);
    }
    void set(const Generated& g) {
        for (int i = 0; i < kJoints; ++i)
            d->qpos[i] = g.q[i], d->qvel[i] = g.qd[i], d->qacc[i] = g.qdd[i];
    }
    void inverse(mjtNum* out) {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_comVel(m, d);
        mj_rne(m, d, 1, out);
    }
    void forward(const double* tau, mjtNum* out) {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_crb(m, d);
        mj_factorM(m, d);
        mj_comVel(m, d);
        mj_rne(m, d, 0, bias);
        for (int i = 0; i < kJoints; ++i) rhs[i] = tau[i] - bias[i];
        mj_solveM(m, d, out, rhs, 1);
    }
    void mass_matrix() {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_crb(m, d);
    }
    void bias_forces(mjtNum* out) {
        mj_kinematics(m, d);
        mj_comPos(m, d);
        mj_comVel(m, d);
        mj_rne(m, d, 0, out);
    }
    mjModel* m = nullptr;
    mjData* d = nullptr;
    mjtNum bias[kJoints] = {}, rhs[kJoints] = {};
};

MujocoArm& mujoco() {
    static MujocoArm a;
    return a;
}

void MujocoInverse(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    mjtNum out[kJoints];
    a.inverse(out);
    if (!agrees(state, max_diff(out, g.id_out, kJoints), g.id_out, kJoints)) return;
    for (auto _ : state) {
        a.inverse(out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void MujocoForward(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    mjtNum out[kJoints];
    a.forward(g.tau.data(), out);
    if (!agrees(state, max_diff(out, g.fd_out, kJoints), g.fd_out, kJoints)) return;
    for (auto _ : state) {
        a.forward(g.tau.data(), out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void MujocoMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    a.mass_matrix();
    mjtNum M[kJoints * kJoints];
    mj_fullM(a.m, M, a.d->qM);
    if (!agrees(state, max_diff(M, g.M, kJoints * kJoints), g.M, kJoints * kJoints)) return;
    for (auto _ : state) {
        a.mass_matrix();
        benchmark::DoNotOptimize(a.d->qM);
        benchmark::ClobberMemory();
    }
}

// M alone as a dense matrix (mj_fullM after mj_crb), as the generated function gives it
void MujocoMassMatrixDense(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    mjtNum M[kJoints * kJoints];
    a.mass_matrix();
    mj_fullM(a.m, M, a.d->qM);
    if (!agrees(state, max_diff(M, g.M, kJoints * kJoints), g.M, kJoints * kJoints)) return;
    for (auto _ : state) {
        a.mass_matrix();
        mj_fullM(a.m, M, a.d->qM);
        benchmark::DoNotOptimize(M);
        benchmark::ClobberMemory();
    }
}

// C(q, q') q' + g(q): mj_rne without accelerations
void MujocoBiasForces(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    mjtNum out[kJoints];
    a.bias_forces(out);
    if (!agrees(state, max_diff(out, g.bias_out, kJoints), g.bias_out, kJoints)) return;
    for (auto _ : state) {
        a.bias_forces(out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

// the body Jacobian of link 7 at its frame's origin: kinematics, com positions (cdof), then
// mj_jacBody (MuJoCo 2.2 has no J' q')
void MujocoJacobian(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    mjtNum jacp[3 * kJoints], jacr[3 * kJoints], J[6 * kJoints];
    auto run = [&] {
        mj_kinematics(a.m, a.d);
        mj_comPos(a.m, a.d);
        mj_jacBody(a.m, a.d, jacp, jacr, kJoints);
    };
    run();
    std::copy(jacr, jacr + 3 * kJoints, J);
    std::copy(jacp, jacp + 3 * kJoints, J + 3 * kJoints);
    if (!agrees(state, max_diff(J, g.J, 6 * kJoints), g.J, 6 * kJoints)) return;
    for (auto _ : state) {
        run();
        benchmark::DoNotOptimize(jacp);
        benchmark::DoNotOptimize(jacr);
        benchmark::ClobberMemory();
    }
}

// ---- MuJoCo's derivatives: version 2.2 has mjd_transitionFD (finite differences of one
// step, x = (qpos, qvel), centered, eps 1e-6) and no analytic ones. With the Euler step,
// qvel' = qvel + h qacc and qpos' = qpos + h qvel', so its velocity rows are h d qacc/d q and
// I + h d qacc/d qvel: divided by h they are forward dynamics' derivatives. Finite differences
// agree with the generated derivatives to about 1e-6 relative, not to kAgree: checked to
// kAgreeFD.
constexpr double kAgreeFD = 1e-5;
constexpr double kEpsFD = 1e-6;

// d qacc/d q and d qacc/d qvel (row by row) from mjd_transitionFD's A
void transition_to_derivatives(const MujocoArm& a, const mjtNum* A, double* Dq, double* Dqp) {
    const int n = kJoints;
    const double h = a.m->opt.timestep;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Dq[i * n + j] = A[(n + i) * 2 * n + j] / h;
            Dqp[i * n + j] = (A[(n + i) * 2 * n + n + j] - (i == j ? 1.0 : 0.0)) / h;
        }
}

void MujocoTransitionFD(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    for (int i = 0; i < kJoints; ++i) a.d->qfrc_applied[i] = g.tau[i];
    std::vector<mjtNum> A(4 * kJoints * kJoints);
    mjd_transitionFD(a.m, a.d, kEpsFD, 1, A.data(), nullptr, nullptr, nullptr);
    std::array<double, 2 * kJoints * kJoints> D{}, ref{};
    transition_to_derivatives(a, A.data(), D.data(), D.data() + kJoints * kJoints);
    std::copy(g.dqpp_dq.begin(), g.dqpp_dq.end(), ref.begin());
    std::copy(g.dqpp_dqp.begin(), g.dqpp_dqp.end(), ref.begin() + kJoints * kJoints);
    const bool ok = agrees(state, max_diff(D, ref, 2 * kJoints * kJoints), ref,
                           2 * kJoints * kJoints, kAgreeFD);
    if (ok)
        for (auto _ : state) {
            mjd_transitionFD(a.m, a.d, kEpsFD, 1, A.data(), nullptr, nullptr, nullptr);
            benchmark::DoNotOptimize(A.data());
            benchmark::ClobberMemory();
        }
    for (int i = 0; i < kJoints; ++i) a.d->qfrc_applied[i] = 0;
}

// central differences of `f` (the forward or inverse pipeline) in qpos and qvel: 4 n calls
template <class F>
void central_differences(MujocoArm& a, F f, double* Dq, double* Dqp) {
    mjtNum plus[kJoints], minus[kJoints];
    for (int s = 0; s < 2; ++s) {
        mjtNum* x = s == 0 ? a.d->qpos : a.d->qvel;
        double* D = s == 0 ? Dq : Dqp;
        for (int j = 0; j < kJoints; ++j) {
            const mjtNum x0 = x[j];
            x[j] = x0 + kEpsFD;
            f(plus);
            x[j] = x0 - kEpsFD;
            f(minus);
            x[j] = x0;
            for (int i = 0; i < kJoints; ++i) D[i * kJoints + j] = (plus[i] - minus[i]) / (2 * kEpsFD);
        }
    }
}

void MujocoForwardCentralDifferences(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    auto f = [&](mjtNum* out) { a.forward(g.tau.data(), out); };
    std::array<double, 2 * kJoints * kJoints> D{}, ref{};
    central_differences(a, f, D.data(), D.data() + kJoints * kJoints);
    std::copy(g.dqpp_dq.begin(), g.dqpp_dq.end(), ref.begin());
    std::copy(g.dqpp_dqp.begin(), g.dqpp_dqp.end(), ref.begin() + kJoints * kJoints);
    if (!agrees(state, max_diff(D, ref, 2 * kJoints * kJoints), ref, 2 * kJoints * kJoints, kAgreeFD))
        return;
    for (auto _ : state) {
        central_differences(a, f, D.data(), D.data() + kJoints * kJoints);
        benchmark::DoNotOptimize(D.data());
        benchmark::ClobberMemory();
    }
}

void MujocoInverseCentralDifferences(benchmark::State& state) {
    Generated& g = generated();
    MujocoArm& a = mujoco();
    a.set(g);
    auto f = [&](mjtNum* out) { a.inverse(out); };
    std::array<double, 2 * kJoints * kJoints> D{}, ref{};
    central_differences(a, f, D.data(), D.data() + kJoints * kJoints);
    std::copy(g.dtau_dq.begin(), g.dtau_dq.end(), ref.begin());
    std::copy(g.dtau_dqp.begin(), g.dtau_dqp.end(), ref.begin() + kJoints * kJoints);
    if (!agrees(state, max_diff(D, ref, 2 * kJoints * kJoints), ref, 2 * kJoints * kJoints, kAgreeFD))
        return;
    for (auto _ : state) {
        central_differences(a, f, D.data(), D.data() + kJoints * kJoints);
        benchmark::DoNotOptimize(D.data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(MujocoInverse);
BENCHMARK(MujocoForward);
BENCHMARK(MujocoTransitionFD);
BENCHMARK(MujocoForwardCentralDifferences);
BENCHMARK(MujocoInverseCentralDifferences);
BENCHMARK(MujocoMassMatrix);
BENCHMARK(MujocoMassMatrixDense);
BENCHMARK(MujocoBiasForces);
BENCHMARK(MujocoJacobian);
#endif

#ifdef ALEMBERT_BENCH_DART
// ---- DART: revolute joints about z at the URDF joint origins, inertia about the mass centre.
// The positions are set in every timed call, so no cached result is reused.
struct DartArm {
    DartArm() {
        skel = dart::dynamics::Skeleton::create("iiwa14");
        dart::dynamics::BodyNode* parent = nullptr;
        for (const Link& l : kArm) {
            const std::string k = std::to_string(skel->getNumBodyNodes() + 1);
            dart::dynamics::RevoluteJoint::Properties joint;
            joint.mName = "joint" + k;
            auto pair = skel->createJointAndBodyNodePair<dart::dynamics::RevoluteJoint>(
                parent, joint, dart::dynamics::BodyNode::AspectProperties("link" + k));
            Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
            T.linear() = rotation(l.rpy);
            T.translation() = Eigen::Vector3d(l.xyz[0], l.xyz[1], l.xyz[2]);
            pair.first->setTransformFromParentBodyNode(T);
            pair.first->setAxis(Eigen::Vector3d::UnitZ());
            Eigen::Matrix3d I = Eigen::Vector3d(l.inertia[0], l.inertia[1], l.inertia[2]).asDiagonal();
            pair.second->setInertia(dart::dynamics::Inertia(
                l.mass, Eigen::Vector3d(l.com[0], l.com[1], l.com[2]), I));
            parent = pair.second;
        }
        skel->setGravity(Eigen::Vector3d(0, 0, -9.81));
    }
    dart::dynamics::SkeletonPtr skel;
};

DartArm& dart_arm() {
    static DartArm a;
    return a;
}

Eigen::VectorXd vec(const std::array<double, kJoints>& a) {
    return Eigen::Map<const Eigen::VectorXd>(a.data(), kJoints);
}

void DartInverse(benchmark::State& state) {
    Generated& g = generated();
    auto& s = dart_arm().skel;
    const Eigen::VectorXd q = vec(g.q), qd = vec(g.qd), qdd = vec(g.qdd);
    auto run = [&] {
        s->setPositions(q);
        s->setVelocities(qd);
        s->setAccelerations(qdd);
        s->computeInverseDynamics(false, false, false);
        return s->getForces();
    };
    Eigen::VectorXd out = run();
    if (!agrees(state, max_diff(out, g.id_out, kJoints), g.id_out, kJoints)) return;
    for (auto _ : state) benchmark::DoNotOptimize(run());
}

void DartForward(benchmark::State& state) {
    Generated& g = generated();
    auto& s = dart_arm().skel;
    const Eigen::VectorXd q = vec(g.q), qd = vec(g.qd), tau = vec(g.tau);
    auto run = [&] {
        s->setPositions(q);
        s->setVelocities(qd);
        s->setForces(tau);
        s->computeForwardDynamics();
        return s->getAccelerations();
    };
    Eigen::VectorXd out = run();
    if (!agrees(state, max_diff(out, g.fd_out, kJoints), g.fd_out, kJoints)) return;
    for (auto _ : state) benchmark::DoNotOptimize(run());
}

void DartMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    auto& s = dart_arm().skel;
    // DART keeps M until the positions change: the timed loop alternates between the state
    // and a nearby one, so every call forms M again
    const Eigen::VectorXd q = vec(g.q), q_near = q.array() + 1e-3;
    auto run = [&](const Eigen::VectorXd& at) -> const Eigen::MatrixXd& {
        s->setPositions(at);
        return s->getMassMatrix();
    };
    Eigen::Matrix<double, kJoints, kJoints, Eigen::RowMajor> M = run(q);
    if (!agrees(state, max_diff(M.data(), g.M, kJoints * kJoints), g.M, kJoints * kJoints)) return;
    bool near = false;
    for (auto _ : state) {
        benchmark::DoNotOptimize(run((near = !near) ? q_near : q).data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(DartInverse);
BENCHMARK(DartForward);
BENCHMARK(DartMassMatrix);
#endif

#ifdef ALEMBERT_BENCH_SIMBODY
// ---- Simbody (iiwa14_simbody.cpp): ID by calcResidualForceIgnoringConstraints, FD by
// calcAccelerationIgnoringConstraints, M by calcM, after realizing the stages each needs
bench::SimbodyArm& simbody() {
    static std::unique_ptr<bench::SimbodyArm> a = bench::make_simbody_arm();
    return *a;
}

void SimbodyInverse(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> out{};
    simbody().inverse(g.q.data(), g.qd.data(), g.qdd.data(), out.data());
    if (!agrees(state, max_diff(out, g.id_out, kJoints), g.id_out, kJoints)) return;
    for (auto _ : state) {
        simbody().inverse(g.q.data(), g.qd.data(), g.qdd.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
}

void SimbodyForward(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints> out{};
    simbody().forward(g.q.data(), g.qd.data(), g.tau.data(), out.data());
    if (!agrees(state, max_diff(out, g.fd_out, kJoints), g.fd_out, kJoints)) return;
    for (auto _ : state) {
        simbody().forward(g.q.data(), g.qd.data(), g.tau.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
}

void SimbodyMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    std::array<double, kJoints * kJoints> M{};
    simbody().mass_matrix(g.q.data(), M.data());
    if (!agrees(state, max_diff(M, g.M, kJoints * kJoints), g.M, kJoints * kJoints)) return;
    for (auto _ : state) {
        simbody().mass_matrix(g.q.data(), M.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(SimbodyInverse);
BENCHMARK(SimbodyForward);
BENCHMARK(SimbodyMassMatrix);
#endif

}  // namespace

BENCHMARK_MAIN();
