#include "io/centerline_vtp.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/number_text.h"
#include "io/shown_text.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

// A problem inside one DataArray; readDataArray adds the array's name and the file.
struct ArrayProblem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// --- File-wide settings -------------------------------------------------------------------------

struct Encoding {
  std::size_t headerWordBytes = 4;  // header_type UInt32 (VTK's default) or UInt64
  bool swapBytes = false;           // byte_order differs from this machine's
  bool zlib = false;                // compressor="vtkZLibDataCompressor"
};

struct AppendedData {
  bool present = false;
  bool base64 = false;
  std::string_view bytes;  // from the byte after '_'
};

// The XML part of a file, and its appended data, which is not XML (raw bytes may hold '<' or NUL)
// and so is cut off before parsing, as VTK's own parser does: the <AppendedData> tag is closed
// artificially and the document ended after it.
struct SplitFile {
  std::string xml;
  std::optional<std::string_view> appended;  // from the byte after '_'
};

SplitFile splitAppendedData(const std::string& bytes, const fs::path& source) {
  const std::size_t tag = bytes.find("<AppendedData");
  if (tag == std::string::npos) return {bytes, std::nullopt};
  const std::size_t tagEnd = bytes.find('>', tag);
  if (tagEnd == std::string::npos) throw InputError(source, "bad XML: <AppendedData> tag not closed");
  const bool selfClosing = bytes[tagEnd - 1] == '/';
  SplitFile split{bytes.substr(0, selfClosing ? tagEnd - 1 : tagEnd) + "/>\n</VTKFile>\n", {}};
  if (selfClosing) return split;
  std::size_t marker = tagEnd + 1;
  while (marker < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[marker]))) ++marker;
  if (marker >= bytes.size() || bytes[marker] != '_') {
    throw InputError(source, "appended data does not start with '_'");
  }
  const std::size_t close = bytes.rfind("</AppendedData>");
  const std::size_t end = close == std::string::npos || close < marker ? bytes.size() : close;
  split.appended = std::string_view(bytes).substr(marker + 1, end - marker - 1);
  return split;
}

// Integers print as integers ("130", not "130.000000").
std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string attribute(const pugi::xml_node& node, const char* name, const char* fallback = "") {
  const pugi::xml_attribute found = node.attribute(name);
  return found ? found.value() : fallback;
}

Encoding fileEncoding(const pugi::xml_node& root, const fs::path& source) {
  Encoding encoding;
  const std::string byteOrder = attribute(root, "byte_order", "LittleEndian");
  if (byteOrder != "LittleEndian" && byteOrder != "BigEndian") {
    throw InputError(source, "unknown byte_order " + quotedText(byteOrder));
  }
  const bool fileIsBig = byteOrder == "BigEndian";
  encoding.swapBytes = fileIsBig != (std::endian::native == std::endian::big);
  const std::string headerType = attribute(root, "header_type", "UInt32");
  if (headerType == "UInt64") {
    encoding.headerWordBytes = 8;
  } else if (headerType != "UInt32") {
    throw InputError(source, "unsupported header_type " + quotedText(headerType));
  }
  const std::string compressor = attribute(root, "compressor");
  if (compressor == "vtkZLibDataCompressor") {
    encoding.zlib = true;
  } else if (!compressor.empty()) {
    throw InputError(source, "unsupported compressor " + quotedText(compressor) + " (only zlib)");
  }
  return encoding;
}

AppendedData appendedData(const pugi::xml_node& root, const SplitFile& split, const fs::path& source) {
  const pugi::xml_node element = root.child("AppendedData");
  if (!element || !split.appended) return {};
  const std::string encoding = attribute(element, "encoding", "raw");
  if (encoding != "raw" && encoding != "base64") {
    throw InputError(source, "unknown AppendedData encoding " + quotedText(encoding));
  }
  return {true, encoding == "base64", *split.appended};
}

// --- Encoded bytes ------------------------------------------------------------------------------

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// A character for a one-line message: 'c', or its code if it is not printable.
std::string shown(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return std::string("'") + c + "'";
  char code[16];
  std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned char>(c));
  return code;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Bytes read in order from raw data or from base64 text. VTK encodes a binary array's header and
// data as one base64 stream, except with compression, where the header is a stream of its own
// (padded) and the blocks another: endStream() drops what is left of the current 4-character group.
class ByteStream {
 public:
  ByteStream(std::string_view input, bool base64) : input_(input), base64_(base64) {}

  // An upper bound of the bytes left, to refuse sizes the input cannot hold before allocating.
  std::size_t available() const {
    const std::size_t left = input_.size() - position_;
    return (pending_.size() - pendingUsed_) + (base64_ ? left / 4 * 3 + 3 : left);
  }

  std::string read(std::size_t count) {
    if (count > available()) throw ArrayProblem("data ends early");
    std::string out;
    out.reserve(count);
    if (!base64_) {
      out.assign(input_.substr(position_, count));
      position_ += count;
      return out;
    }
    while (out.size() < count) {
      if (pendingUsed_ == pending_.size()) decodeGroup();
      const std::size_t take = std::min(count - out.size(), pending_.size() - pendingUsed_);
      out.append(pending_, pendingUsed_, take);
      pendingUsed_ += take;
    }
    return out;
  }

  // Ends the current base64 stream: what is left of its last group is padding.
  void endStream() {
    pending_.clear();
    pendingUsed_ = 0;
    ended_ = false;
  }

 private:
  void decodeGroup() {
    if (ended_) throw ArrayProblem("data ends early (base64 padding inside the data)");
    char group[4];
    for (char& c : group) {
      while (position_ < input_.size() && isSpace(input_[position_])) ++position_;
      if (position_ == input_.size()) throw ArrayProblem("data ends early");
      c = input_[position_++];
    }
    const int padding = (group[3] == '=') + (group[2] == '=' && group[3] == '=');
    std::uint32_t bits = 0;
    for (int n = 0; n < 4; ++n) {
      const int value = n >= 4 - padding ? 0 : base64Value(group[n]);
      if (value < 0) throw ArrayProblem("invalid base64 character " + shown(group[n]));
      bits = bits << 6 | std::uint32_t(value);
    }
    pending_.assign({char(bits >> 16), char(bits >> 8 & 0xFF), char(bits & 0xFF)});
    pending_.resize(3 - padding);
    pendingUsed_ = 0;
    ended_ = padding > 0;  // a padded group is the last of its stream
  }

  std::string_view input_;
  bool base64_;
  std::size_t position_ = 0;
  std::string pending_;
  std::size_t pendingUsed_ = 0;
  bool ended_ = false;
};

// Copies one word of `size` bytes (at most 8) into `word`, in this machine's byte order.
void loadWord(const char* in, std::size_t size, bool swapBytes, unsigned char (&word)[8]) {
  for (std::size_t b = 0; b < size && b < 8; ++b) {
    word[b] = static_cast<unsigned char>(in[swapBytes ? size - 1 - b : b]);
  }
}

std::uint64_t wordAt(const std::string& bytes, std::size_t index, std::size_t wordBytes,
                     bool swapBytes) {
  unsigned char word[8] = {};
  loadWord(bytes.data() + index * wordBytes, wordBytes, swapBytes, word);
  if (wordBytes == 4) {
    std::uint32_t value;
    std::memcpy(&value, word, 4);
    return value;
  }
  std::uint64_t value;
  std::memcpy(&value, word, 8);
  return value;
}

std::string sizeMismatch(std::uint64_t bytes, std::size_t expectedBytes) {
  return "holds " + std::to_string(bytes) + " bytes, expected " + std::to_string(expectedBytes);
}

// Uncompressed: one header word (the byte count), then the data.
std::string readUncompressed(ByteStream& in, const Encoding& encoding, std::size_t expectedBytes) {
  const std::uint64_t bytes =
      wordAt(in.read(encoding.headerWordBytes), 0, encoding.headerWordBytes, encoding.swapBytes);
  if (bytes != expectedBytes) throw ArrayProblem(sizeMismatch(bytes, expectedBytes));
  return in.read(expectedBytes);
}

void inflateBlock(const std::string& compressed, char* out, std::size_t outBytes) {
  uLongf produced = uLongf(outBytes);
  const int status =
      uncompress(reinterpret_cast<Bytef*>(out), &produced,
                 reinterpret_cast<const Bytef*>(compressed.data()), uLong(compressed.size()));
  if (status != Z_OK || produced != outBytes) {
    throw ArrayProblem("corrupt zlib block (" + std::string(zError(status)) + ")");
  }
}

// How many bytes deflate can make of one (its limit is about 1032), with room to spare.
constexpr std::uint64_t kMaxInflation = 1100;

// vtkZLibDataCompressor: header words [nblocks, blocksize, lastblocksize, compressed size of each
// block] (lastblocksize 0 = the last block is full), then the zlib streams one after another.
std::string readCompressed(ByteStream& in, const Encoding& encoding, std::size_t expectedBytes) {
  const std::size_t word = encoding.headerWordBytes;
  const std::string head = in.read(3 * word);
  const std::uint64_t blocks = wordAt(head, 0, word, encoding.swapBytes);
  const std::uint64_t blockBytes = wordAt(head, 1, word, encoding.swapBytes);
  const std::uint64_t lastBytes = wordAt(head, 2, word, encoding.swapBytes);
  if (blocks > 0 && (blockBytes == 0 || lastBytes > blockBytes)) {
    throw ArrayProblem("bad compression header (block size " + std::to_string(blockBytes) +
                       ", last block " + std::to_string(lastBytes) + ")");
  }
  // Bounding the block count by the expected size first keeps the arithmetic from overflowing.
  if (blocks > 0 && blocks - 1 > expectedBytes / blockBytes) {
    throw ArrayProblem("compression header claims " + std::to_string(blocks) + " blocks");
  }
  const std::uint64_t total =
      blocks == 0 ? 0 : (blocks - 1) * blockBytes + (lastBytes != 0 ? lastBytes : blockBytes);
  if (total != expectedBytes) throw ArrayProblem(sizeMismatch(total, expectedBytes));
  const std::string sizes = in.read(std::size_t(blocks) * word);
  in.endStream();
  // Every block's compressed bytes must be there, and could inflate to its size: deflate makes at
  // most about 1032 bytes of one, so a header claiming more is refused before anything is allocated.
  std::uint64_t compressedTotal = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressedBytes = wordAt(sizes, b, word, encoding.swapBytes);
    const std::uint64_t outBytes = b + 1 == blocks && lastBytes != 0 ? lastBytes : blockBytes;
    if (compressedBytes > in.available() || compressedTotal + compressedBytes > in.available())
      throw ArrayProblem("data ends early (compressed blocks of " + std::to_string(compressedTotal) +
                         "+ bytes in " + std::to_string(in.available()) + ")");
    if (outBytes / kMaxInflation > compressedBytes)
      throw ArrayProblem("zlib block " + std::to_string(b) + " claims " + std::to_string(outBytes) +
                         " bytes from " + std::to_string(compressedBytes) + " compressed");
    compressedTotal += compressedBytes;
  }

  std::string data(expectedBytes, '\0');
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressedBytes = wordAt(sizes, b, word, encoding.swapBytes);
    if (compressedBytes > in.available()) throw ArrayProblem("data ends early");
    const std::size_t outBytes = b + 1 == blocks && lastBytes != 0 ? lastBytes : blockBytes;
    inflateBlock(in.read(std::size_t(compressedBytes)), data.data() + b * blockBytes, outBytes);
  }
  return data;
}

// --- Data arrays --------------------------------------------------------------------------------

struct WordType {
  std::size_t bytes = 0;
  bool isFloat = false;
  bool isSigned = false;
};

std::optional<WordType> wordTypeNamed(const std::string& name) {
  if (name == "Float32") return WordType{4, true, true};
  if (name == "Float64") return WordType{8, true, true};
  if (name == "Int8") return WordType{1, false, true};
  if (name == "UInt8") return WordType{1, false, false};
  if (name == "Int16") return WordType{2, false, true};
  if (name == "UInt16") return WordType{2, false, false};
  if (name == "Int32") return WordType{4, false, true};
  if (name == "UInt32") return WordType{4, false, false};
  if (name == "Int64") return WordType{8, false, true};
  if (name == "UInt64") return WordType{8, false, false};
  return std::nullopt;
}

template <class T>
double loadAs(const unsigned char* word) {
  T value;
  std::memcpy(&value, word, sizeof value);
  return double(value);
}

double wordValue(const unsigned char* word, const WordType& type) {
  if (type.isFloat) return type.bytes == 4 ? loadAs<float>(word) : loadAs<double>(word);
  switch (type.bytes) {
    case 1: return type.isSigned ? loadAs<std::int8_t>(word) : loadAs<std::uint8_t>(word);
    case 2: return type.isSigned ? loadAs<std::int16_t>(word) : loadAs<std::uint16_t>(word);
    case 4: return type.isSigned ? loadAs<std::int32_t>(word) : loadAs<std::uint32_t>(word);
    default: return type.isSigned ? loadAs<std::int64_t>(word) : loadAs<std::uint64_t>(word);
  }
}

std::vector<double> wordsToValues(const std::string& bytes, const WordType& type, bool swapBytes) {
  std::vector<double> values(bytes.size() / type.bytes);
  unsigned char word[8] = {};
  for (std::size_t n = 0; n < values.size(); ++n) {
    loadWord(bytes.data() + n * type.bytes, type.bytes, swapBytes, word);
    values[n] = wordValue(word, type);
  }
  return values;
}

// The element's character data (its first text child; vmtk files put <InformationKey>s after it).
std::string_view elementText(const pugi::xml_node& node) {
  for (const pugi::xml_node child : node.children()) {
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) return child.value();
  }
  return {};
}

// from_chars accepts "nan" and "inf"; the model's validation reports those with the path.
std::vector<double> parseAsciiNumbers(std::string_view text, std::size_t expectedValues) {
  std::vector<double> values;
  values.reserve(std::min(expectedValues, text.size() / 2 + 1));
  std::size_t position = 0;
  while (true) {
    while (position < text.size() && isSpace(text[position])) ++position;
    if (position == text.size()) break;
    std::size_t end = position;
    while (end < text.size() && !isSpace(text[end])) ++end;
    const std::string_view token = text.substr(position, end - position);
    double value = 0;
    const auto [stop, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || stop != token.data() + token.size()) {
      throw ArrayProblem(quotedText(token) + " is not a number");
    }
    values.push_back(value);
    position = end;
  }
  return values;
}

std::vector<double> parseAscii(std::string_view text, std::size_t expectedValues) {
  std::vector<double> values = parseAsciiNumbers(text, expectedValues);
  if (values.size() != expectedValues) {
    throw ArrayProblem("has " + std::to_string(values.size()) + " values, expected " +
                       std::to_string(expectedValues));
  }
  return values;
}

std::size_t parseCount(const std::string& text, const std::string& what) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw ArrayProblem(what + " '" + text + "' is not a count");
  }
  return value;
}

struct ArrayContext {
  const Encoding& encoding;
  const AppendedData& appended;
  const fs::path& source;
  // The file's size: the most values it can hold are a value per byte, or kMaxInflation per byte
  // compressed; counts from the header are checked against that before anything is allocated.
  std::size_t fileBytes = 0;
};

std::vector<double> decodeArray(const pugi::xml_node& array, std::size_t expectedValues,
                                const ArrayContext& context) {
  const std::string typeName = attribute(array, "type");
  const std::optional<WordType> type = wordTypeNamed(typeName);
  if (!type) throw ArrayProblem("unsupported type '" + typeName + "'");
  const std::string format = attribute(array, "format", "ascii");
  if (format == "ascii") return parseAscii(elementText(array), expectedValues);
  std::optional<ByteStream> in;
  if (format == "binary") {
    in.emplace(elementText(array), true);
  } else if (format == "appended") {
    if (!context.appended.present) throw ArrayProblem("is appended but the file has no AppendedData");
    const std::size_t offset = parseCount(attribute(array, "offset"), "offset");
    if (offset > context.appended.bytes.size()) throw ArrayProblem("offset beyond the appended data");
    in.emplace(context.appended.bytes.substr(offset), context.appended.base64);
  } else {
    throw ArrayProblem("unknown format '" + format + "'");
  }
  const std::size_t expectedBytes = expectedValues * type->bytes;
  const std::string bytes = context.encoding.zlib
                                ? readCompressed(*in, context.encoding, expectedBytes)
                                : readUncompressed(*in, context.encoding, expectedBytes);
  return wordsToValues(bytes, *type, context.encoding.swapBytes);
}

// A DataArray's values (any type, as double), checked to be `tuples` x NumberOfComponents.
std::vector<double> readDataArray(const pugi::xml_node& array, std::size_t tuples,
                                  std::size_t components, const ArrayContext& context) {
  const std::string name = attribute(array, "Name", "(unnamed)");
  try {
    const std::size_t declared =
        parseCount(attribute(array, "NumberOfComponents", "1"), "NumberOfComponents");
    const double maxValues =
        double(context.fileBytes) * double(context.encoding.zlib ? kMaxInflation : 1);
    if (double(tuples) * double(components) > maxValues) {
      throw ArrayProblem("claims " + std::to_string(tuples) + " tuples, more than the file's " +
                         std::to_string(context.fileBytes) + " bytes can hold");
    }
    if (declared != components) {
      throw ArrayProblem("has " + std::to_string(declared) + " components, expected " +
                         std::to_string(components));
    }
    return decodeArray(array, tuples * components, context);
  } catch (const ArrayProblem& problem) {
    throw InputError(context.source, "DataArray " + quotedText(name) + ": " + problem.what());
  }
}

// The child `element` (VTK 9 writes a String array as <Array>, numbers as <DataArray>) named `name`.
pugi::xml_node namedArray(const pugi::xml_node& parent, const char* name,
                          const char* element = "DataArray") {
  for (const pugi::xml_node array : parent.children(element)) {
    if (attribute(array, "Name") == name) return array;
  }
  return {};
}

// --- Pieces -------------------------------------------------------------------------------------

std::size_t pieceCount(const pugi::xml_node& piece, const char* name, const fs::path& source) {
  try {
    return parseCount(attribute(piece, name, "0"), name);
  } catch (const ArrayProblem& problem) {
    throw InputError(source, std::string("Piece: ") + problem.what());
  }
}

std::vector<glm::dvec3> readPoints(const pugi::xml_node& piece, std::size_t count,
                                   const ArrayContext& context) {
  if (count == 0) return {};
  const pugi::xml_node array = piece.child("Points").child("DataArray");
  if (!array) throw InputError(context.source, "Piece has no <Points> DataArray");
  const std::vector<double> xyz = readDataArray(array, count, 3, context);
  std::vector<glm::dvec3> points(count);
  for (std::size_t n = 0; n < count; ++n) points[n] = {xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]};
  return points;
}

// vmtk's MaximumInscribedSphereRadius, else a "Radius" array; zeros (unknown) without either.
std::vector<double> readRadii(const pugi::xml_node& piece, std::size_t count,
                              const ArrayContext& context) {
  const pugi::xml_node pointData = piece.child("PointData");
  pugi::xml_node array = namedArray(pointData, "MaximumInscribedSphereRadius");
  if (!array) array = namedArray(pointData, "Radius");
  if (!array || count == 0) return std::vector<double>(count, 0.0);
  return readDataArray(array, count, 1, context);
}

// Line cells as ranges [begin, end) of connectivity; checks the end offsets.
std::vector<std::size_t> readLineEnds(const pugi::xml_node& lines, std::size_t cells,
                                      const ArrayContext& context) {
  const pugi::xml_node array = namedArray(lines, "offsets");
  if (!array) throw InputError(context.source, "<Lines> has no \"offsets\" DataArray");
  const std::vector<double> offsets = readDataArray(array, cells, 1, context);
  std::vector<std::size_t> ends(cells);
  double previous = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (!(offsets[c] >= previous) || offsets[c] != std::floor(offsets[c]) || offsets[c] > 1e15) {
      throw InputError(context.source, "Lines offsets: bad offset " + formatNumber(offsets[c]) +
                                           " of cell " + std::to_string(c));
    }
    ends[c] = std::size_t(offsets[c]);
    previous = offsets[c];
  }
  return ends;
}

// --- Path names ---------------------------------------------------------------------------------

constexpr const char* kNameArray = "CenterlineName";

// VTK's ascii strings: each byte as a number (VTK writes a char as a short, so bytes above 127 are
// negative where char is signed), each string ended by a 0.
std::vector<std::string> asciiStrings(std::string_view text) {
  std::vector<std::string> strings(1);
  for (const double code : parseAsciiNumbers(text, text.size() / 2 + 1)) {
    if (!(code >= -128 && code <= 255) || code != std::floor(code)) {
      throw ArrayProblem("'" + formatNumber(code) + "' is not a character code");
    }
    if (code == 0) {
      strings.emplace_back();
    } else {
      strings.back() += char(int(code));
    }
  }
  if (strings.back().empty()) strings.pop_back();  // what follows the last string's 0
  return strings;
}

// The names of a piece's line cells, or nothing (named by index) without an ascii name array.
std::optional<std::vector<std::string>> readCellNames(const pugi::xml_node& piece, std::size_t cells,
                                                      const ArrayContext& context,
                                                      const CenterlineLoadOptions& options) {
  pugi::xml_node array = namedArray(piece.child("CellData"), kNameArray);
  if (!array) array = namedArray(piece.child("CellData"), kNameArray, "Array");
  if (!array) return std::nullopt;
  if (attribute(array, "type") != "String" || attribute(array, "format", "ascii") != "ascii") {
    if (options.warn) {
      options.warn(context.source.string() + ": CellData '" + kNameArray +
                   "' is not an ascii String array; skipped, paths are named by their index");
    }
    return std::nullopt;
  }
  try {
    std::vector<std::string> names = asciiStrings(elementText(array));
    if (names.size() != cells) {
      throw ArrayProblem("has " + std::to_string(names.size()) + " names, expected " +
                         std::to_string(cells) + " (one per line cell)");
    }
    return names;
  } catch (const ArrayProblem& problem) {
    throw InputError(context.source, "DataArray '" + std::string(kNameArray) + "': " + problem.what());
  }
}

// --- Line cells ---------------------------------------------------------------------------------

struct PiecePoints {
  std::vector<glm::dvec3> positions;
  std::vector<double> radii;
};

// The points of connectivity[begin, end), each index checked against the piece's points.
std::vector<CenterlinePoint> cellPoints(const std::vector<double>& connectivity, std::size_t begin,
                                        std::size_t end, const PiecePoints& points,
                                        const fs::path& source) {
  std::vector<CenterlinePoint> cell;
  for (std::size_t n = begin; n < end; ++n) {
    const double index = connectivity[n];
    if (!(index >= 0 && index < double(points.positions.size())) || index != std::floor(index)) {
      throw InputError(source, "Lines connectivity: point index " + formatNumber(index) +
                                   " out of range (" + std::to_string(points.positions.size()) +
                                   " points)");
    }
    cell.push_back({points.positions[std::size_t(index)], points.radii[std::size_t(index)]});
  }
  return cell;
}

// The points all paths will hold, checked before the connectivity is read: a line cell visits each
// point once (a closed one its first twice), and all paths together stay within kMaxPathPoints (a
// few repeated indices could otherwise ask for more memory than the machine has).
constexpr std::size_t kMaxPathPoints = std::size_t(1) << 24;

void requirePlausiblePathPoints(std::size_t entries, std::size_t points, std::size_t cells,
                                const Centerlines& centerlines, const ArrayContext& context) {
  std::size_t loaded = 0;
  for (const CenterlinePath& path : centerlines.paths) loaded += path.points.size();
  const auto claim = [&] {
    return "Lines: " + std::to_string(entries) + " connectivity entries for " + std::to_string(points) +
           " points in " + std::to_string(cells) + " lines";
  };
  if (double(entries) > double(cells) * (double(points) + 1))
    throw InputError(context.source, claim() + " (a line visits each point once)");
  if (entries > kMaxPathPoints - loaded)
    throw InputError(context.source,
                     claim() + ", more than " + std::to_string(kMaxPathPoints) + " path points in all");
}

void readPiece(const pugi::xml_node& piece, const ArrayContext& context,
               const CenterlineLoadOptions& options, Centerlines& centerlines) {
  const std::size_t pointCount = pieceCount(piece, "NumberOfPoints", context.source);
  const std::size_t cells = pieceCount(piece, "NumberOfLines", context.source);
  const PiecePoints points{readPoints(piece, pointCount, context),
                           readRadii(piece, pointCount, context)};
  if (cells == 0) return;

  const pugi::xml_node lines = piece.child("Lines");
  if (!lines) throw InputError(context.source, "Piece has NumberOfLines but no <Lines>");
  const std::vector<std::size_t> ends = readLineEnds(lines, cells, context);
  requirePlausiblePathPoints(ends.back(), pointCount, cells, centerlines, context);
  const pugi::xml_node connectivityArray = namedArray(lines, "connectivity");
  if (!connectivityArray) throw InputError(context.source, "<Lines> has no \"connectivity\" DataArray");
  const std::vector<double> connectivity = readDataArray(connectivityArray, ends.back(), 1, context);
  const std::optional<std::vector<std::string>> names = readCellNames(piece, cells, context, options);

  for (std::size_t cell = 0; cell < cells; ++cell) {
    const bool named = names && !(*names)[cell].empty();
    centerlines.paths.push_back(
        {named ? (*names)[cell] : std::to_string(centerlines.paths.size()),
         cellPoints(connectivity, cell == 0 ? 0 : ends[cell - 1], ends[cell], points, context.source)});
  }
}

// --- Writing ------------------------------------------------------------------------------------

// An ascii DataArray, one line of values per entry of `lines`, indented as VTK's writer does.
std::string asciiDataArray(const std::string& attributes, const std::vector<std::string>& lines) {
  std::string xml = "        <DataArray " + attributes + " format=\"ascii\">\n";
  for (const std::string& line : lines) xml += "          " + line + "\n";
  return xml + "        </DataArray>\n";
}

void appendWord(std::string& line, const std::string& word) {
  if (!line.empty()) line += ' ';
  line += word;
}

// A string as VTK writes one in ascii: each byte as a (signed) number, then a 0.
std::string vtkStringText(const std::string& text) {
  std::string codes;
  for (const char c : text) appendWord(codes, std::to_string(int(static_cast<signed char>(c))));
  appendWord(codes, "0");
  return codes;
}

// The arrays of the one Piece: each path's points stored in order, so connectivity counts up.
struct PieceText {
  std::vector<std::string> points, radii, connectivity, names;
  std::string offsets;  // one line: the end offset of each cell
};

PieceText pieceText(const Centerlines& centerlines) {
  PieceText text;
  std::size_t pointCount = 0;
  for (const CenterlinePath& path : centerlines.paths) {
    std::string cell;
    for (const CenterlinePoint& point : path.points) {
      const glm::dvec3& p = point.positionMm;
      text.points.push_back(numberText(p.x) + ' ' + numberText(p.y) + ' ' + numberText(p.z));
      text.radii.push_back(numberText(point.radiusMm));
      appendWord(cell, std::to_string(pointCount++));
    }
    text.connectivity.push_back(cell);
    appendWord(text.offsets, std::to_string(pointCount));
    text.names.push_back(vtkStringText(path.name));
  }
  return text;
}

std::string vtpText(const Centerlines& centerlines) {
  const PieceText piece = pieceText(centerlines);
  const std::string cells = std::to_string(centerlines.paths.size());
  std::string xml = "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(piece.points.size()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"" + cells +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  xml += "      <PointData Scalars=\"MaximumInscribedSphereRadius\">\n";
  xml += asciiDataArray("type=\"Float64\" Name=\"MaximumInscribedSphereRadius\"", piece.radii);
  xml += "      </PointData>\n      <CellData>\n";
  xml += asciiDataArray(
      "type=\"String\" Name=\"" + std::string(kNameArray) + "\" NumberOfTuples=\"" + cells + "\"",
      piece.names);
  xml += "      </CellData>\n      <Points>\n";
  xml += asciiDataArray("type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", piece.points);
  xml += "      </Points>\n      <Lines>\n";
  xml += asciiDataArray("type=\"Int64\" Name=\"connectivity\"", piece.connectivity);
  xml += asciiDataArray("type=\"Int64\" Name=\"offsets\"", {piece.offsets});
  return xml + "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

}  // namespace

Centerlines parseCenterlinesVtp(const std::string& bytes, const fs::path& source,
                                const CenterlineLoadOptions& options) {
  const SplitFile split = splitAppendedData(bytes, source);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(split.xml.data(), split.xml.size());
  if (!parsed) {
    throw InputError(source, std::string("bad XML: ") + parsed.description() + " at byte " +
                                 std::to_string(parsed.offset));
  }
  const pugi::xml_node root = document.child("VTKFile");
  if (!root) throw InputError(source, "not a VTK XML file (no <VTKFile> element)");
  const std::string type = attribute(root, "type");
  if (type != "PolyData")
    throw InputError(source, "VTK file of type " + quotedText(type) + ", not PolyData");
  const pugi::xml_node polyData = root.child("PolyData");
  if (!polyData) throw InputError(source, "no <PolyData> element");

  const Encoding encoding = fileEncoding(root, source);
  const AppendedData appended = appendedData(root, split, source);
  const ArrayContext context{encoding, appended, source, bytes.size()};
  Centerlines centerlines;
  centerlines.source = source.string();
  for (const pugi::xml_node piece : polyData.children("Piece")) {
    readPiece(piece, context, options, centerlines);
  }
  checkLoadedCenterlines(centerlines, source, options);
  return centerlines;
}

void writeCenterlinesVtp(const Centerlines& centerlines, const fs::path& file) {
  requirePhysicalFrame(centerlines, "a centerline .vtp");
  writeBytesAtomically(file, vtpText(centerlines));
}

Centerlines readCenterlinesVtp(const fs::path& file, const CenterlineLoadOptions& options) {
  return parseCenterlinesVtp(readCenterlineFileBytes(file), file, options);
}

}  // namespace angio
