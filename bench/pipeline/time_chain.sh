#!/usr/bin/env bash
# The scaling study of the script path (bench/README.md, "Printing and planning at scale"):
# an n-link spatial chain (bench/pipeline/chain.py) through `kane`, `roadmap` (planning,
# forming and printing the road-map of the n motor torques), `report` and `simulate` (1 s),
# each step a script of its own run by ALEMBERT with --tape, timed by wall clock (least of
# RUNS runs), for each n; then the growth exponent of each step, the slope of log(time)
# against log(n) fitted by least squares over the sizes that took more than 0.05 s.
# A step that passes LIMIT seconds is stopped and its larger sizes skipped.
# Usage: time_chain.sh ALEMBERT [RUNS] [LIMIT] [N...]     (default: 1 run, 900 s, 5 10 20 40 80)
set -euo pipefail
alembert=$(realpath "$1")
runs=${2:-1}
limit=${3:-900}
shift $(( $# < 3 ? $# : 3 ))
sizes=("$@")
(( ${#sizes[@]} )) || sizes=(5 10 20 40 80)
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A t
for step in kane roadmap report simulate; do
  for n in "${sizes[@]}"; do
    if [[ ${t[$step,stopped]:-0} == 1 ]]; then t[$step,$n]="-"; continue; fi
    kind=$step
    [[ $step == report ]] && kind=roadmap
    python3 "$here/chain.py" "$n" "$kind" "$tmp/chain$n.alb"
    best=""
    for ((i = 1; i <= runs; i++)); do
      cmd=(run -q --tape "$tmp/chain$n.alb" --out "$tmp/out")
      [[ $step == report ]] && cmd=(report "$tmp/chain$n.alb" --out "$tmp/report")
      start=$(date +%s.%N)
      if ! timeout "$limit" "$alembert" "${cmd[@]}" >/dev/null 2>"$tmp/err"; then
        echo "$step n=$n: stopped or failed after $limit s: $(head -c 300 "$tmp/err")" >&2
        t[$step,stopped]=1
        best="-"
        break
      fi
      s=$(echo "$(date +%s.%N) - $start" | bc)
      if [[ -z $best ]] || (( $(echo "$s < $best" | bc) )); then best=$s; fi
    done
    t[$step,$n]=$best
  done
done
printf '%-9s' "n"; for n in "${sizes[@]}"; do printf '%10s' "$n"; done; printf '%10s\n' "exponent"
for step in kane roadmap report simulate; do
  printf '%-9s' "$step"
  pts=""
  for n in "${sizes[@]}"; do
    v=${t[$step,$n]}
    if [[ $v == - ]]; then printf '%10s' "-"; else printf '%10.2f' "$v"; pts+="$n $v "; fi
  done
  printf '%10s\n' "$(python3 -c '
import math, sys
v = sys.argv[1].split()
p = [(math.log(float(v[i])), math.log(float(v[i + 1]))) for i in range(0, len(v), 2) if float(v[i + 1]) > 0.05]
if len(p) < 2: print("-"); sys.exit()
mx = sum(x for x, _ in p) / len(p); my = sum(y for _, y in p) / len(p)
print("%.2f" % (sum((x - mx) * (y - my) for x, y in p) / sum((x - mx) ** 2 for x, _ in p)))' "$pts")"
done
