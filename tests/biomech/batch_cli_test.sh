#!/usr/bin/env bash
# `alembert inverse MODEL --motion 'trials/*.csv' --jobs 2`: three trials, one malformed; the
# good ones finish, the bad one is named in the summary, and two shards cover the trials once.
# Usage: batch_cli_test.sh ALEMBERT SOURCE_DIR
set -euo pipefail
alembert=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir trials
cp "$src/examples/sit_to_stand_inverse/motion.csv" trials/a.csv
head -80 trials/a.csv > trials/b.csv
{ head -5 trials/a.csv; echo "0.05,-25,abc,-129.9"; sed -n 7,40p trials/a.csv; } > trials/bad.csv
model="$src/examples/sit_to_stand/model.alb"
fail() { echo "batch_cli_test: $*" >&2; exit 1; }

# the whole batch, two at a time: exit 1 for the one failure, the others complete
status=0
"$alembert" inverse "$model" --motion 'trials/*.csv' --jobs 2 --out all > all.txt || status=$?
[[ $status == 1 ]] || fail "exit status $status, expected 1 (one trial failed)"
grep -q "^3 trials: 2 ok, 1 failed; summary in all/summary.csv$" all.txt || fail "counts: $(cat all.txt)"
grep -q "^failed: trials/bad.csv: .*trials/bad.csv:6: cell 3 ('qB') is 'abc', not a finite number" all.txt ||
  fail "the failure is not named: $(cat all.txt)"
[[ -s all/a/loads.csv && -s all/b/loads.csv ]] || fail "the good trials wrote no loads.csv"
[[ $(grep -c '^trials/a.csv,ok,' all/summary.csv) == 9 ]] || fail "trial a: 9 peaks expected"
[[ $(grep -c '^trials/b.csv,ok,' all/summary.csv) == 9 ]] || fail "trial b: 9 peaks expected"
grep -q '^trials/bad.csv,failed,,,,' all/summary.csv || fail "no failed row for bad.csv"

# two shards, as two tasks of a cluster array job: every trial once, same numbers
for i in 0 1; do
  "$alembert" inverse "$model" --motion 'trials/*.csv' --shard "$i/2" --out "shard$i" > "shard$i.txt" || true
done
cut -d, -f1 shard0/summary.csv shard1/summary.csv | grep -v '^trial$' | sort -u > seen.txt
printf 'trials/a.csv\ntrials/b.csv\ntrials/bad.csv\n' > want.txt
diff -u want.txt seen.txt || fail "the shards do not cover the trials once"
if cut -d, -f1 shard0/summary.csv | sort -u | grep -qxFf <(cut -d, -f1 shard1/summary.csv | grep -v '^trial$' | sort -u); then
  fail "a trial ran in both shards"
fi
diff <(grep '^trials/a.csv' all/summary.csv) <(grep -h '^trials/a.csv' shard0/summary.csv shard1/summary.csv) ||
  fail "trial a's peaks differ between the batch and its shard"

# marker trials (.trc) of a script with markers: two good (the second shorter), one whose last
# row lacks a marker; the good ones give the same peaks as the script's own trial
mkdir trc
cp "$src/examples/sit_to_stand/lab/rise.trc" trc/a.trc
head -200 trc/a.trc > trc/b.trc
{ head -20 trc/a.trc; sed -n 21p trc/a.trc | cut -f1-11; } > trc/cut.trc
lab="$src/examples/sit_to_stand/model_lab.alb"
status=0
"$alembert" inverse "$lab" --motion 'trc/*.trc' --jobs 2 --out trcs > trcs.txt || status=$?
[[ $status == 1 ]] || fail ".trc batch: exit status $status, expected 1"
grep -q "^3 trials: 2 ok, 1 failed; summary in trcs/summary.csv$" trcs.txt || fail ".trc counts: $(cat trcs.txt)"
grep -q "^failed: trc/cut.trc: .*'ACR' is missing from t = -0.36 s" trcs.txt || fail "the .trc failure is not named: $(cat trcs.txt)"
[[ $(grep -c '^trc/a.trc,ok,' trcs/summary.csv) == 9 && $(grep -c '^trc/b.trc,ok,' trcs/summary.csv) == 9 ]] ||
  fail ".trc trials: 9 peaks each expected"
grep -q '^trc/a.trc,ok,T_B \[N\*m\],-127.49' trcs/summary.csv || fail "trial a's knee peak: $(cat trcs/summary.csv)"

# a bad shard and a pattern that matches nothing are usage errors
status=0; "$alembert" inverse "$model" --motion 'trials/*.csv' --shard 2/2 --out x 2> err.txt || status=$?
[[ $status == 2 ]] && grep -q "write I/N with 0 <= I < N" err.txt || fail "bad shard: status $status, $(cat err.txt)"
status=0; "$alembert" inverse "$model" --motion 'none/*.trc' --out x 2> err.txt || status=$?
[[ $status == 2 ]] && grep -q "matches no file" err.txt || fail "empty pattern: status $status, $(cat err.txt)"
# an interrupted batch (SIGTERM to the batch, as a scheduler sends it; SIGINT from a terminal
# takes the same path): the trials that finished keep their results and get their summary,
# the running one is stopped and leaves nothing, and the batch ends by the signal
mkdir many
for i in 1 2 3 4 5 6 7 8; do cp trials/a.csv "many/t$i.csv"; done
"$alembert" inverse "$model" --motion 'many/*.csv' --jobs 1 --tape --out stop > stop.txt 2> stop.err &
batch=$!
for _ in $(seq 1 600); do [[ -s stop/t2/loads.csv ]] && break; sleep 0.1; done
[[ -s stop/t2/loads.csv ]] || fail "interrupted batch: the second trial never finished"
kill -TERM "$batch"
status=0; wait "$batch" || status=$?
[[ $status == 143 ]] || fail "interrupted batch: exit status $status, expected 143 (SIGTERM); $(cat stop.err)"
[[ -s stop/summary.csv ]] || fail "interrupted batch: no summary.csv for the trials that finished"
grep -q "interrupted: [0-9]* of 8 trials finished (summary in stop/summary.csv)" stop.err ||
  fail "interrupted batch: no account of what finished: $(cat stop.err)"
finished=$(cut -d, -f1 stop/summary.csv | grep -v '^trial$' | sort -u)
[[ -n $finished ]] || fail "interrupted batch: the summary names no finished trial"
for d in stop/t*; do
  t=${d#stop/}
  # every directory left is a finished trial's, with its table and its log, named in the summary
  [[ -s $d/loads.csv ]] || fail "interrupted batch: $d was left without loads.csv: $(ls -la "$d")"
  grep -qx "many/$t.csv" <<<"$finished" || fail "interrupted batch: $d is not in the summary"
done
[[ -z $(find stop -name '.*tmp*') ]] || fail "interrupted batch: temporary files were left: $(find stop -name '.*tmp*')"

echo "batch_cli_test: OK"
