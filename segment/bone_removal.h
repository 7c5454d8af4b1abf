#pragma once
// Automatic bone (label 1) and table (label 2) removal from the density alone (rendering-model.md,
// "Labels"). Bone: cortex and calcium above cortexHu seed it, small pieces (calcified plaques) are
// dropped, holes are filled so marrow and cancellous bone join the cortex; the edge is refined per
// voxel, strictly next to contrast-filled vessels so a lumen touching bone stays out. Table: what
// is denser than air outside the body and runs along most of the scan. Heavy morphology runs on a
// grid coarsened to about 1.6 mm with ITK filters; the labels are then decided per voxel.
// Centerlines, when given, protect their lumen: no voxel within radius + protectMarginMm of them
// becomes bone, and they seed nothing.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/labels.h"
#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

struct BoneRemovalOptions {
  bool bone = true;   // (re)compute label 1; off: existing label-1 voxels are kept as they are
  bool table = true;  // (re)compute label 2; off: likewise
  // Cortex and calcium: above contrast-filled lumen (CTA lumen reads ~250-500 HU).
  double cortexHu = 600;
  // The bone's edge against soft tissue, where no vessel is near: between muscle and cancellous bone.
  double boneEdgeHu = 120;
  // Contrast-filled lumen starts here: near such regions the bone's edge is cortexHu instead.
  double lumenHu = 200;
  // Dense pieces smaller than this are calcified plaques, not bone (the smallest bones the
  // workstation cares about, a metatarsal's cortex, are a few cm^3).
  double minBoneMm3 = 1000;
  // The body: skin and soft tissue above this; the table's foam pad lies below it.
  double bodyHu = -400;
  // Anything above this outside the body is not air (table shell and pad).
  double airHu = -900;
  // The table runs along at least this fraction of the scan's length (k extent).
  double minTableLengthFraction = 0.5;
  double protectMarginMm = 1.5;

  friend bool operator==(const BoneRemovalOptions&, const BoneRemovalOptions&) = default;
};

struct SegmentationProgress {
  std::function<void(double)> progress;  // fraction in [0, 1], from the calling thread; may be empty
  const std::atomic<bool>* cancel = nullptr;  // when it turns true, the run stops within about a second
};

struct LabelResult {
  // One label (0..15) per voxel, i fastest (Volume::voxels' order); empty when cancelled.
  std::vector<std::uint8_t> labels;
  std::array<std::size_t, kMaxLabel + 1> voxelsPerLabel{};
  bool cancelled = false;
};

// The volume's labels with bone and table (re)computed. User labels (3..15) are kept as they are and
// never overwritten. protect may be null; its centerlines may be in either frame.
LabelResult removeBoneAndTable(const Volume& volume, const Centerlines* protect,
                               const BoneRemovalOptions& options = {},
                               const SegmentationProgress& progress = {});

// Why the thresholds (in HU) may not fit the volume, or "": a CT scan always holds air or lung
// (below -500 HU) around or in the body; a volume with almost none is not calibrated in HU (an
// MR angiogram, a crop inside the body, a volume scaled on export), and bone found there is not
// to be trusted.
std::string calibrationWarning(const Volume& volume);

// Writes labels (one per voxel, as LabelResult::labels) into the volume's label bits.
void applyLabels(Volume& volume, const std::vector<std::uint8_t>& labels);

}  // namespace angio
