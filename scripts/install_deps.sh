#!/usr/bin/env bash
# Installs the Debian packages Alembert needs, only those that are missing.
# Usage: install_deps.sh [example|test]
#   example: what building the `alembert` command and running the examples need
#   test (default): that, plus what the test suite and CI need (SUNDIALS for the bdf
#            integrator, whose Debian package brings MPI, PETSc and gfortran; GoogleTest, Google Benchmark,
#            clang for the sanitizer pass and fuzzing, Python's NumPy and SciPy for the
#            generated Python, Chromium for the report's browser test, LaTeX for roadmap.tex)
set -euo pipefail

profile=${1:-test}
case $profile in
  example|test) ;;
  *) echo "install_deps: unknown profile '$profile' (use example or test)" >&2; exit 2 ;;
esac

packages=(
  build-essential cmake pkg-config
  ninja-build                  # the presets' generator: compiles a target's sources without
                               # waiting for the libraries it links, so both cores stay busy
  libginac-dev libcln-dev libeigen3-dev
  libboost-dev libfmt-dev libcli11-dev libedit-dev
  gnuplot-nox                  # the plots simulate and inverse draw
  libjs-katex                  # HTML reports typeset their equations with KaTeX (inlined)
  libjs-three                  # HTML reports show motion in 3D with three.js (inlined)
)
if [[ $profile == test ]]; then
  packages+=(
    libsundials-dev              # the bdf integrator (SUNDIALS CVODE; optional in a build)
    libgtest-dev libgmock-dev googletest libbenchmark-dev
    clang libclang-rt-14-dev     # the sanitizer pass builds the fuzz target (docs/fuzzing.md)
    libomp-dev                   # clang's OpenMP: SUNDIALS' CMake package asks for it
    llvm                         # llvm-symbolizer: sanitizer reports name functions, and the
                                 # LeakSanitizer suppressions (cmake/lsan.supp) match by name
    python3-numpy python3-scipy  # the tests run the generated Python
    chromium                     # the tests open the HTML report in headless Chromium
    texlive-latex-base texlive-pictures  # the tests compile the reports' LaTeX (TikZ diagrams)
  )
fi
# Not installed here (CI does without them): the peers of bench/spatial_peers_bench,
#   libmujoco-dev libqhull-dev libdart-dev libsimbody-dev

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if (( ${#missing[@]} == 0 )); then
  echo "install_deps: all dependencies present ($profile)"
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
