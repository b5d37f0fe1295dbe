// SPDX-License-Identifier: MIT
// Points: position in a tree of points, velocity and acceleration in any frame.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "alembert/vec/frame.hpp"

namespace alembert {

class Body;

/// A point. It may be located from another point by a position vector (points form a tree,
/// as frames do), and its velocity and acceleration in a frame are derived from that or set
/// directly (for rolling contact, or for statics).
///
/// A point may belong to a body or particle (its "owner"): a force applied at the point acts
/// on the owner. A point with no owner belongs to the surroundings (for example the Newtonian
/// origin). Points neither copy nor move; alembert::System owns them.
class Point {
public:
    Point(std::string name, const Body* owner = nullptr) : name_(std::move(name)), owner_(owner) {}
    ~Point() { invalidate_kinematics(); }
    Point(const Point&) = delete;
    Point& operator=(const Point&) = delete;

    const std::string& name() const { return name_; }
    /// The body or particle this point is fixed on, or nullptr for the surroundings.
    const Body* owner() const { return owner_; }

    // ---- position ------------------------------------------------------------------------
    /// Locates this point P from point O: r^{P/O} = p_OP.
    /// @throws alembert::ModelError if O is this point or the link would close a cycle.
    void set_pos(const Point& O, const Vector& p_OP);
    /// The point this one is located from, or nullptr.
    const Point* located_from() const { return parent_; }
    /// r^{P/O}, the position of this point P from O, along the tree of located points.
    /// @throws alembert::ModelError naming both points if no chain of set_pos links them.
    Vector pos_from(const Point& O) const;

    // ---- velocity and acceleration -------------------------------------------------------
    /// Sets ^F v^P directly.
    void set_vel(const Frame& F, const Vector& v_FP);
    /// Sets ^F a^P directly.
    void set_acc(const Frame& F, const Vector& a_FP);
    /// Sets ^N v^P = ^N v^O + ^N w^B x r^{P/O} for points O, P both fixed on frame B
    /// (Kane 1985, eq. 2.7.1).
    void set_vel_two_point(const Frame& N, const Point& O, const Frame& B);
    /// Sets ^N a^P = ^N a^O + ^N alpha^B x r + ^N w^B x (^N w^B x r), r = r^{P/O}, for points
    /// O, P both fixed on frame B (Kane 1985, eq. 2.7.2).
    void set_acc_two_point(const Frame& N, const Point& O, const Frame& B);
    /// Sets ^N v^P = ^B v^P + ^N v^O + ^N w^B x r^{P/O} for P moving on frame B and O fixed on
    /// B (Kane 1985, eq. 2.8.1).
    void set_vel_one_point(const Frame& N, const Point& O, const Frame& B);

    /// ^F v^P: the velocity set for F, or ^F v^O + ^F d/dt r^{P/O} from the point O this one
    /// is located from, formed point by point outward; for long chains in compact form in
    /// the last frame r^{P/O} is written in, usually the body P is fixed on (see
    /// FormedVector).
    /// @throws alembert::ModelError if neither is available.
    Vector vel_in(const Frame& F) const;
    /// ^F a^P: the acceleration set for F, or ^F d/dt ^F v^P, in compact form when ^F v^P
    /// is.
    Vector acc_in(const Frame& F) const;
    /// True if a velocity in F is set directly.
    bool has_vel_set(const Frame& F) const { return v_.count(&F) != 0; }

private:
    friend class System;  // attaches the points it creates for a body to that body
    std::vector<const Point*> path_to_root() const;

    std::string name_;
    const Body* owner_;
    const Point* parent_ = nullptr;
    Vector p_parent_;
    const FormedVector& formed_vel_in(const Frame& F) const;
    void refresh_caches() const;
    std::map<const Frame*, Vector> v_;
    std::map<const Frame*, Vector> a_;
    // derived ^F v^P and ^F a^P by F, valid while the kinematics epoch stands still
    mutable std::map<const Frame*, FormedVector> v_cache_;
    mutable std::map<const Frame*, Vector> a_cache_;
    mutable std::uint64_t cache_epoch_ = 0;
};

}  // namespace alembert
