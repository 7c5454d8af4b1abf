// The bad-input catalogue of files: volumes (NRRD, MetaImage, NIfTI, DICOM), centerlines (CSV,
// .vtp, markups), transfer functions, render sidecars, sessions, headless scripts, label volumes,
// and outputs that cannot be written. Each case has one bad file and must be refused as
// tests/support/bad_input_case.h says: one line naming the file and the problem, nothing written.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/volume.h"
#include "io/tf_file.h"
#include "io/volume_writer.h"
#include "render/recipe_json.h"
#include "tests/support/bad_input_case.h"
#include "tests/support/dicom_recompress.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/dicom_tag_patch.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::BadInput;

// --- Volumes written by our writer, then one header field changed in the bytes. ---

fs::path niftiIn(const fs::path& dir) {
  const fs::path file = dir / "v.nii";
  writeVolume(makeVolume({8, 8, 8}, {0.8, 0.8, 1.0}, encodeVoxel(100)), file);
  return file;
}

void patchBytes(const fs::path& file, std::size_t offset, const void* value, std::size_t size) {
  std::string bytes = test_support::fileBytes(file);
  bytes.replace(offset, size, static_cast<const char*>(value), size);
  test_support::overwrite(file, bytes);
}

// NIfTI-1 offsets: pixdim[1] 80, qform_code 252, sform_code 254, quatern_b 256, srow_x 280.
void niftiNanSpacing(const fs::path& dir) {
  const float nan = NAN;
  patchBytes(niftiIn(dir), 80, &nan, 4);
}
void niftiZeroSpacing(const fs::path& dir) {
  const float zero = 0;
  patchBytes(niftiIn(dir), 84, &zero, 4);
}
void niftiNanQform(const fs::path& dir) {
  const fs::path file = niftiIn(dir);
  const std::int16_t code = 1;
  const float nan = NAN;
  patchBytes(file, 252, &code, 2);
  patchBytes(file, 260, &nan, 4);
}
void niftiNanSform(const fs::path& dir) {
  const fs::path file = niftiIn(dir);
  const std::int16_t code = 1;
  const float nan = NAN;
  patchBytes(file, 254, &code, 2);
  patchBytes(file, 300, &nan, 4);
}
void niftiTruncated(const fs::path& dir) {
  const fs::path file = niftiIn(dir);
  test_support::truncateBy(file, 600);
}
void niftiTwoDimensional(const fs::path& dir) {
  const std::int16_t rank = 2;
  patchBytes(niftiIn(dir), 40, &rank, 2);
}
void niftiHugeDims(const fs::path& dir) {
  const std::int16_t dims[3] = {32000, 32000, 32000};
  patchBytes(niftiIn(dir), 42, dims, 6);
}

// A float MetaImage whose voxels are NaN and infinite.
void metaImageNanVoxels(const fs::path& dir) {
  std::ofstream(dir / "f.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
                                  "ElementType = MET_FLOAT\nElementDataFile = f.raw\n";
  const float voxels[8] = {NAN, 1, 2, 3, INFINITY, 5, 6, 7};
  std::ofstream(dir / "f.raw", std::ios::binary)
      .write(reinterpret_cast<const char*>(voxels), sizeof voxels);
}

// --- DICOM: a four-slice series in {dir}/ct; one tag of slice IM2-4.dcm changed. ---

fs::path dicomSeries(const fs::path& dir) {
  fs::create_directories(dir / "ct");
  test_support::writeDicomSeries(dir / "ct", {0, 1, 2, 3}, "1.2.3.4", 7);
  return dir / "ct" / "IM2-4.dcm";
}
template <std::uint16_t Group, std::uint16_t Element, int Value>
void dicomShort(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), Group, Element, test_support::unsignedShort(Value));
}
void dicomEightBits(const fs::path& dir) {
  const fs::path slice = dicomSeries(dir);
  test_support::setDicomTag(slice, 0x0028, 0x0100, test_support::unsignedShort(8));
  test_support::setDicomTag(slice, 0x0028, 0x0101, test_support::unsignedShort(8));
  test_support::setDicomTag(slice, 0x0028, 0x0102, test_support::unsignedShort(7));
}
void dicomSpacingZero(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0028, 0x0030, "0\\0 ");
}
void dicomSpacingNegative(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0028, 0x0030, "-0.7\\0.7");
}
void dicomSpacingNan(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0028, 0x0030, "nan\\nan ");
}
void dicomOrientationZero(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0020, 0x0037, "0\\0\\0\\0\\0\\0 ");
}
void dicomSlopeNan(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0028, 0x1053, "nan ");
}
void dicomSlopeZero(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0028, 0x1053, "0 ");
}
void dicomPositionNan(const fs::path& dir) {
  test_support::setDicomTag(dicomSeries(dir), 0x0020, 0x0032, "nan\\0\\0 ");
}
void dicomTruncated(const fs::path& dir) { test_support::truncateBy(dicomSeries(dir), 100); }
void dicomTilted(const fs::path& dir) {
  fs::create_directories(dir / "ct");
  for (int k = 0; k < 4; ++k) {
    test_support::DicomSlice slice;
    slice.fileName = "tilt" + std::to_string(k) + ".dcm";
    slice.position = {-12.0, 30.5 + 0.5 * k, 5.0 + 2.5 * k};
    slice.instanceNumber = k + 1;
    slice.hu = [](int, int) { return short(0); };
    test_support::writeDicomSlice(dir / "ct", slice);
  }
}
void dicomMissingSlice(const fs::path& dir) {
  fs::create_directories(dir / "ct");
  test_support::writeDicomSeries(dir / "ct", {0, 1, 3, 4}, "1.2.3.4", 7);
}
// The series in JPEG lossless; slice IM2-4.dcm's stream makes GDCM's codec abort.
void dicomJpegDecoderAborts(const fs::path& dir) {
  const fs::path damaged = dicomSeries(dir);
  for (const auto& slice : fs::directory_iterator(dir / "ct"))
    test_support::recompressDicomSlice(slice.path(), gdcm::TransferSyntax::JPEGLosslessProcess14_1);
  test_support::strayBytesBeforeJpegFrameHeader(damaged);
}
// The series in RLE; slice IM2-4.dcm ends inside its compressed fragments.
void dicomRleCutShort(const fs::path& dir) {
  const fs::path damaged = dicomSeries(dir);
  for (const auto& slice : fs::directory_iterator(dir / "ct"))
    test_support::recompressDicomSlice(slice.path(), gdcm::TransferSyntax::RLELossless);
  test_support::truncateBy(damaged, 100);
}
void emptyFolder(const fs::path& dir) { fs::create_directories(dir / "ct"); }
void folderOfText(const fs::path& dir) {
  fs::create_directories(dir / "ct");
  std::ofstream(dir / "ct" / "notes.txt") << "not a slice";
}

// --- Sidecars written by our writer with one value no renderer can finish. ---

template <class Change>
void sidecarWith(const fs::path& dir, Change change) {
  RenderRecipe recipe;
  recipe.dataset = std::string(ANGIORAY_SHARED_DATA) + "/aorta.mha";
  recipe.tf = loadPresetOrFile("cta-vessels");
  recipe.quality = Quality::high;
  recipe.params.sampling = qualitySampling(Quality::high);
  change(recipe);
  std::ofstream(dir / "bad.json") << renderSidecarJson(recipe);
}
void sidecarTinyOsd(const fs::path& dir) {
  sidecarWith(dir, [](RenderRecipe& r) { r.params.sampling.osd = 1e-9; });
}
void sidecarTinyIsd(const fs::path& dir) {
  sidecarWith(dir, [](RenderRecipe& r) { r.params.sampling.isd = 1e-9; });
}
void sidecarErtFive(const fs::path& dir) {
  sidecarWith(dir, [](RenderRecipe& r) { r.params.sampling.ert = 5; });
}
void sidecarMissingDataset(const fs::path& dir) {
  sidecarWith(dir, [&](RenderRecipe& r) { r.dataset = (dir / "gone.mha").string(); });
}

// --- Outputs that cannot be written. ---

void sidecarIsAFolder(const fs::path& dir) {
  fs::remove(dir / "out.png.json");
  fs::create_directories(dir / "out.png.json");
}

// --- Headless scripts too long to finish. ---

void longScript(const fs::path& dir) {
  std::ofstream out(dir / "s.json");
  out << "[";
  for (int n = 0; n < 20000; ++n) out << (n ? "," : "") << R"({"move": [10, 10]})";
  out << "]";
}

// A tiny label volume on another grid than the aorta's.
void labelsOnAnotherGrid(const fs::path& dir) {
  writeVolume(makeVolume({4, 4, 4}, {1, 1, 1}, Voxel(0)), dir / "labels.nrrd");
}

#define NRRD_WITH(fields) \
  "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\n" fields "encoding: ascii\n\n1 2 3 4 5 6 7 8\n"
#define MHD_WITH(fields)                                    \
  "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n" fields \
  "ElementType = MET_UCHAR\nElementDataFile = LOCAL\nabcdefgh"
#define RENDER(file) "render {dir}/" file " --out {dir}/out.png"
#define VG(file) \
  "render {aorta} --out {dir}/out.png --vg-focus circle:radius=3 --centerlines {dir}/" file
#define TF_FILE(text) "{\"name\": \"t\", \"points\": " text "}"

const BadInput kFiles[] = {
    // NRRD headers.
    {RENDER("v.nrrd"), "v.nrrd", "unknown voxel spacing", "v.nrrd",
     NRRD_WITH("spacings: nan nan nan\n")},
    {RENDER("v.nrrd"), "v.nrrd", "zero, negative", "v.nrrd", NRRD_WITH("spacings: 0 1 1\n")},
    {RENDER("v.nrrd"), "v.nrrd", "zero, negative", "v.nrrd", NRRD_WITH("spacings: 1 -1 1\n")},
    {RENDER("v.nrrd"), "v.nrrd", "space directions", "v.nrrd",
     NRRD_WITH("space: left-posterior-superior\nspace directions: (nan,0,0) (0,1,0) (0,0,1)\n")},
    {RENDER("v.nrrd"), "v.nrrd", "zero-length axis", "v.nrrd",
     NRRD_WITH("space: left-posterior-superior\nspace directions: (0,0,0) (0,1,0) (0,0,1)\n")},
    {RENDER("v.nrrd"), "v.nrrd", "does not span", "v.nrrd",
     NRRD_WITH("space: left-posterior-superior\nspace directions: (1,0,0) (2,0,0) (0,0,1)\n")},
    {RENDER("v.nrrd"), "v.nrrd", "space origin", "v.nrrd",
     NRRD_WITH(
         "space: left-posterior-superior\nspace directions: (1,0,0) (0,1,0) (0,0,1)\nspace origin: "
         "(0,inf,0)\n")},
    {RENDER("v.nrrd"), "v.nrrd", "GB of memory", "v.nrrd",
     "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n\nabcd"},
    {RENDER("v.nrrd"), "v.nrrd", "2-D", "v.nrrd",
     "NRRD0004\ntype: uchar\ndimension: 2\nsizes: 2 2\nencoding: ascii\n\n1 2 3 4\n"},
    {RENDER("v.nrrd"), "v.nrrd", "cannot be read", "v.nrrd",
     "NRRD0004\ntype: quaternion\ndimension: 3\nsizes: 2 2 2\nencoding: ascii\n\n1 2 3 4 5 6 7 8\n"},
    {RENDER("v.nrrd"), "v.nrrd", "as text cannot hold the 8 values", "v.nrrd",
     "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: ascii\n\n1 2 3\n"},
    {RENDER("v.nrrd"), "v.nrrd", "not a valid NRRD", "v.nrrd", ""},
    {RENDER("v.nrrd"), "v.nrrd", "not a valid NRRD", "v.nrrd", "hello, world\n"},
    {RENDER("v.nhdr"), "v.nhdr", "cannot be read", "v.nhdr",
     "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\ndata file: missing.raw\n"},
    // MetaImage headers.
    {RENDER("v.mha"), "v.mha", "ElementSpacing", "v.mha", MHD_WITH("ElementSpacing = nan 1 1\n")},
    {RENDER("v.mha"), "v.mha", "ElementSpacing", "v.mha", MHD_WITH("ElementSpacing = 0 1 1\n")},
    {RENDER("v.mha"), "v.mha", "Offset", "v.mha", MHD_WITH("Offset = 0 nan 0\n")},
    {RENDER("v.mha"), "v.mha", "does not span", "v.mha",
     MHD_WITH("TransformMatrix = 0 0 0 0 1 0 0 0 1\n")},
    {RENDER("v.mha"), "v.mha", "TransformMatrix", "v.mha",
     MHD_WITH("TransformMatrix = 1 0 0 0 1 0 0 0 inf\n")},
    {RENDER("v.mha"), "v.mha", "NDims", "v.mha",
     "ObjectType = Image\nNDims = 300000000\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile "
     "= "
     "LOCAL\nabcdefgh"},
    {RENDER("v.mha"), "v.mha", "DimSize", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 -2 2\nElementType = MET_UCHAR\nElementDataFile = "
     "LOCAL\nabcdefgh"},
    {RENDER("v.mha"), "v.mha", "DimSize", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2\nElementType = MET_UCHAR\nElementDataFile = "
     "LOCAL\nabcd"},
    {RENDER("v.mha"), "v.mha", "truncated", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2000000 2000000 2000000\nElementType = "
     "MET_UCHAR\nElementDataFile = LOCAL\nabcdefgh"},
    {RENDER("v.mha"), "v.mha", "truncated", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = MET_UCHAR\nElementDataFile = "
     "LOCAL\nabcd"},
    {RENDER("v.mhd"), "v.mhd", "list of files", "v.mhd",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
     "ElementType = MET_UCHAR\nElementDataFile = LIST\n"},
    {RENDER("v.mhd"), "v.mhd", "list of files", "v.mhd",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = "
     "d%03d.raw 0 "
     "2000000000 1\n"},
    {RENDER("v.mhd"), "v.mhd", "its data file 'missing.raw' cannot be read: No such file", "v.mhd",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = "
     "missing.raw\n"},
    {RENDER("v.mha"), "v.mha", "unknown type", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_FROBNICATE\nElementDataFile = "
     "LOCAL\nabcdefgh"},
    {RENDER("v.mha"), "v.mha", "component", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementNumberOfChannels = 3\nElementType = "
     "MET_UCHAR\nElementDataFile = LOCAL\nabcdefghabcdefghabcdefgh"},
    {RENDER("v.mha"), "v.mha", "cannot be read", "v.mha",
     "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nCompressedData = True\nCompressedDataSize = 8\n"
     "ElementType = MET_UCHAR\nElementDataFile = LOCAL\nabcdefgh"},
    // NIfTI headers.
    {RENDER("v.nii"), "v.nii", "pixdim", nullptr, nullptr, niftiNanSpacing},
    {RENDER("v.nii"), "v.nii", "pixdim", nullptr, nullptr, niftiZeroSpacing},
    {RENDER("v.nii"), "v.nii", "qform", nullptr, nullptr, niftiNanQform},
    {RENDER("v.nii"), "v.nii", "sform", nullptr, nullptr, niftiNanSform},
    {RENDER("v.nii"), "v.nii", "truncated", nullptr, nullptr, niftiTruncated},
    {RENDER("v.nii"), "v.nii", "2-D", nullptr, nullptr, niftiTwoDimensional},
    {RENDER("v.nii"), "v.nii", "truncated", nullptr, nullptr, niftiHugeDims},
    {RENDER("v.nii"), "v.nii", "not a valid NIfTI", "v.nii", "hello, world, this is not a NIfTI file\n"},
    {RENDER("v.nii.gz"), "v.nii.gz", "not a valid NIfTI", "v.nii.gz", "not gzip either\n"},
    // DICOM series.
    {RENDER("ct"), "IM2-4.dcm", "3 samples per pixel", nullptr, nullptr, dicomShort<0x0028, 0x0002, 3>},
    {RENDER("ct"), "IM2-4.dcm", "bytes of pixel data", nullptr, nullptr, dicomEightBits},
    {RENDER("ct"), "IM2-4.dcm", "65535 x 16", nullptr, nullptr, dicomShort<0x0028, 0x0010, 65535>},
    {RENDER("ct"), "IM2-4.dcm", "16 x 65535", nullptr, nullptr, dicomShort<0x0028, 0x0011, 65535>},
    {RENDER("ct"), "IM2-4.dcm", "BitsAllocated", nullptr, nullptr, dicomShort<0x0028, 0x0100, 7>},
    {RENDER("ct"), "IM2-4.dcm", "do not fit", nullptr, nullptr, dicomShort<0x0028, 0x0101, 40>},
    {RENDER("ct"), "IM2-4.dcm", "PixelRepresentation", nullptr, nullptr, dicomShort<0x0028, 0x0103, 9>},
    {RENDER("ct"), "IM2-4.dcm", "PixelSpacing", nullptr, nullptr, dicomSpacingZero},
    {RENDER("ct"), "IM2-4.dcm", "PixelSpacing", nullptr, nullptr, dicomSpacingNegative},
    {RENDER("ct"), "IM2-4.dcm", "PixelSpacing", nullptr, nullptr, dicomSpacingNan},
    {RENDER("ct"), "IM2-4.dcm", "ImageOrientationPatient", nullptr, nullptr, dicomOrientationZero},
    {RENDER("ct"), "IM2-4.dcm", "ImagePositionPatient", nullptr, nullptr, dicomPositionNan},
    {RENDER("ct"), "IM2-4.dcm", "RescaleSlope", nullptr, nullptr, dicomSlopeNan},
    {RENDER("ct"), "IM2-4.dcm", "RescaleSlope", nullptr, nullptr, dicomSlopeZero},
    {RENDER("ct"), "IM2-4.dcm", "claims 512 bytes", nullptr, nullptr, dicomTruncated},
    {RENDER("ct"), "ct", "gantry tilt", nullptr, nullptr, dicomTilted},
    {RENDER("ct"), "IM2-4.dcm", "compressed pixel data cannot be decoded", nullptr, nullptr,
     dicomJpegDecoderAborts},
    {RENDER("ct"), "IM2-4.dcm", "claims", nullptr, nullptr, dicomRleCutShort},
    {RENDER("ct"), "ct", "gap in slice positions", nullptr, nullptr, dicomMissingSlice},
    {RENDER("ct"), "ct", "no DICOM", nullptr, nullptr, emptyFolder},
    {RENDER("ct"), "ct", "no DICOM", nullptr, nullptr, folderOfText},
    // Centerline CSV.
    {VG("c.csv"), "c.csv", "single point", "c.csv",
     "path,x_mm,y_mm,z_mm,radius_mm\n0,-218,-316,24,10\n"},
    {VG("c.csv"), "c.csv", "not finite", "c.csv",
     "path,x_mm,y_mm,z_mm,radius_mm\n0,-218,-316,24,10\n0,nan,-316,25,10\n"},
    {VG("c.csv"), "c.csv", "fields", "c.csv", "path,x_mm,y_mm,z_mm,radius_mm\n0,-218,-316\n"},
    {VG("c.csv"), "c.csv", "header", "c.csv", "hello\n"},
    {VG("c.csv"), "c.csv", "empty", "c.csv", ""},
    {VG("c.csv"), "c.csv", "1e999", "c.csv",
     "path,x_mm,y_mm,z_mm,radius_mm\n0,1e999,0,0,1\n0,1,0,0,1\n"},
    // Centerline .vtp.
    {VG("c.vtp"), "c.vtp", "XML", "c.vtp", "<VTKFile type=\"PolyData\"><PolyData>"},
    {VG("c.vtp"), "c.vtp", "more than the file's", "c.vtp",
     R"(<?xml version="1.0"?><VTKFile type="PolyData" version="0.1" byte_order="LittleEndian"><PolyData><Piece NumberOfPoints="1099511627776" NumberOfLines="1"><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 1 1</DataArray></Points><Lines><DataArray type="Int64" Name="connectivity" format="ascii">0 1</DataArray><DataArray type="Int64" Name="offsets" format="ascii">2</DataArray></Lines></Piece></PolyData></VTKFile>)"},
    {VG("c.vtp"), "c.vtp", "connectivity entries", "c.vtp",
     R"(<?xml version="1.0"?><VTKFile type="PolyData" version="0.1" byte_order="LittleEndian"><PolyData><Piece NumberOfPoints="2" NumberOfLines="1"><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 1 1</DataArray></Points><Lines><DataArray type="Int64" Name="connectivity" format="ascii">0 1</DataArray><DataArray type="Int64" Name="offsets" format="ascii">200000000</DataArray></Lines></Piece></PolyData></VTKFile>)"},
    {VG("c.vtp"), "c.vtp", "single point", "c.vtp",
     R"(<?xml version="1.0"?><VTKFile type="PolyData" version="0.1" byte_order="LittleEndian"><PolyData><Piece NumberOfPoints="1" NumberOfLines="1"><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">-218 -316 24</DataArray></Points><Lines><DataArray type="Int64" Name="connectivity" format="ascii">0</DataArray><DataArray type="Int64" Name="offsets" format="ascii">1</DataArray></Lines></Piece></PolyData></VTKFile>)"},
    {VG("c.vtp"), "c.vtp", "XML", "c.vtp", "not xml at all"},
    // Slicer markups.
    {VG("c.mrk.json"), "c.mrk.json", "single point", "c.mrk.json",
     R"({"markups": [{"type": "Curve", "coordinateSystem": "LPS", "controlPoints": [{"position": [-218, -316, 24]}]}]})"},
    {VG("c.mrk.json"), "c.mrk.json", "JSON", "c.mrk.json", "{\"markups\": ["},
    {VG("c.mrk.json"), "c.mrk.json", "position", "c.mrk.json",
     R"({"markups": [{"type": "Curve", "coordinateSystem": "LPS", "controlPoints": [{"position": [1, 2]}, {"position": [1, 2, 3]}]}]})"},
    {VG("c.mrk.json"), "c.mrk.json", "1e999", "c.mrk.json",
     R"({"markups": [{"type": "Curve", "coordinateSystem": "LPS", "controlPoints": [{"position": [1e999, 2, 3]}, {"position": [1, 2, 3]}]}]})"},
    {VG("c.mrk.json"), "c.mrk.json", "markups", "c.mrk.json", R"({"markups": "none"})"},
    {VG("deep.mrk.json"), "deep.mrk.json", "nested", "deep.mrk.json",
     R"({"markups": [{"type": "Curve", "controlPoints": [{"position": {deep}}]}]})"},
    // Transfer functions.
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "JSON", "t.json", "{\"name\": "},
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "points", "t.json",
     TF_FILE("[]")},
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "opacity", "t.json",
     TF_FILE(
         R"([{"hu": 0, "color": [1, 1, 1], "opacity": 2}, {"hu": 100, "color": [1, 1, 1], "opacity": 1}])")},
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "1e999", "t.json",
     TF_FILE(
         R"([{"hu": 1e999, "color": [1, 1, 1], "opacity": 0}, {"hu": 100, "color": [1, 1, 1], "opacity": 1}])")},
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "color", "t.json",
     TF_FILE(
         R"([{"hu": 0, "color": [1, 1], "opacity": 0}, {"hu": 100, "color": [1, 1, 1], "opacity": 1}])")},
    {"render {aorta} --out {dir}/out.png --tf {dir}/t.json", "t.json", "hu", "t.json",
     TF_FILE(
         R"([{"hu": "zero", "color": [1, 1, 1], "opacity": 0}, {"hu": 100, "color": [1, 1, 1], "opacity": 1}])")},
    {"render {aorta} --out {dir}/out.png --tf {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"({"name": "t", "points": [{"hu": {deep}, "color": [0, 0, 0], "opacity": 0}]})"},
    // Render sidecars (--params).
    {"render --params {dir}/bad.json --out {dir}/out.png", "bad.json", "osd", nullptr, nullptr,
     sidecarTinyOsd},
    {"render --params {dir}/bad.json --out {dir}/out.png", "bad.json", "isd", nullptr, nullptr,
     sidecarTinyIsd},
    {"render --params {dir}/bad.json --out {dir}/out.png", "bad.json", "ert", nullptr, nullptr,
     sidecarErtFive},
    {"render --params {dir}/bad.json --out {dir}/out.png", "gone.mha", "does not exist", nullptr,
     nullptr, sidecarMissingDataset},
    {"render --params {dir}/bad.json --out {dir}/out.png", "bad.json", "sidecar", "bad.json",
     R"({"hello": 1})"},
    {"render --params {dir}/bad.json --out {dir}/out.png", "bad.json", "JSON", "bad.json",
     R"({"angioray_render)"},
    {"render --params {dir}/deep.json --out {dir}/out.png", "deep.json", "nested", "deep.json",
     R"({"angioray_render_sidecar": 1, "view": {"axis": {deep}}})"},
    // Sessions.
    {"gui {aorta} --headless --timeout 5 --session {dir}/s.json", "s.json", "JSON", "s.json",
     "{\"view\": "},
    {"gui {aorta} --headless --timeout 5 --session {dir}/s.json", "s.json", "zoom", "s.json",
     R"({"angioray_session": 1, "view": {"zoom": "close"}})"},
    {"gui --headless --timeout 5 --session {dir}/s.json", "gone.mha", "does not exist", "s.json",
     R"({"angioray_session": 1, "dataset": "/nowhere/gone.mha"})"},
    {"gui {aorta} --headless --timeout 5 --session {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"({"view": {"zoom": {deep}}})"},
    // Headless scripts.
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "at most 5000", nullptr,
     nullptr, longScript},
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "unknown action", "s.json",
     R"([{"dance": 1}])"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "wait_ms", "s.json",
     R"([{"wait_ms": 1e12}])"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "drag steps", "s.json",
     R"([{"drag": {"from": [1, 1], "to": [5, 5], "steps": 1000000000}}])"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "list of steps", "s.json",
     R"({"click": [1, 1]})"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/s.json", "s.json", "1e999", "s.json",
     R"([{"click": [1e999, 1]}])"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"([{"click": {deep}}])"},
    // Label volumes.
    {"render {aorta} --out {dir}/out.png --labels {dir}/labels.nrrd", "labels.nrrd", "grid", nullptr,
     nullptr, labelsOnAnotherGrid},
    {"render {aorta} --out {dir}/out.png --labels {dir}/labels.nrrd", "labels.nrrd", "not a valid",
     "labels.nrrd", "garbage"},
    // Outputs that cannot be written: nothing of them may appear or change.
    {"render {aorta} --out {dir}/out.png", "out.png.json", "folder", nullptr, nullptr, sidecarIsAFolder},
    {"render {aorta} --out /proc/out.png", "/proc", "cannot write"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/missing/out.png", "out.png", "folder does not exist"},
    {"phantom /proc/p.mha --size 32x32x32", "/proc", "cannot write"},
    {"trace {aorta} --points '-218,-316,24;-218,-315,25' --out /proc/t.csv", "/proc/t.csv",
     "cannot open for writing"},
    {"segment {aorta} --out {dir}/missing/l.nrrd", "l.nrrd", "folder does not exist"},
};

#undef NRRD_WITH
#undef MHD_WITH
#undef RENDER
#undef VG
#undef TF_FILE

class BadFiles : public test_support::BadInputCatalogue {};

TEST_P(BadFiles, EndWithOneLineNamingTheFileAndLeaveTheFilesAlone) { expectCleanRefusal(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Files, BadFiles, ::testing::ValuesIn(kFiles), test_support::caseName);

}  // namespace
}  // namespace angio
