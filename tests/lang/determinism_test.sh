#!/usr/bin/env bash
# Same input, same output: the sit-to-stand script, a falling triple pendulum and a spatial
# three-link chain, each run five times with address-space randomisation on, write
# byte-identical transcripts, CSVs, plots and generated code. `simulate` and `inverse` evaluate
# compiled C code by default: the first run compiles it into an empty cache, the later ones load
# it, and what they write is the same byte for byte (the choice never depends on the cache).
# Usage: determinism_test.sh ALEMBERT SOURCE_DIR
set -uo pipefail
alembert=$1
root=$2
runs=5
fails=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# the check means something only where addresses move from run to run
if [[ $(cat /proc/sys/kernel/randomize_va_space 2>/dev/null || echo 0) == 0 ]] ||
   (( 0x$(cat /proc/self/personality 2>/dev/null || echo 0) & 0x0040000 )); then
  echo "address-space randomisation is off here (setarch -R or randomize_va_space=0): skipped"
  exit 77
fi

# run_five NAME DIR SCRIPT: five runs into $tmp/NAME/1..5, each with its own transcript
run_five() {
  local name=$1 dir=$2 script=$3 i
  for ((i = 1; i <= runs; i++)); do
    local out=$tmp/$name/$i
    mkdir -p "$out"
    (cd "$dir" && TMPDIR=$tmp/cache "$alembert" run "$script" --out "$out" >"$out/transcript.txt" 2>&1)
    local rc=$?
    if [[ $rc != 0 ]]; then
      echo "FAIL $name: run $i exited $rc"; tail -5 "$out/transcript.txt"; fails=$((fails + 1))
    fi
    (cd "$tmp/cache" && find . -type f -printf '%p %s %T@\n' | sort) >"$tmp/cache_${name}_$i"
  done
  local n_files
  n_files=$(find "$tmp/$name/1" -type f | wc -l)
  if (( n_files < 2 )); then
    echo "FAIL $name: the run wrote only $n_files file(s)"; fails=$((fails + 1))
  fi
  for ((i = 2; i <= runs; i++)); do
    if ! diff -r "$tmp/$name/1" "$tmp/$name/$i" >"$tmp/diff" 2>&1; then
      echo "FAIL $name: run $i differs from run 1:"; head -20 "$tmp/diff"; fails=$((fails + 1))
    fi
  done
  echo "$name: $runs runs, $n_files files each, compared byte for byte"
}

mkdir -p "$tmp/cache"
run_five sit_to_stand "$root/examples/sit_to_stand" model.alb
run_five triple_pendulum_fall "$root/examples/triple_pendulum_fall" model.alb
run_five spatial_chain "$root/tests/lang/determinism" spatial_chain.alb

# the compiled code is built once: later runs load the same libraries. sit_to_stand and
# triple_pendulum_fall say nothing of how they evaluate (compiled by default), spatial_chain says
# `simulate compiled`.
before=/dev/null
for name in sit_to_stand triple_pendulum_fall spatial_chain; do
  libs=$(comm -13 <(grep '\.so ' "$before" | sort) <(grep '\.so ' "$tmp/cache_${name}_1" | sort) | wc -l)
  if (( libs == 0 )); then
    echo "FAIL compiled cache: the first run of $name compiled no library"; fails=$((fails + 1))
  fi
  for ((i = 2; i <= runs; i++)); do
    if ! diff "$tmp/cache_${name}_1" "$tmp/cache_${name}_$i" >"$tmp/diff"; then
      echo "FAIL compiled cache: run $i of $name compiled again:"; cat "$tmp/diff"; fails=$((fails + 1))
    fi
  done
  (( fails == 0 )) && echo "compiled cache: $name compiled $libs libraries in run 1, none in runs 2-$runs"
  before=$tmp/cache_${name}_1
done

exit $((fails > 0))
