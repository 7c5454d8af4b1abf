#!/usr/bin/env bash
# The input-latency table of a volume in a real window under Xvfb (bench/input_latency.sh --window):
# plain DVR and VesselGlyph, each with the motion budget at 40 ms (the default: the finest sampling
# that fits while dragging) and 0 (always the fast level), and plain DVR zoomed 4x.
#   bench/input_latency_table.sh BUILD/angioray VOLUME CENTERLINES [ROUNDS]
# Prints the load first and, per configuration, input -> screen (median, min, max) and the first
# level's render time; the whole reports are in /tmp/angioray-input-latency/table-*.json.
set -euo pipefail
angioray=$(realpath "$1")
volume=$(realpath "$2")
centerlines=$(realpath "$3")
rounds=${4:-5}
here=$(dirname "$(realpath "$0")")
out=/tmp/angioray-input-latency
mkdir -p "$out"
echo "load before: $(uptime)"

session() {  # name, vessel_glyph enabled, zoom
  jq -n --arg c "$centerlines" --argjson vg "$2" --argjson zoom "$3" \
    '{tf_preset: "cta-vessels-bone", view: {zoom: $zoom}, vessel_glyph: {enabled: $vg, centerlines: $c}}' \
    > "$out/table-$1-session.json"
}
session plain false 1
session vg true 1
session zoom4 false 4

printf '%-10s %7s %7s %7s %7s %6s  %s\n' config median p95 min max count "render ms (median)"
for config in plain:40 plain:0 vg:40 vg:0 zoom4:40; do
  name=${config%%:*} budget=${config##*:}
  "$here/input_latency.sh" "$angioray" "$volume" "$rounds" --window \
    --session "$out/table-$name-session.json" --motion-budget "$budget" > "$out/table-$name-$budget.log"
  cp "$out/window.json" "$out/table-$name-$budget.json"
  jq -r --arg c "$name/$budget" '.runtime.latency.stages_ms as $s
    | ($s[] | select(.stage == "input_to_screen")) as $t
    | ($s[] | select(.stage == "render")) as $r
    | [$c, ($t.median, $t.p95, $t.min, $t.max | . * 10 | round / 10), $t.count, ($r.median | . * 10 | round / 10)]
    | @tsv' "$out/table-$name-$budget.json" | awk -F'\t' '{printf "%-10s %7s %7s %7s %7s %6s  %s\n", $1, $2, $3, $4, $5, $6, $7}'
done
echo "load after: $(uptime)"
