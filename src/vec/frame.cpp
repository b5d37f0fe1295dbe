// SPDX-License-Identifier: MIT
// Frame orientation tree, rotation matrices along tree paths, angular velocity and acceleration.
#include "alembert/vec/frame.hpp"

#include <algorithm>
#include <atomic>

#include "alembert/error.hpp"
#include "alembert/sym/simplify.hpp"

namespace alembert {

namespace {
std::atomic<std::uint64_t> g_next_frame_id{1};
// moves on whenever anything kinematic changes, invalidating every cache of derived kinematics
std::atomic<std::uint64_t> g_kinematics_epoch{1};

std::string path_text(const std::vector<const Frame*>& path) {
    std::string s;
    for (const Frame* f : path) s += (s.empty() ? "'" : " -> '") + f->name() + "'";
    return s;
}
}  // namespace

std::uint64_t kinematics_epoch() { return g_kinematics_epoch.load(); }
void invalidate_kinematics() { ++g_kinematics_epoch; }

Frame::Frame(SymbolTable& table, std::string name)
    : table_(&table), name_(std::move(name)), id_(g_next_frame_id++) {
    if (name_.empty()) throw ArgumentError("Frame: a frame needs a non-empty name");
}

// a frame's address may be reused: cached rotations keyed by it must not outlive it
Frame::~Frame() { invalidate_kinematics(); }

Vector Frame::unit(Axis a) const {
    Col3 c;
    c[index_of(a)] = 1;
    return Vector(*this, c);
}

void Frame::set_edge(const Frame& parent, Kind kind, const Mat3& R, const char* caller) {
    if (&parent == this)
        throw ModelError(std::string(caller) + ": frame '" + name_ +
                         "' cannot be oriented relative to itself; orient it relative to "
                         "another frame");
    if (parent.table_ != table_)
        throw ModelError(std::string(caller) + ": frames '" + name_ + "' and '" + parent.name_ +
                         "' belong to different symbol tables (different models)");
    std::vector<const Frame*> up;
    for (const Frame* p = &parent; p; p = p->parent_) {
        up.push_back(p);
        if (p == this)
            throw ModelError(std::string(caller) + ": orienting '" + name_ + "' relative to '" +
                             parent.name_ + "' would close a rotation cycle, because '" +
                             parent.name_ + "' is already oriented relative to '" + name_ +
                             "' (" + path_text(up) +
                             "); a frame tree has no cycles: orient '" + name_ +
                             "' relative to a frame outside that chain");
    }
    parent_ = &parent;
    invalidate_kinematics();
    kind_ = kind;
    R_parent_ = R;
    w_set_.reset();
    alpha_set_.reset();
    w_edge_cache_.reset();
}

void Frame::orient_axis(const Frame& parent, Axis axis, const ex& angle, Sense sense) {
    ex a = sense == Sense::positive ? angle : -angle;
    set_edge(parent, Kind::simple, simple_rotation(axis, a), "Frame::orient_axis()");
    axes_ = {axis};
    angles_ = {a};
}

void Frame::orient_body_fixed(const Frame& parent, RotationSequence seq, const ex& q1,
                              const ex& q2, const ex& q3) {
    auto ax = axes_of(seq);
    Mat3 R = simple_rotation(ax[0], q1) * simple_rotation(ax[1], q2) * simple_rotation(ax[2], q3);
    set_edge(parent, Kind::body, R, "Frame::orient_body_fixed()");
    axes_.assign(ax.begin(), ax.end());
    angles_ = {q1, q2, q3};
}

void Frame::orient_space_fixed(const Frame& parent, RotationSequence seq, const ex& q1,
                               const ex& q2, const ex& q3) {
    auto ax = axes_of(seq);
    Mat3 R = simple_rotation(ax[2], q3) * simple_rotation(ax[1], q2) * simple_rotation(ax[0], q1);
    set_edge(parent, Kind::space, R, "Frame::orient_space_fixed()");
    axes_.assign(ax.begin(), ax.end());
    angles_ = {q1, q2, q3};
}

void Frame::orient_dcm(const Frame& parent, const Mat3& R_PB) {
    set_edge(parent, Kind::dcm, R_PB, "Frame::orient_dcm()");
    axes_.clear();
    angles_.clear();
}

const Mat3& Frame::rotation_from_parent() const {
    if (!parent_)
        throw ModelError("Frame::rotation_from_parent(): frame '" + name_ +
                         "' is not oriented; orient it relative to another frame first");
    return R_parent_;
}

void Frame::set_ang_vel(const Frame& reference, const Vector& w) {
    if (!parent_)
        throw ArgumentError("Frame::set_ang_vel(): the angular velocity of '" + name_ +
                            "' is set relative to the frame it is oriented from, and '" + name_ +
                            "' is not oriented yet; orient '" + name_ + "' first");
    if (parent_ != &reference)
        throw ArgumentError("Frame::set_ang_vel(): the angular velocity of '" + name_ +
                            "' can be set in '" + parent_->name_ +
                            "', the frame it is oriented relative to, not in '" + reference.name_ +
                            "'");
    w_set_ = w;
    w_edge_cache_.reset();
    invalidate_kinematics();
}

void Frame::set_ang_acc(const Frame& reference, const Vector& alpha) {
    if (parent_ != &reference)
        throw ArgumentError("Frame::set_ang_acc(): the angular acceleration of '" + name_ +
                            "' can be set only in the frame it is oriented relative to" +
                            (parent_ ? " ('" + parent_->name_ + "')" : std::string()) +
                            ", not in '" + reference.name_ + "'");
    alpha_set_ = alpha;
    invalidate_kinematics();
}

Vector Frame::edge_ang_vel() const {
    if (w_set_) return *w_set_;
    if (w_edge_cache_) return *w_edge_cache_;
    SymbolTable& st = *table_;
    Vector w;
    switch (kind_) {
        case Kind::none:
            throw ModelError("Frame::ang_vel_in(): frame '" + name_ + "' is not oriented");
        case Kind::simple: w = st.dt(angles_[0]) * unit(axes_[0]); break;
        case Kind::body: {
            // w = q1' a1 + q2' a2 + q3' a3 with each axis carried into B by the later rotations
            Mat3 R3 = simple_rotation(axes_[2], angles_[2]);
            Mat3 R23 = simple_rotation(axes_[1], angles_[1]) * R3;
            Col3 e1, e2, e3;
            e1[index_of(axes_[0])] = 1, e2[index_of(axes_[1])] = 1, e3[index_of(axes_[2])] = 1;
            Col3 c = st.dt(angles_[2]) * e3 + st.dt(angles_[1]) * (R3.transpose() * e2) +
                     st.dt(angles_[0]) * (R23.transpose() * e1);
            w = Vector(*this, c);
            break;
        }
        case Kind::space: {
            // w = q3' n3 + q2' R3 n2 + q1' R3 R2 n1, in the parent
            Mat3 R3 = simple_rotation(axes_[2], angles_[2]);
            Mat3 R32 = R3 * simple_rotation(axes_[1], angles_[1]);
            Col3 e1, e2, e3;
            e1[index_of(axes_[0])] = 1, e2[index_of(axes_[1])] = 1, e3[index_of(axes_[2])] = 1;
            Col3 c = st.dt(angles_[2]) * e3 + st.dt(angles_[1]) * (R3 * e2) +
                     st.dt(angles_[0]) * (R32 * e1);
            w = Vector(*parent_, c);
            break;
        }
        case Kind::dcm: {
            // skew(w)_B = R^T dR/dt (Kane 1985, eq. 2.1.1)
            Mat3 Rdot = R_parent_.map([&](const ex& e) { return st.dt(e); });
            Mat3 W = R_parent_.transpose() * Rdot;
            Col3 c{{simplify(W(2, 1)), simplify(W(0, 2)), simplify(W(1, 0))}};
            w = Vector(*this, c);
            break;
        }
    }
    w_edge_cache_ = w;
    return w;
}

std::vector<const Frame*> Frame::path_to_root() const {
    std::vector<const Frame*> p;
    for (const Frame* f = this; f; f = f->parent_) p.push_back(f);
    return p;
}

namespace {
// the tree path between two frames: each one's chain up to the root, and how many edges of
// each lie below their common ancestor (nullopt when they share no root)
struct TreePath {
    std::vector<const Frame*> up_b, up_f;
    std::size_t below_b = 0, below_f = 0;
};
std::optional<TreePath> tree_path(std::vector<const Frame*> up_b, std::vector<const Frame*> up_f) {
    for (std::size_t i = 0; i < up_b.size(); ++i) {
        auto it = std::find(up_f.begin(), up_f.end(), up_b[i]);
        if (it == up_f.end()) continue;
        std::size_t j = static_cast<std::size_t>(it - up_f.begin());
        return TreePath{std::move(up_b), std::move(up_f), i, j};
    }
    return std::nullopt;
}
}  // namespace

void Frame::refresh_caches() const {
    const std::uint64_t epoch = kinematics_epoch();
    if (cache_epoch_ == epoch) return;
    R_cache_.clear();
    w_cache_.clear();
    alpha_cache_.clear();
    cache_epoch_ = epoch;
}

bool Frame::has_ancestor(const Frame& F) const {
    for (const Frame* p = parent_; p; p = p->parent_)
        if (p == &F) return true;
    return false;
}

Vector Frame::ang_vel_in(const Frame& F) const {
    if (&F == this) return {};
    if (has_ancestor(F)) return ang_vel_from_ancestor(F).value;
    auto p = tree_path(path_to_root(), F.path_to_root());
    if (!p)
        throw ModelError("Frame::ang_vel_in(): frames '" + name_ + "' and '" + F.name_ +
                         "' are not connected by orientations (" + path_text(path_to_root()) +
                         " and " + path_text(F.path_to_root()) +
                         "); orient one relative to the other or to a common frame");
    Vector w;
    for (std::size_t i = 0; i < p->below_b; ++i) w += p->up_b[i]->edge_ang_vel();
    for (std::size_t j = 0; j < p->below_f; ++j) w -= p->up_f[j]->edge_ang_vel();
    return w;
}

// ^F w^B = ^F w^P + ^P w^B for F an ancestor of B (Kane 1985, eq. 2.4.1), formed outward
const FormedVector& Frame::ang_vel_from_ancestor(const Frame& F) const {
    refresh_caches();
    if (auto it = w_cache_.find(&F); it != w_cache_.end()) return it->second;
    FormedVector w{edge_ang_vel(), false};
    if (parent_ != &F) {
        const FormedVector& wp = parent_->ang_vel_from_ancestor(F);
        w = form_compact_if_long(wp.value + w.value, *this, wp.compact);
    }
    return w_cache_.emplace(&F, std::move(w)).first->second;
}

Vector Frame::ang_acc_in(const Frame& F) const {
    if (&F == this) return {};
    if (parent_ == &F && alpha_set_) return *alpha_set_;
    refresh_caches();
    if (auto it = alpha_cache_.find(&F); it != alpha_cache_.end()) return it->second;
    Vector alpha = ang_vel_in(F).dt_in(*this);
    if (has_ancestor(F) && ang_vel_from_ancestor(F).compact)
        alpha = form_compact_if_long(alpha, *this, true).value;
    return alpha_cache_.emplace(&F, std::move(alpha)).first->second;
}

Mat3 Frame::rotation_in(const Frame& F) const {
    if (&F == this) return Mat3::identity();
    refresh_caches();
    if (auto it = R_cache_.find(&F); it != R_cache_.end()) return it->second;
    Mat3 R = compose_rotation_in(F);
    R_cache_.emplace(&F, R);
    return R;
}

Mat3 Frame::compose_rotation_in(const Frame& F) const {
    auto p = tree_path(path_to_root(), F.path_to_root());
    if (!p)
        throw ModelError("rotation_matrix(): no orientation path between frames '" + F.name_ +
                         "' and '" + name_ + "'; orient one relative to the other or to a "
                         "common frame");
    // R_FB = R_CF^T R_CB as a product of factors along the path F -> C -> B: the edges up
    // from F inverted, then the edges down to B. Simple rotations about the same axis in a
    // row fold into one (R_z(a) R_z(b) = R_z(a + b)), so a planar chain of n relative angles
    // gives cos(q1 + ... + qn) instead of a product expanded into 2^n terms.
    std::vector<Factor> factors;
    for (std::size_t j = 0; j < p->below_f; ++j) p->up_f[j]->append_edge_factors(factors, true);
    for (std::size_t i = p->below_b; i-- > 0;) p->up_b[i]->append_edge_factors(factors, false);
    // Products of rotations about different axes do not fold: long ones (spatial chains) grow
    // exponentially, so entries of a partial product beyond a size are named as intermediates
    // (shared by every product with the same prefix), keeping each product linear in length.
    constexpr std::size_t kProductNameOps = 200;
    Mat3 R = Mat3::identity();
    bool first = true;
    for (const Factor& f : factors) {
        Mat3 Rf = f.simple ? simple_rotation(f.axis, f.angle) : f.R;
        R = first ? Rf : R * Rf;
        first = false;
        for (ex& e : R.m)
            if (count_ops(e) > kProductNameOps) e = table_->name_subexpression(e);
    }
    return R;
}

void Frame::append_edge_factors(std::vector<Factor>& out, bool inverse) const {
    auto push_simple = [&](Axis axis, const ex& angle) {
        ex a = inverse ? -angle : angle;
        if (a.is_zero()) return;
        if (!out.empty() && out.back().simple && out.back().axis == axis) {
            out.back().angle += a;
            if (out.back().angle.is_zero()) out.pop_back();
            return;
        }
        out.push_back(Factor{true, axis, a, {}});
    };
    // the edge's matrix R_PB as simple factors in product order
    std::vector<std::pair<Axis, ex>> simple;
    switch (kind_) {
        case Kind::simple: simple = {{axes_[0], angles_[0]}}; break;
        case Kind::body:
            for (std::size_t k = 0; k < 3; ++k) simple.emplace_back(axes_[k], angles_[k]);
            break;
        case Kind::space:
            for (std::size_t k = 3; k-- > 0;) simple.emplace_back(axes_[k], angles_[k]);
            break;
        case Kind::none:
        case Kind::dcm: {
            out.push_back(Factor{false, Axis::x, 0, inverse ? R_parent_.transpose() : R_parent_});
            return;
        }
    }
    // the inverse reverses the order and negates each angle
    if (inverse)
        for (std::size_t k = simple.size(); k-- > 0;) push_simple(simple[k].first, simple[k].second);
    else
        for (const auto& [axis, angle] : simple) push_simple(axis, angle);
}

}  // namespace alembert
