// libFuzzer target: the MetaImage header reader (io/metaimage_header.h readMetaImageHeader).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("metaimage_header", data, size);
}
