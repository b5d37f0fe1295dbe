#!/usr/bin/env bash
# Fails if a lower layer includes a header of a higher (or same-level sibling) layer.
# Order: sym < vec < mech < eom < {sim, codegen, report} < biomech < lang < apps
# (report may also include sim).
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A level=([sym]=0 [vec]=1 [mech]=2 [eom]=3 [sim]=4 [codegen]=4 [report]=4 [biomech]=5 [lang]=6 [apps]=7)

allowed() {  # allowed <from> <to>
  local from=$1 to=$2
  [[ -z ${level[$to]+x} ]] && return 0          # not a layer directory
  [[ $from == "$to" ]] && return 0
  [[ $from == report && $to == sim ]] && return 0
  (( level[$to] < level[$from] ))
}

status=0
for layer in "${!level[@]}"; do
  for dir in "include/alembert/$layer" "src/$layer"; do
    [[ -d $dir ]] || continue
    while IFS= read -r hit; do
      to=$(sed -E 's/.*#[[:space:]]*include[[:space:]]*[<"]alembert\/([A-Za-z0-9_]+)\/.*/\1/' <<<"${hit#*:*:}")
      if ! allowed "$layer" "$to"; then
        echo "layer violation ($layer -> $to): $hit"
        status=1
      fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]alembert/[A-Za-z0-9_]+/' "$dir" || true)
  done
done

(( status == 0 )) && echo "check_layers: OK"
exit $status
