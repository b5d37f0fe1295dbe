#!/usr/bin/env bash
# The malformed corpus through the alembert command, as a user meets it: every script of
# tests/lang/scripts (and through them the data files of tests/lang/scripts/data) exits with
# status 1 or 2 within 30 s, never 0 and never a crash, and says where: FILE:LINE:COL: error:
# as expected.tsv lists it. The few rows marked "ok" run cleanly and exit 0.
# Usage: corpus_cli_test.sh ALEMBERT SOURCE_DIR
set -uo pipefail
alembert=$1
scripts=$2/tests/lang/scripts
fails=0 count=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# a copy of the corpus, run with the default --out (.): messages name '.' as in expected.tsv,
# and whatever a script writes before its error lands in the copy
cp -r "$scripts" "$tmp/scripts" && cd "$tmp/scripts" || exit 1
while IFS=$'\t' read -r script where message; do
  [[ -z $script || $script == \#* ]] && continue
  count=$((count + 1))
  timeout 30 "$alembert" run "$script" >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
  rc=$?
  if [[ $where == ok ]]; then
    [[ $rc == 0 ]] || { echo "FAIL $script: exit $rc, expected 0"; head -3 "$tmp/stderr"; fails=$((fails + 1)); }
    continue
  fi
  case $rc in
    1|2) ;;
    124) echo "FAIL $script: still running after 30 s"; fails=$((fails + 1)); continue ;;
    0) echo "FAIL $script: exit 0 for a malformed input"; fails=$((fails + 1)); continue ;;
    *) echo "FAIL $script: exit $rc (a crash?)"; tail -5 "$tmp/stderr"; fails=$((fails + 1)); continue ;;
  esac
  if ! grep -qF -- "$script:$where: error: $message" "$tmp/stderr"; then
    echo "FAIL $script: expected '$script:$where: error: $message' in:"; head -3 "$tmp/stderr"
    fails=$((fails + 1))
  fi
done <expected.tsv

data=$(find data -type f 2>/dev/null | wc -l)
echo "$count scripts ($data data files they read) through the command: $fails failed"
if (( count + data < 150 )); then
  echo "FAIL the corpus holds $count scripts and $data data files, fewer than 150"; fails=$((fails + 1))
fi
exit $((fails > 0))
