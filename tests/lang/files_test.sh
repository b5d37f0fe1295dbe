#!/usr/bin/env bash
# The files alembert writes: a script's 'to' stays inside --out unless allowed, a bad --out
# fails at once, expansions past --max-terms are refused, and an interrupted run (SIGINT)
# leaves no temporary file, no empty plot and no gnuplot process.
# Usage: files_test.sh ALEMBERT
set -uo pipefail
alembert=$1
fails=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

fail() { echo "FAIL $1"; fails=$((fails + 1)); }
expect() {  # expect NAME STATUS COMMAND...: runs COMMAND, checks its exit status
  local name=$1 want=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [[ $got != "$want" ]]; then fail "$name: exit $got, expected $want"; cat "$tmp/out" "$tmp/err"; fi
}
contains() {  # contains NAME FILE TEXT
  grep -qF -- "$3" "$2" || { fail "$1: '$3' not in:"; cat "$2"; }
}
# no_leftovers NAME DIR: no temporary file and no empty file under DIR
no_leftovers() {
  local left
  left=$(find "$2" \( -name '*.tmp*' -o -name '*gnuplot-errors*' -o -empty -type f \) -print)
  [[ -z $left ]] || fail "$1: left behind: $left"
}
# gone NAME PID: the process has ended (a zombie waiting for its reaper counts as ended)
gone() {
  local state
  for _ in $(seq 50); do
    state=$(ps -o stat= -p "$2" 2>/dev/null)
    [[ -z $state || $state == Z* ]] && return 0
    sleep 0.1
  done
  fail "$1: process $2 still runs"
  kill "$2" 2>/dev/null
}

model='newtonian N
particle Q
variable x'"''"' m
constant m = 1 kg, k = 100 N/m, L0 = 0 m
mass Q = m
translate Q from N_o by x*Nx>
spring s between Q and N_o stiffness k length L0
initial x = 1 m'
printf '%s\nfinal time 0.1 s\nsimulate to "../escaped"\n' "$model" >"$tmp/parent.alb"
printf '%s\nfinal time 0.1 s\nsimulate to "%s/absolute"\n' "$model" "$tmp" >"$tmp/absolute.alb"

# 'to' leaving --out is refused at the path, before anything is written
mkdir -p "$tmp/work"
expect to_parent 1 "$alembert" run "$tmp/parent.alb" --out "$tmp/work/out"
contains to_parent "$tmp/err" "parent.alb:10:13: error: to \"../escaped\" leaves the output directory '$tmp/work/out' (--out)"
contains to_parent "$tmp/err" "--allow-outside-out"
[[ ! -e $tmp/work/escaped ]] || fail "to_parent: wrote outside --out"
expect to_absolute 1 "$alembert" run "$tmp/absolute.alb" --out "$tmp/work/out"
contains to_absolute "$tmp/err" "absolute.alb:10:13: error: to \"$tmp/absolute\" leaves the output directory"
[[ ! -e $tmp/absolute ]] || fail "to_absolute: wrote outside --out"
# ... unless the user allows it
expect to_parent_allowed 0 "$alembert" run "$tmp/parent.alb" --out "$tmp/work/out" --allow-outside-out
[[ -s $tmp/work/escaped/simulation.csv ]] || fail "to_parent_allowed: simulation.csv not written"
expect to_absolute_allowed 0 "$alembert" run "$tmp/absolute.alb" --out "$tmp/work/out" --allow-outside-out
[[ -s $tmp/absolute/simulation.csv ]] || fail "to_absolute_allowed: simulation.csv not written"

# a bad --out fails at once (exit 2), before the script runs
: >"$tmp/a_file"
expect out_is_file 2 "$alembert" run "$tmp/parent.alb" --out "$tmp/a_file"
contains out_is_file "$tmp/err" "alembert: --out '$tmp/a_file' is not a directory"
[[ ! -s $tmp/out ]] || fail "out_is_file: the script ran"
expect out_under_file 2 "$alembert" run "$tmp/parent.alb" --out "$tmp/a_file/sub"
contains out_under_file "$tmp/err" "cannot create the directory"
expect out_unwritable 2 "$alembert" run "$tmp/parent.alb" --out /proc/alembert-out
contains out_unwritable "$tmp/err" "alembert: --out '/proc/alembert-out': cannot create the directory"
if (( EUID != 0 )); then  # permissions do not stop root
  mkdir -p "$tmp/readonly" && chmod 555 "$tmp/readonly"
  expect out_readonly 2 "$alembert" run "$tmp/parent.alb" --out "$tmp/readonly"
  contains out_readonly "$tmp/err" "cannot write there"
fi
expect codegen_out_is_file 2 "$alembert" codegen "$tmp/parent.alb" --lang c --out "$tmp/a_file"
expect inverse_out_is_file 2 "$alembert" inverse "$tmp/parent.alb" --motion "$tmp/a_file" --out "$tmp/a_file"

# --max-terms bounds expand() and simplify()
printf 'newtonian N\nvariable a, b\nz = expand((a + b)^20)\n' >"$tmp/terms.alb"
expect max_terms_default 0 "$alembert" run "$tmp/terms.alb"
expect max_terms_low 1 "$alembert" run "$tmp/terms.alb" --max-terms 10
contains max_terms_low "$tmp/err" "terms.alb:3:5: error: expand(): expanding the expression would form up to 21 terms, more than the limit of 10"
contains max_terms_low "$tmp/err" "raise the limit with --max-terms"
expect max_terms_zero 2 "$alembert" run "$tmp/terms.alb" --max-terms 0
# said in words: once "not in range 0.000000 to 1797693...", a 309-digit number
contains max_terms_zero "$tmp/err" "--max-terms: '0' is not a count: give a whole number, 1 or more (e.g. 100000)"
if [[ $(wc -c <"$tmp/err") -gt 300 ]]; then echo "FAIL max_terms_zero: the message is $(wc -c <"$tmp/err") bytes"; fails=$((fails + 1)); fi
expect print_limit_negative 2 "$alembert" run "$tmp/terms.alb" --print-limit -5
contains print_limit_negative "$tmp/err" "--print-limit: '-5' is not a count: give a whole number, 1 or more"
expect cutoff_negative 2 "$alembert" inverse "$tmp/terms.alb" --motion m.csv --out "$tmp" --cutoff -1
contains cutoff_negative "$tmp/err" "--cutoff: '-1' is not a number of 0 or more (e.g. 6)"
# a data file where the script goes: what reads it, not a lexer error at its first line
printf 'PathFileType\t4\t(X/Y/Z)\trise.trc\n' >"$tmp/rise.trc"
expect data_file_as_script 2 "$alembert" run "$tmp/rise.trc"
contains data_file_as_script "$tmp/err" "rise.trc' is a data file (.trc), not a script; a script reads it: inverse for T_A from"

# job control: background jobs of a script otherwise start with SIGINT ignored, and alembert,
# like other programs, leaves an ignored SIGINT ignored
set -m

# SIGINT in the middle of a simulation: the progress line is on a terminal, so the run goes
# through script(1); the signal goes to alembert once it reports progress
if command -v script >/dev/null; then
  printf '%s\nfinal time 1000000 s\noutput step 100 s\nsimulate\n' "$model" >"$tmp/long.alb"
  mkdir -p "$tmp/long"
  script -qfec "bash -c 'echo \$\$ >\"$tmp/long.pid\"; exec \"$alembert\" run --quiet \"$tmp/long.alb\" --out \"$tmp/long\"'" \
    "$tmp/long.log" >/dev/null 2>&1 &
  runner=$!
  for _ in $(seq 300); do grep -q "simulating 'long': t = " "$tmp/long.log" 2>/dev/null && break; sleep 0.1; done
  if grep -q "simulating 'long': t = " "$tmp/long.log"; then
    kill -INT "$(cat "$tmp/long.pid")"
    wait "$runner"
    gone sigint_simulation "$(cat "$tmp/long.pid")"
    no_leftovers sigint_simulation "$tmp/long"
    [[ ! -e $tmp/long/simulation.csv ]] || fail "sigint_simulation: a table of an unfinished run was written"
  else
    fail "sigint_simulation: no progress line within 30 s"; kill "$runner"
  fi
else
  echo "files_test: script(1) not found; the SIGINT-during-simulation check is skipped"
fi

# SIGINT while gnuplot draws: a stand-in gnuplot creates the files gnuplot would (empty at
# first) and hangs; the interrupted run terminates it and leaves no empty or temporary file
cat >"$tmp/slow_gnuplot" <<EOF
#!/usr/bin/env bash
[[ \${1:-} == --version ]] && exit 0
echo \$\$ >"$tmp/gnuplot.pid"
while IFS= read -r line; do
  if [[ \$line =~ ^set\ output\ \'(.+)\'\$ ]]; then : >"\${BASH_REMATCH[1]}"; fi
done
exec sleep 60
EOF
chmod +x "$tmp/slow_gnuplot"
printf '%s\nfinal time 0.5 s\nsimulate\n' "$model" >"$tmp/plot.alb"
mkdir -p "$tmp/plot"
ALEMBERT_GNUPLOT="$tmp/slow_gnuplot" "$alembert" run --quiet "$tmp/plot.alb" --out "$tmp/plot" \
  >"$tmp/plot.out" 2>&1 &
run=$!
for _ in $(seq 300); do [[ -s $tmp/gnuplot.pid ]] && break; sleep 0.1; done
if [[ -s $tmp/gnuplot.pid ]]; then
  sleep 0.5  # the stand-in has read the script and created its files
  kill -INT "$run"
  wait "$run"
  status=$?
  [[ $status == 130 ]] || fail "sigint_plot: exit $status, expected 130 (ended by SIGINT)"
  gone sigint_plot "$(cat "$tmp/gnuplot.pid")"
  no_leftovers sigint_plot "$tmp/plot"
  [[ ! -e $tmp/plot/simulation.png && ! -e $tmp/plot/simulation.svg ]] || fail "sigint_plot: a plot was left"
else
  fail "sigint_plot: the stand-in gnuplot never started"; cat "$tmp/plot.out"; kill "$run"
fi

(( fails == 0 )) && echo "files_test: OK"
exit $(( fails > 0 ))
