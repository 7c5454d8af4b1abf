#!/usr/bin/env bash
# Input -> image on screen while a user turns the volume: the latency breakdown the app keeps in its
# state report (runtime.latency, gui/latency_trace.h), over many input events, as medians with
# min/max per stage. ROUNDS times: 6 arrow-key steps, a 20-step left drag, wait for the high image.
#   headless (OSMesa):         bench/input_latency.sh BUILD/angioray VOLUME [ROUNDS]
#   real window under Xvfb:    bench/input_latency.sh BUILD/angioray VOLUME [ROUNDS] --window
#   more gui options after the mode, e.g. a session (VesselGlyph on, zoom 4) or the motion budget:
#     bench/input_latency.sh BUILD/angioray VOLUME 5 --window --session vg.json --motion-budget 0
# The window run drives the mouse with xdotool (scripts/setup.sh installs xvfb and xdotool); its
# drag moves every 30 ms, the headless drag one step per 60 Hz frame. Run it with `nice -n -10` on
# a quiet machine and note the load (printed first): on 2 cores other work moves every number.
# Results: /tmp/angioray-input-latency/{headless,window}.json (the whole state report).
set -euo pipefail
angioray=$(realpath "$1")
volume=$(realpath "$2")
rounds=${3:-5}
mode=${4:-headless}
shift $(($# < 4 ? $# : 4))
extra=$(printf ' %q' "$@")  # the gui options ("$@") quoted for the window driver's shell
out=/tmp/angioray-input-latency
mkdir -p "$out"
echo "load: $(uptime)"

summary() {  # the stage table of a state report
  jq -r '.runtime.latency | "superseded requests: \(.superseded_requests), first frames by level: \(.first_frame_levels | tostring)"' "$1"
  jq -r '.runtime.latency as $l
    | (["stage", "count", "median", "p95", "min", "max", "mean"] | @tsv),
      ($l.stages_ms[] | select(.count > 0)
        | [.stage, .count, (.median, .p95, .min, .max, .mean | . * 10 | round / 10)] | @tsv)' "$1" | column -t -s $'\t'
}

if [[ $mode == --window ]]; then
  command -v xvfb-run > /dev/null && command -v xdotool > /dev/null ||
    { echo "needs xvfb-run and xdotool (scripts/setup.sh)" >&2; exit 1; }
  driver="$out/window-driver.sh"
  cat > "$driver" << EOF
XDG_CONFIG_HOME="$out/config" "$angioray" gui "$volume" --size 1280x800 --quit-after 600 $extra \\
  --state-out "$out/window.json" > "$out/window.log" 2>&1 &
app=\$!
window=\$(timeout 60 xdotool search --sync --onlyvisible --name '^angioray\$' | head -1)
[ -n "\$window" ] || { echo "no window" >&2; kill \$app; exit 1; }
sleep 10  # loading and the start-up image up to high
for round in \$(seq $rounds); do
  for k in 1 2 3 4 5 6; do xdotool key --window "\$window" Left; sleep 0.15; done
  sleep 1
  xdotool mousemove --window "\$window" 250 400 sleep 0.2 mousedown 1
  x=250
  for n in \$(seq 20); do x=\$((x + 10)); xdotool mousemove --window "\$window" \$x 400 sleep 0.03; done
  xdotool mouseup 1
  sleep 2
done
kill -TERM \$app
wait \$app
EOF
  xvfb-run -a -s '-screen 0 1400x900x24' sh "$driver"
  summary "$out/window.json"
else
  script="$out/headless-script.json"
  {
    echo '[{"wait_level": "high"}'
    for ((r = 0; r < rounds; ++r)); do
      for k in 1 2 3 4 5 6; do echo ', {"key": "Left"}'; done
      echo ', {"drag": {"from": [250, 400], "to": [450, 400], "steps": 20}}, {"wait_level": "high"}'
    done
    echo ']'
  } > "$script"
  "$angioray" gui "$volume" --headless --size 1280x800 --script "$script" "$@" \
    --screenshot "$out/headless.png" --state-out "$out/headless.json" > /dev/null
  summary "$out/headless.json"
fi
