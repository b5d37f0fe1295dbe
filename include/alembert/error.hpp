// SPDX-License-Identifier: MIT
// Exceptions thrown by Alembert, named for whose fault the failure is.
#pragma once

#include <version>
#if defined(__cpp_lib_source_location)
#include <source_location>
#endif
#include <stdexcept>
#include <string>

namespace alembert {

/// Stable error codes; the command-line tool maps them to exit statuses.
enum class ErrorCode {
    argument = 1,         ///< the caller passed something malformed
    model = 2,            ///< the model is incomplete or inconsistent
    solve = 3,            ///< a numeric or symbolic solve failed
    not_implemented = 4,  ///< a feature Alembert does not offer (yet)
    internal = 5,         ///< a broken invariant of Alembert itself
};

/// Base of every exception Alembert throws on purpose.
class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message)
        : std::runtime_error(message), code_(code) {}
    /// The stable code of this error.
    ErrorCode code() const noexcept { return code_; }

private:
    ErrorCode code_;
};

/// The caller passed something malformed (a zero vector to normalise, a bad sequence name).
class ArgumentError : public Error {
public:
    explicit ArgumentError(const std::string& message) : Error(ErrorCode::argument, message) {}
};

/// The model is incomplete or inconsistent (no path between frames, mass never set,
/// duplicate name, rotation cycle).
class ModelError : public Error {
public:
    explicit ModelError(const std::string& message) : Error(ErrorCode::model, message) {}
};

/// A solve failed (singular mass matrix, no convergence, nonlinear where linear is needed).
class SolveError : public Error {
public:
    explicit SolveError(const std::string& message) : Error(ErrorCode::solve, message) {}
};

/// A feature that Alembert does not offer.
class NotImplemented : public Error {
public:
    explicit NotImplemented(const std::string& message)
        : Error(ErrorCode::not_implemented, message) {}
};

/// A broken internal invariant: a bug in Alembert, never the user's fault.
class InternalError : public Error {
public:
    explicit InternalError(const std::string& message) : Error(ErrorCode::internal, message) {}
};

namespace detail {
#if defined(__cpp_lib_source_location)
using SourceLocation = std::source_location;
#else
/// Stand-in where the standard library has no std::source_location (Debian 12's clang 14 with
/// libstdc++ 12, used to build the fuzz targets): internal errors then name no place.
struct SourceLocation {
    static constexpr SourceLocation current() noexcept { return {}; }
    constexpr const char* file_name() const noexcept { return "(unknown file)"; }
    constexpr const char* function_name() const noexcept { return "(unknown function)"; }
    constexpr unsigned line() const noexcept { return 0; }
};
#endif
[[noreturn]] void throw_internal(const char* condition, SourceLocation where);
}  // namespace detail

}  // namespace alembert

/// Throws alembert::ArgumentError with `message` unless `cond` holds.
#define ALEMBERT_CHECK_ARG(cond, message)                  \
    do {                                                    \
        if (!(cond)) throw ::alembert::ArgumentError(message); \
    } while (false)

/// Checks an internal invariant in every build; a failure is a bug in Alembert.
#define ALEMBERT_ASSERT(cond)                                                              \
    do {                                                                                   \
        if (!(cond))                                                                       \
            ::alembert::detail::throw_internal(#cond, ::alembert::detail::SourceLocation::current());    \
    } while (false)
