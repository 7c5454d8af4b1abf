#include "render/label_styles.h"

#include <charconv>
#include <stdexcept>

#include "core/voxel.h"
#include "io/label_volume_file.h"
#include "io/lowercase.h"

namespace angio {

namespace {

std::optional<int> labelNumber(const std::string& text) {
  int number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (number < 1 || number > kMaxLabel) return std::nullopt;
  return number;
}

}  // namespace

std::string defaultLabelName(int label) {
  if (label == kBoneLabel) return "bone";
  if (label == kTableLabel) return "table";
  return "label " + std::to_string(label);
}

glm::vec3 defaultLabelColor(int label) {
  if (label == kBoneLabel) return {0.95f, 0.9f, 0.75f};
  if (label == kTableLabel) return {0.55f, 0.6f, 0.7f};
  // The user's labels: hues spread around the circle, none close to bone's or the lumen's.
  const glm::vec3 palette[] = {{0.3f, 0.75f, 0.35f}, {0.3f, 0.55f, 0.95f}, {0.9f, 0.6f, 0.2f},
                               {0.7f, 0.4f, 0.9f},   {0.2f, 0.8f, 0.8f},   {0.9f, 0.45f, 0.6f}};
  return palette[(label - 3) % 6];
}

std::optional<int> findLabel(const std::vector<LabelStyle>& styles, const std::string& nameOrNumber) {
  if (const auto number = labelNumber(nameOrNumber)) return number;
  const std::string wanted = lowercase(nameOrNumber);
  for (const LabelStyle& style : styles)
    if (lowercase(style.name) == wanted) return style.label;
  for (int label = 1; label <= kMaxLabel; ++label)
    if (defaultLabelName(label) == wanted) return label;
  return std::nullopt;
}

LabelStyle& styleOf(std::vector<LabelStyle>& styles, int label) {
  for (LabelStyle& style : styles)
    if (style.label == label) return style;
  styles.push_back({label, defaultLabelName(label), LabelMode::main, {}, defaultLabelColor(label)});
  return styles.back();
}

void hideLabels(std::vector<LabelStyle>& styles, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const std::optional<int> label = findLabel(styles, name);
    if (!label)
      throw std::invalid_argument("--hide " + name +
                                  ": no such label (bone, table, 1-15 or a name from the TF's labels)");
    styleOf(styles, *label).mode = LabelMode::hidden;
  }
}

std::vector<SegmentInfo> segmentsOf(const std::vector<LabelStyle>& styles,
                                    const std::array<std::uint64_t, kLabelCount>& voxels) {
  std::vector<LabelStyle> named = styles;
  std::vector<SegmentInfo> segments;
  for (int label = 1; label <= kMaxLabel; ++label) {
    if (voxels[label] == 0) continue;
    const LabelStyle& style = styleOf(named, label);
    segments.push_back({label, style.name, style.color});
  }
  return segments;
}

void writeLabelFile(const std::filesystem::path& file, const Volume& volume,
                    const std::vector<LabelStyle>& styles,
                    const std::array<std::uint64_t, kLabelCount>& voxels) {
  const std::string name = file.filename().string();
  const std::string suffix = ".seg.nrrd";
  if (name.size() > suffix.size() && lowercase(name.substr(name.size() - suffix.size())) == suffix)
    writeSegmentation(file, volume, segmentsOf(styles, voxels));
  else writeLabelVolume(file, volume);
}

std::vector<LabelStyle> withRemovedShown(std::vector<LabelStyle> styles) {
  for (LabelStyle& style : styles) {
    if (style.mode != LabelMode::hidden) continue;
    style.mode = LabelMode::tf;
    style.points = {{-1024, style.color, 0},
                    {-500, style.color, 0},
                    {-300, style.color, 0.02},
                    {3071, style.color, 0.05}};
  }
  return styles;
}

}  // namespace angio
