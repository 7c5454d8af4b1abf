#pragma once
// Checking one DICOM data element against what GDCM expects of it, as our walk of a file meets it
// (io/dicom_file_walk.h). Debian builds GDCM with assertions on: its Attribute<> and image reader
// assert when a tag it reads as a number (Rows, BitsAllocated, ...) has another value
// representation or length, when a sequence stands where a value belongs (or a value where a
// sequence belongs), on VRs it has no string form for, on a RecognitionCode (0008,0010) that is not
// ACR-NEMA's and on image layouts it only half supports (several frames, ImageDimensions 3). Each
// check says what is wrong in a few words, for a one-line message; empty when nothing is.
#include <cstdint>
#include <string>
#include <string_view>

namespace angio {

constexpr std::uint64_t kDicomUndefinedLength = 0xffffffffu;

// One element's header as the file encodes it.
struct DicomElementHeader {
  std::uint16_t group = 0, element = 0;
  std::string vr;                         // explicit VR; empty in implicit VR (the dictionary's applies)
  std::uint64_t length = 0;               // kDicomUndefinedLength: a sequence or encapsulated pixel data
  bool bigEndian = false;                 // how its numbers are stored
  bool topLevel = true;                   // not inside a sequence item
  bool pixelRepresentationKnown = false;  // (0028,0103) came before it

  bool operator==(const DicomElementHeader&) const = default;
};

// Why GDCM must not read the element (its VR or length contradicts the dictionary, a sequence
// where a value belongs, ...), or empty. `value` holds its value bytes (cut short for pixel data).
std::string dicomElementProblem(const DicomElementHeader& header, std::string_view value);

// Why GDCM's image reader must not read a file with this top-level element, though the element is
// well formed: a SOP class that is not a single-frame image, several frames, waveform data, a
// RecognitionCode that is not ACR-NEMA's (GDCM asserts it is). Empty when there is none.
std::string dicomImageProblem(const DicomElementHeader& header, std::string_view value);

// Whether DICOM's dictionary has a sequence at this public tag (an implicit-VR file does not say).
bool dicomDictionarySequence(std::uint16_t group, std::uint16_t element);

// Why the data set's transfer syntax (its UID, padding removed) is not read, or empty: the native
// syntaxes and the JPEG, JPEG-LS, JPEG 2000 and RLE codecs GDCM decodes.
std::string dicomTransferSyntaxProblem(const std::string& uid);

}  // namespace angio
