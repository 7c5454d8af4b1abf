#include "vessel/cpr_resample.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/volume_sampling.h"
#include "core/voxel.h"

namespace angio {

namespace {

void resampleTrilinear(const Volume& volume, const CprSpan& span, float* row) {
  for (int x = span.x0; x < span.x1; ++x) row[x] = trilinearHu(volume, span.pointMm(x));
}

// The densities (label bits masked off) of voxels [i0, i0 + width) x [j0, j0 + height) of slice k.
cv::Mat sliceDensities(const Volume& volume, int i0, int j0, int width, int height, int k) {
  cv::Mat slice(height, width, CV_32F);
  for (int v = 0; v < height; ++v) {
    const Voxel* voxel = volume.voxels.data() + volume.indexOf(i0, j0 + v, k);
    float* out = slice.ptr<float>(v);
    for (int u = 0; u < width; ++u) out[u] = float(densityOf(voxel[u]));
  }
  return slice;
}

// Points [first, last) of `cells` share the slice pair (k, k + 1): one remap per slice, then the
// blend along k.
void remapBetweenSlices(const Volume& volume, const std::vector<Cell>& cells,
                        const std::vector<glm::dvec3>& q, std::size_t first, std::size_t last,
                        float* out) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (std::size_t n = first; n < last; ++n) {
    lo = glm::min(lo, q[n]);
    hi = glm::max(hi, q[n]);
  }
  const glm::ivec3 last3 = volume.dims - 1;
  const int i0 = std::clamp(int(std::floor(lo.x)), 0, last3.x);
  const int j0 = std::clamp(int(std::floor(lo.y)), 0, last3.y);
  const int i1 = std::clamp(int(std::floor(hi.x)) + 1, 0, last3.x);
  const int j1 = std::clamp(int(std::floor(hi.y)) + 1, 0, last3.y);
  const int k = cells[first].base.z;
  const int kNext = std::min(k + 1, last3.z);
  const int count = int(last - first);
  cv::Mat mapX(1, count, CV_32F), mapY(1, count, CV_32F);
  for (int n = 0; n < count; ++n) {
    mapX.at<float>(n) = float(q[first + n].x - i0);
    mapY.at<float>(n) = float(q[first + n].y - j0);
  }
  cv::Mat below, above;
  const int width = i1 - i0 + 1, height = j1 - j0 + 1;
  cv::remap(sliceDensities(volume, i0, j0, width, height, k), below, mapX, mapY, cv::INTER_LINEAR,
            cv::BORDER_REPLICATE);
  cv::remap(sliceDensities(volume, i0, j0, width, height, kNext), above, mapX, mapY, cv::INTER_LINEAR,
            cv::BORDER_REPLICATE);
  for (int n = 0; n < count; ++n) {
    const float a = below.at<float>(n), b = above.at<float>(n);
    out[n] = a + (b - a) * cells[first + n].frac.z - float(kHuOffset);
  }
}

void resampleRemap(const Volume& volume, const CprSpan& span, float* row) {
  const std::size_t count = std::size_t(span.x1 - span.x0);
  std::vector<glm::dvec3> q(count);
  std::vector<Cell> cells(count);
  for (std::size_t n = 0; n < count; ++n) {
    q[n] = span.pointMm(span.x0 + int(n)) / volume.spacing;
    cells[n] = cellAt(volume, q[n]);  // the same slice pair and k fraction as the 3-D filter
  }
  for (std::size_t first = 0; first < count;) {
    std::size_t last = first + 1;
    while (last < count && cells[last].base.z == cells[first].base.z) ++last;
    remapBetweenSlices(volume, cells, q, first, last, row + span.x0 + first);
    first = last;
  }
}

}  // namespace

float trilinearHu(const Volume& volume, glm::dvec3 pointMm) {
  return trilinearDensity(volume, cellAt(volume, pointMm / volume.spacing)) - float(kHuOffset);
}

const char* toString(CprResampler resampler) {
  return resampler == CprResampler::trilinear ? "trilinear" : "opencv-remap";
}

std::optional<CprResampler> parseCprResampler(const std::string& text) {
  for (CprResampler r : {CprResampler::trilinear, CprResampler::opencvRemap}) {
    if (text == toString(r)) return r;
  }
  return std::nullopt;
}

std::vector<float> resampleCpr(const Volume& volume, const CprLayout& layout, CprResampler resampler) {
  std::vector<float> hu(std::size_t(layout.width) * layout.height,
                        std::numeric_limits<float>::quiet_NaN());
  if (volume.voxelCount() == 0) return hu;
  // Spans never overlap, so each writes its own pixels.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layout.spans.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t n = range.begin(); n < range.end(); ++n) {
                        const CprSpan& span = layout.spans[n];
                        float* row = hu.data() + std::size_t(span.row) * layout.width;
                        if (resampler == CprResampler::trilinear) {
                          resampleTrilinear(volume, span, row);
                        } else {
                          resampleRemap(volume, span, row);
                        }
                      }
                    });
  return hu;
}

}  // namespace angio
