#!/usr/bin/env bash
# End-to-end times of the script path: each study (the sit-to-stand model and the KUKA arm, a
# simulation and an inverse dynamics each, with and without `compiled`) run N times by ALEMBERT in a
# fresh directory (its own cache of compiled code, so the first `compiled` run compiles and the
# others load), printing the least wall-clock and the least CPU time (user + system, children
# included: the C compiler, gnuplot) over the runs, and the first run's alone.
# Usage: time_pipeline.sh ALEMBERT [N]
set -euo pipefail
alembert=$(realpath "$1")
runs=${2:-7}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/cache"
cp "$here"/*.alb "$tmp"/
# the same studies with the compiled clause
studies=()
for model in sit_to_stand kuka_iiwa; do
  sed 's/^simulate to/simulate compiled to/' "$tmp/${model}_simulate.alb" >"$tmp/${model}_simulate_compiled.alb"
  sed 's/ to "\([a-z]*\)"$/ compiled to "\1"/' "$tmp/${model}_inverse.alb" >"$tmp/${model}_inverse_compiled.alb"
  studies+=("${model}_simulate" "${model}_simulate_compiled" "${model}_inverse" "${model}_inverse_compiled")
done
for study in "${studies[@]}"; do
  best_wall=999 best_cpu=999 first=""
  for ((i = 1; i <= runs; i++)); do
    out=$( cd "$tmp" && TMPDIR=$tmp/cache /usr/bin/time -f "%e %U %S" "$alembert" run "$study.alb" --out "$tmp/out" 2>&1 >/dev/null | tail -1 )
    read -r wall user sys <<<"$out"
    cpu=$(echo "$user + $sys" | bc)
    [[ -z $first ]] && first=$wall
    best_wall=$(echo "if ($wall < $best_wall) $wall else $best_wall" | bc)
    best_cpu=$(echo "if ($cpu < $best_cpu) $cpu else $best_cpu" | bc)
  done
  printf '%-28s first run %6.2f s   least wall %6.2f s   least CPU %6.2f s\n' "$study" "$first" "$best_wall" "$best_cpu"
done
