#include "gui/app_state.h"

#include <cmath>

#include "io/tf_file.h"

namespace angio {

double wrapDegrees(double degrees) {
  const double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0 ? wrapped + 360.0 : wrapped;
}

RenderParams renderParamsOf(const AppState& state) {
  RenderParams params;
  params.axis = state.view.axis;
  params.angleDeg = state.view.angleDeg;
  params.shading = state.shading;
  params.compositing = state.mode;
  params.mip = {state.tf.mipWindow, state.tf.mipLevel};
  return params;
}

namespace {

nlohmann::json toJson(const Sampling& sampling) {
  return {{"isd", sampling.isd},
          {"osd", sampling.osd},
          {"filter", toString(sampling.filter)},
          {"ert", sampling.ert}};
}

}  // namespace

nlohmann::json toJson(const AppState& state) {
  const ViewState& v = state.view;
  nlohmann::json levels = nlohmann::json::object();
  for (int q = 0; q < kQualityLevels; ++q) levels[toString(Quality(q))] = toJson(state.levels[q]);
  return {
      {"dataset", state.dataset},
      {"view",
       {{"axis", toString(v.axis)},
        {"angle_deg", v.angleDeg},
        {"zoom", v.zoom},
        {"pan_px", {v.panPx.x, v.panPx.y}},
        {"degrees_per_pixel", v.degreesPerPixel},
        {"auto_spin", v.autoSpin},
        {"spin_degrees_per_second", v.spinDegreesPerSecond}}},
      {"transfer_function", nlohmann::json::parse(angio::toJson(state.tf))},
      {"tf_preset", state.tfPreset},
      {"mode", state.mode == Compositing::mip ? "mip" : "dvr"},
      {"shading", {{"enabled", state.shading.enabled}, {"ka", state.shading.ka}, {"kd", state.shading.kd}}},
      {"levels", levels},
  };
}

}  // namespace angio
