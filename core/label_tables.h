#pragma once
// How a render treats each of the 16 labels (rendering model, "Labels"), as the raycasters look it
// up per voxel: a density mask that makes a hidden label's voxels read 0 (-1024 HU), and the TF
// table of a label that has its own. Built once per scene from the TF's label styles.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/transfer_function.h"
#include "core/voxel.h"

namespace angio {

// A voxel's density with hidden labels cut out: v & mask[label], the mask 0 for a hidden label.
struct MaskedDensity {
  std::array<Voxel, kLabelCount> mask;
  std::uint32_t hiddenLabels = 0;  // bit l: label l is hidden (mask[l] == 0), for SIMD lanes
  int operator()(Voxel v) const { return v & mask[labelOf(v)]; }
};

class LabelTables {
 public:
  LabelTables();  // every label as unlabelled voxels
  explicit LabelTables(const std::vector<LabelStyle>& styles);

  bool hidden(int label) const { return read_.mask[label] == 0; }
  // The label's own TF, nullptr where it uses the region's.
  const TfTable* ownTf(int label) const { return own_[label] ? own_[label].get() : nullptr; }
  bool hidesAny() const { return hidesAny_; }
  bool ownsAny() const { return ownsAny_; }
  // True iff some label is rendered differently from unlabelled voxels.
  bool active() const { return hidesAny_ || ownsAny_; }
  const MaskedDensity& density() const { return read_; }

 private:
  MaskedDensity read_;
  std::array<std::shared_ptr<const TfTable>, kLabelCount> own_{};
  bool hidesAny_ = false;
  bool ownsAny_ = false;
};

}  // namespace angio
