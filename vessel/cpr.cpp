#include "vessel/cpr.h"

#include "core/number_text.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace angio {

namespace {

std::string rowMeaning(CprMode mode) {
  switch (mode) {
    case CprMode::projected:
      return "the DVR image's rows: v = (height / 2 - row - 0.5) * mm_per_pixel along the up axis";
    case CprMode::stretched:
      return "centerline length orthogonal to the image's horizontal, (row + 0.5) * mm_per_pixel "
             "from the path start (isometric: lengths along the drawn centerline are true)";
    case CprMode::straightened: return "arc length from the path start: s = (row + 0.5) * mm_per_pixel";
  }
  return "";
}

std::string columnMeaning(const CprLayout& layout) {
  switch (layout.mode) {
    case CprMode::projected: return "the DVR image's columns";
    case CprMode::stretched:
      return "the DVR image's columns shifted: column + " + std::to_string(layout.columnOffset);
    case CprMode::straightened:
      return "distance from the centerline along the vector of interest, panels of " +
             numberText(layout.widthMm) + " mm per path";
  }
  return "";
}

}  // namespace

ViewGeometry cprView(const Volume& volume, Axis axis, double angleDeg, double pixelMm) {
  if (!std::isfinite(pixelMm) || pixelMm <= 0) {
    throw std::invalid_argument("CPR pixel size must be a finite length > 0 mm");
  }
  // The CPR's pixel is the view's image sample distance (in voxels), which has a floor.
  if (pixelMm / voxelUnit(volume) < kMinSamplingDistance) {
    throw std::invalid_argument("CPR pixel size " + numberText(pixelMm) +
                                " mm is too small for this volume (at least " +
                                numberText(kMinSamplingDistance * voxelUnit(volume)) + " mm)");
  }
  RenderParams params;
  params.axis = axis;
  params.angleDeg = angleDeg;
  params.sampling.isd = pixelMm / voxelUnit(volume);
  return makeViewGeometry(volume, params);
}

Cpr computeCpr(const Volume& volume, const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
               const CprSettings& settings, CprResampler resampler) {
  Cpr cpr;
  cpr.layout = layoutCpr(paths, view, settings);
  cpr.hu = resampleCpr(volume, cpr.layout, resampler);
  return cpr;
}

std::optional<CprPick> pickCpr(const Cpr& cpr, int x, int y) {
  if (x < 0 || y < 0 || x >= cpr.layout.width || y >= cpr.layout.height) return std::nullopt;
  // Spans are in row order: find the row's first by bisection, then the one holding x.
  const std::vector<CprSpan>& spans = cpr.layout.spans;
  auto span = std::lower_bound(spans.begin(), spans.end(), y,
                               [](const CprSpan& s, int row) { return s.row < row; });
  for (; span != spans.end() && span->row == y; ++span) {
    if (x < span->x0 || x >= span->x1) continue;
    return CprPick{span->pointMm(x), cpr.huAt(x, y), span->path, span->arcMm};
  }
  return std::nullopt;
}

std::map<std::string, std::string> cprMetadata(const CprLayout& layout,
                                               const CprDescription& description) {
  std::string paths;
  for (const std::string& name : description.pathNames) paths += (paths.empty() ? "" : "; ") + name;
  std::map<std::string, std::string> metadata{
      {"dataset", description.dataset},
      {"centerlines", description.centerlines},
      {"cpr_paths", paths},
      {"cpr_mode", toString(layout.mode)},
      {"axis", toString(description.axis)},
      {"angle_deg", numberText(description.angleDeg)},
      {"mm_per_pixel", numberText(layout.pixelMm)},
      {"cpr_rows", rowMeaning(layout.mode)},
      {"cpr_columns", columnMeaning(layout)},
      {"cpr_width_mm", numberText(layout.widthMm)},
      {"cpr_display", description.display},
      {"cpr_resampler", toString(description.resampler)},
  };
  if (layout.mode == CprMode::stretched)
    metadata["cpr_column_offset"] = std::to_string(layout.columnOffset);
  return metadata;
}

}  // namespace angio
