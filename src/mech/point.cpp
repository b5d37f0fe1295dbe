// SPDX-License-Identifier: MIT
// Point positions along the point tree, and velocities and accelerations derived from them.
#include "alembert/mech/point.hpp"

#include <algorithm>

#include "alembert/error.hpp"

namespace alembert {

void Point::set_pos(const Point& O, const Vector& p_OP) {
    if (&O == this)
        throw ModelError("Point::set_pos(): point '" + name_ +
                         "' cannot be located from itself; locate it from another point");
    std::string chain;
    for (const Point* p = &O; p; p = p->parent_) {
        chain += (chain.empty() ? "'" : " -> '") + p->name_ + "'";
        if (p == this)
            throw ModelError("Point::set_pos(): locating '" + name_ + "' from '" + O.name_ +
                             "' would close a cycle, because '" + O.name_ +
                             "' is already located from '" + name_ + "' (" + chain +
                             "); locate '" + name_ + "' from a point outside that chain");
    }
    parent_ = &O;
    p_parent_ = p_OP;
    invalidate_kinematics();
}

std::vector<const Point*> Point::path_to_root() const {
    std::vector<const Point*> p;
    for (const Point* q = this; q; q = q->parent_) p.push_back(q);
    return p;
}

Vector Point::pos_from(const Point& O) const {
    if (&O == this) return {};
    auto pp = path_to_root(), po = O.path_to_root();
    for (std::size_t i = 0; i < pp.size(); ++i) {
        auto it = std::find(po.begin(), po.end(), pp[i]);
        if (it == po.end()) continue;
        // r^{P/O} = r^{P/C} - r^{O/C} with C the common ancestor
        Vector r;
        for (std::size_t k = 0; k < i; ++k) r += pp[k]->p_parent_;
        for (auto j = po.begin(); j != it; ++j) r -= (*j)->p_parent_;
        return r;
    }
    throw ModelError("Point::pos_from(): the position of '" + name_ + "' from '" + O.name_ +
                     "' is not defined; locate one from the other (set_pos), directly or "
                     "through other points");
}

void Point::set_vel(const Frame& F, const Vector& v_FP) {
    v_[&F] = v_FP;
    invalidate_kinematics();
}

void Point::set_acc(const Frame& F, const Vector& a_FP) {
    a_[&F] = a_FP;
    invalidate_kinematics();
}

void Point::set_vel_two_point(const Frame& N, const Point& O, const Frame& B) {
    set_vel(N, O.vel_in(N) + cross(B.ang_vel_in(N), pos_from(O)));
}

void Point::set_acc_two_point(const Frame& N, const Point& O, const Frame& B) {
    Vector r = pos_from(O), w = B.ang_vel_in(N);
    set_acc(N, O.acc_in(N) + cross(B.ang_acc_in(N), r) + cross(w, cross(w, r)));
}

void Point::set_vel_one_point(const Frame& N, const Point& O, const Frame& B) {
    set_vel(N, vel_in(B) + O.vel_in(N) + cross(B.ang_vel_in(N), pos_from(O)));
}

void Point::refresh_caches() const {
    const std::uint64_t epoch = kinematics_epoch();
    if (cache_epoch_ == epoch) return;
    v_cache_.clear();
    a_cache_.clear();
    cache_epoch_ = epoch;
}

Vector Point::vel_in(const Frame& F) const { return formed_vel_in(F).value; }

const FormedVector& Point::formed_vel_in(const Frame& F) const {
    refresh_caches();
    if (auto c = v_cache_.find(&F); c != v_cache_.end()) return c->second;
    FormedVector formed;
    if (auto it = v_.find(&F); it != v_.end()) {
        formed.value = it->second;
    } else {
        if (!parent_)
            throw ModelError("Point::vel_in(): velocity of '" + name_ + "' in frame '" +
                             F.name() + "' is not defined; call " + name_ + ".set_vel(" +
                             F.name() + ", ...) or locate " + name_ +
                             " from a point whose velocity in " + F.name() + " is known");
        const FormedVector& vo = parent_->formed_vel_in(F);
        Vector v = vo.value + p_parent_.dt_in(F);
        formed.value = v;
        if (!v.is_zero()) {
            // compact form goes in the frame r^{P/O} ends in, usually the body P is fixed on
            const Frame& E = p_parent_.is_zero() ? *v.components().back().first
                                                 : *p_parent_.components().back().first;
            formed = form_compact_if_long(v, E, vo.compact);
        }
    }
    return v_cache_.emplace(&F, std::move(formed)).first->second;
}

Vector Point::acc_in(const Frame& F) const {
    auto it = a_.find(&F);
    if (it != a_.end()) return it->second;
    refresh_caches();
    if (auto c = a_cache_.find(&F); c != a_cache_.end()) return c->second;
    const FormedVector& v = formed_vel_in(F);
    Vector a = v.value.dt_in(F);
    if (v.compact && !a.is_zero()) {
        const Frame& E = v.value.components().size() == 1 ? *v.value.components().front().first
                                                          : *a.components().back().first;
        a = form_compact_if_long(a, E, true).value;
    }
    return a_cache_.emplace(&F, std::move(a)).first->second;
}

}  // namespace alembert
