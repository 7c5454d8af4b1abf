#pragma once
// Pre-integrated classification (rendering model, "Approximations"; Engel, Kraus and Ertl 2001):
// the segment between consecutive samples with densities s_f (front) and s_b (back), osd voxel
// units long, is classified by the emission-absorption integral of the TF over the density varying
// linearly from s_f to s_b, instead of by the TF at s_b alone. A thin shell of visible density
// that falls between two samples still colours the ray, so samples can be farther apart.
//
// The TF here is the table's 4096 entries, each holding for densities within half a unit of it (the
// nearest entry, as post-classification looks up), with extinction tau = -ln(1 - a) per voxel unit.
// For such a TF the integral needs no 2-D table: along a linear path the extinction integral is
// osd times the mean of tau over [s_f, s_b], a difference of prefix sums divided by s_b - s_f, so
//   alpha = 1 - exp(-osd mean(tau))               exact, at the full 4096-entry resolution;
//   rgb   = mean of rgb weighted by tau            the colour emitted along the segment.
// The colour neglects the segment's self-attenuation (its front hides its back); for a colour that
// changes by dc along a segment the error is about |dc| alpha^2 / 12 (second order in the segment's
// opacity). Building is O(4096) per TF, so a TF drag costs nothing measurable, and both voxel
// filters and trilinear use the same table. A segment within one entry (s_f and s_b round to the
// same density) gives exactly the post-classified sample: a constant medium renders as before.
// Shading: the raycasters shade a segment by the mean of the shading factors at its two ends (the
// back end's alone would shift the shading half a segment from the colour it modulates).
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "core/compositing.h"
#include "core/transfer_function.h"
#include "core/voxel.h"

namespace angio {

class PreintegratedTable {
 public:
  PreintegratedTable() = default;
  PreintegratedTable(const TfTable& table, double osd);

  // rgb and per-segment alpha of the segment from density `front` to `back` (both 0..4095), for
  // RayAccumulator::add like a SampleTable entry. Exactly 0 opacity when no density between the
  // two ends is visible, as the TF table's anyVisible says (empty-space skipping relies on it).
  glm::vec4 segment(float front, float back) const {
    const int f = tableIndex(front), b = tableIndex(back);
    if (f == b) return post_[f];
    return crossing(front, back, f, b, osd_);
  }
  // The same for a segment `samples` * osd long (adaptive sampling's skipped samples): the mean
  // extinction does not depend on the length, only the opacity does.
  glm::vec4 segment(float front, float back, int samples) const {
    if (samples == 1) return segment(front, back);
    const int f = tableIndex(front), b = tableIndex(back);
    if (f == b) return within(f, osd_ * samples);
    return crossing(front, back, f, b, osd_ * samples);
  }

 private:
  // Per table entry d: tau = -ln(1 - a) and rgb tau, and their sums over the entries below d. The
  // sums are doubles: a segment's integral is a difference of two of them, and a faint one (tau
  // 1e-3 over a unit) next to 10^5 of opaque ones below must keep its digits.
  struct alignas(64) Entry {
    double tauBelow = 0, tau = 0;
    glm::dvec3 emissionBelow{0.0}, emission{0.0};
  };

  glm::vec4 crossing(float front, float back, int f, int b, double length) const;
  glm::vec4 within(int entry, double length) const;

  double osd_ = 1.0;
  SampleTable post_{};          // post-classification at osd: the segment within one entry
  std::vector<Entry> entries_;  // kDensityLevels + 1 (the last: only sums, for range ends)
  std::array<int, kDensityLevels + 1> visibleBelow_{};  // TfTable::integratedVisible
};

// The frame's TFs (core/compositing.h FrameTables) pre-integrated for its osd, slot for slot.
struct PreintegratedTables {
  PreintegratedTable focus, context, outside;
  std::vector<PreintegratedTable> ownTables;  // FrameTables::ownSlot indexes them

  const PreintegratedTable& of(Region region, int label, const FrameTables& slots) const {
    if (slots.ownSlot[label] >= 0) return ownTables[slots.ownSlot[label]];
    return region == Region::focus ? focus : region == Region::context ? context : outside;
  }
};
PreintegratedTables preintegratedTables(const RegionTables& tables, double osd);

}  // namespace angio
