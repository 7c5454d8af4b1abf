#pragma once
// Where headless scripts click a widget the state report's layout names ([x0, y0, x1, y1] in
// window pixels), as the script's "[x, y]" text.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace angio::test_support {

// A point `fraction` of the way across the widget, at its middle height.
inline std::string across(const nlohmann::json& rect, float fraction) {
  char text[64];
  const float x0 = rect[0].get<float>(), x1 = rect[2].get<float>();
  std::snprintf(text, sizeof text, "[%.1f, %.1f]", x0 + (x1 - x0) * fraction,
                (rect[1].get<float>() + rect[3].get<float>()) / 2);
  return text;
}
inline std::string middleOf(const nlohmann::json& rect) { return across(rect, 0.5f); }
// The box of a checkbox or radio button.
inline std::string leftEnd(const nlohmann::json& rect) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.1f, %.1f]", rect[0].get<float>() + 8,
                (rect[1].get<float>() + rect[3].get<float>()) / 2);
  return text;
}

}  // namespace angio::test_support
