// SPDX-License-Identifier: MIT
// Library messages in the script's words: C++ calls and option names become statements.
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

struct Rewrite {
    std::regex pattern;
    std::string replacement;
};

// the library's advice names the API call; a script writes the statement that makes it
const std::vector<Rewrite>& script_rewrites() {
    static const std::vector<Rewrite> rewrites = [] {
        const std::vector<std::pair<const char*, const char*>> rules = {
            // mech: what to give a body or point
            {R"re(call (\w+)\.set_inertia\(\.\.\.\) first)re", "give it: inertia $1 = Ixx, Iyy, Izz"},
            {R"re(call (\w+)\.set_mass\(\.\.\.\) first)re", "give its mass first: mass $1 = ..."},
            {R"re(call (\w+)\.set_vel\((\w+), \.\.\.\) or locate \1 from a point whose velocity in \2 is known)re",
             "locate $1 from a point whose velocity in $2 is known (translate $1 from $2_o by ...), or give "
             "its velocity: velocity $1 in $2 = ..."},
            {R"re(call (\w+)\.set_acc\((\w+), \.\.\.\))re", "write acceleration $1 in $2 = ..."},
            // sym: a constant without a value (the intermediate it sits in is ours, not the script's)
            {R"re(the constant '([^']+)' \(in [^)]*\) has no value)re", "the constant '$1' has no value"},
            {R"re(the constant '([^']+)' has no value; give it (?:a value|one) with SymbolTable::set_value\(\)(?: or list it as an input)?)re",
             "the constant '$1' has no value; give it one where it is declared (constant $1 = ...)"},
            {R"re((\(constant \w+ = \.\.\.\)); forward dynamics may depend on t, the coordinates, their rates and the inputs: list a load measure among the inputs, or give a constant a value)re",
             "$1"},
            {R"re((\(constant \w+ = \.\.\.\)); inverse dynamics may depend on t and the coordinates with their first and second derivatives: give a constant a value, or make a load measure one of the unknowns)re",
             "$1"},
            {R"re(list a load measure among the inputs)re", "give a load measure as an input (input T = ...)"},
            {R"re(give it a value with SymbolTable::set_value\(\) or list it as an input)re",
             "give it a value where it is declared (constant name = ...)"},
            {R"re(declare it with add_constant\(\))re", "declare it with constant"},
            {R"re(\(add_variable\("u1", 1\)\))re", "(variable u1')"},
            {R"re(declare it with SymbolTable::add_variable\(name, 1\) or pass a coordinate's rate q')re",
             "declare it with a prime (variable u1') or use a coordinate's rate q'"},
            {R"re(\(Point::set_vel\))re", "(velocity P in N = ...)"},
            {R"re(\(Frame::set_ang_vel\))re", "(angvel B in N = ...)"},
            {R"re(form it with form_constraint_row\(\))re", "form it with: row E for x constraint name"},
            {R"re(\bSymbolTable: )re", ""},
            {R"re(the position of '(\w+)' from '(\w+)' is not defined; locate one from the other \(set_pos\), directly or through other points)re",
             "the position of '$1' from '$2' is not defined; locate one from the other, directly or through other "
             "points (translate $1 from $2 by ...)"},
            {R"re(orient one relative to the other or to a common frame)re",
             "orient one relative to the other or to a common frame (rotate ... from ...)"},
            {R"re( and 0 dependent speeds \(\); name one dependent speed per constraint)re",
             " and no dependent speeds; name one dependent speed per constraint (... constraints [...] dependent u2)"},
            {R"re(; name one dependent speed per constraint$)re",
             "; name one dependent speed per constraint (... constraints [...] dependent u2)"},
            {R"re('([^']+)' has no value; give it one \(constants: set_value\))re",
             "'$1' has no value; give it one after 'at', or, for a constant, where it is declared (constant $1 = ...)"},
            {R"re(orient '(\w+)' first)re", "orient '$1' first (rotate $1 from ... before this statement)"},
            {R"re(orient it relative to another frame first)re", "orient it first (rotate ... from ...)"},
            {R"re(weigh every state in Q or choose other inputs)re",
             "give every state a weight above 0 (lqr q1, ..., qn and r1, ...) or choose other inputs"},
            {R"re(\); use a nonlinear solve)re", "); solve it from a guess (solve E for x guess x = ...)"},
            {R"re(joint reactions \(System::add_joint_reaction, the reaction statement\))re",
             "joint reactions (reaction pin between A and B at P force R along u)"},
            {R"re(\b1 coordinates\b)re", "1 coordinate"},
            {R"re(fill it in the capture software, raise the largest gap, or trim the trial)re",
             "fill it in the capture software, or trim the trial (a script fills gaps of up to 0.1 s)"},
            // sim: options a statement sets
            {R"re(\(SimulationOptions::max_output_rows; in a script, ([^)]*)\))re", "(raise it with: $1)"},
            {R"re( \(\w+Options::\w+\))re", ""},
            {R"re(\(SymbolicSolveOptions::max_terms, `solve \.\.\. limit N`\))re", "(solve ... limit N)"},
            {R"re(SimulationOptions::abs_tol)re", "tolerance abs"},
            {R"re(SimulationOptions::rel_tol)re", "tolerance rel"},
            {R"re(SimulationOptions::t_final)re", "final time"},
            {R"re(SimulationOptions::output_step)re", "output step"},
            {R"re(SymbolicSolveOptions::max_terms)re", "solve ... limit N"},
            // the API's solvers by their statements
            {R"re(solve numerically at given values \(solve_numeric, `solve \.\.\. at`\))re",
             "solve numerically at given values (solve ... at)"},
            {R"re(\(solve_numeric\))re", "(solve ... at)"},
            // a C++ function or class naming itself before the message: "Frame::orient_axis(): ",
            // "run_simulation('model'): ", "matrix::solve(): "
            {R"re((?:\b[A-Za-z_]\w*::)*\b[A-Za-z_]\w*\((?:'[^']*')?\): )re", ""},
            {R"re(\bCompiledExpressions: )re", ""},
        };
        std::vector<Rewrite> out;
        for (const auto& [pattern, replacement] : rules) out.push_back({std::regex(pattern), replacement});
        return out;
    }();
    return rewrites;
}

}  // namespace

std::string in_script_words(const std::string& library_message) {
    // the words to rewrite open a message; a long one (a printed expression) keeps its tail
    // as it is, which also keeps std::regex's recursive matcher off long inputs
    constexpr std::size_t kHead = 4000;
    if (library_message.size() > kHead)
        return in_script_words(library_message.substr(0, kHead)) + library_message.substr(kHead);
    std::string s = library_message;
    // a derivative to declare: as many primes as its order, "variable w''"
    static const std::regex add_variable(
        R"re(declare it with SymbolTable::add_variable\("(\w+)", (\d)\) or a higher order)re");
    for (std::smatch m; std::regex_search(s, m, add_variable);) {
        const int primes = std::stoi(m[2].str());
        s = m.prefix().str() + "declare it with " + (primes == 1 ? "a prime" : m[2].str() + " primes") +
            ": variable " + m[1].str() + std::string(static_cast<std::size_t>(primes), '\'') + m.suffix().str();
    }
    for (const Rewrite& r : script_rewrites()) s = std::regex_replace(s, r.pattern, r.replacement);
    return s;
}

std::string unit_of_dimension_hint(const Dimension& expected) {
    if (!expected.known) return "check the units";
    if (expected.is_none()) return "write it as an angle (rad, deg, rev) or as a plain number";
    if (expected == Dimension::none() / Dimension::time())
        return "write it as a rate: Hz or rpm (cycles), rad/s or deg/s";
    return "write it in " + si_unit(expected) + " or another unit of " + describe(expected);
}

}  // namespace alembert::lang
