#!/usr/bin/env bash
# CI entry point: dependencies, warnings-as-errors build + the whole test suite, then a
# sanitizer pass (ASan/UBSan) that with clang also fuzzes the language for
# ALEMBERT_FUZZ_SECONDS. The sanitizer pass leaves out the tests labelled `external`, whose
# time goes into programs other than Alembert (Chromium, LaTeX, a consumer project's CMake
# build): their Alembert side is run by the first pass, and under ASan they add time, not
# coverage of Alembert's memory; and those labelled `large` (the Whipple bicycle formed,
# generated and run as a script: minutes under ASan), whose code paths the rolling disk and
# the smaller models cover. Set ALEMBERT_CI_SANITIZE=0 to skip the pass,
# ALEMBERT_CI_FUZZ=0 to skip the fuzzing. Ends with a summary of each pass.
set -euo pipefail
cd "$(dirname "$0")/.."

installing=$SECONDS
bash scripts/install_deps.sh test
installed=$((SECONDS - installing))

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
summary=()
failed=0

# the closing counts of a ctest log: "passed failed skipped total"
counts() {
  local log=$1 total=0 failed=0 skipped=0
  local line
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1 || true)
  if [[ -n $line ]]; then
    failed=$(sed -E 's/.* ([0-9]+) tests? failed.*/\1/' <<<"$line")
    total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$line")
  fi
  skipped=$(grep -cE '\(Skipped\)$' "$log" || true)
  echo "$((total - failed - skipped)) $failed $skipped $total"
}

# pass NAME PRESET [ctest args...]: configure, build and test one preset, timed
pass() {
  local name=$1 preset=$2
  shift 2
  local start=$SECONDS rc=0
  # a pass that cannot configure or build is reported as such, and the script goes on to its
  # summary
  if ! cmake --preset "$preset" || ! cmake --build --preset "$preset" -j2; then
    summary+=("$(printf '%-22s could not configure or build (see above); %d s' "$name" $((SECONDS - start)))")
    failed=1
    return 0
  fi
  local built=$((SECONDS - start))
  ctest --preset "$preset" "$@" 2>&1 | tee "$logs/$name.log" || rc=$?
  read -r p f s t < <(counts "$logs/$name.log")
  local why=""
  if (( s > 0 )); then
    why=" ($(grep -E '\(Skipped\)$' "$logs/$name.log" | sed -E 's/^[[:space:]]*[0-9]+ - ([^ ]+).*/\1/' | paste -sd, -))"
  fi
  summary+=("$(printf '%-22s %4d tests: %4d passed, %d failed, %d skipped%s; build %d s, tests %d s' \
    "$name" "$t" "$p" "$f" "$s" "$why" "$built" $((SECONDS - start - built)))")
  (( rc == 0 )) || failed=1
}

pass "first pass (gcc, ci)" ci

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
  # the asan presets run each test program as a few processes (ALEMBERT_TEST_SHARDS), not one
  # per test case: its tests below are those processes
  pass "sanitizer pass ($preset, test programs in shards)" "$preset" -LE 'external|large'
fi

echo
echo "test.sh summary"
echo "  installing what was missing: $installed s"
for line in "${summary[@]}"; do echo "  $line"; done
echo "  total time $((SECONDS / 60)) min $((SECONDS % 60)) s"
exit "$failed"
