// SPDX-License-Identifier: MIT
// Generated code computes in SI units: each parameter's label is the SI unit of the value it is
// given, whatever unit the script declared it in (L = 41.82 cm is 0.4182 labelled m, not cm).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "alembert/lang/interpreter.hpp"

namespace codegen_units_lang_test {

using namespace alembert::lang;
namespace fs = std::filesystem;

// a pendulum whose length is declared in cm and whose angle is a coordinate in degrees' terms
const char* const kScript = R"(newtonian N
body A
constant g = 9.81 m/s^2, L = 41.82 cm, m = 2000 g
variable q''
rotate A from N about z by q
translate Acm from N_o by -L*Ay>
mass A = m
inertia A = 0, 0, 0
gravity -g*Ny>
kane K for q
codegen c name pend to "code"
)";

// the generated defaults: name -> (value, label)
std::map<std::string, std::pair<double, std::string>> parameter_defaults() {
    const fs::path dir = fs::temp_directory_path() / "alembert_codegen_units_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ostringstream out, err;
    Interpreter interp(out, err, false);
    interp.set_output_dir(dir.string());
    EXPECT_EQ(interp.run(kScript, "pend.alb"), RunStatus::ok) << err.str();
    std::ifstream in(dir / "code" / "pend.c");
    std::stringstream text;
    text << in.rdbuf();
    fs::remove_all(dir);
    std::map<std::string, std::pair<double, std::string>> defaults;
    static const std::regex line(R"(p->(\w+) = ([-+0-9.eE]+); /\* \[([^\]]*)\] \*/)");
    const std::string c = text.str();
    for (std::sregex_iterator it(c.begin(), c.end(), line), end; it != end; ++it)
        defaults[(*it)[1]] = {std::stod((*it)[2]), (*it)[3]};
    return defaults;
}

TEST(CodegenUnits, ParametersAreLabelledWithTheSIUnitOfTheirValue) {
    const auto d = parameter_defaults();
    ASSERT_TRUE(d.count("L") && d.count("m") && d.count("g")) << d.size() << " labelled parameters";
    EXPECT_NEAR(d.at("L").first, 0.4182, 1e-15);
    EXPECT_EQ(d.at("L").second, "m");
    EXPECT_NEAR(d.at("m").first, 2.0, 1e-15);
    EXPECT_EQ(d.at("m").second, "kg");
    EXPECT_NEAR(d.at("g").first, 9.81, 1e-15);
    EXPECT_NE(d.at("g").second.find("m"), std::string::npos) << d.at("g").second;
}

}  // namespace codegen_units_lang_test
