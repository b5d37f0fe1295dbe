#!/usr/bin/env bash
# Installs the Debian packages Alembert needs, only those that are missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libginac-dev libcln-dev libeigen3-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  libboost-dev libfmt-dev libcli11-dev libedit-dev
  libsundials-dev              # the bdf integrator (SUNDIALS CVODE)
  gnuplot-nox
  clang libclang-rt-14-dev  # the sanitizer pass builds the fuzz target (docs/fuzzing.md)
  python3-numpy python3-scipy  # the tests run the generated Python
  libjs-katex                  # HTML reports typeset their equations with KaTeX (inlined)
  libjs-three                  # HTML reports show motion in 3D with three.js (inlined)
  chromium                     # the tests open the HTML report in headless Chromium
  texlive-latex-base texlive-pictures  # the tests compile the reports' LaTeX (TikZ diagrams)
)
# Not installed here (CI does without them): the peers of bench/spatial_peers_bench,
#   libmujoco-dev libqhull-dev libdart-dev libsimbody-dev

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if (( ${#missing[@]} == 0 )); then
  echo "install_deps: all dependencies present"
  exit 0
fi

sudo=()
if (( EUID != 0 )); then
  if command -v sudo >/dev/null; then
    sudo=(sudo)
  else
    echo "install_deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update
"${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
