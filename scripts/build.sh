#!/usr/bin/env bash
# Configures and builds one build tree. Usage: scripts/build.sh BUILD_DIR [extra cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$1
shift
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build_dir" -G Ninja -Wno-dev "$@" >/dev/null
ninja -C "$build_dir" -j"$(nproc)"
