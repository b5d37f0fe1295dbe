// SPDX-License-Identifier: MIT
// Which bodies each speed moves, by hand for a planar and a spatial chain.
#include "alembert/eom/moving_bodies.hpp"

#include "alembert/mech/sample_models.hpp"
#include "support/expect.hpp"

using namespace alembert;

namespace moving_bodies_test {

TEST(MovingBodies, EachJointOfTheTriplePendulumMovesTheBodiesBeyondIt) {
    // the sit-to-stand's chain A (ankle at N_o), B (knee), C (hip), each turning about Nz by
    // its own angle: qA' turns A, B and C and moves their mass centres; qB' turns B and C only;
    // qC' C only. No coordinate moves A alone, qB moves exactly {B, C}.
    const SampleModel m = make_triple_pendulum();
    MovingBodies moving(m.system);
    const std::vector<const Body*>& bodies = m.system.bodies();
    ASSERT_EQ(bodies.size(), 3u);
    ASSERT_EQ(m.q.size(), 3u);
    for (std::size_t j = 0; j < m.q.size(); ++j) {
        const std::vector<BodyMotion>& motions = moving.calc_motions(m.q[j].d(1));
        ASSERT_EQ(motions.size(), 3u);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            EXPECT_EQ(motions[i].turns, i >= j) << m.q[j].name() << " and " << bodies[i]->name();
            EXPECT_EQ(motions[i].slides, i >= j) << m.q[j].name() << " and " << bodies[i]->name();
        }
    }
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[0], bodies[1], bodies[2]}), m.q[0].name());
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[1], bodies[2]}), m.q[1].name());
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[2]}), m.q[2].name());
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[0]}), "");
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[0], bodies[2]}), "");
}

TEST(MovingBodies, SpatialChainTwoAxesAtEachJointMoveTheLinksBeyond) {
    // three links, each joined to the one before by two axes (qz_k about the parent's z, then
    // qx_k about the link's x): both angles of joint k turn links k to 3; the first link's mass
    // centre moves with them too (it is off the joint at N_o)
    const SampleModel m = make_n_link_pendulum(3, ChainKind::spatial);
    MovingBodies moving(m.system);
    const std::vector<const Body*>& bodies = m.system.bodies();
    ASSERT_EQ(bodies.size(), 3u);
    ASSERT_EQ(m.q.size(), 6u);
    for (std::size_t j = 0; j < m.q.size(); ++j) {
        const std::vector<BodyMotion>& motions = moving.calc_motions(m.q[j].d(1));
        for (std::size_t i = 0; i < bodies.size(); ++i)
            EXPECT_EQ(motions[i].moves(), i >= j / 2) << m.q[j].name() << " and " << bodies[i]->name();
    }
    // the first of the two angles moving exactly S is named
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[1], bodies[2]}), m.q[2].name());
    EXPECT_EQ(moving.calc_coordinate_moving({bodies[2]}), m.q[4].name());
}

}  // namespace moving_bodies_test
