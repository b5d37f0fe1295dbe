#!/usr/bin/env bash
# Builds the release preset and runs the main example, the seed's sit-to-stand model, through
# the alembert command: `alembert run examples/sit_to_stand/model.alb`. The files it writes
# (the torques of rising, their plot) go to build/example-output.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh
cmake --preset release
cmake --build --preset release -j2

exe=build/release/bin/alembert
if [[ ! -x $exe ]]; then
  echo "example.sh: $exe was not built" >&2
  exit 1
fi
exec "$exe" run --out build/example-output examples/sit_to_stand/model.alb "$@"
