// Label volume files: the label bits written as uint8 on the CT's grid read back onto the CT (every
// format, reoriented volumes too), atomic writes, and bad label volumes given to --labels.
#include "io/label_volume_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/input_error.h"
#include "io/volume_formats.h"
#include "io/volume_reader.h"
#include "tests/io/labelled_volumes.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::expectInputError;
using test_support::fileBytes;
using test_support::labelledCt;

using LabelVolumeFileTest = test_support::TempFolderTest;

// The header line of a NRRD file that starts with `field`.
std::string headerLine(const fs::path& file, const std::string& field) {
  const std::string text = fileBytes(file);
  const auto at = text.find("\n" + field);
  if (at == std::string::npos) return "";
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST_F(LabelVolumeFileTest, LabelsReadBackOntoTheCtInEveryFormat) {
  for (const bool flipped : {false, true}) {
    const test_support::LabelledCt ct =
        labelledCt(dir_ / (flipped ? "flipped.nrrd" : "ct.nrrd"), flipped);
    for (const std::string name : {"l.nrrd", "l.nhdr", "l.nii", "l.nii.gz", "l.mha", "l.mhd"}) {
      SCOPED_TRACE(name + (flipped ? " (CT stored flipped)" : ""));
      writeLabelVolume(dir_ / name, ct.volume);
      test_support::expectLabelsReadBack(ct, dir_ / name);
    }
  }
}

TEST_F(LabelVolumeFileTest, StoresUint8LabelsOnTheDensityFilesGrid) {
  const test_support::LabelledCt ct = labelledCt(dir_ / "ct.mha", true);
  const fs::path labels = dir_ / "labels.nrrd", density = dir_ / "density.nrrd";
  writeLabelVolume(labels, ct.volume);
  writeVolume(ct.volume, density);
  // Other programs place the two files by these fields, so they must be the same.
  for (const std::string field : {"space directions:", "space origin:", "sizes:", "space:"}) {
    EXPECT_NE(headerLine(labels, field), "") << field;
    EXPECT_EQ(headerLine(labels, field), headerLine(density, field));
  }
  auto io = makeImageIO(VolumeFormat::nrrd);
  io->SetFileName(labels.string());
  io->ReadImageInformation();
  ASSERT_EQ(io->GetComponentType(), itk::IOComponentEnum::UCHAR);
  std::vector<std::uint8_t> stored(ct.volume.voxelCount());
  io->Read(stored.data());
  for (std::size_t n = 0; n < stored.size(); ++n)
    ASSERT_EQ(stored[n], labelOf(ct.volume.voxels[n])) << n;
}

TEST_F(LabelVolumeFileTest, UnknownExtensionOrMissingFolderIsAnErrorAndWritesNothing) {
  const Volume volume = labelledCt(dir_ / "ct.nrrd", false).volume;
  const std::vector<std::string> before = filesInDir();
  expectInputError([&] { writeLabelVolume(dir_ / "labels.vtk", volume); }, dir_ / "labels.vtk",
                   "unknown volume format '.vtk'");
  const fs::path missingFolder = dir_ / "no-such-folder" / "labels.nrrd";
  expectInputError([&] { writeLabelVolume(missingFolder, volume); }, missingFolder, "");
  expectInputError([&] { writeLabelVolume(dir_ / "empty.nrrd", Volume{}); }, dir_ / "empty.nrrd",
                   "empty");
  EXPECT_EQ(filesInDir(), before);
}

TEST_F(LabelVolumeFileTest, FailedReplacementLeavesTheTargetAndNoTemporaryFile) {
  const Volume volume = labelledCt(dir_ / "ct.nrrd", false).volume;
  // A folder of the target's name: the write succeeds, the rename over it fails.
  const fs::path target = dir_ / "labels.nii.gz";
  fs::create_directory(target);
  std::ofstream(target / "keep.txt") << "user data";
  const std::vector<std::string> before = filesInDir();
  expectInputError([&] { writeLabelVolume(target, volume); }, target, "");
  EXPECT_EQ(filesInDir(), before);
  EXPECT_EQ(fileBytes(target / "keep.txt"), "user data");
}

TEST_F(LabelVolumeFileTest, LabelVolumeOnAnotherGridIsAnErrorNamingTheDifference) {
  const test_support::LabelledCt ct = labelledCt(dir_ / "ct.nrrd", false);
  Volume shifted = ct.volume, coarser = ct.volume, smaller = makeVolume({6, 4, 2}, ct.volume.spacing);
  shifted.origin.x += 0.5;
  coarser.spacing.z = 2.5;
  smaller.origin = ct.volume.origin;
  for (const auto& [name, labels, problem] : std::vector<std::tuple<std::string, Volume, std::string>>{
           {"shifted.nrrd", shifted, "origin -29.5 x 12.5 x 200 mm vs the volume's -30 x 12.5 x 200 mm"},
           {"coarser.nii.gz", coarser,
            "spacing 0.5 x 0.75 x 2.5 mm vs the volume's 0.5 x 0.75 x 1.25 mm"},
           {"smaller.mha", smaller, "dims 6 x 4 x 2 vs the volume's 6 x 4 x 3"}}) {
    writeLabelVolume(dir_ / name, labels);
    ReadOptions options;
    options.labelPath = dir_ / name;
    expectInputError([&] { readVolume(ct.ctFile, options); }, dir_ / name,
                     "label volume is not on the volume's grid (" + problem + ")");
  }
}

TEST_F(LabelVolumeFileTest, LabelValuesAbove15AreAnError) {
  const test_support::LabelledCt ct = labelledCt(dir_ / "ct.nrrd", false);
  // A label file as another program writes it: values up to 20 (a density file read as labels).
  Volume tooHigh = ct.volume;
  for (std::size_t n = 0; n < tooHigh.voxels.size(); ++n)
    tooHigh.voxels[n] = encodeVoxel(double(n % 21));
  writeVolume(tooHigh, dir_ / "labels.nrrd");
  ReadOptions options;
  options.labelPath = dir_ / "labels.nrrd";
  expectInputError([&] { readVolume(ct.ctFile, options); }, dir_ / "labels.nrrd",
                   "15 voxels have label values outside 0..15");
}

}  // namespace
}  // namespace angio
