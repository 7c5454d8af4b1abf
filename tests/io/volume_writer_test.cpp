// Volume writing: int16 HU with geometry, format by extension, compression, atomic replacement.
#include "io/volume_writer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/voxel.h"
#include "io/input_error.h"
#include "io/volume_formats.h"
#include "io/volume_reader.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::fileBytes;

using VolumeWriterTest = test_support::TempFolderTest;

// Densities covering the whole 12-bit range, different at every voxel, with a label in some.
Volume testVolume() {
  Volume v = makeVolume({7, 5, 3}, {0.6, 0.8, 1.25});
  v.origin = {-40.0, 12.5, 300.0};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 7; ++i) {
        const int d = (i * 97 + j * 401 + k * 1361) % kDensityLevels;
        v.voxels[v.indexOf(i, j, k)] = Voxel(d | ((i == 2) << 12));
      }
  v.voxels[v.indexOf(6, 4, 2)] = 4095;
  v.voxels[v.indexOf(0, 0, 0)] = 0;
  return v;
}

TEST_F(VolumeWriterTest, RoundTripsEveryFormatWithoutLabels) {
  const Volume original = testVolume();
  for (const std::string name : {"v.mha", "v.mhd", "v.nrrd", "v.nhdr", "v.nii", "v.nii.gz"}) {
    SCOPED_TRACE(name);
    writeVolume(original, dir_ / name);
    const Volume back = readVolume(dir_ / name).volume;
    ASSERT_EQ(back.dims, original.dims);
    EXPECT_NEAR(glm::length(back.spacing - original.spacing), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(back.origin - original.origin), 0.0, 1e-4);
    EXPECT_EQ(back.direction, glm::dmat3(1.0));
    for (std::size_t n = 0; n < original.voxels.size(); ++n) {
      ASSERT_EQ(back.voxels[n], densityOf(original.voxels[n])) << n;  // labels are not written
    }
  }
}

TEST_F(VolumeWriterTest, StoresInt16HounsfieldUnits) {
  const Volume original = testVolume();
  const fs::path file = dir_ / "hu.nrrd";
  writeVolume(original, file);
  auto io = makeImageIO(VolumeFormat::nrrd);
  io->SetFileName(file.string());
  io->ReadImageInformation();
  ASSERT_EQ(io->GetComponentType(), itk::IOComponentEnum::SHORT);
  std::vector<short> hu(original.voxelCount());
  io->Read(hu.data());
  for (std::size_t n = 0; n < hu.size(); ++n)
    ASSERT_EQ(hu[n], densityOf(original.voxels[n]) - 1024) << n;
}

TEST_F(VolumeWriterTest, KeepsAResidualRotation) {
  Volume original = testVolume();
  const double a = glm::radians(0.7);
  original.direction = glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0),
                                  glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
  writeVolume(original, dir_ / "rotated.mha");
  const Volume back = readVolume(dir_ / "rotated.mha").volume;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(back.direction[c][r], original.direction[c][r], 1e-6);
  EXPECT_EQ(back.voxels[back.indexOf(3, 1, 2)], densityOf(original.voxels[original.indexOf(3, 1, 2)]));
}

TEST_F(VolumeWriterTest, CompressesWhereTheFormatAllows) {
  // A large uniform volume: compressed files are far smaller than the 2 MB of int16 data.
  const Volume uniform = makeVolume({128, 128, 64}, {1.0, 1.0, 1.0}, encodeVoxel(40));
  const double raw = 2.0 * uniform.voxelCount();
  for (const std::string name : {"u.mha", "u.nrrd", "u.nii.gz"}) {
    writeVolume(uniform, dir_ / name);
    EXPECT_LT(fs::file_size(dir_ / name), raw / 20) << name;
  }
  EXPECT_EQ(fileBytes(dir_ / "u.nii.gz").substr(0, 2), "\x1f\x8b");
  writeVolume(uniform, dir_ / "u.nii");
  EXPECT_GT(fs::file_size(dir_ / "u.nii"), raw);  // plain NIfTI is uncompressed by definition
}

TEST_F(VolumeWriterTest, LeavesOnlyTheTargetFiles) {
  const Volume v = testVolume();
  writeVolume(v, dir_ / "a.nii.gz");
  writeVolume(v, dir_ / "a.nii.gz");  // replacing an existing file
  writeVolume(v, dir_ / "b.mhd");
  writeVolume(v, dir_ / "c.nhdr");
  const std::vector<std::string> files = filesInDir();
  ASSERT_EQ(files.size(), 5u) << ::testing::PrintToString(files);
  EXPECT_EQ(files[0], "a.nii.gz");
  EXPECT_EQ(files[1], "b.mhd");
  EXPECT_EQ(files[3], "c.nhdr");
  // The detached headers name their data files by final name.
  EXPECT_NE(fileBytes(dir_ / "b.mhd").find("ElementDataFile = " + files[2]), std::string::npos);
  EXPECT_NE(fileBytes(dir_ / "c.nhdr").find(files[4]), std::string::npos);
}

TEST_F(VolumeWriterTest, UnknownExtensionIsAnErrorAndWritesNothing) {
  try {
    writeVolume(testVolume(), dir_ / "volume.vtk");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("volume.vtk"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("unknown volume format"), std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(VolumeWriterTest, UnwritableTargetIsAnErrorNamingTheFile) {
  for (const std::string name : {"v.mha", "v.mhd"}) {
    const fs::path target = dir_ / "no-such-folder" / name;
    try {
      writeVolume(testVolume(), target);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos) << error.what();
    }
  }
  EXPECT_TRUE(filesInDir().empty());
}

}  // namespace
}  // namespace angio
