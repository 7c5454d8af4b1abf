#include "io/dicom_slice_check.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gdcmAttribute.h>
#include <gdcmMediaStorage.h>
#include <gdcmReader.h>

#include "io/dicom_element_check.h"
#include "io/shown_text.h"
#include "io/dicom_file_walk.h"
#include "io/input_error.h"

namespace angio {

namespace {

namespace fs = std::filesystem;

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

// The user sees the folder they opened, then the slice and what is wrong with it.
struct SliceProblem {
  const fs::path& reported;
  const fs::path& slice;
  [[noreturn]] void fail(const std::string& problem) const {
    const std::string where = reported == slice ? "" : "slice " + slice.filename().string() + " ";
    throw InputError(reported, where + problem);
  }
};

// A tag's value bytes, or empty when the slice does not have it.
std::optional<std::string> valueBytes(const gdcm::DataSet& data, const gdcm::Tag& tag) {
  if (!data.FindDataElement(tag)) return std::nullopt;
  const gdcm::ByteValue* bytes = data.GetDataElement(tag).GetByteValue();
  if (!bytes) return std::string();
  return std::string(bytes->GetPointer(), bytes->GetLength());
}

// An unsigned short (VR US) tag; GDCM's Attribute swaps it for the transfer syntax, once we made
// sure it holds exactly one value (it asserts otherwise).
template <std::uint16_t Group, std::uint16_t Element>
std::optional<int> unsignedShort(const gdcm::DataSet& data, const SliceProblem& problem,
                                 const char* name) {
  const gdcm::Tag tag(Group, Element);
  const std::optional<std::string> bytes = valueBytes(data, tag);
  if (!bytes) return std::nullopt;
  if (bytes->size() != 2) problem.fail(std::string("has a malformed ") + name);
  gdcm::Attribute<Group, Element> attribute;
  attribute.SetFromDataElement(data.GetDataElement(tag));
  return int(attribute.GetValue());
}

// A decimal-string (VR DS) tag's values: "a\b\c", each a finite number, exactly `count` of them.
std::optional<std::vector<double>> decimals(const gdcm::DataSet& data, const gdcm::Tag& tag,
                                            std::size_t count, const SliceProblem& problem,
                                            const char* name) {
  const std::optional<std::string> bytes = valueBytes(data, tag);
  if (!bytes) return std::nullopt;
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= bytes->size()) {
    std::size_t end = bytes->find('\\', start);
    if (end == std::string::npos) end = bytes->size();
    std::string text = bytes->substr(start, end - start);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
    while (!text.empty() && text.front() == ' ') text.erase(text.begin());
    char* parsedEnd = nullptr;
    const double value = std::strtod(text.c_str(), &parsedEnd);
    if (text.empty() || *parsedEnd != '\0' || !std::isfinite(value))
      problem.fail(std::string("has an invalid ") + name + " ('" + shownText(*bytes) + "')");
    values.push_back(value);
    start = end + 1;
  }
  if (values.size() != count)
    problem.fail(std::string("has ") + std::to_string(values.size()) + " values in " + name + " (need " +
                 std::to_string(count) + ")");
  return values;
}

int numberOfFrames(const gdcm::DataSet& data, const SliceProblem& problem) {
  const std::optional<std::string> bytes = valueBytes(data, gdcm::Tag(0x0028, 0x0008));
  if (!bytes) return 1;
  const long frames = std::strtol(bytes->c_str(), nullptr, 10);
  if (frames < 1 || frames > 65535) problem.fail("has an invalid NumberOfFrames");
  return int(frames);
}

void checkImagePixelModule(const gdcm::DataSet& data, const SliceProblem& problem,
                           DicomSliceTags& tags) {
  const auto rows = unsignedShort<0x0028, 0x0010>(data, problem, "Rows (0028,0010)");
  const auto columns = unsignedShort<0x0028, 0x0011>(data, problem, "Columns (0028,0011)");
  if (!rows || !columns || *rows < 1 || *columns < 1)
    problem.fail("has no image (Rows or Columns missing or 0)");
  const int samples =
      unsignedShort<0x0028, 0x0002>(data, problem, "SamplesPerPixel (0028,0002)").value_or(1);
  if (samples != 1)
    problem.fail("has " + std::to_string(samples) + " samples per pixel; need greyscale CT");
  const auto bits = unsignedShort<0x0028, 0x0100>(data, problem, "BitsAllocated (0028,0100)");
  if (!bits || (*bits != 8 && *bits != 12 && *bits != 16 && *bits != 32))
    problem.fail("has BitsAllocated (0028,0100) " + (bits ? std::to_string(*bits) : "missing") +
                 "; need 8, 12, 16 or 32");
  const int stored =
      unsignedShort<0x0028, 0x0101>(data, problem, "BitsStored (0028,0101)").value_or(*bits);
  const int highBit =
      unsignedShort<0x0028, 0x0102>(data, problem, "HighBit (0028,0102)").value_or(stored - 1);
  if (stored < 1 || stored > *bits || highBit < stored - 1 || highBit >= *bits)
    problem.fail("has BitsStored " + std::to_string(stored) + " / HighBit " + std::to_string(highBit) +
                 " that do not fit BitsAllocated " + std::to_string(*bits));
  const int representation =
      unsignedShort<0x0028, 0x0103>(data, problem, "PixelRepresentation (0028,0103)").value_or(0);
  if (representation != 0 && representation != 1)
    problem.fail("has an invalid PixelRepresentation (0028,0103) " + std::to_string(representation));
  tags.rows = *rows;
  tags.columns = *columns;
  tags.bitsAllocated = *bits;
}

// The patient and study tags, read with the slice's other tags (GDCM's image reader, which ITK
// uses for them, would decode compressed pixels: io/slices_in_child.h).
StudyInfo studyTags(const gdcm::DataSet& data) {
  const auto tag = [&](std::uint16_t group, std::uint16_t element) {
    return trimmedDicomValue(valueBytes(data, gdcm::Tag(group, element)).value_or(""));
  };
  return {readablePersonName(tag(0x0010, 0x0010)), tag(0x0010, 0x0020),
          readableDate(tag(0x0008, 0x0020)), tag(0x0008, 0x103e), tag(0x0008, 0x0060)};
}

// What GDCM's image reader takes without asserting. It reads a file without a meta header as
// ACR-NEMA and one of an unknown SOP class by guessing, both with assertions on the tags it finds;
// it asserts on palette colour tables, on an icon image without a PhotometricInterpretation and on
// curve and overlay groups it cannot count. CT slices have none of these; a slice that does is
// refused here, before ITK hands it to that reader.
void checkReadableImage(const gdcm::File& file, const SliceProblem& problem) {
  const gdcm::DataSet& data = file.GetDataSet();
  if (file.GetHeader().IsEmpty())
    problem.fail(
        "has no DICOM file meta header (an ACR-NEMA file or a bare data set), which is not read");
  std::optional<std::string> sopClass = valueBytes(file.GetHeader(), gdcm::Tag(0x0002, 0x0002));
  if (!sopClass) sopClass = valueBytes(data, gdcm::Tag(0x0008, 0x0016));
  const std::string uid = trimmedDicomValue(sopClass.value_or(""));
  if (!gdcm::MediaStorage::IsImage(gdcm::MediaStorage::GetMSType(uid.c_str())))
    problem.fail("is not an image (SOP class '" + shownText(uid) + "')");
  if (const auto photometric = valueBytes(data, gdcm::Tag(0x0028, 0x0004))) {
    const std::string name = trimmedDicomValue(*photometric);
    if (name != "MONOCHROME1" && name != "MONOCHROME2")
      problem.fail("has PhotometricInterpretation (0028,0004) '" + shownText(name.substr(0, 16)) +
                   "'; need greyscale CT (MONOCHROME1 or MONOCHROME2)");
  }
  if (data.FindDataElement(gdcm::Tag(0x0088, 0x0200)))
    problem.fail("has an icon image sequence (0088,0200), which is not read");
  for (const std::uint16_t first : {std::uint16_t(0x5000), std::uint16_t(0x6000)}) {
    const gdcm::DataElement& next = data.FindNextDataElement(gdcm::Tag(first, 0x0000));
    if (next.GetTag().GetGroup() >= first && next.GetTag().GetGroup() <= first + 0xff)
      problem.fail(first == 0x5000 ? "has curve data (50xx), which is not read"
                                   : "has an overlay (60xx), which is not read");
  }
}

void checkRescale(const gdcm::DataSet& data, const SliceProblem& problem) {
  const auto slope = decimals(data, gdcm::Tag(0x0028, 0x1053), 1, problem, "RescaleSlope (0028,1053)");
  if (slope && (*slope)[0] == 0) problem.fail("has a RescaleSlope (0028,1053) of 0");
  decimals(data, gdcm::Tag(0x0028, 0x1052), 1, problem, "RescaleIntercept (0028,1052)");
}

void checkPlacement(const gdcm::DataSet& data, const SliceProblem& problem, bool required,
                    DicomSliceTags& tags) {
  const auto spacing = decimals(data, gdcm::Tag(0x0028, 0x0030), 2, problem, "PixelSpacing (0028,0030)");
  const auto position =
      decimals(data, gdcm::Tag(0x0020, 0x0032), 3, problem, "ImagePositionPatient (0020,0032)");
  const auto cosines =
      decimals(data, gdcm::Tag(0x0020, 0x0037), 6, problem, "ImageOrientationPatient (0020,0037)");
  if (required && (!spacing || !position || !cosines))
    problem.fail(
        "does not say where it lies (PixelSpacing, ImagePositionPatient and "
        "ImageOrientationPatient are all needed)");
  if (spacing) {
    if (!((*spacing)[0] > 0 && (*spacing)[1] > 0))
      problem.fail("has a zero or negative PixelSpacing (0028,0030)");
    // DICOM's PixelSpacing is (between rows, between columns): y first.
    tags.pixelSpacing = {(*spacing)[1], (*spacing)[0]};
  }
  if (position) tags.position = {(*position)[0], (*position)[1], (*position)[2]};
  if (cosines) {
    tags.row = {(*cosines)[0], (*cosines)[1], (*cosines)[2]};
    tags.column = {(*cosines)[3], (*cosines)[4], (*cosines)[5]};
    // Scanners write 6 decimals at most; anything further from orthonormal is not a direction.
    const double tolerance = 1e-2;
    if (std::abs(glm::length(tags.row) - 1) > tolerance ||
        std::abs(glm::length(tags.column) - 1) > tolerance ||
        std::abs(glm::dot(tags.row, tags.column)) > tolerance)
      problem.fail(
          "has an ImageOrientationPatient (0020,0037) whose rows and columns are not "
          "orthogonal unit vectors");
  }
}

std::uint32_t littleEndian32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}
std::uint32_t bigEndian32(const unsigned char* b) {
  return std::uint32_t(b[3]) | std::uint32_t(b[2]) << 8 | std::uint32_t(b[1]) << 16 |
         std::uint32_t(b[0]) << 24;
}

// The pixel data element's declared length and the bytes the file still holds after its header,
// read from the file at `offset`. Empty when no pixel data element starts there.
struct PixelDataExtent {
  std::uint64_t declared = 0;  // 0xffffffff: undefined (encapsulated)
  std::uint64_t available = 0;
};

enum class HeaderForm { Explicit, Implicit, Either };

std::optional<PixelDataExtent> pixelDataAt(const fs::path& slice, std::uint64_t offset,
                                           HeaderForm form) {
  std::ifstream in(slice, std::ios::binary);
  std::array<unsigned char, 12> head{};
  in.seekg(std::streamoff(offset));
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (in.gcount() < 8) return std::nullopt;
  const bool little = head[0] == 0xe0 && head[1] == 0x7f && head[2] == 0x10 && head[3] == 0x00;
  const bool big = head[0] == 0x7f && head[1] == 0xe0 && head[2] == 0x00 && head[3] == 0x10;
  if (!little && !big) return std::nullopt;
  const std::string vr(reinterpret_cast<const char*>(&head[4]), 2);
  const bool explicitLong =
      form != HeaderForm::Implicit &&
      (vr == "OB" || vr == "OW" || vr == "OF" || vr == "OD" || vr == "OL" || vr == "OV" || vr == "UN");
  if (explicitLong && in.gcount() < 12) return std::nullopt;
  if (form == HeaderForm::Explicit && !explicitLong) return std::nullopt;
  const unsigned char* length = explicitLong ? &head[8] : &head[4];
  const std::uint64_t headerBytes = explicitLong ? 12 : 8;
  PixelDataExtent extent;
  extent.declared = little ? littleEndian32(length) : bigEndian32(length);
  const std::uint64_t fileBytes = fs::file_size(slice);
  extent.available = fileBytes > offset + headerBytes ? fileBytes - offset - headerBytes : 0;
  return extent;
}

// Native (uncompressed) pixel data must hold exactly Rows x Columns x frames pixels of
// BitsAllocated bits (an odd length padded by one byte), and the file must hold all of it.
void checkPixelDataLength(const fs::path& slice, std::uint64_t offset, const gdcm::DataSet& data,
                          const SliceProblem& problem, DicomSliceTags& tags) {
  // GDCM stops after the element's header: 12 bytes in explicit VR (tag, VR, 2 reserved, length),
  // 8 in implicit VR (tag, length); the explicit form is tried first since its VR is checked.
  std::optional<PixelDataExtent> extent;
  const std::pair<std::uint64_t, HeaderForm> candidates[] = {
      {12, HeaderForm::Explicit}, {8, HeaderForm::Implicit}, {0, HeaderForm::Either}};
  for (const auto& [back, form] : candidates)
    if (!extent && offset >= back) extent = pixelDataAt(slice, offset - back, form);
  if (!extent) problem.fail("has no pixel data (7fe0,0010)");
  if (extent->declared == 0xffffffffu) {
    tags.encapsulated = true;
    return;
  }
  const std::uint64_t bits = std::uint64_t(tags.rows) * std::uint64_t(tags.columns) *
                             std::uint64_t(numberOfFrames(data, problem)) *
                             std::uint64_t(tags.bitsAllocated);
  const std::uint64_t expected = (bits + 7) / 8;
  if (extent->declared != expected && extent->declared != expected + 1)
    problem.fail("has " + std::to_string(extent->declared) +
                 " bytes of pixel data where Rows x Columns x "
                 "BitsAllocated (" +
                 std::to_string(tags.rows) + " x " + std::to_string(tags.columns) + " x " +
                 std::to_string(tags.bitsAllocated) + ") need " + std::to_string(expected));
  if (extent->available < expected)
    problem.fail("is truncated (" + std::to_string(extent->available) + " of " +
                 std::to_string(expected) + " bytes of pixel data)");
}

}  // namespace

DicomSliceTags checkDicomSlice(const fs::path& reported, const fs::path& slice, bool requirePlacement) {
  const SliceProblem problem{reported, slice};
  // Our walk first: GDCM's reader must only ever see well-formed elements (io/dicom_element_check.h).
  const std::optional<DicomFileFacts> facts = walkDicomFile(reported, slice);
  if (!facts) problem.fail("is not a DICOM file");
  if (!facts->imageProblem.empty()) problem.fail(facts->imageProblem);
  gdcm::Reader reader;
  reader.SetFileName(slice.c_str());
  if (!reader.ReadUpToTag(kPixelData, {kPixelData})) problem.fail("is not a readable DICOM file");
  const gdcm::DataSet& data = reader.GetFile().GetDataSet();
  DicomSliceTags tags;
  checkReadableImage(reader.GetFile(), problem);
  checkImagePixelModule(data, problem, tags);
  checkRescale(data, problem);
  checkPlacement(data, problem, requirePlacement, tags);
  tags.study = studyTags(data);
  const gdcm::TransferSyntax syntax = reader.GetFile().GetHeader().GetDataSetTransferSyntax();
  // A deflated data set's offsets are those of the inflated stream; encapsulated pixel data is
  // decoded (and its size checked) by GDCM's codecs.
  if (syntax.IsEncapsulated() || syntax == gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian) {
    tags.encapsulated = true;
    return tags;
  }
  checkPixelDataLength(slice, reader.GetStreamCurrentPosition(), data, problem, tags);
  return tags;
}

}  // namespace angio
