#include "io/segmentation_file.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstdint>
#include <map>
#include <sstream>
#include <string_view>

#include <itkMetaDataObject.h>
#include <itkNrrdImageIO.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "io/grid_image_writing.h"
#include "io/input_error.h"
#include "io/volume_formats.h"

namespace angio {

namespace {

// Field names and values as Slicer's vtkMRMLSegmentationStorageNode writes them.
constexpr const char* kBinaryLabelmap = "Binary labelmap";
constexpr const char* kEmptyExtent = "0 -1 0 -1 0 -1";  // VTK's empty extent

std::string segmentKey(std::size_t index, const char* field) {
  return "Segment" + std::to_string(index) + "_" + field;
}

std::string segmentText(const SegmentInfo& segment) {
  return "segment '" + segment.name + "' (label " + std::to_string(segment.label) + ")";
}

// ---- writing -----------------------------------------------------------------------------------

// The voxel-index bounding box of one label's voxels.
struct VoxelBox {
  glm::ivec3 min{INT_MAX};
  glm::ivec3 max{INT_MIN};

  bool empty() const { return min.x > max.x; }
  void add(glm::ivec3 voxel) {
    min = glm::min(min, voxel);
    max = glm::max(max, voxel);
  }
  void add(const VoxelBox& box) {
    if (!box.empty()) add(box.min), add(box.max);
  }
};

using LabelBoxes = std::array<VoxelBox, kMaxLabel + 1>;

LabelBoxes labelBoxes(const Volume& volume) {
  const auto rowsOf = [&](const tbb::blocked_range<int>& slices, LabelBoxes boxes) {
    for (int k = slices.begin(); k != slices.end(); ++k)
      for (int j = 0; j < volume.dims.y; ++j) {
        const Voxel* row = volume.voxels.data() + volume.indexOf(0, j, k);
        for (int i = 0; i < volume.dims.x; ++i)
          if (const int label = labelOf(row[i])) boxes[label].add({i, j, k});
      }
    return boxes;
  };
  const auto merge = [](LabelBoxes a, const LabelBoxes& b) {
    for (int label = 0; label <= kMaxLabel; ++label) a[label].add(b[label]);
    return a;
  };
  return tbb::parallel_reduce(tbb::blocked_range<int>(0, volume.dims.z), LabelBoxes{}, rowsOf, merge);
}

// Slicer's "i0 i1 j0 j1 k0 k1", inclusive voxel indices.
std::string extentText(const VoxelBox& box) {
  if (box.empty()) return kEmptyExtent;
  std::ostringstream text;
  text << box.min.x << " " << box.max.x << " " << box.min.y << " " << box.max.y << " " << box.min.z
       << " " << box.max.z;
  return text.str();
}

// Slicer's color text: default stream formatting (6 significant digits), as it writes it.
std::string colorText(glm::vec3 color) {
  std::ostringstream text;
  text << double(color.r) << " " << double(color.g) << " " << double(color.b);
  return text.str();
}

// Shortest text that reads back as the same double (as VTK's vtkNumberToString writes).
std::string numberText(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value + 0.0).ptr;  // + 0.0: no "-0"
  return std::string(text, end);
}

// The "Reference image geometry" conversion parameter: the grid Slicer's Segment Editor edits on,
// as vtkSegmentationConverter::SerializeImageGeometry writes it: the image-to-world matrix in RAS
// (row by row, spacing included), then the extent, each followed by ';'.
std::string referenceGeometryText(const Volume& volume) {
  const glm::dvec3 lpsToRas(-1.0, -1.0, 1.0);
  std::string text;
  for (int row = 0; row < 3; ++row) {
    for (int axis = 0; axis < 3; ++axis)
      text += numberText(lpsToRas[row] * volume.direction[axis][row] * volume.spacing[axis]) + ";";
    text += numberText(lpsToRas[row] * volume.origin[row]) + ";";
  }
  text += "0;0;0;1;";
  for (int axis = 0; axis < 3; ++axis) text += "0;" + std::to_string(volume.dims[axis] - 1) + ";";
  return text;
}

// Slicer serialises each conversion parameter as "name|value|description&"; it reads any subset
// and keeps its defaults for the rest, so only the reference geometry (the CT's grid) is written.
std::string conversionParametersText(const Volume& volume) {
  return "Reference image geometry|" + referenceGeometryText(volume) +
         "|Image geometry of the labelmap: the grid of the CT it was made on.&";
}

void requireValidSegments(const std::filesystem::path& file, const std::vector<SegmentInfo>& segments) {
  std::array<const SegmentInfo*, kMaxLabel + 1> byLabel{};
  for (const SegmentInfo& segment : segments) {
    if (segment.label < 1 || segment.label > kMaxLabel)
      throw InputError(file, segmentText(segment) + ": labels are 1..15");
    if (const SegmentInfo* other = byLabel[segment.label])
      throw InputError(file, segmentText(*other) + " and " + segmentText(segment) + " share a label");
    byLabel[segment.label] = &segment;
  }
}

// A segment as written: a "label N" segment made up for unnamed voxels says its name and color
// were generated, so Slicer may replace them.
struct WrittenSegment {
  SegmentInfo info;
  bool generated = false;
};

// `segments`, then a gray "label N" segment for each label that voxels carry but no segment names.
std::vector<WrittenSegment> everyLabelsSegment(const std::vector<SegmentInfo>& segments,
                                               const LabelBoxes& boxes) {
  std::vector<WrittenSegment> all;
  for (const SegmentInfo& segment : segments) all.push_back({segment, false});
  for (int label = 1; label <= kMaxLabel; ++label) {
    const auto named = [&](const SegmentInfo& segment) { return segment.label == label; };
    if (!boxes[label].empty() && std::none_of(segments.begin(), segments.end(), named))
      all.push_back({{label, "label " + std::to_string(label), glm::vec3(0.5f)}, true});
  }
  return all;
}

void addField(itk::MetaDataDictionary& fields, const std::string& key, const std::string& value) {
  itk::EncapsulateMetaData<std::string>(fields, key, value);
}

itk::MetaDataDictionary segmentationFields(const Volume& volume,
                                           const std::vector<WrittenSegment>& segments,
                                           const LabelBoxes& boxes) {
  itk::MetaDataDictionary fields;
  addField(fields, "Segmentation_MasterRepresentation", kBinaryLabelmap);
  addField(fields, "Segmentation_ContainedRepresentationNames", std::string(kBinaryLabelmap) + "|");
  addField(fields, "Segmentation_ConversionParameters", conversionParametersText(volume));
  addField(fields, "Segmentation_ReferenceImageExtentOffset", "0 0 0");  // the file is the whole grid
  for (std::size_t n = 0; n < segments.size(); ++n) {
    const SegmentInfo& segment = segments[n].info;
    const std::string generated = segments[n].generated ? "1" : "0";
    addField(fields, segmentKey(n, "ID"), "Segment_" + std::to_string(segment.label));
    addField(fields, segmentKey(n, "Name"), segment.name);
    addField(fields, segmentKey(n, "NameAutoGenerated"), generated);
    addField(fields, segmentKey(n, "Color"), colorText(segment.color));
    addField(fields, segmentKey(n, "ColorAutoGenerated"), generated);
    addField(fields, segmentKey(n, "LabelValue"), std::to_string(segment.label));
    addField(fields, segmentKey(n, "Layer"), "0");
    addField(fields, segmentKey(n, "Extent"), extentText(boxes[segment.label]));
    addField(fields, segmentKey(n, "Tags"), "");
  }
  return fields;
}

// ---- reading -----------------------------------------------------------------------------------

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::optional<int> wholeNumber(std::string_view text) {
  text = trimmed(text);
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// "r g b"; Slicer's own reader falls back to gray for what it cannot parse.
glm::vec3 colorOf(const std::string& text) {
  std::istringstream stream(text);
  glm::dvec3 color(0.5);
  if (!(stream >> color.r >> color.g >> color.b)) return glm::vec3(0.5f);
  return glm::vec3(color);
}

// The header's key/value pairs (NRRD fields that ITK keeps under "NRRD_" are not among them).
using HeaderFields = std::map<std::string, std::string>;

struct NrrdHeader {
  HeaderFields fields;
  int components = 1;
};

NrrdHeader readNrrdHeader(const std::filesystem::path& file) {
  auto io = itk::NrrdImageIO::New();
  if (!io->CanReadFile(file.c_str()))
    throw InputError(file, "is not a valid NRRD file (corrupt or truncated header)");
  io->SetFileName(file.string());
  try {
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject& error) {
    throw InputError(file, "cannot be read: " + oneLine(error));
  }
  NrrdHeader header;
  header.components = int(io->GetNumberOfComponents());
  const itk::MetaDataDictionary& dictionary = io->GetMetaDataDictionary();
  for (const std::string& key : dictionary.GetKeys()) {
    std::string value;
    if (itk::ExposeMetaData<std::string>(dictionary, key, value)) header.fields[key] = value;
  }
  return header;
}

// The N of a "SegmentN_..." key, if it is one.
std::optional<std::size_t> segmentIndexOf(const std::string& key) {
  const std::string_view prefix = "Segment";
  if (key.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  const auto underscore = key.find('_', prefix.size());
  if (underscore == std::string::npos) return std::nullopt;
  const auto index =
      wholeNumber(std::string_view(key).substr(prefix.size(), underscore - prefix.size()));
  if (!index || *index < 0) return std::nullopt;
  return std::size_t(*index);
}

bool isSegmentation(const HeaderFields& fields) {
  return std::any_of(fields.begin(), fields.end(), [](const auto& field) {
    return field.first.rfind("Segmentation_", 0) == 0 || segmentIndexOf(field.first);
  });
}

// Slicer reads Segment0_ID, Segment1_ID, ... up to the first one missing; fields of a segment past
// that would be silently lost, so they are an error here.
std::size_t segmentCount(const std::filesystem::path& file, const HeaderFields& fields) {
  std::size_t count = 0;
  while (fields.count(segmentKey(count, "ID"))) ++count;
  for (const auto& [key, value] : fields)
    if (const auto index = segmentIndexOf(key); index && *index >= count)
      throw InputError(
          file, "has " + key + " but no " + segmentKey(*index, "ID") + " (inconsistent segment fields)");
  return count;
}

struct StoredSegment {
  SegmentInfo info;
  int layer = 0;
};

// A segment's field ("Name" of Segment2 is Segment2_Name), or null.
struct SegmentFields {
  const HeaderFields& fields;
  std::size_t index;

  const std::string* operator[](const char* name) const {
    const auto found = fields.find(segmentKey(index, name));
    return found == fields.end() ? nullptr : &found->second;
  }
};

int labelOfSegment(const std::filesystem::path& file, const std::string& where,
                   const std::string* value) {
  if (!value) throw InputError(file, where + " has no LabelValue");
  const std::optional<int> label = wholeNumber(*value);
  if (!label) throw InputError(file, where + " has LabelValue '" + *value + "', not a whole number");
  if (*label < 1 || *label > kMaxLabel)
    throw InputError(file, where + " has LabelValue " + std::to_string(*label) +
                               "; angioray labels are 1..15 (renumber the segments in Slicer)");
  return *label;
}

int layerOfSegment(const std::filesystem::path& file, const std::string& where, const std::string* value,
                   std::size_t index, int layers) {
  // Without a Layer field Slicer puts segment N in layer N.
  const std::string text = value ? "'" + *value + "'" : std::to_string(index);
  const std::optional<int> layer = value ? wholeNumber(*value) : std::optional<int>(int(index));
  if (!layer || *layer < 0 || *layer >= layers)
    throw InputError(file, where + " is in layer " + text + " but the file has " +
                               std::to_string(layers) + " layer(s)");
  return *layer;
}

StoredSegment storedSegment(const std::filesystem::path& file, const HeaderFields& fields,
                            std::size_t index, int layers) {
  const SegmentFields field{fields, index};
  StoredSegment segment;
  segment.info.name = field["Name"] ? *field["Name"] : *field["ID"];  // as Slicer names a nameless one
  segment.info.color = field["Color"] ? colorOf(*field["Color"]) : glm::vec3(0.5f);
  const std::string where = "segment '" + segment.info.name + "' (Segment" + std::to_string(index) + ")";
  segment.info.label = labelOfSegment(file, where, field["LabelValue"]);
  segment.layer = layerOfSegment(file, where, field["Layer"], index, layers);
  return segment;
}

// Two segments in one layer with one label value could not be told apart.
void requireDistinctLabels(const std::filesystem::path& file,
                           const std::vector<StoredSegment>& segments) {
  for (std::size_t a = 0; a < segments.size(); ++a)
    for (std::size_t b = a + 1; b < segments.size(); ++b)
      if (segments[a].layer == segments[b].layer && segments[a].info.label == segments[b].info.label)
        throw InputError(file, segmentText(segments[a].info) + " and " + segmentText(segments[b].info) +
                                   " share a label value in one layer");
}

}  // namespace

void writeSegmentation(const std::filesystem::path& file, const Volume& volume,
                       const std::vector<SegmentInfo>& segments) {
  if (volumeFormatOf(file) != VolumeFormat::nrrd)
    throw InputError(file, "a segmentation is written as NRRD: name it .seg.nrrd");
  requireWritableVolume(volume, file);
  requireValidSegments(file, segments);
  const LabelBoxes boxes = labelBoxes(volume);
  const itk::MetaDataDictionary fields =
      segmentationFields(volume, everyLabelsSegment(segments, boxes), boxes);
  writeOnGrid<std::uint8_t>(
      volume, file, [](Voxel voxel) { return std::uint8_t(labelOf(voxel)); }, fields);
}

std::optional<SegmentationInfo> readSegmentationInfo(const std::filesystem::path& file) {
  if (volumeFormatOf(file) != VolumeFormat::nrrd) return std::nullopt;
  const NrrdHeader header = readNrrdHeader(file);
  if (!isSegmentation(header.fields)) return std::nullopt;
  SegmentationInfo segmentation;
  segmentation.layers = header.components;  // Slicer stores layers along a leading "list" axis
  std::vector<StoredSegment> stored;
  const std::size_t count = segmentCount(file, header.fields);
  for (std::size_t n = 0; n < count; ++n)
    stored.push_back(storedSegment(file, header.fields, n, segmentation.layers));
  requireDistinctLabels(file, stored);
  for (const StoredSegment& segment : stored) segmentation.segments.push_back(segment.info);
  return segmentation;
}

std::array<bool, kMaxLabel + 1> segmentLabelValues(const std::filesystem::path& file,
                                                   const SegmentationInfo& segmentation) {
  if (segmentation.layers > 1)
    throw InputError(file, "overlapping segments (" + std::to_string(segmentation.layers) +
                               " layers) are not supported; in Slicer, make the segments not overlap "
                               "(Segment Editor, masking: overwrite other segments) and save again, "
                               "or export them to a labelmap volume");
  std::array<bool, kMaxLabel + 1> labels{};
  labels[0] = true;  // background
  for (const SegmentInfo& segment : segmentation.segments) labels[segment.label] = true;
  return labels;
}

}  // namespace angio
