// libFuzzer target: one DICOM slice, as a file and as a folder (io/volume_reader.h, io/dicom_series.h).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("dicom_slice", data, size);
}
