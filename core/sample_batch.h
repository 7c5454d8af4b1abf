#pragma once
// Eight consecutive samples of one ray reconstructed at once, for the trilinear and mean filters:
// positions, cells or voxels and densities in SIMD lanes, without a branch per sample. DVR then
// classifies them there (table entries, opacities, which are visible), with the trilinear filter
// shades them there too (the corners' central differences, interpolated), and composites only the
// visible ones, one by one, in ray order; MIP takes their maximum (core/fast_raycaster.cpp).
// The rows of a bundle share the in-plane positions and differ in the trilinear fraction along the
// rotation axis a, so a batch serves each row of the bundle from one set of corner reads. Voxels
// come from the flat volume or one block of the blocked volume (core/voxel_grid.h); hidden labels
// read as density 0, and a label with a TF of its own gives its samples that TF's table
// (LaneTables: by the label of the sample's nearest voxel or nearest corner, as one by one).
//
// xsimd (header-only, in Debian) gives one type per register width, so the same code builds for
// AVX2 (8 floats, what -march=x86-64-v3 enables) and for SSE or NEON elsewhere. It has no
// conversion between lane counts (4 doubles to 4 of 8 ints or floats) nor a lane bit mask, and its
// AVX2 gathers are not reached (below): those few operations use AVX's intrinsics where they exist.
//
// Every value is the scalar path's (core/volume_sampling.h): positions are samplePosition's (one
// fused multiply-add per axis), the nearest voxel floor(q + 0.5) and the cell cellAt's, clamped to
// the volume; the mean's seven densities are integers whose sum is exact in any order; trilinear
// interpolates along x, then y, then z with interpolate's fused multiply-add; tableIndex truncates.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/glm.hpp>
#include <xsimd/xsimd.hpp>

#include "core/compositing.h"
#include "core/label_tables.h"
#include "core/volume.h"
#include "core/volume_sampling.h"
#include "core/voxel_grid.h"

namespace angio {

using FloatLanes = xsimd::batch<float>;
using IntLanes = xsimd::batch<std::int32_t>;
using DoubleLanes = xsimd::batch<double>;
constexpr int kBatchSamples = int(FloatLanes::size);
static_assert(IntLanes::size == FloatLanes::size && DoubleLanes::size * 2 == FloatLanes::size,
              "a batch is two halves of double lanes");

// One row's classification of the batch's samples (scratch: left uninitialised until classifyRow
// fills it, since zeroing the batches of every span was measurable).
struct RowClasses {
  alignas(64) std::array<std::int32_t, kBatchSamples> entry;  // tableIndex(density)
  alignas(64) std::array<float, kBatchSamples> opacity;       // the table's alpha there
  std::uint32_t visible = 0;                                  // bit j: opacity[j] > 0
};

// 0, 1, 2, ...: each lane's sample after the batch's first.
alignas(64) constexpr std::array<double, kBatchSamples> kLaneNumbers = [] {
  std::array<double, kBatchSamples> numbers{};
  for (int j = 0; j < kBatchSamples; ++j) numbers[j] = j;
  return numbers;
}();

// Integer-valued doubles below 2^31, two halves, as one batch of ints.
inline IntLanes narrowToInt(const DoubleLanes& low, const DoubleLanes& high) {
#if XSIMD_WITH_AVX2
  return _mm256_set_m128i(_mm256_cvttpd_epi32(high), _mm256_cvttpd_epi32(low));
#else
  alignas(64) std::array<std::int32_t, kBatchSamples> lanes;
  for (std::size_t j = 0; j < DoubleLanes::size; ++j) {
    lanes[j] = std::int32_t(low.get(j));
    lanes[j + DoubleLanes::size] = std::int32_t(high.get(j));
  }
  return IntLanes::load_aligned(lanes.data());
#endif
}

// Gathers (xsimd 8.1's AVX2 gathers are never chosen: their enable_if cannot be deduced, so its
// lane-by-lane fallback runs; the intrinsics here where AVX2 exists).
inline IntLanes gatherInts(const std::int32_t* base, const IntLanes& index) {
#if XSIMD_WITH_AVX2
  return _mm256_i32gather_epi32(base, index, 4);
#else
  return IntLanes::gather(base, index);
#endif
}

inline FloatLanes gatherFloats(const float* base, const IntLanes& index) {
#if XSIMD_WITH_AVX2
  return _mm256_i32gather_ps(base, index, 4);
#else
  return FloatLanes::gather(base, index);
#endif
}

// Bit j: lane j is true.
inline std::uint32_t laneBits(const xsimd::batch_bool<float>& lanes) {
#if XSIMD_WITH_AVX
  return std::uint32_t(_mm256_movemask_ps(lanes));
#else
  std::uint32_t bits = 0;
  for (std::size_t j = 0; j < FloatLanes::size; ++j) bits |= std::uint32_t(lanes.get(j)) << j;
  return bits;
#endif
}

// Doubles, two halves, as one batch of floats (each rounded to nearest, as float(x) does).
inline FloatLanes narrowToFloat(const DoubleLanes& low, const DoubleLanes& high) {
#if XSIMD_WITH_AVX
  return _mm256_set_m128(_mm256_cvtpd_ps(high), _mm256_cvtpd_ps(low));
#else
  alignas(64) std::array<float, kBatchSamples> lanes;
  for (std::size_t j = 0; j < DoubleLanes::size; ++j) {
    lanes[j] = float(low.get(j));
    lanes[j + DoubleLanes::size] = float(high.get(j));
  }
  return FloatLanes::load_aligned(lanes.data());
#endif
}

// The positions q of half a batch, per axis; `half` 0 or 1, lanes past count at the last sample.
inline std::array<DoubleLanes, 3> halfPositions(const RaySamples& positions, long first, int count,
                                                int half) {
  const DoubleLanes lane = DoubleLanes::load_aligned(kLaneNumbers.data() + half * DoubleLanes::size);
  const DoubleLanes k =
      xsimd::min(DoubleLanes(double(first)) + lane, DoubleLanes(double(first + count - 1)));
  std::array<DoubleLanes, 3> q;
  for (int axis = 0; axis < 3; ++axis)
    q[axis] = xsimd::fma(k, DoubleLanes(positions.stepQ[axis]), DoubleLanes(positions.originQ[axis]));
  return q;
}

// Voxel (i, j, k) as an index into Volume::voxels, exact in doubles (below 2^53).
inline DoubleLanes linearIndex(const Volume& volume, const std::array<DoubleLanes, 3>& v) {
  const glm::dvec3 strides(1.0, double(volume.dims.x), double(volume.dims.x) * volume.dims.y);
  return xsimd::fma(v[2], DoubleLanes(strides.z), xsimd::fma(v[1], DoubleLanes(strides.y), v[0]));
}

// A batch's voxels as 32-bit lanes: indices relative to an even voxel index near them, since the
// lanes could not hold the indices of a volume of 2^31 voxels or more (1024 x 1024 x 2048).
struct VoxelLanes {
  std::size_t origin = 0;  // even
  IntLanes offset;         // voxel index - origin
};

// The voxel indices `index` (two halves, whole numbers >= 0) relative to the even index at or
// below lane 0 of the low half. False where an offset, or it plus `reach` (the largest offset a
// caller adds), could leave the 32-bit range.
inline bool voxelLanes(const std::array<DoubleLanes, 2>& index, int reach, VoxelLanes& lanes) {
  const double origin = 2.0 * std::floor(index[0].get(0) / 2.0);
  const DoubleLanes low = index[0] - DoubleLanes(origin), high = index[1] - DoubleLanes(origin);
  const DoubleLanes limit(double(std::int32_t{1} << 30) - reach);
  if (!xsimd::all((xsimd::abs(low) < limit) & (xsimd::abs(high) < limit))) return false;
  lanes.origin = std::size_t(origin);
  lanes.offset = narrowToInt(low, high);
  return true;
}

// The 16-bit voxels at `offset` (VoxelLanes), density and label bits. A lane reads the aligned
// 32-bit word holding its voxel (little-endian: an even index is the low half; the origin is even,
// so the offset's parity is the index's, and its arithmetic shift the word's). No read passes the
// volume's storage unless the voxel is the last of a volume with an odd count: callers keep every
// index below the last voxel's.
inline IntLanes voxelsAt(const std::int32_t* words, const IntLanes& offset) {
  static_assert(std::endian::native == std::endian::little, "voxel words read as little-endian");
  const IntLanes word = gatherInts(words, offset >> 1);
  return (word >> ((offset & IntLanes(1)) << 4)) & IntLanes(0xFFFF);
}

// The voxels at `offset` and at `offset` + 1 (the next along i) in one gather: each lane reads the
// unaligned 32-bit word that starts at its voxel, which is that word's low half (little-endian).
// Both voxels must lie in the storage.
struct VoxelPairLanes {
  IntLanes first, second;
};
inline VoxelPairLanes voxelPairsAt(const std::int32_t* words, const IntLanes& offset) {
#if XSIMD_WITH_AVX2
  const IntLanes word = _mm256_i32gather_epi32(words, offset, 2);  // scale 2: a voxel's bytes
#else
  alignas(64) std::array<std::int32_t, kBatchSamples> lanes;
  const auto* bytes = reinterpret_cast<const unsigned char*>(words);
  for (std::size_t j = 0; j < IntLanes::size; ++j)
    std::memcpy(&lanes[j], bytes + 2 * std::ptrdiff_t(offset.get(j)), sizeof(std::int32_t));
  const IntLanes word = IntLanes::load_aligned(lanes.data());
#endif
  return {word & IntLanes(0xFFFF), (word >> 16) & IntLanes(0xFFFF)};
}

// Voxels' densities as `read` gives them: PlainDensity's, or MaskedDensity's with the voxels of
// hidden labels read as 0 (core/label_tables.h).
inline IntLanes densitiesOf(const IntLanes& voxel, const PlainDensity&) {
  return voxel & IntLanes(0x0FFF);
}
inline IntLanes densitiesOf(const IntLanes& voxel, const MaskedDensity& read) {
  const IntLanes hidden = (IntLanes(std::int32_t(read.hiddenLabels)) >> (voxel >> 12)) & IntLanes(1);
  return voxel & IntLanes(0x0FFF) & (hidden - IntLanes(1));  // all bits where shown, none where hidden
}
template <class Read>
IntLanes densitiesAt(const std::int32_t* words, const IntLanes& offset, const Read& read) {
  return densitiesOf(voxelsAt(words, offset), read);
}

// Whether every voxel index of the half stays below the volume's last voxel.
inline bool belowLastVoxel(const Volume& volume, const DoubleLanes& highestIndex) {
  return xsimd::all(highestIndex < DoubleLanes(double(volume.voxels.size() - 1)));
}

// A batch's voxels ready to gather: the lanes' voxels as offsets from a voxel that starts a 32-bit
// word. Their neighbours are VoxelGrid::steps and strides away.
struct BatchVoxels {
  const std::int32_t* words = nullptr;  // the word whose low half is the voxel at offset 0
  IntLanes offset;
};

// Where a batch's voxels are, built half by half (so that only one half's coordinates are held at
// a time): each half's voxels v (whole numbers inside the volume) become indices into the flat
// volume's voxels, or into one block's window, for reads up to `reach` past them (the largest
// offset a caller adds through VoxelGrid::steps and strides). False, and the batch goes to the
// scalar path, where a flat volume's read could pass its last voxel (voxelsAt) or the lanes
// lie too far apart (voxelLanes), and where a blocked volume's lanes lie in more than one block.
class BatchAddresses {
 public:
  BatchAddresses(const VoxelGrid& grid, int reach) : grid_(grid), reach_(reach) {}

  bool addHalf(int half, const std::array<DoubleLanes, 3>& v) {
    if (!grid_.blocks()) {
      index_[half] = linearIndex(grid_.geometry(), v);
      return belowLastVoxel(grid_.geometry(), index_[half] + DoubleLanes(double(reach_)));
    }
    return addBlockedHalf(half, v);
  }

  // After both halves.
  bool finish(BatchVoxels& out) const {
    if (!grid_.blocks()) {
      VoxelLanes lanes;
      if (!voxelLanes(index_, reach_, lanes)) return false;
      out = {reinterpret_cast<const std::int32_t*>(grid_.geometry().voxels.data() + lanes.origin),
             lanes.offset};
      return true;
    }
    static_assert(kBlockSlotVoxels % 2 == 0, "every block starts a 32-bit word");
    const BlockedVolume& blocked = *grid_.blocks();
    out = {reinterpret_cast<const std::int32_t*>(blocked.blockVoxels(blocked.blockIndex(block_))),
           narrowToInt(index_[0], index_[1])};
    return true;
  }

 private:
  // Out of line: only frames from a blocked volume take it, and the flat volume's hot loop stays
  // as small as before (see the inlining limits in core/CMakeLists.txt).
  [[gnu::noinline]] bool addBlockedHalf(int half, const std::array<DoubleLanes, 3>& v) {
    if (half == 0)
      for (int axis = 0; axis < 3; ++axis) block_[axis] = int(v[axis].get(0)) / kBlockSize;
    const glm::ivec3 origin = BlockedVolume::windowOrigin(block_);
    std::array<DoubleLanes, 3> local;
    for (int axis = 0; axis < 3; ++axis) {
      local[axis] = v[axis] - DoubleLanes(double(origin[axis]));
      if (!xsimd::all((local[axis] >= DoubleLanes(double(kBlockOverlapBelow))) &
                      (local[axis] < DoubleLanes(double(kBlockOverlapBelow + kBlockSize)))))
        return false;
    }
    const glm::dvec3 strides(VoxelGrid::kBlockStrides);
    index_[half] = xsimd::fma(local[2], DoubleLanes(strides.z),
                              xsimd::fma(local[1], DoubleLanes(strides.y), local[0]));
    return true;
  }

  const VoxelGrid& grid_;
  const int reach_;
  glm::ivec3 block_{0};
  std::array<DoubleLanes, 2> index_;
};

// The cells of a batch: corner densities and fractions (cellAt), per lane.
struct CellLanes {
  std::array<FloatLanes, 8> corner;  // corner(dx, dy, dz) = dx + 2 dy + 4 dz
  std::array<FloatLanes, 3> frac;
  BatchVoxels voxels;        // corner (0, 0, 0) of each lane
  bool shellInside = false;  // base - 1 .. base + 2 can be read along every axis, for every lane
  IntLanes labels;           // if asked for: the corners' labels, 4 bits each, corner c at bit 4 c
};

// The samples first .. first + count - 1 of one ray (count <= kBatchSamples; the lanes past count
// repeat the last sample and are not visible), classified for each row of a bundle. The trilinear
// filter keeps the cells, for shading.
template <int Rows>
struct SampleBatch {
  long first = 0;
  std::array<RowClasses, Rows> rows;
  CellLanes cells;
};

// Labels with TFs of their own, in lanes: the tables one after the other (the region's first) and
// per label where its table starts there (0: the region's; FrameTables::of(region, label)).
struct LaneTables {
  const glm::vec4* entries = nullptr;
  alignas(64) std::array<std::int32_t, kLabelCount> start{};
};

// The table entries and opacities of one row's densities, and which are visible: each lane's entry
// in its table, which starts at `tableStart` in `tables`.
inline void classifyRow(const glm::vec4* tables, const IntLanes& tableStart, const FloatLanes& density,
                        int count, RowClasses& row) {
  // tableIndex: the conversion truncates, as int() does.
  const IntLanes entry =
      xsimd::min(xsimd::to_int(density + FloatLanes(0.5f)), IntLanes(kDensityLevels - 1)) + tableStart;
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "the table's entries are packed floats");
  const FloatLanes opacity = gatherFloats(&tables[0].a, entry << 2);  // alpha every 4th float
  entry.store_aligned(row.entry.data());
  opacity.store_aligned(row.opacity.data());
  row.visible = laneBits(opacity > FloatLanes(0.f)) & ((std::uint32_t{1} << count) - 1);
}
inline void classifyRow(const SampleTable& table, const FloatLanes& density, int count,
                        RowClasses& row) {
  classifyRow(table.data(), IntLanes(0), density, count, row);
}

// Where each lane's table starts (LaneTables::start of the lane's label).
inline IntLanes tableStarts(const LaneTables& own, const IntLanes& labels) {
  return gatherInts(own.start.data(), labels);
}

// The TF tables the rows of a batch classify with: per row its table's first entry (nullptr: the
// row's samples lie in a region that is not rendered, none is visible), or, with `own`, the labels'
// tables (every row's entry then LaneTables::entries).
template <int Rows>
struct BatchTables {
  std::array<const glm::vec4*, Rows> row{};
  const LaneTables* own = nullptr;
};

// The mean (thesis sec. 4.4: the nearest voxel and its six face neighbours, equally weighted), one
// row: the rows of a bundle read the same voxels. False, with nothing set, where a voxel lacks
// a neighbour (the volume's faces) or the lanes lie too far apart (voxelLanes): there the caller
// samples one by one.
template <class Read>
bool meanDensities(const VoxelGrid& grid, const Read& read, const RaySamples& positions, long first,
                   int count, FloatLanes& densities, IntLanes* labels = nullptr) {
  const Volume& volume = grid.geometry();
  const glm::ivec3 strides = grid.strides();
  BatchAddresses addresses(grid, strides.z);
  for (int half = 0; half < 2; ++half) {
    const std::array<DoubleLanes, 3> q = halfPositions(positions, first, count, half);
    std::array<DoubleLanes, 3> v;  // nearestVoxel
    auto inside = xsimd::batch_bool<double>(true);
    for (int axis = 0; axis < 3; ++axis) {
      v[axis] = xsimd::min(xsimd::max(xsimd::floor(q[axis] + DoubleLanes(0.5)), DoubleLanes(0.0)),
                           DoubleLanes(double(volume.dims[axis] - 1)));
      inside = inside & (v[axis] >= DoubleLanes(1.0)) &
               (v[axis] <= DoubleLanes(double(volume.dims[axis] - 2)));
    }
    // A flat volume lacks the neighbours at its faces; a block's window replicates them.
    if (!grid.blocks() && !xsimd::all(inside)) return false;
    if (!addresses.addHalf(half, v)) return false;
  }
  BatchVoxels voxels;
  if (!addresses.finish(voxels)) return false;
  const IntLanes voxel = voxelsAt(voxels.words, voxels.offset);
  if (labels) *labels = voxel >> 12;  // labelOf
  IntLanes sum = densitiesOf(voxel, read);
  for (int axis = 0; axis < 3; ++axis)
    sum += densitiesAt(voxels.words, voxels.offset - IntLanes(strides[axis]), read) +
           densitiesAt(voxels.words, voxels.offset + IntLanes(strides[axis]), read);
  densities = xsimd::to_float(sum) / FloatLanes(7.f);
  return true;
}

// One row's classification with its tables (BatchTables); `labels` gives the lanes' labels where
// labels have TFs of their own.
template <int Rows, class Labels>
void classifyRowWith(const BatchTables<Rows>& tables, int r, const FloatLanes& density, int count,
                     Labels&& labels, RowClasses& row) {
  if (tables.own)
    classifyRow(tables.own->entries, tableStarts(*tables.own, labels()), density, count, row);
  else if (tables.row[r]) classifyRow(tables.row[r], IntLanes(0), density, count, row);
  else row = {.entry = {}, .opacity = {}, .visible = 0};
}

// With own TFs (BatchTables::own) each sample's TF is its nearest voxel's label's.
template <int Rows, class Read>
bool classifyMeanSamples(const VoxelGrid& grid, const Read& read, const RaySamples& positions,
                         const BatchTables<Rows>& tables, long first, int count,
                         SampleBatch<Rows>& batch) {
  FloatLanes densities;
  IntLanes labels;
  if (!meanDensities(grid, read, positions, first, count, densities, tables.own ? &labels : nullptr))
    return false;
  batch.first = first;
  classifyRowWith(
      tables, 0, densities, count, [&] { return labels; }, batch.rows[0]);
  return true;
}

inline FloatLanes interpolateLanes(const FloatLanes& a, const FloatLanes& b, const FloatLanes& t) {
  return xsimd::fma(b - a, t, a);
}

// cellAt of every lane, and the cells' corner densities; with `Shell` also whether the cells'
// shell can be read (shading). False where BatchAddresses is.
template <bool Shell, class Read>
bool cellLanes(const VoxelGrid& grid, const Read& read, const RaySamples& positions, long first,
               int count, CellLanes& cells, bool labels = false) {
  const Volume& volume = grid.geometry();
  const glm::ivec3 steps = grid.steps();
  BatchAddresses addresses(grid, steps.x + steps.y + steps.z);
  std::array<std::array<DoubleLanes, 2>, 3> frac;
  auto shellInside = xsimd::batch_bool<double>(true);
  for (int half = 0; half < 2; ++half) {
    const std::array<DoubleLanes, 3> q = halfPositions(positions, first, count, half);
    std::array<DoubleLanes, 3> base;
    for (int axis = 0; axis < 3; ++axis) {
      const DoubleLanes clamped =
          xsimd::min(xsimd::max(q[axis], DoubleLanes(0.0)), DoubleLanes(double(volume.dims[axis] - 1)));
      base[axis] =
          xsimd::min(xsimd::floor(clamped), DoubleLanes(double(std::max(volume.dims[axis] - 2, 0))));
      frac[axis][half] = clamped - base[axis];
      if constexpr (Shell)
        shellInside = shellInside & (base[axis] >= DoubleLanes(1.0)) &
                      (base[axis] <= DoubleLanes(double(volume.dims[axis] - 3)));
    }
    if (!addresses.addHalf(half, base)) return false;
  }
  BatchVoxels& voxels = cells.voxels;
  if (!addresses.finish(voxels)) return false;
  // A block's window holds base - 1 .. base + 2 of every voxel in its core.
  cells.shellInside = Shell && (grid.blocks() || xsimd::all(shellInside));
  for (int axis = 0; axis < 3; ++axis) cells.frac[axis] = narrowToFloat(frac[axis][0], frac[axis][1]);
  const auto take = [&](int c, const IntLanes& voxel) {
    cells.corner[c] = xsimd::to_float(densitiesOf(voxel, read));
    if (labels) cells.labels = cells.labels | ((voxel >> 12) << (4 * c));  // labelOf
  };
  if (labels) cells.labels = IntLanes(0);
  if (steps.x != 1) {  // a flat volume one voxel wide along i
    for (int c = 0; c < 8; ++c) {
      const int offset = (c & 1) * steps.x + (c >> 1 & 1) * steps.y + (c >> 2) * steps.z;
      take(c, voxelsAt(voxels.words, voxels.offset + IntLanes(offset)));
    }
    return true;
  }
  // The corners along i are neighbours in memory: one gather reads both.
  for (int c = 0; c < 8; c += 2) {
    const int offset = (c >> 1 & 1) * steps.y + (c >> 2) * steps.z;
    const VoxelPairLanes pair = voxelPairsAt(voxels.words, voxels.offset + IntLanes(offset));
    take(c, pair.first);
    take(c + 1, pair.second);
  }
  return true;
}

// Each lane's label as one row of a bundle sees its cell: the label of the nearest corner
// (TrilinearRaySampler::label), from cells filled with their labels.
inline IntLanes nearestLabels(const CellLanes& cells, int axis, float fracA) {
  FloatLanes corner(0.f);  // nearestCorner's index, dx + 2 dy + 4 dz
  for (int a = 0; a < 3; ++a) {
    const FloatLanes f = a == axis ? FloatLanes(fracA) : cells.frac[a];
    corner += xsimd::select(f >= FloatLanes(0.5f), FloatLanes(float(1 << a)), FloatLanes(0.f));
  }
  return (cells.labels >> (xsimd::to_int(corner) << 2)) & IntLanes(0xF);
}

// The bilinear value of corner values `c` (corner(dx, dy, dz) as CellLanes::corner) in the
// cells' plane dz, along x then y (bilinearInPlane).
inline FloatLanes bilinearLanes(const std::array<FloatLanes, 8>& c, int dz, const FloatLanes& fx,
                                const FloatLanes& fy) {
  return interpolateLanes(interpolateLanes(c[4 * dz], c[4 * dz + 1], fx),
                          interpolateLanes(c[4 * dz + 2], c[4 * dz + 3], fx), fy);
}

// Trilinear of corner values `c` for each row of a bundle: the rows' fractions along the rotation
// axis `axis` replace the cells' `f` (TrilinearRaySampler::interpolateRow). Calls perRow(r, values)
// for rows r = 0 .. rows - 1.
template <class PerRow>
void interpolateRows(const std::array<FloatLanes, 8>& c, const std::array<FloatLanes, 3>& f, int axis,
                     const float* fracA, int rows, PerRow&& perRow) {
  if (axis == 2) {  // the two planes serve every row
    const FloatLanes low = bilinearLanes(c, 0, f[0], f[1]), high = bilinearLanes(c, 1, f[0], f[1]);
    for (int r = 0; r < rows; ++r) perRow(r, interpolateLanes(low, high, FloatLanes(fracA[r])));
    return;
  }
  for (int r = 0; r < rows; ++r) {
    const FloatLanes fx = axis == 0 ? FloatLanes(fracA[r]) : f[0];
    const FloatLanes fy = axis == 1 ? FloatLanes(fracA[r]) : f[1];
    perRow(r, interpolateLanes(bilinearLanes(c, 0, fx, fy), bilinearLanes(c, 1, fx, fy), f[2]));
  }
}

// Trilinear densities for each row of a bundle (TrilinearRaySampler::density), for MIP. Calls
// perRow(r, densities) for rows r = 0 .. rows - 1; false, without calling it, where the scalar
// path must take the batch.
template <class Read, class PerRow>
bool trilinearRowDensities(const VoxelGrid& grid, const Read& read, const RaySamples& positions,
                           long first, int count, int axis, const float* fracA, int rows,
                           PerRow&& perRow) {
  CellLanes cells;
  if (!cellLanes</*Shell=*/false>(grid, read, positions, first, count, cells)) return false;
  interpolateRows(cells.corner, cells.frac, axis, fracA, rows, perRow);
  return true;
}

// With own TFs (BatchTables::own) each sample's TF is its nearest corner's label's.
template <int Rows, class Read>
bool classifyTrilinearSamples(const VoxelGrid& grid, const Read& read, const RaySamples& positions,
                              const BatchTables<Rows>& tables, long first, int count, int axis,
                              const float* fracA, int rows, SampleBatch<Rows>& batch) {
  batch.first = first;
  if (!cellLanes</*Shell=*/true>(grid, read, positions, first, count, batch.cells,
                                 tables.own != nullptr))
    return false;
  interpolateRows(batch.cells.corner, batch.cells.frac, axis, fracA, rows,
                  [&](int r, const FloatLanes& density) {
                    classifyRowWith(
                        tables, r, density, count,
                        [&] { return nearestLabels(batch.cells, axis, fracA[r]); }, batch.rows[r]);
                  });
  return true;
}

// The central differences of the cells' corners along every axis (as TrilinearRaySampler's
// loadGradients: the neighbour inside the cell is the corner across it, the other lies in the
// shell around the cell), gradient[axis][corner]. Needs cells.shellInside (which implies at least
// four voxels along every axis, so the voxels along i are neighbours in memory).
template <class Read>
std::array<std::array<FloatLanes, 8>, 3> cornerGradients(const VoxelGrid& grid, const Read& read,
                                                         const CellLanes& cells) {
  const glm::ivec3 strides = grid.strides();
  const glm::dvec3 spacing = grid.geometry().spacing;
  const BatchVoxels& v = cells.voxels;
  const auto density = [&](const IntLanes& voxel) { return xsimd::to_float(densitiesOf(voxel, read)); };
  const auto pairAt = [&](int dx, int dy, int dz) {
    return voxelPairsAt(v.words, v.offset + IntLanes(dx + dy * strides.y + dz * strides.z));
  };
  const auto& c = cells.corner;
  std::array<std::array<FloatLanes, 8>, 3> g;
  const auto difference = [](const FloatLanes& below, const FloatLanes& above, double spacing) {
    return (above - below) * FloatLanes(float(0.5 / spacing));  // centralDifference
  };
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy) {  // along i: voxels -1 and 2 of the cell's row
      const int row = 2 * dy + 4 * dz;
      g[0][row] = difference(density(pairAt(-1, dy, dz).first), c[row + 1], spacing.x);
      g[0][row + 1] = difference(c[row], density(pairAt(1, dy, dz).second), spacing.x);
    }
  for (int dz = 0; dz < 2; ++dz) {  // along j: rows -1 and 2 of the cell's plane
    const VoxelPairLanes below = pairAt(0, -1, dz), above = pairAt(0, 2, dz);
    const int plane = 4 * dz;
    g[1][plane] = difference(density(below.first), c[plane + 2], spacing.y);
    g[1][plane + 1] = difference(density(below.second), c[plane + 3], spacing.y);
    g[1][plane + 2] = difference(c[plane], density(above.first), spacing.y);
    g[1][plane + 3] = difference(c[plane + 1], density(above.second), spacing.y);
  }
  for (int dy = 0; dy < 2; ++dy) {  // along k: planes -1 and 2
    const VoxelPairLanes below = pairAt(0, dy, -1), above = pairAt(0, dy, 2);
    const int row = 2 * dy;
    g[2][row] = difference(density(below.first), c[row + 4], spacing.z);
    g[2][row + 1] = difference(density(below.second), c[row + 5], spacing.z);
    g[2][row + 4] = difference(c[row], density(above.first), spacing.z);
    g[2][row + 5] = difference(c[row + 1], density(above.second), spacing.z);
  }
  return g;
}

// shadingFactor (core/compositing.h) of each lane's gradient, the same operations in lanes.
inline FloatLanes shadingLanes(const Shading& shading, const std::array<FloatLanes, 3>& g,
                               const glm::vec3& viewDir) {
  const FloatLanes length = xsimd::sqrt(xsimd::fma(g[2], g[2], xsimd::fma(g[1], g[1], g[0] * g[0])));
  const FloatLanes facing =
      xsimd::fma(g[2], FloatLanes(viewDir.z),
                 xsimd::fma(g[1], FloatLanes(viewDir.y), g[0] * FloatLanes(viewDir.x)));
  const FloatLanes shade =
      FloatLanes(float(shading.ka)) + FloatLanes(float(shading.kd)) * xsimd::abs(facing) / length;
  return xsimd::select(length < FloatLanes(1e-3f), FloatLanes(1.f), shade);
}

// The shading factors of a classified batch's samples for each row (TrilinearRaySampler::gradient,
// then shadingFactor), into shades[r]; false where the cells' shell cannot be read in lanes (a flat
// volume's faces): there the caller shades one by one.
template <int Rows, class Read>
bool shadeRows(const VoxelGrid& grid, const Read& read, const SampleBatch<Rows>& batch, int axis,
               const float* fracA, int rows, const Shading& shading, const glm::vec3& viewDir,
               std::array<std::array<float, kBatchSamples>, std::size_t(Rows)>& shades) {
  if (!batch.cells.shellInside) return false;
  const auto corners = cornerGradients(grid, read, batch.cells);
  std::array<std::array<FloatLanes, 3>, Rows> gradients;
  for (int component = 0; component < 3; ++component)
    interpolateRows(corners[component], batch.cells.frac, axis, fracA, rows,
                    [&](int r, const FloatLanes& value) { gradients[r][component] = value; });
  for (int r = 0; r < rows; ++r)
    shadingLanes(shading, gradients[r], viewDir).store_unaligned(shades[r].data());
  return true;
}

// The largest of lanes from .. count - 1 of `densities` (-infinity where from >= count).
inline float largestDensity(const FloatLanes& densities, int from, int count) {
  alignas(64) std::array<float, kBatchSamples> lanes;
  densities.store_aligned(lanes.data());
  float largest = -std::numeric_limits<float>::infinity();
  for (int j = from; j < count; ++j) largest = std::max(largest, lanes[j]);
  return largest;
}

}  // namespace angio
