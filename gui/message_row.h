#pragma once
// A side-panel section's message row: always one row, empty when there is nothing to say, so the
// widgets below do not move under the pointer when an error, a warning or a note comes or goes.
// Of several messages the row shows the first that is not empty (callers order them error,
// warning, note); a message wider than the row is cut with "..." and shown whole in a tooltip.
#include <string>
#include <vector>

#include <imgui.h>

namespace angio {

enum class MessageKind { note, warning, error };

struct PanelMessage {
  MessageKind kind = MessageKind::note;
  std::string text;
};

// The first message with text (none: an empty one).
PanelMessage firstMessage(const std::vector<PanelMessage>& candidates);
// `text` cut to fit `width` pixels with the font's `measure`, "..." at the end; whole if it fits.
std::string fitToWidth(const std::string& text, float width, float (*measure)(const std::string&));

void drawMessageRow(const std::vector<PanelMessage>& candidates);
// `count` empty rows as tall as a widget row: where a choice shows fewer controls than another,
// so the rows below stay where they were.
void drawBlankWidgetRows(int count);

}  // namespace angio
