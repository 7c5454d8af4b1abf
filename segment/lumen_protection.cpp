#include "segment/lumen_protection.h"

#include <algorithm>
#include <cmath>

namespace angio::segment {

namespace {

struct TaperedSegment {
  glm::dvec3 a{0.0}, b{0.0};  // volume frame, mm
  double ra = 0, rb = 0;

  bool contains(glm::dvec3 p) const {
    const glm::dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    const double r = glm::mix(ra, rb, t);
    const glm::dvec3 d = p - (a + t * ab);
    return glm::dot(d, d) <= r * r;
  }
};

void markSegment(std::vector<std::uint8_t>& flags, std::uint8_t bit, const Volume& volume,
                 const TaperedSegment& segment) {
  const double r = std::max(segment.ra, segment.rb);
  const glm::dvec3 lo = (glm::min(segment.a, segment.b) - r) / volume.spacing;
  const glm::dvec3 hi = (glm::max(segment.a, segment.b) + r) / volume.spacing;
  const glm::ivec3 first = glm::max(glm::ivec3(glm::ceil(lo)), glm::ivec3(0));
  const glm::ivec3 last = glm::min(glm::ivec3(glm::floor(hi)), volume.dims - 1);
  for (int k = first.z; k <= last.z; ++k)
    for (int j = first.y; j <= last.y; ++j)
      for (int i = first.x; i <= last.x; ++i)
        if (segment.contains(glm::dvec3(i, j, k) * volume.spacing))
          flags[volume.indexOf(i, j, k)] |= bit;
}

}  // namespace

void markLumen(std::vector<std::uint8_t>& flags, std::uint8_t bit, const Volume& volume,
               const Centerlines& centerlines, double marginMm) {
  const Centerlines inVolume =
      centerlines.frame == CenterlineFrame::volume ? centerlines : toVolumeFrame(centerlines, volume);
  for (const CenterlinePath& path : inVolume.paths) {
    for (std::size_t n = 0; n < path.points.size(); ++n) {
      const CenterlinePoint& a = path.points[n];
      const CenterlinePoint& b = path.points[std::min(n + 1, path.points.size() - 1)];
      markSegment(flags, bit, volume,
                  {a.positionMm, b.positionMm, std::max(a.radiusMm, 0.0) + marginMm,
                   std::max(b.radiusMm, 0.0) + marginMm});
    }
  }
}

}  // namespace angio::segment
