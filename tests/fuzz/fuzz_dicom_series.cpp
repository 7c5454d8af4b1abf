// libFuzzer target: a DICOM series folder, slices separated by kSliceSeparator (io/dicom_series.h).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("dicom_series", data, size);
}
