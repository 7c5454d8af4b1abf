#!/usr/bin/env bash
# The whole test suite from a fresh clone: install what is missing, build and run every test in
# Release, then once more built with AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

"$root/scripts/setup.sh"
# The tree is formatted with .clang-format (clang-format -i on the files you changed).
(cd "$root" && git ls-files '*.h' '*.cpp' | xargs clang-format --dry-run --Werror)

"$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release
ctest --test-dir "$root/build" --output-on-failure -j"$jobs"

# The sanitizer pass covers the libraries' tests (renderer, vessels, CPR, segmentation, loaders,
# exports), built at -O1 with line tables only, to keep CI within its 30 minutes; the GUI's tests
# run in Release. Tracing the full-size phantom (PhantomTracing: a 1.3 GB distance map, minutes at
# -O1 with ASan) runs in Release only; the synthetic tubes take the same code through ASan.
"$root/scripts/build.sh" "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DANGIORAY_SANITIZE=ON -- core_tests vessel_tests io_tests phantom_tests segment_tests render_tests
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions="$root/tests/ubsan.supp" \
LSAN_OPTIONS=suppressions="$root/tests/lsan.supp" \
  ctest --test-dir "$root/build-asan" --output-on-failure -j"$jobs" -E '(gui|cli)_tests_NOT_BUILT|PhantomTracing'
