// Headless scripts as parsed: the modifiers a wheel or a drag step holds, and a bad one as an
// error naming the script and the step.
#include <gtest/gtest.h>

#include "gui/app_script.h"
#include "io/input_error.h"

namespace angio {
namespace {

TEST(GuiScript, AWheelOrDragHoldsTheModifiersItNames) {
  const std::vector<ScriptStep> steps = parseScript(
      R"([{"wheel": {"at": [1, 2], "delta": -1, "hold": "Ctrl"}},
          {"drag": {"from": [1, 2], "to": [3, 4], "hold": "Ctrl+Shift"}},
          {"drag": {"from": [1, 2], "to": [3, 4]}}])",
      "s.json");
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_TRUE(steps[0].ctrl);
  EXPECT_FALSE(steps[0].shift);
  EXPECT_TRUE(steps[1].ctrl && steps[1].shift);
  EXPECT_FALSE(steps[2].ctrl || steps[2].shift);
}

TEST(GuiScript, AnUnknownModifierIsAnErrorNamingTheScriptAndTheStep) {
  try {
    parseScript(R"([{"move": [1, 1]}, {"wheel": {"at": [1, 2], "hold": "Alt"}}])", "s.json");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("s.json"), std::string::npos) << message;
    EXPECT_NE(message.find("step 2"), std::string::npos) << message;
    EXPECT_NE(message.find("hold"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace angio
