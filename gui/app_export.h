#pragma once
// "Export image": the current view rendered at the high level's sampling with a chosen image
// sampling distance (e.g. 0.25 for print), as the window shows it (render/export.h writes it).
#include <string>

#include "gui/document.h"
#include "render/recipe_json.h"

namespace angio {

// What an export of the current view renders: the state's view and TF at the high level's
// sampling with image sampling distance `isd`; plain DVR/MIP (the app adds its VesselGlyph and
// hybrid recipes when it shows them).
RenderRecipe exportSidecar(const Document& state, const std::string& dataset, double isd);

}  // namespace angio
