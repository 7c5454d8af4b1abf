#include "gui/app_export.h"

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

}  // namespace angio
