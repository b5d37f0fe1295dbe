// SPDX-License-Identifier: MIT
// The KUKA iiwa 14 sample arm (make_kuka_iiwa14, src/mech/sample_kuka_iiwa.cpp): the recursive formation and Kane's closed
// form agree at random states, and the statics of the upright arm by hand.
#include <cmath>
#include <random>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/tree_dynamics.hpp"
#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;

TEST(KukaIiwa14, RecursiveAndKaneEquationsAgreeAtRandomStates) {
    SampleModel m = make_kuka_iiwa14();
    ASSERT_EQ(m.q.size(), 7u);
    TreeEquations tree = form_tree_equations(m.system, m.q);
    std::vector<ex> kane = form_kane_equations(m.system, m.q);
    const SymbolTable& st = m.system.symbols();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int trial = 0; trial < 3; ++trial) {
        exmap at;
        for (const TimeVariable& q : m.q)
            for (int k = 0; k <= 2; ++k) at[q.d(k)] = d(rng);
        for (const ex& T : m.unknowns) at[T] = 10 * d(rng);
        for (std::size_t i = 0; i < 7; ++i) {
            double a = st.evaluate(tree.residuals[i], at), b = st.evaluate(kane[i], at);
            EXPECT_NEAR(a, b, 1e-12 * std::max(1.0, std::abs(b))) << "joint " << i + 1;
        }
    }
}

TEST(KukaIiwa14, ForwardDynamicsBalancesThePowerOfTheJointTorques) {
    // along any motion d/dt (T + V) = sum_i T_i q_i' (no damping, gravity in V): with q'' from
    // the articulated-body recursion at random states and torques, the rate of the energy
    // (formed from the model's velocities and heights, not from the equations) must equal the
    // power of the torques
    SampleModel m = make_kuka_iiwa14();
    TreeEquations tree = form_tree_equations(m.system, m.q);
    ASSERT_EQ(tree.accelerations.size(), 7u);
    System& sys = m.system;
    SymbolTable& st = sys.symbols();
    const ex g = st.symbol("g");
    ex energy = sys.calc_kinetic_energy(sys.bodies());
    for (RigidBody* B : m.links)
        energy += B->mass() * g * dot(B->cm().pos_from(sys.origin()), sys.newtonian().z());
    const ex energy_rate = st.dt(energy);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int trial = 0; trial < 4; ++trial) {
        exmap at;
        for (const TimeVariable& q : m.q) at[q.symbol()] = d(rng), at[q.d(1)] = d(rng);
        for (const ex& T : m.unknowns) at[T] = 10 * d(rng);
        double power = 0;
        for (std::size_t i = 0; i < 7; ++i) {
            power += st.evaluate(m.unknowns[i], at) * st.evaluate(m.q[i].d(1), at);
        }
        for (std::size_t i = 0; i < 7; ++i) at[m.q[i].d(2)] = st.evaluate(tree.accelerations[i], at);
        const double rate = st.evaluate(energy_rate, at);
        EXPECT_NEAR(rate, power, 1e-10 * std::max(1.0, std::abs(power))) << "trial " << trial;
    }
}
