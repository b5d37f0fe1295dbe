#!/usr/bin/env bash
# The alembert command end to end: exit statuses (0 success, 1 script error, 2 usage error),
# standard input, the road-map command and the interactive session going on after an error.
# Usage: cli_test.sh ALEMBERT SOURCE_DIR
set -uo pipefail
alembert=$1
root=$2
fails=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

expect() {  # expect NAME STATUS COMMAND...: runs COMMAND, checks its exit status
  local name=$1 want=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [[ $got != "$want" ]]; then
    echo "FAIL $name: exit $got, expected $want"; cat "$tmp/out" "$tmp/err"; fails=$((fails + 1))
  fi
}
contains() {  # contains NAME FILE TEXT
  if ! grep -qF -- "$3" "$2"; then
    echo "FAIL $1: '$3' not in:"; cat "$2"; fails=$((fails + 1))
  fi
}

expect version 0 "$alembert" --version
contains version "$tmp/out" "alembert 0."
expect help 0 "$alembert" --help
contains help "$tmp/out" "roadmap"
expect bad_option 2 "$alembert" --frobnicate
expect run_without_file 2 "$alembert" run
expect missing_file 2 "$alembert" run "$tmp/none.alb"
contains missing_file "$tmp/err" "cannot open"
expect directory 2 "$alembert" run "$tmp"

printf 'newtonian N\nvariable q'"''"'\nz = 2*q\nz = undefined\nw = 3\n' >"$tmp/bad.alb"
expect script_error 1 "$alembert" run "$tmp/bad.alb"
contains script_error "$tmp/err" "bad.alb:4:5: error: 'undefined' is not declared"
contains script_error "$tmp/out" "z = 2*q"
if grep -q "w = 3" "$tmp/out"; then echo "FAIL script_error: the run went on after the error"; fails=$((fails + 1)); fi

expect stdin 0 bash -c "printf 'newtonian N\nz = 1 + 1\n' | '$alembert' run -"
contains stdin "$tmp/out" "> z = 1 + 1"
expect quiet 0 bash -c "printf 'newtonian N\nz = 1 + 1\n' | '$alembert' run --quiet -"
if grep -q "^> " "$tmp/out"; then echo "FAIL quiet: statements echoed"; fails=$((fails + 1)); fi

# the interactive session reports an error and goes on; a bracket continues the statement
expect session 0 bash -c "printf 'newtonian N\nz = nope\nZ = [1,\n 2]\nw = 5\n' | '$alembert'"
contains session "$tmp/err" "<stdin>:2:5: error: 'nope' is not declared"
contains session "$tmp/out" "Z[2]: 0 = 2"
contains session "$tmp/out" "w = 5"

expect roadmap 0 "$alembert" roadmap "$root/examples/sit_to_stand/model.alb"
contains roadmap "$tmp/out" "| T_A      | rotate           | Nz>       | {A, B, C} |"
expect roadmap_json 0 "$alembert" roadmap --json "$root/examples/sit_to_stand/model.alb"
contains roadmap_json "$tmp/out" '"system": ["B", "C"], '
expect roadmap_error 1 "$alembert" roadmap "$tmp/bad.alb"

(( fails == 0 )) && echo "cli_test: OK"
exit $(( fails > 0 ))
