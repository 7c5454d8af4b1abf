#pragma once
// The labelled test volumes of the label volume and segmentation file tests: a CT file on disk
// (plain or stored with flipped axes, so that loading reorients it) and its loaded volume with
// labels painted in, as the app would hold it before saving them.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/volume.h"
#include "core/voxel.h"
#include "io/volume_reader.h"
#include "io/volume_writer.h"

namespace angio::test_support {

// Label of voxel (i, j, k) in the volume frame: different along every axis, 0 in part of the
// volume, and label 4 only in the box i >= 4, j <= 1, k >= 2 (its bounding box is known).
inline int paintedLabel(int i, int j, int k) {
  if (i >= 4 && j <= 1 && k >= 2) return 4;
  if (k == 0) return i < 2 ? 1 : 0;
  return j == 2 ? 2 : (i + j + k) % 3 == 0 ? 15 : 0;
}

// A CT file and the volume loaded from it, with paintedLabel in its label bits.
struct LabelledCt {
  std::filesystem::path ctFile;
  Volume volume;
};

// Writes a 6 x 4 x 3 CT (HU different at every voxel) to `ctFile`, stored with its i and k axes
// pointing -L and -S when `flipped` (so readVolume reorients it), loads it and paints the labels.
inline LabelledCt labelledCt(const std::filesystem::path& ctFile, bool flipped) {
  Volume stored = makeVolume({6, 4, 3}, {0.5, 0.75, 1.25});
  stored.origin = {-30.0, 12.5, 200.0};
  if (flipped)
    stored.direction = glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));
  for (std::size_t n = 0; n < stored.voxels.size(); ++n)
    stored.voxels[n] = encodeVoxel(double(n) * 7 - 300);
  writeVolume(stored, ctFile);
  LabelledCt ct{ctFile, readVolume(ctFile).volume};
  EXPECT_EQ(ct.volume.direction, glm::dmat3(1.0));
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 6; ++i) {
        Voxel& voxel = ct.volume.voxels[ct.volume.indexOf(i, j, k)];
        voxel = Voxel(densityOf(voxel) | (paintedLabel(i, j, k) << 12));
      }
  return ct;
}

// Loads `ctFile` with `labelFile` as its labels and expects the voxels of `expected`, labels and
// densities.
inline void expectLabelsReadBack(const LabelledCt& ct, const std::filesystem::path& labelFile) {
  ReadOptions options;
  options.labelPath = labelFile;
  const Volume back = readVolume(ct.ctFile, options).volume;
  ASSERT_EQ(back.dims, ct.volume.dims);
  for (std::size_t n = 0; n < back.voxels.size(); ++n)
    ASSERT_EQ(back.voxels[n], ct.volume.voxels[n]) << n;
}

}  // namespace angio::test_support
