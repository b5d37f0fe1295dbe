// SPDX-License-Identifier: MIT
// The seed's sit-to-stand model, an inverted triple pendulum, built through the public API:
// prints the kinematics the road-map uses, the road-map the planner writes (the seed's three
// rows), the torques it gives (inverse dynamics), the mass-matrix form (forward dynamics), the
// statics torques, and the count brute-force free-body diagrams would need.
#include <cstdio>
#include <iostream>

#include <alembert/alembert.hpp>

using namespace alembert;

int main() {
    System sys("N");
    SymbolTable& s = sys.symbols();
    Frame& N = sys.newtonian();

    // constants (70 kg, 1.70 m person; Winter, Table 4.1) and coordinates qA, qB, qC
    ex g = s.add_constant("g", 9.81);
    ex L_A = s.add_constant("L_A", 0.4182), L_B = s.add_constant("L_B", 0.4165);
    ex d_A = s.add_constant("d_A", 0.2371), d_B = s.add_constant("d_B", 0.2362),
       d_C = s.add_constant("d_C", 0.3065);
    ex m_A = s.add_constant("m_A", 6.51), m_B = s.add_constant("m_B", 14.00),
       m_C = s.add_constant("m_C", 47.46);
    ex I_A = s.add_constant("I_A", 0.1038), I_B = s.add_constant("I_B", 0.2534),
       I_C = s.add_constant("I_C", 2.799);
    TimeVariable qA = s.add_variable("qA"), qB = s.add_variable("qB"), qC = s.add_variable("qC");
    ex T_A = s.add_unknown("T_A"), T_B = s.add_unknown("T_B"), T_C = s.add_unknown("T_C");

    // shank A, thigh B, head-arms-trunk C: frames, joints and mass centres
    RigidBody &A = sys.add_rigid_body("A"), &B = sys.add_rigid_body("B"),
              &C = sys.add_rigid_body("C");
    A.body_frame().orient_axis(N, Axis::z, qA);
    B.body_frame().orient_axis(A.body_frame(), Axis::z, qB);
    C.body_frame().orient_axis(B.body_frame(), Axis::z, qC);
    Point &A_o = sys.point("A_o"), &B_o = sys.point("B_o"), &C_o = sys.point("C_o");
    A_o.set_pos(sys.origin(), Vector());
    B_o.set_pos(A_o, L_A * A.body_frame().y());
    C_o.set_pos(B_o, L_B * B.body_frame().y());
    A.cm().set_pos(A_o, d_A * A.body_frame().y());
    B.cm().set_pos(B_o, d_B * B.body_frame().y());
    C.cm().set_pos(C_o, d_C * C.body_frame().y());

    // mass, inertia, gravity and the three motor torques
    A.set_mass(m_A), B.set_mass(m_B), C.set_mass(m_C);
    A.set_inertia(A.cm(), 0, 0, I_A), B.set_inertia(B.cm(), 0, 0, I_B);
    C.set_inertia(C.cm(), 0, 0, I_C);
    sys.set_gravity(-g * N.y());
    sys.add_torque_pair(A, N, T_A * N.z(), "T_A");
    sys.add_torque_pair(B, A.body_frame(), T_B * N.z(), "T_B");
    sys.add_torque_pair(C, B.body_frame(), T_C * N.z(), "T_C");

    // what the road-map of qA uses: kinematics and H of S = {A, B, C} about A_o
    for (const RigidBody* b : {&A, &B, &C})
        std::cout << "w_" << b->name() << "_N> = " << b->body_frame().ang_vel_in(N) << "\n";
    for (const RigidBody* b : {&A, &B, &C})
        std::cout << "v_" << b->cm().name() << "_N> = " << b->cm().vel_in(N).simplify() << "\n";
    BodySet S = sys.bodies({"A", "B", "C"});
    ex H_z = dot(sys.calc_angular_momentum(S, A_o), N.z());
    std::cout << "H_S_Ao> = (" << to_string(collect_in(H_z, {qA.d(1), qB.d(1), qC.d(1)}))
              << ")*Nz>\n";
    ex M_z = dot(sys.calc_resultant(S, A_o).moment, N.z());
    std::cout << "M_S_Ao> = (" << to_string(simplify(M_z)) << ")*Nz>\n";
    std::cout << "PE = " << to_string(simplify(sys.calc_potential_energy())) << "\n";

    // the MG road-map: one row per unknown torque, each free of joint forces
    std::vector<TimeVariable> q{qA, qB, qC};
    std::vector<ex> T{T_A, T_B, T_C};
    std::vector<RoadmapRow> rows = plan_roadmap(sys, q, T);
    std::cout << "\nMG road-map (inverse dynamics)\n" << format_roadmap_table(sys, rows);

    // inverse dynamics at one instant of rising from a chair (angles in rad, rad/s, rad/s^2)
    exmap state{{qA, 0.35}, {qB, -1.2}, {qC, 0.9}, {qA.d(1), 0.5}, {qB.d(1), 1.1},
                {qC.d(1), -0.8}, {qA.d(2), 0.2}, {qB.d(2), 1.5}, {qC.d(2), -1.0}};
    Eigen::VectorXd torque = solve_numeric(s, form_linear_system(residuals_of(rows), T), state);
    std::cout << "\ntorques at qA = 0.35, qB = -1.2, qC = 0.9 rad (moving):\n";
    for (int i = 0; i < 3; ++i)
        std::printf("  %s = %.4f N m\n", to_string(T[static_cast<std::size_t>(i)]).c_str(), torque(i));

    // forward dynamics: the same rows solved for the accelerations, M(q) q'' = f
    std::vector<ex> acc{qA.d(2), qB.d(2), qC.d(2)};
    LinearSystem fwd = form_linear_system(residuals_of(plan_roadmap(sys, q, acc)), acc);
    std::cout << "\nmass matrix M(q) (rows: qA, qB, qC road-map rows):\n";
    for (unsigned i = 0; i < 3; ++i) {
        std::cout << "  [";
        for (unsigned j = 0; j < 3; ++j)
            std::cout << (j ? ", " : "") << to_string(simplify(fwd.A(i, j)));
        std::cout << "]\n";
    }
    exmap motors{{qA, 0.35}, {qB, -1.2}, {qC, 0.9}, {qA.d(1), 0.5}, {qB.d(1), 1.1},
                 {qC.d(1), -0.8}};
    for (int i = 0; i < 3; ++i) motors[T[static_cast<std::size_t>(i)]] = torque(i);
    Eigen::VectorXd qdd = solve_numeric(s, fwd, motors);
    std::printf("those torques give back qA'' = %.4f, qB'' = %.4f, qC'' = %.4f rad/s^2\n",
                qdd(0), qdd(1), qdd(2));

    // statics: holding a crouch still
    std::vector<RoadmapRow> still = plan_roadmap(sys, q, T, Analysis::statics);
    exmap crouch{{qA, 0.35}, {qB, -1.2}, {qC, 0.9}};
    Eigen::VectorXd hold = solve_numeric(s, form_linear_system(residuals_of(still), T), crouch);
    std::printf("\nstatics, same pose at rest: T_A = %.4f, T_B = %.4f, T_C = %.4f N m\n",
                hold(0), hold(1), hold(2));

    // what the road-map saves
    std::cout << "\n" << summarize(form_newton_euler_equations(sys, q, T)) << "\n";
    NewtonEulerOptions spatial{NewtonEulerMode::spatial};
    std::cout << summarize(form_newton_euler_equations(sys, q, T, spatial)) << "\n";
    return 0;
}
