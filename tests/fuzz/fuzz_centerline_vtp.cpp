// libFuzzer target: the centerline .vtp reader (io/centerline_vtp.h parseCenterlinesVtp).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("centerline_vtp", data, size);
}
