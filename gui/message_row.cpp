#include "gui/message_row.h"

namespace angio {

namespace {

ImVec4 colorOf(MessageKind kind) {
  if (kind == MessageKind::error) return ImVec4(1, 0.45f, 0.35f, 1);
  if (kind == MessageKind::warning) return ImVec4(1, 0.8f, 0.4f, 1);
  return ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
}

float imguiTextWidth(const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; }

}  // namespace

PanelMessage firstMessage(const std::vector<PanelMessage>& candidates) {
  for (const PanelMessage& message : candidates)
    if (!message.text.empty()) return message;
  return {};
}

std::string fitToWidth(const std::string& text, float width, float (*measure)(const std::string&)) {
  if (measure(text) <= width) return text;
  // Binary search on the kept prefix: the longest that fits with the ellipsis.
  std::size_t fits = 0, fails = text.size();
  while (fails - fits > 1) {
    const std::size_t middle = (fits + fails) / 2;
    if (measure(text.substr(0, middle) + "...") <= width) fits = middle;
    else fails = middle;
  }
  return text.substr(0, fits) + "...";
}

void drawMessageRow(const std::vector<PanelMessage>& candidates) {
  const PanelMessage message = firstMessage(candidates);
  const float width = ImGui::GetContentRegionAvail().x;
  const std::string shown = fitToWidth(message.text, width, imguiTextWidth);
  ImGui::PushStyleColor(ImGuiCol_Text, colorOf(message.kind));
  ImGui::TextUnformatted(shown.c_str());  // an empty text still takes its row
  ImGui::PopStyleColor();
  if (shown != message.text && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", message.text.c_str());
}

void drawBlankWidgetRows(int count) {
  for (int n = 0; n < count; ++n) ImGui::Dummy(ImVec2(1, ImGui::GetFrameHeight()));
}

}  // namespace angio
