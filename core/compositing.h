#pragma once
// The per-sample arithmetic of the rendering model, shared by the reference and the fast
// raycaster so that both evaluate every sample with the same operations (and so the same bits).
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/view_geometry.h"
#include "core/volume.h"

namespace angio {

// Opacity per sample at distance osd voxel units: alpha = 1 - (1 - a)^osd (rendering model).
float opacityAtDistance(float opacityPerVoxel, double osd);

// The TF table with opacities corrected for the sample distance, computed once per frame.
using SampleTable = std::array<glm::vec4, kDensityLevels>;
SampleTable correctedTable(const TfTable& table, double osd);

// Interpolated density (>= 0) -> table entry: the nearest of the 4096 entries.
inline int tableIndex(float density) {
  return std::min(int(density + 0.5f), kDensityLevels - 1);
}

// Continuous voxel coordinates of the samples of one ray: q(k) = p(k delta) / spacing, written as
// origin/spacing + k * (delta d / spacing) so a sample costs one multiply-add per axis.
struct RaySamples {
  glm::dvec3 originQ{0.0};
  glm::dvec3 stepQ{0.0};

  RaySamples(const Volume& volume, const ViewGeometry& view, const glm::dvec3& originMm)
      : originQ(originMm / volume.spacing), stepQ(view.sampleMm * view.viewDir / volume.spacing) {}
  glm::dvec3 at(long k) const { return originQ + double(k) * stepQ; }
};

inline float shadingFactor(const Shading& shading, glm::vec3 gradient, glm::vec3 viewDir) {
  if (!shading.enabled) return 1.f;
  const float length = glm::length(gradient);
  if (length < 1e-3f) return 1.f;
  return float(shading.ka + shading.kd * std::abs(glm::dot(gradient, viewDir)) / length);
}

// Front-to-back accumulation state of one ray.
struct RayAccumulator {
  glm::vec3 colour{0.f};
  float opacity = 0.f;

  // C += (1 - A) alpha s rgb, A += (1 - A) alpha.
  void add(const glm::vec4& rgba, float shade) {
    const float weight = (1.f - opacity) * rgba.a;
    colour += weight * shade * glm::vec3(rgba);
    opacity += weight;
  }
  glm::vec4 pixel() const { return glm::vec4(colour, opacity); }
};

// MIP: the maximum density through the window as grey (rendering model).
glm::vec4 mipPixel(float maximumDensity, const MipWindow& window);

}  // namespace angio
