#!/usr/bin/env bash
# Fuzzes every file reader with libFuzzer (tests/fuzz): builds the fuzz targets with clang, ASan and
# UBSan, writes the seed corpora with our own writers, runs every target for the given time (as
# many at once as there are cores) and prints per target the executions, seconds and findings.
# Exits non-zero if any target crashed, hung (-timeout) or ran out of memory (-rss_limit_mb); each
# finding's input is kept in BUILD_DIR/artifacts/<target>/ (replay: BUILD_DIR/tests/fuzz/fuzz_<target>
# FILE; once fixed, save it to tests/data/fuzz-regressions/<target>/). The corpora grow in
# BUILD_DIR/corpus/<target>/ from run to run.
# Usage: scripts/fuzz.sh [BUILD_DIR [SECONDS_PER_TARGET [TARGET...]]]   (defaults: build-fuzz 20, all)
#        scripts/fuzz-long.sh [BUILD_DIR [TARGET...]]                    (an hour per target)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$(realpath -m "${1:-$root/build-fuzz}")
seconds=${2:-20}
shift $(($# < 2 ? $# : 2))
started=$(date +%s)

"$root/scripts/build.sh" "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DANGIORAY_FUZZ=ON -- fuzz_targets
built=$(date +%s)

if [[ $# -gt 0 ]]; then
  targets=("$@")
else
  targets=()
  for binary in "$build_dir"/tests/fuzz/fuzz_*; do targets+=("${binary##*/fuzz_}"); done
fi

seeds="$build_dir/seeds"
rm -rf "$seeds"
"$build_dir/tests/fuzz/write_fuzz_seeds" "$seeds"
cp -r "$root"/tests/fuzz/seeds/. "$seeds"/
# Saved findings start the corpus too, so a regression shows at once; not the unfixed ones (in
# code the readers do not own, see tests/support/fuzz_regressions.h).
for saved in "$root"/tests/data/fuzz-regressions/*/*; do
  [[ -f $saved && ${saved##*/} != unfixed-* ]] || continue
  target=$(basename "$(dirname "$saved")")
  mkdir -p "$seeds/$target"
  cp "$saved" "$seeds/$target/"
done

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=$root/tests/ubsan.supp
export LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan.supp
symbolizer=$(command -v llvm-symbolizer || command -v llvm-symbolizer-14 || true)
[[ -n $symbolizer ]] && export ASAN_SYMBOLIZER_PATH=$symbolizer

dictionary_of() {
  case $1 in
    tf | centerline_markups | render_sidecar | session | script) echo json ;;
    centerline_vtp) echo vtp ;;
    centerline_csv) echo csv ;;
    dicom_*) echo dicom ;;
    *) echo volume ;;
  esac
}
max_len_of() {
  case $1 in
    volume_* | dicom_*) echo 262144 ;;  # a few small slices or a small volume with its header
    *) echo 65536 ;;                    # text files
  esac
}

# Runs one target until its time is spent; after a finding it starts again for the time left (at
# most 20 findings), so a long run reports more than the first. Writes BUILD_DIR/results/<target>:
# "executions seconds findings".
fuzz_target() {
  local target=$1 executions=0 findings=0 start log left status
  local corpus="$build_dir/corpus/$target" artifacts="$build_dir/artifacts/$target"
  rm -rf "$artifacts"  # the last run's findings (save them before running again)
  mkdir -p "$corpus" "$artifacts" "$build_dir/logs"
  log="$build_dir/logs/$target.log"
  : >"$log"
  start=$(date +%s)
  while :; do
    left=$((seconds - ($(date +%s) - start)))
    ((left > 0)) || break
    status=0
    "$build_dir/tests/fuzz/fuzz_$target" -max_total_time="$left" -timeout=10 -rss_limit_mb=2048 \
      -max_len="$(max_len_of "$target")" -dict="$root/tests/fuzz/dictionaries/$(dictionary_of "$target").dict" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 -close_fd_mask=1 \
      "$corpus" "$seeds/$target" >"$log.run" 2>&1 || status=$?
    # The executions: the final stats, or after a crash the last status line ("#1234 ...").
    local ran
    ran=$(grep -ao 'stat::number_of_executed_units: [0-9]*' "$log.run" | tail -1 | grep -o '[0-9]*$' || true)
    [[ -z $ran ]] && ran=$(grep -aoE '^#[0-9]+' "$log.run" | tail -1 | tr -d '#' || true)
    executions=$((executions + ${ran:-0}))
    cat "$log.run" >>"$log" && rm "$log.run"
    echo "--- end of run (exit $status) ---" >>"$log"
    ((status == 0)) && break
    # A finding leaves its input in the artifacts; an exit without one is a broken run (bad flags).
    if (($(find "$artifacts" -type f | wc -l) == findings)); then
      findings=-1
      break
    fi
    findings=$((findings + 1))
    ((findings < 20)) || break
  done
  echo "$executions $(($(date +%s) - start)) $findings" >"$build_dir/results/$target"
}

rm -rf "$build_dir/results"
mkdir -p "$build_dir/results"
jobs=$(nproc)
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  fuzz_target "$target" &
done
wait

# A target that crashed left its scratch folder (/dev/shm/angioray-fuzz-PID) behind.
for scratch in /dev/shm/angioray-fuzz-* "${TMPDIR:-/tmp}"/angioray-fuzz-*; do
  [[ -d $scratch ]] && ! kill -0 "${scratch##*-}" 2>/dev/null && rm -rf "$scratch"
done

failed=0
printf '%-20s %12s %8s %9s\n' target executions seconds findings
for target in "${targets[@]}"; do
  read -r executions secs findings <"$build_dir/results/$target"
  printf '%-20s %12s %8s %9s\n' "$target" "$executions" "$secs" "$findings"
  if ((findings < 0)); then
    failed=1
    echo "  the run failed without a finding:"
    tail -3 "$build_dir/logs/$target.log" | sed 's/^/  /'
  elif ((findings > 0)); then
    failed=1
    for artifact in "$build_dir/artifacts/$target"/*; do echo "  $artifact"; done
    grep -a -m3 -E 'ERROR: |SUMMARY: |fuzz_[a-z_]+: ' "$build_dir/logs/$target.log" | sed 's/^/  /' || true
  fi
done
echo "fuzz: build $((built - started)) s, seeds and runs $(($(date +%s) - built)) s, logs in $build_dir/logs"
exit $failed
