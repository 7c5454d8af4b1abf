#!/usr/bin/env bash
# Scaling table: frame times and peak memory against volume size.
#
# For each phantom size: generates the phantom (realistic style) into DIR, runs
#   angioray bench VOL --angles N --no-contributions --json J --threads 2
# and a plain
#   angioray render VOL -o DIR/x.png --quality high
# both under /usr/bin/time -v (peak RSS), then prints one row per size and deletes the volume.
#
#   bench/scale_table.sh [--sizes "IxJxK ..."] [--angles N] [--dir DIR] [--binary PATH] [--keep]
#                        [--ext nii|nrrd|mha]
#
# Defaults: sizes 256x256x600 512x512x1200 768x768x1800 1024x1024x2400, 6 angles, DIR /tmp/scale,
# binary build/angioray beside this script, volumes written as .nii (the one uncompressed format
# the writer offers: .nrrd/.mha are gzip/zlib compressed, which is slow to write and read at GiBs).
# 1024x1024x2400 needs 4.7 GiB of disk and, extrapolated from small sizes, ~11 GB RAM for its phantom.
#
# Columns: raw MiB = I*J*K*2 (16-bit voxels); gen s = phantom wall time (generation + write);
# load s = render wall time minus its "rendered in" (reading the file, start-up, PNG); prep s =
# bench's preparation (slice tiles + TF classification + blocked volume build); per level the
# median (min-max) ms of the "all" row over N angles; bench/render GiB = peak RSS (GiB = 2^30 B);
# render s = wall time of the whole render command. A failing step is reported in its row (exit
# code or signal, e.g. 9 = killed, out of memory, and angioray's last line), and the script goes on.
# Logs of every step stay in DIR/logs/.
set -u

here=$(cd "$(dirname "$0")" && pwd)
sizes="256x256x600 512x512x1200 768x768x1800 1024x1024x2400"
angles=6
dir=/tmp/scale
bin="$here/../build/angioray"
keep=0
ext=nii
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes=$2; shift 2 ;;
    --angles) angles=$2; shift 2 ;;
    --dir) dir=$2; shift 2 ;;
    --binary) bin=$2; shift 2 ;;
    --ext) ext=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "scale_table.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

[ -x "$bin" ] || { echo "scale_table.sh: no executable angioray at $bin (--binary)" >&2; exit 2; }
command -v jq >/dev/null || { echo "scale_table.sh: needs jq (apt-get install jq)" >&2; exit 2; }
if [ ! -x /usr/bin/time ]; then
  echo "installing package time for /usr/bin/time" >&2
  apt-get install -y time >/dev/null || { echo "scale_table.sh: cannot install time" >&2; exit 2; }
fi
mkdir -p "$dir/logs" || exit 2

voxels() { echo "$1" | awk -Fx '{printf "%.0f", $1 * $2 * $3}'; }
free_bytes() { df -Pk "$dir" | awk 'NR == 2 {printf "%.0f", $4 * 1024}'; }
gib() { awk -v b="$1" 'BEGIN {printf "%.2f", b / 2^30}'; }
# From a /usr/bin/time -v file: peak RSS in GiB, wall seconds; failure: "signal N" / "exit N" or "".
rss_gib() { awk -F': ' '/Maximum resident/ {printf "%.2f", $2 / 2^20}' "$1"; }
wall_s() { awk -F'): ' '/Elapsed \(wall clock\)/ {n = split($2, a, ":"); s = 0;
             for (i = 1; i <= n; i++) s = s * 60 + a[i]; printf "%.1f", s}' "$1"; }
failure() { # $1 exit code of /usr/bin/time, $2 its -v file, $3 the command's log
  local why last
  why=$(sed -n 's/^Command terminated by signal \([0-9]*\)/signal \1/p' "$2")
  [ "$why" = "signal 9" ] && why="signal 9 (killed: out of memory?)"
  [ -z "$why" ] && [ "$1" -ne 0 ] && why="exit $1"
  last=$(grep -v '^[[:space:]]*$' "$3" | tail -n 1 | tr -d '\r' | cut -c1-100)
  [ -n "$why" ] && echo "$why${last:+: $last}"
}

# Disk: one volume at a time (all of them with --keep), each about its raw size (less if compressed).
need=0
for s in $sizes; do
  b=$(( $(voxels "$s") * 2 ))
  if [ "$keep" = 1 ]; then need=$((need + b)); elif [ "$b" -gt "$need" ]; then need=$b; fi
done
echo "disk: $(df -h "$dir" | awk 'NR == 2 {print $4 " free on " $6}') ($dir); the run needs up to $(gib "$need") GiB (raw 16-bit)"
[ "$need" -gt "$(free_bytes)" ] && echo "WARNING: not enough free disk in $dir for the largest size(s); they will be skipped"
echo "binary: $bin; $angles angles, 2 threads; volumes as .$ext"
echo

row() { printf '%-15s %8s %7s %7s %7s %-19s %-19s %-19s %-22s %7s %7s %8s  %s\n' "$@"; }
row size "raw MiB" "gen s" "load s" "prep s" "fast ms" "medium ms" "medium-tri ms" "high ms" \
  "bench" "render" "render" ""
row "" "" "" "" "" "med (min-max)" "med (min-max)" "med (min-max)" "med (min-max)" \
  "GiB" "GiB" "wall s" "errors"
for s in $sizes; do
  vol="$dir/phantom-$s.$ext" json="$dir/logs/bench-$s.json" log="$dir/logs/$s"
  raw=$(( $(voxels "$s") * 2 ))
  gen=- load=- prep=- brss=- rrss=- rwall=- err=""
  declare -A ms=([fast]=- [medium]=- [medium-trilinear]=- [high]=-)
  if [ "$raw" -gt "$(free_bytes)" ]; then
    err="skipped: needs $(gib "$raw") GiB of disk, $(gib "$(free_bytes)") GiB free"
  else
    # 1. phantom
    /usr/bin/time -v -o "$log.phantom.time" "$bin" phantom "$vol" --size "$s" >"$log.phantom.log" 2>&1
    rc=$?
    gen=$(wall_s "$log.phantom.time")
    why=$(failure "$rc" "$log.phantom.time" "$log.phantom.log")
    if [ -n "$why" ]; then
      err="phantom $why"
    else
      # 2. bench
      rm -f "$json"
      /usr/bin/time -v -o "$log.bench.time" "$bin" bench "$vol" --angles "$angles" \
        --no-contributions --json "$json" --threads 2 >"$log.bench.log" 2>&1
      rc=$?
      brss=$(rss_gib "$log.bench.time")
      why=$(failure "$rc" "$log.bench.time" "$log.bench.log")
      [ -n "$why" ] && err="bench $why"
      if [ -s "$json" ]; then
        prep=$(jq '.preprocess_ms + .classify_ms + .blocked_volume.build_ms' "$json" | awk '{printf "%.1f", $1 / 1000}')
        for level in fast medium medium-trilinear high; do
          cell=$(jq -r --arg l "$level" '.frames[] | select(.level == $l and .variant == "all")
            | "\(.median_ms) \(.min_ms) \(.max_ms)"' "$json" | awk '{printf "%.1f (%.1f-%.1f)", $1, $2, $3}')
          ms[$level]=${cell:--}
        done
      fi
      # 3. plain render
      rm -f "$dir/x.png" "$dir/x.png.json"
      /usr/bin/time -v -o "$log.render.time" "$bin" render "$vol" -o "$dir/x.png" --quality high \
        >"$log.render.log" 2>&1
      rc=$?
      rrss=$(rss_gib "$log.render.time")
      rwall=$(wall_s "$log.render.time")
      why=$(failure "$rc" "$log.render.time" "$log.render.log")
      if [ -n "$why" ]; then
        err="${err:+$err; }render $why"
      else
        rendered=$(sed -n 's/.*rendered in \([0-9.]*\) s.*/\1/p' "$log.render.log")
        [ -n "$rendered" ] && load=$(awk -v w="$rwall" -v r="$rendered" 'BEGIN {printf "%.1f", w - r}')
      fi
    fi
    [ "$keep" = 1 ] || rm -f "$vol"
  fi
  row "$s" "$(awk -v b="$raw" 'BEGIN {printf "%.0f", b / 2^20}')" "$gen" "$load" "$prep" \
    "${ms[fast]}" "${ms[medium]}" "${ms[medium-trilinear]}" "${ms[high]}" "${brss:--}" "${rrss:--}" "$rwall" "$err"
done
