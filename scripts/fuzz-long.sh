#!/usr/bin/env bash
# scripts/fuzz.sh with an hour per target (as many targets at once as there are cores).
# Usage: scripts/fuzz-long.sh [BUILD_DIR [TARGET...]]   (default build-fuzz, all targets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${1:-$root/build-fuzz}
shift $(($# < 1 ? $# : 1))
exec "$root/scripts/fuzz.sh" "$build_dir" 3600 "$@"
