// SPDX-License-Identifier: MIT
// The compiled fast path: a tape's program generated as C, compiled by the system compiler,
// loaded, and called; the interpreted tape when that cannot be done.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "alembert/sym/evaluator.hpp"

namespace alembert {

/// How a NativeExpressions evaluates.
enum class NativeStatus {
    compiled,        ///< natively: compiled now
    cached,          ///< natively: a library compiled earlier from the same code was loaded
    no_compiler,     ///< on the tape: no C compiler was found
    compile_failed,  ///< on the tape: the compiler failed (message() has its first lines)
    load_failed,     ///< on the tape: the library could not be loaded
    no_directory,    ///< on the tape: no directory to compile in ($TMPDIR missing, unwritable)
};

/// The word for a status ("compiled", "no_compiler", ...).
const char* to_string(NativeStatus status);

/// How the native code is built.
struct NativeOptions {
    /// The C compiler: a name looked up on PATH or a path. Empty: $CC if set, else "cc".
    std::string compiler = "";
    /// Flags before the source (-shared -fPIC and -lm are always added).
    std::vector<std::string> flags{"-O2"};
    /// Where libraries are cached, by a hash of their source, compiler and flags. Empty: the
    /// directory "alembert-native" in the system's temporary directory.
    std::filesystem::path cache_dir{};
    /// Called with the program's operation count just before the compiler runs (not when the
    /// library is cached), and with `done` once it has finished: for a progress note on a
    /// terminal, since a large program takes seconds to compile.
    std::function<void(std::size_t operations, bool done)> on_compile{};
};

/// A CompiledExpressions made native: its program printed as C (the prelude and the body of
/// CompiledExpressions::calc_program, so common subexpressions, folding and hoisting carry
/// over), compiled by the system C compiler into a shared library (cc -O2 -shared -fPIC),
/// loaded with dlopen and called through `operator()(inputs, outputs)` with the tape's input
/// and output order. Libraries are cached in a temporary directory by a hash of their source,
/// so a second construction from the same expressions only loads. When no compiler is found,
/// compilation fails or loading fails, the object evaluates on the tape instead and says why
/// (status(), message()): results are the same up to rounding either way.
///
/// Copies share the loaded library, which is closed with the last of them. The native call
/// allocates nothing and may run concurrently; the tape fallback uses the tape's scratch
/// buffer (one thread at a time).
class NativeExpressions {
public:
    /// Compiles `tape` natively (see the class comment); never throws for a missing or failing
    /// compiler, which only changes status().
    /// @throws alembert::ArgumentError if the cache directory cannot be created.
    explicit NativeExpressions(CompiledExpressions tape, const NativeOptions& options = {});

    /// True if calls run compiled code, false if they run the tape.
    bool is_native() const { return body_ != nullptr; }
    /// How calls run, and why.
    NativeStatus status() const { return status_; }
    /// What happened: the library loaded, or why the tape is used (naming the compiler and its
    /// first lines of output).
    const std::string& message() const { return message_; }
    /// The tape the object was made from (and falls back to).
    const CompiledExpressions& tape() const { return tape_; }
    /// The generated C source.
    const std::string& source() const { return source_; }

    std::size_t input_count() const { return tape_.input_count(); }
    std::size_t output_count() const { return tape_.output_count(); }

    /// Sets the parameter values (as CompiledExpressions::set_parameters) and runs the prelude.
    /// @throws alembert::ArgumentError if `values` has the wrong size.
    void set_parameters(std::span<const double> values);

    /// The outputs at `inputs` (input_count() values, in the order of tape().inputs()) into
    /// `outputs` (output_count() values).
    void operator()(const double* inputs, double* outputs) const;
    /// As above with the sizes checked.
    /// @throws alembert::ArgumentError if a span has the wrong size.
    void evaluate(std::span<const double> inputs, std::span<double> outputs) const;

private:
    using Prelude = void (*)(double*);
    using Body = void (*)(const double*, const double*, double*);

    CompiledExpressions tape_;
    std::string source_;
    std::shared_ptr<void> library_;
    Prelude prelude_ = nullptr;
    Body body_ = nullptr;
    std::vector<double> fixed_;  // parameter values, then the prelude's results
    NativeStatus status_ = NativeStatus::no_compiler;
    std::string message_;
};

/// The C source NativeExpressions compiles for `tape`: functions
/// `void alembert_prelude(double* fx)` (fx: parameters, then the values computed from them)
/// and `void alembert_body(const double* in, const double* fx, double* out)`.
std::string native_source(const CompiledExpressions& tape);

}  // namespace alembert
