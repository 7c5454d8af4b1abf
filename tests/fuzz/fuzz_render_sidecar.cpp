// libFuzzer target: the render sidecar reader (render/recipe_json.h parseRenderSidecar).
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return angio::fuzz::fuzzTarget("render_sidecar", data, size);
}
