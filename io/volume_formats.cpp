#include "io/volume_formats.h"

#include <algorithm>
#include <optional>
#include <string>

#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>

#include "io/lowercase.h"

namespace angio {

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::optional<VolumeFormat> volumeFormatOf(const std::filesystem::path& path) {
  const std::string name = lowercase(path.filename().string());
  if (endsWith(name, ".mha") || endsWith(name, ".mhd")) return VolumeFormat::metaImage;
  if (endsWith(name, ".nrrd") || endsWith(name, ".nhdr")) return VolumeFormat::nrrd;
  if (endsWith(name, ".nii") || endsWith(name, ".nii.gz")) return VolumeFormat::nifti;
  return std::nullopt;
}

const char* formatName(VolumeFormat format) {
  switch (format) {
    case VolumeFormat::metaImage: return "MetaImage";
    case VolumeFormat::nrrd: return "NRRD";
    case VolumeFormat::nifti: return "NIfTI";
  }
  return "?";
}

itk::ImageIOBase::Pointer makeImageIO(VolumeFormat format) {
  switch (format) {
    case VolumeFormat::metaImage: return itk::MetaImageIO::New().GetPointer();
    case VolumeFormat::nrrd: return itk::NrrdImageIO::New().GetPointer();
    case VolumeFormat::nifti: return itk::NiftiImageIO::New().GetPointer();
  }
  return nullptr;
}

std::string componentTypeName(itk::IOComponentEnum type) {
  using C = itk::IOComponentEnum;
  switch (type) {
    case C::UCHAR: return "uint8";
    case C::CHAR: return "int8";
    case C::USHORT: return "uint16";
    case C::SHORT: return "int16";
    case C::UINT: return "uint32";
    case C::INT: return "int32";
    case C::ULONG: return "uint" + std::to_string(8 * sizeof(unsigned long));
    case C::LONG: return "int" + std::to_string(8 * sizeof(long));
    case C::ULONGLONG: return "uint64";
    case C::LONGLONG: return "int64";
    case C::FLOAT: return "float32";
    case C::DOUBLE: return "float64";
    case C::LDOUBLE: return "long double";
    default: return "unknown type";
  }
}

namespace {

// Of teem's chain of messages, outermost first ("[nrrd] nrrdLoad: trouble reading ...\n[nrrd]
// _nrrdHeaderCheck: type (short) and encoding (bzip2) require endian info"), the innermost one
// that says something, without its function name: the one that names the problem.
std::optional<std::string> innermostTeemMessage(const std::string& text) {
  const std::string marker = "[nrrd] ";
  for (std::size_t at = text.rfind(marker); at != std::string::npos;
       at = at == 0 ? std::string::npos : text.rfind(marker, at - 1)) {
    std::string message = text.substr(at + marker.size());
    message = message.substr(0, message.find('\n'));
    const std::size_t colon = message.find(':');
    if (colon != std::string::npos && message.find(' ') > colon) message.erase(0, colon + 1);
    if (message.find_first_not_of(" \t\r") != std::string::npos) return message;
  }
  return std::nullopt;
}

}  // namespace

std::string readProblemInOurWords(const std::string& text) {
  // Binary data too short are refused before MetaIO reads them (io/volume_integrity.h), so what
  // reaches these is data as text with a word that is not a number, or too few numbers.
  for (const char* metaIo : {"M_ReadElementsData: file stream is fail after read",
                             "M_ReadElementsData: data not read completely"})
    if (text.find(metaIo) != std::string::npos)
      return "its voxel data end early or hold text that is not a number";
  return text;
}

std::string oneLine(const itk::ExceptionObject& error) {
  std::string text = error.GetDescription();
  // itkExceptionMacro prefixes "ITK ERROR: ClassName(0x55d0...): " (or "itk::ERROR: ..."), which
  // means nothing to users.
  for (const std::string prefix : {"ITK ERROR: ", "itk::ERROR: "}) {
    if (text.compare(0, prefix.size(), prefix) != 0) continue;
    const auto end = text.find("): ");
    text = end == std::string::npos ? text.substr(prefix.size()) : text.substr(end + 3);
  }
  if (const auto teem = innermostTeemMessage(text)) text = *teem;
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  // Collapse runs of spaces and trim.
  std::string squeezed;
  for (char c : text) {
    if (c == ' ' && (squeezed.empty() || squeezed.back() == ' ')) continue;
    squeezed += c;
  }
  while (!squeezed.empty() && squeezed.back() == ' ') squeezed.pop_back();
  if (squeezed.size() > 300) squeezed = squeezed.substr(0, 297) + "...";
  return squeezed.empty() ? "unknown ITK error" : readProblemInOurWords(squeezed);
}

}  // namespace angio
