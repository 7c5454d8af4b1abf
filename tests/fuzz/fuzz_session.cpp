// libFuzzer target: the session file reader (gui/session_file.h parseSession).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("session", data, size);
}
