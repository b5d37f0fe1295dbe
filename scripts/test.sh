#!/usr/bin/env bash
# CI entry point: dependencies, warnings-as-errors build + tests, then a sanitizer pass
# (set ALEMBERT_CI_SANITIZE=0 to skip it).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh

cmake --preset ci
cmake --build --preset ci -j2
ctest --preset ci

if [[ ${ALEMBERT_CI_SANITIZE:-1} == 1 ]]; then
  cmake --preset asan
  cmake --build --preset asan -j2
  ctest --preset asan
fi
