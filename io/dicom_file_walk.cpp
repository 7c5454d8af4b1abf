#include "io/dicom_file_walk.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "io/input_error.h"

namespace angio {

namespace {

namespace fs = std::filesystem;

// The headers before the pixel data lie in the first kilobytes; a multi-frame file's are walked
// up to here (its pixel data's length is checked against the whole file).
constexpr std::uint64_t kMaxWalkedBytes = 64 << 20;
constexpr std::uint64_t kOpen = ~std::uint64_t(0);  // a sequence of undefined length

struct Syntax {
  bool explicitVr = true;
  bool bigEndian = false;
};

class ElementWalk {
 public:
  ElementWalk(const fs::path& reported, const fs::path& file, std::string bytes, std::uint64_t fileSize)
      : reported_(reported), file_(file), bytes_(std::move(bytes)), fileSize_(fileSize) {}

  std::optional<DicomFileFacts> run() {
    std::size_t at = 0;
    if (bytes_.size() >= 132 && bytes_.compare(128, 4, "DICM") == 0) at = 132;
    if (at + 4 > bytes_.size()) return std::nullopt;
    const std::uint16_t firstGroup = read16(at, false);
    if (at == 0 && firstGroup != 0x0002 && firstGroup != 0x0008) return std::nullopt;
    // The file meta group is explicit VR little endian; without it GDCM guesses implicit VR.
    Syntax syntax{firstGroup == 0x0002 || at == 132, false};
    std::string transferSyntax;
    bool inMeta = firstGroup == 0x0002;
    // Where the open sequences end (kOpen: at their delimiter); an item belongs inside one.
    std::vector<std::uint64_t> open;
    while (at + 8 <= bytes_.size()) {
      while (!open.empty() && open.back() != kOpen && at >= open.back()) open.pop_back();
      if (inMeta && read16(at, false) != 0x0002) {
        inMeta = false;
        syntax = syntaxOf(transferSyntax);
        if (transferSyntax.rfind("1.2.840.10008.1.2.1.99", 0) == 0)  // the data set is zlib data
          failFile("its data set is deflated (transfer syntax " + transferSyntax +
                   "), which is not read; store it uncompressed");
      }
      const Syntax current = inMeta ? Syntax{} : syntax;
      const std::uint16_t group = read16(at, current.bigEndian);
      const std::uint16_t element = read16(at + 2, current.bigEndian);
      std::size_t header = 8;
      std::uint64_t length = 0;
      if (group == 0xfffe) {  // item and delimiters: always tag + 4-byte length
        if (open.empty() || (element != 0xe000 && element != 0xe00d && element != 0xe0dd))
          fail(group, element, "is an item tag outside a sequence");
        if (element == 0xe0dd) {
          if (open.back() != kOpen) fail(group, element, "ends a sequence that has a length");
          open.pop_back();
        }
        at += 8;  // an item's contents are walked as elements
        continue;
      }
      if (current.explicitVr) {
        const std::string vr = bytes_.substr(at + 4, 2);
        if (!(std::isupper(static_cast<unsigned char>(vr[0])) &&
              std::isupper(static_cast<unsigned char>(vr[1]))))
          fail(group, element, "has no valid value representation");
        if (!knownVr(vr)) fail(group, element, "has an unknown value representation");
        if (longForm(vr)) {
          if (at + 12 > bytes_.size()) fail(group, element, "is cut off");
          length = read32(at + 8, current.bigEndian);
          header = 12;
        } else {
          length = read16(at + 6, current.bigEndian);
        }
        if (vr == "SQ" && inMeta) fail(group, element, "is a sequence in the file meta group");
        if (vr == "SQ" && length != 0xffffffffu && length <= fileSize_ - at - header) {
          open.push_back(at + header + length);  // walked into
          length = 0;
        }
      } else {
        length = read32(at + 4, current.bigEndian);
      }
      if (length == 0xffffffffu) {  // undefined: a sequence or encapsulated data, walked into
        if (inMeta) fail(group, element, "has an undefined length in the file meta group");
        open.push_back(kOpen);
        at += header;
        continue;
      }
      const std::uint64_t left = fileSize_ - at - header;
      if (length > left)
        fail(group, element,
             "claims " + std::to_string(length) + " bytes where the file has " + std::to_string(left) +
                 " left");
      if (group == 0x0002 && element == 0x0010) transferSyntax = value(at + header, length);
      if (open.empty()) noteTopLevel(group, element, at + header, length);
      at += header + length;
    }
    requireWholeElements(at, inMeta);
    return facts_;
  }

 private:
  // The walk stopped less than a header before the end: GDCM asserts on a file that ends inside its
  // meta group (it reads on for the first data set element) or inside an element header.
  void requireWholeElements(std::uint64_t at, bool inMeta) const {
    if (bytes_.size() < fileSize_) return;  // only the first kMaxWalkedBytes were walked
    if (inMeta) failFile("the file ends inside its file meta group");
    if (at < fileSize_)
      failFile("the file ends " + std::to_string(fileSize_ - at) + " bytes into an element header");
  }
  void noteTopLevel(std::uint16_t group, std::uint16_t element, std::uint64_t valueAt,
                    std::uint64_t length) {
    if (group == 0x0020 && element == 0x000e) facts_.seriesUid = value(valueAt, length);
    if (group == 0x7fe0 && element == 0x0010) facts_.hasPixelData = true;
  }
  // A short text value (a UID), without its padding; cut at 64 bytes, a UID's most.
  std::string value(std::uint64_t at, std::uint64_t length) const {
    if (at >= bytes_.size()) return "";
    std::string text = bytes_.substr(at, std::min<std::uint64_t>(length, 64));
    while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
    return text;
  }
  static bool knownVr(const std::string& vr) {
    static constexpr const char* kVrs[] = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL",
                                           "IS", "LO", "LT", "OB", "OD", "OF", "OL", "OV", "OW",
                                           "PN", "SH", "SL", "SQ", "SS", "ST", "SV", "TM", "UC",
                                           "UI", "UL", "UN", "UR", "US", "UT", "UV"};
    for (const char* candidate : kVrs)
      if (vr == candidate) return true;
    return false;
  }
  static bool longForm(const std::string& vr) {
    for (const char* candidate :
         {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV"})
      if (vr == candidate) return true;
    return false;
  }
  static Syntax syntaxOf(const std::string& uid) {
    if (uid == "1.2.840.10008.1.2") return {false, false};
    if (uid == "1.2.840.10008.1.2.2") return {true, true};
    return {true, false};
  }
  std::uint16_t read16(std::size_t at, bool bigEndian) const {
    const auto b = [&](std::size_t n) {
      return std::uint16_t(static_cast<unsigned char>(bytes_[at + n]));
    };
    return bigEndian ? std::uint16_t(b(0) << 8 | b(1)) : std::uint16_t(b(1) << 8 | b(0));
  }
  std::uint32_t read32(std::size_t at, bool bigEndian) const {
    const std::uint32_t high = read16(at + (bigEndian ? 0 : 2), bigEndian);
    const std::uint32_t low = read16(at + (bigEndian ? 2 : 0), bigEndian);
    return high << 16 | low;
  }
  [[noreturn]] void fail(std::uint16_t group, std::uint16_t element, const std::string& problem) const {
    char tag[16];
    std::snprintf(tag, sizeof tag, "(%04x,%04x)", group, element);
    failFile(std::string("element ") + tag + " " + problem);
  }
  [[noreturn]] void failFile(const std::string& problem) const {
    const std::string where = reported_ == file_ ? "" : "slice " + file_.filename().string() + ": ";
    throw InputError(reported_, where + problem + " (a damaged DICOM file)");
  }

  const fs::path& reported_;
  const fs::path& file_;
  std::string bytes_;       // the file's first kMaxWalkedBytes
  std::uint64_t fileSize_;  // what the lengths are checked against
  DicomFileFacts facts_;
};

}  // namespace

std::optional<DicomFileFacts> walkDicomFile(const fs::path& reported, const fs::path& file) {
  std::error_code error;
  const std::uint64_t size = fs::file_size(file, error);
  std::ifstream in(file, std::ios::binary);
  if (error || !in) return std::nullopt;
  std::string bytes(std::min(size, kMaxWalkedBytes), '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  bytes.resize(std::size_t(in.gcount()));
  return ElementWalk(reported, file, std::move(bytes), size).run();
}

}  // namespace angio
