#include "segment/bone_removal.h"

#include <algorithm>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "segment/coarse_grid.h"
#include "segment/lumen_protection.h"
#include "segment/mask_filters.h"
#include "segment/segmentation_run.h"

// Bone: on the coarse grid, blocks whose brightest voxel is above cortexHu seed it (cortex is thin,
// so the block maximum keeps it); a closing by one block seals pinholes in thin cortex; pieces
// smaller than minBoneMm3 are dropped (calcified plaques are isolated specks and rings); holes are
// filled (marrow and cancellous bone, whose densities overlap soft tissue and lumen, are enclosed by
// cortex). Per voxel: the solid eroded by one block is bone; within one block of the solid's edge a
// voxel is bone when it is above boneEdgeHu, or above cortexHu where contrast-filled regions are
// near (so a lumen touching bone stays out). Table: the body is the largest piece above bodyHu with
// its holes filled; beyond a block from it (the body's partial-volume rim goes), what is above air
// and runs along most of the scan is the table; per voxel it is refined by the same
// thresholds.

namespace angio {

namespace {

using namespace segment;

constexpr std::uint8_t kLabelBits = 0x0f;
constexpr std::uint8_t kProtectedBit = 0x80;  // beside the 4 label bits, during the run only
constexpr short kMaxHu = 32767;

// Coarse masks the per-voxel decision reads; empty pointers for what was not asked for.
struct Zones {
  MaskImage::Pointer boneCore, boneBand, nearVessel;
  MaskImage::Pointer table, nearBody;
};

// Progress steps: the ITK filters and the run's own passes, as the functions below make them.
constexpr int kBoneSteps = 11;
constexpr int kTableSteps = 9;
constexpr int kCommonSteps = 3;

int stepsFor(const BoneRemovalOptions& options) {
  return kCommonSteps + (options.bone ? kBoneSteps : 0) + (options.table ? kTableSteps : 0);
}

// The input's labels, without those this run recomputes.
std::vector<std::uint8_t> startingLabels(const Volume& volume, const BoneRemovalOptions& options,
                                         const SegmentationRun& run) {
  std::vector<std::uint8_t> labels(volume.voxelCount());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, labels.size(), 1 << 20),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      run.throwIfCancelled();
                      for (std::size_t n = range.begin(); n != range.end(); ++n) {
                        const int label = labelOf(volume.voxels[n]);
                        const bool recomputed = (label == kBoneLabel && options.bone) ||
                                                (label == kTableLabel && options.table);
                        labels[n] = recomputed ? 0 : std::uint8_t(label);
                      }
                    });
  return labels;
}

// Sets the bone zones.
void findBone(const Volume& volume, const CoarseGrid& grid, const std::vector<std::uint8_t>& labels,
              const BoneRemovalOptions& options, Zones& zones, SegmentationRun& run) {
  HuImage::Pointer maxima =
      shrinkToBlocks(volume, grid, BlockValue::maximum, labels, kProtectedBit, run);
  run.stepDone();
  MaskImage::Pointer dense = threshold(maxima, options.cortexHu, kMaxHu, run);
  maxima = nullptr;
  dense = erode(dilate(dense, 1, run), 1, run);  // a closing: seals pinholes in thin cortex
  dense = keepPiecesOfAtLeast(dense, options.minBoneMm3 / grid.voxelMm3(), run);
  MaskImage::Pointer solid = fillHoles(dense, run);
  zones.boneCore = erode(solid, 1, run);
  zones.boneBand = dilate(solid, 1, run);
}

// Contrast-filled regions beyond the bone's band (the partial-volume rim around bone is in the
// band, so it is not taken for a vessel), grown by two blocks: back across the band to the solid's
// edge, where a lumen touches bone.
MaskImage::Pointer findNearVessels(const HuImage* means, const MaskImage* boneBand,
                                   const BoneRemovalOptions& options, SegmentationRun& run) {
  MaskImage::Pointer lumen = threshold(means, options.lumenHu, options.cortexHu - 1, run);
  lumen = subtract(lumen, boneBand, run);
  return dilate(lumen, 2, run);
}

void findTable(const HuImage* means, const BoneRemovalOptions& options, Zones& zones,
               SegmentationRun& run) {
  MaskImage::Pointer body = threshold(means, options.bodyHu, kMaxHu, run);
  body = keepLargestPiece(body, run);
  body = fillHoles(body, run);
  zones.nearBody = dilate(body, 1, run);
  // Without the body's partial-volume rim (within a block of it), which runs along the scan too.
  MaskImage::Pointer outside = threshold(means, options.airHu, kMaxHu, run);
  outside = subtract(outside, zones.nearBody, run);
  MaskImage::Pointer table = keepPiecesAlongK(outside, options.minTableLengthFraction, run);
  zones.table = dilate(table, 2, run);  // back to the body where the patient lies on the pad
}

struct VoxelRule {
  const BoneRemovalOptions& options;
  const std::uint8_t *boneCore = nullptr, *boneBand = nullptr, *nearVessel = nullptr;
  const std::uint8_t *table = nullptr, *nearBody = nullptr;

  static const std::uint8_t* buffer(const MaskImage::Pointer& mask) {
    return mask ? mask->GetBufferPointer() : nullptr;
  }
  explicit VoxelRule(const BoneRemovalOptions& o, const Zones& zones)
      : options(o), boneCore(buffer(zones.boneCore)), boneBand(buffer(zones.boneBand)),
        nearVessel(buffer(zones.nearVessel)), table(buffer(zones.table)),
        nearBody(buffer(zones.nearBody)) {}

  bool isBone(std::size_t c, double hu) const {
    if (!boneCore) return false;
    if (boneCore[c]) return true;
    return boneBand[c] && hu > (nearVessel[c] ? options.cortexHu : options.boneEdgeHu);
  }
  bool isTable(std::size_t c, double hu) const {
    return table && table[c] && hu > options.airHu && (hu < options.bodyHu || !nearBody[c]);
  }
  // The voxel's final label from its starting byte (label bits and protection flag).
  std::uint8_t label(std::uint8_t start, std::size_t c, double hu) const {
    if (start & kLabelBits) return start & kLabelBits;
    if (!(start & kProtectedBit) && isBone(c, hu)) return kBoneLabel;
    return isTable(c, hu) ? kTableLabel : 0;
  }
};

void decideVoxels(const Volume& volume, const CoarseGrid& grid, const VoxelRule& rule,
                  std::vector<std::uint8_t>& labels, LabelResult& result, const SegmentationRun& run) {
  using Counts = std::array<std::size_t, kMaxLabel + 1>;
  tbb::combinable<Counts> counts([] { return Counts{}; });
  tbb::parallel_for(tbb::blocked_range<int>(0, volume.dims.z),
                    [&](const tbb::blocked_range<int>& slices) {
                      Counts& local = counts.local();
                      for (int k = slices.begin(); k != slices.end(); ++k) {
                        run.throwIfCancelled();
                        for (int j = 0; j < volume.dims.y; ++j) {
                          for (int i = 0; i < volume.dims.x; ++i) {
                            const std::size_t n = volume.indexOf(i, j, k);
                            const double hu = huOfDensity(densityOf(volume.voxels[n]));
                            labels[n] = rule.label(labels[n], grid.indexOf(i, j, k), hu);
                            ++local[labels[n]];
                          }
                        }
                      }
                    });
  counts.combine_each([&](const Counts& local) {
    for (int label = 0; label <= kMaxLabel; ++label) result.voxelsPerLabel[label] += local[label];
  });
}

}  // namespace

LabelResult removeBoneAndTable(const Volume& volume, const Centerlines* protect,
                               const BoneRemovalOptions& options, const SegmentationProgress& progress) {
  SegmentationRun run(progress, stepsFor(options));
  LabelResult result;
  try {
    std::vector<std::uint8_t> labels = startingLabels(volume, options, run);
    if (protect && options.bone)
      markLumen(labels, kProtectedBit, volume, *protect, options.protectMarginMm);
    run.stepDone();
    const CoarseGrid grid = coarseGridFor(volume);
    Zones zones;
    if (options.bone) findBone(volume, grid, labels, options, zones, run);
    HuImage::Pointer means;
    if (options.bone || options.table) {
      means = shrinkToBlocks(volume, grid, BlockValue::mean, {}, 0, run);
      run.stepDone();
    }
    if (options.bone) zones.nearVessel = findNearVessels(means, zones.boneBand, options, run);
    if (options.table) findTable(means, options, zones, run);
    means = nullptr;
    decideVoxels(volume, grid, VoxelRule(options, zones), labels, result, run);
    run.stepDone();
    result.labels = std::move(labels);
  } catch (const Cancelled&) {
    return {.labels = {}, .voxelsPerLabel = {}, .cancelled = true};
  }
  return result;
}

std::string calibrationWarning(const Volume& volume) {
  if (looksHuCalibrated(volume)) return "";
  return "almost no voxel below -500 HU (air, lung): the values may not be calibrated HU, and "
         "bone removal's HU thresholds may label vessels";
}

void applyLabels(Volume& volume, const std::vector<std::uint8_t>& labels) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, std::min(labels.size(), volume.voxels.size())),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t n = range.begin(); n != range.end(); ++n)
                        volume.voxels[n] = Voxel((volume.voxels[n] & 0x0FFF) | (labels[n] << 12));
                    });
}

}  // namespace angio
