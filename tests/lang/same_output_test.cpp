// SPDX-License-Identifier: MIT
// Same script, same output inside one process: the transcript does not follow what the process
// made before (GiNaC orders the terms of sums and products by its symbols' serial numbers and
// hashes, which depend on every symbol made earlier).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/eom/planner.hpp"
#include "alembert/lang/interpreter.hpp"
#include "alembert/mech/sample_models.hpp"

namespace same_output_lang_test {

using namespace alembert;
using namespace alembert::lang;

namespace fs = std::filesystem;

// the sit-to-stand model: its road-map, Kane's equations made readable, the road-map solved, an
// evaluation, and the equations as C
const char* const kScript = R"(newtonian N
body A, B, C
constant g = 9.81 m/s^2, L_A = 41.82 cm, L_B = 41.65 cm
constant d_A = 23.71 cm, d_B = 23.62 cm, d_C = 30.65 cm
constant m_A = 6.51 kg, m_B = 14.00 kg, m_C = 47.46 kg
constant I_A = 0.1038 kg*m^2, I_B = 0.2534 kg*m^2, I_C = 2.799 kg*m^2
variable qA'', qB'', qC''
unknown T_A N*m, T_B N*m, T_C N*m
rotate A from N about z by qA
rotate B from A about z by qB
rotate C from B about z by qC
translate A_o from N_o by 0>
translate B_o from A_o by L_A*Ay>
translate C_o from B_o by L_B*By>
translate Acm from A_o by d_A*Ay>
translate Bcm from B_o by d_B*By>
translate Ccm from C_o by d_C*Cy>
mass A = m_A; mass B = m_B; mass C = m_C
inertia A = 0, 0, I_A; inertia B = 0, 0, I_B; inertia C = 0, 0, I_C
gravity -g*Ny>
torque T_A on A from N = T_A*Nz>
torque T_B on B from A = T_B*Nz>
torque T_C on C from B = T_C*Nz>
roadmap R for T_A, T_B, T_C
kane K for qA, qB, qC
simplify K
solve R for T_A, T_B, T_C at qA = 20 deg, qB = -70 deg, qC = 60 deg, qA' = 0, qB' = 0, qC' = 0, qA'' = 0, qB'' = 0, qC'' = 0
evaluate dot(pos(Ccm, N_o), Ny>) at qA = 20 deg, qB = -70 deg, qC = 60 deg
codegen c name fall to "code"
)";

struct Output {
    std::string transcript;
    std::map<std::string, std::string> files;  // by path under the output folder
};

Output run_script() {
    const fs::path dir = fs::temp_directory_path() / "alembert_same_output_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(dir.string());
    EXPECT_EQ(interp.run(kScript, "model.alb"), RunStatus::ok) << err.str();
    Output o{out.str(), {}};
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        o.files[fs::relative(e.path(), dir).string()] = text.str();
    }
    fs::remove_all(dir);
    return o;
}

TEST(SameOutput, TranscriptDoesNotFollowWhatWasMadeBefore) {
    const Output first = run_script();
    ASSERT_FALSE(first.files.empty()) << "codegen wrote nothing";
    // (the generated C is not compared yet: the expressions it is compiled from still take
    // forms, and the compiler an order of operands, that follow GiNaC's term order)
    for (int round = 0; round < 3; ++round) {
        // unrelated symbols and another model first: every later symbol's serial number moves
        std::vector<GiNaC::symbol> unrelated;
        for (int k = 0; k < 1000 + 777 * round; ++k) unrelated.emplace_back("d" + std::to_string(k));
        SampleModel other = make_n_link_pendulum(2 + round);
        (void)plan_roadmap(other.system, other.q, other.unknowns);
        const Output again = run_script();
        EXPECT_TRUE(again.transcript == first.transcript)
            << "round " << round << ", the transcript was\n" << first.transcript << "\nand is\n" << again.transcript;
    }
}

}  // namespace same_output_lang_test
