// SPDX-License-Identifier: MIT
// Reference frames: right-handed unit vectors, orientation in a tree, angular velocity.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <optional>
#include <string>
#include <vector>

#include "alembert/sym/symbol_table.hpp"
#include "alembert/vec/compact_form.hpp"
#include "alembert/vec/rotation.hpp"
#include "alembert/vec/vector.hpp"

namespace alembert {

/// A counter that moves on whenever anything kinematic of any model changes (a frame is
/// oriented, given an angular velocity or destroyed; a point is located or given a velocity):
/// caches of derived kinematics (rotation matrices, angular velocities, point velocities)
/// are valid while it stands still.
std::uint64_t kinematics_epoch();
/// Moves the kinematics epoch on, invalidating every cache of derived kinematics.
void invalidate_kinematics();

/// A reference frame with right-handed, mutually perpendicular unit vectors Fx>, Fy>, Fz>.
///
/// Frames form a tree: each frame is oriented relative to at most one parent, by a simple
/// rotation, a three-angle sequence or a direction-cosine matrix, and every rotation matrix,
/// angular velocity and angular acceleration between two frames of a tree follows from the
/// edges on the path between them (addition theorem, Kane 1985, eq. 2.4.1). A frame neither
/// copies nor moves: vectors refer to it by address, and the owner (usually alembert::System)
/// keeps it alive.
class Frame {
public:
    /// A frame named `name` whose derivatives use `table`.
    Frame(SymbolTable& table, std::string name);
    ~Frame();
    Frame(const Frame&) = delete;
    Frame& operator=(const Frame&) = delete;

    const std::string& name() const { return name_; }
    /// Creation index, used to order vector components deterministically.
    std::uint64_t id() const { return id_; }
    SymbolTable& symbols() const { return *table_; }

    /// The unit vectors Fx>, Fy>, Fz>.
    Vector x() const { return unit(Axis::x); }
    Vector y() const { return unit(Axis::y); }
    Vector z() const { return unit(Axis::z); }
    Vector unit(Axis a) const;

    // ---- orientation (defines the edge parent -> this) -----------------------------------
    /// Simple rotation relative to `parent` by `angle` about the axis the two share; with
    /// Sense::negative the rotation is left-handed (angle -> -angle).
    /// @throws alembert::ModelError if parent is this frame or the edge would close a cycle.
    void orient_axis(const Frame& parent, Axis axis, const ex& angle,
                     Sense sense = Sense::positive);
    /// Body-fixed three-angle sequence: successive rotations q1, q2, q3 about the named axes of
    /// the frame as rotated so far, R_PB = R_1(q1) R_2(q2) R_3(q3).
    void orient_body_fixed(const Frame& parent, RotationSequence seq, const ex& q1,
                           const ex& q2, const ex& q3);
    /// Space-fixed three-angle sequence: successive rotations about the named axes of the
    /// parent, R_PB = R_3(q3) R_2(q2) R_1(q1).
    void orient_space_fixed(const Frame& parent, RotationSequence seq, const ex& q1,
                            const ex& q2, const ex& q3);
    /// Orientation by the direction-cosine matrix R_PB ([v]_P = R_PB [v]_B; the columns are
    /// this frame's unit vectors expressed in `parent`).
    void orient_dcm(const Frame& parent, const Mat3& R_PB);

    /// The parent frame, or nullptr for a root (the Newtonian frame or a frame not oriented).
    const Frame* parent() const { return parent_; }
    /// R_PB of the edge to the parent.
    /// @throws alembert::ModelError if this frame is not oriented.
    const Mat3& rotation_from_parent() const;

    /// Sets the angular velocity of this frame in its parent directly (e.g. in terms of chosen
    /// speeds wx, wy, wz); it replaces the one derived from the orientation.
    /// @throws alembert::ArgumentError if `reference` is not this frame's parent.
    void set_ang_vel(const Frame& reference, const Vector& w);
    /// Sets the angular acceleration of this frame in its parent directly.
    void set_ang_acc(const Frame& reference, const Vector& alpha);

    // ---- kinematics (calc: derived, may be expensive, mutates nothing observable) --------
    /// ^F w^B, the angular velocity of this frame B in frame F: the sum of the edge angular
    /// velocities on the tree path from F to B (addition theorem). When F is an ancestor of B
    /// (F = N, usually) it is formed frame by frame outward, ^F w^B = ^F w^P + ^P w^B, and
    /// put in compact form in B for long chains (see FormedVector).
    /// @throws alembert::ModelError if the frames are not connected.
    Vector ang_vel_in(const Frame& F) const;
    /// ^F alpha^B = ^F d/dt ^F w^B (equal to ^B d/dt ^F w^B, the cheaper one used), in
    /// compact form when ^F w^B is.
    Vector ang_acc_in(const Frame& F) const;
    /// R_FB, the rotation matrix with [v]_F = R_FB [v]_B, from the tree path.
    /// @throws alembert::ModelError naming both frames if they are not connected.
    Mat3 rotation_in(const Frame& F) const;

private:
    enum class Kind { none, simple, body, space, dcm };
    std::vector<const Frame*> path_to_root() const;
    Vector edge_ang_vel() const;
    void set_edge(const Frame& parent, Kind kind, const Mat3& R, const char* caller);
    // one factor of a rotation product: a simple rotation (foldable with its neighbours
    // about the same axis) or a general matrix
    struct Factor {
        bool simple = false;
        Axis axis = Axis::x;
        ex angle{};
        Mat3 R{};
    };
    void append_edge_factors(std::vector<Factor>& out, bool inverse) const;
    Mat3 compose_rotation_in(const Frame& F) const;

    SymbolTable* table_;
    std::string name_;
    std::uint64_t id_;
    const Frame* parent_ = nullptr;
    Kind kind_ = Kind::none;
    Mat3 R_parent_;
    std::vector<Axis> axes_;
    std::vector<ex> angles_;
    std::optional<Vector> w_set_;
    std::optional<Vector> alpha_set_;
    mutable std::optional<Vector> w_edge_cache_;
    const FormedVector& ang_vel_from_ancestor(const Frame& F) const;
    bool has_ancestor(const Frame& F) const;
    void refresh_caches() const;
    // R_FB, ^F w^B and ^F alpha^B by F, valid while the kinematics epoch stands still
    mutable std::unordered_map<const Frame*, Mat3> R_cache_;
    mutable std::unordered_map<const Frame*, FormedVector> w_cache_;
    mutable std::unordered_map<const Frame*, Vector> alpha_cache_;
    mutable std::uint64_t cache_epoch_ = 0;
};

/// R_AB, the rotation matrix with [v]_A = R_AB [v]_B.
inline Mat3 rotation_matrix(const Frame& A, const Frame& B) { return B.rotation_in(A); }

}  // namespace alembert
