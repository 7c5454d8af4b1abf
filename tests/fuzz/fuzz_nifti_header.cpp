// libFuzzer target: the NIfTI header reader (io/nifti_header.h readNiftiHeader).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("nifti_header", data, size);
}
