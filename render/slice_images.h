#pragma once
// The linked slice view's images (axial, coronal, sagittal) through a cursor point, as 8-bit grey
// through a window/level, at voxel resolution (one pixel per voxel; pixels are spacing-sized, so
// they are not square on anisotropic data: the viewer scales by sliceSpacingMm).
//
// Display convention: radiological, as reading workstations show CT. The volume's axes i, j, k run
// +L, +P, +S, so
//   axial    (k fixed): x = i (patient right on the image left), y = j (anterior at the top);
//   coronal  (j fixed): x = i (patient right on the image left), y = K-1-k (superior up);
//   sagittal (i fixed): x = j (anterior on the image left),      y = K-1-k (superior up).
// Pixel (x, y) covers [x, x+1) x [y, y+1); its centre x+0.5 is the voxel centre. Points are mm of
// the volume frame (index * spacing).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "core/window_level.h"
#include "vessel/centerline.h"

namespace angio {

enum class SliceOrientation { axial = 0, coronal = 1, sagittal = 2 };

const char* sliceOrientationName(SliceOrientation orientation);  // "axial", "coronal", "sagittal"

// Grey = clamp((HU - (level - window/2)) / window, 0, 1) * 255, rounded.
std::uint8_t greyOfHu(double hu, WindowLevel windowLevel);

struct SliceImage {
  SliceOrientation orientation = SliceOrientation::axial;
  int width = 0, height = 0;
  std::vector<std::uint8_t> grey;  // row-major, row 0 at the top
  int index = 0;                   // the fixed voxel index (k, j or i)
  double positionMm = 0;           // that index * spacing along the fixed axis

  std::uint8_t at(int x, int y) const { return grey[std::size_t(y) * width + x]; }
  friend bool operator==(const SliceImage&, const SliceImage&) = default;
};

// The voxel nearest to a point (mm, volume frame), clamped into the volume: a cursor outside
// still shows the edge slices.
glm::ivec3 cursorVoxel(const Volume& volume, glm::dvec3 pointMm);

// The fixed voxel axis of a slice: 2 (k) axial, 1 (j) coronal, 0 (i) sagittal.
int fixedAxisOf(SliceOrientation orientation);

// The voxel axes along a slice image's x and y, and whether y runs against its axis (superior up).
struct SliceAxes {
  int x, y;
  bool yFlipped;
};
SliceAxes axesOf(SliceOrientation orientation);

// The slice through the cursor's voxel.
SliceImage extractSlice(const Volume& volume, SliceOrientation orientation, glm::dvec3 cursorMm,
                        WindowLevel windowLevel);

// Image size in pixels and mm per pixel (x, y) of a slice.
glm::ivec2 sliceSize(const Volume& volume, SliceOrientation orientation);
glm::dvec2 sliceSpacingMm(const Volume& volume, SliceOrientation orientation);

// A point (mm, volume frame) projected into a slice's image (continuous pixel coordinates).
glm::dvec2 slicePixelOf(const Volume& volume, SliceOrientation orientation, glm::dvec3 pointMm);

// The point under an image position: the in-plane coordinates from the pixel, the fixed one kept
// from `cursorMm`. Not clamped (callers clamp the result with clampToVolume).
glm::dvec3 pointOfSlicePixel(const Volume& volume, SliceOrientation orientation, glm::dvec2 pixel,
                             glm::dvec3 cursorMm);

// Clamps a point into the box of voxel centres.
glm::dvec3 clampToVolume(const Volume& volume, glm::dvec3 pointMm);

// Where a centerline path crosses a slice's plane (the plane through the cursor voxel's centre).
struct SliceCrossing {
  int path = 0;
  glm::dvec2 pixel{0.0};  // slicePixelOf the crossing point
  friend bool operator==(const SliceCrossing&, const SliceCrossing&) = default;
};

// Every crossing of every path's polyline with the slice plane. A segment crosses when its ends lie
// on different sides (an end exactly on the plane counts as the far side, so a polyline touching
// the plane at a vertex yields one crossing, not two). `centerlines` must be in the volume frame.
std::vector<SliceCrossing> sliceCrossings(const Volume& volume, SliceOrientation orientation,
                                          glm::dvec3 cursorMm, const Centerlines& centerlines);

}  // namespace angio
