// SPDX-License-Identifier: MIT
// libFuzzer target: any bytes given to the interpreter run or stop with a script error; an
// internal error, a crash, a hang or a sanitizer report is a bug (docs/fuzzing.md).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>

#include "alembert/lang/interpreter.hpp"

namespace {

namespace fs = std::filesystem;

// the files scripts write (simulate, inverse, codegen, compiled evaluators) go to one
// temporary directory, emptied after each input and removed when the fuzzer exits (a crash
// or timeout ends it at once and leaves the directory, alembert-fuzz-*, for inspection)
fs::path g_out;

void remove_output_dir() {
    std::error_code ec;
    if (!g_out.empty()) fs::remove_all(g_out, ec);
}

}  // namespace

// ASan's memory of its own, which libFuzzer counts against -rss_limit_mb: a quarantine of
// freed blocks (256 MB by default) and the stack traces of allocations and frees, kept for
// good and growing run after run (docs/fuzzing.md, Memory). A small quarantine and no
// allocation stacks keep a long run flat; replay a crash with ASAN_OPTIONS=malloc_context_size=30
// to see where its memory was allocated and freed (ASAN_OPTIONS overrides these).
extern "C" const char* __asan_default_options() {
    return "quarantine_size_mb=16:malloc_context_size=0:allocator_release_to_os_interval_ms=500";
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string pattern = (fs::temp_directory_path() / "alembert-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) std::abort();
    g_out = pattern;
    std::atexit(remove_output_dir);
    // the compiled evaluators' cache (temp_directory_path()/alembert-native) goes there too
    ::setenv("TMPDIR", pattern.c_str(), 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 8192) return 0;  // long inputs test nothing new and slow the search down
    std::string text(reinterpret_cast<const char*>(data), size);
    std::ostringstream out, err;
    alembert::lang::RunStatus status;
    {
        alembert::lang::Interpreter interp(out, err, true);
        interp.set_output_dir(g_out.string());
        // the tape: a compiler run per input would slow the search a hundredfold (the
        // statements' own `compiled` clause still reaches the compiled path)
        interp.set_evaluation(alembert::lang::Evaluation::tape);
        status = interp.run(text, "fuzz.alb");
    }
    // empty the output directory for the next input
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(g_out, ec)) fs::remove_all(e.path(), ec);
    if (status == alembert::lang::RunStatus::internal_error) __builtin_trap();
    return 0;
}
