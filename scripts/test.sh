#!/usr/bin/env bash
# CI entry point: dependencies, warnings-as-errors build + tests, then a sanitizer pass that
# with clang also fuzzes the language for ALEMBERT_FUZZ_SECONDS (set ALEMBERT_CI_SANITIZE=0 to
# skip the pass, ALEMBERT_CI_FUZZ=0 to skip the fuzzing).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh

cmake --preset ci
cmake --build --preset ci -j2
ctest --preset ci

# clang with libFuzzer (Debian: clang, libclang-rt-14-dev) links a fuzz target?
have_libfuzzer() {
  command -v clang++ >/dev/null || return 1
  local dir
  dir=$(mktemp -d)
  printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' >"$dir/f.cpp"
  local ok=0
  clang++ -fsanitize=fuzzer,address "$dir/f.cpp" -o "$dir/f" >/dev/null 2>&1 || ok=1
  rm -rf "$dir"
  return "$ok"
}

if [[ ${ALEMBERT_CI_SANITIZE:-1} == 1 ]]; then
  # with clang, the sanitizer pass also builds the fuzz target on the same instrumented
  # libraries, and its tests include the bounded fuzz run (docs/fuzzing.md)
  preset=asan
  if [[ ${ALEMBERT_CI_FUZZ:-1} == 1 ]]; then
    if have_libfuzzer; then
      preset=asan-fuzz
    else
      echo "test.sh: clang with libFuzzer not found (Debian: clang libclang-rt-14-dev); the bounded fuzz run is skipped"
    fi
  fi
  cmake --preset "$preset"
  cmake --build --preset "$preset" -j2
  ctest --preset "$preset"
fi
