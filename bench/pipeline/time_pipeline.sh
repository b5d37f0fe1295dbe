#!/usr/bin/env bash
# End-to-end times of the script path: each study (the sit-to-stand model and the KUKA arm, a
# simulation and an inverse dynamics each, and the arm's motor torques alone) run N times by ALEMBERT in a fresh directory, once as
# written (compiled C code, the default where a C compiler is found: the directory's own cache of
# compiled code is empty, so the first run compiles and the others load) and once with `--tape`
# (the interpreted tape, no compiler), printing the least wall-clock and the least CPU time
# (user + system, children included: the C compiler, gnuplot) over the runs, and the first
# run's alone.
# Usage: time_pipeline.sh ALEMBERT [N]
set -euo pipefail
alembert=$(realpath "$1")
runs=${2:-7}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/cache"
cp "$here"/*.alb "$tmp"/
for study in sit_to_stand_simulate sit_to_stand_inverse kuka_iiwa_simulate kuka_iiwa_inverse kuka_iiwa_torques; do
    for how in tape compiled; do
      flags=()
      [[ $how == tape ]] && flags=(--tape)
      best_wall=999 best_cpu=999 first=""
      for ((i = 1; i <= runs; i++)); do
        out=$( cd "$tmp" && TMPDIR=$tmp/cache /usr/bin/time -f "%e %U %S" "$alembert" run "$study.alb" "${flags[@]}" --out "$tmp/out" 2>&1 >/dev/null | tail -1 )
        read -r wall user sys <<<"$out"
        cpu=$(echo "$user + $sys" | bc)
        [[ -z $first ]] && first=$wall
        best_wall=$(echo "if ($wall < $best_wall) $wall else $best_wall" | bc)
        best_cpu=$(echo "if ($cpu < $best_cpu) $cpu else $best_cpu" | bc)
      done
      printf '%-32s first run %6.2f s   least wall %6.2f s   least CPU %6.2f s\n' "$study ($how)" "$first" "$best_wall" "$best_cpu"
    done
done
