// SPDX-License-Identifier: MIT
// generate_code: plan the programs once, print them in one language, write the files.
#include <algorithm>
#include <cctype>

#include "alembert/codegen/codegen.hpp"
#include "alembert/codegen/code_plan.hpp"
#include "alembert/codegen/emitter.hpp"
#include "alembert/error.hpp"
#include "file_writer.hpp"

#ifndef ALEMBERT_VERSION
#define ALEMBERT_VERSION "unknown"
#endif

namespace alembert {

const char* to_string(Language language) {
    switch (language) {
        case Language::c: return "c";
        case Language::cpp: return "cpp";
        case Language::matlab: return "matlab";
        case Language::python: return "python";
    }
    return "?";
}

Language parse_language(std::string_view word) {
    std::string w(word);
    std::transform(w.begin(), w.end(), w.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (w == "c" || w == "c99") return Language::c;
    if (w == "cpp" || w == "c++" || w == "cxx") return Language::cpp;
    if (w == "matlab" || w == "octave" || w == "m") return Language::matlab;
    if (w == "python" || w == "py") return Language::python;
    throw ArgumentError("parse_language(): unknown language '" + std::string(word) +
                        "'; use c, cpp, matlab or python");
}

const char* generator_version() { return ALEMBERT_VERSION; }

namespace {

// the files of `plan` in `language` written to out_dir, and what the functions cost
GeneratedCode write_code(const CodePlan& plan, Language language,
                         const std::filesystem::path& out_dir) {
    std::vector<GeneratedFile> files = make_emitter(language)->emit(plan);
    GeneratedCode result;
    for (const GeneratedFile& f : files) {
        std::filesystem::path path = out_dir / f.name;
        detail::write_file_atomically(path, f.text, "generate_code()");
        result.files.push_back(path);
    }
    auto ops = [](const CodeFunction& f) {
        return f.empty() ? std::size_t{0} : f.program.operation_count(f.program.body);
    };
    result.mass_forcing_operations = ops(plan.mass_forcing);
    result.accelerations_operations = ops(plan.accelerations);
    result.mass_matrix_operations = ops(plan.mass_matrix);
    result.bias_forces_operations = ops(plan.bias_forces);
    result.inverse_dynamics_operations = ops(plan.inverse_dynamics);
    result.inverse_dynamics_derivatives_operations = ops(plan.inverse_dynamics_derivatives);
    result.outputs_operations = ops(plan.output_function);
    result.kinematics_operations = ops(plan.kinematics);
    result.dependent_speeds_operations = ops(plan.dependent_speed_function);
    for (const CodeFunction* f : plan.functions())
        result.prelude_operations += f->program.operation_count(f->program.prelude);
    result.symmetric_mass_matrix = plan.symmetric_mass_matrix;
    result.inverse_dynamics = !plan.inverse_dynamics.empty();
    result.constraint_count = plan.constraint_count();
    return result;
}

}  // namespace

GeneratedCode generate_code(const SymbolTable& table, const DynamicsEquations& equations,
                            Language language, const std::filesystem::path& out_dir,
                            const CodegenOptions& options) {
    // the directory first: a bad path fails before any work
    if (!equations.constraints.empty() && language == Language::matlab)
        throw ArgumentError(std::string("generate_code(): code for models with constraints is "
                                        "generated in C, C++ and Python only, not in ") +
                            to_string(language) + "; choose the language c, cpp or python");
    detail::ensure_directory(out_dir, "generate_code()");
    return write_code(plan_code(table, equations, options), language, out_dir);
}

GeneratedCode generate_code(const SymbolTable& table, const KaneEquations& kane,
                            const std::vector<ex>& loads, Language language,
                            const std::filesystem::path& out_dir, const CodegenOptions& options) {
    if (language == Language::matlab)
        throw ArgumentError(std::string("generate_code(): code for equations in generalized "
                                        "speeds is generated in C, C++ and Python only, not in ") +
                            to_string(language) + "; choose the language c, cpp or python");
    detail::ensure_directory(out_dir, "generate_code()");
    return write_code(plan_speed_code(table, kane, loads, options), language, out_dir);
}

}  // namespace alembert
