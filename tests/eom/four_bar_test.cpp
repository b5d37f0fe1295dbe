// SPDX-License-Identifier: MIT
// A closed loop: the four-bar linkage's road-map with constraint rows, the crank torque that
// holds it still on each assembly branch (checked by virtual work on hand-solved geometry),
// and its dynamics (checked by the power balance).
#include <cmath>
#include <numbers>

#include "alembert/eom/equations.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace {

// ---- the linkage's geometry solved by hand (circle intersection), independent of Alembert

constexpr double kLN = 1.0, kLA = 0.4, kLB = 1.2, kLC = 0.8;
constexpr double kmA = 1.0, kmB = 2.0, kmC = 1.5, kg = 9.81;

struct Pose {
    double qA, qB, qC;  // qB relative to the crank, qC absolute
};

// branch +1: the coupler-rocker pin above the line from the crank tip to N_c; -1: below
Pose solve_pose(double qA, int branch) {
    double ax = kLA * std::cos(qA), ay = kLA * std::sin(qA);
    double dx = kLN - ax, dy = -ay, d = std::hypot(dx, dy);
    double a = (kLB * kLB - kLC * kLC + d * d) / (2 * d), h = std::sqrt(kLB * kLB - a * a);
    double ex = dx / d, ey = dy / d;
    double px = ax + a * ex - branch * h * ey, py = ay + a * ey + branch * h * ex;
    double thetaB = std::atan2(py - ay, px - ax);
    return {qA, thetaB - qA, std::atan2(py, px - kLN)};
}

// gravitational potential energy of the three uniform rods at a pose
double potential(const Pose& p) {
    double thB = p.qA + p.qB;
    double yA = kLA / 2 * std::sin(p.qA);
    double yB = kLA * std::sin(p.qA) + kLB / 2 * std::sin(thB);
    double yC = kLC / 2 * std::sin(p.qC);
    return kg * (kmA * yA + kmB * yB + kmC * yC);
}

// by virtual work, the torque that holds the linkage still is dV/dqA along the loop
double holding_torque(double qA, int branch) {
    const double h = 1e-5;
    return (potential(solve_pose(qA + h, branch)) - potential(solve_pose(qA - h, branch))) / (2 * h);
}

exmap pose_values(const SampleModel& m, const Pose& p) {
    return {{m.q[0].symbol(), p.qA}, {m.q[1].symbol(), p.qB}, {m.q[2].symbol(), p.qC}};
}

}  // namespace

TEST(FourBar, StaticsRoadmapHasThreeBalanceRowsAndTwoConstraintRows) {
    SampleModel m = make_four_bar();
    const System& sys = m.system;
    ASSERT_EQ(sys.constraints().size(), 2u);
    ex T = m.unknowns[0], Fx = m.unknowns[1], Fy = m.unknowns[2];
    std::vector<ex> unknowns{T, Fx, Fy, m.q[1].symbol(), m.q[2].symbol()};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns, Analysis::statics);
    ASSERT_EQ(rows.size(), 5u);
    // T: what turns with the crank (A and the coupler it carries) about the crank pivot
    EXPECT_TRUE(rows[0].variable.is_equal(T));
    EXPECT_EQ(rows[0].motion, Motion::rotate);
    ASSERT_EQ(rows[0].system.size(), 2u);
    EXPECT_EQ(rows[0].system[0]->name(), "A");
    EXPECT_EQ(rows[0].system[1]->name(), "B");
    EXPECT_EQ(rows[0].about->name(), "A_o");
    // the loop's pin force stays in every balance row: the table says so
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(rows[static_cast<std::size_t>(i)].motion, Motion::rotate);
        EXPECT_TRUE(rows[static_cast<std::size_t>(i)].equation.has(Fx));
        EXPECT_NE(rows[static_cast<std::size_t>(i)].note.find("no choice of S and O eliminates"),
                  std::string::npos);
        EXPECT_NE(rows[static_cast<std::size_t>(i)].note.find("loop_x, loop_y"), std::string::npos);
    }
    EXPECT_EQ(rows[1].about->name(), "B_o");
    EXPECT_EQ(rows[2].about->name(), "C_o");
    // the dependent coordinates come from the loop's constraint rows
    EXPECT_EQ(rows[3].motion, Motion::constraint);
    EXPECT_EQ(rows[4].motion, Motion::constraint);
    EXPECT_TRUE(rows[3].variable.is_equal(m.q[1].symbol()));
    EXPECT_EQ(rows[3].constraint, "loop_x");
    EXPECT_EQ(rows[4].constraint, "loop_y");
    std::string table = format_roadmap_table(sys, rows);
    EXPECT_NE(table.find("| constraint"), std::string::npos) << table;
    EXPECT_NE(table.find("loop_x = 0"), std::string::npos) << table;
    EXPECT_NE(format_roadmap_json(sys, rows).find("\"motion\": \"constraint\""), std::string::npos);
}

TEST(FourBar, CrankTorqueHoldingItStillMatchesVirtualWorkOnBothBranches) {
    SampleModel m = make_four_bar();
    const System& sys = m.system;
    std::vector<ex> unknowns{m.unknowns[0], m.unknowns[1], m.unknowns[2], m.q[1].symbol(),
                             m.q[2].symbol()};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns, Analysis::statics);
    std::vector<ex> balance{rows[0].equation, rows[1].equation, rows[2].equation};
    LinearSystem loads = form_linear_system(balance, m.unknowns);
    const SymbolTable& st = sys.symbols();
    for (double qA : {std::numbers::pi / 3, 2.0, -0.7}) {
        double torque[2];
        for (int branch : {+1, -1}) {
            Pose p = solve_pose(qA, branch);
            exmap at = pose_values(m, p);
            // the hand-solved pose satisfies the declared loop constraints
            EXPECT_NEAR(st.evaluate(rows[3].equation, at), 0, 1e-12);
            EXPECT_NEAR(st.evaluate(rows[4].equation, at), 0, 1e-12);
            Eigen::VectorXd x = solve_numeric(st, loads, at);
            EXPECT_NEAR(x(0), holding_torque(qA, branch), 1e-7) << "qA = " << qA << ", branch " << branch;
            torque[branch > 0 ? 0 : 1] = x(0);
        }
        // the two assembly branches are different equilibria with different torques
        EXPECT_GT(std::abs(torque[0] - torque[1]), 1e-3);
    }
}

TEST(FourBar, SolvingTheRoadmapFindsEachAssemblyBranchAndItsTorque) {
    // the whole statics road-map (3 balance rows, 2 loop rows) solved together for the crank
    // torque, the pin force and the dependent angles; a sign condition picks the branch:
    // the pin above (+) or below (-) the line from the crank tip to the rocker pivot
    SampleModel m = make_four_bar();
    const System& sys = m.system;
    const SymbolTable& st = sys.symbols();
    ex qA = m.q[0].symbol(), qB = m.q[1].symbol(), qC = m.q[2].symbol();
    std::vector<ex> unknowns{m.unknowns[0], m.unknowns[1], m.unknowns[2], qB, qC};
    std::vector<ex> E = residuals_of(plan_roadmap(sys, m.q, unknowns, Analysis::statics));
    ex LA = st.symbol("L_A"), LN = st.symbol("L_N");
    ex side = (LN - LA * GiNaC::cos(qA)) * GiNaC::sin(qA + qB) +
              LA * GiNaC::sin(qA) * GiNaC::cos(qA + qB);  // (r^{N_c/A_tip} x Bx>) . Nz>
    const double angle = std::numbers::pi / 3;
    for (int branch : {+1, -1}) {
        StaticsOptions opt;
        opt.conditions = {{side, branch > 0, branch > 0 ? "pin above" : "pin below"}};
        Pose hand = solve_pose(angle, branch);
        // start from a rough guess on the wanted side
        exmap guess{{qB, hand.qB + 0.3}, {qC, hand.qC - 0.3}};
        Equilibrium eq = solve_equilibrium(st, E, unknowns, guess, {{qA, angle}}, opt);
        EXPECT_NEAR(eq.value(qB), hand.qB, 1e-9) << "branch " << branch;
        EXPECT_NEAR(eq.value(qC), hand.qC, 1e-9) << "branch " << branch;
        EXPECT_NEAR(eq.value(m.unknowns[0]), holding_torque(angle, branch), 1e-7);
    }
    // a guess on one side with the other side's condition is refused, not silently accepted
    StaticsOptions wrong;
    wrong.conditions = {{side, false, "pin below"}};
    Pose above = solve_pose(angle, +1);
    EXPECT_THROW(solve_equilibrium(st, E, unknowns, {{qB, above.qB}, {qC, above.qC}},
                                   {{qA, angle}}, wrong),
                 SolveError);
}

TEST(FourBar, DynamicsRowsConserveEnergyAlongTheLoop) {
    // forward dynamics with the crank torque given: q'' and the pin force from 3 balance rows
    // and the loop's constraints at the acceleration level; the pin force does no net work,
    // so d/dt (KE + PE) must equal the crank torque's power T qA'
    SampleModel m = make_four_bar();
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    std::vector<ex> unknowns{m.q[0].d(2), m.q[1].d(2), m.q[2].d(2), m.unknowns[1], m.unknowns[2]};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, m.q, unknowns);
    ASSERT_EQ(rows.size(), 5u);
    std::size_t constraint_rows = 0;
    for (const RoadmapRow& r : rows) constraint_rows += r.motion == Motion::constraint ? 1 : 0;
    EXPECT_EQ(constraint_rows, 2u);
    EXPECT_TRUE(rows[0].variable.is_equal(m.q[0].d(2)));  // the crank keeps its own row
    std::vector<ex> E;
    for (const RoadmapRow& r : rows) E.push_back(r.equation);
    LinearSystem ls = form_linear_system(E, unknowns);
    ex energy_rate = st.dt(sys.calc_kinetic_energy(sys.bodies()) + sys.calc_potential_energy());
    for (int branch : {+1, -1}) {
        const double qA = 1.1, wA = 0.8, T = 2.5, h = 1e-6;
        Pose p = solve_pose(qA, branch), p1 = solve_pose(qA + h, branch),
             p0 = solve_pose(qA - h, branch);
        exmap at = pose_values(m, p);
        at[m.q[0].d(1)] = wA;  // dependent speeds along the loop, by hand-geometry differences
        at[m.q[1].d(1)] = (p1.qB - p0.qB) / (2 * h) * wA;
        at[m.q[2].d(1)] = (p1.qC - p0.qC) / (2 * h) * wA;
        at[m.unknowns[0]] = T;
        Eigen::VectorXd x = solve_numeric(st, ls, at);
        for (std::size_t i = 0; i < 3; ++i) at[unknowns[i]] = x(static_cast<int>(i));
        EXPECT_NEAR(st.evaluate(energy_rate, at), T * wA, 1e-7) << "branch " << branch;
    }
}

TEST(FourBar, TooManyUnknownsForTheRowsIsAModelError) {
    SampleModel m = make_four_bar();
    std::vector<ex> unknowns{m.unknowns[0], m.unknowns[1], m.unknowns[2], m.q[0].symbol(),
                             m.q[1].symbol(), m.q[2].symbol()};
    EXPECT_THROW_MSG(plan_roadmap(m.system, m.q, unknowns, Analysis::statics), ModelError,
                     "2 constraint rows");
}
