#!/usr/bin/env bash
# Installs what building and running the examples needs (not the test tools), builds the
# `alembert` command alone (release preset, no tests or example programs) and runs the main
# example, the seed's sit-to-stand model: `alembert run examples/sit_to_stand/model.alb`.
# The files it writes (the torques of rising, their plot) go to build/example-output.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh example
cmake --preset release -DALEMBERT_BUILD_TESTS=OFF -DALEMBERT_BUILD_EXAMPLES=OFF
cmake --build --preset release --target alembert_cli

exe=build/release/bin/alembert
if [[ ! -x $exe ]]; then
  echo "example.sh: $exe was not built" >&2
  exit 1
fi
exec "$exe" run --out build/example-output examples/sit_to_stand/model.alb "$@"
