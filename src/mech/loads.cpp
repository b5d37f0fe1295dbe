// SPDX-License-Identifier: MIT
// Declaring loads: forces, torques, action/reaction pairs and the textbook force models.
#include "alembert/error.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

const Body* System::require_owner(const Point& P, const char* caller) const {
    if (!P.owner())
        throw ModelError(std::string(caller) + ": point '" + P.name() +
                         "' is not fixed on a body or particle, so a force there acts on "
                         "nothing; create it with add_point(\"" + P.name() +
                         "\", &body) or apply the force at a point of the body");
    return P.owner();
}

Load System::add_force(const Point& P, const Vector& F, const std::string& label) {
    const Body* on = require_owner(P, "System::add_force()");
    loads_.push_back(Load{.kind = LoadKind::force, .label = label, .point = &P, .vector = F,
                          .on = on, .from = nullptr});
    return loads_.back();
}

void System::add_pair(const Point& P, const Point& Q, const Vector& F_on_P,
                      const std::string& label, bool conservative) {
    if (!P.owner() && !Q.owner())
        throw ModelError("System: neither '" + P.name() + "' nor '" + Q.name() +
                         "' is fixed on a body or particle, so the load '" + label +
                         "' acts on nothing; attach one of the points to a body");
    if (P.owner())
        loads_.push_back(Load{.kind = LoadKind::force, .label = label, .point = &P,
                              .vector = F_on_P, .on = P.owner(), .from = Q.owner(),
                              .conservative = conservative});
    if (Q.owner())
        loads_.push_back(Load{.kind = LoadKind::force, .label = label, .point = &Q,
                              .vector = -F_on_P, .on = Q.owner(), .from = P.owner(),
                              .conservative = conservative});
}

void System::add_force_pair(const Point& P, const Point& Q, const Vector& F,
                            const std::string& label) {
    add_pair(P, Q, F, label);
}

namespace {

// a particle does not turn: a torque on it would do no work and enter no equation
void require_turning_body(const Body& B, const std::string& label, const char* fn) {
    if (!B.frame())
        throw ModelError(std::string(fn) + ": the torque '" + label + "' acts on '" + B.name() +
                         "', a particle: a particle does not turn, so a torque on it does "
                         "nothing; apply it to a rigid body, or apply a force at the particle");
}

}  // namespace

Load System::add_torque(const Body& B, const Vector& T, const std::string& label) {
    require_turning_body(B, label, "System::add_torque()");
    loads_.push_back(Load{.kind = LoadKind::torque, .label = label, .point = nullptr,
                          .vector = T, .on = &B, .from = nullptr});
    return loads_.back();
}

void System::add_torque_pair(const Body& B, const Frame& A, const Vector& T,
                             const std::string& label) {
    require_turning_body(B, label, "System::add_torque_pair()");
    const Body* from = body_of(A);
    if (from == &B)
        throw ModelError("System::add_torque_pair(): the torque '" + label + "' acts on '" +
                         B.name() + "' from its own frame; name the other body's frame");
    loads_.push_back(Load{.kind = LoadKind::torque, .label = label, .point = nullptr,
                          .vector = T, .on = &B, .from = from});
    if (from)
        loads_.push_back(Load{.kind = LoadKind::torque, .label = label, .point = nullptr,
                              .vector = -T, .on = from, .from = &B});
}

const JointReaction& System::add_joint_reaction(const std::string& name, const Body* parent,
                                                const Body& child, const Point& at,
                                                const std::vector<ReactionComponent>& forces,
                                                const std::vector<ReactionComponent>& torques) {
    const std::string caller = "System::add_joint_reaction(): ";
    if (name.empty()) throw ArgumentError(caller + "a joint reaction needs a name");
    for (const JointReaction& r : reactions_)
        if (r.name == name)
            throw ArgumentError(caller + "a joint reaction named '" + name +
                                "' is declared already; give this one another name");
    if (parent == &child)
        throw ArgumentError(caller + "the reaction '" + name + "' is between '" + child.name() +
                            "' and itself; name the body it is joined to");
    if (forces.empty() && torques.empty())
        throw ArgumentError(caller + "the reaction '" + name +
                            "' has no force or torque component; give at least one");
    JointReaction r{.name = name, .parent = parent, .child = &child, .at = &at, .components = {}};
    auto add = [&](const ReactionComponent& c, LoadKind kind) {
        const ex& m = c.measure;
        if (!GiNaC::is_a<GiNaC::symbol>(m) || !table_->owns(m) ||
            table_->kind(m) != SymbolKind::unknown)
            throw ArgumentError(caller + "the measure '" + to_string(m) + "' of '" + name +
                                "' is not an unknown; declare it as an unknown first");
        for (const JointReaction& other : reactions_)
            for (const ReactionComponent& o : other.components)
                if (o.measure.is_equal(m))
                    throw ArgumentError(caller + "the measure '" + to_string(m) +
                                        "' belongs to the reaction '" + other.name +
                                        "' already; give '" + name + "' its own unknowns");
        for (const ReactionComponent& o : r.components)
            if (o.measure.is_equal(m))
                throw ArgumentError(caller + "the measure '" + to_string(m) +
                                    "' appears twice in '" + name + "'; one per direction");
        if (c.direction.simplify().is_zero())
            throw ArgumentError(caller + "the direction of '" + to_string(m) + "' in '" + name +
                                "' is zero; give a direction the joint prevents");
        r.components.push_back({m, c.direction, kind});
    };
    for (const ReactionComponent& c : forces) add(c, LoadKind::force);
    for (const ReactionComponent& c : torques) add(c, LoadKind::torque);
    // the loads: on the child from the parent, and the opposite on the parent
    for (const ReactionComponent& c : r.components) {
        const std::string label = to_string(c.measure);
        const Vector v = c.measure * c.direction;
        const LoadKind kind = c.kind;
        const Point* point = kind == LoadKind::force ? &at : nullptr;
        loads_.push_back(Load{.kind = kind,
                              .label = label,
                              .point = point,
                              .vector = v,
                              .on = &child,
                              .from = parent});
        if (parent)
            loads_.push_back(Load{.kind = kind,
                                  .label = label,
                                  .point = point,
                                  .vector = -v,
                                  .on = parent,
                                  .from = &child});
    }
    reactions_.push_back(std::move(r));
    return reactions_.back();
}

const JointReaction* System::reaction_of(const ex& measure) const {
    for (const JointReaction& r : reactions_)
        for (const ReactionComponent& c : r.components)
            if (c.measure.is_equal(measure)) return &r;
    return nullptr;
}

void System::set_gravity(const Vector& g) { gravity_ = g; }

namespace {
// r = r^{P/Q}, its length and unit vector
struct Line {
    Vector r;
    ex length;
};
Line line_between(const Point& P, const Point& Q, const char* caller) {
    Vector r = P.pos_from(Q);
    if (r.simplify().is_zero())
        throw ModelError(std::string(caller) + ": points '" + P.name() + "' and '" + Q.name() +
                         "' coincide, so the line of action is not defined; separate them");
    return {r, GiNaC::sqrt(simplify(dot(r, r)))};
}
}  // namespace

void System::add_spring(const Point& P, const Point& Q, const ex& k, const ex& L0,
                        const std::string& label) {
    Line l = line_between(P, Q, "System::add_spring()");
    ex stretch = l.length - L0;
    add_pair(P, Q, (-k * stretch / l.length) * l.r, label, /*conservative=*/true);
    potentials_.push_back({k * stretch * stretch / 2});
}

void System::add_damper(const Point& P, const Point& Q, const ex& c, const std::string& label) {
    Line l = line_between(P, Q, "System::add_damper()");
    Vector u = l.r / l.length;
    Vector v = P.vel_in(newtonian()) - Q.vel_in(newtonian());
    add_pair(P, Q, (-c * dot(v, u)) * u, label);
}

void System::add_drag(const Point& P, const ex& c, DragLaw law, const std::string& label) {
    require_owner(P, "System::add_drag()");
    Vector v = P.vel_in(newtonian());
    ex s = law == DragLaw::linear ? -c : -c * GiNaC::sqrt(simplify(dot(v, v)));
    add_force(P, s * v, label);
}

void System::add_coulomb_friction(const Point& P, const Point& Q, const ex& mu, const ex& Fn,
                                  const Vector& u, const std::string& label) {
    Vector v = P.vel_in(newtonian()) - Q.vel_in(newtonian());
    add_pair(P, Q, (-mu * GiNaC::abs(Fn) * GiNaC::csgn(dot(v, u))) * u, label);
}

void System::add_inverse_square_gravity(const Point& P, const Point& Q, const ex& G,
                                        const std::string& label) {
    const Body* bp = require_owner(P, "System::add_inverse_square_gravity()");
    const Body* bq = require_owner(Q, "System::add_inverse_square_gravity()");
    Line l = line_between(P, Q, "System::add_inverse_square_gravity()");
    ex mm = G * bp->mass() * bq->mass();
    add_pair(P, Q, (-mm / GiNaC::pow(l.length, 3)) * l.r, label, /*conservative=*/true);
    potentials_.push_back({-mm / l.length});
}

const JointReaction* System::find_joint_reaction(const Point& at, const Body* parent,
                                                 const Body* child) const {
    for (const JointReaction& r : reactions_)
        if (r.at == &at && r.parent == parent && r.child == child) return &r;
    return nullptr;
}

}  // namespace alembert
