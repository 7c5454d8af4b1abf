#pragma once
// The per-sample arithmetic of the rendering model, shared by the reference and the fast
// raycaster so that both evaluate every sample with the same operations (and so the same bits).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "core/label_tables.h"
#include "core/region_intervals.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/view_geometry.h"
#include "core/volume.h"

namespace angio {

// Opacity per sample at distance osd voxel units: alpha = 1 - (1 - a)^osd (rendering model).
float opacityAtDistance(float opacityPerVoxel, double osd);

// The same opacity per voxel unit as an extinction coefficient, tau = -ln(1 - a) per voxel unit
// (alpha = 1 - exp(-tau osd)), for the approximations that integrate along a ray. Capped where a is
// 1 (tau infinite) so sums of it stay finite: 0.3 voxel units through it still give alpha 1 - 6e-6.
constexpr double kMaxExtinction = 40.0;
double extinctionPerVoxel(float opacityPerVoxel);

// The TF table with opacities corrected for the sample distance, computed once per frame.
using SampleTable = std::array<glm::vec4, kDensityLevels>;
SampleTable correctedTable(const TfTable& table, double osd);

// The TFs of a frame by region (VesselGlyph, thesis ch. 5): focus and context of each ray from
// RayRegions, everything else "outside". Plain DVR is the case without regions, where every sample
// is outside and the outside TF is the TF: VG-DVR generalises DVR.
// Labels (rendering model, "Labels") apply in every region: a hidden label is cut out everywhere,
// and a label's own TF replaces the TF of whatever region the sample is in (a clipped region
// stays clipped).
struct RegionTables {
  const RayRegions* regions = nullptr;  // none: every sample is outside
  const TfTable* focus = nullptr;
  const TfTable* context = nullptr;
  const TfTable* outside = nullptr;     // none: the outside is clipped (not rendered)
  const LabelTables* labels = nullptr;  // none: every label as unlabelled voxels

  // True iff some label renders differently from unlabelled voxels.
  bool labelsActive() const { return labels && labels->active(); }
  // How voxels read: hidden labels as density 0 (none without labels).
  MaskedDensity density() const { return labels ? labels->density() : LabelTables().density(); }
};

inline RegionTables singleTable(const TfTable& table) { return {nullptr, nullptr, nullptr, &table}; }

// The region and label TFs with opacities corrected for the sample distance, once per frame.
struct FrameTables {
  SampleTable focus{}, context{}, outside{};
  bool hasFocus = false, hasContext = false, hasOutside = false;
  std::vector<SampleTable> ownTables;    // the labels' own TFs
  std::array<int, kLabelCount> ownSlot;  // per label: its index in ownTables, -1 = none

  // The table for a region, or nullptr where the region is not rendered.
  const SampleTable* of(Region region) const {
    switch (region) {
      case Region::focus: return hasFocus ? &focus : nullptr;
      case Region::context: return hasContext ? &context : nullptr;
      case Region::outside: return hasOutside ? &outside : nullptr;
    }
    return nullptr;
  }
  // The table for a sample whose nearest voxel has `label`, or nullptr where not rendered.
  const SampleTable* of(Region region, int label) const {
    const SampleTable* table = of(region);
    return table && ownSlot[label] >= 0 ? &ownTables[ownSlot[label]] : table;
  }
};
FrameTables frameTables(const RegionTables& tables, double osd);

// Walks one ray's sorted intervals as the sample depth grows: amortised O(1) per sample.
class RegionCursor {
 public:
  RegionCursor() = default;  // no regions: every sample is outside
  RegionCursor(const RayRegions* regions, int x, int y) {
    if (!regions || regions->rayBegin.empty()) return;
    const std::size_t n = std::size_t(y) * regions->width + x;
    next_ = regions->intervals.data() + regions->rayBegin[n];
    end_ = regions->intervals.data() + regions->rayBegin[n + 1];
  }
  Region at(double t) {
    while (next_ != end_ && t >= double(next_->end)) ++next_;
    return next_ != end_ && t >= double(next_->begin) ? next_->region : Region::outside;
  }
  // After at(t): the depth where the region next changes (the end of the interval holding t, or
  // the begin of the next one), infinity when t is beyond every interval.
  double nextChange(double t) const {
    if (next_ == end_) return std::numeric_limits<double>::infinity();
    return t >= double(next_->begin) ? double(next_->end) : double(next_->begin);
  }

 private:
  const RegionInterval* next_ = nullptr;
  const RegionInterval* end_ = nullptr;
};

// Interpolated density (>= 0) -> table entry: the nearest of the 4096 entries.
inline int tableIndex(float density) { return std::min(int(density + 0.5f), kDensityLevels - 1); }

// originQ + k stepQ with one rounding per axis (a fused multiply-add), whatever the compiler would
// contract: every path that places samples (the raycasters, the fast one's SIMD lanes, adaptive
// sampling) gets the same bits, so a ray through voxel boundaries rounds alike in all of them.
inline glm::dvec3 samplePosition(const glm::dvec3& originQ, const glm::dvec3& stepQ, double k) {
  return {std::fma(k, stepQ.x, originQ.x), std::fma(k, stepQ.y, originQ.y),
          std::fma(k, stepQ.z, originQ.z)};
}

// Continuous voxel coordinates of the samples of one ray: q(k) = p(k delta) / spacing, written as
// origin/spacing + k * (delta d / spacing) so a sample costs one multiply-add per axis.
struct RaySamples {
  glm::dvec3 originQ{0.0};
  glm::dvec3 stepQ{0.0};

  RaySamples(const Volume& volume, const ViewGeometry& view, const glm::dvec3& originMm)
      : originQ(originMm / volume.spacing), stepQ(view.sampleMm * view.viewDir / volume.spacing) {}
  glm::dvec3 at(long k) const { return samplePosition(originQ, stepQ, double(k)); }
};

// ka + kd |g . v| / |g|, or 1 where |g| < 1e-3. Every operation is written out (the sums as fused
// multiply-adds, x first, in float) so that the fast raycaster's eight-lane shading
// (core/sample_batch.h) gives the same bits whatever the compiler contracts.
inline float shadingFactor(const Shading& shading, glm::vec3 gradient, glm::vec3 viewDir) {
  if (!shading.enabled) return 1.f;
  const glm::vec3 g = gradient;
  const float length = std::sqrt(std::fma(g.z, g.z, std::fma(g.y, g.y, g.x * g.x)));
  if (length < 1e-3f) return 1.f;
  const float facing = std::fma(g.z, viewDir.z, std::fma(g.y, viewDir.y, g.x * viewDir.x));
  return float(shading.ka) + float(shading.kd) * std::abs(facing) / length;
}

// Front-to-back accumulation state of one ray.
struct RayAccumulator {
  glm::vec3 color{0.f};
  float opacity = 0.f;

  // C += (1 - A) alpha s rgb, A += (1 - A) alpha.
  void add(const glm::vec4& rgba, float shade) {
    const float weight = (1.f - opacity) * rgba.a;
    color += weight * shade * glm::vec3(rgba);
    opacity += weight;
  }
  glm::vec4 pixel() const { return glm::vec4(color, opacity); }
};

// MIP: the maximum density through the window as grey (rendering model).
glm::vec4 mipPixel(float maximumDensity, const MipWindow& window);

}  // namespace angio
