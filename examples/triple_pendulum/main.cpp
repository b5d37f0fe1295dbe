// SPDX-License-Identifier: MIT
// The seed's sit-to-stand model, an inverted triple pendulum, built through the public API:
// prints angular velocities, mass-centre velocities and the angular momentum of {A, B, C}
// about the ankle A_o.
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
    return 0;
}
