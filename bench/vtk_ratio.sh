#!/bin/sh
# Bench only: time VTK's CPU raycaster against angioray per quality level (bench/vtk_ratio.py).
#   bench/vtk_ratio.sh [--volume PATH.nrrd] [--tf PRESET|FILE] [--angles N] [--levels L ...] [--images DIR]
# Needs Debian's python3-vtk9 (not installed by scripts/setup.sh). Debian's VTK has X11 render
# windows only (no OSMesa/EGL): even off-screen rendering needs an X server, so without DISPLAY
# the script runs under xvfb-run.
set -eu
here=$(dirname "$0")
# Debian's /usr/bin/python3: python3-vtk9 lives in its dist-packages, not in a pyenv/venv python.
py=/usr/bin/python3
if ! "$py" -c 'import vtk' 2>/dev/null; then
  echo "vtk_ratio: python3-vtk9 is not importable by $py: apt-get install python3-vtk9" >&2
  exit 1
fi
# Mesa's llvmpipe only draws VTK's finished image; keep its threads to the bench's 2 as well.
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
if [ -n "${DISPLAY:-}" ]; then
  exec "$py" "$here/vtk_ratio.py" "$@"
fi
if ! command -v xvfb-run >/dev/null; then
  echo "vtk_ratio: no DISPLAY and no xvfb-run: apt-get install xvfb" >&2
  exit 1
fi
exec xvfb-run -a "$py" "$here/vtk_ratio.py" "$@"
