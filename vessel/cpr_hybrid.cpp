#include "vessel/cpr_hybrid.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <opencv2/imgproc.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "vessel/cpr_resample.h"

namespace angio {

namespace {

// The CPR's weight per pixel: 1 on the footprint, fading to 0 over the transition band beyond it.
std::vector<float> cprWeights(const std::vector<std::uint8_t>& footprint, int width, int height,
                              const HybridCompositing& settings) {
  std::vector<float> weights(footprint.size());
  for (std::size_t n = 0; n < footprint.size(); ++n) weights[n] = footprint[n] ? 1.f : 0.f;
  if (settings.transitionMm <= 0 || footprint.empty()) return weights;
  // Exact Euclidean distance (pixels) of every non-footprint pixel to the nearest footprint pixel.
  cv::Mat outsideMask(height, width, CV_8U);
  for (std::size_t n = 0; n < footprint.size(); ++n) outsideMask.data[n] = footprint[n] ? 0 : 255;
  cv::Mat distance;
  cv::distanceTransform(outsideMask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const double band = settings.transitionMm / settings.pixelMm;  // in pixels
  for (int y = 0; y < height; ++y) {
    const float* row = distance.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      float& weight = weights[std::size_t(y) * width + x];
      if (weight == 0.f) weight = float(std::max(0.0, 1.0 - row[x] / band));
    }
  }
  return weights;
}

void checkSizes(const Image& dvr, int cprWidth, int cprHeight,
                const std::vector<std::uint8_t>& footprint, const HybridCompositing& settings) {
  if (cprWidth != dvr.width || cprHeight != dvr.height ||
      footprint.size() != std::size_t(dvr.width) * dvr.height)
    throw std::invalid_argument("hybrid: the DVR image, the CPR and the focus footprint differ in size");
  if (!(settings.transitionMm >= 0) || !(settings.pixelMm > 0))
    throw std::invalid_argument("hybrid: the transition must be >= 0 mm and the pixel size > 0");
}

// The CPR color over the DVR color with the CPR's weight in (0, 1].
glm::vec4 blend(glm::vec4 dvr, glm::vec4 cpr, float weight) {
  return weight >= 1.f ? cpr : (1.f - weight) * dvr + weight * cpr;
}

}  // namespace

std::vector<std::uint8_t> focusFootprint(const RayRegions& regions) {
  std::vector<std::uint8_t> footprint(std::size_t(regions.width) * regions.height, 0);
  if (regions.rayBegin.size() != footprint.size() + 1) return footprint;
  for (std::size_t n = 0; n < footprint.size(); ++n) {
    for (std::uint32_t i = regions.rayBegin[n]; i < regions.rayBegin[n + 1]; ++i)
      if (regions.intervals[i].region == Region::focus) footprint[n] = 1;
  }
  return footprint;
}

Image compositeHybrid(const Image& dvr, const Image& cpr, const std::vector<std::uint8_t>& footprint,
                      const HybridCompositing& settings) {
  checkSizes(dvr, cpr.width, cpr.height, footprint, settings);
  const std::vector<float> weights = cprWeights(footprint, dvr.width, dvr.height, settings);
  Image out = dvr;
  for (std::size_t n = 0; n < out.pixels.size(); ++n) {
    const float weight = weights[n] * cpr.pixels[n].a;
    if (weight > 0.f) out.pixels[n] = blend(dvr.pixels[n], cpr.pixels[n], weight);
  }
  return out;
}

void compositeCprInPlace(Image& dvr, const Volume& volume, const CprLayout& layout,
                         const std::vector<std::uint8_t>& footprint, const CprDisplay& display,
                         const HybridCompositing& settings) {
  checkSizes(dvr, layout.width, layout.height, footprint, settings);
  if (volume.voxelCount() == 0) return;  // nothing sampled
  // A hard cut's weights are the footprint itself (no full-size copy).
  const std::vector<float> weights = settings.transitionMm > 0
                                         ? cprWeights(footprint, dvr.width, dvr.height, settings)
                                         : std::vector<float>{};
  const auto weightAt = [&](std::size_t n) {
    return weights.empty() ? (footprint[n] ? 1.f : 0.f) : weights[n];
  };
  const std::optional<TfTable> table =
      display.tf ? std::optional<TfTable>(buildTable(*display.tf)) : std::nullopt;
  // Spans never overlap, so each writes its own pixels.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layout.spans.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t s = range.begin(); s < range.end(); ++s) {
                        const CprSpan& span = layout.spans[s];
                        const std::size_t row = std::size_t(span.row) * layout.width;
                        for (int x = span.x0; x < span.x1; ++x) {
                          const float weight = weightAt(row + x);
                          if (weight <= 0.f) continue;
                          const float hu = trilinearHu(volume, span.pointMm(x));
                          if (std::isnan(hu)) continue;  // displayCpr leaves it transparent
                          glm::vec4& pixel = dvr.pixels[row + x];
                          pixel = blend(pixel, cprColor(hu, display, table ? &*table : nullptr), weight);
                        }
                      }
                    });
}

}  // namespace angio
