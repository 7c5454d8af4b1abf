#pragma once
// The workstation's long-lived state: one plain struct, drawn from every frame and printable as
// JSON (it becomes the session file). Runtime things (textures, the worker) live in App.
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/progressive_renderer.h"
#include "core/render_params.h"
#include "core/transfer_function.h"

namespace angio {

struct ViewState {
  Axis axis = Axis::k;            // rotation axis (default: the patient's long axis)
  double angleDeg = 0;            // theta of the rendering model, kept in [0, 360)
  double zoom = 1;                // 1 = the whole volume fits the viewport
  glm::dvec2 panPx{0.0};          // image centre offset from the viewport centre, screen pixels
  double degreesPerPixel = 0.5;   // left-drag rotation speed
  bool autoSpin = false;
  double spinDegreesPerSecond = 30;
};

struct AppState {
  std::string dataset;  // file or folder, or "phantom IxJxK"
  ViewState view;
  TransferFunction tf;
  std::string tfPreset;  // preset id the TF came from, empty if edited or loaded from a file
  Compositing mode = Compositing::dvr;
  Shading shading;
  LevelSamplings levels = defaultLevelSamplings();
};

// theta wrapped into [0, 360).
double wrapDegrees(double degrees);

// The render parameters the state asks for (sampling left at its default: each level sets it).
RenderParams renderParamsOf(const AppState& state);

nlohmann::json toJson(const AppState& state);

}  // namespace angio
