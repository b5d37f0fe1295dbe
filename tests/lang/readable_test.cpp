// SPDX-License-Identifier: MIT
// Equations a person can read: every intermediate a transcript names is defined before it is
// used, printed equations mean what was formed, and they are shorter than as formed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <ginac/ginac.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/lang/interpreter.hpp"

namespace fs = std::filesystem;
using namespace alembert::lang;

namespace {

struct Session {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    std::string run(const std::string& text) {
        out.str("");
        RunStatus s = interp.run(text, "test.alb");
        EXPECT_EQ(s, RunStatus::ok) << err.str();
        return out.str();
    }
};

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Names of intermediates (z1, z12', ...) a transcript uses before a line "zN = ..." defines
// them; empty when every one is defined first.
std::vector<std::string> undefined_intermediates(const std::string& transcript) {
    static const std::regex name(R"((^|[^A-Za-z0-9_])(z[0-9]+'*))");
    std::set<std::string> defined;
    std::vector<std::string> bad;
    std::istringstream in(transcript);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("> ", 0) == 0) continue;  // the statement echoed
        std::string body = line;
        std::smatch def;
        // the name and " = " only: a `(.*)$` over a line of thousands of characters recurses
        // once per character in libstdc++'s regex (a stack overflow in unoptimized code)
        static const std::regex definition(R"(^(z[0-9]+'*) = )");
        std::string lhs;
        if (std::regex_search(line, def, definition, std::regex_constants::match_continuous))
            lhs = def[1], body = def.suffix();
        for (auto it = std::sregex_iterator(body.begin(), body.end(), name); it != std::sregex_iterator(); ++it)
            if (!defined.count((*it)[2].str())) bad.push_back((*it)[2].str() + " in: " + line.substr(0, 120));
        if (!lhs.empty()) defined.insert(lhs);
    }
    return bad;
}

// the right-hand side of the line that starts with `label`
std::string rhs(const std::string& transcript, const std::string& label) {
    std::istringstream in(transcript);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(label, 0) == 0) return line.substr(label.size());
    ADD_FAILURE() << "no line '" << label << "' in:\n" << transcript;
    return "0";
}

// "= 0" with or without a unit: what evaluate prints for a difference that vanishes
bool is_zero(const std::string& printed) { return printed == "= 0\n" || printed.rfind("= 0 ", 0) == 0; }

// terms of a printed sum at the outer level
int outer_terms(const std::string& s) {
    int depth = 0, n = 1;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '(') ++depth;
        else if (s[i] == ')') --depth;
        else if (depth == 0 && i > 0 && s[i - 1] == ' ' && (s[i] == '+' || s[i] == '-') && i + 1 < s.size() &&
                 s[i + 1] == ' ')
            ++n;
    }
    return n;
}

const char* const kTriplePendulum = R"(newtonian N
body A, B, C
constant g = 9.81 m/s^2, L_A = 41.82 cm, L_B = 41.65 cm
constant d_A = 23.71 cm, d_B = 23.62 cm, d_C = 30.65 cm
constant m_A = 6.51 kg, m_B = 14.00 kg, m_C = 47.46 kg
constant I_A = 0.1038 kg*m^2, I_B = 0.2534 kg*m^2, I_C = 2.799 kg*m^2
variable qA'', qB'', qC''
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
)";

// a four-link chain: its kinematics are in compact form, with named intermediates
const char* const kFourLinks = R"(newtonian N
body A, B, C, D
constant g = 9.81 m/s^2, L = 1 m, m = 1 kg, I = 0.1 kg*m^2
variable qA'', qB'', qC'', qD''
unknown T_A N*m, T_B N*m, T_C N*m, T_D N*m
rotate A from N about z by qA
rotate B from A about z by qB
rotate C from B about z by qC
rotate D from C about z by qD
translate A_o from N_o by 0>
translate B_o from A_o by L*Ay>
translate C_o from B_o by L*By>
translate D_o from C_o by L*Cy>
translate Acm from A_o by L/2*Ay>
translate Bcm from B_o by L/2*By>
translate Ccm from C_o by L/2*Cy>
translate Dcm from D_o by L/2*Dy>
mass A = m; mass B = m; mass C = m; mass D = m
inertia A = 0, 0, I; inertia B = 0, 0, I; inertia C = 0, 0, I; inertia D = 0, 0, I
gravity -g*Ny>
torque T_A on A from N = T_A*Nz>
torque T_B on B from A = T_B*Nz>
torque T_C on C from B = T_C*Nz>
torque T_D on D from C = T_D*Nz>
vel(Dcm, N)
acc(Dcm, N)
kane K for qA, qB, qC, qD
lagrange Lg for qA, qB, qC, qD
roadmap E for T_A, T_B, T_C, T_D
row R for T_D rotate D about D_o along Nz>
simplify K
)";

const char* const kState =
    "qA = 0.31, qB = -0.72, qC = 1.13, qA' = 0.4, qB' = -0.9, qC' = 1.7, qA'' = 0.23, qB'' = -1.1, qC'' = 0.61";

}  // namespace

TEST(Readable, NoExampleTranscriptNamesAnIntermediateBeforeDefiningIt) {
    int files = 0;
    for (const auto& dir : fs::directory_iterator(fs::path(ALEMBERT_SOURCE_DIR) / "examples")) {
        for (const char* f : {"expected_output.txt", "expected_roadmap.txt"}) {
            fs::path p = dir.path() / f;
            if (!fs::exists(p)) continue;
            ++files;
            for (const std::string& bad : undefined_intermediates(read(p))) ADD_FAILURE() << p << ": " << bad;
        }
    }
    EXPECT_GE(files, 10);
}

TEST(Readable, AFourLinkChainsTranscriptDefinesEveryIntermediateItNames) {
    Session s;
    std::string t = s.run(kFourLinks);
    for (const std::string& bad : undefined_intermediates(t)) ADD_FAILURE() << bad << "\n" << t;
    // the scan does see intermediates here: some are long enough to stay named and be defined
    EXPECT_TRUE(std::regex_search(t, std::regex(R"(\nz[0-9]+'* = )"))) << t;
    // and the scan itself catches a name used before its definition
    EXPECT_EQ(undefined_intermediates("K[1]: 0 = m*z3\nz3 = L*qA\n").size(), 1u);
    EXPECT_TRUE(undefined_intermediates("z3 = L*qA\nK[1]: 0 = m*z3'\n").size() == 1u);
}

TEST(Readable, TriplePendulumKaneAndLagrangePrintWhatWasFormedShorter) {
    Session s;
    s.run(kTriplePendulum);
    std::string formed = s.run("kane K for qA, qB, qC\nlagrange Lg for qA, qB, qC\n");
    std::size_t before_chars = 0, after_chars = 0;
    int before_terms = 0, after_terms = 0;
    for (const char* name : {"K", "Lg"}) {
        for (int i = 1; i <= 3; ++i) {
            std::string label = std::string(name) + "[" + std::to_string(i) + "]";
            std::string shown = rhs(formed, label + ": 0 = ");
            // as formed: the stored equation printed without simplification
            std::string raw = rhs(s.run(label + "\n"), label + " = ");
            // the printed form means what was formed: their difference is 0 at a random state
            std::string diff = s.run("evaluate " + label + " - (" + shown + ") at " + kState + "\n");
            EXPECT_TRUE(is_zero(diff)) << label << ": " << diff << shown;
            // Lagrange's equations as formed are products of the energies' derivatives, far
            // longer than collected; Kane's are nested products a little shorter than expanded
            // and collected (simplify K, below, factors them shorter than formed)
            if (std::string(name) == "Lg") EXPECT_LT(shown.size(), raw.size()) << label;
            else EXPECT_LT(shown.size(), raw.size() * 13 / 10) << label;
            before_chars += raw.size(), after_chars += shown.size();
            before_terms += outer_terms(raw), after_terms += outer_terms(shown);
            std::cout << label << ": " << raw.size() << " -> " << shown.size() << " characters, "
                      << outer_terms(raw) << " -> " << outer_terms(shown) << " outer terms\n";
        }
    }
    std::cout << "K and Lg: " << before_chars << " -> " << after_chars << " characters, " << before_terms
              << " -> " << after_terms << " outer terms\n";
    EXPECT_LT(after_chars, before_chars);
    // each acceleration appears once per printed equation: collected
    for (int i = 1; i <= 3; ++i) {
        std::string shown = rhs(formed, "K[" + std::to_string(i) + "]: 0 = ");
        for (const char* a : {"qA''", "qB''", "qC''"}) {
            std::size_t first = shown.find(a);
            ASSERT_NE(first, std::string::npos) << shown;
            EXPECT_EQ(shown.find(a, first + 1), std::string::npos) << shown;
        }
    }
}

TEST(Readable, SimplifyStatementFactorsKeepsTheMeaningAndShortens) {
    Session s;
    s.run(kTriplePendulum);
    std::string printed = s.run("kane K for qA, qB, qC\nK0 = K\n");
    std::string factored = s.run("simplify K\n");
    std::size_t formed_chars = 0, printed_chars = 0, factored_chars = 0;
    for (int i = 1; i <= 3; ++i) {
        std::string label0 = "K0[" + std::to_string(i) + "]";
        formed_chars += rhs(s.run(label0 + "\n"), label0 + " = ").size();
        printed_chars += rhs(printed, "K[" + std::to_string(i) + "]: 0 = ").size();
        factored_chars += rhs(factored, "K[" + std::to_string(i) + "]: 0 = ").size();
    }
    std::cout << "Kane's equations of the triple pendulum: " << formed_chars << " characters as formed, "
              << printed_chars << " printed by kane, " << factored_chars << " after simplify K\n";
    EXPECT_LT(factored_chars, formed_chars);
    EXPECT_LT(factored_chars, printed_chars);
    for (int i = 1; i <= 3; ++i) {
        std::string label = "K[" + std::to_string(i) + "]";
        std::string shown = rhs(factored, label + ": 0 = ");
        // the stored equation changed in form, not in meaning
        EXPECT_TRUE(is_zero(s.run("evaluate " + label + " - K0[" + std::to_string(i) + "] at " + kState + "\n")));
        EXPECT_TRUE(is_zero(s.run("evaluate K0[" + std::to_string(i) + "] - (" + shown + ") at " + kState + "\n")))
            << shown;
        EXPECT_LE(shown.size(), rhs(printed, label + ": 0 = ").size()) << shown;
    }
    // the velocity terms of the third equation share d_C*L_B*m_C*sin(qC): one term, not three
    EXPECT_EQ(outer_terms(rhs(factored, "K[3]: 0 = ")), 6) << factored;
}

TEST(Readable, SimplifyStatementRefusesWhatIsNotAListOfEquations) {
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    EXPECT_EQ(interp.run(std::string(kTriplePendulum) + "simplify K\n", "t.alb"), RunStatus::script_error);
    EXPECT_NE(err.str().find("there are no equations named 'K'"), std::string::npos) << err.str();
    EXPECT_NE(err.str().find("t.alb:20:10"), std::string::npos) << err.str();
}

TEST(Readable, AnAngleShiftedByPiPrintsWithoutTheShift) {
    Session s;
    s.run(kTriplePendulum);
    EXPECT_EQ(s.run("simplify(sin(qB + pi))\n"), "= -sin(qB)\n");
    // a half turn written as a decimal number (as 180 deg arrives) counts too
    EXPECT_EQ(s.run("simplify(cos(qB - pi/2) + cos(qC + 3.141592653589793))\n"), "= sin(qB) - cos(qC)\n");
}

namespace {

// an n-link spatial chain, each link turning about z or x of the one before (as
// bench/pipeline/chain.py writes it), ending with Kane's equations and a road-map
std::string spatial_chain(int n) {
    std::string names, coords, torques, q;
    for (int i = 1; i <= n; ++i) {
        const std::string k = std::to_string(i), sep = i > 1 ? ", " : "";
        names += sep + "B" + k;
        coords += sep + "q" + k + "''";
        torques += sep + "T" + k + " N*m";
        q += sep + "q" + k;
    }
    std::string s = "newtonian N\nbody " + names + "\nconstant g = 9.81 m/s^2, L = 0.1 m, mL = 0.2 kg, IL = 0.0002 kg*m^2\n" +
                    "variable " + coords + "\nunknown " + torques + "\n";
    std::string ts;
    for (int i = 1; i <= n; ++i) {
        const std::string k = std::to_string(i), p = i == 1 ? "N" : "B" + std::to_string(i - 1);
        const std::string axis = i % 2 ? "z" : "x";
        s += "rotate B" + k + " from " + p + " about " + axis + " by q" + k + "\n";
        s += "translate B" + k + "_o from " + (i == 1 ? "N_o by 0>" : p + "_o by -L*" + p + "y>") + "\n";
        s += "translate B" + k + "cm from B" + k + "_o by -L/2*B" + k + "y>\n";
        s += "mass B" + k + " = mL; inertia B" + k + " = IL, IL/10, IL\n";
        s += "torque T" + k + " on B" + k + " from " + p + " = T" + k + "*B" + k + axis + ">\n";
        ts += (i > 1 ? ", T" : "T") + k;
    }
    return s + "gravity -g*Ny>\nkane K for " + q + "\nroadmap E for " + ts + "\n";
}

// "name = rhs" and "K[i]: 0 = rhs" lines of a transcript or file, in order: each one's value
// at a point given by the names' spelling, intermediates from the lines before them
std::map<std::string, double> values_of_lines(const std::string& text) {
    std::map<std::string, double> at;
    GiNaC::symtab names;
    std::istringstream in(text);
    std::string line;
    // the label and " = " only, the right-hand side is what follows (see above)
    static const std::regex labelled(R"(^([A-Za-z_][A-Za-z0-9_']*(\[[0-9]+\])?)(: 0)? = )");
    while (std::getline(in, line)) {
        std::smatch m;
        if (line.rfind("> ", 0) == 0 ||
            !std::regex_search(line, m, labelled, std::regex_constants::match_continuous))
            continue;
        std::string rhs = std::regex_replace(m.suffix().str(), std::regex("'"), "_d");
        GiNaC::parser reader(names);
        GiNaC::ex e;
        try {
            e = reader(rhs);
        } catch (const std::exception&) {
            continue;  // not an equation (a table row, a message)
        }
        names = reader.get_syms();
        GiNaC::exmap values;
        for (const auto& [name, sym] : names) {
            if (!at.count(name)) at[name] = 0.2 + 0.07 * static_cast<double>(std::hash<std::string>{}(name) % 17);
            values[sym] = at[name];
        }
        const std::string lhs = std::regex_replace(m[1].str(), std::regex("'"), "_d");
        at[lhs] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
    }
    return at;
}

}  // namespace

TEST(Readable, EquationsPastThePrintLimitGoToAFileAbbreviatedAndMeanWhatIsPrintedWhole) {
    const fs::path dir = fs::temp_directory_path() / ("alembert_print_limit_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string script = spatial_chain(4);
    Session whole;
    whole.interp.set_output_dir(dir.string());
    const std::string printed = whole.run(script);
    Session cut;
    cut.interp.set_output_dir(dir.string());
    cut.interp.set_print_limit(50);
    const std::string summary = cut.run(script);
    // the transcript says what and where, and holds no equation
    EXPECT_NE(summary.find("K: 4 equations in q1'', q2'', q3'', q4''"), std::string::npos) << summary;
    EXPECT_NE(summary.find("written to K.txt"), std::string::npos) << summary;
    EXPECT_NE(summary.find("written to E.txt"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("K[1]: 0 ="), std::string::npos) << summary;
    EXPECT_LT(summary.size(), printed.size() / 4);
    for (const char* name : {"K", "E"}) {
        const std::string file = read(dir / (std::string(name) + ".txt"));
        for (const std::string& bad : undefined_intermediates(file)) ADD_FAILURE() << name << ": " << bad;
        std::istringstream in(file);
        std::string line;
        while (std::getline(in, line)) EXPECT_LE(line.size(), 130u) << line;
        // the file's equations have the values of the ones printed whole
        const auto a = values_of_lines(printed), b = values_of_lines(file);
        for (int i = 1; i <= 4; ++i) {
            const std::string label = name == std::string("K") ? "K[" + std::to_string(i) + "]" : "E_T" + std::to_string(i);
            ASSERT_TRUE(a.count(label) && b.count(label)) << label;
            EXPECT_NEAR(a.at(label), b.at(label), 1e-9 * std::max(1.0, std::abs(a.at(label)))) << label;
        }
    }
    fs::remove_all(dir);
}
