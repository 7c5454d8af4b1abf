#!/usr/bin/env bash
# Configures and builds one build tree.
# Usage: scripts/build.sh BUILD_DIR [extra cmake args...] [-- ninja targets...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$1
shift
cmake_args=()
while [[ $# -gt 0 && $1 != "--" ]]; do cmake_args+=("$1"); shift; done
[[ $# -gt 0 ]] && shift  # the "--"
"$root/scripts/setup.sh"
# ccache keys on paths relative to the checkout, so clones in other folders share the cache.
export CCACHE_BASEDIR="$root"
cmake -S "$root" -B "$build_dir" -G Ninja -Wno-dev "${cmake_args[@]}" >/dev/null
ninja -C "$build_dir" -j"$(nproc)" "$@"
