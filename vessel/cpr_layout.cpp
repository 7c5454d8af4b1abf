#include "vessel/cpr_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace angio {

namespace {

constexpr double kTiny = 1e-9;

std::string quoted(const CenterlinePath& path) { return "path '" + path.name + "'"; }

bool isFinite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool insideDomain(glm::dvec3 p, glm::dvec3 extent) {
  constexpr double kTolerance = 1e-6;  // mm; the closed box of voxel centres
  return glm::all(glm::greaterThanEqual(p, glm::dvec3(-kTolerance))) &&
         glm::all(glm::lessThanEqual(p, extent + kTolerance));
}

void checkPath(const CenterlinePath& path) {
  if (path.points.empty()) throw CprPathError(quoted(path) + " has no points");
  if (path.points.size() < 2) {
    throw CprPathError(quoted(path) + " has a single point; a CPR needs at least 2");
  }
  for (const CenterlinePoint& point : path.points) {
    if (!isFinite(point.positionMm)) {
      throw CprPathError(quoted(path) + " has a non-finite coordinate");
    }
  }
  if (!(pathLengthMm(path) > 0)) throw CprPathError(quoted(path) + " has zero length");
}

// Validates the paths and the settings; returns the warnings for paths partly outside the volume.
std::vector<std::string> checkInput(const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
                                    double widthMm) {
  if (paths.empty()) throw CprPathError("no centerline paths to reformat");
  if (!std::isfinite(widthMm) || widthMm <= 0) {
    throw std::invalid_argument("CPR width must be a finite length > 0 mm");
  }
  if (!std::isfinite(view.pixelMm) || view.pixelMm <= 0) {
    throw std::invalid_argument("CPR pixel size must be a finite length > 0 mm");
  }
  std::vector<std::string> warnings;
  for (const CenterlinePath& path : paths) {
    checkPath(path);
    const auto outside = std::count_if(path.points.begin(), path.points.end(), [&](auto& point) {
      return !insideDomain(point.positionMm, view.extent);
    });
    if (std::size_t(outside) == path.points.size()) {
      throw CprPathError(quoted(path) + " lies entirely outside the volume");
    }
    if (outside > 0) {
      warnings.push_back(quoted(path) + ": " + std::to_string(outside) + " of " +
                         std::to_string(path.points.size()) +
                         " points lie outside the volume; the CPR is clipped there");
    }
  }
  return warnings;
}

// In doubles, so absurd sizes (a pixel of 1e-300 mm) are refused before any integer overflows.
void checkPixelCount(double width, double height) {
  if (!(width * height <= double(kMaxCprPixels))) {
    char message[160];
    std::snprintf(message, sizeof message, "CPR would be %.0f x %.0f pixels; choose a larger pixel size",
                  width, height);
    throw std::invalid_argument(message);
  }
}

// Arc length of the points two paths share (their common trunk), or -1 if they share none.
double sharedArcMm(const CenterlinePath& a, const CenterlinePath& b) {
  const std::size_t shared = sharedPrefixLength(a, b);
  return shared == 0 ? -1.0 : arcLengthsMm(a)[shared - 1];
}

// Index of the first vertex of path p that is not part of a trunk shared with an earlier path,
// minus one (the junction), so that each piece of the tree is drawn once.
std::size_t firstOwnVertex(const std::vector<CenterlinePath>& paths, std::size_t p) {
  std::size_t shared = 0;
  for (std::size_t q = 0; q < p; ++q) shared = std::max(shared, sharedPrefixLength(paths[p], paths[q]));
  return shared == 0 ? 0 : shared - 1;
}

// Restricts a span to the pixels whose points lie in the closed domain box [0, E].
bool clipToDomain(CprSpan& span, glm::dvec3 extent) {
  constexpr double kTolerance = 1e-9;  // mm: points exactly on a face stay inside
  double lo = span.x0, hi = span.x1 - 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = span.originMm[axis], d = span.stepMm[axis];
    if (std::abs(d) < 1e-15) {
      if (o < -kTolerance || o > extent[axis] + kTolerance) return false;
      continue;
    }
    double a = (-kTolerance - o) / d, b = (extent[axis] + kTolerance - o) / d;
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  if (lo > hi) return false;
  span.x0 = int(std::ceil(lo));
  span.x1 = int(std::floor(hi)) + 1;
  return span.x0 < span.x1;
}

void addClipped(CprLayout& layout, CprSpan span, glm::dvec3 extent) {
  span.x0 = std::max(span.x0, 0);
  span.x1 = std::min(span.x1, layout.width);
  if (span.x0 < span.x1 && clipToDomain(span, extent)) layout.spans.push_back(span);
}

// --- A path sampled by arc length ---------------------------------------------------------------

class ArcSampler {
 public:
  explicit ArcSampler(const CenterlinePath& path) : path_(path), arc_(arcLengthsMm(path)) {}

  double length() const { return arc_.back(); }

  glm::dvec3 at(double s) const {
    s = std::clamp(s, 0.0, length());
    const auto upper = std::upper_bound(arc_.begin(), arc_.end(), s);
    const std::size_t b = std::clamp<std::size_t>(upper - arc_.begin(), 1, arc_.size() - 1);
    const std::size_t a = b - 1;
    const double segment = arc_[b] - arc_[a];
    const double t = segment > 0 ? (s - arc_[a]) / segment : 0.0;
    return glm::mix(path_.points[a].positionMm, path_.points[b].positionMm, t);
  }

 private:
  const CenterlinePath& path_;
  std::vector<double> arc_;
};

// --- Straightened --------------------------------------------------------------------------------

struct StraightenedPath {
  std::vector<double> arcMm;         // per row: (y + 0.5) D, clamped to the path's length
  std::vector<glm::dvec3> centreMm;  // c(s)
  std::vector<glm::dvec3> acrossMm;  // v(s), unit
};

glm::dvec3 unitAxis(int index) {
  glm::dvec3 e(0.0);
  e[index] = 1.0;
  return e;
}

// The RMF's start: r at angle 0 (e_b) made normal to the first tangent; e_c if the vessel starts
// (nearly) along e_b.
glm::dvec3 initialNormal(const ViewGeometry& view, glm::dvec3 tangent) {
  for (int axis : {view.axisB, view.axisC}) {
    const glm::dvec3 e = unitAxis(axis);
    const glm::dvec3 normal = e - glm::dot(e, tangent) * tangent;
    if (glm::length(normal) > 0.2) return glm::normalize(normal);
  }
  return glm::normalize(unitAxis(view.axis) - glm::dot(unitAxis(view.axis), tangent) * tangent);
}

StraightenedPath straightenPath(const CenterlinePath& path, const ViewGeometry& view) {
  const ArcSampler sampler(path);
  const double D = view.pixelMm;
  const int rows = std::max(1, int(std::ceil(sampler.length() / D - kTiny)));
  // Tangents from a chord of +-5 mm (at least a pixel): centerlines traced slice by slice are
  // good to about a voxel, and tangents over shorter chords tilt with that noise (by up to 30
  // degrees on aorta.mha with +-2 mm), swinging the vector of interest. A symmetric chord of a
  // circular arc is parallel to the tangent at its middle, so real bends lose nothing.
  const double halfChord = std::max(D, 5.0);
  StraightenedPath out;
  std::vector<glm::dvec3> tangents;
  for (int y = 0; y < rows; ++y) {
    const double s = std::min((y + 0.5) * D, sampler.length());
    out.arcMm.push_back(s);
    out.centreMm.push_back(sampler.at(s));
    const glm::dvec3 chord = sampler.at(s + halfChord) - sampler.at(s - halfChord);
    const double length = glm::length(chord);
    tangents.push_back(length > kTiny ? chord / length : (tangents.empty() ? view.up : tangents.back()));
  }
  const std::vector<glm::dvec3> normals =
      rotationMinimizingNormals(out.centreMm, tangents, initialNormal(view, tangents.front()));
  // Turn by the view angle in the sense r turns about the up axis, as seen along the vessel's
  // start (for a vessel starting across the up axis the sense is a matter of convention).
  const double theta = std::atan2(view.right[view.axisC], view.right[view.axisB]);
  const double sense = glm::dot(tangents.front(), view.up) >= 0 ? 1.0 : -1.0;
  const double c = std::cos(sense * theta), s = std::sin(sense * theta);
  for (std::size_t n = 0; n < normals.size(); ++n) {
    const glm::dvec3 binormal = glm::cross(tangents[n], normals[n]);
    out.acrossMm.push_back(glm::normalize(c * normals[n] + s * binormal));
  }
  return out;
}

CprLayout layoutStraightened(const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
                             double widthMm) {
  const double D = view.pixelMm;
  const std::size_t count = paths.size();
  double longest = 0;
  for (const CenterlinePath& path : paths) longest = std::max(longest, pathLengthMm(path));
  const double halfPanel = std::round(widthMm / (2 * D));
  checkPixelCount(double(count) * (2 * halfPanel + 1), std::ceil(longest / D));
  const int panel = 2 * int(halfPanel) + 1;  // odd: a centre column
  CprLayout layout;
  layout.width = int(count) * panel;
  std::vector<StraightenedPath> straight;
  for (const CenterlinePath& path : paths) {
    straight.push_back(straightenPath(path, view));
    layout.height = std::max(layout.height, int(straight.back().arcMm.size()));
  }
  std::vector<std::vector<double>> shared(count, std::vector<double>(count, -1));
  for (std::size_t p = 0; p < count; ++p)
    for (std::size_t q = p + 1; q < count; ++q) shared[p][q] = sharedArcMm(paths[p], paths[q]);

  auto hasRow = [&](std::size_t p, int y) { return y < int(straight[p].arcMm.size()); };
  // centre[p][y]: the column of path p's centerline in row y; leader[p][y]: whose samples.
  std::vector<std::vector<double>> centre(count);
  std::vector<std::vector<std::size_t>> leader(count);
  for (int y = 0; y < layout.height; ++y) {
    const double s = (y + 0.5) * D;
    for (std::size_t p = 0; p < count;) {
      if (!hasRow(p, y)) {
        ++p;
        continue;
      }
      // Consecutive paths through the same point at this arc length form one span.
      std::size_t end = p + 1;
      while (end < count && hasRow(end, y) && s <= shared[p][end] + kTiny) ++end;
      // The centre column (of an even-width group, the left of the two middle ones), so that a
      // column shows the centerline itself.
      const int first = int(p) * panel, last = int(end) * panel;
      const int cx = (first + last - 1) / 2;
      const StraightenedPath& lead = straight[p];
      CprSpan span;
      span.row = y;
      span.x0 = first;
      span.x1 = last;
      span.stepMm = D * lead.acrossMm[y];
      span.originMm = lead.centreMm[y] - double(cx) * span.stepMm;
      span.path = int(p);
      span.centreX = cx;
      span.arcMm = lead.arcMm[y];
      addClipped(layout, span, view.extent);
      for (std::size_t m = p; m < end; ++m) {
        centre[m].push_back(cx);
        leader[m].push_back(p);
      }
      p = end;
    }
  }
  for (std::size_t p = 0; p < count; ++p) {
    CprCurve curve;
    curve.path = int(p);
    const int rows = int(centre[p].size());
    int start = 0;
    while (start < rows && leader[p][start] != p) ++start;
    for (int y = std::max(start - 1, 0); y < rows && start < rows; ++y) {
      curve.pixels.push_back({centre[p][y], double(y)});
      curve.arcMm.push_back(straight[p].arcMm[y]);
    }
    layout.curves.push_back(std::move(curve));
  }
  return layout;
}

// --- Projected and stretched: rows cut the centerline --------------------------------------------

struct Crossing {
  double x = 0;  // image column (continuous)
  glm::dvec3 pointMm{0.0};
  int path = 0;
  double arcMm = 0;
};

// A path's vertices in image coordinates.
struct ImagePath {
  std::vector<glm::dvec2> pixels;
  std::vector<double> arcMm;
};

double dvrColumn(const ViewGeometry& view, glm::dvec3 p) {
  return glm::dot(p - view.centre, view.right) / view.pixelMm + 0.5 * view.width - 0.5;
}

ImagePath projectPath(const CenterlinePath& path, const ViewGeometry& view, CprMode mode,
                      int columnOffset) {
  ImagePath image;
  image.arcMm = arcLengthsMm(path);
  double sigma = 0;  // length orthogonal to r so far (stretched rows)
  for (std::size_t n = 0; n < path.points.size(); ++n) {
    const glm::dvec3 p = path.points[n].positionMm;
    if (n > 0) {
      const glm::dvec3 step = p - path.points[n - 1].positionMm;
      sigma += glm::length(step - glm::dot(step, view.right) * view.right);
    }
    const double x = dvrColumn(view, p) - columnOffset;
    const double y = mode == CprMode::projected
                         ? 0.5 * view.height - 0.5 - glm::dot(p - view.centre, view.up) / view.pixelMm
                         : sigma / view.pixelMm - 0.5;
    image.pixels.push_back({x, y});
  }
  return image;
}

void addCrossings(const CenterlinePath& path, const ImagePath& image, int pathIndex,
                  std::vector<std::vector<Crossing>>& rows) {
  const int height = int(rows.size());
  const std::size_t last = path.points.size() - 1;
  std::vector<char> crossed(height, 0);
  for (std::size_t n = 0; n < last; ++n) {
    const double ya = image.pixels[n].y, yb = image.pixels[n + 1].y;
    if (ya == yb) continue;  // runs along the row: its neighbours cross it
    // Half-open [lo, hi) so a vertex on a row is counted once; the path's last segment is closed.
    const double lo = std::min(ya, yb), hi = std::max(ya, yb);
    const int first = std::max(int(std::ceil(lo)), 0);
    const int lastRow =
        std::min(n + 1 == last ? int(std::floor(hi)) : int(std::ceil(hi)) - 1, height - 1);
    for (int y = first; y <= lastRow; ++y) {
      const double t = (y - ya) / (yb - ya);
      rows[y].push_back({glm::mix(image.pixels[n].x, image.pixels[n + 1].x, t),
                         glm::mix(path.points[n].positionMm, path.points[n + 1].positionMm, t),
                         pathIndex, glm::mix(image.arcMm[n], image.arcMm[n + 1], t)});
      crossed[y] = 1;
    }
  }
  // An end point between row centres still shows in its nearest row (else the first and last
  // half pixel of a path would be lost).
  for (std::size_t n : {std::size_t(0), last}) {
    const int y = int(std::floor(image.pixels[n].y + 0.5));
    if (y < 0 || y >= height || crossed[y]) continue;
    rows[y].push_back({image.pixels[n].x, path.points[n].positionMm, pathIndex, image.arcMm[n]});
    crossed[y] = 1;
  }
}

// The same point reached through two paths (their shared trunk) is one crossing.
void sortAndMerge(std::vector<Crossing>& crossings) {
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
  auto same = [](const Crossing& a, const Crossing& b) {
    return std::abs(a.x - b.x) < kTiny && glm::distance(a.pointMm, b.pointMm) < kTiny;
  };
  crossings.erase(std::unique(crossings.begin(), crossings.end(), same), crossings.end());
}

// Splits a row between its crossings (each pixel to the nearest one), within `band` pixels of it.
void addRowSpans(CprLayout& layout, int y, const std::vector<Crossing>& crossings, double band,
                 glm::dvec3 right, glm::dvec3 extent) {
  const double D = layout.pixelMm;
  const double limit = double(layout.width) + 1;  // keeps the column arithmetic in int range
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const Crossing& c = crossings[k];
    double lo = std::max(c.x - band, -1.0), hi = std::min(c.x + band, limit);
    int x0 = int(std::ceil(lo)), x1 = int(std::floor(hi)) + 1;
    // Pixel x belongs to crossing k if it lies right of the midpoint to k - 1 and not right of
    // the midpoint to k + 1.
    if (k > 0) x0 = std::max(x0, int(std::floor(0.5 * (crossings[k - 1].x + c.x))) + 1);
    if (k + 1 < crossings.size()) {
      x1 = std::min(x1, int(std::floor(0.5 * (c.x + crossings[k + 1].x))) + 1);
    }
    CprSpan span;
    span.row = y;
    span.x0 = x0;
    span.x1 = x1;
    span.stepMm = D * right;
    span.originMm = c.pointMm - c.x * span.stepMm;
    span.path = c.path;
    span.centreX = c.x;
    span.arcMm = c.arcMm;
    addClipped(layout, span, extent);
  }
}

// bandMm: projected only, the sampled band around each crossing; marginMm: stretched only, the
// margin left and right of the centerlines' columns.
CprLayout layoutCrossings(const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
                          CprMode mode, std::optional<double> bandMm, double marginMm) {
  const double D = view.pixelMm;
  CprLayout layout;
  std::vector<ImagePath> images;
  for (const CenterlinePath& path : paths) images.push_back(projectPath(path, view, mode, 0));
  if (mode == CprMode::projected) {
    layout.width = view.width;
    layout.height = view.height;
  } else {
    // Stretched: the columns the centerlines cover plus the margin, on the DVR image's grid.
    const double margin = marginMm / D;
    double minX = std::numeric_limits<double>::max(), maxX = -minX, maxY = 0;
    for (const ImagePath& image : images) {
      for (glm::dvec2 pixel : image.pixels) {
        minX = std::min(minX, pixel.x);
        maxX = std::max(maxX, pixel.x);
        maxY = std::max(maxY, pixel.y);
      }
    }
    const double lowest = std::floor(minX - margin), highest = std::ceil(maxX + margin);
    checkPixelCount(highest - lowest + 1, std::ceil(maxY + 0.5));
    layout.columnOffset = int(lowest);
    layout.width = int(highest - lowest) + 1;
    layout.height = std::max(1, int(std::ceil(maxY + 0.5 - kTiny)));
    for (ImagePath& image : images)
      for (glm::dvec2& pixel : image.pixels) pixel.x -= layout.columnOffset;
  }
  checkPixelCount(layout.width, layout.height);
  layout.pixelMm = D;
  std::vector<std::vector<Crossing>> rows(layout.height);
  for (std::size_t p = 0; p < paths.size(); ++p) addCrossings(paths[p], images[p], int(p), rows);
  const double band = bandMm ? *bandMm / (2 * D) : std::numeric_limits<double>::infinity();
  for (int y = 0; y < layout.height; ++y) {
    sortAndMerge(rows[y]);
    addRowSpans(layout, y, rows[y], band, view.right, view.extent);
  }
  for (std::size_t p = 0; p < paths.size(); ++p) {
    CprCurve curve;
    curve.path = int(p);
    for (std::size_t n = firstOwnVertex(paths, p); n < paths[p].points.size(); ++n) {
      curve.pixels.push_back(images[p].pixels[n]);
      curve.arcMm.push_back(images[p].arcMm[n]);
    }
    if (curve.pixels.size() < 2) curve = {int(p), {}, {}};  // wholly shared with an earlier path
    layout.curves.push_back(std::move(curve));
  }
  return layout;
}

}  // namespace

const char* toString(CprMode mode) {
  switch (mode) {
    case CprMode::projected: return "projected";
    case CprMode::stretched: return "stretched";
    case CprMode::straightened: return "straightened";
  }
  return "?";
}

std::optional<CprMode> parseCprMode(const std::string& text) {
  for (CprMode mode : {CprMode::projected, CprMode::stretched, CprMode::straightened}) {
    if (text == toString(mode)) return mode;
  }
  return std::nullopt;
}

std::vector<glm::dvec3> rotationMinimizingNormals(const std::vector<glm::dvec3>& points,
                                                  const std::vector<glm::dvec3>& tangents,
                                                  glm::dvec3 initialNormal) {
  std::vector<glm::dvec3> normals;
  if (points.empty()) return normals;
  normals.reserve(points.size());
  const glm::dvec3 t0 = tangents.front();
  normals.push_back(glm::normalize(initialNormal - glm::dot(initialNormal, t0) * t0));
  // Double reflection: reflect (normal, tangent) in the bisector plane of the step, then in the
  // plane that maps the reflected tangent onto the next tangent.
  auto reflect = [](glm::dvec3 v, glm::dvec3 axis, double axisSquared) {
    return axisSquared > 1e-24 ? v - (2.0 / axisSquared) * glm::dot(axis, v) * axis : v;
  };
  for (std::size_t n = 0; n + 1 < points.size(); ++n) {
    const glm::dvec3 v1 = points[n + 1] - points[n];
    const double c1 = glm::dot(v1, v1);
    const glm::dvec3 normalL = reflect(normals[n], v1, c1);
    const glm::dvec3 tangentL = reflect(tangents[n], v1, c1);
    const glm::dvec3 v2 = tangents[n + 1] - tangentL;
    glm::dvec3 next = reflect(normalL, v2, glm::dot(v2, v2));
    // Keep it exactly normal to the tangent and of unit length (rounding drifts over many steps).
    const glm::dvec3 t = tangents[n + 1];
    next -= glm::dot(next, t) * t;
    const double length = glm::length(next);
    normals.push_back(length > kTiny ? next / length : normals.back());
  }
  return normals;
}

CprLayout layoutCpr(const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
                    const CprSettings& settings) {
  const double widthMm = settings.widthMm.value_or(kDefaultCprWidthMm);
  std::vector<std::string> warnings = checkInput(paths, view, widthMm);
  CprLayout layout;
  switch (settings.mode) {
    case CprMode::straightened: layout = layoutStraightened(paths, view, widthMm); break;
    case CprMode::stretched:
      layout = layoutCrossings(paths, view, settings.mode, std::nullopt, 0.5 * widthMm);
      break;
    case CprMode::projected:
      layout = layoutCrossings(paths, view, settings.mode, settings.widthMm, 0);
      break;
  }
  layout.mode = settings.mode;
  layout.pixelMm = view.pixelMm;
  if (settings.mode == CprMode::straightened) {
    layout.widthMm = layout.width / double(paths.size()) * view.pixelMm;
  } else {
    layout.widthMm =
        settings.mode == CprMode::projected && !settings.widthMm ? layout.width * view.pixelMm : widthMm;
  }
  layout.warnings = std::move(warnings);
  return layout;
}

std::vector<CenterlinePath> selectPaths(const Centerlines& centerlines, const std::string& which) {
  if (which == "all") return centerlines.paths;
  const std::size_t count = centerlines.paths.size();
  const std::string range =
      count == 0 ? "it has no paths"
                 : "it has " + std::to_string(count) + " (0.." + std::to_string(count - 1) + ")";
  std::size_t used = 0;
  long index = -1;
  try {
    index = std::stol(which, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != which.size() || which.empty()) {
    throw CprPathError("path selection '" + which + "' is neither 'all' nor a path number; " + range);
  }
  if (index < 0 || std::size_t(index) >= count) {
    throw CprPathError("there is no path " + which + "; " + range);
  }
  return {centerlines.paths[std::size_t(index)]};
}

}  // namespace angio
