#pragma once
// Showing a CPR: grey through a window/level, or colored through a transfer
// function so it harmonises with the DVR (thesis sec. 5.2.2), with the centerline marked and an
// arc-length ruler. Pixels the CPR does not sample are transparent black (A = 0), sampled ones
// opaque, so a projected CPR can be laid over the DVR image it registers with.
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/transfer_function.h"
#include "core/window_level.h"
#include "vessel/cpr_layout.h"

namespace angio {

// Presets (calibrated HU). "cta-lumen": contrast-filled lumen (~250-500 HU) mid-grey to white
// against soft tissue; "calcium": wide enough to tell calcified plaque (~700-1500+ HU) from the
// lumen beside it.
constexpr WindowLevel kCtaLumenWindow{800, 250};
constexpr WindowLevel kCalciumWindow{1800, 700};
std::optional<WindowLevel> windowPreset(const std::string& name);  // "cta-lumen", "calcium"

struct CprDisplay {
  WindowLevel windowLevel = kCtaLumenWindow;
  std::optional<TransferFunction> tf;  // if set: TF color (rgb at the pixel's HU) instead of grey
  bool centerlineMarker = true;
  bool ruler = true;
  double rulerStepMm = 10;  // a tick every step, a label every 5 steps
};

// The arc-length ruler's ticks, every stepMm along each curve (a curve that continues a shared
// trunk starts after the trunk's last tick), a major one every fifth. `pixel` is on the curve (CPR
// pixel coordinates, centres at integers), `across` the unit normal to the curve there,
// (-along.y, along.x): towards -x where the curve runs down the image.
struct CprRulerTick {
  glm::dvec2 pixel{0.0}, across{0.0};
  double arcMm = 0;
  bool major = false;
  int path = 0;  // the curve's
};
std::vector<CprRulerTick> cprRulerTicks(const std::vector<CprCurve>& curves, double stepMm);

// Grey value of a HU under a window/level: clamp((HU - (level - window / 2)) / window, 0, 1).
float windowGrey(float hu, WindowLevel windowLevel);

// The color of a sampled pixel of `hu`: through `table` (= buildTable(*display.tf), when the
// display has a TF), else grey through the window; opaque.
glm::vec4 cprColor(float hu, const CprDisplay& display, const TfTable* table);

// Sampled HU (row-major width x height, NaN = not sampled) colored by cprColor, without marker or
// ruler: a CPR's pixels, or a cross-section's (vessel/cross_section.h).
Image coloredHu(int width, int height, const std::vector<float>& hu, const CprDisplay& display);

// hu: row-major layout.width x layout.height, NaN = not sampled (resampleCpr's output).
Image displayCpr(const CprLayout& layout, const std::vector<float>& hu, const CprDisplay& display);

}  // namespace angio
