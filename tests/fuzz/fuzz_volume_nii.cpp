// libFuzzer target: a whole .nii volume read (io/volume_reader.h readVolume).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("volume_nii", data, size);
}
