// SPDX-License-Identifier: MIT
// Joint reactions given to generate_code that it cannot compute fail with messages naming the
// measure (their numbers are checked from scripts in tests/lang/codegen_reactions_test.cpp).
#include "alembert/codegen/codegen.hpp"

#include "alembert/error.hpp"
#include "harness.hpp"
#include "support/expect.hpp"

using namespace alembert;
using namespace alembert::test;

TEST(ReactionsCodegen, MeasuresThatAreNotLoadsOrLackTheirRowsFailWithClearMessages) {
    CodegenCase c = triple_pendulum_reactions_case();
    const SymbolTable& T = c.table();
    System& sys = c.model->system;
    const ex R_x = T.symbol("R_" + c.model->links[0]->name() + "_x");
    const ex R_y = T.symbol("R_" + c.model->links[0]->name() + "_y");
    DynamicsEquations eq = c.equations;
    eq.inverse_residuals.clear();
    for (const RoadmapRow& row : plan_roadmap(sys, c.model->q, {R_x, R_y})) {
        eq.reactions.push_back(row.variable);
        eq.reaction_residuals.push_back(row.equation);
    }
    ScratchDir dir("reaction-errors");
    // the rows of one measure for two
    DynamicsEquations one_row = eq;
    one_row.reaction_residuals.pop_back();
    EXPECT_THROW_MSG(generate_code(T, one_row, Language::c, dir.path()), ArgumentError,
                     "1 road-map rows for 2 joint-reaction measures");
    // a measure that is not a load: the simulation has no column to write it to
    DynamicsEquations not_a_load = eq;
    std::erase_if(not_a_load.loads, [&](const ex& u) { return u.is_equal(R_y); });
    EXPECT_THROW_MSG(generate_code(T, not_a_load, Language::c, dir.path()), ArgumentError,
                     "the joint-reaction measure '" + to_string(R_y) + "' is not one of the loads");
    // a row that does not hold its measure (another measure's row in its place)
    DynamicsEquations wrong_row = eq;
    std::swap(wrong_row.reaction_residuals[0], wrong_row.reaction_residuals[1]);
    wrong_row.reaction_residuals[1] = wrong_row.reaction_residuals[0];
    EXPECT_THROW(generate_code(T, wrong_row, Language::c, dir.path()), SolveError);
}
