// SPDX-License-Identifier: MIT
// Generated inverse dynamics, forward dynamics and mass matrix of a 7-joint spatial arm (the
// KUKA LBR iiwa 14 of its public URDF) beside MuJoCo, DART and Simbody on the same model,
// measured in one run; every peer is checked against the generated code at a random state
// before it is timed (bench/README.md, "Spatial arm beside MuJoCo, DART and Simbody").
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

// ---- the generated code: recursive formation, C with constants folded, cc -O2, loaded
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
    Generated() : model(make_kuka_iiwa14()) {
        TreeEquations t =
            form_tree_equations(model.system, model.q, TreeOptions{.mass_matrix = true});
        DynamicsEquations eq{model.q, t.residuals, model.unknowns, std::nullopt, t.accelerations};
        eq.mass_matrix = t.mass_matrix;
        eq.bias_forces = t.bias_forces;
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
        dir = fs::temp_directory_path() / ("alembert-spatial-bench-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        generate_code(model.system.symbols(), eq, Language::c, dir, options);
        std::ofstream(dir / "context.c")
            << "#include <stddef.h>\n#include \"arm.h\"\n"
               "size_t arm_context_size(void) { return sizeof(arm_context); }\n";
        const std::string cc = std::getenv("CC") ? std::getenv("CC") : "cc";
        const std::string cmd = "cd " + dir.string() + " && " + cc +
                                " -O2 -shared -fPIC -o arm.so arm.c context.c -lm";
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("compiling failed: " + cmd);
        handle = ::dlopen((dir / "arm.so").c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error(::dlerror());
        auto size = reinterpret_cast<std::size_t (*)()>(::dlsym(handle, "arm_context_size"));
        auto init = reinterpret_cast<Init>(::dlsym(handle, "arm_init"));
        inverse = reinterpret_cast<Inverse>(::dlsym(handle, "arm_inverse_dynamics"));
        forward = reinterpret_cast<Forward>(::dlsym(handle, "arm_forward_dynamics"));
        mass_forcing = reinterpret_cast<MassForcing>(::dlsym(handle, "arm_mass_forcing"));
        mass_matrix = reinterpret_cast<MassMatrix>(::dlsym(handle, "arm_mass_matrix"));
        bias = reinterpret_cast<Bias>(::dlsym(handle, "arm_bias_forces"));
        jacobian = reinterpret_cast<Jacobian>(::dlsym(handle, "arm_link7_jacobian"));
        jacobian_dot = reinterpret_cast<Bias>(::dlsym(handle, "arm_link7_jacobian_dot_rates"));
        context.resize(size() / sizeof(double) + 1);
        init(context.data(), nullptr);
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> d(-1, 1);
        for (int i = 0; i < kJoints; ++i)
            q[i] = d(rng), qd[i] = d(rng), qdd[i] = d(rng), tau[i] = 10 * d(rng);
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
    }
    ~Generated() {
        if (handle) ::dlclose(handle);
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    SampleModel model;
    std::size_t ops_id = 0, calls_id = 0, ops_mf = 0, calls_mf = 0, ops_fd = 0, calls_fd = 0;
    std::size_t ops_mm = 0, calls_mm = 0, ops_bf = 0, calls_bf = 0;
    std::size_t ops_j = 0, calls_j = 0, ops_jd = 0, calls_jd = 0;
    fs::path dir;
    void* handle = nullptr;
    Inverse inverse = nullptr;
    Forward forward = nullptr;
    MassForcing mass_forcing = nullptr;
    MassMatrix mass_matrix = nullptr;
    Bias bias = nullptr;
    Jacobian jacobian = nullptr;
    Bias jacobian_dot = nullptr;
    std::vector<double> context;
    std::array<double, kJoints> q{}, qd{}, qdd{}, tau{}, id_out{}, fd_out{}, bias_out{};
    std::array<double, kJoints * kJoints> M{};  // row by row
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
bool agrees(benchmark::State& state, double diff, const R& reference, int n) {
    double scale = 1;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(reference[i]));
    state.counters["max_diff"] = diff;
    state.counters["rel_diff"] = diff / scale;
    if (diff <= kAgree * scale) return true;
    char message[120];
    std::snprintf(message, sizeof message,
                  "disagrees with the generated code by %.3g (relative %.3g)", diff, diff / scale);
    state.SkipWithError(message);
    return false;
}

void counters(benchmark::State& state, std::size_t ops, std::size_t calls) {
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

BENCHMARK(GeneratedInverse);
BENCHMARK(GeneratedForward);
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

BENCHMARK(MujocoInverse);
BENCHMARK(MujocoForward);
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
