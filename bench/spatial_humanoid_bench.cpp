// SPDX-License-Identifier: MIT
// Generated inverse dynamics, forward dynamics and mass matrix of a floating-base humanoid
// (make_humanoid: 15 segments of de Leva's tables, 32 degrees of freedom) beside MuJoCo, DART
// and Simbody on the same model, measured in the run of spatial_peers_bench; every peer is
// checked against the generated code at a random state before it is timed (bench/README.md,
// "Floating-base humanoid beside MuJoCo, DART and Simbody"); the generated derivatives of
// inverse and forward dynamics beside MuJoCo's finite differences ("Derivatives of the
// dynamics").
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <unistd.h>

#include <alembert/codegen/code_plan.hpp>
#include <alembert/codegen/codegen.hpp>
#include <alembert/eom/tree_dynamics.hpp>
#include <alembert/mech/ball_joint.hpp>
#include <alembert/mech/sample_models.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef ALEMBERT_BENCH_MUJOCO
#include <mujoco/mujoco.h>
#endif
#ifdef ALEMBERT_BENCH_DART
#include <dart/dynamics/BallJoint.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#endif

#include "humanoid_peers.hpp"

namespace {

using namespace alembert;
namespace fs = std::filesystem;
using bench::HumanoidSegment;
constexpr int kN = bench::kHumanoidDofs;
constexpr double kAgree = 1e-10;  // a peer farther than this from the generated code fails

using Vec = std::array<double, kN>;
using Mat = std::array<double, kN * kN>;  // row by row

// ---- the generated code -----------------------------------------------------------------------
// Generated functions take q, q', q'' arrays of one entry per speed. Each unit quaternion (the
// free joint's and each ball joint's Euler parameters) enters by its vector part ev, its scalar
// part being e0 = +sqrt(1 - ev.ev) (every orientation has Euler parameters with e0 >= 0), and
// its three speeds w (the body's angular velocity in its parent, body axes) as q'. The free
// joint's entries are q = (x, y, z, ev) of the pelvis, q' = (x', y', z', w), its loads F in N
// axes and T in pelvis axes; a ball's are q = ev, q' = w, its loads the torque components
// along the segment's axes; a hinge's its angle, rate and torque. So the model is formed again
// with each such frame oriented by (sqrt(1 - ev.ev), ev) and its angular velocity set in the
// rates ev': the rows and accelerations are those of make_humanoid's speeds, read with w = ev'.
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
    using InverseDerivatives = void (*)(const void*, double, const double*, const double*,
                                        const double*, double*, double*);
    using ForwardDerivatives = int (*)(const void*, double, const double*, const double*,
                                       const double*, double*, double*, double*);
    Generated() : model(make_humanoid()) {
        System& sys = model.system;
        SymbolTable& st = sys.symbols();
        // each quaternion (e0_<B>..e3_<B>) by its vector part
        for (std::size_t i = 0; i < model.q.size(); ++i) {
            const std::string& name = model.q[i].name();
            if (name.rfind("e0_", 0) != 0) {
                q.push_back(model.q[i]);
                continue;
            }
            Frame& B = sys.frame(name.substr(3));
            std::vector<TimeVariable> ev;
            for (const char* e : {"ev1_", "ev2_", "ev3_"}) ev.push_back(st.add_variable(e + B.name(), 2));
            const ex e1 = ev[0].d(0), e2 = ev[1].d(0), e3 = ev[2].d(0);
            B.orient_dcm(*B.parent(), euler_parameter_rotation(
                                          GiNaC::sqrt(1 - e1 * e1 - e2 * e2 - e3 * e3), e1, e2, e3));
            B.set_ang_vel(*B.parent(), ev[0].d(1) * B.x() + ev[1].d(1) * B.y() + ev[2].d(1) * B.z());
            q.insert(q.end(), ev.begin(), ev.end());
            i += 3;
        }
        TreeEquations t = form_tree_equations(sys, q, TreeOptions{.mass_matrix = true});
        joints = t.joints;
        DynamicsEquations eq{q, t.residuals, model.unknowns, std::nullopt, t.accelerations};
        eq.mass_matrix = t.mass_matrix;
        eq.bias_forces = t.bias_forces;
        // d tau/d q, d tau/d u and d u'/d q, d u'/d u, q at fixed u (docs/codegen.md, "Equations
        // in generalized speeds: d/dq at fixed u")
        add_dynamics_derivatives(st, eq);
        CodegenOptions options;
        options.name = "humanoid";
        options.source = "make_humanoid(), recursive formation";
        options.parameters = std::vector<ex>{};
        CodePlan plan = plan_code(st, eq, options);
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
        const StraightLineProgram& idd = plan.inverse_dynamics_derivatives.program;
        ops_idd = idd.operation_count(idd.body), calls_idd = idd.call_count(idd.body);
        symmetric_M = plan.symmetric_mass_matrix;
        dir = fs::temp_directory_path() / ("alembert-humanoid-bench-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        generate_code(st, eq, Language::c, dir, options);
        std::ofstream(dir / "context.c")
            << "#include <stddef.h>\n#include \"humanoid.h\"\n"
               "size_t humanoid_context_size(void) { return sizeof(humanoid_context); }\n";
        const std::string cc = std::getenv("CC") ? std::getenv("CC") : "cc";
        const std::string cmd = "cd " + dir.string() + " && " + cc +
                                " -O2 -shared -fPIC -o humanoid.so humanoid.c context.c -lm";
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("compiling failed: " + cmd);
        handle = ::dlopen((dir / "humanoid.so").c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error(::dlerror());
        auto size = reinterpret_cast<std::size_t (*)()>(::dlsym(handle, "humanoid_context_size"));
        auto init = reinterpret_cast<Init>(::dlsym(handle, "humanoid_init"));
        inverse = reinterpret_cast<Inverse>(::dlsym(handle, "humanoid_inverse_dynamics"));
        forward = reinterpret_cast<Forward>(::dlsym(handle, "humanoid_forward_dynamics"));
        mass_forcing = reinterpret_cast<MassForcing>(::dlsym(handle, "humanoid_mass_forcing"));
        mass_matrix = reinterpret_cast<MassMatrix>(::dlsym(handle, "humanoid_mass_matrix"));
        bias = reinterpret_cast<Bias>(::dlsym(handle, "humanoid_bias_forces"));
        inverse_derivatives = reinterpret_cast<InverseDerivatives>(
            ::dlsym(handle, "humanoid_inverse_dynamics_derivatives"));
        forward_derivatives = reinterpret_cast<ForwardDerivatives>(
            ::dlsym(handle, "humanoid_forward_dynamics_derivatives"));
        context.resize(size() / sizeof(double) + 1);
        init(context.data(), nullptr);
        // a random state: angles, speeds, rates, loads, and per free or ball joint a unit
        // quaternion with e0 >= 0 (its vector part in q) and its rotation R_PB
        std::mt19937 rng(42);
        std::uniform_real_distribution<double> d(-1, 1);
        for (int i = 0; i < kN; ++i) qg[i] = d(rng), u[i] = d(rng), udot[i] = d(rng), tau[i] = 10 * d(rng);
        segs = segments();
        for (const HumanoidSegment& seg : segs) {
            std::array<double, 4> e4{1, 0, 0, 0};
            if (seg.dofs != 1) {
                for (double& x : e4) x = d(rng);
                const double norm = std::sqrt(e4[0] * e4[0] + e4[1] * e4[1] + e4[2] * e4[2] + e4[3] * e4[3]);
                for (double& x : e4) x /= (e4[0] < 0 ? -norm : norm);
                for (int i = 0; i < 3; ++i) qg[seg.speed + (seg.dofs == 6 ? 3 : 0) + i] = e4[1 + i];
            }
            quaternions.push_back(e4);
            rotations.push_back(Eigen::Quaterniond(e4[0], e4[1], e4[2], e4[3]).toRotationMatrix());
        }
        e = quaternions[0];
        R_NP = rotations[0];
        inverse(context.data(), 0, qg.data(), u.data(), udot.data(), id_out.data());
        if (forward(context.data(), 0, qg.data(), u.data(), tau.data(), fd_out.data()) != 0)
            throw std::runtime_error("generated forward dynamics failed");
        Vec f{}, no_loads{};
        mass_forcing(context.data(), 0, qg.data(), u.data(), tau.data(), M.data(), f.data());
        // M alone and the bias forces alone agree with M and f (no loads: f = -bias)
        Mat M_alone{}, M0{};
        mass_matrix(context.data(), 0, qg.data(), M_alone.data());
        bias(context.data(), 0, qg.data(), u.data(), bias_out.data());
        mass_forcing(context.data(), 0, qg.data(), u.data(), no_loads.data(), M0.data(), f.data());
        double d_M = 0, d_b = 0, scale = 1;
        for (int i = 0; i < kN * kN; ++i)
            d_M = std::max(d_M, std::abs(M_alone[i] - M[i])), scale = std::max(scale, std::abs(M[i]));
        for (int i = 0; i < kN; ++i)
            d_b = std::max(d_b, std::abs(bias_out[i] + f[i])), scale = std::max(scale, std::abs(f[i]));
        if (d_M > 1e-12 * scale || d_b > 1e-12 * scale)
            throw std::runtime_error("generated M alone or bias forces disagree with M and f");
        inverse_derivatives(context.data(), 0, qg.data(), u.data(), udot.data(), dtau_dq.data(),
                            dtau_du.data());
        Vec udot2{};
        if (forward_derivatives(context.data(), 0, qg.data(), u.data(), tau.data(), udot2.data(),
                                dudot_dq.data(), dudot_du.data()) != 0)
            throw std::runtime_error("generated forward dynamics' derivatives failed");
    }
    // D (row by row) with each quaternion's three columns d/d ev turned into d/d dtheta, the
    // small rotation in the segment's axes by which MuJoCo perturbs a ball or free joint's
    // quaternion, e <- e (x) (1, dtheta/2): d ev = 1/2 (e0 I + [ev]x) dtheta
    Mat in_rotation_perturbations(const Mat& D) const {
        Mat out = D;
        for (std::size_t k = 0; k < segs.size(); ++k) {
            const HumanoidSegment& seg = segs[k];
            if (seg.dofs == 1) continue;
            const std::array<double, 4>& e4 = quaternions[k];
            Eigen::Matrix3d ev_x;
            ev_x << 0, -e4[3], e4[2], e4[3], 0, -e4[1], -e4[2], e4[1], 0;
            const Eigen::Matrix3d J = 0.5 * (e4[0] * Eigen::Matrix3d::Identity() + ev_x);
            const int j0 = seg.speed + (seg.dofs == 6 ? 3 : 0);
            for (int i = 0; i < kN; ++i)
                for (int c = 0; c < 3; ++c) {
                    double s = 0;
                    for (int r = 0; r < 3; ++r) s += D[i * kN + j0 + r] * J(r, c);
                    out[i * kN + j0 + c] = s;
                }
        }
        return out;
    }
    ~Generated() {
        if (handle) ::dlclose(handle);
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    // the segments as the peers build them, read from the model at zero angles
    std::vector<HumanoidSegment> segments() const {
        const SymbolTable& st = model.system.symbols();
        exmap zero;
        for (const TimeVariable& v : q) zero[v.d(0)] = 0;
        auto joint_of = [&](const Body* b) -> const TreeJoint& {
            for (const TreeJoint& j : joints)
                if (j.body == b) return j;
            throw std::logic_error("no joint of " + b->name());
        };
        auto segment_index = [&](const Body* b) {
            for (std::size_t k = 0; k < model.links.size(); ++k)
                if (model.links[k] == b) return static_cast<int>(k);
            return -1;
        };
        std::vector<HumanoidSegment> out;
        for (const RigidBody* B : model.links) {
            HumanoidSegment s;
            const TreeJoint* j = &joint_of(B);  // one joint per segment: no gimbal stages
            s.dofs = static_cast<int>(j->coordinates.size());
            s.speed = static_cast<int>(j->coordinates.front());
            s.parent = j->parent ? segment_index(j->parent) : -1;
            if (j->parent) {
                const Body& parent = *j->parent;
                const Col3 at = j->origin->pos_from(*joint_of(&parent).origin)
                                    .components_in(*parent.frame());
                for (int i = 0; i < 3; ++i) s.at[i] = st.evaluate(at[i], zero);
            }
            const Frame& F = *B->frame();
            const Col3 c = B->cm().pos_from(*joint_of(B).origin).components_in(F);
            const Mat3 I = B->inertia().components_in(F);
            s.mass = st.evaluate(B->mass(), zero);
            for (int i = 0; i < 3; ++i)
                s.com[i] = st.evaluate(c[i], zero), s.inertia[i] = st.evaluate(I(i, i), zero);
            out.push_back(s);
        }
        return out;
    }
    SampleModel model;
    std::vector<TimeVariable> q;
    std::vector<TreeJoint> joints;
    std::size_t ops_id = 0, calls_id = 0, ops_mf = 0, calls_mf = 0, ops_fd = 0, calls_fd = 0;
    std::size_t ops_mm = 0, calls_mm = 0, ops_bf = 0, calls_bf = 0, ops_idd = 0, calls_idd = 0;
    bool symmetric_M = false;  // the derivatives' M factored by Cholesky (else LU)
    fs::path dir;
    void* handle = nullptr;
    Inverse inverse = nullptr;
    Forward forward = nullptr;
    MassForcing mass_forcing = nullptr;
    MassMatrix mass_matrix = nullptr;
    Bias bias = nullptr;
    InverseDerivatives inverse_derivatives = nullptr;
    ForwardDerivatives forward_derivatives = nullptr;
    std::vector<double> context;
    std::vector<HumanoidSegment> segs;
    std::vector<std::array<double, 4>> quaternions;  // per segment: its joint's (1 0 0 0: a hinge)
    std::vector<Eigen::Matrix3d> rotations;          // per segment: R_PB of its joint's quaternion
    std::array<double, 4> e{};  // the pelvis's unit quaternion
    Eigen::Matrix3d R_NP;
    Vec qg{}, u{}, udot{}, tau{}, id_out{}, fd_out{}, bias_out{};
    Mat M{};
    // d tau/d q, d tau/d u at (q, u, u'); d u'/d q, d u'/d u at (q, u, tau); q at fixed u, d/d ev
    Mat dtau_dq{}, dtau_du{}, dudot_dq{}, dudot_du{};
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

// Agreement to kAgree relative to the largest magnitude of the generated result (at least 1).
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
    state.counters["dofs"] = kN;
    state.counters["ops"] = static_cast<double>(ops);
    state.counters["ops_per_dof"] = static_cast<double>(ops) / kN;
    state.counters["calls"] = static_cast<double>(calls);
}

// M_ours = T^T M_peer T for a peer whose speeds are T times ours
Mat congruence(const Eigen::MatrixXd& M_peer, const Eigen::MatrixXd& T) {
    Eigen::Matrix<double, kN, kN, Eigen::RowMajor> M = T.transpose() * M_peer * T;
    Mat out;
    std::copy(M.data(), M.data() + kN * kN, out.begin());
    return out;
}

void HumanoidGeneratedInverse(benchmark::State& state) {
    Generated& g = generated();
    Vec out{};
    for (auto _ : state) {
        g.inverse(g.context.data(), 0, g.qg.data(), g.u.data(), g.udot.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_id, g.calls_id);
}

void HumanoidGeneratedForward(benchmark::State& state) {
    Generated& g = generated();
    Vec out{};
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            g.forward(g.context.data(), 0, g.qg.data(), g.u.data(), g.tau.data(), out.data()));
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_fd, g.calls_fd);
}

void HumanoidGeneratedMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    Mat M{};
    Vec f{};
    for (auto _ : state) {
        g.mass_forcing(g.context.data(), 0, g.qg.data(), g.u.data(), g.tau.data(), M.data(),
                       f.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_mf, g.calls_mf);
}

// M alone (composite-rigid-body recursion)
void HumanoidGeneratedMassMatrixAlone(benchmark::State& state) {
    Generated& g = generated();
    Mat M{};
    for (auto _ : state) {
        g.mass_matrix(g.context.data(), 0, g.qg.data(), M.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_mm, g.calls_mm);
}

// C(q, q') q' + g(q) alone
void HumanoidGeneratedBiasForces(benchmark::State& state) {
    Generated& g = generated();
    Vec out{};
    for (auto _ : state) {
        g.bias(g.context.data(), 0, g.qg.data(), g.u.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_bf, g.calls_bf);
}

// d tau/d q (q at fixed u) and d tau/d u of inverse dynamics (32 x 32 each), through the
// intermediates
void HumanoidGeneratedInverseDerivatives(benchmark::State& state) {
    Generated& g = generated();
    Mat Dq{}, Du{};
    for (auto _ : state) {
        g.inverse_derivatives(g.context.data(), 0, g.qg.data(), g.u.data(), g.udot.data(),
                              Dq.data(), Du.data());
        benchmark::DoNotOptimize(Dq.data());
        benchmark::DoNotOptimize(Du.data());
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_idd, g.calls_idd);
}

// u' with d u'/d q and d u'/d u: the articulated-body accelerations, M alone, the derivatives
// of inverse dynamics at u', then -M^-1 on the 64 columns (M factored once: Cholesky or LU, as
// the generator decided); ops counts the three straight-line programs, solve_ops the dense
// factorization and solves (flops)
void HumanoidGeneratedForwardDerivatives(benchmark::State& state) {
    Generated& g = generated();
    Vec udot{};
    Mat Dq{}, Du{};
    for (auto _ : state) {
        benchmark::DoNotOptimize(g.forward_derivatives(g.context.data(), 0, g.qg.data(),
                                                       g.u.data(), g.tau.data(), udot.data(),
                                                       Dq.data(), Du.data()));
        benchmark::ClobberMemory();
    }
    counters(state, g.ops_fd + g.ops_mm + g.ops_idd, g.calls_fd + g.calls_mm + g.calls_idd);
    // the factorization (Cholesky n^3/3 flops, LU 2 n^3/3), 2n right sides through both
    // triangles (2 n^2 each), the negation
    const double n = kN;
    state.counters["solve_ops"] = (g.symmetric_M ? 1.0 : 2.0) * n * n * n / 3 + 4 * n * n * n + 2 * n * n;
    state.counters["lu"] = g.symmetric_M ? 0 : 1;
}

BENCHMARK(HumanoidGeneratedInverse);
BENCHMARK(HumanoidGeneratedForward);
BENCHMARK(HumanoidGeneratedInverseDerivatives);
BENCHMARK(HumanoidGeneratedForwardDerivatives);
BENCHMARK(HumanoidGeneratedMassMatrix);
BENCHMARK(HumanoidGeneratedMassMatrixAlone);
BENCHMARK(HumanoidGeneratedBiasForces);

#ifdef ALEMBERT_BENCH_MUJOCO
// ---- MuJoCo: nested bodies at the joint centres, a free joint for the pelvis, a ball joint
// for a ball, a hinge about y; the inertial at the mass centre with the principal moments; no
// geoms. MuJoCo's free and ball joints have our coordinates: qpos (the free joint's position
// and quaternion w x y z, a ball's quaternion w x y z in its parent), qvel (the free joint's
// velocity in the world and angular velocity in the body, a ball's angular velocity in the
// child's frame), qfrc likewise, so no speed, rate or load is converted: the state's
// quaternions are written out whole.
struct MujocoHumanoid {
    explicit MujocoHumanoid(const std::vector<HumanoidSegment>& s) {
        std::string xml = "<mujoco><option gravity=\"0 0 -9.81\"/><worldbody>";
        std::function<void(int)> emit = [&](int k) {
            const HumanoidSegment& seg = s[static_cast<std::size_t>(k)];
            char buf[512];
            std::snprintf(buf, sizeof buf, "<body pos=\"%.17g %.17g %.17g\">", seg.at[0], seg.at[1],
                          seg.at[2]);
            xml += buf;
            if (seg.dofs == 6) xml += "<freejoint/>";
            if (seg.dofs == 3) xml += "<joint type=\"ball\"/>";
            if (seg.dofs == 1) xml += "<joint type=\"hinge\" axis=\"0 1 0\"/>";
            std::snprintf(buf, sizeof buf,
                          "<inertial pos=\"%.17g %.17g %.17g\" mass=\"%.17g\" diaginertia=\"%.17g "
                          "%.17g %.17g\"/>",
                          seg.com[0], seg.com[1], seg.com[2], seg.mass, seg.inertia[0],
                          seg.inertia[1], seg.inertia[2]);
            xml += buf;
            for (std::size_t c = 0; c < s.size(); ++c)
                if (s[c].parent == k) emit(static_cast<int>(c));
            xml += "</body>";
        };
        emit(0);
        xml += "</worldbody></mujoco>";
        const std::string path = "/tmp/alembert_bench_humanoid_" + std::to_string(::getpid()) + ".xml";
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(xml.c_str(), f);
        std::fclose(f);
        char error[1000] = "";
        m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
        std::remove(path.c_str());
        if (!m) throw std::runtime_error(std::string("MuJoCo: ") + error);
        if (m->nv != kN || m->nq != bench::kHumanoidCoordinates)
            throw std::runtime_error("MuJoCo: the humanoid has " + std::to_string(m->nv) + " dofs");
        d = mj_makeData(m);
    }
    ~MujocoHumanoid() {
        mj_deleteData(d);
        mj_deleteModel(m);
    }
    void set(const Generated& g) {
        int p = 0;  // qpos of the segment's joint
        for (std::size_t k = 0; k < g.segs.size(); ++k) {
            const HumanoidSegment& seg = g.segs[k];
            if (seg.dofs == 6)
                for (int i = 0; i < 3; ++i) d->qpos[p++] = g.qg[seg.speed + i];
            if (seg.dofs == 1)
                d->qpos[p++] = g.qg[seg.speed];
            else
                for (int i = 0; i < 4; ++i) d->qpos[p++] = g.quaternions[k][i];
        }
        for (int i = 0; i < kN; ++i) d->qvel[i] = g.u[i], d->qacc[i] = g.udot[i];
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
        for (int i = 0; i < kN; ++i) rhs[i] = tau[i] - bias[i];
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
    mjtNum bias[kN] = {}, rhs[kN] = {};
};

MujocoHumanoid& mujoco() {
    static MujocoHumanoid h(generated().segments());
    return h;
}

void HumanoidMujocoInverse(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    mjtNum out[kN];
    h.inverse(out);
    if (!agrees(state, max_diff(out, g.id_out, kN), g.id_out, kN)) return;
    for (auto _ : state) {
        h.inverse(out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void HumanoidMujocoForward(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    mjtNum out[kN];
    h.forward(g.tau.data(), out);
    if (!agrees(state, max_diff(out, g.fd_out, kN), g.fd_out, kN)) return;
    for (auto _ : state) {
        h.forward(g.tau.data(), out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void HumanoidMujocoMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    h.mass_matrix();
    mjtNum M[kN * kN];
    mj_fullM(h.m, M, h.d->qM);
    if (!agrees(state, max_diff(M, g.M, kN * kN), g.M, kN * kN)) return;
    for (auto _ : state) {
        h.mass_matrix();
        benchmark::DoNotOptimize(h.d->qM);
        benchmark::ClobberMemory();
    }
}

// M alone as a dense matrix (mj_fullM after mj_crb), as the generated function gives it
void HumanoidMujocoMassMatrixDense(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    mjtNum M[kN * kN];
    h.mass_matrix();
    mj_fullM(h.m, M, h.d->qM);
    if (!agrees(state, max_diff(M, g.M, kN * kN), g.M, kN * kN)) return;
    for (auto _ : state) {
        h.mass_matrix();
        mj_fullM(h.m, M, h.d->qM);
        benchmark::DoNotOptimize(M);
        benchmark::ClobberMemory();
    }
}

// C(q, q') q' + g(q): mj_rne without accelerations
void HumanoidMujocoBiasForces(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    mjtNum out[kN];
    h.bias_forces(out);
    if (!agrees(state, max_diff(out, g.bias_out, kN), g.bias_out, kN)) return;
    for (auto _ : state) {
        h.bias_forces(out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

// ---- MuJoCo's derivatives (2.2: mjd_transitionFD and no analytic ones), as for the arm
// (spatial_peers_bench.cpp): the velocity rows of the Euler step's transition, h d qacc/d x
// and I + h d qacc/d qvel, divided by h; and central differences by hand over the forward and
// inverse pipelines. MuJoCo perturbs a free or ball joint's quaternion by a small rotation in
// the segment's axes (mj_integratePos), so the generated d/d ev columns are turned into d/d
// dtheta (Generated::in_rotation_perturbations) for the check. Finite differences agree to
// about 1e-6 relative, not to kAgree: checked to kAgreeFD.
constexpr double kAgreeFD = 1e-5;
constexpr double kEpsFD = 1e-6;

// d tau/d x (or d u'/d x), x = q then u, the generated pair in MuJoCo's perturbations; 2 n^2
std::vector<double> reference_fd(const Generated& g, const Mat& Dq, const Mat& Du) {
    const Mat Dtheta = g.in_rotation_perturbations(Dq);
    std::vector<double> ref(Dtheta.begin(), Dtheta.end());
    ref.insert(ref.end(), Du.begin(), Du.end());
    return ref;
}

// Agreement of finite differences to kAgreeFD relative to the largest generated entry.
bool agrees_fd(benchmark::State& state, const std::vector<double>& D, const std::vector<double>& ref) {
    double diff = 0, scale = 1;
    for (std::size_t i = 0; i < ref.size(); ++i)
        diff = std::max(diff, std::abs(D[i] - ref[i])), scale = std::max(scale, std::abs(ref[i]));
    state.counters["max_diff"] = diff;
    state.counters["rel_diff"] = diff / scale;
    if (diff <= kAgreeFD * scale) return true;
    char message[120];
    std::snprintf(message, sizeof message,
                  "disagrees with the generated derivatives by %.3g (relative %.3g)", diff, diff / scale);
    state.SkipWithError(message);
    return false;
}

void HumanoidMujocoTransitionFD(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    for (int i = 0; i < kN; ++i) h.d->qfrc_applied[i] = g.tau[i];
    std::vector<mjtNum> A(4 * kN * kN);
    mjd_transitionFD(h.m, h.d, kEpsFD, 1, A.data(), nullptr, nullptr, nullptr);
    // the velocity rows: h d qacc/d x and I + h d qacc/d qvel, row by row
    const double step = h.m->opt.timestep;
    std::vector<double> D(2 * kN * kN);
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            D[i * kN + j] = A[(kN + i) * 2 * kN + j] / step;
            D[kN * kN + i * kN + j] = (A[(kN + i) * 2 * kN + kN + j] - (i == j ? 1.0 : 0.0)) / step;
        }
    if (agrees_fd(state, D, reference_fd(g, g.dudot_dq, g.dudot_du)))
        for (auto _ : state) {
            mjd_transitionFD(h.m, h.d, kEpsFD, 1, A.data(), nullptr, nullptr, nullptr);
            benchmark::DoNotOptimize(A.data());
            benchmark::ClobberMemory();
        }
    for (int i = 0; i < kN; ++i) h.d->qfrc_applied[i] = 0;
}

// qpos moved by eps along speed j as mj_integratePos moves it: a position or a hinge angle by
// eps, a free or ball joint's quaternion by the rotation of eps about the segment's axis
void move_along_speed(const mjModel* m, mjtNum* qpos, int j, double eps) {
    const int joint = m->dof_jntid[j];
    int adr = m->jnt_qposadr[joint], k = j - m->jnt_dofadr[joint];
    if (m->jnt_type[joint] == mjJNT_HINGE || m->jnt_type[joint] == mjJNT_SLIDE) {
        qpos[adr] += eps;
        return;
    }
    if (m->jnt_type[joint] == mjJNT_FREE) {
        if (k < 3) {
            qpos[adr + k] += eps;
            return;
        }
        adr += 3, k -= 3;
    }
    mjtNum axis[3] = {0, 0, 0};
    axis[k] = 1;
    mju_quatIntegrate(qpos + adr, axis, eps);
}

// central differences of `f` (the forward or inverse pipeline) in qpos (along each speed, as
// above) and qvel: 4 n calls; D is d/d q then d/d u, row by row
template <class F>
void central_differences(MujocoHumanoid& h, F f, std::vector<double>& D) {
    mjtNum plus[kN], minus[kN], qpos0[bench::kHumanoidCoordinates];
    std::copy(h.d->qpos, h.d->qpos + bench::kHumanoidCoordinates, qpos0);
    for (int j = 0; j < kN; ++j) {
        move_along_speed(h.m, h.d->qpos, j, kEpsFD);
        f(plus);
        std::copy(qpos0, qpos0 + bench::kHumanoidCoordinates, h.d->qpos);
        move_along_speed(h.m, h.d->qpos, j, -kEpsFD);
        f(minus);
        std::copy(qpos0, qpos0 + bench::kHumanoidCoordinates, h.d->qpos);
        for (int i = 0; i < kN; ++i) D[i * kN + j] = (plus[i] - minus[i]) / (2 * kEpsFD);
    }
    for (int j = 0; j < kN; ++j) {
        const mjtNum x0 = h.d->qvel[j];
        h.d->qvel[j] = x0 + kEpsFD;
        f(plus);
        h.d->qvel[j] = x0 - kEpsFD;
        f(minus);
        h.d->qvel[j] = x0;
        for (int i = 0; i < kN; ++i) D[kN * kN + i * kN + j] = (plus[i] - minus[i]) / (2 * kEpsFD);
    }
}

void HumanoidMujocoForwardCentralDifferences(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    auto f = [&](mjtNum* out) { h.forward(g.tau.data(), out); };
    std::vector<double> D(2 * kN * kN);
    central_differences(h, f, D);
    if (!agrees_fd(state, D, reference_fd(g, g.dudot_dq, g.dudot_du))) return;
    for (auto _ : state) {
        central_differences(h, f, D);
        benchmark::DoNotOptimize(D.data());
        benchmark::ClobberMemory();
    }
}

void HumanoidMujocoInverseCentralDifferences(benchmark::State& state) {
    Generated& g = generated();
    MujocoHumanoid& h = mujoco();
    h.set(g);
    auto f = [&](mjtNum* out) { h.inverse(out); };
    std::vector<double> D(2 * kN * kN);
    central_differences(h, f, D);
    if (!agrees_fd(state, D, reference_fd(g, g.dtau_dq, g.dtau_du))) return;
    for (auto _ : state) {
        central_differences(h, f, D);
        benchmark::DoNotOptimize(D.data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(HumanoidMujocoInverse);
BENCHMARK(HumanoidMujocoForward);
BENCHMARK(HumanoidMujocoTransitionFD);
BENCHMARK(HumanoidMujocoForwardCentralDifferences);
BENCHMARK(HumanoidMujocoInverseCentralDifferences);
BENCHMARK(HumanoidMujocoMassMatrix);
BENCHMARK(HumanoidMujocoMassMatrixDense);
BENCHMARK(HumanoidMujocoBiasForces);
#endif

#ifdef ALEMBERT_BENCH_DART
// ---- DART: a dart::dynamics::FreeJoint for the pelvis, BallJoints for the balls, RevoluteJoints
// about y. DART's free joint has its own coordinates (exponential map; the pelvis's angular
// velocity and origin velocity in pelvis axes; torque and force in pelvis axes), so the state
// is converted once, outside the timed loop, through DART's dart::dynamics::FreeJoint setters, and its
// results are converted back for the agreement check. A BallJoint's positions are the
// exponential map of R_PB (converted once, BallJoint::convertToPositions); its velocities,
// accelerations and forces are ours (angular velocity and torque in the child's axes).
struct DartHumanoid {
    explicit DartHumanoid(const std::vector<HumanoidSegment>& s) {
        using namespace dart::dynamics;
        skel = Skeleton::create("humanoid");
        std::vector<BodyNode*> nodes;
        for (std::size_t k = 0; k < s.size(); ++k) {
            const HumanoidSegment& seg = s[k];
            BodyNode* parent = seg.parent < 0 ? nullptr : nodes[static_cast<std::size_t>(seg.parent)];
            const BodyNode::AspectProperties body("segment" + std::to_string(k));
            BodyNode* b = nullptr;
            Joint* j = nullptr;
            if (seg.dofs == 6) {
                dart::dynamics::FreeJoint::Properties p;
                p.mName = "joint" + std::to_string(k);
                auto pair = skel->createJointAndBodyNodePair<dart::dynamics::FreeJoint>(parent, p, body);
                j = pair.first, b = pair.second;
            } else if (seg.dofs == 3) {
                dart::dynamics::BallJoint::Properties p;
                p.mName = "joint" + std::to_string(k);
                auto pair = skel->createJointAndBodyNodePair<dart::dynamics::BallJoint>(parent, p, body);
                j = pair.first, b = pair.second;
            } else {
                RevoluteJoint::Properties p;
                p.mAxis = Eigen::Vector3d::UnitY();
                p.mName = "joint" + std::to_string(k);
                auto pair = skel->createJointAndBodyNodePair<RevoluteJoint>(parent, p, body);
                j = pair.first, b = pair.second;
            }
            Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
            T.translation() = Eigen::Vector3d(seg.at[0], seg.at[1], seg.at[2]);
            j->setTransformFromParentBodyNode(T);
            const Eigen::Matrix3d I =
                Eigen::Vector3d(seg.inertia[0], seg.inertia[1], seg.inertia[2]).asDiagonal();
            b->setInertia(Inertia(seg.mass, Eigen::Vector3d(seg.com[0], seg.com[1], seg.com[2]), I));
            nodes.push_back(b);
        }
        skel->setGravity(Eigen::Vector3d(0, 0, -9.81));
        pelvis = nodes[0];
        free = static_cast<dart::dynamics::FreeJoint*>(pelvis->getParentJoint());
    }
    // DART's positions, velocities and accelerations at the generated code's state
    void set(const Generated& g) {
        using dart::dynamics::Frame;
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.linear() = g.R_NP;
        T.translation() = Eigen::Vector3d(g.qg[0], g.qg[1], g.qg[2]);
        Eigen::VectorXd q(kN);
        for (int i = 6; i < kN; ++i) q[i] = g.qg[i];
        q.head<6>() = dart::dynamics::FreeJoint::convertToPositions(T);
        for (std::size_t k = 0; k < g.segs.size(); ++k)
            if (g.segs[k].dofs == 3)
                q.segment<3>(g.segs[k].speed) =
                    dart::dynamics::BallJoint::convertToPositions(g.rotations[k]);
        skel->setPositions(q);
        Eigen::VectorXd v = Eigen::VectorXd::Zero(kN), a = Eigen::VectorXd::Zero(kN);
        for (int i = 6; i < kN; ++i) v[i] = g.u[i], a[i] = g.udot[i];
        skel->setVelocities(v);
        skel->setAccelerations(a);
        const Eigen::Vector3d x_d(g.u[0], g.u[1], g.u[2]), w(g.u[3], g.u[4], g.u[5]);
        const Eigen::Vector3d x_dd(g.udot[0], g.udot[1], g.udot[2]), w_d(g.udot[3], g.udot[4], g.udot[5]);
        free->setAngularVelocity(g.R_NP * w, Frame::World(), Frame::World());
        free->setLinearVelocity(x_d, Frame::World(), Frame::World());
        free->setAngularAcceleration(g.R_NP * w_d, Frame::World(), Frame::World());
        free->setLinearAcceleration(x_dd, Frame::World(), Frame::World());
        positions = skel->getPositions();
        velocities = skel->getVelocities();
        accelerations = skel->getAccelerations();
        forces = Eigen::VectorXd(kN);
        const Eigen::Vector3d F(g.tau[0], g.tau[1], g.tau[2]), Tq(g.tau[3], g.tau[4], g.tau[5]);
        forces.head<3>() = Tq;
        forces.segment<3>(3) = g.R_NP.transpose() * F;
        for (int i = 6; i < kN; ++i) forces[i] = g.tau[i];
        // speeds: DART's (w, R^T x') of ours (x', w)
        T_speeds = Eigen::MatrixXd::Identity(kN, kN);
        T_speeds.topLeftCorner<6, 6>().setZero();
        T_speeds.block<3, 3>(0, 3).setIdentity();
        T_speeds.block<3, 3>(3, 0) = g.R_NP.transpose();
    }
    dart::dynamics::SkeletonPtr skel;
    dart::dynamics::BodyNode* pelvis = nullptr;
    dart::dynamics::FreeJoint* free = nullptr;
    Eigen::VectorXd positions, velocities, accelerations, forces;
    Eigen::MatrixXd T_speeds;
};

DartHumanoid& dart_humanoid() {
    static DartHumanoid h(generated().segments());
    return h;
}

void HumanoidDartInverse(benchmark::State& state) {
    Generated& g = generated();
    DartHumanoid& h = dart_humanoid();
    h.set(g);
    auto& s = h.skel;
    auto run = [&] {
        s->setPositions(h.positions);
        s->setVelocities(h.velocities);
        s->setAccelerations(h.accelerations);
        s->computeInverseDynamics(false, false, false);
        return s->getForces();
    };
    const Eigen::VectorXd f = run();
    Vec out{};
    const Eigen::Vector3d F = g.R_NP * f.segment<3>(3);
    for (int i = 0; i < 3; ++i) out[i] = F[i], out[3 + i] = f[i];
    for (int i = 6; i < kN; ++i) out[i] = f[i];
    if (!agrees(state, max_diff(out, g.id_out, kN), g.id_out, kN)) return;
    for (auto _ : state) benchmark::DoNotOptimize(run());
}

void HumanoidDartForward(benchmark::State& state) {
    Generated& g = generated();
    DartHumanoid& h = dart_humanoid();
    h.set(g);
    auto& s = h.skel;
    auto run = [&] {
        s->setPositions(h.positions);
        s->setVelocities(h.velocities);
        s->setForces(h.forces);
        s->computeForwardDynamics();
        return s->getAccelerations();
    };
    const Eigen::VectorXd a = run();
    Vec out{};
    const Eigen::Vector3d x_dd = h.pelvis->getLinearAcceleration();
    const Eigen::Vector3d w_d =
        h.pelvis->getAngularAcceleration(dart::dynamics::Frame::World(), h.pelvis);
    for (int i = 0; i < 3; ++i) out[i] = x_dd[i], out[3 + i] = w_d[i];
    for (int i = 6; i < kN; ++i) out[i] = a[i];
    if (!agrees(state, max_diff(out, g.fd_out, kN), g.fd_out, kN)) return;
    for (auto _ : state) benchmark::DoNotOptimize(run());
}

void HumanoidDartMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    DartHumanoid& h = dart_humanoid();
    h.set(g);
    auto& s = h.skel;
    // DART keeps M until the positions change: alternate with a nearby state
    const Eigen::VectorXd q = h.positions, q_near = q.array() + 1e-3;
    auto run = [&](const Eigen::VectorXd& at) -> const Eigen::MatrixXd& {
        s->setPositions(at);
        return s->getMassMatrix();
    };
    const Mat M = congruence(run(q), h.T_speeds);
    if (!agrees(state, max_diff(M, g.M, kN * kN), g.M, kN * kN)) return;
    bool near = false;
    for (auto _ : state) {
        benchmark::DoNotOptimize(run((near = !near) ? q_near : q).data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(HumanoidDartInverse);
BENCHMARK(HumanoidDartForward);
BENCHMARK(HumanoidDartMassMatrix);
#endif

#ifdef ALEMBERT_BENCH_SIMBODY
// ---- Simbody (humanoid_simbody.cpp): its Free mobilizer has q = (quaternion, position) and
// u = (angular velocity, velocity) in ground axes, rotation first; its Ball mobilizer q = the
// quaternion and u = the angular velocity in the parent's axes, R_PB w (so u' = R_PB w', as
// R_PB' w = R_PB (w x w) = 0, and the generalized forces R_PB T). The state is converted once,
// outside the timed loop, and the results back for the agreement check.
struct SimbodyState {
    explicit SimbodyState(const Generated& g) {
        T_speeds = Eigen::MatrixXd::Identity(kN, kN);
        int p = 0;  // q of the segment's mobilizer
        for (std::size_t k = 0; k < g.segs.size(); ++k) {
            const HumanoidSegment& seg = g.segs[k];
            const int o = seg.speed;
            if (seg.dofs == 1) {
                q[p++] = g.qg[o];
                u[o] = g.u[o], udot[o] = g.udot[o], tau[o] = g.tau[o];
                continue;
            }
            for (int i = 0; i < 4; ++i) q[p++] = g.quaternions[k][i];
            if (seg.dofs == 6) {
                for (int i = 0; i < 3; ++i) q[p++] = g.qg[o + i];
                for (int i = 0; i < 3; ++i)
                    u[o + 3 + i] = g.u[o + i], udot[o + 3 + i] = g.udot[o + i], tau[o + 3 + i] = g.tau[o + i];
            }
            // the rotation's speeds, rates and torques: ours at w (after the free joint's
            // translation), Simbody's first, in the parent's axes
            const int w = seg.dofs == 6 ? o + 3 : o;
            const Eigen::Matrix3d& R_PB = g.rotations[k];
            const Eigen::Vector3d u_w = R_PB * Eigen::Vector3d(g.u[w], g.u[w + 1], g.u[w + 2]);
            const Eigen::Vector3d u_dot_w = R_PB * Eigen::Vector3d(g.udot[w], g.udot[w + 1], g.udot[w + 2]);
            const Eigen::Vector3d T = R_PB * Eigen::Vector3d(g.tau[w], g.tau[w + 1], g.tau[w + 2]);
            for (int i = 0; i < 3; ++i) u[o + i] = u_w[i], udot[o + i] = u_dot_w[i], tau[o + i] = T[i];
            T_speeds.block(o, o, seg.dofs, seg.dofs).setZero();
            T_speeds.block<3, 3>(o, w) = R_PB;
            if (seg.dofs == 6) T_speeds.block<3, 3>(o + 3, o).setIdentity();
        }
    }
    // Simbody's generalized forces or accelerations to ours: u_simbody = T u_ours with T
    // orthogonal, so both go back by T^T (rotation and translation swapped, R_PB^T)
    Vec to_ours(const Vec& s, const Generated& g) const {
        Vec out = s;
        for (std::size_t k = 0; k < g.segs.size(); ++k) {
            const HumanoidSegment& seg = g.segs[k];
            const int o = seg.speed;
            if (seg.dofs == 1) continue;
            const int w = seg.dofs == 6 ? o + 3 : o;
            const Eigen::Vector3d rot = g.rotations[k].transpose() * Eigen::Vector3d(s[o], s[o + 1], s[o + 2]);
            if (seg.dofs == 6)
                for (int i = 0; i < 3; ++i) out[o + i] = s[o + 3 + i];
            for (int i = 0; i < 3; ++i) out[w + i] = rot[i];
        }
        return out;
    }
    std::array<double, bench::kHumanoidCoordinates> q{};
    Vec u{}, udot{}, tau{};
    Eigen::MatrixXd T_speeds;
};

bench::SimbodyHumanoid& simbody() {
    static std::unique_ptr<bench::SimbodyHumanoid> h =
        bench::make_simbody_humanoid(generated().segments());
    return *h;
}

void HumanoidSimbodyInverse(benchmark::State& state) {
    Generated& g = generated();
    const SimbodyState s(g);
    Vec out{};
    simbody().inverse(s.q.data(), s.u.data(), s.udot.data(), out.data());
    const Vec ours = s.to_ours(out, g);
    if (!agrees(state, max_diff(ours, g.id_out, kN), g.id_out, kN)) return;
    for (auto _ : state) {
        simbody().inverse(s.q.data(), s.u.data(), s.udot.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
}

void HumanoidSimbodyForward(benchmark::State& state) {
    Generated& g = generated();
    const SimbodyState s(g);
    Vec out{};
    simbody().forward(s.q.data(), s.u.data(), s.tau.data(), out.data());
    const Vec ours = s.to_ours(out, g);
    if (!agrees(state, max_diff(ours, g.fd_out, kN), g.fd_out, kN)) return;
    for (auto _ : state) {
        simbody().forward(s.q.data(), s.u.data(), s.tau.data(), out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
}

void HumanoidSimbodyMassMatrix(benchmark::State& state) {
    Generated& g = generated();
    const SimbodyState s(g);
    Mat M{};
    simbody().mass_matrix(s.q.data(), M.data());
    const Mat ours = congruence(Eigen::Map<Eigen::Matrix<double, kN, kN, Eigen::RowMajor>>(M.data()),
                                s.T_speeds);
    if (!agrees(state, max_diff(ours, g.M, kN * kN), g.M, kN * kN)) return;
    for (auto _ : state) {
        simbody().mass_matrix(s.q.data(), M.data());
        benchmark::DoNotOptimize(M.data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(HumanoidSimbodyInverse);
BENCHMARK(HumanoidSimbodyForward);
BENCHMARK(HumanoidSimbodyMassMatrix);
#endif

}  // namespace
