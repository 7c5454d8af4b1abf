#include "io/dicom_element_check.h"
#include "io/shown_text.h"

#include <array>
#include <cstdio>

#include <gdcmGlobal.h>
#include <gdcmDicts.h>
#include <gdcmTag.h>
#include <gdcmVR.h>

namespace angio {

namespace {

using VrType = gdcm::VR::VRType;

// The image pixel module's counts and sizes: GDCM reads each with Attribute<> as one US value and
// asserts on anything else.
constexpr std::array<std::uint16_t, 10> kSingleUsPixelTags = {
    0x0002,  // SamplesPerPixel
    0x0005,  // ImageDimensions (ACR-NEMA)
    0x0006,  // PlanarConfiguration
    0x0010,  // Rows
    0x0011,  // Columns
    0x0012,  // Planes (ACR-NEMA)
    0x0100,  // BitsAllocated
    0x0101,  // BitsStored
    0x0102,  // HighBit
    0x0103,  // PixelRepresentation
};

// VRs GDCM 3.0 parses but has no string form or Attribute for (added to DICOM after its design).
constexpr std::array<const char*, 5> kUnreadVrs = {"OD", "OL", "OV", "SV", "UV"};

// SOP classes of single-frame images (CT, MR, PET, CR, secondary capture): the others are
// multi-frame (enhanced, ultrasound, NM, X-ray angiography), RT dose grids, or not images.
constexpr std::array<const char*, 5> kSingleFrameImageClasses = {
    "1.2.840.10008.5.1.4.1.1.2",    // CT Image Storage
    "1.2.840.10008.5.1.4.1.1.4",    // MR Image Storage
    "1.2.840.10008.5.1.4.1.1.128",  // Positron Emission Tomography Image Storage
    "1.2.840.10008.5.1.4.1.1.1",    // Computed Radiography Image Storage
    "1.2.840.10008.5.1.4.1.1.7",    // Secondary Capture Image Storage
};

constexpr std::array<const char*, 12> kReadTransferSyntaxes = {
    "1.2.840.10008.1.2",      "1.2.840.10008.1.2.1",    "1.2.840.10008.1.2.2",
    "1.2.840.10008.1.2.4.50", "1.2.840.10008.1.2.4.51", "1.2.840.10008.1.2.4.57",
    "1.2.840.10008.1.2.4.70", "1.2.840.10008.1.2.4.80", "1.2.840.10008.1.2.4.81",
    "1.2.840.10008.1.2.4.90", "1.2.840.10008.1.2.4.91", "1.2.840.10008.1.2.5",
};

// The recognition codes GDCM's image reader accepts (it asserts the value starts with one).
constexpr std::array<std::string_view, 3> kRecognitionCodes = {"ACR-NEMA", "ACRNEMA", "MIPS 2.0"};

template <std::size_t N>
bool listed(const std::array<const char*, N>& list, std::string_view text) {
  for (const char* entry : list)
    if (text == entry) return true;
  return false;
}

std::string trimmedText(std::string_view value) {
  while (!value.empty() && (value.back() == '\0' || value.back() == ' ')) value.remove_suffix(1);
  while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
  return std::string(value);
}

std::uint16_t unsigned16(std::string_view value, bool bigEndian) {
  const auto byte = [&](std::size_t n) { return std::uint16_t(static_cast<unsigned char>(value[n])); };
  return bigEndian ? std::uint16_t(byte(0) << 8 | byte(1)) : std::uint16_t(byte(1) << 8 | byte(0));
}

VrType dictionaryVr(const DicomElementHeader& header) {
  if (header.group % 2 == 1 || header.element == 0x0000) return gdcm::VR::INVALID;
  const gdcm::Dicts& dicts = gdcm::Global::GetInstance().GetDicts();
  return dicts.GetPublicDict().GetDictEntry(gdcm::Tag(header.group, header.element)).GetVR();
}

// The size of one value of a binary VR (0 for text, bulk data and sequences).
std::uint64_t binarySize(VrType vr) {
  switch (vr) {
    case gdcm::VR::US:
    case gdcm::VR::SS:
    case gdcm::VR::US_SS: return 2;
    case gdcm::VR::UL:
    case gdcm::VR::SL:
    case gdcm::VR::FL:
    case gdcm::VR::AT: return 4;
    case gdcm::VR::FD: return 8;
    default: return 0;
  }
}

bool isPrivateCreator(const DicomElementHeader& header) {
  return header.group % 2 == 1 && header.element >= 0x0010 && header.element <= 0x00ff;
}

bool isSingleUsPixelTag(const DicomElementHeader& header) {
  if (header.group != 0x0028) return false;
  for (const std::uint16_t element : kSingleUsPixelTags)
    if (header.element == element) return true;
  return false;
}

// Group lengths (gggg,0000) and the image pixel module's counts: one value of exactly this form
// (whatever GDCM's dictionary says of the retired ones).
std::string fixedFormProblem(const DicomElementHeader& header) {
  const bool groupLength = header.element == 0x0000;
  const std::string vr = groupLength ? "UL" : "US";
  const std::uint64_t bytes = groupLength ? 4 : 2;
  if (!header.vr.empty() && header.vr != vr)
    return "has value representation " + header.vr + " where DICOM has one " + vr + " value";
  if (header.length != bytes)
    return "has a value of " + std::to_string(header.length) + " bytes where DICOM has one " + vr +
           " value";
  return "";
}

// Explicit VR against the dictionary's, for what GDCM reads as numbers or as a sequence.
std::string explicitVrProblem(const DicomElementHeader& header, VrType dictionary) {
  const VrType file = gdcm::VR::GetVRType(header.vr.c_str());
  if (listed(kUnreadVrs, header.vr))
    return "has value representation " + header.vr + ", which is not read";
  if (header.vr == "UN" || dictionary == gdcm::VR::INVALID || dictionary == gdcm::VR::UN) return "";
  const char* expected = gdcm::VR::GetVRString(dictionary);
  if (file == gdcm::VR::SQ && dictionary != gdcm::VR::SQ)
    return std::string("is a sequence where DICOM has a value (") + expected + ")";
  if (file != gdcm::VR::SQ && dictionary == gdcm::VR::SQ)
    return "has a value (" + header.vr + ") where DICOM has a sequence";
  if (binarySize(dictionary) > 0 && (file & dictionary) == 0)
    return "has value representation " + header.vr + " where DICOM has " + expected;
  return "";
}

std::string lengthProblem(const DicomElementHeader& header, VrType dictionary) {
  const bool undefined = header.length == kDicomUndefinedLength;
  const VrType file = header.vr.empty() ? dictionary : gdcm::VR::GetVRType(header.vr.c_str());
  if (undefined && header.vr.empty() && dictionary != gdcm::VR::INVALID && dictionary != gdcm::VR::UN &&
      dictionary != gdcm::VR::SQ && !(header.group == 0x7fe0 && header.element == 0x0010))
    return "has an undefined length where DICOM has a value";
  if (undefined && !header.vr.empty() && header.vr != "SQ" && header.vr != "UN" &&
      !(header.group == 0x7fe0 && header.element == 0x0010))
    return "has an undefined length but value representation " + header.vr;
  const std::uint64_t size = binarySize(file == gdcm::VR::INVALID ? dictionary : file);
  if (size > 0 && !undefined && header.length % size != 0)
    return "has a value of " + std::to_string(header.length) + " bytes, not a whole number of " +
           std::to_string(size) + "-byte values";
  return "";
}

}  // namespace

bool dicomDictionarySequence(std::uint16_t group, std::uint16_t element) {
  return dictionaryVr(DicomElementHeader{group, element}) == gdcm::VR::SQ;
}

std::string dicomElementProblem(const DicomElementHeader& header, std::string_view) {
  if (isPrivateCreator(header) && (header.vr == "SQ" || header.length == kDicomUndefinedLength))
    return "is a private creator encoded as a sequence";
  if (header.element == 0x0000 || isSingleUsPixelTag(header)) return fixedFormProblem(header);
  const VrType dictionary = dictionaryVr(header);
  if (!header.vr.empty()) {
    const std::string vr = explicitVrProblem(header, dictionary);
    if (!vr.empty()) return vr;
  } else if ((dictionary == gdcm::VR::US_SS || dictionary == gdcm::VR::US_SS_OW) &&
             !header.pixelRepresentationKnown) {
    // Implicit VR: GDCM takes US or SS from PixelRepresentation, which must come first.
    return "is US or SS in implicit VR before PixelRepresentation (0028,0103) says which";
  }
  return lengthProblem(header, dictionary);
}

std::string dicomImageProblem(const DicomElementHeader& header, std::string_view value) {
  const std::uint32_t tag = std::uint32_t(header.group) << 16 | header.element;
  if (header.group == 0x5400) return "has waveform data (5400), which is not read";
  if (tag == 0x00020002 || tag == 0x00080016) {
    const std::string uid = trimmedText(value);
    if (!listed(kSingleFrameImageClasses, uid))
      return "is of SOP class '" + shownText(uid) +
             "', not a single-frame CT, MR, PET, CR or secondary capture image";
  }
  if (tag == 0x00280008 && trimmedText(value) != "1")
    return "has NumberOfFrames (0028,0008) '" + shownText(trimmedText(value)) +
           "'; need single-frame slices";
  if (tag == 0x00280005 && value.size() == 2 && unsigned16(value, header.bigEndian) != 2)
    return "has ImageDimensions (0028,0005) " + std::to_string(unsigned16(value, header.bigEndian)) +
           "; need 2-D slices";
  if (tag == 0x00080010 && !trimmedText(value).empty()) {
    for (const std::string_view code : kRecognitionCodes)
      if (value.substr(0, code.size()) == code) return "";
    return "has a RecognitionCode (0008,0010) '" + shownText(trimmedText(value)) +
           "' that is not ACR-NEMA's";
  }
  return "";
}

std::string dicomTransferSyntaxProblem(const std::string& uid) {
  if (listed(kReadTransferSyntaxes, uid)) return "";
  return "has transfer syntax '" + shownText(uid) +
         "', which is not read (need native, JPEG, JPEG-LS, JPEG 2000 or RLE)";
}

}  // namespace angio
