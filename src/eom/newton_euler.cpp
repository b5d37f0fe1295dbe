// SPDX-License-Identifier: MIT
// Brute-force Newton–Euler: joints inferred from the model, reactions as unknowns, F = m a and
// Euler's equations per body.
#include "alembert/eom/newton_euler.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "alembert/eom/inertia_forces.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/evaluator.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

namespace {

const char* const kAxisLetter[3] = {"x", "y", "z"};

// values for every symbol met, drawn once: the random state at which ranks are decided
class GenericState {
public:
    explicit GenericState(const SymbolTable& st) : st_(st), rng_(20240611) {}

    // e at the state, through its intermediates (compiled, not expanded: the intermediates
    // of a long chain's kinematics expand to expressions far larger than their definitions)
    double value(const ex& e) {
        std::uniform_real_distribution<double> mag(0.3, 1.7);
        std::bernoulli_distribution negative(0.5);
        std::vector<ex> inputs;
        std::vector<double> x;
        for (const ex& s : leaves(e)) {
            if (st_.owns(s) && st_.kind(s) == SymbolKind::constant && st_.value(s)) continue;
            if (!values_.count(s)) values_[s] = (negative(rng_) ? -1 : 1) * mag(rng_);
            inputs.push_back(s);
            x.push_back(values_.at(s));
        }
        CompiledExpressions f(st_, inputs, {e});
        double out = 0;
        f.evaluate(x.data(), &out);
        ALEMBERT_ASSERT(std::isfinite(out));
        return out;
    }

    Eigen::Vector3d value(const Vector& v, const Frame& N) {
        Col3 c = v.components_in(N);
        return {value(c[0]), value(c[1]), value(c[2])};
    }

private:
    // the symbols e depends on, through intermediates, other than intermediates
    GiNaC::exset leaves(const ex& e) const { return st_.calc_leaf_symbols(e); }

    const SymbolTable& st_;
    std::mt19937 rng_;
    std::map<ex, double, GiNaC::ex_is_less> values_;
};

// the directions of `dirs` that are independent at the random state, in order
std::vector<Vector> independent(const std::vector<Vector>& dirs, const Frame& N,
                                GenericState& at) {
    std::vector<Vector> out;
    Eigen::Matrix3Xd basis(3, 0);
    for (const Vector& d : dirs) {
        Eigen::Vector3d c = at.value(d, N);
        if (c.norm() < 1e-12) continue;
        Eigen::Matrix3Xd trial(3, basis.cols() + 1);
        trial << basis, c / c.norm();
        Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(trial);
        if (svd.singularValues().minCoeff() < 1e-8) continue;
        basis = trial;
        out.push_back(d);
    }
    return out;
}

// the axis of F that v lies along, if any
std::optional<int> aligned_axis(const Vector& v, const Frame& F) {
    Col3 c = v.components_in(F);
    int nonzero = 0, axis = -1;
    for (int i = 0; i < 3; ++i)
        if (!simplify(c[i]).is_zero()) ++nonzero, axis = i;
    if (nonzero != 1) return std::nullopt;
    return axis;
}

bool time_free(const SymbolTable& st, const ex& e) {
    for (const ex& s : symbols_of(st.expand_intermediates(e)))
        if (!st.owns(s) || st.kind(s) != SymbolKind::constant) return false;
    return true;
}

// a reaction direction and the suffix of its measure's name
struct Direction {
    Vector v;
    std::string suffix;
};

// v as an axis of one of `frames` when it is one, else normalised when |v| is a number
Direction named(const Vector& v, const std::vector<const Frame*>& frames,
                const std::string& fallback) {
    for (const Frame* F : frames)
        if (auto i = aligned_axis(v, *F)) return {F->unit(static_cast<Axis>(*i)), kAxisLetter[*i]};
    ex n2 = simplify(dot(v, v));
    if (GiNaC::is_a<GiNaC::numeric>(n2) && GiNaC::ex_to<GiNaC::numeric>(n2).is_positive())
        return {(v / GiNaC::sqrt(n2)).simplify(), fallback};
    return {v.simplify(), fallback};
}

// the two axes of F other than i
std::vector<Direction> other_axes(const Frame& F, int i) {
    std::vector<Direction> out;
    for (int j = 0; j < 3; ++j)
        if (j != i) out.push_back({F.unit(static_cast<Axis>(j)), kAxisLetter[j]});
    return out;
}

// a basis of the orthogonal complement of span(free), in space
std::vector<Direction> complement_in_space(const std::vector<Vector>& free,
                                           const std::vector<const Frame*>& frames,
                                           const Frame& base, const SymbolTable& st,
                                           GenericState& at) {
    switch (free.size()) {
        case 0: {
            std::vector<Direction> out;
            for (int j = 0; j < 3; ++j) out.push_back({base.unit(static_cast<Axis>(j)), kAxisLetter[j]});
            return out;
        }
        case 1: {
            const Vector& d = free.front();
            for (const Frame* F : frames)
                if (auto i = aligned_axis(d, *F)) return other_axes(*F, *i);
            // not along an axis: cross with the axis least aligned with d, of a frame in
            // which d is constant (so the pair never degenerates), else of the base frame
            const Frame* F = &base;
            for (const Frame* c : frames) {
                Col3 dc = d.components_in(*c);
                if (time_free(st, dc[0]) && time_free(st, dc[1]) && time_free(st, dc[2])) {
                    F = c;
                    break;
                }
            }
            Eigen::Vector3d n = at.value(d, *F);
            Eigen::Index k = 0;
            n.cwiseAbs().minCoeff(&k);
            Vector e1 = cross(d, F->unit(static_cast<Axis>(k))).simplify();
            Vector e2 = cross(d, e1).simplify();
            return {named(e1, frames, "1"), named(e2, frames, "2")};
        }
        case 2:
            return {named(cross(free[0], free[1]).simplify(), frames, "n")};
        default:
            return {};
    }
}

// a basis of the in-plane complement of span(free); k is the plane's normal (axis k of N)
std::vector<Direction> complement_in_plane(const std::vector<Vector>& free,
                                           const std::vector<const Frame*>& frames,
                                           const Frame& N, int k) {
    if (free.size() >= 2) return {};
    if (free.empty()) {
        // the in-plane axes of the first frame with an axis along the normal
        for (const Frame* F : frames)
            for (int i = 0; i < 3; ++i)
                if (aligned_axis(F->unit(static_cast<Axis>(i)), N) == k) return other_axes(*F, i);
        return other_axes(N, k);
    }
    return {named(cross(N.unit(static_cast<Axis>(k)), free.front()).simplify(), frames, "n")};
}

// the axis of N the model's motion is perpendicular to, or why there is none
std::optional<int> plane_normal(const System& sys, std::string& why) {
    const Frame& N = sys.newtonian();
    std::set<int> turn;
    for (const Body* b : sys.bodies()) {
        if (!b->frame()) continue;
        Col3 w = b->frame()->ang_vel_in(N).components_in(N);
        for (int i = 0; i < 3; ++i)
            if (!simplify(w[i]).is_zero()) turn.insert(i);
        if (turn.size() > 1) {
            why = "'" + b->name() + "' turns about more than one axis of " + N.name() +
                  " (or bodies turn about different axes)";
            return std::nullopt;
        }
    }
    std::vector<Col3> v;
    for (const Body* b : sys.bodies()) v.push_back(b->cm().vel_in(N).components_in(N));
    std::vector<int> tries = turn.empty() ? std::vector<int>{2, 1, 0} : std::vector<int>{*turn.begin()};
    for (int k : tries) {
        bool in_plane = true;
        for (std::size_t i = 0; i < v.size() && in_plane; ++i)
            if (!simplify(v[i][k]).is_zero()) {
                in_plane = false;
                why = "the mass centre of '" + sys.bodies()[i]->name() + "' moves along " +
                      N.name() + kAxisLetter[k] + ">";
            }
        if (in_plane) return k;
    }
    return std::nullopt;
}

// the point of b joined to the rest: b's origin B_o, else the first point of b located from
// a point of another body or of the surroundings
const Point* joint_point(const System& sys, const Body& b) {
    const Point* found = nullptr;
    for (const Point* p : sys.points()) {
        if (p->owner() != &b || !p->located_from() || p->located_from()->owner() == &b) continue;
        if (p->name() == b.name() + "_o") return p;
        if (!found) found = p;
    }
    return found;
}

// the body (nullptr: the ground) and a frame of it that B's frame is oriented from
struct Orientation {
    const Body* body = nullptr;
    const Frame* frame = nullptr;
};

Orientation torque_parent(const System& sys, const RigidBody& b) {
    const Frame& N = sys.newtonian();
    const Frame* f = b.frame()->parent();
    if (!f)
        throw ModelError("form_newton_euler_equations(): the frame of '" + b.name() +
                         "' is not oriented from any frame, so its joint cannot be inferred; "
                         "orient it from " + N.name() + " or from another body's frame");
    while (f != &N && !sys.body_of(*f)) {
        if (!f->parent())
            throw ModelError("form_newton_euler_equations(): frame '" + f->name() +
                             "', which the frame of '" + b.name() +
                             "' is oriented from, is not oriented from " + N.name() +
                             "; connect it to the frame tree");
        f = f->parent();
    }
    return {f == &N ? nullptr : sys.body_of(*f), f};
}

std::string name_of(const System& sys, const Body* b) {
    return b ? b->name() : sys.newtonian().name();
}

// the unknown `name` (reused if the table holds it as an unknown), unique within one call
ex reaction_symbol(SymbolTable& st, std::string name, std::set<std::string>& used) {
    for (int k = 2; used.count(name); ++k) name += "_" + std::to_string(k);
    used.insert(name);
    if (!st.contains(name)) return st.add_unknown(name);
    const ex& s = st.symbol(name);
    if (st.kind(s) != SymbolKind::unknown)
        throw ModelError("form_newton_euler_equations(): the joint-reaction unknown '" + name +
                         "' clashes with the " + to_string(st.kind(s)) + " of that name; "
                         "rename the " + to_string(st.kind(s)) + " or the bodies");
    return s;
}

// infers the joint of b: points, parents, free directions
NewtonEulerJoint infer_joint(const System& sys, const Body& b, const std::vector<TimeVariable>& q,
                             std::vector<Vector>& slides, std::vector<Vector>& rotations,
                             const Frame*& force_frame, const Frame*& torque_frame) {
    const Frame& N = sys.newtonian();
    NewtonEulerJoint j;
    j.body = &b;
    j.at = joint_point(sys, b);
    if (!j.at)
        throw ModelError("form_newton_euler_equations(): no point of '" + b.name() +
                         "' is located from a point of another body or of the ground, so its "
                         "joint cannot be inferred; locate " + b.name() +
                         (b.frame() ? "_o" : "") + " with set_pos");
    // the parent's point: up through points of no body to a body's point or the ground
    const Point* from = j.at->located_from();
    while (!from->owner() && from->located_from()) from = from->located_from();
    j.parent = from->owner();
    if (j.parent == &b)
        throw ModelError("form_newton_euler_equations(): '" + j.at->name() + "' of '" +
                         b.name() + "' is located from a point of the same body through "
                         "points of no body; locate it from its parent");
    force_frame = j.parent && j.parent->frame() ? j.parent->frame() : &N;

    // slides: partial velocities of J relative to the parent
    Vector v_rel = j.at->vel_in(N) - from->vel_in(N);
    if (j.parent && j.parent->frame())
        v_rel -= cross(j.parent->frame()->ang_vel_in(N), j.at->pos_from(*from));
    for (const TimeVariable& qr : q) {
        Vector d = v_rel.diff(qr.d(1)).simplify();
        if (!d.is_zero()) slides.push_back(d);
    }

    // rotations: partial angular velocities of B relative to its torque parent
    torque_frame = &N;
    if (const auto* rb = dynamic_cast<const RigidBody*>(&b)) {
        Orientation o = torque_parent(sys, *rb);
        j.torque_parent = o.body;
        torque_frame = o.frame;
        Vector w_rel = rb->frame()->ang_vel_in(*o.frame);
        for (const TimeVariable& qr : q) {
            Vector d = w_rel.diff(qr.d(1)).simplify();
            if (!d.is_zero()) rotations.push_back(d);
        }
    }
    return j;
}

// frames to name directions by: the parent's, the body's, those of the vectors, then N
std::vector<const Frame*> naming_frames(const Frame& parent, const Body& b,
                                        const std::vector<Vector>& dirs, const Frame& N) {
    std::vector<const Frame*> out{&parent};
    auto add = [&](const Frame* F) {
        if (F && std::find(out.begin(), out.end(), F) == out.end()) out.push_back(F);
    };
    add(b.frame());
    for (const Vector& d : dirs)
        for (const auto& [F, c] : d.components()) add(F);
    add(&N);
    return out;
}

// one per body: its joint, free slides and rotations, and the directions its joint
// transmits a force and a torque along (planar: in the plane, about the normal)
struct Inferred {
    NewtonEulerJoint joint;
    std::vector<Vector> slides, rotations;
    const Frame* force_frame = nullptr;
    const Frame* torque_frame = nullptr;
    std::vector<Direction> forces, torques;
};

// the model's joints and whether it is planar (k: the normal's axis, -1 when spatial);
// creates no symbol
std::vector<Inferred> infer_joints(const System& sys, const std::vector<TimeVariable>& q,
                                   const NewtonEulerOptions& options, int& k) {
    const Frame& N = sys.newtonian();
    const SymbolTable& st = N.symbols();
    GenericState at(st);
    std::vector<Inferred> inferred;
    for (const Body* b : sys.bodies()) {
        Inferred i;
        i.joint = infer_joint(sys, *b, q, i.slides, i.rotations, i.force_frame, i.torque_frame);
        i.slides = independent(i.slides, N, at);
        i.rotations = independent(i.rotations, N, at);
        i.joint.free_slides = static_cast<int>(i.slides.size());
        i.joint.free_rotations = static_cast<int>(i.rotations.size());
        inferred.push_back(std::move(i));
    }

    // planar or spatial
    k = -1;
    if (options.mode != NewtonEulerMode::spatial) {
        std::string why;
        std::optional<int> normal = plane_normal(sys, why);
        if (normal) {
            k = *normal;
        } else if (options.mode == NewtonEulerMode::planar) {
            throw ModelError("form_newton_euler_equations(): planar mode asked, but the model is "
                             "not planar: " + why + "; use NewtonEulerMode::spatial");
        }
    }
    const bool planar = k >= 0;

    // the directions each joint constrains
    for (Inferred& i : inferred) {
        const Body* b = i.joint.body;
        std::vector<const Frame*> fr = naming_frames(*i.force_frame, *b, i.slides, N);
        std::vector<const Frame*> tr = naming_frames(*i.torque_frame, *b, i.rotations, N);
        if (planar) {
            i.forces = complement_in_plane(i.slides, fr, N, k);
            if (b->frame() && i.rotations.empty())
                i.torques = {{N.unit(static_cast<Axis>(k)), kAxisLetter[k]}};
        } else {
            i.forces = complement_in_space(i.slides, fr, *i.force_frame, st, at);
            if (b->frame()) i.torques = complement_in_space(i.rotations, tr, *i.torque_frame, st, at);
        }
    }
    return inferred;
}

}  // namespace

NewtonEulerCount count_newton_euler_equations(const System& sys,
                                              const std::vector<TimeVariable>& q,
                                              std::size_t caller_unknowns,
                                              const NewtonEulerOptions& options) {
    int k = -1;
    const std::vector<Inferred> inferred = infer_joints(sys, q, options, k);
    NewtonEulerCount c;
    c.planar = k >= 0;
    c.caller_unknowns = caller_unknowns;
    for (const Body* b : sys.bodies()) {
        const bool rigid = b->frame() != nullptr;
        (rigid ? c.rigid_bodies : c.particles) += 1;
        c.equations += c.planar ? (rigid ? 3 : 2) : (rigid ? 6 : 3);
    }
    for (const Inferred& i : inferred) {
        NewtonEulerJointCount j;
        j.body = i.joint.body;
        j.parent = i.joint.parent;
        j.at = i.joint.at;
        j.free_slides = i.joint.free_slides;
        j.free_rotations = i.joint.free_rotations;
        j.forces = i.forces.size();
        j.torques = i.torques.size();
        c.force_reactions += j.forces;
        c.torque_reactions += j.torques;
        c.joints.push_back(j);
    }
    c.unknowns = c.caller_unknowns + c.force_reactions + c.torque_reactions;
    return c;
}

NewtonEulerEquations form_newton_euler_equations(const System& sys,
                                                 const std::vector<TimeVariable>& q,
                                                 const std::vector<ex>& unknowns,
                                                 const NewtonEulerOptions& options) {
    const Frame& N = sys.newtonian();
    SymbolTable& st = N.symbols();
    NewtonEulerEquations ne;
    int k = -1;
    std::vector<Inferred> inferred = infer_joints(sys, q, options, k);
    ne.planar = k >= 0;
    if (ne.planar) ne.normal = N.unit(static_cast<Axis>(k));

    // a reaction measure per constrained direction
    std::set<std::string> used;
    for (Inferred& i : inferred) {
        NewtonEulerJoint& j = i.joint;
        const Body* b = j.body;
        const std::vector<Direction>& forces = i.forces;
        const std::vector<Direction>& torques = i.torques;
        std::string fname = "F_" + name_of(sys, j.parent) + b->name() + "_";
        std::string tname = "M_" + name_of(sys, j.torque_parent) + b->name() + "_";
        for (const Direction& d : forces) {
            ex m = reaction_symbol(st, fname + d.suffix, used);
            j.reactions.push_back({m, d.v, LoadKind::force});
            j.force += m * d.v;
            ++ne.force_reactions;
        }
        for (const Direction& d : torques) {
            ex m = reaction_symbol(st, tname + d.suffix, used);
            j.reactions.push_back({m, d.v, LoadKind::torque});
            j.torque += m * d.v;
            ++ne.torque_reactions;
        }
        for (const ReactionComponent& r : j.reactions) ne.reactions.push_back(r.measure);
        ne.joints.push_back(std::move(j));
    }
    ne.caller_unknowns = unknowns.size();
    ne.unknowns = unknowns;
    ne.unknowns.insert(ne.unknowns.end(), ne.reactions.begin(), ne.reactions.end());

    // per body: applied + reactions + inertia = 0, force and moment about the mass centre
    for (const Body* b : sys.bodies()) {
        LoadResultant R = sys.calc_resultant({b}, b->cm());
        Vector F = R.force, M = R.moment;
        for (const NewtonEulerJoint& j : ne.joints) {
            if (j.body == b) {
                F += j.force;
                M += j.torque + cross(j.at->pos_from(b->cm()), j.force);
            }
            if (j.parent == b) {
                F -= j.force;
                M -= cross(j.at->pos_from(b->cm()), j.force);
            }
            if (j.torque_parent == b) M -= j.torque;
        }
        InertiaLoads star = calc_inertia_loads(*b, N);
        F += star.force;
        M += star.torque;
        for (int i = 0; i < 3; ++i) {
            if (i == k) continue;
            ne.equations.push_back(dot(N.unit(static_cast<Axis>(i)), F));
            ne.labels.push_back(b->name() + ": force . " + N.name() + kAxisLetter[i] + ">");
        }
        if (!b->frame()) continue;
        const Frame& B = *b->frame();
        for (int i = 0; i < 3; ++i) {
            if (ne.planar && i != k) continue;
            const Frame& E = ne.planar ? N : B;
            ne.equations.push_back(dot(E.unit(static_cast<Axis>(i)), M));
            ne.labels.push_back(b->name() + ": moment about " + b->cm().name() + " . " +
                                E.name() + kAxisLetter[i] + ">");
        }
    }
    return ne;
}

std::string summarize(const NewtonEulerEquations& ne) {
    auto count = [](std::size_t n, const char* word) {
        return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
    };
    return std::string("brute-force Newton–Euler") + (ne.planar ? " (planar): " : " (spatial): ") +
           count(ne.equations.size(), "equation") + " in " + count(ne.unknowns.size(), "unknown") +
           " (" + count(ne.reactions.size(), "joint reaction") + ": " +
           std::to_string(ne.force_reactions) + " force, " + std::to_string(ne.torque_reactions) +
           " torque) vs " + count(ne.caller_unknowns, "road-map equation");
}

}  // namespace alembert
