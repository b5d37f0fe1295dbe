#!/usr/bin/env bash
# `alembert import` end to end: the translated script is written (through a temporary renamed
# into place) and runs; warnings and errors name file:line:col; bad input exits 1 and leaves
# the target as it was; usage errors exit 2; the same input gives the same bytes.
# Usage: import_cli_test.sh ALEMBERT SOURCE_DIR
set -uo pipefail
alembert=$1
models=$2/tests/lang/autolev/models
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

# every model translates without a word on stderr, and the script runs
for al in "$models"/*.al; do
  name=$(basename "$al" .al)
  expect "$name import" 0 "$alembert" import "$al" --out "$tmp/$name.alb"
  [[ -s $tmp/err ]] && { fail "$name: unexpected messages"; cat "$tmp/err"; }
  contains "$name import" "$tmp/out" "wrote $tmp/$name.alb"
  expect "$name run" 0 "$alembert" run -q "$tmp/$name.alb" --out "$tmp/run_$name"
done
left=$(find "$tmp" -maxdepth 1 -name '.*tmp*' -print)
[[ -z $left ]] || fail "temporary files left: $left"

# the same input gives the same bytes
"$alembert" import "$models/rolling_disk.al" --out "$tmp/again.alb" >/dev/null
cmp -s "$tmp/again.alb" "$tmp/rolling_disk.alb" || fail "two imports differ"

# '-' reads standard input and --out - writes standard output
expect "stdin to stdout" 0 sh -c "\"$alembert\" import - --out - < \"$models/gyroscope.al\""
contains "stdin to stdout" "$tmp/out" "kane K for Q1, Q2, Q3"

# a statement without counterpart: a warning with file:line:col, the script still written
printf 'NEWTONIAN N\nPAUSE\nPARTICLES P\n' > "$tmp/warn.al"
expect "warning" 0 "$alembert" import "$tmp/warn.al" --out "$tmp/warn.alb"
contains "warning" "$tmp/err" "warn.al:2:1: warning: PAUSE is not translated"
contains "warning" "$tmp/out" "(1 message above)"
contains "warning" "$tmp/warn.alb" "particle P"

# a statement with no counterpart is left out with a warning, a comment at its place and the
# statements that use what it defined; a summary on stderr; exit 0; the script runs
printf 'NEWTONIAN N\nCONSTANTS L\nX = SQR(L)\nY = 2*X\nZ = 3*L\n' > "$tmp/out.al"
expect "left out" 0 "$alembert" import "$tmp/out.al" --out "$tmp/out.alb"
contains "left out" "$tmp/err" "out.al:3:5: warning: left out: the Autolev function SQR() has no translation"
contains "left out" "$tmp/err" "out.al:4:7: warning: left out: uses X, which line 3 left out"
contains "left out" "$tmp/err" "alembert: '$tmp/out.al' imported with 2 statements left out (lines 3, 4)"
contains "left out" "$tmp/out.alb" "# left out ($tmp/out.al:3): the Autolev function SQR() has no translation"
contains "left out" "$tmp/out.alb" "Z = 3*L"
expect "left out runs" 0 "$alembert" run "$tmp/out.alb"

# an error: file:line:col with the line and a caret, exit 1, the target untouched
printf 'NEWTONIAN N\nCONSTANTS L\nR> = N1> + L\n' > "$tmp/bad.al"
echo "keep me" > "$tmp/bad.alb"
expect "error" 1 "$alembert" import "$tmp/bad.al" --out "$tmp/bad.alb"
contains "error" "$tmp/err" "bad.al:3:10: error: '+' between a vector and a scalar"
contains "error" "$tmp/err" "    3 | R> = N1> + L"
contains "error" "$tmp/err" "hint:"
contains "error" "$tmp/bad.alb" "keep me"

# a part of a statement that is not translated is said at its column with a caret; a name
# that is a frame and a variable is renamed with a note; '&' continues a line
printf 'NEWTONIAN N\nCONSTANTS L+, &\n  M-\nFRAMES A\nVARIABLES A\n' > "$tmp/parts.al"
expect "parts" 0 "$alembert" import "$tmp/parts.al" --out "$tmp/parts.alb"
contains "parts" "$tmp/err" "parts.al:3:4: warning: the qualifier '-' (negative) of 'M' is not translated"
contains "parts" "$tmp/err" "    3 |   M-"
contains "parts" "$tmp/err" "      |    ^"
contains "parts" "$tmp/err" "parts.al:5:11: note: 'A' is declared as a variable at line 5 and as a frame at line 4"
contains "parts" "$tmp/parts.alb" "positive L"
contains "parts" "$tmp/parts.alb" "# renamed: 'A' is declared as a variable"
contains "parts" "$tmp/parts.alb" "variable A_var''"

# usage errors
expect "missing file" 2 "$alembert" import "$tmp/none.al" --out "$tmp/none.alb"
expect "no --out" 2 "$alembert" import "$models/gyroscope.al"
expect "--out is a directory" 2 "$alembert" import "$models/gyroscope.al" --out "$tmp"
expect "unwritable --out" 2 "$alembert" import "$models/gyroscope.al" --out "$tmp/no/such/dir/x.alb"

if [[ $fails -ne 0 ]]; then echo "$fails failure(s)"; exit 1; fi
echo "import: all checks passed"
