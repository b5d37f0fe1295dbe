// SPDX-License-Identifier: MIT
// A model: the Newtonian frame, frames, points, bodies, loads, and what is derived from them.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "alembert/mech/constraint.hpp"
#include "alembert/mech/load.hpp"
#include "alembert/mech/particle.hpp"
#include "alembert/mech/rigid_body.hpp"

namespace alembert {

/// A set of bodies and particles of a model (the system S of a road-map row).
using BodySet = std::vector<const Body*>;

/// Resultant of the loads external to a system: the force F^S and the moment M^{S/O}.
struct LoadResultant {
    Vector force;
    Vector moment;
};

/// Drag laws for air resistance.
enum class DragLaw {
    linear,     ///< F = -c v
    quadratic,  ///< F = -c |v| v
};

/// A mechanical model. Owns the symbol table, the Newtonian frame N and its origin N_o, and
/// every frame, point, particle, rigid body and load; everything it hands out by reference
/// lives as long as the System (moving the System keeps them in place).
class System {
public:
    /// A model whose Newtonian frame is named `newtonian` (origin point "<newtonian>_o").
    explicit System(const std::string& newtonian = "N");
    System(System&&) noexcept;
    System& operator=(System&&) noexcept;
    ~System();

    SymbolTable& symbols() { return *table_; }
    const SymbolTable& symbols() const { return *table_; }
    /// The Newtonian (inertial) frame.
    Frame& newtonian() { return *frames_.front(); }
    const Frame& newtonian() const { return *frames_.front(); }
    /// The origin of the Newtonian frame, fixed in it (zero velocity and acceleration in N).
    Point& origin() { return *points_.front(); }
    const Point& origin() const { return *points_.front(); }

    // ---- declaration ---------------------------------------------------------------------
    /// A new reference frame.
    /// @throws alembert::ArgumentError if the name is empty,
    ///         alembert::ModelError if a frame of that name exists.
    Frame& add_frame(const std::string& name);
    /// A new point, fixed on `owner` (a force applied at it acts on owner), or on the
    /// surroundings when owner is nullptr.
    Point& add_point(const std::string& name, const Body* owner = nullptr);
    /// A new rigid body `name` with its frame `name`, a body-fixed origin point `name_o` and
    /// its mass centre `namecm` (locate the mass centre from the origin with set_pos).
    /// @throws alembert::ArgumentError if the name is empty, alembert::ModelError if any of
    ///         these names is taken (then nothing is declared).
    RigidBody& add_rigid_body(const std::string& name);
    /// A new particle `name` at a new point of the same name.
    /// @throws alembert::ArgumentError if the name is empty, alembert::ModelError if it is taken.
    Particle& add_particle(const std::string& name);

    // ---- look-up by name (each throws alembert::ModelError listing the declared names) ----
    Frame& frame(const std::string& name);
    Point& point(const std::string& name);
    Body& body(const std::string& name);
    RigidBody& rigid_body(const std::string& name);
    /// The body whose frame is F, or nullptr (N and plain frames).
    const Body* body_of(const Frame& F) const;
    /// Every body and particle, in declaration order.
    BodySet bodies() const;
    /// Every point, in declaration order (N_o first).
    std::vector<const Point*> points() const;
    /// The named bodies and particles.
    BodySet bodies(std::initializer_list<std::string> names);

    // ---- loads ---------------------------------------------------------------------------
    /// A force F at point P acting on P's owner, exerted by the surroundings; returns a copy
    /// of the load recorded.
    /// @throws alembert::ModelError if P has no owner (the force would act on nothing).
    Load add_force(const Point& P, const Vector& F, const std::string& label = "");
    /// An action/reaction pair: F on P's owner at P, and -F on Q's owner at Q.
    void add_force_pair(const Point& P, const Point& Q, const Vector& F,
                        const std::string& label = "");
    /// A torque T on body B, exerted by the surroundings; returns a copy of the load recorded.
    Load add_torque(const Body& B, const Vector& T, const std::string& label = "");
    /// An action/reaction pair: T on body B from frame A's body, and -T on A's body (nothing
    /// when A is the Newtonian frame or a frame of no body).
    void add_torque_pair(const Body& B, const Frame& A, const Vector& T,
                         const std::string& label = "");
    /// Uniform gravity: m g at the mass centre of every body and particle, now and later.
    void set_gravity(const Vector& g);
    /// A linear spring between P and Q, stiffness k, natural length L0: the force on P is
    /// -k (|r| - L0) r/|r| with r = r^{P/Q}, and the opposite on Q.
    void add_spring(const Point& P, const Point& Q, const ex& k, const ex& L0,
                    const std::string& label = "");
    /// A linear damper between P and Q: the force on P is -c ((^N v^P - ^N v^Q) . u) u with
    /// u = r^{P/Q}/|r^{P/Q}|, and the opposite on Q.
    void add_damper(const Point& P, const Point& Q, const ex& c, const std::string& label = "");
    /// Air resistance on P: -c ^N v^P (linear) or -c |^N v^P| ^N v^P (quadratic).
    void add_drag(const Point& P, const ex& c, DragLaw law, const std::string& label = "");
    /// Coulomb friction on P sliding along the unit vector u relative to Q's owner (or the
    /// surroundings): -mu |Fn| sign(v . u) u with v = ^N v^P - ^N v^Q, and the opposite on Q.
    void add_coulomb_friction(const Point& P, const Point& Q, const ex& mu, const ex& Fn,
                              const Vector& u, const std::string& label = "");
    /// Inverse-square gravitational attraction between the owners of P and Q (their masses):
    /// the force on P is -G m_P m_Q / |r|^2 r/|r|, r = r^{P/Q}, and the opposite on Q.
    void add_inverse_square_gravity(const Point& P, const Point& Q, const ex& G,
                                    const std::string& label = "");
    /// A joint reaction between `parent` (nullptr: the ground) and `child` at the point `at`:
    /// the force sum F_i d_i over `forces` and the torque sum T_j d_j over `torques`, exerted
    /// by the parent on the child (at `at`), and their opposites on the parent. Each measure
    /// must be an unknown of the symbol table, used by no other reaction; its load is recorded
    /// as a load labelled with the measure's name. Returns the reaction recorded.
    /// Reactions are constraint forces: declared along directions in which the joint moves
    /// freely they would do work, so declare them along the directions the joint prevents.
    /// @throws alembert::ArgumentError if the name is empty or taken, if there is no
    ///         component, a measure is not an unknown symbol or is used twice, a direction is
    ///         zero, or parent and child are the same body.
    const JointReaction& add_joint_reaction(const std::string& name, const Body* parent,
                                            const Body& child, const Point& at,
                                            const std::vector<ReactionComponent>& forces,
                                            const std::vector<ReactionComponent>& torques = {});
    /// Every declared joint reaction, in the order declared.
    const std::vector<JointReaction>& joint_reactions() const { return reactions_; }
    /// The joint reaction declared at point `at` between `parent` (nullptr: the ground) and
    /// `child`, or nullptr: free-body diagrams draw its measures in place of the joint's force.
    const JointReaction* find_joint_reaction(const Point& at, const Body* parent,
                                             const Body* child) const;
    /// The joint reaction one of whose measures is `measure`, or nullptr.
    const JointReaction* reaction_of(const ex& measure) const;
    /// Every load, in the order added (gravity is applied when resultants are formed).
    const std::vector<Load>& loads() const { return loads_; }
    /// The gravity vector (zero if none).
    const Vector& gravity() const { return gravity_; }

    // ---- constraints ---------------------------------------------------------------------
    /// Declares a configuration constraint f(q, t) = 0 (a closed loop, a point kept on a
    /// surface); returns it. Equations that need it at the velocity or acceleration level
    /// take its time derivatives.
    /// @throws alembert::ArgumentError if the name is empty or taken, or the residual holds
    ///         a speed or an acceleration (then it is a motion constraint), or is zero.
    const Constraint& add_configuration_constraint(const std::string& name, const ex& residual);
    /// Declares a vector configuration constraint v = 0 as one scalar constraint per non-zero
    /// measure of v in frame F, named name_x, name_y, name_z (a loop closing at a point:
    /// v = r^{P/Q} for points P and Q that must coincide).
    std::vector<Constraint> add_configuration_constraint(const std::string& name,
                                                         const Vector& v, const Frame& F);
    /// Declares a motion constraint, linear in the speeds q' (rolling without slip: the
    /// velocity of the contact point is zero); returns it.
    /// @throws alembert::ArgumentError if the name is empty or taken, the residual holds an
    ///         acceleration, holds no speed, or is not linear in the speeds.
    const Constraint& add_motion_constraint(const std::string& name, const ex& residual);
    /// Declares a vector motion constraint v = 0, one per non-zero measure of v in F.
    std::vector<Constraint> add_motion_constraint(const std::string& name, const Vector& v,
                                                  const Frame& F);
    /// Every declared constraint, in the order declared.
    const std::vector<Constraint>& constraints() const { return constraints_; }

    // ---- derived quantities of a system S (calc: may be expensive, mutate nothing) -------
    /// Total mass of S.
    ex calc_mass(const BodySet& S) const;
    /// Position of the mass centre of S from O.
    Vector calc_cm_pos(const BodySet& S, const Point& O) const;
    /// ^N L^S = sum m ^N v^{cm}.
    Vector calc_linear_momentum(const BodySet& S) const;
    /// ^N H^{S/O} = sum over S of each body's angular momentum about O.
    Vector calc_angular_momentum(const BodySet& S, const Point& O) const;
    /// Kinetic energy of S in N.
    ex calc_kinetic_energy(const BodySet& S) const;
    /// Potential energy of gravity (zero at N_o), springs and inverse-square gravity.
    ex calc_potential_energy() const;
    /// Resultant force F^S and moment M^{S/O} of the loads external to S (a load counts if it
    /// acts on a member of S and is not exerted by a member of S), gravity included.
    LoadResultant calc_resultant(const BodySet& S, const Point& O) const;

private:
    struct Potential {
        ex energy;
    };
    const Body* require_owner(const Point& P, const char* caller) const;
    const Constraint& add_constraint(const std::string& name, ConstraintKind kind,
                                     const ex& residual, const char* caller);
    std::vector<Constraint> add_vector_constraint(const std::string& name, ConstraintKind kind,
                                                  const Vector& v, const Frame& F,
                                                  const char* caller);
    void require_new_body_name(const std::string& name, const char* caller) const;
    void add_pair(const Point& P, const Point& Q, const Vector& F_on_P, const std::string& label,
                  bool conservative = false);

    std::unique_ptr<SymbolTable> table_;
    std::vector<std::unique_ptr<Frame>> frames_;
    std::vector<std::unique_ptr<Point>> points_;
    std::vector<std::unique_ptr<Body>> bodies_;
    std::vector<Load> loads_;
    std::vector<Constraint> constraints_;
    std::vector<JointReaction> reactions_;
    std::vector<Potential> potentials_;
    Vector gravity_;
};

}  // namespace alembert
