#include "io/dicom_file_walk.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/dicom_element_check.h"
#include "io/input_error.h"

namespace angio {

namespace {

namespace fs = std::filesystem;

// The headers before the pixel data lie in the first kilobytes; a multi-frame file's are walked
// up to here (its pixel data's length is checked against the whole file).
constexpr std::uint64_t kMaxWalkedBytes = 64 << 20;
constexpr std::uint64_t kOpen = ~std::uint64_t(0);  // the end of a container of undefined length

struct Syntax {
  bool explicitVr = true;
  bool bigEndian = false;
};

// What the walk is inside: a sequence (its items hold elements), an item (one of undefined length
// ends at an item delimiter) or encapsulated pixel data (its items are compressed fragments,
// stepped over whole).
struct Container {
  enum class Kind { sequence, item, fragments };
  Kind kind;
  std::uint64_t end;        // kOpen: at its delimiter
  bool implicitVr = false;  // its data set is implicit VR little endian (inside a UN sequence)
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
    // PS3.10 7.1: the file meta group follows the preamble. Without it GDCM guesses the syntax,
    // byte order included, and reads lengths this walk does not see (a 3.9 GB one, say).
    if (at == 132 && firstGroup != 0x0002) failFile("has no file meta group (0002) after its preamble");
    // The file meta group is explicit VR little endian. A bare data set (no preamble, group 0008
    // first) GDCM reads as explicit VR when a VR's name follows its first tag, as implicit VR
    // otherwise (gdcm::FileMetaInformation::ReadCompat); the walk reads it as GDCM will.
    const bool bareExplicit = firstGroup == 0x0008 && guessedExplicitVr(bytes_.substr(at + 4, 2));
    Syntax syntax{firstGroup == 0x0002 || at == 132 || bareExplicit, false};
    std::string transferSyntax;
    bool inMeta = firstGroup == 0x0002;
    // The sequences, items and encapsulated pixel data the walk is inside, innermost last.
    std::vector<Container> open;
    while (at + 8 <= bytes_.size()) {
      while (!open.empty() && open.back().end != kOpen && at >= open.back().end) open.pop_back();
      if (inMeta && read16(at, false) != 0x0002) {
        inMeta = false;
        syntax = syntaxOf(transferSyntax);
        if (transferSyntax.rfind("1.2.840.10008.1.2.1.99", 0) == 0)  // the data set is zlib data
          refuse("its data set is deflated (transfer syntax " + transferSyntax +
                 "), which is not read; store it uncompressed");
        if (transferSyntax.empty()) failFile("its file meta group has no TransferSyntaxUID (0002,0010)");
        if (const std::string problem = dicomTransferSyntaxProblem(transferSyntax); !problem.empty())
          refuse("its data set " + problem);
      }
      const bool implicitInside = !open.empty() && open.back().implicitVr;
      const Syntax current = inMeta ? Syntax{} : implicitInside ? Syntax{false, false} : syntax;
      const std::uint16_t group = read16(at, current.bigEndian);
      const std::uint16_t elementNumber = read16(at + 2, current.bigEndian);
      if (group == 0xfffe) {  // items and delimiters: always tag + 4-byte length
        at = afterItemTag(at, elementNumber, read32(at + 4, current.bigEndian), open);
        continue;
      }
      std::size_t header = 8;
      const DicomElementHeader element = headerAt(at, current, inMeta, open.empty(), header);
      checkElement(element, at + header);
      std::uint64_t length = element.length;
      const bool sequence =
          current.explicitVr ? element.vr == "SQ" : dicomDictionarySequence(group, elementNumber);
      if (sequence && length != 0xffffffffu && length <= fileSize_ - at - header) {
        open.push_back(
            {Container::Kind::sequence, at + header + length, implicitInside});  // walked into
        length = 0;
      }
      if (length == 0xffffffffu) {  // undefined: a sequence or encapsulated data, walked into
        if (inMeta) fail(group, elementNumber, "has an undefined length in the file meta group");
        // PS3.5 7.1.3; GDCM asserts on any other VR (gdcm::ExplicitDataElement::ReadValue).
        if (current.explicitVr && !undefinedLengthAllowed(element.vr))
          fail(group, elementNumber,
               "has an undefined length with VR " + element.vr + " (only SQ, UN, OB and OW may)");
        const bool pixels = group == 0x7fe0 && elementNumber == 0x0010;
        // A sequence of unknown VR holds an implicit VR little endian data set (PS3.5 6.2.2).
        const bool unknown = current.explicitVr && element.vr == "UN";
        open.push_back({pixels ? Container::Kind::fragments : Container::Kind::sequence, kOpen,
                        implicitInside || unknown});
        if (open.size() == 1) noteTopLevel(group, elementNumber, at + header, 0);
        at += header;
        continue;
      }
      const std::uint64_t left = fileSize_ - at - header;
      if (length > left)
        fail(group, elementNumber,
             "claims " + std::to_string(length) + " bytes where the file has " + std::to_string(left) +
                 " left");
      if (group == 0x0002 && elementNumber == 0x0010) transferSyntax = value(at + header, length);
      if (open.empty()) noteTopLevel(group, elementNumber, at + header, length);
      at += header + length;
    }
    requireWholeElements(at, inMeta);
    requireClosed(open);
    return facts_;
  }

 private:
  // The header of the element at `at` (whose tag is read); `header` becomes its size in bytes.
  DicomElementHeader headerAt(std::size_t at, Syntax syntax, bool inMeta, bool topLevel,
                              std::size_t& header) const {
    DicomElementHeader element{read16(at, syntax.bigEndian),
                               read16(at + 2, syntax.bigEndian),
                               "",
                               0,
                               syntax.bigEndian,
                               topLevel,
                               pixelRepresentationKnown_};
    header = 8;
    if (!syntax.explicitVr) {
      element.length = read32(at + 4, syntax.bigEndian);
      return element;
    }
    element.vr = bytes_.substr(at + 4, 2);
    const auto fail = [&](const std::string& problem) {
      this->fail(element.group, element.element, problem);
    };
    if (!(std::isupper(static_cast<unsigned char>(element.vr[0])) &&
          std::isupper(static_cast<unsigned char>(element.vr[1]))))
      fail("has no valid value representation");
    if (!knownVr(element.vr)) fail("has an unknown value representation");
    if (element.vr == "SQ" && inMeta) fail("is a sequence in the file meta group");
    if (longForm(element.vr)) {
      if (at + 12 > bytes_.size()) fail("is cut off");
      header = 12;
      element.length = read32(at + 8, syntax.bigEndian);
    } else {
      element.length = read16(at + 6, syntax.bigEndian);
    }
    return element;
  }
  // Steps over the item or delimiter tag at `at` (its 4-byte length is `length`); returns where the
  // walk goes on. GDCM asserts on an item of undefined length the file ends in, and allocates an
  // item's length before it reads it.
  std::uint64_t afterItemTag(std::uint64_t at, std::uint16_t elementNumber, std::uint32_t length,
                             std::vector<Container>& open) const {
    const auto fail = [&](const std::string& problem) { this->fail(0xfffe, elementNumber, problem); };
    const auto innermost = [&](Container::Kind kind) {
      return !open.empty() && open.back().kind == kind;
    };
    const bool undefined = length == 0xffffffffu;
    // A delimiter's length is 0 (PS3.5 7.5). GDCM reads a delimiter of encapsulated pixel data as
    // one more fragment and allocates its length; elsewhere it only warns.
    const bool delimiter = elementNumber == 0xe00d || elementNumber == 0xe0dd;
    if (delimiter && length != 0 &&
        (innermost(Container::Kind::fragments) || length > fileSize_ - at - 8))
      fail("is a delimiter with a length of " + std::to_string(length) + " (a delimiter has none)");
    switch (elementNumber) {
      case 0xe000: {  // an item
        if (open.empty() || innermost(Container::Kind::item)) fail("is an item tag outside a sequence");
        if (!undefined && length > fileSize_ - at - 8)
          fail("claims " + std::to_string(length) + " bytes where the file has " +
               std::to_string(fileSize_ - at - 8) + " left");
        if (innermost(Container::Kind::fragments)) {
          if (undefined) fail("is a pixel data fragment of undefined length");
          return at + 8 + length;
        }
        open.push_back(
            {Container::Kind::item, undefined ? kOpen : at + 8 + length, open.back().implicitVr});
        return at + 8;  // its elements are walked
      }
      case 0xe00d:  // an item's end (GDCM refuses a stray one itself, without asserting)
        if (innermost(Container::Kind::item) && open.back().end == kOpen) open.pop_back();
        return at + 8;
      case 0xe0dd:  // a sequence's end
        // GDCM asserts when it meets one in an item of undefined length (in implicit VR at least).
        if (innermost(Container::Kind::item) && open.back().end == kOpen)
          fail("ends a sequence inside an item that was not ended");
        if (open.empty() || innermost(Container::Kind::item)) fail("ends a sequence outside a sequence");
        if (open.back().end != kOpen) fail("ends a sequence that has a length");
        open.pop_back();
        return at + 8;
      default: this->fail(0xfffe, elementNumber, "is an item tag outside a sequence");
    }
  }
  // GDCM asserts when the file ends inside an item of undefined length; a sequence or encapsulated
  // pixel data without its delimiter is as damaged.
  void requireClosed(const std::vector<Container>& open) const {
    if (bytes_.size() < fileSize_) return;  // only the first kMaxWalkedBytes were walked
    for (auto container = open.rbegin(); container != open.rend(); ++container)  // innermost first
      if (container->end == kOpen)
        failFile(container->kind == Container::Kind::item
                     ? "the file ends inside an item of undefined length"
                 : container->kind == Container::Kind::fragments
                     ? "the file ends inside its encapsulated pixel data"
                     : "the file ends inside a sequence of undefined length");
  }
  // The walk stopped less than a header before the end: GDCM asserts on a file that ends inside its
  // meta group (it reads on for the first data set element) or inside an element header.
  void requireWholeElements(std::uint64_t at, bool inMeta) const {
    if (bytes_.size() < fileSize_) return;  // only the first kMaxWalkedBytes were walked
    if (inMeta) failFile("the file ends inside its file meta group");
    if (at < fileSize_)
      failFile("the file ends " + std::to_string(fileSize_ - at) + " bytes into an element header");
  }
  // GDCM's expectations of one element (io/dicom_element_check.h): a malformed one is refused at
  // once; one an image must not have (its SOP class, frames, ...) only if the file is an image.
  void checkElement(const DicomElementHeader& element, std::uint64_t valueAt) {
    const std::string_view value = valueBytes(valueAt, element.length);
    if (const std::string problem = dicomElementProblem(element, value); !problem.empty())
      fail(element.group, element.element, problem);
    if (!element.topLevel) return;
    // GDCM keeps the first of two equal tags and sorts the rest: what the walk saw would not be
    // what GDCM reads.
    const std::uint32_t tag = std::uint32_t(element.group) << 16 | element.element;
    if (lastTopLevelTag_ && tag <= *lastTopLevelTag_)
      fail(element.group, element.element, "is out of order (tags must ascend)");
    lastTopLevelTag_ = tag;
    if (element.group == 0x0028 && element.element == 0x0103) pixelRepresentationKnown_ = true;
    if (facts_.imageProblem.empty()) facts_.imageProblem = dicomImageProblem(element, value);
  }
  // The value bytes the walk holds (none for an undefined length, cut at the end of what was read).
  std::string_view valueBytes(std::uint64_t at, std::uint64_t length) const {
    if (length == kDicomUndefinedLength || at >= bytes_.size()) return {};
    return std::string_view(bytes_).substr(at, std::min<std::uint64_t>(length, bytes_.size() - at));
  }
  void noteTopLevel(std::uint16_t group, std::uint16_t element, std::uint64_t valueAt,
                    std::uint64_t length) {
    // GDCM keeps the first of a repeated element (implicit VR files have no order to check).
    if (group == 0x0020 && element == 0x000e && !seriesUidSeen_) {
      facts_.seriesUid = value(valueAt, length);
      seriesUidSeen_ = true;
    }
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
  static bool undefinedLengthAllowed(const std::string& vr) {
    return vr == "SQ" || vr == "UN" || vr == "OB" || vr == "OW";
  }
  // GDCM's guess takes any name of its VR table, its "??" (an invalid VR) among them.
  static bool guessedExplicitVr(const std::string& vr) { return knownVr(vr) || vr == "??"; }
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
    refuse(problem + " (a damaged DICOM file)");
  }
  [[noreturn]] void refuse(const std::string& problem) const {
    const std::string where = reported_ == file_ ? "" : "slice " + file_.filename().string() + ": ";
    throw InputError(reported_, where + problem);
  }

  const fs::path& reported_;
  const fs::path& file_;
  std::string bytes_;       // the file's first kMaxWalkedBytes
  std::uint64_t fileSize_;  // what the lengths are checked against
  DicomFileFacts facts_;
  bool seriesUidSeen_ = false;
  bool pixelRepresentationKnown_ = false;         // (0028,0103) was met at the top level
  std::optional<std::uint32_t> lastTopLevelTag_;  // the tag before, (group << 16 | element)
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
