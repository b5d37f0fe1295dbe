// SPDX-License-Identifier: MIT
// The emitter base: turns a CodePlan into the files of one target language.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "alembert/codegen/code_plan.hpp"
#include "alembert/codegen/code_printer.hpp"

namespace alembert {

/// A file an emitter produces: its name (no directory) and its text.
struct GeneratedFile {
    std::string name;
    std::string text;
};

/// Turns a CodePlan into source files of one language. The base holds what every language
/// shares: identifiers for the model's names, the header every file opens with, the inputs a
/// program reads, and the spelling of a function's values; each language prints its own
/// declarations around the programs its printer prints.
class Emitter {
public:
    virtual ~Emitter() = default;
    /// The language emitted.
    virtual Language language() const = 0;
    /// The printer of the language's statements.
    virtual const CodePrinter& printer() const = 0;
    /// The files for `plan`, in the order they are written.
    virtual std::vector<GeneratedFile> emit(const CodePlan& plan) const = 0;

protected:
    /// Identifiers in the language for every name of the plan (raw name -> identifier):
    /// coordinates, rates (qA' -> qAp), loads, parameters and outputs, unique and clear of
    /// the language's reserved words. Time is "t".
    std::map<std::string, std::string> identifiers(const CodePlan& plan) const;
    /// The opening lines of every file (without comment markers): what the file is, the
    /// generator and its version, the source, "generated - do not edit", operation counts.
    std::vector<std::string> header(const CodePlan& plan, const std::string& what) const;
    /// For each input of `f`'s program, whether the prelude, the body or an output reads it.
    static std::vector<bool> inputs_read(const StraightLineProgram& p);
    /// For each parameter of `f`'s program, whether `code` (or the outputs, with `outputs`)
    /// reads it.
    static std::vector<bool> parameters_read(const StraightLineProgram& p,
                                             const std::vector<ProgramInstruction>& code,
                                             bool outputs);
    /// The spelling of f's values: inputs and parameters by their identifiers, hoisted values
    /// by `hoisted`.
    ValueSpelling spelling(const CodeFunction& f, const std::map<std::string, std::string>& id,
                           std::function<std::string(std::size_t)> hoisted) const;
    /// "name [unit]", or the name alone without a unit.
    static std::string with_unit(const std::string& name, const std::string& unit);
};

/// The emitter of `language`.
std::unique_ptr<Emitter> make_emitter(Language language);

}  // namespace alembert
