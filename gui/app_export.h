#pragma once
// "Export image": the current view rendered at the high level's sampling with a chosen image
// sampling distance (e.g. 0.25 for print), as the window shows it (render/export.h writes it).
#include <filesystem>
#include <string>
#include <vector>

#include "gui/document.h"
#include "gui/label_change.h"
#include "render/recipe_json.h"

namespace angio {

// What an export of the current view renders: the state's view and TF at the high level's
// sampling with image sampling distance `isd`; plain DVR/MIP (the app adds its VesselGlyph and
// hybrid recipes when it shows them).
RenderRecipe exportSidecar(const Document& state, const std::string& dataset, double isd);

// Labels changed since they were loaded or saved: an export writes them beside itself, so its
// sidecar names a label file that reproduces the image (`render --params`).
struct UnsavedLabels {
  std::vector<LabelStyle> styles;
  LabelCounts voxels{};
};

// Writes `labels` to `file` (a .seg.nrrd) and makes `recipe` name it.
void saveLabelsFor(RenderRecipe& recipe, const Volume& volume, const UnsavedLabels& labels,
                   const std::filesystem::path& file);

// The suffix of the file an export writes unsaved vessel paths to (IMAGE.centerlines.vtp: vmtk's
// format, which keeps the names and the radii).
constexpr const char* kBesideCenterlines = ".centerlines.vtp";

// Writes the unsaved vessel paths (`physical`) to `file`, makes `recipe`'s VesselGlyph name it and
// returns what the file reads back in the volume frame: what the export and `render --params` use.
Centerlines saveCenterlinesFor(RenderRecipe& recipe, const Volume& volume, const Centerlines& physical,
                               const std::filesystem::path& file);

}  // namespace angio
