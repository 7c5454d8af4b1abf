#include "gui/app_export.h"

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

}  // namespace angio
