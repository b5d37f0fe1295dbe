#!/usr/bin/env bash
# Runs a program and compares what it prints with an expected transcript.
# Usage: check_output.sh EXPECTED_FILE PROGRAM [ARGS...]
# Set ALEMBERT_UPDATE_GOLDEN=1 to rewrite EXPECTED_FILE from the program's output instead.
set -euo pipefail
expected=$1
shift
actual=$(mktemp)
trap 'rm -f "$actual"' EXIT
"$@" >"$actual"
if [[ ${ALEMBERT_UPDATE_GOLDEN:-0} == 1 ]]; then
  tmp="$expected.tmp.$$"
  cp "$actual" "$tmp" && mv "$tmp" "$expected"
  echo "updated $expected"
  exit 0
fi
if ! diff -u "$expected" "$actual"; then
  echo "output of '$*' differs from $expected (see the diff above);" >&2
  echo "if the change is intended, rerun with ALEMBERT_UPDATE_GOLDEN=1 and review the diff" >&2
  exit 1
fi
