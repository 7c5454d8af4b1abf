// Centerline loaders: VTK XML PolyData (.vtp) in every encoding VTK writes, Slicer markups curves,
// CSV, the choice by extension, every kind of broken file, and the shared aorta data (the .vtp and
// .csv give the same model, which lies in the aorta's lumen).
#include "io/centerline_file.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/voxel.h"
#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
#include "io/input_error.h"
#include "io/volume_reader.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

// --- A VTK XML PolyData writer for fixtures -----------------------------------------------------
// Written from the file format (header words, zlib blocks, base64 streams, appended offsets) so
// that each encoding variant can be produced; the shared aorta file, written by VTK 9.1 itself,
// checks the reader against the real thing.

struct VtpStyle {
  std::string name;               // for test output
  std::string format = "binary";  // ascii | binary | appended
  bool base64Appended = false;    // appended data as base64 instead of raw bytes
  bool zlib = false;
  bool uint64Header = false;
  bool bigEndian = false;
  std::size_t blockBytes = 32768;  // uncompressed zlib block size (VTK's default)
  std::string pointType = "Float32";
  std::string indexType = "Int64";
  std::string radiusName = "MaximumInscribedSphereRadius";  // "" = no radius array
};

void PrintTo(const VtpStyle& style, std::ostream* out) { *out << style.name; }

struct Array {
  std::string name;
  std::string type;
  int components = 1;
  std::vector<double> values;
};

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t n = 0; n < bytes.size(); n += 3) {
    const std::size_t count = std::min<std::size_t>(3, bytes.size() - n);
    std::uint32_t bits = 0;
    for (std::size_t b = 0; b < 3; ++b) {
      bits = bits << 8 | (b < count ? static_cast<unsigned char>(bytes[n + b]) : 0);
    }
    for (std::size_t c = 0; c < 4; ++c) {
      out += c <= count ? digits[bits >> (18 - 6 * c) & 63] : '=';
    }
  }
  return out;
}

template <class T>
std::string wordBytes(T value, bool bigEndian) {
  std::string bytes(sizeof value, '\0');
  std::memcpy(bytes.data(), &value, sizeof value);
  if (bigEndian) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

std::string valueBytes(const Array& array, bool bigEndian) {
  std::string bytes;
  for (double v : array.values) {
    if (array.type == "Float32") bytes += wordBytes(float(v), bigEndian);
    if (array.type == "Float64") bytes += wordBytes(v, bigEndian);
    if (array.type == "Int32") bytes += wordBytes(std::int32_t(v), bigEndian);
    if (array.type == "Int64") bytes += wordBytes(std::int64_t(v), bigEndian);
    if (array.type == "UInt8") bytes += wordBytes(std::uint8_t(v), bigEndian);
  }
  return bytes;
}

std::string headerWord(std::uint64_t value, const VtpStyle& style) {
  return style.uint64Header ? wordBytes(value, style.bigEndian)
                            : wordBytes(std::uint32_t(value), style.bigEndian);
}

// The encoded streams of one array: [header + data] uncompressed; [header, blocks] with zlib.
std::vector<std::string> binaryStreams(const std::string& data, const VtpStyle& style) {
  if (!style.zlib) return {headerWord(data.size(), style) + data};
  const std::size_t blocks = (data.size() + style.blockBytes - 1) / style.blockBytes;
  std::string header = headerWord(blocks, style) + headerWord(style.blockBytes, style) +
                       headerWord(data.size() % style.blockBytes, style);
  std::string compressed;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::string block = data.substr(b * style.blockBytes, style.blockBytes);
    uLongf size = compressBound(uLong(block.size()));
    std::string out(size, '\0');
    EXPECT_EQ(compress(reinterpret_cast<Bytef*>(out.data()), &size,
                       reinterpret_cast<const Bytef*>(block.data()), uLong(block.size())),
              Z_OK);
    out.resize(size);
    header += headerWord(size, style);
    compressed += out;
  }
  return {header, compressed};
}

std::string asciiText(const Array& array) {
  std::string text;
  char number[40];
  for (double v : array.values) {
    std::snprintf(number, sizeof number, "%.17g ", v);
    text += number;
  }
  return text;
}

std::string encodedStreams(const std::vector<std::string>& streams, bool asBase64) {
  std::string out;
  for (const std::string& stream : streams) out += asBase64 ? base64(stream) : stream;
  return out;
}

// One <DataArray>, adding its bytes to `appended` when the style says so.
std::string dataArrayXml(const Array& array, const VtpStyle& style, std::string& appended) {
  std::string xml = "<DataArray type=\"" + array.type + "\" Name=\"" + array.name +
                    "\" NumberOfComponents=\"" + std::to_string(array.components) + "\" format=\"" +
                    style.format + "\"";
  if (style.format == "ascii") return xml + ">\n" + asciiText(array) + "\n</DataArray>\n";
  const std::vector<std::string> streams = binaryStreams(valueBytes(array, style.bigEndian), style);
  if (style.format == "binary") {
    return xml + ">\n          " + encodedStreams(streams, true) + "\n        </DataArray>\n";
  }
  xml += " offset=\"" + std::to_string(appended.size()) + "\"/>\n";
  appended += encodedStreams(streams, style.base64Appended);
  return xml;
}

struct Polylines {
  std::vector<glm::dvec3> points;
  std::vector<double> radii;
  std::vector<std::vector<std::size_t>> lines;  // point indices of each line cell
};

std::string writeVtp(const Polylines& data, const VtpStyle& style) {
  Array points{"Points", style.pointType, 3, {}};
  for (glm::dvec3 p : data.points) points.values.insert(points.values.end(), {p.x, p.y, p.z});
  Array connectivity{"connectivity", style.indexType, 1, {}}, offsets{"offsets", style.indexType, 1, {}};
  for (const auto& line : data.lines) {
    for (std::size_t index : line) connectivity.values.push_back(double(index));
    offsets.values.push_back(double(connectivity.values.size()));
  }
  std::string appended;
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"" +
                    std::string(style.bigEndian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
                    (style.uint64Header ? "UInt64" : "UInt32") + "\"" +
                    (style.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n";
  xml += "  <PolyData>\n    <Piece NumberOfPoints=\"" + std::to_string(data.points.size()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"" + std::to_string(data.lines.size()) +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n      <PointData>\n";
  if (!style.radiusName.empty()) {
    xml += dataArrayXml({"EdgeArray", "Float64", 1, std::vector<double>(data.points.size(), 7)}, style,
                        appended);
    xml += dataArrayXml({style.radiusName, "Float64", 1, data.radii}, style, appended);
  }
  xml += "      </PointData>\n      <CellData>\n      </CellData>\n      <Points>\n";
  xml += dataArrayXml(points, style, appended);
  xml += "      </Points>\n      <Lines>\n";
  xml += dataArrayXml(connectivity, style, appended);
  xml += dataArrayXml(offsets, style, appended);
  xml += "      </Lines>\n    </Piece>\n  </PolyData>\n";
  if (style.format == "appended") {
    xml += "  <AppendedData encoding=\"" + std::string(style.base64Appended ? "base64" : "raw") +
           "\">\n   _" + appended + "\n  </AppendedData>\n";
  }
  return xml + "</VTKFile>\n";
}

// Two paths sharing a trunk by point index, as a tree could be stored: trunk (points 0..29), then
// 50 points of each branch. Connectivity bytes include 0x00, '<' (60) and '>' (62), which raw
// appended data must survive.
Polylines branchingFixture() {
  Polylines data;
  for (int n = 0; n < 130; ++n) {
    const double angle = 0.05 * n;
    data.points.push_back({-150.25 + 10 * std::cos(angle), -80.5 + 0.75 * n, 12.125 + std::sin(angle)});
    data.radii.push_back(2.0 + 0.03125 * n);
  }
  std::vector<std::size_t> left, right;
  for (std::size_t n = 0; n < 30; ++n) left.push_back(n), right.push_back(n);
  for (std::size_t n = 30; n < 80; ++n) left.push_back(n);
  for (std::size_t n = 80; n < 130; ++n) right.push_back(n);
  data.lines = {left, right};
  return data;
}

// --- Helpers ------------------------------------------------------------------------------------

using CenterlineFiles = test_support::TempFolderTest;

// The InputError message of loading `file`, or "" if it loads.
std::string loadError(const fs::path& file) {
  try {
    loadCenterlines(file);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// Loads, collecting warnings.
Centerlines loadWarned(const fs::path& file, std::vector<std::string>& warnings) {
  CenterlineLoadOptions options;
  options.warn = [&](const std::string& warning) { warnings.push_back(warning); };
  return loadCenterlines(file, options);
}

void expectMatches(const Centerlines& loaded, const Polylines& data, double toleranceMm) {
  ASSERT_EQ(loaded.paths.size(), data.lines.size());
  for (std::size_t p = 0; p < data.lines.size(); ++p) {
    EXPECT_EQ(loaded.paths[p].name, std::to_string(p));
    ASSERT_EQ(loaded.paths[p].points.size(), data.lines[p].size());
    for (std::size_t n = 0; n < data.lines[p].size(); ++n) {
      const CenterlinePoint& point = loaded.paths[p].points[n];
      const std::size_t index = data.lines[p][n];
      EXPECT_NEAR(glm::distance(point.positionMm, data.points[index]), 0.0, toleranceMm)
          << "path " << p << " point " << n;
      EXPECT_EQ(point.radiusMm, data.radii[index]) << "path " << p << " point " << n;
    }
  }
}

// --- .vtp in every encoding ---------------------------------------------------------------------

class VtpEncodings : public CenterlineFiles, public ::testing::WithParamInterface<VtpStyle> {};

TEST_P(VtpEncodings, LoadEveryPathPointAndRadius) {
  const Polylines data = branchingFixture();
  const fs::path file = write("fixture.vtp", writeVtp(data, GetParam()));
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  EXPECT_EQ(loaded.source, file.string());
  EXPECT_EQ(loaded.frame, CenterlineFrame::physical);
  // Float32 points keep ~7 digits: ~1e-5 mm at 150 mm.
  expectMatches(loaded, data, GetParam().pointType == "Float32" ? 5e-5 : 1e-12);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(sharedPrefixLength(loaded.paths[0], loaded.paths[1]), 30u);
}

VtpStyle style(std::string name, std::string format) {
  VtpStyle s;
  s.name = std::move(name);
  s.format = std::move(format);
  return s;
}

// Every encoding tested: each of VTK's formats with the header words, zlib blocks, byte orders and
// value types it can write.
std::vector<VtpStyle> allStyles() {
  return {
      {.name = "Ascii", .format = "ascii"},
      {.name = "AsciiFloat64Int32", .format = "ascii", .pointType = "Float64", .indexType = "Int32"},
      {.name = "Binary", .format = "binary"},
      {.name = "BinaryUInt64Header", .format = "binary", .uint64Header = true},
      {.name = "BinaryZlib", .format = "binary", .zlib = true},
      // Points and radii fill whole blocks, connectivity does not.
      {.name = "BinaryZlibUInt64ManyBlocks",
       .format = "binary",
       .zlib = true,
       .uint64Header = true,
       .blockBytes = 520},
      {.name = "BinaryZlibBigEndian",
       .format = "binary",
       .zlib = true,
       .bigEndian = true,
       .blockBytes = 300},
      {.name = "BinaryFloat64Radius",
       .format = "binary",
       .pointType = "Float64",
       .radiusName = "Radius"},
      {.name = "AppendedRaw", .format = "appended"},
      {.name = "AppendedRawZlib", .format = "appended", .zlib = true, .blockBytes = 256},
      {.name = "AppendedRawBigEndianUInt64",
       .format = "appended",
       .uint64Header = true,
       .bigEndian = true},
      {.name = "AppendedBase64", .format = "appended", .base64Appended = true},
      {.name = "AppendedBase64ZlibUInt64",
       .format = "appended",
       .base64Appended = true,
       .zlib = true,
       .uint64Header = true,
       .blockBytes = 1000},
  };
}

INSTANTIATE_TEST_SUITE_P(CenterlineVtp, VtpEncodings, ::testing::ValuesIn(allStyles()),
                         [](const auto& info) { return info.param.name; });

using CenterlineVtp = CenterlineFiles;

TEST_F(CenterlineVtp, WithoutARadiusArrayRadiiAreZeroWithAWarningPerPath) {
  VtpStyle noRadius = style("", "binary");
  noRadius.radiusName = "";
  const fs::path file = write("noradius.vtp", writeVtp(branchingFixture(), noRadius));
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[1].points[40].radiusMm, 0.0);
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          file.string() + ": path '0': 80 of 80 points have radius 0 (unknown)",
                          file.string() + ": path '1': 80 of 80 points have radius 0 (unknown)"}));
}

TEST_F(CenterlineVtp, PrefersMaximumInscribedSphereRadiusOverRadius) {
  // A file with both arrays: "Radius" first (holding 99), vmtk's array second.
  Polylines data = branchingFixture();
  std::string xml = writeVtp(data, style("", "ascii"));
  std::string ninetyNines;
  for (int n = 0; n < 130; ++n) ninetyNines += "99 ";
  xml.insert(
      xml.find("<PointData>") + 11,
      "<DataArray type=\"Float64\" Name=\"Radius\" format=\"ascii\">" + ninetyNines + "</DataArray>");
  const Centerlines loaded = loadCenterlines(write("both.vtp", xml));
  expectMatches(loaded, data, 1e-9);
}

// A broken copy of the fixture and the words its error must contain.
struct Broken {
  std::string name;
  std::string bytes;
  std::string expected;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::vector<Broken> brokenVtps() {
  const Polylines good = branchingFixture();
  const std::string ascii = writeVtp(good, style("", "ascii"));
  VtpStyle zlibStyle = style("", "binary");
  zlibStyle.zlib = true;
  const std::string zlibFile = writeVtp(good, zlibStyle);

  Polylines outOfRange = good;
  outOfRange.lines[1].back() = 130;
  Polylines nanPoint = good;
  nanPoint.points[100].y = std::numeric_limits<double>::quiet_NaN();
  Polylines negativeRadius = good;
  negativeRadius.radii[5] = -1;
  Polylines emptyLine = good;
  emptyLine.lines.push_back({});
  Polylines noLines = good;
  noLines.lines.clear();

  // Corrupt one byte inside the first zlib block of the points (its base64 text).
  std::string corruptZlib = zlibFile;
  const std::size_t points = corruptZlib.find("Name=\"Points\"");
  const std::size_t text = corruptZlib.find('>', points) + 11 + 40;
  corruptZlib[text] = corruptZlib[text] == 'A' ? 'B' : 'A';

  std::string truncated = writeVtp(good, style("", "binary"));
  const std::size_t pointsText = truncated.find('>', truncated.find("Name=\"Points\"")) + 11;
  truncated.erase(pointsText + 100, 40);

  return {
      {"BadXml", replaced(ascii, "</Points>", "</Pointz>"), "bad XML"},
      {"NotXml", "hello, not a vtp file", "bad XML"},
      {"NotPolyData", replaced(ascii, "type=\"PolyData\"", "type=\"ImageData\""), "not PolyData"},
      {"ConnectivityOutOfRange", writeVtp(outOfRange, style("", "binary")),
       "point index 130 out of range (130 points)"},
      {"RadiusCountWrongAscii",
       replaced(ascii,
                "Name=\"MaximumInscribedSphereRadius\" NumberOfComponents=\"1\" format=\"ascii\">\n2 ",
                "Name=\"MaximumInscribedSphereRadius\" NumberOfComponents=\"1\" format=\"ascii\">\n"),
       "DataArray 'MaximumInscribedSphereRadius': has 129 values, expected 130"},
      {"PointCountWrongBinary",
       replaced(writeVtp(good, style("", "binary")), "NumberOfPoints=\"130\"", "NumberOfPoints=\"131\""),
       "DataArray 'Points': holds 1560 bytes, expected 1572"},
      {"PointCountWrongZlib", replaced(zlibFile, "NumberOfPoints=\"130\"", "NumberOfPoints=\"129\""),
       "DataArray 'Points': holds 1560 bytes, expected 1548"},
      {"TwoComponentPoints",
       replaced(ascii, "Name=\"Points\" NumberOfComponents=\"3\"",
                "Name=\"Points\" NumberOfComponents=\"2\""),
       "has 2 components, expected 3"},
      {"NanPointAscii", writeVtp(nanPoint, style("", "ascii")),
       "path '1': point 50: coordinate is not finite"},
      {"NanPointBinary", writeVtp(nanPoint, zlibStyle), "path '1': point 50: coordinate is not finite"},
      {"NegativeRadius", writeVtp(negativeRadius, style("", "appended")), "point 5: negative radius"},
      {"EmptyLine", writeVtp(emptyLine, style("", "binary")), "path '2': has no points"},
      {"NoLines", writeVtp(noLines, style("", "binary")), "contains no centerline paths"},
      {"NotANumber", replaced(ascii, "format=\"ascii\">\n2 ", "format=\"ascii\">\ntwo "),
       "'two' is not a number"},
      // Values from the file are shown with their control bytes escaped and long ones cut short.
      {"ControlByteInAnAttribute",
       replaced(ascii, "type=\"PolyData\"",
                "type=\"Poly\x01"
                "Data\""),
       "VTK file of type 'Poly\\x01Data', not PolyData"},
      {"LongWordInAscii",
       replaced(ascii, "format=\"ascii\">\n2 ", "format=\"ascii\">\n" + std::string(5000, 'w') + " "),
       "'" + std::string(80, 'w') + "...' is not a number"},
      {"CorruptZlib", corruptZlib, "DataArray 'Points': corrupt zlib block"},
      {"TruncatedBase64", truncated, "DataArray 'Points': data ends early"},
      {"InvalidBase64",
       replaced(writeVtp(good, style("", "binary")),
                "\"Points\" NumberOfComponents=\"3\" format=\"binary\">\n",
                "\"Points\" NumberOfComponents=\"3\" format=\"binary\">\n*"),
       "DataArray 'Points': invalid base64 character '*'"},
      {"UnsupportedCompressor", replaced(zlibFile, "vtkZLibDataCompressor", "vtkLZ4DataCompressor"),
       "unsupported compressor 'vtkLZ4DataCompressor'"},
      {"UnsupportedType", replaced(ascii, "type=\"Float32\"", "type=\"Float16\""),
       "unsupported type 'Float16'"},
      {"DecreasingOffsets",
       replaced(ascii, "Name=\"offsets\" NumberOfComponents=\"1\" format=\"ascii\">\n80 160",
                "Name=\"offsets\" NumberOfComponents=\"1\" format=\"ascii\">\n80 70"),
       "Lines offsets: bad offset"},
      // Appended raw: EdgeArray and the radius take 4 + 130 * 8 bytes each, then come the points.
      {"AppendedOffsetBeyondData",
       replaced(writeVtp(good, style("", "appended")),
                "\"Points\" NumberOfComponents=\"3\" format=\"appended\" offset=\"2088\"",
                "\"Points\" NumberOfComponents=\"3\" format=\"appended\" offset=\"99999\""),
       "offset beyond the appended data"},
      {"AppendedWithoutUnderscore", replaced(writeVtp(good, style("", "appended")), "   _", "   #"),
       "appended data does not start with '_'"},
      {"NoPoints", replaced(replaced(ascii, "<Points>", "<Pointless>"), "</Points>", "</Pointless>"),
       "no <Points> DataArray"},
  };
}

TEST_F(CenterlineVtp, BrokenFilesGiveAnInputErrorNamingFileAndProblem) {
  for (const Broken& broken : brokenVtps()) {
    const fs::path file = write(broken.name + ".vtp", broken.bytes);
    const std::string error = loadError(file);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << broken.name << ": " << error;
    EXPECT_NE(error.find(broken.expected), std::string::npos) << broken.name << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << broken.name << ": " << error;
  }
}

TEST_F(CenterlineVtp, MissingFileAndDirectoryAreInputErrors) {
  EXPECT_NE(loadError(dir_ / "absent.vtp").find("no such file"), std::string::npos);
  fs::create_directories(dir_ / "folder.vtp");
  EXPECT_NE(loadError(dir_ / "folder.vtp").find("is a directory"), std::string::npos);
}

// --- .vtp path names ----------------------------------------------------------------------------

// The fixture with a CellData array in its (empty) <CellData>.
std::string withCellData(const std::string& dataArray) {
  return replaced(writeVtp(branchingFixture(), style("", "ascii")), "<CellData>\n      </CellData>",
                  "<CellData>\n" + dataArray + "      </CellData>");
}

std::string nameArray(const std::string& format, const std::string& values) {
  return "<DataArray type=\"String\" Name=\"CenterlineName\" NumberOfTuples=\"2\" format=\"" + format +
         "\">\n" + values + "\n</DataArray>\n";
}

// As VTK writes a String array in ascii: each byte as a number (a char printed as a short, so
// UTF-8 bytes are negative where char is signed), each string ended by a 0.
TEST_F(CenterlineVtp, CellDataNamesNameThePaths) {
  // "Left é" with signed bytes, "Right é" with unsigned ones.
  const std::string codes = "76 101 102 116 32 -61 -87 0\n82 105 103 104 116 32 195 169 0";
  std::vector<std::string> warnings;
  const Centerlines loaded =
      loadWarned(write("named.vtp", withCellData(nameArray("ascii", codes))), warnings);
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[0].name, "Left \u00e9");
  EXPECT_EQ(loaded.paths[1].name, "Right \u00e9");
  EXPECT_EQ(loaded.paths[1].points.size(), 80u);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// VTK 9.1's vtkXMLPolyDataWriter in ascii mode writes a String array as an <Array> element.
TEST_F(CenterlineVtp, NamesInAnArrayElementAsVtk9WritesThemAreRead) {
  const Centerlines loaded = loadCenterlines(
      write("vtk9.vtp", withCellData("<Array type=\"String\" Name=\"CenterlineName\" format=\"ascii\">\n"
                                     "76 0 82 0\n</Array>\n")));
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[0].name, "L");
  EXPECT_EQ(loaded.paths[1].name, "R");
}

TEST_F(CenterlineVtp, EmptyNamesAreNamedByTheirIndex) {
  const Centerlines loaded =
      loadCenterlines(write("unnamed.vtp", withCellData(nameArray("ascii", "0 76 0"))));
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[0].name, "0");
  EXPECT_EQ(loaded.paths[1].name, "L");
}

// VTK's binary strings are not read; the paths keep their index names and the user is told.
TEST_F(CenterlineVtp, NamesNotInAsciiAreSkippedWithAWarning) {
  const fs::path file = write("binary-names.vtp", withCellData(nameArray("binary", "CAAAAAAAAABMAFIA")));
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[1].name, "1");
  EXPECT_EQ(warnings, std::vector<std::string>{file.string() +
                                               ": CellData 'CenterlineName' is not an ascii String "
                                               "array; skipped, paths are named by their index"});
}

TEST_F(CenterlineVtp, BadNameArraysGiveAnInputError) {
  const std::vector<Broken> cases = {
      {"OneNameForTwoLines", withCellData(nameArray("ascii", "76 0")),
       "DataArray 'CenterlineName': has 1 names, expected 2 (one per line cell)"},
      {"NotACharacter", withCellData(nameArray("ascii", "76 300 0 82 0")),
       "DataArray 'CenterlineName': '300' is not a character code"},
      {"NotANumber", withCellData(nameArray("ascii", "L 0 R 0")), "'L' is not a number"},
  };
  for (const Broken& broken : cases) {
    const fs::path file = write(broken.name + ".vtp", broken.bytes);
    const std::string error = loadError(file);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << broken.name << ": " << error;
    EXPECT_NE(error.find(broken.expected), std::string::npos) << broken.name << ": " << error;
  }
}

// --- Slicer markups -----------------------------------------------------------------------------

using CenterlineMarkups = CenterlineFiles;

std::string curveJson(const std::string& extra, const std::string& points) {
  return R"({"@schema": "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/markups-schema-v1.0.3.json#",
  "markups": [{"type": "Curve", "name": "LeftIliac", )" +
         extra + R"("controlPoints": [)" + points + "]}]}";
}

const char* kThreePoints =
    R"({"id": "1", "label": "C-1", "position": [1.5, -2.0, 30.0], "positionStatus": "defined"},
       {"id": "2", "label": "C-2", "position": [2.5, -3.0, 31.0], "positionStatus": "defined"},
       {"id": "3", "label": "C-3", "position": [3.5, -4.0, 32.0], "positionStatus": "defined"})";

TEST_F(CenterlineMarkups, LpsCurveWithRadiusMeasurement) {
  const fs::path file =
      write("curve.mrk.json", curveJson(
                                  R"("coordinateSystem": "LPS", "coordinateUnits": "mm",
         "measurements": [{"name": "length", "value": 2.8, "units": "mm"},
                          {"name": "Radius", "units": "mm", "controlPointValues": [4.0, 3.5, 3.0]}], )",
                                  kThreePoints));
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  ASSERT_EQ(loaded.paths.size(), 1u);
  EXPECT_EQ(loaded.paths[0].name, "LeftIliac");
  ASSERT_EQ(loaded.paths[0].points.size(), 3u);
  EXPECT_EQ(loaded.paths[0].points[1].positionMm, glm::dvec3(2.5, -3.0, 31.0));
  EXPECT_EQ(loaded.paths[0].points[2].radiusMm, 3.0);
  EXPECT_TRUE(warnings.empty());
}

TEST_F(CenterlineMarkups, RasBecomesLpsAndMicrometresBecomeMillimetres) {
  const Centerlines ras = loadCenterlines(write(
      "ras.mrk.json",
      curveJson(
          R"("coordinateSystem": "RAS", "measurements": [{"name": "radius", "controlPointValues": [1, 1, 1]}], )",
          kThreePoints)));
  EXPECT_EQ(ras.paths[0].points[0].positionMm, glm::dvec3(-1.5, 2.0, 30.0));
  const Centerlines um =
      loadCenterlines(write("um.mrk.json", curveJson(
                                               R"("coordinateUnits": ["um", "UCUM", "micrometer"],
         "measurements": [{"name": "Radius", "controlPointValues": [1, 1, 1]}], )",
                                               kThreePoints)));
  EXPECT_NEAR(glm::distance(um.paths[0].points[2].positionMm, glm::dvec3(0.0035, -0.004, 0.032)), 0.0,
              1e-15);
}

TEST_F(CenterlineMarkups, WithoutRadiusRadiiAreZeroWithAWarning) {
  const fs::path file = write("plain.json", curveJson("", kThreePoints));
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  EXPECT_EQ(loaded.paths[0].points[0].radiusMm, 0.0);
  EXPECT_EQ(warnings, std::vector<std::string>{
                          file.string() + ": path 'LeftIliac': 3 of 3 points have radius 0 (unknown)"});
}

TEST_F(CenterlineMarkups, OtherMarkupTypesAndUndefinedPointsAreSkippedWithWarnings) {
  const std::string json = R"({"markups": [
      {"type": "Fiducial", "controlPoints": [{"position": [0, 0, 0]}]},
      {"type": "Curve", "measurements": [{"name": "Radius", "controlPointValues": [2, 9, 2]}],
       "controlPoints": [{"position": [0, 0, 0]}, {"positionStatus": "undefined"}, {"position": [0, 0, 5]}]}]})";
  const fs::path file = write("mixed.mrk.json", json);
  std::vector<std::string> warnings;
  const Centerlines loaded = loadWarned(file, warnings);
  ASSERT_EQ(loaded.paths.size(), 1u);
  EXPECT_EQ(loaded.paths[0].name, "1");  // unnamed: its index in the file
  ASSERT_EQ(loaded.paths[0].points.size(), 2u);
  EXPECT_EQ(loaded.paths[0].points[1].radiusMm, 2.0);
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          file.string() + ": markup 0 of type 'Fiducial' is not a curve; skipped",
                          file.string() + ": markup '1': skipped 1 control points without a position"}));
}

TEST_F(CenterlineMarkups, BrokenFilesGiveAnInputErrorNamingFileAndProblem) {
  const std::vector<Broken> cases = {
      {"BadJson", "{\"markups\": [", "not valid JSON"},
      {"NoMarkups", "{\"points\": []}", "no \"markups\" array"},
      {"PositionOfTwo", curveJson("", R"({"position": [1, 2]})"),
       "markup 'LeftIliac' control point 0: position is not an array of 3 numbers"},
      {"PositionText", curveJson("", R"({"position": [1, "2", 3]})"),
       "control point 0: y is not a number"},
      {"RadiusCount",
       curveJson(R"("measurements": [{"name": "Radius", "controlPointValues": [1, 2]}], )",
                 kThreePoints),
       "Radius measurement has 2 values for 3 control points"},
      {"NegativeRadius",
       curveJson(R"("measurements": [{"name": "Radius", "controlPointValues": [1, -2, 1]}], )",
                 kThreePoints),
       "path 'LeftIliac': point 1: negative radius"},
      {"UnknownSystem", curveJson(R"("coordinateSystem": "XYZ", )", kThreePoints),
       "unknown coordinateSystem 'XYZ'"},
      {"UnknownUnits", curveJson(R"("coordinateUnits": "inch", )", kThreePoints),
       "unknown coordinateUnits 'inch'"},
      {"EmptyCurve", curveJson("", ""), "path 'LeftIliac': has no points"},
      {"NoCurves", R"({"markups": [{"type": "Plane"}]})", "contains no centerline paths"},
  };
  for (const Broken& broken : cases) {
    const fs::path file = write(broken.name + ".mrk.json", broken.bytes);
    const std::string error = loadError(file);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << broken.name << ": " << error;
    EXPECT_NE(error.find(broken.expected), std::string::npos) << broken.name << ": " << error;
  }
}

// --- CSV ----------------------------------------------------------------------------------------

using CenterlineCsv = CenterlineFiles;

TEST_F(CenterlineCsv, WrittenCentrelinesReadBackExactlyWithTheirNames) {
  Centerlines written;
  written.paths = {
      {"trunk-left",
       {{{double(-218.4904f), -316.4061, 1.0 / 3.0}, double(10.3651f)}, {{-218.5, -315.5, 24.4}, 10.0}}},
      {"trunk, \"right\"", {{{1, 2, 3}, 0.5}, {{1, 2, 4}, 0.25}}}};
  const fs::path file = dir_ / "round.csv";
  writeCenterlinesCsv(written, file);
  const Centerlines read = readCenterlinesCsv(file);
  written.source = file.string();
  EXPECT_EQ(read, written);
}

TEST_F(CenterlineCsv, VolumeFrameCentrelinesAreNotWritten) {
  Centerlines framed;
  framed.frame = CenterlineFrame::volume;
  framed.paths = {{"a", {{{0, 0, 0}, 1}}}};
  EXPECT_THROW(writeCenterlinesCsv(framed, dir_ / "framed.csv"), std::logic_error);
}

TEST_F(CenterlineCsv, IdsGroupRowsAndBlankLinesAndSpacesAreIgnored) {
  const fs::path file = write("ids.csv",
                              "path, x_mm, y_mm, z_mm, radius_mm\r\n"
                              "left,1,2,3,4\r\n\r\n"
                              "right,5,6,7,8\n"
                              " left , 1.5 , +2 , 3e0 , 4.25\n"
                              "right,5,6,8,8\n");
  const Centerlines loaded = loadCenterlines(file);
  ASSERT_EQ(loaded.paths.size(), 2u);
  EXPECT_EQ(loaded.paths[0].name, "left");
  ASSERT_EQ(loaded.paths[0].points.size(), 2u);
  EXPECT_EQ(loaded.paths[0].points[1].positionMm, glm::dvec3(1.5, 2, 3));
  EXPECT_EQ(loaded.paths[0].points[1].radiusMm, 4.25);
  EXPECT_EQ(loaded.paths[1].points[0].positionMm, glm::dvec3(5, 6, 7));
}

// RFC 4180 quoting as spreadsheets write it: commas, doubled quotes, a line break and the spaces
// inside the quotes are the name's; spaces outside are not. Each id's two rows make one path.
TEST_F(CenterlineCsv, QuotedIdsKeepCommasQuotesLineBreaksAndSpaces) {
  const std::vector<std::pair<std::string, std::string>> fieldAndName = {
      {"\"left, \"\"iliac\"\"\"", "left, \"iliac\""},
      {" \"  two\nlines \" ", "  two\nlines "},
      {"\"\"\"\"", "\""},
      {"\"Aorta \u2192 (\u53f3)\"", "Aorta \u2192 (\u53f3)"}};
  std::string text = "path,x_mm,y_mm,z_mm,radius_mm\r\n";
  for (const auto& [field, name] : fieldAndName) text += field + ",1,2,3,4\r\n" + field + ",5,6,7,8\n";
  const Centerlines loaded = loadCenterlines(write("quoted.csv", text));
  ASSERT_EQ(loaded.paths.size(), fieldAndName.size());
  for (std::size_t p = 0; p < fieldAndName.size(); ++p) {
    EXPECT_EQ(loaded.paths[p].name, fieldAndName[p].second);
    ASSERT_EQ(loaded.paths[p].points.size(), 2u) << fieldAndName[p].second;
    EXPECT_EQ(loaded.paths[p].points[1].positionMm, glm::dvec3(5, 6, 7)) << fieldAndName[p].second;
  }
}

TEST_F(CenterlineCsv, BrokenFilesGiveAnInputErrorNamingFileLineAndProblem) {
  const std::string header = "path,x_mm,y_mm,z_mm,radius_mm\n";
  const std::vector<Broken> cases = {
      {"Empty", "", "empty file"},
      {"NoHeader", "0,1,2,3,4\n", "line 1: expected the header 'path,x_mm,y_mm,z_mm,radius_mm'"},
      {"HeaderOnly", header, "contains no centerline paths"},
      {"FourFields", header + "0,1,2,3,4\n0,1,2,3\n", "line 3: 4 fields, expected 5"},
      {"NotANumber", header + "0,1,2,three,4\n", "line 2: 'three' is not a number"},
      {"EmptyNumber", header + "0,1,,3,4\n", "line 2: '' is not a number"},
      {"NoId", header + ",1,2,3,4\n", "line 2: no path id"},
      {"Nan", header + "0,1,2,3,4\n7,1,nan,3,4\n", "path '7': point 0: coordinate is not finite"},
      {"NanRadius", header + "0,1,2,3,NaN\n", "path '0': point 0: radius is not finite"},
      {"NegativeRadius", header + "0,1,2,3,4\n0,1,2,4,-4\n", "path '0': point 1: negative radius"},
      {"QuoteNotClosed", header + "0,1,2,3,4\n\"left,1,2,3,4\n0,1,2,3,4\n",
       "line 3: quoted field not closed"},
      {"TextAfterQuote", header + "\"left\"x,1,2,3,4\n", "line 2: text after the closing quote"},
      // A line break inside quotes moves the lines that follow.
      {"LineAfterQuotedBreak", header + "\"a\nb\",1,2,3,4\n0,1,2\n", "line 4: 3 fields, expected 5"},
  };
  for (const Broken& broken : cases) {
    const fs::path file = write(broken.name + ".csv", broken.bytes);
    const std::string error = loadError(file);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << broken.name << ": " << error;
    EXPECT_NE(error.find(broken.expected), std::string::npos) << broken.name << ": " << error;
  }
}

// --- Points outside a volume --------------------------------------------------------------------

TEST_F(CenterlineFiles, PointsOutsideAVolumeAreAWarningNamingFileAndPath) {
  const fs::path file = write("outside.csv",
                              "path,x_mm,y_mm,z_mm,radius_mm\n"
                              "0,1,1,1,1\n0,2,2,2,1\n1,1,1,1,1\n1,50,1,1,1\n1,1,1,-3,1\n");
  const Centerlines centerlines = loadCenterlines(file);
  const Volume volume = makeVolume({10, 10, 10}, {1.0, 1.0, 1.0});  // voxel centres 0..9 mm
  std::vector<std::string> warnings;
  CenterlineLoadOptions options;
  options.warn = [&](const std::string& warning) { warnings.push_back(warning); };
  checkCenterlinesInside(centerlines, volume, options);
  EXPECT_EQ(warnings, std::vector<std::string>{file.string() +
                                               ": path '1': 2 of 3 points lie outside the volume"});
}

// --- Choice by extension ------------------------------------------------------------------------

TEST_F(CenterlineFiles, FormatIsChosenByExtension) {
  const Polylines data = branchingFixture();
  EXPECT_EQ(loadCenterlines(write("upper.VTP", writeVtp(data, style("", "binary")))).paths.size(), 2u);
  EXPECT_EQ(loadCenterlines(write("a.mrk.json", curveJson("", kThreePoints))).paths.size(), 1u);
  EXPECT_EQ(loadCenterlines(write("a.csv", "path,x_mm,y_mm,z_mm,radius_mm\n0,1,2,3,4\n0,1,2,4,4\n"))
                .paths.size(),
            1u);
  // A .vtp that holds CSV fails as XML, not silently.
  EXPECT_NE(loadError(write("csv.vtp", "path,x_mm,y_mm,z_mm,radius_mm\n")).find("bad XML"),
            std::string::npos);
  EXPECT_NE(loadError(write("a.txt", "0,1,2,3,4\n")).find("unknown centerline format"),
            std::string::npos);
}

// --- The shared aorta data ----------------------------------------------------------------------

const fs::path kSharedData = ANGIORAY_SHARED_DATA;

TEST(CenterlineSharedData, VtpAndCsvGiveTheSameModel) {
  std::vector<std::string> warnings;
  CenterlineLoadOptions options;
  options.warn = [&](const std::string& warning) { warnings.push_back(warning); };
  const Centerlines vtp = loadCenterlines(kSharedData / "aorta-centerlines.vtp", options);
  const Centerlines csv = loadCenterlines(kSharedData / "aorta-centerlines.csv", options);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(vtp.paths.size(), 2u);
  ASSERT_EQ(csv.paths.size(), 2u);
  // Neither file names its paths: the .vtp's are named by cell index, the CSV's ids are 0 and 1.
  EXPECT_EQ(vtp.paths[0].name, "0");
  EXPECT_EQ(vtp.paths[1].name, "1");
  EXPECT_EQ(csv.paths[0].name, "0");
  EXPECT_EQ(csv.paths[1].name, "1");
  for (std::size_t p = 0; p < 2; ++p) {
    ASSERT_EQ(vtp.paths[p].points.size(), 331u);
    ASSERT_EQ(csv.paths[p].points.size(), 331u);
    for (std::size_t n = 0; n < 331; ++n) {
      const CenterlinePoint& a = vtp.paths[p].points[n];
      const CenterlinePoint& b = csv.paths[p].points[n];
      EXPECT_NEAR(glm::distance(a.positionMm, b.positionMm), 0.0, 1e-3) << p << " " << n;
      EXPECT_NEAR(a.radiusMm, b.radiusMm, 5e-4) << p << " " << n;  // CSV keeps 3 decimals
    }
    EXPECT_GE(vtp.paths[p].points.front().radiusMm, 2.4);
  }
  // vmtk repeats the trunk in both paths.
  EXPECT_EQ(sharedPrefixLength(vtp.paths[0], vtp.paths[1]), 213u);
}

// The stored value (uncalibrated, read as HU) at the voxel nearest to a physical point, or
// nullopt outside the volume.
std::optional<double> valueAt(const Volume& volume, glm::dvec3 physicalMm) {
  const glm::ivec3 voxel = nearestVoxelToPoint(volume, physicalMm);
  if (!glm::all(glm::greaterThanEqual(voxel, glm::ivec3(0))) ||
      !glm::all(glm::lessThan(voxel, volume.dims))) {
    return std::nullopt;
  }
  return huOfDensity(volume.densityAt(voxel.x, voxel.y, voxel.z));
}

// aorta.mha is not calibrated in HU (shared data README). Its lumen is brighter than every tissue
// voxel, also at the top of the trunk where the contrast fades, so "lumen" is any value above the
// brightest tissue, and "full contrast" the band the well-filled lumen holds.
bool inLumen(double value) { return value > 700 && value <= 2600; }
bool fullContrast(double value) { return value >= 1200 && value <= 2400; }

TEST(CenterlineSharedData, CenterlinesLieInTheAortaLumen) {
  const Volume volume = readVolume(kSharedData / "aorta.mha").volume;
  const Centerlines centerlines = loadCenterlines(kSharedData / "aorta-centerlines.vtp");
  EXPECT_TRUE(checkInsideVolume(centerlines, volume).empty());
  for (const CenterlinePath& path : centerlines.paths) {
    std::size_t inside = 0, lumen = 0, full = 0, shiftedLumen = 0;
    for (const CenterlinePoint& point : path.points) {
      const std::optional<double> value = valueAt(volume, point.positionMm);
      if (!value) continue;
      ++inside;
      lumen += inLumen(*value);
      full += fullContrast(*value);
      // Control: 25 mm to the side (beyond the largest radius, 11 mm) is mostly not lumen.
      const std::optional<double> beside = valueAt(volume, point.positionMm + glm::dvec3(25, 0, 0));
      shiftedLumen += beside && inLumen(*beside);
    }
    const double count = double(path.points.size());
    EXPECT_EQ(inside, path.points.size()) << path.name;
    EXPECT_GE(lumen / count, 0.95) << path.name << ": " << lumen;
    EXPECT_GE(full / count, 0.85) << path.name << ": " << full;
    EXPECT_LT(shiftedLumen / count, 0.5) << path.name << ": " << shiftedLumen;
  }
  // In the volume frame the paths run along voxel axis j, the aorta's long axis, over most of
  // the 393-voxel extent; their boxes stay inside the volume's extent grown by the radius.
  const Centerlines framed = toVolumeFrame(centerlines, volume);
  const glm::dvec3 extent = domainExtent(volume);
  for (const BoxMm& box : pathBounds(framed)) {
    EXPECT_GT(box.hi.y - box.lo.y, 0.75 * extent.y);
    EXPECT_GE(box.lo.x, -11.0);
    EXPECT_LE(box.hi.x, extent.x + 11.0);
  }
}

TEST(CenterlineSharedData, ResamplingKeepsLengthAndEndpoints) {
  const Centerlines centerlines = loadCenterlines(kSharedData / "aorta-centerlines.csv");
  // Steps up to about two voxels: the path zigzags by up to a voxel (it was tracked slice by slice),
  // and coarser steps cut those corners, which shortens the path.
  for (double step : {0.25, 0.5, 1.0, 2.0}) {
    const Centerlines resampled = resampleByArcLength(centerlines, step);
    for (std::size_t p = 0; p < centerlines.paths.size(); ++p) {
      const CenterlinePath& before = centerlines.paths[p];
      const CenterlinePath& after = resampled.paths[p];
      EXPECT_NEAR(pathLengthMm(after), pathLengthMm(before), 0.01 * pathLengthMm(before)) << step;
      EXPECT_EQ(after.points.front().positionMm, before.points.front().positionMm);
      EXPECT_EQ(after.points.back().positionMm, before.points.back().positionMm);
      EXPECT_EQ(after.points.back().radiusMm, before.points.back().radiusMm);
      EXPECT_NEAR(double(after.points.size()), pathLengthMm(before) / step + 1, 1.5) << step;
    }
  }
}

}  // namespace
}  // namespace angio
