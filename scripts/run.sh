#!/usr/bin/env bash
# The main job from a fresh clone: install what is missing, build (Release), run `angioray`
# with any arguments given (none: the embedded phantom demo).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release >&2
exec "$root/build/angioray" "$@"
