#pragma once
// The Rendering section: DVR or MIP; MIP's window/level (with the CTA, bone and soft-tissue
// windows), DVR's shading. Returns the edited settings when a widget changed them.
#include <optional>

#include "gui/workstation.h"

namespace angio {

std::optional<RenderingEdit> drawRenderingPanel(const Document& document);

}  // namespace angio
