// Voxels decoded by io/ itself in slabs (voxel_data_layout.h, voxel_slab_reader.h) against ITK's
// one-call read of the same file: byte for byte, for every format, type and encoding it takes on;
// and the files it leaves to ITK.
#include "io/voxel_slab_reader.h"

#include <gtest/gtest.h>

#include <zlib.h>

#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <itkImage.h>
#include <itkImageFileWriter.h>

#include "io/input_error.h"
#include "io/volume_formats.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::fileBytes;

// Odd dims, so no slice or row happens to fall on a power of two.
constexpr int kDims[3] = {37, 23, 19};

// A 37 x 23 x 19 image of random values of T over T's whole range (floats: -5000..5000).
template <class T>
typename itk::Image<T, 3>::Pointer randomImage(unsigned seed) {
  using Image = itk::Image<T, 3>;
  typename Image::RegionType region;
  for (int axis = 0; axis < 3; ++axis) region.SetSize(axis, kDims[axis]);
  auto image = Image::New();
  image->SetRegions(region);
  image->Allocate();
  std::mt19937 random(seed);
  T* voxel = image->GetBufferPointer();
  for (std::size_t n = 0; n < region.GetNumberOfPixels(); ++n) {
    if constexpr (std::is_floating_point_v<T>) {
      voxel[n] = std::uniform_real_distribution<T>(-5000, 5000)(random);
    } else {
      voxel[n] = T(std::uniform_int_distribution<int>(std::numeric_limits<T>::min(),
                                                      std::numeric_limits<T>::max())(random));
    }
  }
  return image;
}

template <class T>
void writeImage(const typename itk::Image<T, 3>::Pointer& image, const fs::path& file, bool compress) {
  auto writer = itk::ImageFileWriter<itk::Image<T, 3>>::New();
  writer->SetImageIO(makeImageIO(*volumeFormatOf(file)));
  writer->SetFileName(file.string());
  writer->SetInput(image);
  writer->SetUseCompression(compress);
  writer->Update();
}

itk::ImageIOBase::Pointer headerOf(const fs::path& file) {
  itk::ImageIOBase::Pointer io = makeImageIO(*volumeFormatOf(file));
  io->SetFileName(file.string());
  io->ReadImageInformation();
  return io;
}

StoredDataSize sizeOf(const itk::ImageIOBase& io) {
  return {std::uint64_t(io.GetImageSizeInBytes()), unsigned(io.GetComponentSize())};
}

// The voxel bytes as ITK reads them (the reader's path for the files without a layout).
std::vector<char> itkBytes(const fs::path& file) {
  const itk::ImageIOBase::Pointer io = headerOf(file);
  itk::ImageIORegion region(io->GetNumberOfDimensions());
  for (unsigned d = 0; d < io->GetNumberOfDimensions(); ++d) region.SetSize(d, io->GetDimensions(d));
  io->SetIORegion(region);
  std::vector<char> bytes(io->GetImageSizeInBytes());
  io->Read(bytes.data());
  return bytes;
}

std::optional<VoxelDataLayout> layoutOf(const fs::path& file) {
  return voxelDataLayout(file, *volumeFormatOf(file), sizeOf(*headerOf(file)));
}

// The voxel bytes decoded in slabs; fails the test if the file has no layout.
std::vector<char> slabBytes(const fs::path& file, std::vector<double>* fractions = nullptr) {
  const auto layout = layoutOf(file);
  EXPECT_TRUE(layout.has_value()) << file << " has no layout";
  if (!layout) return {};
  const itk::ImageIOBase::Pointer io = headerOf(file);
  const std::uint64_t slices = io->GetDimensions(2);
  std::vector<char> bytes(io->GetImageSizeInBytes());
  readVoxelSlabs(*layout, {bytes.size() / slices, slices}, bytes.data(), [&](double fraction) {
    if (fractions) fractions->push_back(fraction);
  });
  return bytes;
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

class VoxelSlabReaderTest : public test_support::TempFolderTest {
 protected:
  // Writes one random image of T to every format, compressed and not, and expects the slab
  // reader to give ITK's bytes for each.
  template <class T>
  void expectItksBytesInEveryFormat() {
    const auto image = randomImage<T>(sizeof(T) * 7 + std::is_signed_v<T>);
    struct Written {
      const char* name;
      bool compress;
    };
    // .nii is never compressed and .nii.gz always; the .mhd/.nhdr data files sit beside them.
    for (const Written written : {Written{"z.mha", true},
                                  {"r.mha", false},
                                  {"z.mhd", true},
                                  {"r.mhd", false},
                                  {"z.nrrd", true},
                                  {"r.nrrd", false},
                                  {"z.nhdr", true},
                                  {"r.nhdr", false},
                                  {"r.nii", false},
                                  {"z.nii.gz", true}}) {
      SCOPED_TRACE(written.name);
      const fs::path file = dir_ / written.name;
      writeImage<T>(image, file, written.compress);
      const std::vector<char> expected = itkBytes(file);
      ASSERT_EQ(expected.size(), sizeof(T) * kDims[0] * kDims[1] * kDims[2]);
      EXPECT_TRUE(slabBytes(file) == expected);
    }
  }
};

TEST_F(VoxelSlabReaderTest, Int16VoxelsAreItksInEveryFormat) { expectItksBytesInEveryFormat<short>(); }

TEST_F(VoxelSlabReaderTest, Uint16VoxelsAreItksInEveryFormat) {
  expectItksBytesInEveryFormat<unsigned short>();
}

TEST_F(VoxelSlabReaderTest, Float32VoxelsAreItksInEveryFormat) { expectItksBytesInEveryFormat<float>(); }

TEST_F(VoxelSlabReaderTest, ReportsTheFractionReadAfterEverySlabButTheLast) {
  const fs::path file = dir_ / "v.nrrd";
  writeImage<short>(randomImage<short>(1), file, true);
  std::vector<double> fractions;
  slabBytes(file, &fractions);
  // 19 slices: a slab per slice.
  ASSERT_EQ(fractions.size(), std::size_t(kDims[2] - 1));
  for (std::size_t n = 0; n < fractions.size(); ++n)
    EXPECT_DOUBLE_EQ(fractions[n], double(n + 1) / kDims[2]);
}

TEST_F(VoxelSlabReaderTest, GzipOfSeveralMembersReadsOnAsZlibDoes) {
  const fs::path plain = dir_ / "v.nii", split = dir_ / "split.nii.gz";
  writeImage<short>(randomImage<short>(2), plain, false);
  const std::string bytes = fileBytes(plain);
  std::string members;
  for (const std::string& part : {bytes.substr(0, 10000), bytes.substr(10000)}) {
    const fs::path member = dir_ / "member.gz";
    gzFile gz = gzopen(member.c_str(), "wb");
    gzwrite(gz, part.data(), unsigned(part.size()));
    gzclose(gz);
    members += fileBytes(member);
  }
  writeBytes(split, members);
  EXPECT_TRUE(slabBytes(split) == itkBytes(plain));
}

TEST_F(VoxelSlabReaderTest, DataEndingEarlyIsAStreamError) {
  for (const char* name : {"cut.nrrd", "cut.mha"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir_ / name;
    writeImage<short>(randomImage<short>(3), file, true);
    const auto layout = layoutOf(file);
    ASSERT_TRUE(layout.has_value());
    fs::resize_file(file, fs::file_size(file) - 100);
    std::vector<char> bytes(sizeof(short) * kDims[0] * kDims[1] * kDims[2]);
    EXPECT_THROW(readVoxelSlabs(*layout, {bytes.size() / kDims[2], kDims[2]}, bytes.data(), {}),
                 VoxelStreamError);
  }
}

// ---- files left to ITK ---------------------------------------------------------------------------

// A 2 x 2 x 2 int16 NRRD with the header lines `fields` and `data` attached.
std::string nrrdText(const std::string& fields, const std::string& data) {
  return "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 2\n" + fields + "\n" + data;
}

TEST_F(VoxelSlabReaderTest, UnusualNrrdsHaveNoLayout) {
  const std::string data(16, '\1');
  const struct {
    const char* name;
    std::string text;
  } cases[] = {
      {"big.nrrd", nrrdText("encoding: raw\nendian: big\n", data)},
      {"no-endian.nrrd", nrrdText("encoding: raw\n", data)},
      {"byte-skip.nrrd", nrrdText("encoding: raw\nendian: little\nbyte skip: 4\n", "abcd" + data)},
      {"line-skip.nrrd", nrrdText("encoding: raw\nendian: little\nline skip: 1\n", "x\n" + data)},
      {"ascii.nrrd", nrrdText("encoding: ascii\n", "1 1 1 1 1 1 1 1\n")},
      {"bzip2.nrrd", nrrdText("encoding: bzip2\nendian: little\n", data)},
      {"list.nhdr", nrrdText("encoding: raw\nendian: little\ndata file: LIST\n", "a.raw\n")},
      {"pattern.nhdr", nrrdText("encoding: raw\nendian: little\ndata file: s%03d.raw 0 1 1\n", "")},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_FALSE(voxelDataLayout(write(c.name, c.text), VolumeFormat::nrrd, {16, 2}).has_value());
  }
  // The same header in this machine's byte order does have one.
  EXPECT_TRUE(voxelDataLayout(write("little.nrrd", nrrdText("encoding: raw\nendian: little\n", data)),
                              VolumeFormat::nrrd, {16, 2})
                  .has_value());
}

TEST_F(VoxelSlabReaderTest, UnusualMetaImagesHaveNoLayout) {
  const std::string header = "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_SHORT\n";
  const std::string data(16, '\1');
  const struct {
    const char* name;
    std::string text;
  } cases[] = {
      {"msb.mha",
       header + "BinaryData = True\nElementByteOrderMSB = True\nElementDataFile = LOCAL\n" + data},
      {"ascii.mha", header + "BinaryData = False\nElementDataFile = LOCAL\n1 1 1 1 1 1 1 1\n"},
      {"skip.mhd", header + "BinaryData = True\nHeaderSize = 4\nElementDataFile = v.raw\n"},
      {"list.mhd", header + "BinaryData = True\nElementDataFile = LIST\na.raw\nb.raw\n"},
      {"pattern.mhd", header + "BinaryData = True\nElementDataFile = s%03d.raw 0 1 1\n"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_FALSE(voxelDataLayout(write(c.name, c.text), VolumeFormat::metaImage, {16, 2}).has_value());
  }
  EXPECT_TRUE(
      voxelDataLayout(write("plain.mha", header + "BinaryData = True\nElementDataFile = LOCAL\n" + data),
                      VolumeFormat::metaImage, {16, 2})
          .has_value());
}

// MetaIO takes data as binary where the header does not say, reads on after a CRLF line end and
// looks for a data file named with folders relative to the header's folder.
TEST_F(VoxelSlabReaderTest, MetaImagesReadWhereMetaIoReadsThem) {
  const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  for (const bool compress : {true, false}) {
    SCOPED_TRACE(compress ? "compressed" : "raw");
    const fs::path written = dir_ / "v.mha";
    writeImage<short>(randomImage<short>(5), written, compress);
    const std::string bytes = fileBytes(written);
    const std::size_t dataStart = bytes.find("ElementDataFile = LOCAL\n") + 24;
    std::string crlf = bytes.substr(0, dataStart);
    for (std::size_t at = 0; (at = crlf.find('\n', at)) != std::string::npos; at += 2)
      crlf.insert(at, "\r");
    const fs::path files[] = {
        write("crlf.mha", crlf + bytes.substr(dataStart)),
        write("unsaid.mha", replaced(bytes, "BinaryData = True\n", "")),
    };
    for (const fs::path& file : files) {
      SCOPED_TRACE(file.filename());
      EXPECT_TRUE(slabBytes(file) == itkBytes(written));
    }
    const fs::path header = dir_ / "v.mhd", data = compress ? "v.zraw" : "v.raw";
    writeImage<short>(randomImage<short>(5), header, compress);
    fs::create_directory(dir_ / "voxels");
    fs::rename(dir_ / data, dir_ / "voxels" / data);
    const std::string named = "ElementDataFile = " + data.string();
    writeBytes(header, replaced(fileBytes(header), named, "ElementDataFile = voxels/" + data.string()));
    EXPECT_TRUE(slabBytes(header) == itkBytes(written));
    EXPECT_TRUE(itkBytes(header) == itkBytes(written));
  }
}

// MetaIO's inflate loop never ends on a stream asking for a preset dictionary, so compressed data
// io/ cannot place are refused rather than left to it.
TEST_F(VoxelSlabReaderTest, CompressedMetaImageDataWithoutALayoutAreRefused) {
  const std::string header =
      "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = "
      "MET_SHORT\nCompressedData = True\n";
  const std::string data = "x^" + std::string(14, '\1');
  const struct {
    const char* name;
    std::string text;
    const char* why;
  } cases[] = {
      {"msb.mha", header + "ElementByteOrderMSB = True\nElementDataFile = LOCAL\n" + data,
       "in big-endian byte order"},
      {"skip.mhd", header + "HeaderSize = 4\nElementDataFile = v.raw\n", "after a HeaderSize"},
      {"list.mhd", header + "ElementDataFile = LIST\na.raw\nb.raw\n", "in a list or pattern of files"},
      {"channels.mha", header + "ElementNumberOfChannels = 2\nElementDataFile = LOCAL\n" + data,
       "with several channels per voxel"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path file = write(c.name, c.text);
    try {
      voxelDataLayout(file, VolumeFormat::metaImage, {16, 2});
      ADD_FAILURE() << "not refused";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                file.string() + ": has compressed voxel data " + c.why +
                    ", which angioray does not read (compressed data must be one little-endian block "
                    "of single-channel voxels)");
    }
  }
  // As text, MetaIO does not inflate them.
  EXPECT_FALSE(
      voxelDataLayout(write("text.mha", header + "BinaryData = False\nElementDataFile = LOCAL\n1\n"),
                      VolumeFormat::metaImage, {16, 2})
          .has_value());
}

TEST_F(VoxelSlabReaderTest, ScaledOrSwappedNiftiHasNoLayout) {
  const fs::path file = dir_ / "v.nii";
  writeImage<short>(randomImage<short>(4), file, false);
  const std::string written = fileBytes(file);
  ASSERT_TRUE(layoutOf(file).has_value());
  const auto patched = [&](const char* name, std::size_t offset, const void* value, std::size_t size) {
    std::string bytes = written;
    std::memcpy(bytes.data() + offset, value, size);
    return write(name, bytes);
  };
  const float two = 2.0f, ten = 10.0f;
  const unsigned char swappedSize[4] = {0, 0, 1, 92};  // 348, big-endian
  for (const fs::path& unusual : {patched("slope.nii", 112, &two, 4), patched("inter.nii", 116, &ten, 4),
                                  patched("swapped.nii", 0, swappedSize, 4)}) {
    SCOPED_TRACE(unusual.filename().string());
    EXPECT_FALSE(voxelDataLayout(unusual, VolumeFormat::nifti, sizeOf(*headerOf(file))).has_value());
  }
}

TEST_F(VoxelSlabReaderTest, NiftiGzBesideItsNiiIsLeftToItk) {
  // ITK reads v.nii when asked for v.nii.gz if both exist; the layout must not read the .gz then.
  writeImage<short>(randomImage<short>(5), dir_ / "v.nii.gz", true);
  ASSERT_TRUE(layoutOf(dir_ / "v.nii.gz").has_value());
  writeImage<short>(randomImage<short>(6), dir_ / "v.nii", false);
  EXPECT_FALSE(layoutOf(dir_ / "v.nii.gz").has_value());
  EXPECT_TRUE(itkBytes(dir_ / "v.nii.gz") == itkBytes(dir_ / "v.nii"));  // the premise
}

}  // namespace
}  // namespace angio
