#pragma once
// The centerline model of a vessel tree: paths = polylines of points in mm with a
// lumen radius per point, each with a name. Paths run root to leaf; a bifurcation's trunk is
// repeated in every path through it (vmtk's layout, also the phantom's) and kept as given —
// sharedPrefixLength finds it.
//
// Two frames, both in mm (tagged in Centerlines::frame):
// - physical: LPS patient coordinates, physical = origin + direction * (index * spacing);
//   what the files hold.
// - volume: index * spacing, origin at voxel (0, 0, 0), axes along the volume's voxel axes i, j, k;
//   the coordinates of the renderer's rays (rendering-model.md, "Volume frame").
// The map between them is rigid (direction is a rotation), so lengths and radii are the same in both.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"

namespace angio {

struct CenterlinePoint {
  glm::dvec3 positionMm{0.0};
  double radiusMm = 0;  // lumen radius; 0 = unknown

  friend bool operator==(const CenterlinePoint&, const CenterlinePoint&) = default;
};

struct CenterlinePath {
  std::string name;
  std::vector<CenterlinePoint> points;

  friend bool operator==(const CenterlinePath&, const CenterlinePath&) = default;
};

enum class CenterlineFrame { physical, volume };

struct Centerlines {
  std::string source;  // the file (or "phantom"), for messages
  CenterlineFrame frame = CenterlineFrame::physical;
  std::vector<CenterlinePath> paths;

  friend bool operator==(const Centerlines&, const Centerlines&) = default;
};

// --- Conversion and frames ----------------------------------------------------------------------

// Physical (mm, LPS) -> volume frame (mm): physicalToIndex(volume, p) * spacing.
glm::dvec3 volumeFrameMm(const Volume& volume, glm::dvec3 physicalMm);

// The voxel whose centre is nearest to a physical point (may lie outside the volume).
glm::ivec3 nearestVoxelToPoint(const Volume& volume, glm::dvec3 physicalMm);

// All points mapped into the volume frame; radii unchanged. Throws std::logic_error if
// `centerlines` is already in the volume frame.
Centerlines toVolumeFrame(const Centerlines& centerlines, const Volume& volume);

// Volume frame (mm) -> physical (mm, LPS): the inverse of volumeFrameMm.
glm::dvec3 physicalFrameMm(const Volume& volume, glm::dvec3 volumeMm);

// All points mapped into the physical frame (what files hold); radii unchanged. Throws
// std::logic_error if `centerlines` is already in the physical frame.
Centerlines toPhysicalFrame(const Centerlines& centerlines, const Volume& volume);

// --- Geometry (in whichever frame the path is) ---------------------------------------------------

// Cumulative arc length at each point: 0 at the first point, the path length at the last.
std::vector<double> arcLengthsMm(const CenterlinePath& path);
double pathLengthMm(const CenterlinePath& path);

// Points every `stepMm` of arc length from the first point, plus the last point (so the endpoints
// are kept and only the last step may be shorter); radius interpolated linearly in arc length.
// Paths of fewer than 2 points, or of zero length, come back unchanged.
// Throws std::invalid_argument unless stepMm is finite and > 0.
CenterlinePath resampleByArcLength(const CenterlinePath& path, double stepMm);
Centerlines resampleByArcLength(const Centerlines& centerlines, double stepMm);

struct BoxMm {
  glm::dvec3 lo{0.0};
  glm::dvec3 hi{0.0};
};

// The box around a path's points grown by its largest radius (so it holds the whole tube).
// An empty path gives an empty box (lo > hi).
BoxMm pathBounds(const CenterlinePath& path);
std::vector<BoxMm> pathBounds(const Centerlines& centerlines);

// How many leading points two paths share (positions within toleranceMm): the common trunk of a
// bifurcation, repeated in both paths.
std::size_t sharedPrefixLength(const CenterlinePath& a, const CenterlinePath& b,
                               double toleranceMm = 1e-6);

// --- Validation ---------------------------------------------------------------------------------

enum class IssueSeverity { warning, error };

struct CenterlineIssue {
  IssueSeverity severity = IssueSeverity::error;
  std::string problem;  // one line naming the path, e.g. "path 'left iliac': 2 points have radius 0"
};

// Errors: no paths, an empty path, non-finite coordinates or radii, negative radii.
// Warnings: paths of a single point, zero radii (kept: 0 means unknown).
std::vector<CenterlineIssue> validateCenterlines(const Centerlines& centerlines);

// Warnings for paths with points whose nearest voxel lies outside the volume, naming the path and
// how many points. Works in either frame.
std::vector<CenterlineIssue> checkInsideVolume(const Centerlines& centerlines, const Volume& volume);

bool hasError(const std::vector<CenterlineIssue>& issues);

// "<source>: <problem>", the one-line form for the user.
std::string describe(const Centerlines& centerlines, const CenterlineIssue& issue);

}  // namespace angio
