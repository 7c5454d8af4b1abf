// libFuzzer target: the Slicer markups reader (io/centerline_markups.h parseCenterlinesMarkups).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("centerline_markups", data, size);
}
