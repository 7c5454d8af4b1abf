#include "gui/app_state.h"

#include <cmath>
#include <filesystem>

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

nlohmann::json toJson(const AppState& state) { return nlohmann::json::parse(toJson(Session(state))); }

void applySessionState(AppState& state, const Session& session) {
  const std::string dataset = state.dataset;
  std::vector<std::string> recent = std::move(state.recentFiles);
  static_cast<Session&>(state) = session;
  state.dataset = dataset;
  state.recentFiles = std::move(recent);
  state.view.angleDeg = wrapDegrees(session.view.angleDeg);
}

bool isPhantomName(const std::string& dataset) { return dataset.rfind("phantom ", 0) == 0; }

std::string absoluteDataset(const std::string& dataset) {
  std::error_code error;
  if (isPhantomName(dataset) || !std::filesystem::exists(dataset, error)) return dataset;
  const std::filesystem::path absolute = std::filesystem::absolute(dataset, error);
  return error ? dataset : absolute.lexically_normal().string();
}

}  // namespace angio
