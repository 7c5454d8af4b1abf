#pragma once
// DICOM slices built in memory element by element, as scanners write them (explicit or implicit VR
// little endian, a file meta group, a 4x4 signed 16-bit CT image), so a test can replace, add or
// remove one element and write the bytes: the malformed slices GDCM would assert on, and real-world
// forms ITK's writer does not produce.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/dicom_tag_patch.h"

namespace angio::test_support {

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;
// VRs whose explicit header has 2 reserved bytes and a 4-byte length.
constexpr const char* kLongFormVrs[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                        "SV", "UC", "UN", "UR", "UT", "UV"};

struct DicomTestElement {
  std::uint16_t group = 0, element = 0;
  std::string vr;                // written in explicit VR only
  std::string value;             // padded to an even length when written (text with a space, UI with \0)
  bool undefinedLength = false;  // the value is then written as is (items and delimiters)
};

inline std::string dicomUnsignedShorts(std::initializer_list<int> values) {
  std::string bytes;
  for (const int value : values) bytes += littleEndian(std::uint32_t(value), 2);
  return bytes;
}

// An empty sequence of undefined length: its value is the delimiter alone.
inline std::string emptySequenceValue() {
  return littleEndian(0xfffe, 2) + littleEndian(0xe0dd, 2) + littleEndian(0, 4);
}

class DicomTestSlice {
 public:
  explicit DicomTestSlice(bool explicitVr) : explicitVr_(explicitVr) {}

  // Replaces the element with this tag, or adds it in tag order.
  DicomTestSlice& set(DicomTestElement element) {
    remove(element.group, element.element);
    const auto at = std::find_if(elements_.begin(), elements_.end(),
                                 [&](const DicomTestElement& e) { return key(e) > key(element); });
    elements_.insert(at, std::move(element));
    return *this;
  }
  DicomTestSlice& set(std::uint16_t group, std::uint16_t element, const std::string& vr,
                      const std::string& value) {
    return set(DicomTestElement{group, element, vr, value, false});
  }
  // Adds the element last, out of tag order if it comes before the others.
  DicomTestSlice& append(DicomTestElement element) {
    elements_.push_back(std::move(element));
    return *this;
  }
  DicomTestSlice& remove(std::uint16_t group, std::uint16_t element) {
    std::erase_if(elements_,
                  [&](const DicomTestElement& e) { return e.group == group && e.element == element; });
    return *this;
  }

  // Preamble, "DICM", the meta group (explicit VR, its length computed), then the data set.
  std::string bytes() const {
    std::string meta, data;
    for (const DicomTestElement& element : elements_)
      (element.group == 0x0002 ? meta : data) +=
          encoded(element, element.group == 0x0002 || explicitVr_);
    const std::string groupLength =
        encoded({0x0002, 0x0000, "UL", littleEndian(std::uint32_t(meta.size()), 4)}, true);
    return std::string(128, '\0') + "DICM" + groupLength + meta + data;
  }
  void write(const std::filesystem::path& file) const { overwrite(file, bytes()); }

 private:
  static std::uint32_t key(const DicomTestElement& e) {
    return std::uint32_t(e.group) << 16 | e.element;
  }
  static std::string encoded(const DicomTestElement& element, bool explicitVr) {
    std::string value = element.value;
    if (!element.undefinedLength && value.size() % 2) value += element.vr == "UI" ? '\0' : ' ';
    const std::uint32_t length =
        element.undefinedLength ? kUndefinedLength : std::uint32_t(value.size());
    std::string bytes = littleEndian(element.group, 2) + littleEndian(element.element, 2);
    if (!explicitVr) return bytes + littleEndian(length, 4) + value;
    const bool longForm = std::find(std::begin(kLongFormVrs), std::end(kLongFormVrs), element.vr) !=
                          std::end(kLongFormVrs);
    bytes += element.vr;
    return bytes + (longForm ? littleEndian(0, 2) + littleEndian(length, 4) : littleEndian(length, 2)) +
           value;
  }

  bool explicitVr_;
  std::vector<DicomTestElement> elements_;
};

// A 4x4 CT slice at z (mm) with signed 16-bit pixels (HU = stored - 1024), as a scanner writes it.
inline DicomTestSlice ctTestSlice(double z, bool explicitVr, int instance) {
  const std::string ct = "1.2.840.10008.5.1.4.1.1.2";
  const std::string uid = "1.2.826.0.1.3680043.2.1125.888.1." + std::to_string(instance);
  const std::string syntax = explicitVr ? "1.2.840.10008.1.2.1" : "1.2.840.10008.1.2";
  std::string pixels;
  for (int n = 0; n < 16; ++n) pixels += littleEndian(std::uint32_t(1024 + 10 * n + int(z)), 2);
  DicomTestSlice slice(explicitVr);
  slice.set(0x0002, 0x0001, "OB", std::string("\0\1", 2))
      .set(0x0002, 0x0002, "UI", ct)
      .set(0x0002, 0x0003, "UI", uid)
      .set(0x0002, 0x0010, "UI", syntax)
      .set(0x0008, 0x0016, "UI", ct)
      .set(0x0008, 0x0018, "UI", uid)
      .set(0x0008, 0x0060, "CS", "CT")
      .set(0x0010, 0x0010, "PN", "DOE^JANE")
      .set(0x0020, 0x000d, "UI", "1.2.826.0.1.3680043.2.1125.888")
      .set(0x0020, 0x000e, "UI", "1.2.826.0.1.3680043.2.1125.888.2")
      .set(0x0020, 0x0013, "IS", std::to_string(instance))
      .set(0x0020, 0x0032, "DS", "-1\\-1\\" + std::to_string(z))
      .set(0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0")
      .set(0x0028, 0x0002, "US", dicomUnsignedShorts({1}))
      .set(0x0028, 0x0004, "CS", "MONOCHROME2")
      .set(0x0028, 0x0010, "US", dicomUnsignedShorts({4}))
      .set(0x0028, 0x0011, "US", dicomUnsignedShorts({4}))
      .set(0x0028, 0x0030, "DS", "0.5\\0.5")
      .set(0x0028, 0x0100, "US", dicomUnsignedShorts({16}))
      .set(0x0028, 0x0101, "US", dicomUnsignedShorts({16}))
      .set(0x0028, 0x0102, "US", dicomUnsignedShorts({15}))
      .set(0x0028, 0x0103, "US", dicomUnsignedShorts({1}))
      .set(0x0028, 0x1052, "DS", "-1024")
      .set(0x0028, 0x1053, "DS", "1")
      .set(0x7fe0, 0x0010, "OW", pixels);
  return slice;
}

}  // namespace angio::test_support
