// SPDX-License-Identifier: MIT
// The model registry: declaring and looking up frames, points and bodies.
#include "alembert/mech/system.hpp"

#include <algorithm>

#include "alembert/error.hpp"

namespace alembert {

namespace {
template <class T, class Name>
std::string known_names(const std::vector<std::unique_ptr<T>>& items, Name name) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + name(*i);
    return s.empty() ? "(none)" : s;
}
}  // namespace

System::System(const std::string& newtonian) : table_(std::make_unique<SymbolTable>()) {
    frames_.push_back(std::make_unique<Frame>(*table_, newtonian));
    points_.push_back(std::make_unique<Point>(newtonian + "_o"));
    points_.front()->set_vel(*frames_.front(), Vector());
    points_.front()->set_acc(*frames_.front(), Vector());
}

System::System(System&&) noexcept = default;
System& System::operator=(System&&) noexcept = default;
System::~System() = default;

Frame& System::add_frame(const std::string& name) {
    for (const auto& f : frames_)
        if (f->name() == name)
            throw ModelError("System::add_frame(): a frame named '" + name +
                             "' exists already; choose another name");
    frames_.push_back(std::make_unique<Frame>(*table_, name));
    return *frames_.back();
}

Point& System::add_point(const std::string& name, const Body* owner) {
    if (name.empty()) throw ArgumentError("System::add_point(): a point needs a non-empty name");
    for (const auto& p : points_)
        if (p->name() == name)
            throw ModelError("System::add_point(): a point named '" + name +
                             "' exists already; choose another name");
    points_.push_back(std::make_unique<Point>(name, owner));
    return *points_.back();
}

void System::require_new_body_name(const std::string& name, const char* caller) const {
    for (const auto& b : bodies_)
        if (b->name() == name)
            throw ModelError(std::string(caller) + ": a body named '" + name +
                             "' exists already; choose another name");
}

RigidBody& System::add_rigid_body(const std::string& name) {
    require_new_body_name(name, "System::add_rigid_body()");
    // check every name the body needs before declaring any, so a clash leaves nothing behind
    auto clash = [&](const char* what, const std::string& taken, const char* use) {
        throw ModelError("System::add_rigid_body(): a " + std::string(what) + " named '" + taken +
                         "' exists already, and rigid body '" + name + "' needs that name for " +
                         use + "; choose another name");
    };
    for (const auto& f : frames_)
        if (f->name() == name) clash("frame", name, "its frame");
    for (const auto& p : points_) {
        if (p->name() == name + "_o") clash("point", name + "_o", "its origin");
        if (p->name() == name + "cm") clash("point", name + "cm", "its mass centre");
    }
    Frame& B = add_frame(name);
    Point& Bo = add_point(name + "_o");
    Point& Bcm = add_point(name + "cm");
    auto body = std::make_unique<RigidBody>(name, B, Bcm);
    RigidBody& ref = *body;
    bodies_.push_back(std::move(body));
    // both points are fixed on the body: forces applied there act on it
    Bo.owner_ = &ref;
    Bcm.owner_ = &ref;
    return ref;
}

Particle& System::add_particle(const std::string& name) {
    require_new_body_name(name, "System::add_particle()");
    Point& P = add_point(name);
    auto body = std::make_unique<Particle>(name, P);
    Particle& ref = *body;
    bodies_.push_back(std::move(body));
    P.owner_ = &ref;
    return ref;
}

Frame& System::frame(const std::string& name) {
    for (const auto& f : frames_)
        if (f->name() == name) return *f;
    throw ModelError("System::frame(): unknown frame '" + name + "'; declared frames: " +
                     known_names(frames_, [](const Frame& f) { return f.name(); }));
}

Point& System::point(const std::string& name) {
    for (const auto& p : points_)
        if (p->name() == name) return *p;
    throw ModelError("System::point(): unknown point '" + name + "'; declared points: " +
                     known_names(points_, [](const Point& p) { return p.name(); }));
}

Body& System::body(const std::string& name) {
    for (const auto& b : bodies_)
        if (b->name() == name) return *b;
    throw ModelError("System::body(): unknown body or particle '" + name +
                     "'; declared: " +
                     known_names(bodies_, [](const Body& b) { return b.name(); }));
}

RigidBody& System::rigid_body(const std::string& name) {
    Body& b = body(name);
    auto* r = dynamic_cast<RigidBody*>(&b);
    if (!r)
        throw ModelError("System::rigid_body(): '" + name +
                         "' is a particle, not a rigid body");
    return *r;
}

const Body* System::body_of(const Frame& F) const {
    for (const auto& b : bodies_)
        if (b->frame() == &F) return b.get();
    return nullptr;
}

BodySet System::bodies() const {
    BodySet s;
    for (const auto& b : bodies_) s.push_back(b.get());
    return s;
}

std::vector<const Point*> System::points() const {
    std::vector<const Point*> out;
    for (const auto& p : points_) out.push_back(p.get());
    return out;
}

BodySet System::bodies(std::initializer_list<std::string> names) {
    BodySet s;
    for (const auto& n : names) s.push_back(&body(n));
    return s;
}

}  // namespace alembert
