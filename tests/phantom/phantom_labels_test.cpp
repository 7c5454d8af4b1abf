// The phantom's scanner table and its ground-truth labels: bone where the anatomy has bone (cortex
// and marrow), table under the body along the whole length, no label in the lumen, and the labels
// never change the densities.
#include <gtest/gtest.h>

#include "core/labels.h"
#include "core/volume.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

constexpr glm::ivec3 kDims{128, 128, 300};

Phantom labelledPhantom(glm::ivec3 dims) {
  PhantomOptions options;
  options.style = PhantomStyle::simple;
  options.dims = dims;
  options.groundTruthLabels = true;
  return generatePhantom(options);
}

// Anatomy frame (phantom_anatomy.h) to physical: the top of the box is at z = 0.
glm::dvec3 physical(double x, double y, double zAnatomy) { return {x, y, zAnatomy - 1200}; }

Voxel voxelAt(const Volume& volume, glm::dvec3 physicalMm) {
  const glm::ivec3 index(glm::floor(physicalToIndex(volume, physicalMm) + 0.5));
  return volume.at(index.x, index.y, index.z);
}

class PhantomLabels : public ::testing::Test {
 protected:
  void SetUp() override { phantom = labelledPhantom(kDims); }
  int labelAt(glm::dvec3 physicalMm) const { return labelOf(voxelAt(phantom.volume, physicalMm)); }
  double huAt(glm::dvec3 physicalMm) const {
    return huOfDensity(densityOf(voxelAt(phantom.volume, physicalMm)));
  }
  Phantom phantom;
};

TEST_F(PhantomLabels, BoneIsLabelledThroughCortexAndMarrow) {
  // L3's body (cancellous core), a femur's fatty marrow and its cortex, the iliac wing.
  EXPECT_EQ(labelAt(physical(0, 40, 1121)), kBoneLabel);
  for (double side : {1.0, -1.0}) {
    EXPECT_EQ(labelAt(physical(111 * side, 36, 720)), kBoneLabel) << "femur marrow " << side;
    EXPECT_LT(huAt(physical(111 * side, 36, 720)), 200) << "marrow is fatty " << side;
    EXPECT_EQ(labelAt(physical((111 + 12) * side, 36, 720)), kBoneLabel) << "femur cortex " << side;
    EXPECT_EQ(labelAt(physical(85 * side, 30, 1000)), kBoneLabel) << "iliac wing " << side;
  }
  // Kidneys are shelled like bones but are not bone; muscle in front of the femur is not either.
  EXPECT_EQ(labelAt(physical(72, 52, 1160)), 0);
  EXPECT_EQ(labelAt(physical(125, -15, 720)), 0);
}

TEST_F(PhantomLabels, LumenIsNeverLabelled) {
  std::size_t points = 0, labelled = 0;
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    for (const CenterlinePoint& point : path.points) {
      ++points;
      labelled += labelAt(point.positionMm) != 0;
    }
  }
  ASSERT_GT(points, 4000u);
  EXPECT_EQ(labelled, 0u);
}

TEST_F(PhantomLabels, TableRunsUnderTheBodyTheWholeLength) {
  const Volume& volume = phantom.volume;
  const glm::dvec3 centreMm = indexToPhysical(volume, glm::dvec3(volume.dims - 1) / 2.0);
  for (int k = 0; k < volume.dims.z; ++k) {
    std::size_t table = 0, anteriorOfBodyCentre = 0;
    for (int j = 0; j < volume.dims.y; ++j) {
      for (int i = 0; i < volume.dims.x; ++i) {
        if (labelOf(volume.at(i, j, k)) != kTableLabel) continue;
        ++table;
        anteriorOfBodyCentre += indexToPhysical(volume, glm::dvec3(i, j, k)).y < centreMm.y + 50;
      }
    }
    EXPECT_GT(table, 100u) << "slice " << k;
    EXPECT_EQ(anteriorOfBodyCentre, 0u) << "slice " << k;  // +y is posterior: the patient lies on it
  }
  // The pad reads as foam, the shell as carbon fibre; the body rests on the pad under the back.
  EXPECT_NEAR(huAt(physical(0, 133, 600)), -700, 60);
  EXPECT_EQ(labelAt(physical(0, 133, 600)), kTableLabel);
  EXPECT_GT(huAt(physical(0, 121 + 25 + 2, 600)), -500);
  EXPECT_EQ(labelAt(physical(0, 121 + 25 + 2, 600)), kTableLabel);
  EXPECT_LT(huAt(physical(0, 175, 600)), -900);  // air below the table
  EXPECT_EQ(labelAt(physical(0, 175, 600)), 0);
  EXPECT_EQ(labelAt(physical(0, 110, 1100)), 0);  // the back's muscle just above the pad
  EXPECT_GT(huAt(physical(0, 110, 1100)), -200);
}

TEST(PhantomGroundTruth, LabelsDoNotChangeTheDensities) {
  const glm::ivec3 dims{64, 64, 120};
  const Phantom plain = generatePhantom({.dims = dims, .seed = 5, .style = PhantomStyle::simple});
  PhantomOptions options{.dims = dims, .seed = 5, .style = PhantomStyle::simple};
  options.groundTruthLabels = true;
  const Phantom labelled = generatePhantom(options);
  std::size_t withLabel = 0, densityDiffers = 0;
  for (std::size_t n = 0; n < plain.volume.voxels.size(); ++n) {
    EXPECT_EQ(labelOf(plain.volume.voxels[n]), 0);
    withLabel += labelOf(labelled.volume.voxels[n]) != 0;
    densityDiffers += densityOf(labelled.volume.voxels[n]) != densityOf(plain.volume.voxels[n]);
  }
  EXPECT_EQ(densityDiffers, 0u);
  EXPECT_GT(withLabel, plain.volume.voxels.size() / 100);
}

}  // namespace
}  // namespace angio
