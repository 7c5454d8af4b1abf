#pragma once
// Transfer function (rendering model, "Post-classification"): control points (HU, rgb, opacity)
// linearly interpolated and tabulated over the 4096 densities, plus the integrated opacity table
// (thesis sec. 4.2.2): prefix sums of opacity, so "is any density in [lo, hi] visible?" is one
// subtraction. Opacity is per voxel unit.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/voxel.h"

namespace angio {

struct ControlPoint {
  double hu = 0;
  glm::vec3 color{0.f};  // rgb in [0, 1]
  double opacity = 0;    // in [0, 1], per voxel unit

  friend bool operator==(const ControlPoint&, const ControlPoint&) = default;
};

// The thesis's "safe" manipulators (sec. 4.2.2): they never change the TF's shape.
struct TfModulators {
  double opacityScale = 1.0;  // global opacity modulator, result clamped to [0, 1]
  double huShift = 0.0;       // every control point moved by this many HU

  friend bool operator==(const TfModulators&, const TfModulators&) = default;
};

// How the voxels of one segmentation label are rendered (rendering model, "Labels"); labels not
// listed use the main TF.
enum class LabelMode {
  main,    // classified with the TF of the sample's region, as unlabelled voxels
  hidden,  // read as -1024 HU (density 0) for sampling, gradients and MIP: cut out of the scan
  tf,      // classified with the label's own TF where it is the sample's nearest voxel's label
};

struct LabelStyle {
  int label = 1;  // 1..15
  std::string name;
  LabelMode mode = LabelMode::main;
  std::vector<ControlPoint> points;    // the own TF (mode tf), no modulators
  glm::vec3 color{0.9f, 0.85f, 0.7f};  // the label's color in lists, overlays and Slicer

  friend bool operator==(const LabelStyle&, const LabelStyle&) = default;
};

struct TransferFunction {
  std::string name;
  std::vector<ControlPoint> points;  // sorted by hu (sortPoints keeps them so)
  TfModulators modulators;
  // Per-label rendering; at most one entry per label (the first one counts).
  std::vector<LabelStyle> labels;
  // MIP window/level (HU) that goes with this TF; used when rendering in MIP mode.
  double mipWindow = 600;
  double mipLevel = 250;

  friend bool operator==(const TransferFunction&, const TransferFunction&) = default;
};

void sortPoints(TransferFunction& tf);

// Piecewise-linear evaluation at a HU value, modulators applied; constant beyond the end points,
// fully transparent black when there are no points.
glm::vec4 evaluate(const TransferFunction& tf, double hu);

struct TfTable {
  std::array<glm::vec4, kDensityLevels> rgba{};  // by density d, opacity per voxel unit
  // integratedOpacity[d] = sum of opacity over densities < d; [4096] = total (thesis sec. 4.2.2).
  std::array<double, kDensityLevels + 1> integratedOpacity{};
  // The same prefix sum over "opacity > 0" as integers: exact even for opacities too small to
  // change a floating-point sum, so the visibility query never misses a visible density.
  std::array<int, kDensityLevels + 1> integratedVisible{};

  // True iff some density in [lo, hi] (clamped to the table) has opacity > 0. O(1).
  bool anyVisible(int lo, int hi) const {
    if (hi < lo) return false;  // before clamping: [5000, 4500] is empty, not density 4095
    lo = lo < 0 ? 0 : (lo > kDensityLevels - 1 ? kDensityLevels - 1 : lo);
    hi = hi < 0 ? 0 : (hi > kDensityLevels - 1 ? kDensityLevels - 1 : hi);
    return integratedVisible[hi + 1] - integratedVisible[lo] > 0;
  }
};

TfTable buildTable(const TransferFunction& tf);

// A table whose anyVisible answers "visible in any of `tables`" (null entries ignored); only its
// visibility prefix sums are set.
TfTable visibilityUnion(const std::vector<const TfTable*>& tables);

}  // namespace angio
