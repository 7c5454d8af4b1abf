#!/usr/bin/env bash
# The whole test suite from a fresh clone: install what is missing, build and run every test in
# Release, then the libraries' tests once more built with clang's AddressSanitizer +
# UndefinedBehaviorSanitizer, and a short libFuzzer run of every file reader.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

"$root/scripts/setup.sh"
# The tree is formatted with .clang-format (clang-format -i on the files you changed).
(cd "$root" && git ls-files '*.h' '*.cpp' | xargs clang-format --dry-run --Werror)

"$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release
ctest --test-dir "$root/build" --output-on-failure -j"$jobs"

# The sanitizer pass: the libraries' tests (renderer, vessels, CPR, segmentation, loaders,
# exports) and the file readers' libFuzzer targets, in one clang build with AddressSanitizer +
# UndefinedBehaviorSanitizer at -O1 with line tables only, to keep CI within its 30 minutes; the
# GUI's and the command line's tests run in Release. Three full-size cases run in Release only,
# their code goes through ASan on smaller data: tracing the full-size phantom (PhantomTracing: a
# 1.3 GB distance map; the synthetic tubes), bone removal on it (3 min at -O1 with ASan; the small
# phantom's cases) and the fast raycaster against the reference on the real aorta (the phantom's
# and the clipped, labelled and VesselGlyph cases).
sanitized="$root/build-fuzz"
"$root/scripts/build.sh" "$sanitized" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DANGIORAY_FUZZ=ON \
  -- core_tests vessel_tests io_tests phantom_tests segment_tests render_tests
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions="$root/tests/ubsan.supp" \
LSAN_OPTIONS=suppressions="$root/tests/lsan.supp" \
  ctest --test-dir "$sanitized" --output-on-failure -j"$jobs" \
  -E '^(gui|cli)_tests|PhantomTracing|BoneRemoval.FindsThePhantomsBoneAndTableButNotItsLumen|FastRaycaster.MatchesReferenceOnRealAorta'

# Every reader's fuzz target for a short run (scripts/fuzz-long.sh: an hour each).
"$root/scripts/fuzz.sh" "$sanitized" "${ANGIORAY_CI_FUZZ_SECONDS:-10}" tf centerline_csv centerline_vtp \
  centerline_markups render_sidecar session script metaimage_header nifti_header volume_mha volume_mhd \
  volume_nrrd volume_nii dicom_slice dicom_series
