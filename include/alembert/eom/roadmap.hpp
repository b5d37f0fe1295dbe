// SPDX-License-Identifier: MIT
// MG road-map rows: one equation per unknown from a chosen system, direction and point.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "alembert/mech/system.hpp"

namespace alembert {

/// Whether a row balances forces along a direction or moments about a line, or is a
/// constraint the model declares (closed loops, rolling) at the level the analysis needs.
enum class Motion { translate, rotate, constraint };

/// Dynamics (inertia terms kept) or statics (all inertia terms zero).
enum class Analysis { dynamics, statics };

/// One row of an MG road-map (Mitiguy, Advanced Dynamics & Motion Simulation, ch. 21).
///
/// Sign convention, used everywhere in Alembert: an equation is a residual
/// E = applied - inertial, set to zero:
///  - translate: E = u . (F^S - sum m ^N a^{cm})          (statics: u . F^S)
///  - rotate:    E = u . (M^{S/O} - ^N d/dt ^N H^{S/O} - ^N v^O x ^N L^S)   (statics: u . M^{S/O})
/// where F^S and M^{S/O} hold only the loads external to S.
struct RoadmapRow {
    ex variable{};                  ///< the unknown the row is for (q'', q, or a torque)
    Motion motion = Motion::rotate;
    Vector direction{};             ///< u, the unit vector the balance is projected on
    BodySet system{};               ///< S
    const Point* about = nullptr;   ///< O, for rotate rows
    Analysis analysis = Analysis::dynamics;
    std::string constraint{};       ///< for constraint rows: the declared constraint's name

    // ---- filled by form_roadmap_row() ----------------------------------------------------
    ex equation{};                        ///< the residual E (= 0)
    std::vector<std::string> fbd{};       ///< the free-body diagram of S: loads from outside
    std::vector<ex> additional_unknowns{};  ///< unknowns in E other than `variable`
    std::string note{};                   ///< the planner's remarks (empty when all is well)

    /// An about point off the bodies the planner located for this row (the instantaneous
    /// centre of S's motion, the intersection of two unknown forces' lines of action);
    /// `about` points to it. Null when O is a point of the model.
    std::shared_ptr<const Point> about_owned{};
};

/// The residual E of a row (see RoadmapRow for the formula and sign).
/// @throws alembert::ArgumentError if a rotate row has no about point or S is empty.
ex form_roadmap_equation(const System& sys, const RoadmapRow& row);

/// Forms the row's equation, its free-body diagram and its additional unknowns (those of
/// `unknowns` that appear in the equation besides the row's variable).
void form_roadmap_row(const System& sys, RoadmapRow& row, const std::vector<ex>& unknowns);

/// Forms a constraint row: `row.constraint` names a constraint declared in `sys`; statics
/// uses a configuration constraint as declared, dynamics its time derivative at the level of
/// the accelerations (second derivative of a configuration constraint, first of a motion
/// constraint). Sets the motion to Motion::constraint, the equation and the additional
/// unknowns.
/// @throws alembert::ArgumentError if no constraint of that name is declared, or a motion
///         constraint is used in statics (it restricts speeds only).
void form_constraint_row(const System& sys, RoadmapRow& row, const std::vector<ex>& unknowns);

/// True if point P of a body is a joint: it is located (through points of no body) from a
/// point of another body C (or of the ground, C = nullptr) by an offset that stays constant in
/// C's frame (N for the ground), so P is a point of both (a pin or a weld) and unknown contact
/// loads act there. An offset that changes with the coordinates (a disk's centre at
/// x Nx> + r Ny>, a rod's foot at L sin q Nx>) only says where P is: no joint. `other`
/// receives C. Decided at random states (alembert::is_zero_at_random_states).
bool is_joint_point(const System& sys, const Point& P, const Body** other = nullptr);

/// The free-body diagram of S as text lines: each load external to S with where it acts and
/// what exerts it, gravity, and the joints where S connects to the rest (unknown forces).
std::vector<std::string> describe_free_body_diagram(const System& sys, const BodySet& S);

/// The same, marking the loads whose unknown measures the row's `equation` does not keep
/// ("(unknown, drops out)": a joint force through the about point, a force normal to u).
std::vector<std::string> describe_free_body_diagram(const System& sys, const BodySet& S,
                                                    const ex& equation);

/// The road-map as an aligned text table (variable | translate/rotate | direction | system S |
/// FBD of S | about point | equation | additional unknowns), followed by the equations
/// (E_x: 0 = ..., each simplified where it is small enough), unless `with_equations` is false.
std::string format_roadmap_table(const System& sys, const std::vector<RoadmapRow>& rows,
                                 bool with_equations = true);

/// The road-map as JSON: an array of row objects with the same fields as the table.
std::string format_roadmap_json(const System& sys, const std::vector<RoadmapRow>& rows);

/// `s` as the inside of a JSON string (quotes, backslashes and control characters escaped).
/// With `for_script`, '<', '>' and '&' are written as \u003c, \u003e and \u0026 too, so the
/// JSON can sit inside an HTML <script> element (the report embeds its data that way).
std::string json_escape(const std::string& s, bool for_script = false);

}  // namespace alembert
