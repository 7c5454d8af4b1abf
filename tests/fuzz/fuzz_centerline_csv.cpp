// libFuzzer target: the centerline CSV reader (io/centerline_csv.h parseCenterlinesCsv).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("centerline_csv", data, size);
}
