// Writes the fuzz targets' seed corpora with our own writers: OUT_DIR/<target>/<seed>.
// Usage: write_fuzz_seeds OUT_DIR
// The seeds are valid files of each format (TF presets, centerlines in every format and, for .vtp,
// every encoding the reader knows, sidecars, sessions, small volumes, a DICOM series), so the
// fuzzer starts from inputs that reach deep into the readers. Hand-made seeds of formats without a
// writer of ours (headless scripts) are checked in under tests/fuzz/seeds/.
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/volume.h"
#include "gui/document.h"
#include "gui/session_file.h"
#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
#include "io/tf_file.h"
#include "io/volume_writer.h"
#include "render/recipe_json.h"
#include "tests/fuzz/reader_inputs.h"
#include "tests/support/dicom_recompress.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/file_bytes.h"

namespace fs = std::filesystem;
using namespace angio;
using test_support::fileBytes;

namespace {

class SeedWriter {
 public:
  explicit SeedWriter(fs::path root) : root_(std::move(root)) {}

  void seed(const std::string& target, const std::string& name, const std::string& bytes) const {
    fs::create_directories(root_ / target);
    std::ofstream(root_ / target / name, std::ios::binary) << bytes;
  }
  // A scratch file for a writer that takes a path.
  fs::path scratch(const std::string& name) const {
    fs::create_directories(root_ / ".scratch");
    return root_ / ".scratch" / name;
  }
  void removeScratch() const { fs::remove_all(root_ / ".scratch"); }

 private:
  fs::path root_;
};

Centerlines sampleCenterlines() {
  Centerlines centerlines;
  centerlines.source = "seed";
  CenterlinePath aorta{"aorta", {}};
  for (int n = 0; n < 6; ++n) aorta.points.push_back({{-12.5 + n, 30.25, 100.0 - 7.5 * n}, 10.0 - n});
  CenterlinePath iliac{"left iliac, \"common\"", {}};
  for (int n = 0; n < 4; ++n) iliac.points.push_back({{-8.0 + 4 * n, 31.0, 62.5 - 10 * n}, 0.0});
  CenterlinePath unnamed{"", {{{1e-3, -2e5, 3.5}, 1.5}, {{2.0, 2.0, 2.0}, 1.25}}};
  centerlines.paths = {aorta, iliac, unnamed};
  return centerlines;
}

// --- .vtp in the binary encodings (our writer writes ascii only) -------------------------------

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t n = 0; n < bytes.size(); n += 3) {
    std::uint32_t bits = std::uint32_t(static_cast<unsigned char>(bytes[n])) << 16;
    if (n + 1 < bytes.size()) bits |= std::uint32_t(static_cast<unsigned char>(bytes[n + 1])) << 8;
    if (n + 2 < bytes.size()) bits |= std::uint32_t(static_cast<unsigned char>(bytes[n + 2]));
    text += kDigits[bits >> 18 & 63];
    text += kDigits[bits >> 12 & 63];
    text += n + 1 < bytes.size() ? kDigits[bits >> 6 & 63] : '=';
    text += n + 2 < bytes.size() ? kDigits[bits & 63] : '=';
  }
  return text;
}

template <class T>
std::string wordsOf(const std::vector<T>& values) {
  std::string bytes(values.size() * sizeof(T), '\0');
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

template <class Header>
std::string headerWords(const std::vector<Header>& words) {
  return wordsOf(words);
}

enum class VtpEncoding { binary, zlib, appendedRaw, appendedBase64 };

struct VtpArrays {
  std::string points, radii, connectivity, offsets;  // raw little-endian words
  std::size_t pointCount = 0, cells = 0;
};

VtpArrays vtpArrays(const Centerlines& centerlines) {
  std::vector<float> points;
  std::vector<double> radii;
  std::vector<std::int64_t> connectivity, offsets;
  for (const CenterlinePath& path : centerlines.paths) {
    for (const CenterlinePoint& point : path.points) {
      points.insert(points.end(),
                    {float(point.positionMm.x), float(point.positionMm.y), float(point.positionMm.z)});
      radii.push_back(point.radiusMm);
      connectivity.push_back(std::int64_t(radii.size() - 1));
    }
    offsets.push_back(std::int64_t(connectivity.size()));
  }
  return {wordsOf(points),  wordsOf(radii), wordsOf(connectivity),
          wordsOf(offsets), radii.size(),   centerlines.paths.size()};
}

// One array's encoded bytes: the header (byte count, or zlib's block table) and the data.
std::string encodedArray(const std::string& raw, VtpEncoding encoding) {
  if (encoding != VtpEncoding::zlib) {
    return base64(headerWords<std::uint32_t>({std::uint32_t(raw.size())}) + raw);
  }
  uLongf compressedBytes = compressBound(uLong(raw.size()));
  std::string compressed(compressedBytes, '\0');
  compress(reinterpret_cast<Bytef*>(compressed.data()), &compressedBytes,
           reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
  compressed.resize(compressedBytes);
  const std::uint64_t size = raw.size();
  return base64(headerWords<std::uint64_t>({1, size, size, compressedBytes})) + base64(compressed);
}

std::string vtpText(const Centerlines& centerlines, VtpEncoding encoding) {
  const VtpArrays arrays = vtpArrays(centerlines);
  const bool appended = encoding == VtpEncoding::appendedRaw || encoding == VtpEncoding::appendedBase64;
  std::string appendedBytes;
  const auto array = [&](const std::string& attributes, const std::string& raw) {
    if (!appended) {
      return "<DataArray " + attributes + " format=\"binary\">" + encodedArray(raw, encoding) +
             "</DataArray>\n";
    }
    const std::string offset = std::to_string(appendedBytes.size());
    const std::string header = headerWords<std::uint32_t>({std::uint32_t(raw.size())});
    appendedBytes += encoding == VtpEncoding::appendedRaw ? header + raw : base64(header + raw);
    return "<DataArray " + attributes + " format=\"appended\" offset=\"" + offset + "\"/>\n";
  };
  std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
      "byte_order=\"LittleEndian\"";
  xml += encoding == VtpEncoding::zlib
             ? " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
             : " header_type=\"UInt32\">\n";
  xml += "<PolyData>\n<Piece NumberOfPoints=\"" + std::to_string(arrays.pointCount) +
         "\" NumberOfLines=\"" + std::to_string(arrays.cells) + "\">\n<PointData>\n";
  xml += array("type=\"Float64\" Name=\"MaximumInscribedSphereRadius\"", arrays.radii);
  xml += "</PointData>\n<Points>\n";
  xml += array("type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"", arrays.points);
  xml += "</Points>\n<Lines>\n";
  xml += array("type=\"Int64\" Name=\"connectivity\"", arrays.connectivity);
  xml += array("type=\"Int64\" Name=\"offsets\"", arrays.offsets);
  xml += "</Lines>\n</Piece>\n</PolyData>\n";
  if (appended) {
    xml += std::string("<AppendedData encoding=\"") +
           (encoding == VtpEncoding::appendedRaw ? "raw" : "base64") + "\">\n_" + appendedBytes +
           "\n</AppendedData>\n";
  }
  return xml + "</VTKFile>\n";
}

// --- Seeds per target ---------------------------------------------------------------------------

void writeTfSeeds(const SeedWriter& out) {
  for (const Preset& preset : listPresets()) {
    out.seed("tf", preset.id + ".json", toJson(loadTransferFunction(preset.file)));
  }
}

void writeCenterlineSeeds(const SeedWriter& out) {
  const Centerlines centerlines = sampleCenterlines();
  Centerlines one = centerlines;
  one.paths.resize(1);
  for (const auto& [name, model] : {std::pair{"three-paths", centerlines}, std::pair{"one-path", one}}) {
    writeCenterlinesCsv(model, out.scratch("seed.csv"));
    out.seed("centerline_csv", std::string(name) + ".csv", fileBytes(out.scratch("seed.csv")));
    writeCenterlinesVtp(model, out.scratch("seed.vtp"));
    out.seed("centerline_vtp", std::string(name) + ".vtp", fileBytes(out.scratch("seed.vtp")));
    writeCenterlinesMarkups(model, out.scratch("seed.mrk.json"));
    out.seed("centerline_markups", std::string(name) + ".mrk.json",
             fileBytes(out.scratch("seed.mrk.json")));
  }
  out.seed("centerline_vtp", "binary.vtp", vtpText(centerlines, VtpEncoding::binary));
  out.seed("centerline_vtp", "zlib.vtp", vtpText(centerlines, VtpEncoding::zlib));
  out.seed("centerline_vtp", "appended-raw.vtp", vtpText(centerlines, VtpEncoding::appendedRaw));
  out.seed("centerline_vtp", "appended-base64.vtp", vtpText(centerlines, VtpEncoding::appendedBase64));
}

void writeSidecarAndSessionSeeds(const SeedWriter& out) {
  const TransferFunction tf = loadPresetOrFile("cta-vessels");
  RenderRecipe plain;
  plain.image = "aorta.png";
  plain.dataset = "/data/aorta.mha";
  plain.tf = tf;
  out.seed("render_sidecar", "plain.png.json", renderSidecarJson(plain));
  RenderRecipe glyph = plain;
  glyph.quality = Quality::high;
  glyph.vesselGlyph.emplace();
  glyph.vesselGlyph->centerlines = "/data/aorta.vtp";
  glyph.vesselGlyph->focusTf = tf;
  glyph.vesselGlyph->contextTf = tf;
  glyph.vesselGlyph->outsideTf = tf;
  glyph.hybrid.emplace();
  out.seed("render_sidecar", "vessel-glyph.png.json", renderSidecarJson(glyph));

  Document session;
  session.dataset = "/data/aorta.mha";
  session.tf = tf;
  session.recentFiles = {"/data/aorta.mha", "/data/legs"};
  out.seed("session", "session.json", toJson(session));
  out.seed("session", "default.json", toJson(Document{}));
}

Volume sampleVolume() {
  Volume volume = makeVolume({6, 5, 4}, {0.7, 0.8, 2.5});
  volume.origin = {-12.0, 30.5, 5.0};
  for (std::size_t n = 0; n < volume.voxels.size(); ++n)
    volume.voxels[n] = encodeVoxel(int(n * 37 % 2000) - 1000);
  return volume;
}

void writeVolumeSeeds(const SeedWriter& out) {
  const Volume volume = sampleVolume();
  for (const auto& [target, extension] :
       {std::pair{"volume_mha", ".mha"}, std::pair{"volume_nrrd", ".nrrd"},
        std::pair{"volume_nii", ".nii"}}) {
    writeVolume(volume, out.scratch(std::string("seed") + extension));
    const std::string bytes = fileBytes(out.scratch(std::string("seed") + extension));
    out.seed(target, std::string("small") + extension, bytes);
    if (std::string(extension) == ".mha") out.seed("metaimage_header", "small.mha", bytes);
    if (std::string(extension) == ".nii") out.seed("nifti_header", "small.nii", bytes);
  }
  // A detached header naming the voxel file every volume_mhd input comes with (8x8x4 int16).
  const std::string mhd =
      "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
      "CompressedData = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = -12 30.5 5\n"
      "ElementSpacing = 0.7 0.7 2.5\nDimSize = 8 8 4\nElementType = MET_SHORT\n"
      "ElementDataFile = input.raw\n";
  static_assert(fuzz::kMhdRawBytes == 8 * 8 * 4 * 2);
  out.seed("volume_mhd", "small.mhd", mhd);
  out.seed("metaimage_header", "small.mhd", mhd);
}

void writeDicomSeeds(const SeedWriter& out) {
  const fs::path folder = out.scratch("dicom");
  fs::create_directories(folder);
  test_support::writeDicomSeries(folder, {0, 1, 2}, "1.2.826.0.1.3680043.2.1125.777.1", 7,
                                 {{"0010|0010", "Seed^Patient"}, {"0008|0020", "20240131"}});
  std::vector<fs::path> slices;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) slices.push_back(entry.path());
  std::sort(slices.begin(), slices.end());
  const auto seriesOf = [](const std::vector<fs::path>& files) {
    std::string series;
    for (const fs::path& file : files) {
      if (!series.empty()) series += fuzz::kSliceSeparator;
      series += fileBytes(file);
    }
    return series;
  };
  for (const fs::path& slice : slices)
    out.seed("dicom_slice", slice.filename().string(), fileBytes(slice));
  out.seed("dicom_series", "three-slices", seriesOf(slices));
  // Encapsulated pixel data: the walk's fragments and, in a series, GDCM's decoders (in the
  // decoder process, io/slices_in_child.h) get fuzzed too.
  for (const auto& [name, syntax] :
       {std::pair{"jpeg-lossless", gdcm::TransferSyntax::JPEGLosslessProcess14_1},
        std::pair{"jpeg-ls", gdcm::TransferSyntax::JPEGLSLossless},
        std::pair{"jpeg-2000", gdcm::TransferSyntax::JPEG2000Lossless},
        std::pair{"rle", gdcm::TransferSyntax::RLELossless}}) {
    std::vector<fs::path> compressed;
    for (const fs::path& slice : slices) {
      compressed.push_back(folder / (std::string(name) + "-" + slice.filename().string()));
      fs::copy_file(slice, compressed.back());
      test_support::recompressDicomSlice(compressed.back(), syntax);
    }
    out.seed("dicom_slice", std::string(name) + ".dcm", fileBytes(compressed.front()));
    out.seed("dicom_series", std::string("three-slices-") + name, seriesOf(compressed));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_fuzz_seeds OUT_DIR\n");
    return 2;
  }
  try {
    const SeedWriter out(argv[1]);
    writeTfSeeds(out);
    writeCenterlineSeeds(out);
    writeSidecarAndSessionSeeds(out);
    writeVolumeSeeds(out);
    writeDicomSeeds(out);
    out.removeScratch();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "write_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
