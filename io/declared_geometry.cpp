#include "io/declared_geometry.h"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/number_text.h"
#include "io/input_error.h"
#include "io/metaimage_header.h"
#include "io/nifti_header.h"
#include "io/nrrd_header.h"
#include "io/shown_text.h"

namespace angio {

namespace {

namespace fs = std::filesystem;

// `word` as a finite number, or NaN if it is not wholly one.
double wholeNumber(const std::string& word) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  return !word.empty() && *end == '\0' && std::isfinite(value) ? value : NAN;
}

// The numbers in `text`, separated by blanks, commas or parentheses; a word that is not a number
// (NaN, inf, "none") is NaN.
std::vector<double> numbersIn(const std::string& text) {
  std::vector<double> numbers;
  std::string word;
  const auto flush = [&] {
    if (word.empty()) return;
    numbers.push_back(wholeNumber(word));
    word.clear();
  };
  for (const char c : text) {
    if (c == ' ' || c == '\t' || c == ',' || c == '(' || c == ')' || c == '\r') flush();
    else word += c;
  }
  flush();
  return numbers;
}

// The components of the NRRD vectors "(x,y,z)" in `text`, in order, with "none" (a non-spatial
// axis) left out. Teem reads a component up to the first character that is not part of a number
// ("(0(.7,0,0)" is (0,0,0)); one that is not wholly a number is NaN here, so that such a header is
// refused rather than read otherwise than teem reads it.
std::vector<double> vectorNumbers(const std::string& text) {
  std::vector<double> numbers;
  for (std::size_t at = 0; at < text.size();) {
    if (text[at] == ' ' || text[at] == '\t') {
      ++at;
    } else if (text.compare(at, 4, "none") == 0) {
      at += 4;
    } else if (const std::size_t close = text.find(')', at);
               text[at] == '(' && close != std::string::npos) {
      std::istringstream components(text.substr(at + 1, close - at - 1));
      for (std::string component; std::getline(components, component, ',');) {
        component.erase(0, component.find_first_not_of(" \t"));
        component.erase(component.find_last_not_of(" \t") + 1);
        numbers.push_back(wholeNumber(component));
      }
      at = close + 1;
    } else {
      numbers.push_back(NAN);  // not a vector
      break;
    }
  }
  return numbers;
}

// Coordinates and lengths in mm beyond this are not a patient (a scanner's bore is under 1 m);
// ITK's direction decomposition does not finish on values near the float limit.
constexpr double kMaxHeaderMm = 1e6;

bool allFinite(const std::vector<double>& values) {
  for (const double v : values)
    if (!std::isfinite(v) || std::abs(v) > kMaxHeaderMm) return false;
  return true;
}

void requireSpacing(const fs::path& file, const std::string& field, const std::vector<double>& spacing,
                    const std::string& text) {
  for (const double s : spacing)
    if (!(s > 0 && s <= kMaxHeaderMm))
      throw InputError(file, "has a zero, negative or unknown voxel spacing in " + field + " (" +
                                 shownText(text) + ")");
}

void requireFinite(const fs::path& file, const std::string& field, const std::vector<double>& values,
                   const std::string& text) {
  if (!allFinite(values))
    throw InputError(file, "has a non-finite or absurd " + field + " (" + shownText(text) + ")");
}

// Three axis vectors (column-wise) must span space.
void requireAxes(const fs::path& file, const std::string& field, const std::vector<double>& values,
                 const std::string& text) {
  requireFinite(file, field, values, text);
  if (values.size() < 9) return;
  const glm::dmat3 axes(values[0], values[1], values[2], values[3], values[4], values[5], values[6],
                        values[7], values[8]);
  double scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, glm::length(axes[c]));
  if (!(std::abs(glm::determinant(axes)) > 1e-12 * scale * scale * scale))
    throw InputError(file, "has an invalid direction matrix: " + field + " does not span 3-D space (" +
                               shownText(text) + ")");
}

// Teem quotes a field line it cannot parse (an unknown field, a value it cannot read) in an error
// message formatted into a fixed stack buffer of 1025 bytes (biffMsgAddVL, AIR_STRLEN_HUGE): a
// longer line overflows it and the process aborts. Its messages add at most ~150 characters to the
// line; real field lines (sizes, space directions, measurement frame) are under 200. Comments and
// "key:=value" pairs (Slicer's segment metadata can be long) are never quoted.
constexpr std::size_t kMaxNrrdFieldLine = 768;

void requireShortFieldLine(const fs::path& file, const NrrdHeaderLine& line) {
  // The whole line: teem's message has been seen to quote more of a line than up to its first NUL.
  if (line.text.size() > kMaxNrrdFieldLine)
    throw InputError(file, "header line " + std::to_string(line.number) + " has " +
                               std::to_string(line.text.size()) +
                               " characters (a NRRD field has at most " +
                               std::to_string(kMaxNrrdFieldLine) + "; a damaged header)");
}

void checkNrrd(const fs::path& file) {
  const auto header = readNrrdHeader(file);
  // Teem reads a long first line in pieces joined as C strings, so "NRRD\0\0...0004" can pass its
  // magic test while the checks could not read the header at all.
  if (!header) throw InputError(file, "is not a valid NRRD file (its first line is not NRRD000N)");
  std::vector<double> directions;
  std::string directionsText;
  for (const NrrdHeaderLine& line : header->lines) {
    // Teem never quotes a comment or a key/value pair in a message; the ones it has quoted past a
    // NUL byte were lines it could not read, but a key/value pair with a NUL is checked too.
    const bool hasNul = line.text.find('\0') != std::string::npos;
    const bool plainKeyValue = line.kind == NrrdLineKind::keyValue && !hasNul;
    if (line.kind == NrrdLineKind::comment || plainKeyValue) continue;
    requireShortFieldLine(file, line);
    // Teem reads a line longer than its buffer in pieces and joins them as C strings, so what it
    // reads past a NUL depends on the lines before: "sizes: 2 5 4\0xxxxx99..." has been read as
    // 2 5 4999... (the piece after the NUL's piece appended to "4").
    if (hasNul) throw InputError(file, "header line " + std::to_string(line.number) + " has a NUL byte");
    const std::string& key = line.name;
    const std::string& value = line.value;
    // ITK keeps sizes as unsigned int; teem allocates what the header says, and reads a size up to
    // the first character that is not a digit ("5~" is 5, "99496765535rr0" is 99496765535).
    if (key == "sizes")
      for (const double size : numbersIn(value))
        if (!(size >= 1 && size <= double(std::numeric_limits<int>::max()) && size == std::floor(size)))
          throw InputError(file, "has impossible dimensions (sizes: " + shownText(value) + ")");
    if (key == "spacings") {
      // Axes past the third are not spatial (NaN is NRRD's "no spacing" for them).
      std::vector<double> spacings = numbersIn(value);
      spacings.resize(std::min<std::size_t>(spacings.size(), 3));
      requireSpacing(file, "spacings", spacings, value);
    }
    if (key == "spaceorigin") requireFinite(file, "space origin", vectorNumbers(value), value);
    if (key == "spacedirections") {
      directions = vectorNumbers(value);
      directionsText = value;
      requireFinite(file, "space directions", directions, value);
      for (std::size_t axis = 0; axis + 3 <= directions.size() && directions.size() == 9; axis += 3)
        if (glm::length(glm::dvec3(directions[axis], directions[axis + 1], directions[axis + 2])) == 0)
          throw InputError(file,
                           "has a zero-length axis in space directions (" + shownText(value) + ")");
    }
  }
  if (directions.size() == 9) requireAxes(file, "space directions", directions, directionsText);
}

// MetaIO leaks its stream when it cannot open the data file a header names (relative to the
// header's folder), so that is checked before it tries.
void requireReadableDataFile(const fs::path& file, const std::string& dataFile) {
  const fs::path data =
      fs::path(dataFile).is_absolute() ? fs::path(dataFile) : file.parent_path() / dataFile;
  std::error_code error;
  if (fs::is_directory(data, error))
    throw InputError(file, "its data file " + quotedText(dataFile) + " is a folder");
  std::ifstream stream(data, std::ios::binary);
  if (!stream)
    throw InputError(
        file, "its data file " + quotedText(dataFile) + " cannot be read: " + std::strerror(errno));
}

// MetaIO reads a list of slice files (LIST, or a printf pattern with a range) without saying when
// one is missing; a CT arrives as one .mha or .mhd + .raw, so only those are read.
void checkMetaImageLayout(const fs::path& file, const MetaImageHeader& header) {
  if (!header.repeated.empty())
    throw InputError(file, "has the field " + shownText(*header.repeated.begin()) +
                               " more than once (a damaged header)");
  const std::string dims = header.field("NDims");
  if (dims.empty())
    throw InputError(file, "is not a valid MetaImage file (corrupt or truncated header)");
  if (header.unreadableLine) throw InputError(file, *header.unreadableLine + " (a damaged header)");
  char* end = nullptr;
  const long ndims = std::strtol(dims.c_str(), &end, 10);
  if (dims.empty() || *end != '\0' || ndims < 1 || ndims > 8)
    throw InputError(file, "has NDims '" + shownText(dims) + "'; need 3");
  const std::vector<double> sizes = numbersIn(header.field("DimSize"));
  bool whole = sizes.size() == std::size_t(ndims);
  for (const double n : sizes) whole = whole && n >= 1 && n == std::floor(n);
  if (!whole)
    throw InputError(file, "has DimSize '" + shownText(header.field("DimSize")) + "' that is not " +
                               std::to_string(ndims) + " whole numbers >= 1");
  // MetaIO keeps a size as an int (a larger one wraps around to a negative size).
  for (const double n : sizes)
    if (n > double(std::numeric_limits<int>::max()))
      throw InputError(file,
                       "has impossible dimensions (DimSize " + shownText(header.field("DimSize")) + ")");
  const std::string data = header.field("ElementDataFile");
  // MetaIO takes an empty name for a data file of (size_t) -1 bytes and asks for that much memory.
  if (data.empty())
    throw InputError(file,
                     "names no voxel data (ElementDataFile is missing or empty; LOCAL or a file name)");
  // MetaIO reads the name as a C string: a control byte (a NUL) in it leaves it empty, as above;
  // it also strips unprintable bytes from its end (a name of only such bytes is empty too).
  const auto control = [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; };
  if (std::any_of(data.begin(), data.end(), control) || static_cast<unsigned char>(data.back()) >= 0x80)
    throw InputError(file, "names its voxel data file with control bytes (ElementDataFile = " +
                               shownText(data) + "; a damaged header)");
  // MetaIO reads every name that starts with LIST as a list of files.
  if (data.rfind("LIST", 0) == 0 || data.find('%') != std::string::npos)
    throw InputError(file, "keeps its voxels in a list of files (ElementDataFile = " + shownText(data) +
                               "); only one data file (or LOCAL) is read: convert it to one .mha");
  if (data != "LOCAL") requireReadableDataFile(file, data);
}

void checkMetaImage(const fs::path& file) {
  const MetaImageHeader header = readMetaImageHeader(file);
  checkMetaImageLayout(file, header);
  for (const char* key : {"ElementSpacing", "ElementSize"})
    if (const std::string value = header.field(key); !value.empty())
      requireSpacing(file, key, numbersIn(value), value);
  for (const char* key : {"Offset", "Origin", "Position", "CenterOfRotation"})
    if (const std::string value = header.field(key); !value.empty())
      requireFinite(file, key, numbersIn(value), value);
  for (const char* key : {"TransformMatrix", "Rotation", "Orientation"})
    if (const std::string value = header.field(key); !value.empty())
      requireAxes(file, key, numbersIn(value), value);
}

void checkNifti(const fs::path& file) {
  const auto header = readNiftiHeader(file);
  // ITK's reader takes headers ours refuses (a wrong header size), then trusts their fields.
  if (!header) throw InputError(file, "is not a valid NIfTI file (its header does not add up)");
  // The NIfTI library keeps a NIfTI-1 vox_offset as an int: a larger one becomes the header's size
  // there, so ITK would read the header as voxels.
  if (!header->nifti2 && header->dataOffset > std::uint64_t(std::numeric_limits<int>::max())) {
    const std::string offset = std::to_string(header->dataOffset);
    throw InputError(file, "has an impossible vox_offset (" + offset + " bytes)");
  }
  const auto text = [](auto values) {
    std::string out;
    for (const double v : values) {
      if (!out.empty()) out += ' ';
      out += std::isfinite(v) ? numberText(v) : std::to_string(v);
    }
    return out;
  };
  const std::vector<double> pixdim(header->pixdim.begin(), header->pixdim.end());
  requireSpacing(file, "pixdim", pixdim, text(pixdim));
  if (header->qformCode > 0) {
    const std::vector<double> qform(header->qform.begin(), header->qform.end());
    requireFinite(file, "qform (quatern_b/c/d, qoffset)", qform, text(qform));
    const double squared = qform[0] * qform[0] + qform[1] * qform[1] + qform[2] * qform[2];
    if (squared > 1.0 + 1e-4)
      throw InputError(file, "has a qform quaternion longer than 1 (" + text(qform) + ")");
  }
  if (header->sformCode > 0) {
    const auto& s = header->sform;
    const std::vector<double> values(s.begin(), s.end());
    requireFinite(file, "sform (srow_x/y/z)", values, text(values));
    requireAxes(file, "sform (srow_x/y/z) axes", {s[0], s[4], s[8], s[1], s[5], s[9], s[2], s[6], s[10]},
                text(values));
  }
}

}  // namespace

void checkDeclaredGeometry(const fs::path& file, VolumeFormat format) {
  switch (format) {
    case VolumeFormat::nrrd: return checkNrrd(file);
    case VolumeFormat::metaImage: return checkMetaImage(file);
    case VolumeFormat::nifti: return checkNifti(file);
  }
}

}  // namespace angio
