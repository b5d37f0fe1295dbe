#!/usr/bin/env bash
# Usage: scripts/check_consumer.sh BUILD_DIR
# Installs the build in BUILD_DIR into a temporary prefix, then configures,
# builds and runs tests/consumer against it with find_package(Alembert).
set -euo pipefail

build_dir=$(cd "${1:?usage: $0 BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
cache="$build_dir/CMakeCache.txt"
[[ -f $cache ]] || { echo "check_consumer: no CMakeCache.txt in $build_dir" >&2; exit 1; }

cache_get() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n1; }
cxx=$(cache_get CMAKE_CXX_COMPILER)
build_type=$(cache_get CMAKE_BUILD_TYPE)
sanitize=$(cache_get ALEMBERT_SANITIZE)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build_dir" --prefix "$tmp/prefix" >/dev/null

args=(-S "$root/tests/consumer" -B "$tmp/build"
      -DCMAKE_PREFIX_PATH="$tmp/prefix"
      -DCMAKE_CXX_COMPILER="$cxx"
      -DCMAKE_BUILD_TYPE="${build_type:-Release}"
      -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
case "${sanitize^^}" in
  ON|TRUE|1|YES)
    san="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
    args+=(-DCMAKE_CXX_FLAGS="$san" -DCMAKE_EXE_LINKER_FLAGS="$san") ;;
esac

cmake "${args[@]}"
cmake --build "$tmp/build" -j2
"$tmp/build/consumer"
echo "check_consumer: OK"
