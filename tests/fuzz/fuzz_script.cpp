// libFuzzer target: the headless script reader (gui/app_script.h parseScript).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("script", data, size);
}
