#include "gui/app_export.h"

#include "gui/vessel_files.h"
#include "render/label_styles.h"

namespace angio {

RenderRecipe exportSidecar(const Document& state, const std::string& dataset, double isd) {
  RenderRecipe sidecar;
  sidecar.dataset = absoluteDataset(dataset);
  sidecar.quality = Quality::high;
  sidecar.params = renderParamsOf(state);
  sidecar.params.sampling = state.levels[int(Quality::high)];
  sidecar.params.sampling.isd = isd;
  sidecar.tf = renderedTf(state);
  return sidecar;
}

void saveLabelsFor(RenderRecipe& recipe, const Volume& volume, const UnsavedLabels& labels,
                   const std::filesystem::path& file) {
  writeLabelFile(file, volume, labels.styles, labels.voxels);
  recipe.labels = std::filesystem::absolute(file).lexically_normal().string();
}

Centerlines saveCenterlinesFor(RenderRecipe& recipe, const Volume& volume, const Centerlines& physical,
                               const std::filesystem::path& file) {
  const Centerlines readBack = writeAndReadBack(physical, file);
  if (recipe.vesselGlyph)
    recipe.vesselGlyph->centerlines = std::filesystem::absolute(file).lexically_normal().string();
  return toVolumeFrame(readBack, volume);
}

}  // namespace angio
