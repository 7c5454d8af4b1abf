#include "gui/label_change.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace angio {

LabelChange changeTo(const Volume& volume, const std::vector<std::uint8_t>& labels, std::string what) {
  LabelChange change{std::move(what), {}, {}, {}};
  for (std::size_t n = 0; n < volume.voxels.size(); ++n) {
    const int now = labelOf(volume.voxels[n]);
    if (now == labels[n]) continue;
    change.voxels.push_back(n);
    change.before.push_back(std::uint8_t(now));
    change.after.push_back(labels[n]);
  }
  return change;
}

LabelChange changeOf(const Volume& volume, const std::vector<std::size_t>& voxels, int label,
                     std::string what) {
  LabelChange change{std::move(what), {}, {}, {}};
  for (const std::size_t n : voxels) {
    const int now = labelOf(volume.voxels[n]);
    if (now == label) continue;
    change.voxels.push_back(n);
    change.before.push_back(std::uint8_t(now));
    change.after.push_back(std::uint8_t(label));
  }
  return change;
}

void apply(const LabelChange& change, bool undo, Volume& volume, LabelCounts& counts) {
  const std::vector<std::uint8_t>& to = undo ? change.before : change.after;
  for (std::size_t m = 0; m < change.voxels.size(); ++m) {
    Voxel& voxel = volume.voxels[change.voxels[m]];
    --counts[labelOf(voxel)];
    ++counts[to[m]];
    voxel = withLabel(voxel, to[m]);
  }
}

LabelCounts countLabels(const Volume& volume) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, volume.voxels.size(), 1 << 16), LabelCounts{},
      [&](const tbb::blocked_range<std::size_t>& range, LabelCounts counts) {
        for (std::size_t n = range.begin(); n != range.end(); ++n) ++counts[labelOf(volume.voxels[n])];
        return counts;
      },
      [](LabelCounts a, const LabelCounts& b) {
        for (int label = 0; label < kLabelCount; ++label) a[label] += b[label];
        return a;
      });
}

}  // namespace angio
