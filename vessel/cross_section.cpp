#include "vessel/cross_section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "vessel/cpr_resample.h"

namespace angio {

namespace {

// upHint without its component along the unit tangent; a fallback axis when they are parallel.
glm::dvec3 inPlaneUp(glm::dvec3 tangent, glm::dvec3 upHint) {
  for (const glm::dvec3 hint : {upHint, glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0)}) {
    const glm::dvec3 up = hint - glm::dot(hint, tangent) * tangent;
    if (glm::length(up) > 1e-6 * std::max(glm::length(hint), 1e-300)) return glm::normalize(up);
  }
  return glm::normalize(glm::cross(tangent, glm::dvec3(1, 0, 0)));
}

bool insideDomain(const Volume& volume, glm::dvec3 pointMm) {
  const glm::dvec3 extent = glm::dvec3(volume.dims - 1) * volume.spacing;
  return glm::all(glm::greaterThanEqual(pointMm, glm::dvec3(0.0))) &&
         glm::all(glm::lessThanEqual(pointMm, extent));
}

glm::dvec3 pointAtArc(const CenterlinePath& path, const std::vector<double>& arcs, double arcMm) {
  const auto upper = std::upper_bound(arcs.begin(), arcs.end(), arcMm);
  const std::size_t n = std::clamp<std::size_t>(std::size_t(upper - arcs.begin()), 1, arcs.size() - 1);
  const double span = arcs[n] - arcs[n - 1];
  const double f = span > 0 ? std::clamp((arcMm - arcs[n - 1]) / span, 0.0, 1.0) : 0.0;
  return glm::mix(path.points[n - 1].positionMm, path.points[n].positionMm, f);
}

}  // namespace

PathPlace placeOnPath(const CenterlinePath& path, double arcMm) {
  if (path.points.size() < 2) throw std::invalid_argument("a path place needs 2 points");
  const std::vector<double> arcs = arcLengthsMm(path);
  const double arc = std::clamp(arcMm, 0.0, arcs.back());
  PathPlace place;
  place.pointMm = pointAtArc(path, arcs, arc);
  const glm::dvec3 chord = pointAtArc(path, arcs, std::min(arc + kTangentSpanMm / 2, arcs.back())) -
                           pointAtArc(path, arcs, std::max(arc - kTangentSpanMm / 2, 0.0));
  if (glm::length(chord) > 0) place.tangent = glm::normalize(chord);
  return place;
}

CrossSection sampleCrossSection(const Volume& volume, glm::dvec3 centreMm, glm::dvec3 tangent,
                                glm::dvec3 upHint, double extentMm, double pixelMm) {
  if (!(pixelMm > 0) || !(extentMm > 0) || !(glm::length(tangent) > 0))
    throw std::invalid_argument("cross-section: extent, pixel size and tangent must be positive");
  CrossSection section;
  const glm::dvec3 t = glm::normalize(tangent);
  section.vAxis = inPlaneUp(t, upHint);
  section.uAxis = glm::cross(section.vAxis, t);  // right-handed: u x v = t
  section.size = 2 * int(std::ceil(extentMm / pixelMm / 2)) + 1;
  section.pixelMm = pixelMm;
  section.centreMm = centreMm;
  section.hu.assign(std::size_t(section.size) * section.size, std::numeric_limits<float>::quiet_NaN());
  const double c = (section.size - 1) / 2.0;
  for (int y = 0; y < section.size; ++y)
    for (int x = 0; x < section.size; ++x) {
      const glm::dvec3 p =
          centreMm + (x - c) * pixelMm * section.uAxis - (y - c) * pixelMm * section.vAxis;
      if (insideDomain(volume, p))
        section.hu[std::size_t(y) * section.size + x] = trilinearHu(volume, p);
    }
  return section;
}

}  // namespace angio
