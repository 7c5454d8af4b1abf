#pragma once
// VesselGlyph regions per ray (thesis ch. 5): from the centerlines, every ray of
// a view gets sorted depth intervals labelled focus or context (core/region_intervals.h); depths
// not covered are "outside" (clipped or rendered with a third TF: the raycaster decides).
//
// The regions, all sizes in mm:
// - Focus: the tube around the centerlines, radius = TubeRadius of the vessel radius, interpolated
//   along each segment. Exactly the union of round cones around consecutive points
//   (vessel/capsule_intersection.h), so oblique and horizontal vessels are enclosed completely.
// - Context, one of:
//   * slab (thesis fig. 5.2 a/b): parallel to the image plane, from `frontMm` in front of to `backMm`
//     behind the centerline's depth, following that depth row by row. Row y takes the centerline
//     points whose image-space height v lies within the row's band [v_y - D/2, v_y + D/2] (the
//     thesis's "center points belonging to the current slice"), and the slab reaches sideways only
//     `halfWidthMm` from them: pixel (h, v_y) at depth t is context when such a point c has
//     |h - h(c)| <= halfWidthMm and -frontMm <= t - t(c) <= backMm. A bone beside the vessel is thus
//     either wholly outside or cut by a slab that follows one smooth vessel depth, instead of being
//     cut into stripes by unbounded slabs of far-away paths (thesis 5.3.3); halfWidthMm = infinity
//     gives the thesis's unbounded slabs. The slab ends where its chain ends (a path's ends, a
//     branch's start at the bifurcation, the sides of a non-finite point): the chain's slab leaves
//     out the rectangle beyond each end, halfWidthMm deep along the end segment's image-space
//     direction and halfWidthMm to either side of it. Without it a path running sideways in the
//     image, whose points lie in few rows, would reach halfWidthMm past its ends along those rows.
//   * tube: a second, wider tube around the centerlines (TubeRadius as the focus).
//   * none: focus only.
// - Focus wins where focus and context overlap.
// - Half-vessel cut (fig. 5.3 d-f, fig. 5.5 d): the focus is clipped at the image-parallel curved
//   surface through the centerline: each segment's round cone keeps, on the ray of pixel (h, v),
//   only depths behind its axis line's depth under (h, v) (the point of the line whose projection
//   is nearest), so the front half of the vessel is removed. Exact for straight runs; at a bend
//   the two segments' cut planes differ by the bend angle, so a sliver of the front half near the
//   joint may remain. (Set slab.frontMm = 0 too for the thesis's d1 = 0 slab.)
// - Foreground cleft (fig. 5.3 b/c): on every ray that meets the focus (the focus's image-space
//   footprint) no context begins before the ray's first focus interval: that stretch becomes a gap
//   (uncovered, i.e. "outside"), so the vessel shows through the context. Context between and
//   behind focus intervals is kept.
//
// Shared trunks (vmtk's layout: every path repeats the trunk from the root; points equal within
// 1e-6 mm and radius) are counted once, and each path is simplified before the per-view work:
// consecutive points are merged while the merged tube stays within `simplifyToleranceMm` of the
// exact one; the radii are then grown by that tolerance, so the result holds the exact tube and
// lies within twice the tolerance of it (tubes; slabs follow the centerline within it).
//
// Output (RayRegions): depths t in mm from the pixel's ray origin (ViewGeometry::rayOrigin, the
// plane through P0) along viewDir; per pixel the intervals [begin, end) are sorted, disjoint and
// non-empty in float, each labelled focus or context, two of one region never touching (merged);
// a focus and a context interval may touch. Not clipped to the volume's domain (the raycaster
// samples only inside it). Work per view: the segments whose reach overlaps a band of 8 rows are
// binned to it; per row, each segment's tube is intersected with the rays of the columns it can
// reach (round cone split into balls and frustum, each with its own column range), the spans of
// one chain joined per column, and slab interiors kept as runs over columns; rows in parallel.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/region_intervals.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

enum class RadiusMode { constant, vesselFactor };

struct TubeRadius {
  RadiusMode mode = RadiusMode::vesselFactor;
  double value = 1.0;     // mm (constant) or factor of the vessel radius (vesselFactor)
  double marginMm = 0.0;  // added in either mode

  // The tube radius at a centerline point of the given lumen radius (mm).
  double at(double vesselRadiusMm) const;

  friend bool operator==(const TubeRadius&, const TubeRadius&) = default;
};

struct SlabContext {
  double frontMm = 20;      // d1: in front of the centerline's depth
  double backMm = 20;       // d2: behind it
  double halfWidthMm = 40;  // sideways from the centerline, in image space; may be infinity

  friend bool operator==(const SlabContext&, const SlabContext&) = default;
};

enum class ContextShape { none, slab, tube };

struct VesselGlyphSettings {
  TubeRadius focus{RadiusMode::vesselFactor, 2.0, 0.0};
  ContextShape context = ContextShape::slab;
  SlabContext slab;
  TubeRadius contextTube{RadiusMode::constant, 20.0, 0.0};
  bool cleft = false;
  bool halfVessel = false;
  // Lumen radius assumed where the centerline has none (0 = unknown), for vesselFactor tubes.
  double unknownVesselRadiusMm = 2.0;
  // Path simplification before the per-view work (see above); 0 keeps every point.
  double simplifyToleranceMm = 0.05;

  friend bool operator==(const VesselGlyphSettings&, const VesselGlyphSettings&) = default;
};

// Why the settings are unusable (one line naming the setting), or nothing when they are fine:
// sizes must be finite and >= 0 (slab.halfWidthMm may be infinity).
std::optional<std::string> settingsProblem(const VesselGlyphSettings& settings);

// The view-independent part: the centerlines as de-duplicated, simplified tube polylines with the
// focus and context-tube radii per point. Paths with non-finite points are split at them.
// Throws std::logic_error unless `inVolumeFrame` is in the volume frame, std::invalid_argument
// when settingsProblem finds one.
struct GlyphTubes {
  struct Vertex {
    glm::dvec3 positionMm{0.0};  // volume frame
    double focusRadiusMm = 0;
    double contextRadiusMm = 0;  // the context tube's radius (tube only)
  };
  std::vector<std::vector<Vertex>> chains;  // each a polyline of >= 1 vertex
  std::size_t sourcePoints = 0;             // points in the centerlines given
};
GlyphTubes prepareGlyphTubes(const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings);

// The per-view part. Deterministic: the same output whatever the thread count.
RayRegions buildRayRegions(const ViewGeometry& view, const GlyphTubes& tubes,
                           const VesselGlyphSettings& settings);

// For a renderer that builds the regions of many views of one set of centerlines: prepares the
// tubes once and keeps its interval scratch from view to view; with the same `out` passed every
// time, the big buffers are reused once sizes have settled (fresh memory costs page faults). One
// build at a time per builder.
class RayRegionBuilder {
 public:
  // Throws what prepareGlyphTubes throws.
  RayRegionBuilder(const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings);
  ~RayRegionBuilder();
  RayRegionBuilder(RayRegionBuilder&&) noexcept;
  RayRegionBuilder& operator=(RayRegionBuilder&&) noexcept;

  void build(const ViewGeometry& view, RayRegions& out);

  const GlyphTubes& tubes() const { return tubes_; }
  const VesselGlyphSettings& settings() const { return settings_; }

 private:
  struct Scratch;
  VesselGlyphSettings settings_;
  GlyphTubes tubes_;
  std::unique_ptr<Scratch> scratch_;
};

// Both parts. `volume` must be the one `view` was made for (checked by its extent; else
// std::invalid_argument).
RayRegions buildRayRegions(const Volume& volume, const ViewGeometry& view,
                           const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings);

}  // namespace angio
