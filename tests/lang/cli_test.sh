#!/usr/bin/env bash
# The alembert command end to end: exit statuses (0 success, 1 script error, 2 usage error),
# standard input, the road-map command and the interactive session (going on after an error,
# its exit status, help, quit and exit).
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
printf 'newtonian N\nconstant a = 2\nevaluate sqrt(a)\n' >"$tmp/digits.alb"
expect digits 0 "$alembert" run --digits 12 "$tmp/digits.alb"
contains digits "$tmp/out" "= 1.41421356237"
expect digits_range 2 "$alembert" run --digits 18 "$tmp/digits.alb"
contains digits_range "$tmp/err" "--digits"
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

# the interactive session reports an error and goes on; a bracket continues the statement;
# piped input that had an error ends with status 1
expect session 1 bash -c "printf 'newtonian N\nz = nope\nZ = [1,\n 2]\nw = 5\n' | '$alembert'"
contains session "$tmp/err" "<stdin>:2:5: error: 'nope' is not declared"
contains session "$tmp/out" "Z[2]: 0 = 2"
contains session "$tmp/out" "w = 5"
expect session_ok 0 bash -c "printf 'newtonian N\nw = 5\n' | '$alembert'"
contains session_ok "$tmp/out" "w = 5"

# quit and exit end the session (status 0 when nothing failed); later lines do not run
for word in quit exit; do
  expect "session_$word" 0 bash -c "printf 'newtonian N\nw = 5\n$word\nv = 6\n' | '$alembert'"
  contains "session_$word" "$tmp/out" "w = 5"
  if grep -q "v = 6" "$tmp/out"; then echo "FAIL session_$word: ran past '$word'"; fails=$((fails + 1)); fi
done
expect session_quit_after_error 1 bash -c "printf 'newtonian N\nz = nope\nquit\n' | '$alembert'"

# help lists every statement of docs/language.md's tables; help WORD shows its forms
expect session_help 0 bash -c "printf 'help\nhelp rotate\nhelp nope\n' | '$alembert'"
keywords=$(sed -n '/<!-- statements:/,/<!-- end of statements -->/s/^| `\([a-z]*\)[` ].*/\1/p' "$root/docs/language.md" | sort -u)
[[ $(wc -w <<<"$keywords") -ge 44 ]] || { echo "FAIL session_help: statements not found in docs/language.md"; fails=$((fails + 1)); }
for k in $keywords; do
  grep -qE "^  $k +[^ ]" "$tmp/out" || { echo "FAIL session_help: '$k' not listed by help"; fails=$((fails + 1)); }
done
contains session_help "$tmp/out" "  rotate B from A about [-]axis by angle"
contains session_help "$tmp/out" "      e.g. rotate B from A about z by qB"
contains session_help "$tmp/out" "'nope' is not a statement; type help for the list of statements"

expect roadmap 0 "$alembert" roadmap "$root/examples/sit_to_stand/model.alb"
contains roadmap "$tmp/out" "| T_A      | rotate           | Nz>       | {A, B, C} |"
expect roadmap_json 0 "$alembert" roadmap --json "$root/examples/sit_to_stand/model.alb"
contains roadmap_json "$tmp/out" '"system": ["B", "C"], '
expect roadmap_error 1 "$alembert" roadmap "$tmp/bad.alb"

# alembert inverse: the sit-to-stand model over the shipped motion table agrees with the
# example's torques (the same model and data; the last printed digit may differ); the model's
# joint reactions are unknowns too, so the file holds torques and forces (loads.csv)
model="$root/examples/sit_to_stand/model.alb"
motion="$root/examples/sit_to_stand_inverse/motion.csv"
expect inverse 0 "$alembert" inverse "$model" --motion "$motion" --out "$tmp/inv"
contains inverse "$tmp/inv/loads.csv" "t [s],T_A [N*m],T_B [N*m],T_C [N*m],F_Ac [N],F_As [N],F_Kc [N],F_Ks [N],F_Hc [N],F_Hs [N]"
contains inverse "$tmp/out" "inverse dynamics over the motion table motion.csv, t = 0 to 1.5 s: 151 samples"
if grep -q "^E_T_A\|^> " "$tmp/out"; then echo "FAIL inverse: the model's own transcript printed"; fails=$((fails + 1)); fi
if ! paste -d, <(tail -n +2 "$tmp/inv/loads.csv") <(tail -n +2 "$root/examples/sit_to_stand_inverse/torques.csv") |
     awk -F, '{ for (i = 1; i <= 4; ++i) { d = $i - $(i + 10); if (d < 0) d = -d; if (d > 1e-9) bad = 1 } } END { exit bad }'; then
  echo "FAIL inverse: torques differ from examples/sit_to_stand_inverse/torques.csv"; fails=$((fails + 1))
fi
expect inverse_missing_motion 2 "$alembert" inverse "$model" --motion "$tmp/none.csv" --out "$tmp/inv2"
contains inverse_missing_motion "$tmp/err" "is not a file"
expect inverse_negative_cutoff 2 "$alembert" inverse "$model" --motion "$motion" --out "$tmp/inv3" --cutoff -1
expect inverse_without_out 2 "$alembert" inverse "$model" --motion "$motion"
printf 'newtonian N\nparticle Q\nvariable x'"''"' m\nconstant m = 1 kg\nmass Q = m\ntranslate Q from N_o by x*Nx>\n' >"$tmp/noload.alb"
expect inverse_no_loads 1 "$alembert" inverse "$tmp/noload.alb" --motion "$motion" --out "$tmp/inv4"
contains inverse_no_loads "$tmp/err" "declares no load measures"
# a column without a unit for a coordinate declared in degrees: refused unless --unitless says how
degrees="$root/tests/lang/scripts/inverse_motion_no_unit.alb"
bare="$root/tests/lang/scripts/data/motion_no_unit.csv"
expect inverse_no_unit 1 "$alembert" inverse "$degrees" --motion "$bare" --out "$tmp/inv5"
contains inverse_no_unit "$tmp/err" "column 'q' has no unit, but the coordinate 'q' is declared in deg"
expect inverse_unitless_deg 0 "$alembert" inverse "$degrees" --motion "$bare" --out "$tmp/inv5" --unitless deg
contains inverse_unitless_deg "$tmp/inv5/torques.csv" "t [s],T_A [N*m]"
expect inverse_unitless_length 1 "$alembert" inverse "$degrees" --motion "$bare" --out "$tmp/inv6" --unitless mm
contains inverse_unitless_length "$tmp/err" "column 'q' has no unit"

# alembert codegen
expect codegen 0 "$alembert" codegen "$model" --lang python --out "$tmp/py" --name sts
contains codegen "$tmp/out" "generated Python for 'sts': sts.py"
[[ -f $tmp/py/sts.py ]] || { echo "FAIL codegen: sts.py not written"; fails=$((fails + 1)); }
expect codegen_language 2 "$alembert" codegen "$model" --lang fortran --out "$tmp/f"
expect codegen_name 1 "$alembert" codegen "$model" --lang c --out "$tmp/c" --name 2bad
contains codegen_name "$tmp/err" "'2bad' cannot name generated code"
# a closed loop: the crank torque an input, the pin force solved for (C, C++ and Python)
{ grep -v '^roadmap\|^solve' "$root/examples/four_bar_linkage/model.alb"; echo 'input T = 0'; } >"$tmp/loop.alb"
expect codegen_loop 0 "$alembert" codegen "$tmp/loop.alb" --lang c --out "$tmp/loop"
contains codegen_loop "$tmp/out" "2 constraints: the equations and the constraints solved for the accelerations and 2 constraint forces"
[[ -f $tmp/loop/loop.c ]] || { echo "FAIL codegen_loop: loop.c not written"; fails=$((fails + 1)); }
expect codegen_loop_matlab 1 "$alembert" codegen "$tmp/loop.alb" --lang matlab --out "$tmp/loop_m"
contains codegen_loop_matlab "$tmp/err" "generated in C, C++ and Python only"
# rolling in generalized speeds: the kane statement's equations, state (q, u_r)
expect codegen_rolling 0 "$alembert" codegen "$root/examples/rolling_disk/model.alb" --lang c --out "$tmp/rolling"
contains codegen_rolling "$tmp/out" "equations in generalized speeds, state (q, u1, ...)"
[[ -f $tmp/rolling/model.c ]] || { echo "FAIL codegen_rolling: model.c not written"; fails=$((fails + 1)); }

# run --out: files of simulate go there
printf 'newtonian N\nparticle Q\nvariable x'"''"' m\nconstant m = 1 kg\nmass Q = m\ntranslate Q from N_o by x*Nx>\ninitial x = 1 m\nfinal time 0.1 s\nsimulate\n' >"$tmp/sim.alb"
expect run_out 0 "$alembert" run "$tmp/sim.alb" --out "$tmp/simout"
[[ -f $tmp/simout/simulation.csv ]] || { echo "FAIL run_out: simulation.csv not in --out"; fails=$((fails + 1)); }

# compiled C by default, cached in $TMPDIR/alembert-native; --tape runs no compiler; inverse
# takes --compiled or --tape, not both
count_libraries() { find "$1" -name '*.so' 2>/dev/null | wc -l; }
mkdir -p "$tmp/cache_tape" "$tmp/cache_default"
TMPDIR=$tmp/cache_tape expect run_tape 0 "$alembert" run --tape "$tmp/sim.alb" --out "$tmp/simtape"
[[ $(count_libraries "$tmp/cache_tape") == 0 ]] || { echo "FAIL run_tape: a library was compiled"; fails=$((fails + 1)); }
TMPDIR=$tmp/cache_default expect run_compiled 0 "$alembert" run "$tmp/sim.alb" --out "$tmp/simdefault"
[[ $(count_libraries "$tmp/cache_default") -gt 0 ]] || { echo "FAIL run_compiled: no library compiled by default"; fails=$((fails + 1)); }
TMPDIR=$tmp/cache_tape expect inverse_tape 0 "$alembert" inverse "$model" --motion "$motion" --out "$tmp/invtape" --tape
[[ $(count_libraries "$tmp/cache_tape") == 0 ]] || { echo "FAIL inverse_tape: a library was compiled"; fails=$((fails + 1)); }
expect inverse_compiled_and_tape 2 "$alembert" inverse "$model" --motion "$motion" --out "$tmp/invboth" --compiled --tape
contains inverse_compiled_and_tape "$tmp/err" "excludes"

(( fails == 0 )) && echo "cli_test: OK"
exit $(( fails > 0 ))
