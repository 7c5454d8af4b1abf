#pragma once
// Analytic raycaster tests: a TF that shows every density from -900 HU up with one color and
// opacity (a block of 0 HU in air then shows uniformly), and sampling whose pixel opacity is
// 1 - (1 - a)^n for the n samples of a ray (nearest, osd 1, no shading, no early termination).
#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/transfer_function.h"

namespace angio::test_support {

inline TfTable constantTable(double opacity, glm::vec3 color) {
  TransferFunction tf;
  tf.points = {{-1024, color, 0}, {-901, color, 0}, {-900, color, opacity}, {3071, color, opacity}};
  return buildTable(tf);
}

inline RenderParams plainParams() {
  RenderParams p;
  p.sampling = {1.0, 1.0, Filter::nearest, 1.0};
  p.shading.enabled = false;
  return p;
}

}  // namespace angio::test_support
