// libFuzzer target: the transfer-function JSON reader (io/tf_file.h parseTransferFunction).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("tf", data, size);
}
