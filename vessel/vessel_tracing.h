#pragma once
// Vessel tracing from clicks: a click snapped to the lumen's centre nearby, centerlines between
// clicks as the cheapest path through the contrast-filled lumen (vessel/lumen_paths.h), placed on
// the lumen's centre with a radius per point (vessel/lumen_section.h). The contrast range comes
// from the lumen at the first click, unless given. Everything is in the volume frame (mm).
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "vessel/centerline.h"
#include "vessel/downstream_tracing.h"
#include "vessel/lumen_field.h"

namespace angio {

struct TraceSettings {
  double stepMm = 0.5;  // the centerlines' point spacing
  // What surrounds the vessels (the contrast range's lower half); none: 50 HU in calibrated data,
  // else the volume's median.
  std::optional<double> tissueHu;
  // Where calcium begins; none: twice the lumen's margin above it (in data that are not
  // calibrated HU, core/volume.h looksHuCalibrated, the top of the scale).
  std::optional<double> calciumHu;
  double snapRadiusMm = 6;                // how far from a click a lumen is looked for
  double marginMm = 30;                   // the lumen field's box around the points
  std::optional<ContrastRange> contrast;  // none: from the first click's lumen
  DownstreamSettings downstream;

  friend bool operator==(const TraceSettings&, const TraceSettings&) = default;
};

// A click placed on the lumen's centre, or the one-line reason it could not be.
struct SnappedPoint {
  std::optional<glm::dvec3> positionMm;
  std::string problem;
};

// The vessel tree downstream of a click: root-to-leaf paths (volume frame) sharing their trunks
// point for point (as vmtk writes them), named "1", "2", ... from the longest.
struct TracedTree {
  Centerlines centerlines;
  std::string problem;
};

struct TracedPath {
  std::optional<CenterlinePath> path;  // volume frame
  std::string problem;
};

class VesselTracer {
 public:
  explicit VesselTracer(const Volume& volume, TraceSettings settings = {});

  const TraceSettings& settings() const { return settings_; }
  // The range in use; none until a click found a lumen.
  std::optional<ContrastRange> contrast() const { return contrast_; }
  // The lumen's density near a point (the brightest place a climb from it reaches within the snap
  // radius, noise averaged over 3x3x3 voxels), in HU; none outside the volume.
  std::optional<double> lumenHuNear(glm::dvec3 pointMm) const;
  // Widens the contrast range (unless the settings fix it) to hold the lumen near the point, if
  // there is one: bolus density varies along a run-off, and more still in uncalibrated data.
  void widenContrastFor(glm::dvec3 pointMm);

  // The lumen field covers `box` after this (rebuilt over the union when it did not); false if
  // cancelled. Called by snap and trace as needed; the GUI calls it once for the whole volume in
  // the background. Needs the contrast range.
  bool prepare(const VoxelBox& box, const std::atomic<bool>* cancel = nullptr);
  const LumenField& field() const { return field_; }

  SnappedPoint snap(glm::dvec3 pointMm, const std::atomic<bool>* cancel = nullptr);
  // Through the points in order (start, waypoints, end), each snapped first.
  TracedPath trace(const std::vector<glm::dvec3>& pointsMm, const std::atomic<bool>* cancel = nullptr);
  // Follows the contrast-filled lumen from the click to its ends, branching where it branches.
  // Needs the field over the whole volume (built here if it is not). progress(fraction) may be
  // empty.
  TracedTree traceDownstream(glm::dvec3 seedMm, const std::atomic<bool>* cancel = nullptr,
                             const std::function<void(double)>& progress = {});

 private:
  std::optional<glm::ivec3> nearestLumenVoxel(glm::dvec3 pointMm) const;
  void learnTheData();
  glm::ivec3 climbToRidge(glm::ivec3 voxel, glm::dvec3 clickMm) const;
  CenterlinePath centerlineOf(const std::vector<glm::ivec3>& voxels) const;
  std::optional<std::vector<glm::ivec3>> joinThroughLumen(const std::vector<glm::ivec3>& ends,
                                                          const std::atomic<bool>* cancel);

  const Volume* volume_;
  TraceSettings settings_;
  std::optional<ContrastRange> contrast_;
  std::optional<bool> calibrated_;  // looksHuCalibrated, once needed
  double tissueHu_ = 0;
  std::optional<double> calciumHu_;
  LumenField field_;
};

}  // namespace angio
