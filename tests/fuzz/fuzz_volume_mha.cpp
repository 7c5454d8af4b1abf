// libFuzzer target: a whole .mha volume read (io/volume_reader.h readVolume).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("volume_mha", data, size);
}
