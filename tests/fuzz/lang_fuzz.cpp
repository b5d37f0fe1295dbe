// SPDX-License-Identifier: MIT
// libFuzzer target: any bytes given to the interpreter run or stop with a script error; an
// internal error, a crash, a hang or a sanitizer report is a bug (docs/fuzzing.md).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "alembert/lang/interpreter.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 8192) return 0;  // long inputs test nothing new and slow the search down
    std::string text(reinterpret_cast<const char*>(data), size);
    std::ostringstream out, err;
    alembert::lang::Interpreter interp(out, err, true);
    if (interp.run(text, "fuzz.alb") == alembert::lang::RunStatus::internal_error) __builtin_trap();
    return 0;
}
