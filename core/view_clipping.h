#pragma once
// What of the volume a view renders (rendering model, "Crop, clip, slab"): a crop box along the
// voxel axes, one clip plane and a thick slab facing the viewer, each optional. Every one of them
// cuts a ray's depth range to one interval (core/clip_interval.h), so together they are one
// interval per ray and the sample grid t_k = k delta stays as it is.
#include <optional>

#include <glm/glm.hpp>

namespace angio {

// Everything outside the box [minMm, maxMm] (mm of the volume frame, where voxel centres sit at
// index * spacing) is not rendered.
struct CropBox {
  glm::dvec3 minMm{0.0};
  glm::dvec3 maxMm{0.0};

  friend bool operator==(const CropBox&, const CropBox&) = default;
};

// The half-space on the normal's side of the plane is removed. facingViewer: the plane follows the
// view, perpendicular to the view direction d at depth offsetMm from the domain centre (positive:
// farther from the viewer), its normal pointing at the viewer (-d), so what lies in front of it is
// removed; pointMm and normal are then unused.
struct ClipPlane {
  bool facingViewer = false;
  double offsetMm = 0;
  glm::dvec3 pointMm{0.0};       // a point of the plane, mm of the volume frame
  glm::dvec3 normal{0, 0, 1.0};  // any length but zero

  friend bool operator==(const ClipPlane&, const ClipPlane&) = default;
};

// The plane facing the viewer at depth offsetMm (pointMm and normal at their defaults, so equal
// facing planes compare equal).
inline ClipPlane facingPlane(double offsetMm) {
  ClipPlane plane;
  plane.facingViewer = true;
  plane.offsetMm = offsetMm;
  return plane;
}

// Only the slab perpendicular to d between depths offsetMm -+ thicknessMm / 2 (from the domain
// centre, positive farther from the viewer) is rendered, composited as the view's mode says.
struct ThickSlab {
  double offsetMm = 0;
  double thicknessMm = 10;

  friend bool operator==(const ThickSlab&, const ThickSlab&) = default;
};

struct ViewClipping {
  std::optional<CropBox> crop;
  std::optional<ClipPlane> plane;
  std::optional<ThickSlab> slab;

  bool any() const { return crop || plane || slab; }
  friend bool operator==(const ViewClipping&, const ViewClipping&) = default;
};

}  // namespace angio
