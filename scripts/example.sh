#!/usr/bin/env bash
# Builds the release preset and runs the triple pendulum example.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh
cmake --preset release
cmake --build --preset release -j2

exe=build/release/examples/triple_pendulum/triple_pendulum
if [[ ! -x $exe ]]; then
  echo "example.sh: $exe was not built (is examples/triple_pendulum there yet?)" >&2
  exit 1
fi
exec "$exe" "$@"
