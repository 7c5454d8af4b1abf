// Volume loading: formats, component types, reorientation to the LPS-aligned frame, DICOM series,
// labels and every kind of bad input (rendering-model.md "Volume frame" and voxel encoding).
#include "io/volume_reader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <itkGDCMImageIO.h>
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkMetaDataObject.h>
#include <itkRGBPixel.h>
#include <nifti1_io.h>

#include "core/voxel.h"
#include "io/input_error.h"
#include "io/dicom_series.h"
#include "io/volume_formats.h"
#include "io/volume_writer.h"
#include "tests/fuzz/teem_agreement.h"
#include "tests/support/dicom_recompress.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

struct Placement {
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  glm::dmat3 direction{1.0};  // columns: directions of the stored axes
};

// An image of `dims` whose voxel at index i holds value(i) (i a std::array<int, N>).
template <class T, unsigned N = 3, class Value>
typename itk::Image<T, N>::Pointer makeImage(const std::array<int, N>& dims, const Value& value,
                                             const Placement& placement = {}) {
  using Image = itk::Image<T, N>;
  typename Image::RegionType region;
  typename Image::SpacingType spacing;
  typename Image::PointType origin;
  typename Image::DirectionType direction;
  direction.SetIdentity();
  for (unsigned a = 0; a < N; ++a) {
    region.SetSize(a, dims[a]);
    spacing[a] = a < 3 ? placement.spacing[a] : 1.0;
    origin[a] = a < 3 ? placement.origin[a] : 0.0;
    for (unsigned r = 0; r < std::min(N, 3u) && a < 3; ++r) direction[r][a] = placement.direction[a][r];
  }
  auto image = Image::New();
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  T* buffer = image->GetBufferPointer();
  std::array<int, N> index{};
  for (std::size_t n = 0; n < region.GetNumberOfPixels(); ++n) {
    std::size_t rest = n;
    for (unsigned a = 0; a < N; ++a) index[a] = int(rest % dims[a]), rest /= dims[a];
    buffer[n] = T(value(index));
  }
  return image;
}

template <class Image>
void writeImage(const Image* image, const fs::path& file, bool compress = true) {
  auto writer = itk::ImageFileWriter<Image>::New();
  writer->SetImageIO(makeImageIO(*volumeFormatOf(file)));
  writer->SetFileName(file.string());
  writer->SetInput(image);
  writer->SetUseCompression(compress);
  writer->Update();
}

// A volume with a different value at every voxel: HU = i + 10 j + 100 k - 500.
short asymmetricHu(std::array<int, 3> i) { return short(i[0] + 10 * i[1] + 100 * i[2] - 500); }

// What readVolume gave, and every warning it reported.
struct WarnedLoad {
  LoadedVolume loaded;
  std::vector<std::string> warnings;
};

WarnedLoad readCollectingWarnings(const fs::path& path) {
  WarnedLoad result;
  ReadOptions options;
  options.warn = [&](const std::string& w) { result.warnings.push_back(w); };
  result.loaded = readVolume(path, options);
  return result;
}

// The volume's grid: `dims` voxels of `spacingMm`, each spacing within `toleranceMm`.
void expectGrid(const Volume& v, glm::ivec3 dims, glm::dvec3 spacingMm, double toleranceMm) {
  EXPECT_EQ(v.dims, dims);
  EXPECT_NEAR(v.spacing.x, spacingMm.x, toleranceMm);
  EXPECT_NEAR(v.spacing.y, spacingMm.y, toleranceMm);
  EXPECT_NEAR(v.spacing.z, spacingMm.z, toleranceMm);
}

// Exactly one warning, containing each of `texts`.
void expectOneWarning(const std::vector<std::string>& warnings,
                      std::initializer_list<std::string> texts) {
  ASSERT_EQ(warnings.size(), 1u);
  for (const std::string& text : texts)
    EXPECT_NE(warnings[0].find(text), std::string::npos) << warnings[0];
}

// The test's own folder, and the asymmetric test image written into it.
class VolumeReaderTest : public test_support::TempFolderTest {
 protected:
  // Writes the 4 x 3 x 2 asymmetricHu image, stored with `placement`, to the file `name` in the
  // folder; returns its path.
  fs::path writeAsymmetric(const std::string& name, const Placement& placement = {}) const {
    const fs::path file = dir_ / name;
    writeImage(makeImage<short>({4, 3, 2}, asymmetricHu, placement).GetPointer(), file);
    return file;
  }
};

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

// Expects readVolume(file) to throw an InputError whose one-line message names `file` and contains
// `problem`.
void expectInputError(const fs::path& file, const std::string& problem,
                      const ReadOptions& options = {}) {
  try {
    readVolume(file, options);
    ADD_FAILURE() << "no InputError for " << file;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

glm::dvec3 storedPhysical(const Placement& p, glm::dvec3 index) {
  return p.origin + p.direction * (index * p.spacing);
}

// Every stored voxel must land at the new index whose physical point is the same, with its value.
void expectSamePhysicalVoxels(const Volume& volume, std::array<int, 3> storedDims,
                              const Placement& stored,
                              const std::function<short(std::array<int, 3>)>& hu) {
  for (int k = 0; k < storedDims[2]; ++k)
    for (int j = 0; j < storedDims[1]; ++j)
      for (int i = 0; i < storedDims[0]; ++i) {
        const glm::dvec3 physical = storedPhysical(stored, glm::dvec3(i, j, k));
        const glm::dvec3 index = physicalToIndex(volume, physical);
        const glm::ivec3 voxel(glm::round(index));
        ASSERT_LT(glm::length(index - glm::dvec3(voxel)), 1e-6) << i << " " << j << " " << k;
        ASSERT_TRUE(glm::all(glm::greaterThanEqual(voxel, glm::ivec3(0))) &&
                    glm::all(glm::lessThan(voxel, volume.dims)));
        EXPECT_EQ(volume.densityAt(voxel.x, voxel.y, voxel.z), densityOfHu(hu({i, j, k})));
        EXPECT_LT(glm::length(indexToPhysical(volume, glm::dvec3(voxel)) - physical), 1e-6);
      }
}

TEST_F(VolumeReaderTest, ReadsEveryFormatWithValuesAndGeometry) {
  const Placement placement{{0.5, 0.75, 2.0}, {10.0, -20.0, 30.0}, glm::dmat3(1.0)};
  for (const std::string name : {"v.mha", "v.mhd", "v.nrrd", "v.nhdr", "v.nii", "v.nii.gz"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir_ / name;
    writeImage(makeImage<short>({5, 4, 3}, asymmetricHu, placement).GetPointer(), file);
    const LoadedVolume loaded = readVolume(file);
    const Volume& v = loaded.volume;
    expectGrid(v, {5, 4, 3}, {0.5, 0.75, 2.0}, 1e-6);
    EXPECT_NEAR(glm::length(v.origin - placement.origin), 0.0, 1e-4);
    EXPECT_EQ(v.direction, glm::dmat3(1.0));
    EXPECT_NE(loaded.description.find("int16"), std::string::npos) << loaded.description;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) ASSERT_EQ(v.densityAt(i, j, k), asymmetricHu({i, j, k}) + 1024);
  }
}

TEST_F(VolumeReaderTest, ReadsFloatAndUint8AsHounsfieldUnits) {
  const fs::path floats = dir_ / "f.nii.gz";
  // -1000.4 rounds to -1000, 2.5 rounds away from zero to 3, 5000 clamps to 3071 (d = 4095).
  const std::array<float, 3> values{-1000.4f, 2.5f, 5000.0f};
  writeImage(makeImage<float>({3, 2, 2}, [&](auto i) { return values[i[0]]; }).GetPointer(), floats);
  const Volume f = readVolume(floats).volume;
  EXPECT_EQ(f.densityAt(0, 1, 1), 24);
  EXPECT_EQ(f.densityAt(1, 1, 1), 1027);
  EXPECT_EQ(f.densityAt(2, 0, 0), 4095);

  const fs::path bytes = dir_ / "b.nrrd";
  writeImage(
      makeImage<unsigned char>({3, 2, 2}, [](auto i) { return (unsigned char)(100 * i[0] + i[2]); })
          .GetPointer(),
      bytes);
  const LoadedVolume b = readVolume(bytes);
  EXPECT_NE(b.description.find("uint8"), std::string::npos);
  EXPECT_EQ(b.volume.densityAt(2, 1, 1), 201 + 1024);
  EXPECT_EQ(b.volume.densityAt(0, 0, 0), 1024);
}

TEST_F(VolumeReaderTest, FlippedAxesComeOutLpsAlignedWithVoxelsMoved) {
  // Stored i runs to -L (right), j to -P (anterior): the aorta.mha layout.
  const Placement stored{{0.8, 0.9, 1.5},
                         {-100.0, -20.0, 7.0},
                         glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1))};
  const Volume v = readVolume(writeAsymmetric("flipped.mha", stored)).volume;
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  // New voxel (0,0,0) is the stored (3,2,0): the one furthest right and anterior.
  EXPECT_NEAR(glm::length(v.origin - storedPhysical(stored, {3, 2, 0})), 0.0, 1e-9);
  EXPECT_EQ(v.densityAt(0, 0, 0), asymmetricHu({3, 2, 0}) + 1024);
  EXPECT_EQ(v.densityAt(3, 0, 1), asymmetricHu({0, 2, 1}) + 1024);
  expectSamePhysicalVoxels(v, {4, 3, 2}, stored, asymmetricHu);
}

TEST_F(VolumeReaderTest, PermutedAxesComeOutLpsAlignedWithSpacingPermuted) {
  // Stored i runs to +S, j to -L, k to +P (a sagittal-like stack).
  const Placement stored{{0.5, 0.7, 2.0},
                         {5.0, 6.0, 7.0},
                         glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0))};
  const Volume v = readVolume(writeAsymmetric("permuted.nrrd", stored)).volume;
  expectGrid(v, {3, 2, 4}, {0.7, 2.0, 0.5}, 1e-9);
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  // New (i, j, k) = stored (k, 2 - i, j).
  EXPECT_EQ(v.densityAt(0, 1, 3), asymmetricHu({3, 2, 1}) + 1024);
  expectSamePhysicalVoxels(v, {4, 3, 2}, stored, asymmetricHu);
}

glm::dmat3 rotationAboutZ(double degrees) {
  const double a = glm::radians(degrees);
  return glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0), glm::dvec3(-std::sin(a), std::cos(a), 0),
                    glm::dvec3(0, 0, 1));
}

TEST_F(VolumeReaderTest, ObliqueVolumeIsSnappedWithWarningAndKeepsTrueRotation) {
  // 10 degrees about S, and the first axis flipped: snapped to +L/+P/+S, residual kept.
  Placement stored{{1.0, 1.2, 2.0}, {3.0, 4.0, 5.0}, rotationAboutZ(10.0)};
  stored.direction[0] = -stored.direction[0];
  const WarnedLoad read = readCollectingWarnings(writeAsymmetric("oblique.mha", stored));
  ASSERT_NO_FATAL_FAILURE(expectOneWarning(read.warnings, {"10.0 degrees", "oblique.mha"}));
  const Volume& v = read.loaded.volume;
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
  const glm::dmat3 residual = v.direction;
  EXPECT_NEAR(residual[0][0], std::cos(glm::radians(10.0)), 1e-6);  // +L axis, rotated 10 degrees
  EXPECT_NEAR(residual[0][1], std::sin(glm::radians(10.0)), 1e-6);
  expectSamePhysicalVoxels(v, {4, 3, 2}, stored, asymmetricHu);
}

TEST_F(VolumeReaderTest, SlightlyObliqueVolumeKeepsRotationWithoutWarning) {
  const Placement stored{{1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, rotationAboutZ(0.5)};
  const WarnedLoad read = readCollectingWarnings(writeAsymmetric("slight.nii.gz", stored));
  EXPECT_TRUE(read.warnings.empty());
  EXPECT_NEAR(read.loaded.volume.direction[0][1], std::sin(glm::radians(0.5)), 1e-5);
}

TEST_F(VolumeReaderTest, AortaLoadsReorientedWithValuesAsStored) {
  const fs::path file = fs::path(ANGIORAY_SHARED_DATA) / "aorta.mha";
  const LoadedVolume loaded = readVolume(file);
  const Volume& v = loaded.volume;
  expectGrid(v, {157, 393, 34}, {0.878906, 0.878906, 1.50009}, 1e-6);
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_NE(loaded.description.find("float32"), std::string::npos);
  // Stored direction diag(-1,-1,1), origin (-156.445, -24.6094, 0): new voxel 0 is stored (156, 392, 0).
  EXPECT_NEAR(v.origin.x, -156.445 - 156 * 0.878906, 1e-3);
  EXPECT_NEAR(v.origin.y, -24.6094 - 392 * 0.878906, 1e-3);
  EXPECT_NEAR(v.origin.z, 0.0, 1e-9);

  // Compare with the file read directly: new (i, j, k) = stored (156 - i, 392 - j, k).
  auto reader = itk::ImageFileReader<itk::Image<float, 3>>::New();
  reader->SetImageIO(makeImageIO(VolumeFormat::metaImage));
  reader->SetFileName(file.string());
  reader->Update();
  const float* stored = reader->GetOutput()->GetBufferPointer();
  for (int k = 0; k < 34; ++k)
    for (int j = 0; j < 393; ++j)
      for (int i = 0; i < 157; ++i) {
        const float hu = stored[(std::size_t(k) * 393 + (392 - j)) * 157 + (156 - i)];
        ASSERT_EQ(v.densityAt(i, j, k), densityOfHu(hu)) << i << " " << j << " " << k;
      }
  // Lumen (~1200-2400) is there, kept as is rather than recalibrated.
  const DensityRange range = densityRange(v);
  EXPECT_GT(range.maxDensity, 1200 + kHuOffset);
  EXPECT_LE(range.maxDensity, 4095);
}

TEST_F(VolumeReaderTest, NanAndInfinityBecomeMinus1024WithWarning) {
  const fs::path file = dir_ / "nan.mha";
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  writeImage(makeImage<float>({3, 2, 2},
                              [&](auto i) {
                                if (i == std::array<int, 3>{0, 0, 0} || i == std::array<int, 3>{2, 1, 1})
                                  return nan;
                                if (i == std::array<int, 3>{1, 0, 1}) return -inf;
                                return 40.0f;
                              })
                 .GetPointer(),
             file);
  const WarnedLoad read = readCollectingWarnings(file);
  const Volume& v = read.loaded.volume;
  EXPECT_EQ(v.densityAt(0, 0, 0), 0);
  EXPECT_EQ(v.densityAt(2, 1, 1), 0);
  EXPECT_EQ(v.densityAt(1, 0, 1), 0);
  EXPECT_EQ(v.densityAt(1, 1, 0), 40 + 1024);
  expectOneWarning(read.warnings, {"3 voxels"});
}

// Every progress report of reading `file`.
std::vector<double> progressReports(const fs::path& file) {
  std::vector<double> reports;
  ReadOptions options;
  options.progress = [&](double p) { reports.push_back(p); };
  readVolume(file, options);
  return reports;
}

TEST_F(VolumeReaderTest, ReportsProgressFromStartToEnd) {
  const std::vector<double> reports = progressReports(writeAsymmetric("p.mha"));
  ASSERT_GE(reports.size(), 2u);
  EXPECT_EQ(reports.front(), 0.0);
  EXPECT_EQ(reports.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
}

// A 64 x 64 x 256 volume in each single-file format, raw and compressed.
std::vector<fs::path> writeTallVolumes(const fs::path& folder) {
  const auto image = makeImage<short>({64, 64, 256}, [](auto i) { return i[0] + i[1] - i[2]; });
  std::vector<fs::path> files;
  for (const char* name : {"z.mha", "r.mha", "z.nrrd", "r.nrrd", "r.nii", "z.nii.gz"}) {
    files.push_back(folder / name);
    writeImage(image.GetPointer(), files.back(), name[0] == 'z');
  }
  return files;
}

TEST_F(VolumeReaderTest, SingleFileFormatsReportProgressWhileReadingVoxels) {
  for (const fs::path& file : writeTallVolumes(dir_)) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<double> reports = progressReports(file);
    EXPECT_GE(reports.size(), 50u);
    EXPECT_EQ(reports.front(), 0.0);
    EXPECT_EQ(reports.back(), 1.0);
    EXPECT_TRUE(std::adjacent_find(reports.begin(), reports.end(), std::greater_equal<>()) ==
                reports.end())
        << "not strictly increasing";
  }
}

TEST_F(VolumeReaderTest, CancelStopsASingleFileReadAfterItsFirstSlab) {
  for (const fs::path& file : writeTallVolumes(dir_)) {
    SCOPED_TRACE(file.filename().string());
    std::vector<double> reports;
    ReadOptions options;
    options.progress = [&](double p) {
      reports.push_back(p);
      if (reports.size() == 3) throw LoadCancelled();
    };
    EXPECT_THROW(readVolume(file, options), LoadCancelled);
    ASSERT_EQ(reports.size(), 3u);  // nothing reported after the cancel
    // The 3rd report (after "started" and "header read") comes a slab into the voxels, not after all.
    EXPECT_LT(reports[2], 0.1);
  }
}

TEST_F(VolumeReaderTest, NiftiScalingIsApplied) {
  const fs::path file = writeAsymmetric("scaled.nii");
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const float slope = 2.0f, intercept = 10.0f;  // scl_slope and scl_inter of the NIfTI-1 header
  std::memcpy(bytes.data() + 112, &slope, 4);
  std::memcpy(bytes.data() + 116, &intercept, 4);
  writeText(file, bytes);
  const Volume v = readVolume(file).volume;
  for (const std::array<int, 3> i : {std::array<int, 3>{0, 0, 0}, {3, 2, 1}, {1, 2, 0}})
    EXPECT_EQ(v.densityAt(i[0], i[1], i[2]), 2 * asymmetricHu(i) + 10 + 1024);
}

// The NIfTI library keeps vox_offset as an int: 1.5e12 became its header size (348), so ITK would
// read the header as voxels while io/ looked for them past the end of the file.
TEST_F(VolumeReaderTest, NiftiVoxOffsetBeyondAnIntIsRefused) {
  const fs::path file = writeAsymmetric("far.nii");
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const float voxOffset = 1.5e12f;
  std::memcpy(bytes.data() + 108, &voxOffset, 4);
  writeText(file, bytes);
  nifti_set_debug_level(0);
  nifti_image* image = nifti_image_read(file.c_str(), 0);
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(image->iname_offset, 348);
  nifti_image_free(image);
  expectInputError(file, "has an impossible vox_offset (1500000026624 bytes)");
}

// Compressed MetaImage data without CompressedDataSize: zlib packs at most 1032 bytes into one, so
// a few bytes cannot hold a big volume (MetaIO would allocate the volume first).
TEST_F(VolumeReaderTest, CompressedMetaImageDataTooShortForItsVolumeIsRefused) {
  const std::string header =
      "ObjectType = Image\nNDims = 3\nBinaryData = True\nCompressedData = True\n"
      "ElementSpacing = 1 1 1\nDimSize = 64 64 64\nElementType = MET_SHORT\nElementDataFile = LOCAL\n";
  const std::string zeros(64 * 64 * 64 * 2, '\0');
  std::string packed(compressBound(uLong(zeros.size())), '\0');
  uLongf packedBytes = uLongf(packed.size());
  ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &packedBytes,
                      reinterpret_cast<const Bytef*>(zeros.data()), uLong(zeros.size()), 9),
            Z_OK);
  packed.resize(packedBytes);  // about 1000:1, near zlib's limit
  writeText(dir_ / "packed.mha", header + packed);
  EXPECT_EQ(readVolume(dir_ / "packed.mha").volume.dims, glm::ivec3(64, 64, 64));
  writeText(dir_ / "short.mha", header + packed.substr(0, 100));
  expectInputError(dir_ / "short.mha",
                   "is truncated: its 100 bytes of compressed voxel data cannot hold the 524288 bytes");
}

TEST_F(VolumeReaderTest, AnUnknownVoxelTypeIsNamedSo) {
  writeText(dir_ / "type.mha",
            "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_FOO\n"
            "ElementDataFile = LOCAL\nabcdefghabcdefgh");
  expectInputError(dir_ / "type.mha",
                   "has voxels of an unknown type; need integer or floating-point voxels");
}

// A header that ends the file (no line end after ElementDataFile) has no voxel data at all.
TEST_F(VolumeReaderTest, MetaImageHeaderEndingTheFileIsTruncated) {
  writeText(dir_ / "header.mha",
            "ObjectType = Image\nNDims = 3\nElementSpacing = 1 1 1\n"
            "DimSize = 6 5 99496729\nElementType = MET_SHORT\nElementDataFile = LOCAL");
  expectInputError(dir_ / "header.mha",
                   "is truncated: its header promises 5969803740 bytes of voxel data, the file holds 0");
}

// Voxels as text take at least a digit and a separator each: fewer bytes cannot hold them, and
// the volume is not allocated for them.
TEST_F(VolumeReaderTest, MetaImageTextTooShortForItsVolumeIsRefused) {
  const auto header = [](const char* dims) {
    return std::string("ObjectType = Image\nNDims = 3\nBinaryData = False\nElementSpacing = 1 1 1\n") +
           "DimSize = " + dims + "\nElementType = MET_SHORT\nElementDataFile = LOCAL\n";
  };
  writeText(dir_ / "text.mha", header("2 2 2") + "-1000 0 1 2\n3 4 5 1200\n");
  const LoadedVolume loaded = readVolume(dir_ / "text.mha");
  EXPECT_EQ(loaded.volume.dims, glm::ivec3(2, 2, 2));
  const auto [lowest, highest] =
      std::minmax_element(loaded.volume.voxels.begin(), loaded.volume.voxels.end());
  EXPECT_EQ(densityOf(*lowest), -1000 + 1024);
  EXPECT_EQ(densityOf(*highest), 1200 + 1024);
  // 16 bytes for 8 values is just enough ("1 1 1 1 1 1 1 1\n"); 15 is not.
  writeText(dir_ / "least.mha", header("2 2 2") + "1 1 1 1 1 1 1 1\n");
  EXPECT_EQ(readVolume(dir_ / "least.mha").volume.dims, glm::ivec3(2, 2, 2));
  writeText(dir_ / "short.mha", header("2 2 2") + "1 1 1 1 1 1 1 1");
  expectInputError(
      dir_ / "short.mha",
      "is truncated: its 15 bytes of voxel data as text cannot hold the 8 values its header "
      "promises (2 bytes each at least)");
  writeText(dir_ / "huge.mha", header("6 5 99496729") + "1 2 3\n");
  expectInputError(dir_ / "huge.mha", "cannot hold the 2984901870 values");
  // Long enough, but a word MetaIO cannot read as a number: said in our words, not MetaIO's.
  writeText(dir_ / "word.mha", header("2 2 2") + "1 2 x 4 5 6 7 8 9\n");
  expectInputError(dir_ / "word.mha",
                   "cannot be read: its voxel data end early or hold text that is not a number");
}

TEST_F(VolumeReaderTest, LabelsOnTheSameGridGoToTheLabelBits) {
  const Placement flipped{{1.0, 1.0, 1.0},
                          {0.0, 0.0, 0.0},
                          glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1))};
  const fs::path volumeFile = dir_ / "ct.mha", labelFile = dir_ / "labels.nii.gz";
  writeImage(makeImage<short>({4, 3, 2}, asymmetricHu, flipped).GetPointer(), volumeFile);
  writeImage(makeImage<unsigned char>(
                 {4, 3, 2}, [](auto i) { return (unsigned char)(i[0] + 4 * i[2]); }, flipped)
                 .GetPointer(),
             labelFile);
  ReadOptions options;
  options.labelPath = labelFile;
  const Volume v = readVolume(volumeFile, options).volume;
  // New i = 3 - stored i.
  EXPECT_EQ(labelOf(v.at(0, 2, 1)), 3 + 4);
  EXPECT_EQ(densityOf(v.at(0, 2, 1)), asymmetricHu({3, 2, 1}) + 1024);
  EXPECT_EQ(labelOf(v.at(3, 0, 0)), 0);
}

TEST_F(VolumeReaderTest, LabelsOnAnotherGridOrOutOfRangeAreErrors) {
  const fs::path volumeFile = dir_ / "ct.mha";
  writeImage(makeImage<short>({4, 3, 2}, asymmetricHu).GetPointer(), volumeFile);
  const fs::path smaller = dir_ / "small-labels.mha";
  writeImage(makeImage<unsigned char>({4, 3, 3}, [](auto) { return (unsigned char)1; }).GetPointer(),
             smaller);
  const fs::path shifted = dir_ / "shifted-labels.mha";
  writeImage(makeImage<unsigned char>(
                 {4, 3, 2}, [](auto) { return (unsigned char)1; },
                 Placement{{1, 1, 1}, {0.5, 0, 0}, glm::dmat3(1.0)})
                 .GetPointer(),
             shifted);
  const fs::path tooBig = dir_ / "big-labels.mha";
  writeImage(
      makeImage<unsigned char>({4, 3, 2}, [](auto i) { return (unsigned char)(i[0] * 6); }).GetPointer(),
      tooBig);
  for (const auto& [labels, problem] :
       std::vector<std::pair<fs::path, std::string>>{{smaller, "not on the volume's grid"},
                                                     {shifted, "origin"},
                                                     {tooBig, "outside 0..15"},
                                                     {dir_ / "missing-labels.mha", "does not exist"}}) {
    ReadOptions options;
    options.labelPath = labels;
    try {
      readVolume(volumeFile, options);
      ADD_FAILURE() << "no error for " << labels;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(labels.filename().string()), std::string::npos)
          << error.what();
      EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
    }
  }
}

// ---- DICOM -------------------------------------------------------------------------------------

using test_support::DicomSlice;
using test_support::sliceHu;
using test_support::writeDicomSeries;
using test_support::writeDicomSlice;

TEST_F(VolumeReaderTest, DicomSeriesLoadsInPositionOrderWithRescaleApplied) {
  writeDicomSeries(dir_, {0, 1, 2, 3, 4, 5, 6, 7}, "1.2.826.0.1.3680043.2.1125.777.1", 42);
  const LoadedVolume loaded = readVolume(dir_);
  const Volume& v = loaded.volume;
  expectGrid(v, {16, 16, 8}, {0.7, 0.7, 2.5}, 1e-6);
  EXPECT_NEAR(glm::length(v.origin - glm::dvec3(-12, 30.5, 5)), 0.0, 1e-6);
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_NE(loaded.description.find("8 slices"), std::string::npos) << loaded.description;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i)
        ASSERT_EQ(v.densityAt(i, j, k), sliceHu(k, i, j) + 1024) << i << " " << j << " " << k;
}

// Every codec a series may come in (GDCM's JPEG 2000 encoding under the lossy syntax is exact too;
// its 12-bit lossy JPEG of these signed 16-bit slices is not DICOM-conformant data, so not here):
// the walk before GDCM steps over the encapsulated pixel data's fragments, GDCM's codecs decode
// them in a child process and the values come back exactly.
TEST_F(VolumeReaderTest, CompressedDicomSeriesLoadsTheSameValuesAsNative) {
  for (const auto syntax :
       {gdcm::TransferSyntax::JPEG2000, gdcm::TransferSyntax::JPEGLosslessProcess14_1,
        gdcm::TransferSyntax::JPEGLSLossless, gdcm::TransferSyntax::JPEG2000Lossless,
        gdcm::TransferSyntax::RLELossless}) {
    const std::string uid = gdcm::TransferSyntax::GetTSString(syntax);
    SCOPED_TRACE(uid);
    const fs::path folder = dir_ / ("codec" + std::to_string(int(syntax)));
    fs::create_directories(folder);
    writeDicomSeries(folder, {0, 1, 2, 3}, "1.2.826.0.1.3680043.2.1125.777.1", 42);
    for (const auto& slice : fs::directory_iterator(folder)) {
      test_support::recompressDicomSlice(slice.path(), syntax);
      ASSERT_NE(test_support::fileBytes(slice.path()).find(uid), std::string::npos);
    }
    const Volume v = readVolume(folder).volume;
    expectGrid(v, {16, 16, 4}, {0.7, 0.7, 2.5}, 1e-6);
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          ASSERT_EQ(v.densityAt(i, j, k), sliceHu(k, i, j) + 1024) << i << " " << j << " " << k;
  }
}

// GDCM's JPEG codec asserts on a libjpeg warning (here: stray bytes before the frame header), which
// would abort the app: compressed slices are decoded in a child process, so the load fails with the
// slice's name and the process goes on.
TEST_F(VolumeReaderTest, ACompressedSliceTheDecoderAbortsOnFailsTheLoadNotTheProcess) {
  writeDicomSeries(dir_, {0, 1, 2, 3}, "1.2.826.0.1.3680043.2.1125.777.1", 42);
  for (const auto& slice : fs::directory_iterator(dir_))
    test_support::recompressDicomSlice(slice.path(), gdcm::TransferSyntax::JPEGLosslessProcess14_1);
  test_support::strayBytesBeforeJpegFrameHeader(dir_ / "IM2-1.dcm");
  expectInputError(dir_,
                   "slice IM2-1.dcm: its compressed pixel data cannot be decoded (the decoder was "
                   "killed by signal 6");
}

TEST_F(VolumeReaderTest, DicomSeriesBringsThePatientAndStudyForTheBanner) {
  writeDicomSeries(dir_, {0, 1, 2, 3}, "1.2.826.0.1.3680043.2.1125.777.1", 5,
                   {{"0010|0010", "DOE^JANE^Q"},
                    {"0010|0020", "PAT-0042"},
                    {"0008|0020", "20240301"},
                    {"0008|103e", "CTA Aorta 1.0 B26f"}});
  const StudyInfo study = readVolume(dir_).study;
  EXPECT_EQ(study.patientName, "DOE, JANE Q");
  EXPECT_EQ(study.patientId, "PAT-0042");
  EXPECT_EQ(study.studyDate, "2024-03-01");
  EXPECT_EQ(study.seriesDescription, "CTA Aorta 1.0 B26f");
  EXPECT_EQ(study.modality, "CT");
}

TEST_F(VolumeReaderTest, AnonymisedSeriesAndOtherFormatsHaveNoStudy) {
  writeDicomSeries(dir_, {0, 1, 2}, "1.2.826.0.1.3680043.2.1125.777.1", 6);
  const StudyInfo anonymised = readVolume(dir_).study;
  EXPECT_EQ(anonymised.patientName, "");
  EXPECT_EQ(anonymised.patientId, "");
  EXPECT_EQ(anonymised.modality, "CT");
  const fs::path nrrd = dir_ / "plain.nrrd";
  writeVolume(makeVolume({4, 4, 4}, {1, 1, 1}, encodeVoxel(0)), nrrd);
  EXPECT_TRUE(readVolume(nrrd).study.empty());
}

TEST_F(VolumeReaderTest, DicomSeriesWithMissingSlicesNamesThePositions) {
  writeDicomSeries(dir_, {0, 1, 2, 5, 6, 7}, "1.2.826.0.1.3680043.2.1125.777.1", 7);
  expectInputError(dir_, "gap in slice positions: missing z = 12.5, 15.0 mm");
}

TEST_F(VolumeReaderTest, DicomFolderWithTwoSeriesLoadsTheBiggerAndWarns) {
  writeDicomSeries(dir_, {0, 1, 2}, "1.2.826.0.1.3680043.2.1125.777.2", 1);
  writeDicomSeries(dir_, {0, 1, 2, 3, 4, 5}, "1.2.826.0.1.3680043.2.1125.777.3", 2);
  const WarnedLoad read = readCollectingWarnings(dir_);
  EXPECT_EQ(read.loaded.volume.dims.z, 6);
  EXPECT_NE(read.loaded.description.find("777.3"), std::string::npos) << read.loaded.description;
  expectOneWarning(read.warnings, {"1.2.826.0.1.3680043.2.1125.777.2 (3 slices)"});
}

TEST_F(VolumeReaderTest, DicomSeriesWithMixedOrientationsIsAnError) {
  writeDicomSeries(dir_, {0, 1, 2, 3}, "1.2.826.0.1.3680043.2.1125.777.1", 3);
  DicomSlice tilted;
  tilted.fileName = "tilted.dcm";
  tilted.position = {-12.0, 30.5, 30.0};
  tilted.instanceNumber = 99;
  tilted.orientation = "1\\0\\0\\0\\0\\-1";
  tilted.hu = [](int, int) { return short(0); };
  writeDicomSlice(dir_, tilted);
  expectInputError(dir_, "mixed slice orientations");
}

TEST_F(VolumeReaderTest, DicomCoronalSeriesIsReorientedToLps) {
  // Rows along +L, columns along -S (head to foot), slices stacked along +P.
  for (int k = 0; k < 3; ++k) {
    DicomSlice slice;
    slice.fileName = std::to_string(2 - k) + "-coronal.dcm";
    slice.instanceNumber = k + 1;
    slice.orientation = "1\\0\\0\\0\\0\\-1";
    slice.position = {-12.0, 30.5 + 2.5 * k, 50.0};
    slice.hu = [k](int i, int j) { return sliceHu(k, i, j); };
    writeDicomSlice(dir_, slice);
  }
  const Volume v = readVolume(dir_).volume;
  EXPECT_EQ(v.dims, glm::ivec3(16, 3, 16));
  EXPECT_NEAR(v.spacing.y, 2.5, 1e-6);
  EXPECT_NEAR(v.spacing.z, 0.7, 1e-6);
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_NEAR(glm::length(v.origin - glm::dvec3(-12.0, 30.5, 50.0 - 15 * 0.7)), 0.0, 1e-6);
  for (int s = 0; s < 16; ++s)
    for (int p = 0; p < 3; ++p)
      for (int l = 0; l < 16; ++l) ASSERT_EQ(v.densityAt(l, p, s), sliceHu(p, l, 15 - s) + 1024);
}

TEST(DicomSlicePositions, FindsMissingSlicesAndRejectsIrregularSteps) {
  EXPECT_TRUE(missingSlicePositions({0.0, 1.25, 2.5, 3.75}).empty());
  EXPECT_TRUE(missingSlicePositions({0.0, 1.25, 2.501, 3.749}).empty());  // scanner jitter
  EXPECT_EQ(missingSlicePositions({0.0, 1.25, 5.0, 6.25}), (std::vector<double>{2.5, 3.75}));
  EXPECT_THROW(missingSlicePositions({0.0, 1.25, 1.25, 2.5}), std::invalid_argument);     // duplicate
  EXPECT_THROW(missingSlicePositions({0.0, 1.0, 2.0, 3.5, 4.5}), std::invalid_argument);  // 1.5 steps
}

TEST_F(VolumeReaderTest, StronglyObliqueVolumeStillMapsEveryVoxel) {
  // 44 degrees about S: each stored axis still gets its own LPS axis.
  const Placement stored{{0.9, 1.1, 1.3}, {1.0, 2.0, 3.0}, rotationAboutZ(44.0)};
  const WarnedLoad read = readCollectingWarnings(writeAsymmetric("steep.nrrd", stored));
  ASSERT_NO_FATAL_FAILURE(expectOneWarning(read.warnings, {"44.0 degrees"}));
  expectSamePhysicalVoxels(read.loaded.volume, {4, 3, 2}, stored, asymmetricHu);
}

// ---- bad input -------------------------------------------------------------------------------

TEST_F(VolumeReaderTest, MissingPathIsAnError) {
  expectInputError(dir_ / "nowhere.nii.gz", "does not exist");
}

TEST_F(VolumeReaderTest, TruncatedFilesAreErrors) {
  for (const std::string name :
       {"cut.mha", "cut-raw.mha", "cut.nii.gz", "cut.nii", "cut.nrrd", "cut-raw.nrrd"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir_ / name;
    const bool compress = name.find("raw") == std::string::npos && name != "cut.nii";
    writeImage(makeImage<short>({40, 30, 20}, asymmetricHu).GetPointer(), file, compress);
    fs::resize_file(file, fs::file_size(file) * 2 / 3);
    expectInputError(file, name.find("nrrd") == std::string::npos ? "is truncated" : "");
  }
  // A .mhd whose data file lost its tail.
  writeImage(makeImage<short>({40, 30, 20}, asymmetricHu).GetPointer(), dir_ / "cut.mhd", false);
  fs::resize_file(dir_ / "cut.raw", 1000);
  expectInputError(dir_ / "cut.mhd", "is truncated");
}

TEST_F(VolumeReaderTest, GarbageBytesAreErrors) {
  std::string garbage(4096, '\0');
  std::mt19937 random(5);
  for (char& c : garbage) c = char(random());
  for (const std::string name :
       {"garbage.nii", "garbage.nii.gz", "garbage.mha", "garbage.nrrd", "garbage.xyz"}) {
    SCOPED_TRACE(name);
    writeText(dir_ / name, garbage);
    expectInputError(dir_ / name, name == "garbage.xyz" ? "unknown volume format" : "is not a valid");
  }
  writeText(dir_ / "empty.mha", "");
  expectInputError(dir_ / "empty.mha", "is not a valid MetaImage file");
}

TEST_F(VolumeReaderTest, TwoDimensionalFourDimensionalAndRgbImagesAreErrors) {
  const fs::path flat = dir_ / "flat.mha";
  writeImage(makeImage<short, 2>({8, 8}, [](auto) { return short(0); }).GetPointer(), flat);
  expectInputError(flat, "is 2-D (8 x 8 voxels); need a 3-D scalar volume");

  const fs::path slab = dir_ / "slab.nrrd";
  writeImage(makeImage<short>({8, 8, 1}, [](auto) { return short(0); }).GetPointer(), slab);
  expectInputError(slab, "is 2-D");

  const fs::path series = dir_ / "time.nii";
  writeImage(makeImage<short, 4>({4, 4, 4, 3}, [](auto) { return short(0); }).GetPointer(), series);
  expectInputError(series, "is 4-D");

  using Rgb = itk::RGBPixel<unsigned char>;
  const fs::path color = dir_ / "color.mha";
  writeImage(makeImage<Rgb>({4, 4, 4}, [](auto) { return Rgb(); }).GetPointer(), color);
  expectInputError(color, "need a 3-D scalar volume");
}

// A MetaImage header with the given fields and 16 bytes of int16 data (`extra` header lines
// may claim they are compressed).
void writeMetaImage(const fs::path& file, const std::string& dimSize, const std::string& spacing,
                    const std::string& extra = "") {
  writeText(file, "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n" +
                      extra + "DimSize = " + dimSize + "\nElementSpacing = " + spacing +
                      "\nElementType = MET_SHORT\nElementDataFile = LOCAL\n" + std::string(16, '\0'));
}

// A line MetaIO cannot read as one field sends it looking for the next '=' past ElementDataFile,
// into the voxels, where a name of 255 characters or more overflows its buffer (an abort).
TEST_F(VolumeReaderTest, MetaImageHeaderLinesMetaIoCannotReadAreRefusedBeforeIt) {
  writeMetaImage(dir_ / "colon.mha", "2 2 2", "1 1 1", "Comment: written by hand\n");
  EXPECT_EQ(readVolume(dir_ / "colon.mha").volume.dims, glm::ivec3(2, 2, 2));
  writeMetaImage(dir_ / "bare.mha", "2 2 2", "1 1 1", "Orientation\n");
  expectInputError(dir_ / "bare.mha", "header line 5 is not 'Key = Value' (a damaged header)");
  writeMetaImage(dir_ / "name.mha", "2 2 2", "1 1 1", std::string(300, 'K') + " = 1\n");
  expectInputError(dir_ / "name.mha",
                   "header line 5 has a field name of 300 characters (MetaIO reads 254)");
  writeMetaImage(dir_ / "long.mha", "2 2 2", "1 1 1", "Comment = " + std::string(600, 'v') + "\n");
  expectInputError(dir_ / "long.mha", "header line 5 has 610 characters (MetaIO reads 499)");
  // MetaIO strcpy's a string value into 255 bytes (ObjectType, Name, Comment, the data file).
  writeMetaImage(dir_ / "value.mha", "2 2 2", "1 1 1", "Name = " + std::string(300, 'v') + "\n");
  expectInputError(dir_ / "value.mha", "header line 5 has a value of 300 characters (MetaIO keeps 254)");
  // Read as MetaIO reads them: a flag by its first letter, a name up to a NUL; MetaIO allocated
  // the compressed size these claim.
  writeMetaImage(dir_ / "flag.mha", "2 2 2", "1 1 1",
                 "CompressedData = tRUE\nCompressedDataSize = 2300000000000002\n");
  expectInputError(dir_ / "flag.mha", "is truncated: its header promises 2300000000000002 bytes");
  writeMetaImage(dir_ / "nul.mha", "2 2 2", "1 1 1",
                 std::string("CompressedData = True\nCompressedDataSize\0\0 = 2300000000000002\n", 62));
  expectInputError(dir_ / "nul.mha", "is truncated: its header promises 2300000000000002 bytes");
  // A value as MetaIO reads it: past every '=', ':' and blank, a number up to what is not one; a
  // negative size wraps around to nearly 2^64.
  for (const std::string size : {": 2300000000000002", "2.300000000000002e15 bytes"}) {
    writeMetaImage(dir_ / "size.mha", "2 2 2", "1 1 1",
                   "CompressedData = True\nCompressedDataSize = " + size + "\n");
    expectInputError(dir_ / "size.mha", "is truncated: its header promises 2300000000000002 bytes");
  }
  writeMetaImage(dir_ / "negative.mha", "2 2 2", "1 1 1",
                 "CompressedData = True\nCompressedDataSize = -5\n");
  expectInputError(dir_ / "negative.mha", "has an impossible CompressedDataSize (-5)");
  // What MetaIO reads differently from the name written: a list (any name starting with LIST), a
  // name ending in bytes it strips.
  writeText(dir_ / "list.mha",
            "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
            "ElementType = MET_SHORT\nElementDataFile = LIST@L\n");
  expectInputError(dir_ / "list.mha", "keeps its voxels in a list of files");
  writeText(dir_ / "high.mha",
            "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
            "ElementType = MET_SHORT\nElementDataFile = \x9a\n");
  expectInputError(dir_ / "high.mha", "names its voxel data file with control bytes");
  // MetaIO leaks its stream when it cannot open the data file (LeakSanitizer), so ours says it first.
  const std::string detached =
      "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_SHORT\n";
  writeText(dir_ / "missing.mhd", detached + "ElementDataFile = LOCAL0 x = 1\n");
  expectInputError(dir_ / "missing.mhd", "its data file 'LOCAL0 x = 1' cannot be read: No such file");
  fs::create_directory(dir_ / "folder.raw");
  writeText(dir_ / "folder.mhd", detached + "ElementDataFile = folder.raw\n");
  expectInputError(dir_ / "folder.mhd", "its data file 'folder.raw' is a folder");
  writeText(dir_ / "data.raw", std::string(16, '\0'));
  writeText(dir_ / "data.mhd", detached + "ElementDataFile = " + (dir_ / "data.raw").string() + "\n");
  EXPECT_EQ(readVolume(dir_ / "data.mhd").volume.dims, glm::ivec3(2, 2, 2));
}

// A 2x2x2 uint8 NRRD with the given extra header lines.
void writeNrrd(const fs::path& file, const std::string& extra) {
  writeText(file, "NRRD0004\ntype: unsigned char\ndimension: 3\nsizes: 2 2 2\n" + extra +
                      "encoding: raw\n\n" + std::string(8, '\x40'));
}

// Teem quotes a field line it cannot parse in an error formatted into a 1025-byte stack buffer:
// a long one aborted the process (buffer overflow detected). Long comments and key:=value pairs
// are not quoted and still load.
TEST_F(VolumeReaderTest, NrrdFieldLinesTeemWouldOverflowOnAreRefusedBeforeIt) {
  const std::string longText(3000, 'a');
  writeNrrd(dir_ / "pairs.nrrd", "# " + longText + "\nSegment0_Name:=" + longText + "\n");
  EXPECT_EQ(readVolume(dir_ / "pairs.nrrd").volume.dims, glm::ivec3(2, 2, 2));
  writeNrrd(dir_ / "unknown.nrrd", "not a field: " + longText + "\n");
  expectInputError(dir_ / "unknown.nrrd",
                   "header line 5 has 3013 characters (a NRRD field has at most 768; a damaged header)");
  writeText(dir_ / "sizes.nrrd", "NRRD0004\ntype: unsigned char\ndimension: 3\nsizes: 2 2 2 " +
                                     longText + "\nencoding: raw\n\n" + std::string(8, '\x40'));
  expectInputError(dir_ / "sizes.nrrd", "header line 4 has 3013 characters");
  // Teem takes a line for a field when its ": " comes first, and ends it at a NUL byte.
  writeNrrd(dir_ / "late.nrrd", "content: " + longText + ":=\n");
  expectInputError(dir_ / "late.nrrd", "header line 5 has 3011 characters");
  writeNrrd(dir_ / "nul.nrrd", std::string("key\0", 4) + longText + ":=\n");
  expectInputError(dir_ / "nul.nrrd", "header line 5 has 3006 characters");
}

// Teem reports a chain of messages, outermost first ("nrrdLoad: trouble reading ... nrrdRead:
// trouble ..."); the innermost names the problem, and it is what the user reads.
TEST_F(VolumeReaderTest, TeemsProblemIsItsInnermostMessage) {
  writeText(dir_ / "endian.nrrd",
            "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 2\nencoding: bzip2\n\n12");
  expectInputError(dir_ / "endian.nrrd",
                   "endian.nrrd: cannot be read: type (short) and encoding (bzip2) require endian info");
}

// Teem allocates the volume before it parses text or hex data: a value as text takes a digit and
// a separator (the last one a digit), a byte as hex two digits.
TEST_F(VolumeReaderTest, NrrdTextOrHexTooShortForItsVolumeIsRefused) {
  const auto nrrd = [](const std::string& sizes, const std::string& encoding, const std::string& data) {
    return "NRRD0004\ntype: short\ndimension: 3\nsizes: " + sizes +
           "\nendian: little\nencoding: " + encoding + "\n\n" + data;
  };
  writeText(dir_ / "least.nrrd", nrrd("2 2 2", "ascii", "1 1 1 1 1 1 1 1"));
  EXPECT_EQ(readVolume(dir_ / "least.nrrd").volume.dims, glm::ivec3(2, 2, 2));
  writeText(dir_ / "short.nrrd", nrrd("2 2 2", "text", "1 1 1 1 1 1 11"));
  expectInputError(dir_ / "short.nrrd",
                   "is truncated: its 14 bytes of voxel data as text cannot hold the 8 values");
  writeText(dir_ / "huge.nrrd", nrrd("6 5 99496729", "txt", "1 2 3\n"));
  expectInputError(dir_ / "huge.nrrd", "cannot hold the 2984901870 values");
  // Skipped lines only make the data shorter (teem took 47 s and 6 GB to find this one short).
  writeText(dir_ / "skip.nrrd", nrrd("6 5 99496729", "ascii\nline skip: 1", "x\n1 2 3\n"));
  expectInputError(dir_ / "skip.nrrd", "its 8 bytes of voxel data as text cannot hold");
  const std::string hex = "0100020003000400050006000700080";
  writeText(dir_ / "hex.nrrd", nrrd("2 2 2", "hex", hex + "0"));
  EXPECT_EQ(readVolume(dir_ / "hex.nrrd").volume.dims, glm::ivec3(2, 2, 2));
  writeText(dir_ / "short-hex.nrrd", nrrd("2 2 2", "hex", hex));
  expectInputError(dir_ / "short-hex.nrrd",
                   "is truncated: its 31 bytes of voxel data as hex cannot hold the 16 bytes its header "
                   "promises (2 digits each)");
}

// A NRRD file whose sizes no machine holds, with 16 bytes of data: its lines end with `lineEnd`
// and its sizes field is named `sizesName`.
std::string hugeSizesNrrd(const std::string& lineEnd = "\n", const std::string& sizesName = "sizes") {
  std::string text;
  for (const std::string& line :
       std::initializer_list<std::string>{"NRRD0004", "# a comment", "type: short", "dimension: 3",
                                          sizesName + ": 2 42999345910 4", "encoding: raw", ""})
    text += line + lineEnd;
  return text + std::string(16, '\0');
}
constexpr const char* kHugeSizes = "has impossible dimensions (sizes: 2 42999345910 4)";

// ITK keeps NRRD sizes as unsigned int (42999345910 became 49672950) while teem allocates what the
// header says; and teem allocates the whole volume before it finds the data short.
TEST_F(VolumeReaderTest, NrrdSizesAndDataAreCheckedBeforeTeemAllocates) {
  writeText(dir_ / "huge.nrrd", hugeSizesNrrd());
  expectInputError(dir_ / "huge.nrrd", kHugeSizes);
  const std::string header = "NRRD0004\ntype: short\ndimension: 3\nsizes: 20 20 20\nendian: little\n";
  writeText(dir_ / "short.nrrd", header + "encoding: raw\n\n" + std::string(100, '\0'));
  expectInputError(dir_ / "short.nrrd",
                   "is truncated: its header promises 16000 bytes of voxel data, the file holds 100");
  // Whatever the byte order and the case teem reads its values in.
  std::string big = header;
  big.replace(big.find("little"), 6, "big");
  writeText(dir_ / "short-big.nrrd", big + "encoding: RAW\n\n" + std::string(100, '\0'));
  expectInputError(dir_ / "short-big.nrrd", "is truncated");
  std::string crlf = header + "encoding: raw\n\n";
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2))
    crlf.insert(at, "\r");
  writeText(dir_ / "short-crlf.nrrd", crlf + std::string(100, '\0'));
  expectInputError(dir_ / "short-crlf.nrrd", "is truncated");
  writeText(dir_ / "whole-crlf.nrrd", crlf + std::string(16000, '\0'));
  EXPECT_EQ(readVolume(dir_ / "whole-crlf.nrrd").volume.dims, glm::ivec3(20, 20, 20));
  writeText(dir_ / "short-gzip.nrrd", header + "encoding: gzip\n\n");
  gzFile gz = gzopen((dir_ / "short-gzip.nrrd").c_str(), "ab");
  ASSERT_NE(gz, nullptr);
  ASSERT_EQ(gzwrite(gz, std::string(100, '\0').data(), 100), 100);
  gzclose(gz);
  expectInputError(dir_ / "short-gzip.nrrd",
                   "is truncated: its header promises 16000 bytes of voxel data, the file holds 100");
  writeText(dir_ / "whole-gzip.nrrd", header + "encoding: gzip\n\n");
  gz = gzopen((dir_ / "whole-gzip.nrrd").c_str(), "ab");
  ASSERT_EQ(gzwrite(gz, std::string(16000, '\0').data(), 16000), 16000);
  gzclose(gz);
  EXPECT_EQ(readVolume(dir_ / "whole-gzip.nrrd").volume.dims, glm::ivec3(20, 20, 20));
}

// Teem ends a header line at a CR too and matches field names case-insensitively: the checks made
// before it reads a file see the fields it sees.
TEST_F(VolumeReaderTest, NrrdFieldsAreCheckedAsTeemReadsThem) {
  writeText(dir_ / "cr.nrrd", hugeSizesNrrd("\r"));
  expectInputError(dir_ / "cr.nrrd", kHugeSizes);
  writeText(dir_ / "upper.nrrd", hugeSizesNrrd("\n", "SIZES"));
  expectInputError(dir_ / "upper.nrrd", kHugeSizes);
  // Teem joins the pieces of a long first line as C strings: NULs in the magic vanish (and the
  // checks, which cannot read such a header, must not let teem read it unchecked).
  std::string nulMagic =
      "NRRD" + std::string(14, '\0') +
      "0004\ntype: short\ndimension: 3\nsizes: 2 3 4\nendian: little\nencoding: raw\n\n";
  writeText(dir_ / "nul-magic.nrrd", nulMagic + std::string(48, '\0'));
  const std::optional<fuzz::TeemReading> magic = fuzz::TeemHeaderRead(dir_ / "nul-magic.nrrd").reading();
  ASSERT_TRUE(magic.has_value());
  EXPECT_EQ(magic->sizes, "2 3 4");
  expectInputError(dir_ / "nul-magic.nrrd", "is not a valid NRRD file (its first line is not NRRD000N)");
  const std::string header =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 20 20 20\nendian: little\n"
      "encoding: raw\n";
  writeText(dir_ / "axes.nrrd", header +
                                    "space: left-posterior-superior\n"
                                    "spacedirections: (0,0,0) (0,1,0) (0,0,1)\n\n" +
                                    std::string(16000, '\0'));
  expectInputError(dir_ / "axes.nrrd", "has a zero-length axis in space directions");
  // Teem reads a size up to the first character that is not a digit: this was 6 5 994967655352.
  writeText(dir_ / "sizes.nrrd",
            "NRRD0004\ntype: short\ndimension: 3\nsizes: 6 5~ 994967655352rr0\n"
            "encoding: ascii\n\n3 2 3\n");
  const std::optional<fuzz::TeemReading> sizes = fuzz::TeemHeaderRead(dir_ / "sizes.nrrd").reading();
  ASSERT_TRUE(sizes.has_value());
  EXPECT_EQ(sizes->sizes, "6 5 994967655352");
  expectInputError(dir_ / "sizes.nrrd", "has impossible dimensions (sizes: 6 5~ 994967655352rr0)");
  // Teem reads a vector's component up to the first character that is not part of a number.
  writeText(dir_ / "garbled.nrrd", header +
                                       "space: left-posterior-superior\n"
                                       "space directions: (0(.7,0,0) (0,1,0) (0,0,1)\n\n" +
                                       std::string(16000, '\0'));
  const std::optional<fuzz::TeemReading> garbled = fuzz::TeemHeaderRead(dir_ / "garbled.nrrd").reading();
  ASSERT_TRUE(garbled.has_value());
  EXPECT_EQ(garbled->badSpacing, "axis 0 spacing 0.000000");
  expectInputError(dir_ / "garbled.nrrd", "has a non-finite or absurd space directions ((0(.7,0,0)");
  for (const std::string vectors : {"(1, 0, 0) (0,1,0) (0,0,1)", "(1,0,0)(0,1,0)(0,0,1)"}) {
    writeText(dir_ / "vectors.nrrd", header + "space: left-posterior-superior\nspace directions: " +
                                         vectors + "\n\n" + std::string(16000, '\0'));
    EXPECT_EQ(readVolume(dir_ / "vectors.nrrd").volume.dims, glm::ivec3(20, 20, 20)) << vectors;
  }
  std::string cr = header + "\n";
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  writeText(dir_ / "short-cr.nrrd", cr + std::string(100, '\0'));
  expectInputError(dir_ / "short-cr.nrrd",
                   "is truncated: its header promises 16000 bytes of voxel data, the file holds 100");
  writeText(dir_ / "whole-cr.nrrd", cr + std::string(16000, '\0'));
  EXPECT_EQ(readVolume(dir_ / "whole-cr.nrrd").volume.dims, glm::ivec3(20, 20, 20));
  // Teem reads a key/value pair up to a NUL byte and goes on (a fuzzer's way around the data
  // check); past a NUL in a long line it reads what the lines before decide.
  const std::string nul = "NRRD0004\nkey:=a" + std::string(1, '\0') + "b\n";
  writeText(dir_ / "short-nul.nrrd", nul + header.substr(9) + "\n" + std::string(100, '\0'));
  expectInputError(dir_ / "short-nul.nrrd", "header line 2 has a NUL byte");
  const std::string joined = "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 5 4" + std::string(1, '\0') +
                             "xxxxx" + std::string(40, '9') + "\nendian: little\nencoding: raw\n\n";
  writeText(dir_ / "joined.nrrd", joined + std::string(100, '\0'));
  const std::optional<fuzz::TeemReading> teem = fuzz::TeemHeaderRead(dir_ / "joined.nrrd").reading();
  ASSERT_TRUE(teem.has_value());
  EXPECT_FALSE(teem->sizesFitInt) << teem->sizes;
  expectInputError(dir_ / "joined.nrrd", "header line 4 has a NUL byte");
}

TEST_F(VolumeReaderTest, ZeroOrNegativeSpacingIsAnError) {
  writeMetaImage(dir_ / "zero.mha", "2 2 2", "1 0 1");
  expectInputError(dir_ / "zero.mha", "spacing");
  writeMetaImage(dir_ / "negative.mha", "2 2 2", "1 1 -2");
  expectInputError(dir_ / "negative.mha", "spacing");
}

TEST_F(VolumeReaderTest, DegenerateDirectionIsAnError) {
  writeMetaImage(dir_ / "parallel.mha", "2 2 2", "1 1 1", "TransformMatrix = 1 0 0 1 0 0 0 0 1\n");
  expectInputError(dir_ / "parallel.mha", "direction");
}

TEST_F(VolumeReaderTest, VolumeLargerThanMemoryIsRefusedBeforeAllocating) {
  // Compressed data of the declared size, so only the memory check can object.
  writeMetaImage(dir_ / "huge.mha", "100000 100000 100000", "1 1 1",
                 "CompressedData = True\nCompressedDataSize = 16\n");
  expectInputError(dir_ / "huge.mha", "of memory");
}

TEST_F(VolumeReaderTest, FolderWithoutDicomIsAnError) {
  writeText(dir_ / "notes.txt", "not an image");
  expectInputError(dir_, "no DICOM series");
}

}  // namespace
}  // namespace angio
