#include "gui/document.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "render/label_styles.h"
#include "render/region_tfs.h"

namespace angio {

const char* cprColoringName(CprColoring coloring) {
  constexpr const char* kNames[] = {"cta-lumen", "calcium", "focus-tf"};
  return kNames[int(coloring)];
}

const char* tfTargetName(TfTarget target) {
  constexpr const char* kNames[] = {"main", "focus", "context"};
  return kNames[int(target)];
}

const char* followingTfLabel(TfTarget region) {
  return region == TfTarget::context ? "main TF, faded" : "main TF";
}

TransferFunction regionTf(const VesselGlyphState& vesselGlyph, TfTarget region,
                          const TransferFunction& main) {
  switch (region) {
    case TfTarget::focus: return vesselGlyph.focusFollowsMain ? main : vesselGlyph.focusTf;
    case TfTarget::context:
      return vesselGlyph.contextFollowsMain ? followingContextTf(main) : vesselGlyph.contextTf;
    case TfTarget::main: break;
  }
  return main;
}

TransferFunction tfOf(const Document& document, TfTarget target) {
  return regionTf(document.vesselGlyph, target, document.tf);
}

bool followsMainTf(const Document& document, TfTarget target) {
  switch (target) {
    case TfTarget::focus: return document.vesselGlyph.focusFollowsMain;
    case TfTarget::context: return document.vesselGlyph.contextFollowsMain;
    case TfTarget::main: break;
  }
  return false;
}

const std::string& presetOf(const Document& document, TfTarget target) {
  switch (target) {
    case TfTarget::focus: return document.vesselGlyph.focusPreset;
    case TfTarget::context: return document.vesselGlyph.contextPreset;
    case TfTarget::main: break;
  }
  return document.tfPreset;
}

TransferFunction renderedTf(const Document& document) {
  TransferFunction tf = document.tf;
  if (document.labels.showRemoved) tf.labels = withRemovedShown(std::move(tf.labels));
  return tf;
}

RenderParams renderParamsOf(const Document& document) {
  RenderParams params;
  params.axis = document.view.axis;
  params.angleDeg = document.view.angleDeg;
  params.shading = document.shading;
  params.compositing = document.mode;
  params.mip = {document.tf.mipWindow, document.tf.mipLevel};
  return params;
}

void addRecentFile(std::vector<std::string>& recent, const std::string& path) {
  recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
  recent.insert(recent.begin(), path);
  if (recent.size() > kMaxRecentFiles) recent.resize(kMaxRecentFiles);
}

Centerlines centerlinesOf(const VesselsState& vessels) {
  Centerlines centerlines;
  centerlines.source = vessels.file.empty() ? "traced paths" : vessels.file;
  for (const VesselPath& path : vessels.paths)
    if (path.centerline.points.size() >= 2) centerlines.paths.push_back(path.centerline);
  return centerlines;
}

bool isPhantomName(const std::string& dataset) { return dataset.rfind("phantom ", 0) == 0; }

std::string absoluteDataset(const std::string& dataset) {
  std::error_code error;
  if (isPhantomName(dataset) || !std::filesystem::exists(dataset, error)) return dataset;
  const std::filesystem::path absolute = std::filesystem::absolute(dataset, error);
  return error ? dataset : absolute.lexically_normal().string();
}

}  // namespace angio
