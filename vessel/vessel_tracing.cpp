#include "vessel/vessel_tracing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/volume_sampling.h"
#include "vessel/downstream_tracing.h"
#include "vessel/lumen_paths.h"
#include "vessel/lumen_section.h"
#include "vessel/trunk_sharing.h"

namespace angio {

namespace {

// The mean density of the 3x3x3 voxels around one (clamped at the border).
double smoothedDensity(const Volume& volume, glm::ivec3 voxel) {
  double sum = 0;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) sum += densityAtClamped(volume, voxel + glm::ivec3(di, dj, dk));
  return sum / 27.0;
}

bool insideVolume(const Volume& volume, glm::ivec3 voxel) {
  return glm::all(glm::greaterThanEqual(voxel, glm::ivec3(0))) &&
         glm::all(glm::lessThan(voxel, volume.dims));
}

glm::ivec3 voxelAt(const Volume& volume, glm::dvec3 pointMm) {
  return glm::ivec3(glm::floor(pointMm / volume.spacing + 0.5));
}

// How much brighter than tissue a lumen must be to count as contrast-filled.
constexpr double kMinContrastHu = 100;
constexpr double kSoftTissueHu = 50;

double medianHu(const Volume& volume) {
  const DensityHistogram histogram = densityHistogram(volume);
  std::uint64_t seen = 0;
  for (int d = 0; d < kDensityLevels; ++d) {
    seen += histogram[d];
    if (2 * seen >= volume.voxelCount()) return huOfDensity(d);
  }
  return kSoftTissueHu;
}

std::string pointName(std::size_t n) { return "point " + std::to_string(n + 1); }

}  // namespace

VesselTracer::VesselTracer(const Volume& volume, TraceSettings settings)
    : volume_(&volume), settings_(settings), contrast_(settings.contrast) {}

std::optional<double> VesselTracer::lumenHuNear(glm::dvec3 pointMm) const {
  glm::ivec3 voxel = voxelAt(*volume_, pointMm);
  if (!insideVolume(*volume_, voxel)) return std::nullopt;
  const glm::ivec3 start = voxel;
  double here = smoothedDensity(*volume_, voxel);
  // Steepest ascent: from a click on a vessel's surface the density rises into its lumen.
  for (bool climbed = true; climbed;) {
    climbed = false;
    glm::ivec3 best = voxel;
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const glm::ivec3 next = voxel + glm::ivec3(di, dj, dk);
          if (!insideVolume(*volume_, next)) continue;
          if (glm::length(glm::dvec3(next - start) * volume_->spacing) > settings_.snapRadiusMm)
            continue;
          const double density = smoothedDensity(*volume_, next);
          if (density > here) {
            here = density;
            best = next;
            climbed = true;
          }
        }
    voxel = best;
  }
  return huOfDensity(here);
}

// What the data say surrounds the vessels, unless the settings say: soft tissue's 50 HU in
// calibrated CT; in data that are not calibrated HU (exported research scans: tissue can reach
// 500 and the lumen vary 900-2400 along one vessel) the volume's median density (a cropped scan is
// mostly tissue), and calcium has no known density there, so the range reaches the top of the
// 12-bit scale.
void VesselTracer::learnTheData() {
  if (calibrated_) return;
  calibrated_ = looksHuCalibrated(*volume_);
  tissueHu_ = settings_.tissueHu ? *settings_.tissueHu
              : *calibrated_     ? kSoftTissueHu
                                 : medianHu(*volume_);
  calciumHu_ = settings_.calciumHu;
  if (!calciumHu_ && !*calibrated_) calciumHu_ = huOfDensity(kDensityLevels - 1);
}

void VesselTracer::widenContrastFor(glm::dvec3 pointMm) {
  if (settings_.contrast) return;
  learnTheData();
  // Only a lumen brighter than tissue counts: a click on air or fat must not set the range.
  const auto lumen = lumenHuNear(pointMm);
  if (!lumen || *lumen < tissueHu_ + kMinContrastHu) return;
  if (contrast_ && *lumen >= contrast_->lowHu && *lumen <= contrast_->highHu) return;
  const ContrastRange here = contrastRangeFor(*lumen, tissueHu_, calciumHu_);
  contrast_ = contrast_ ? ContrastRange{std::min(contrast_->lowHu, here.lowHu),
                                        std::max(contrast_->highHu, here.highHu)}
                        : here;
}

bool VesselTracer::prepare(const VoxelBox& box, const std::atomic<bool>* cancel) {
  if (!contrast_) return false;
  if (field_.isReady() && field_.range() == *contrast_ && containsBox(field_.coverage(), box))
    return true;
  VoxelBox wanted = box;
  if (field_.isReady() && field_.range() == *contrast_) {
    wanted.lo = glm::min(wanted.lo, field_.coverage().lo);
    wanted.hi = glm::max(wanted.hi, field_.coverage().hi);
  }
  LumenField field(*volume_, *contrast_, wanted, cancel);
  if (!field.isReady()) return false;
  field_ = std::move(field);
  return true;
}

std::optional<glm::ivec3> VesselTracer::nearestLumenVoxel(glm::dvec3 pointMm) const {
  const glm::ivec3 centre = voxelAt(*volume_, pointMm);
  const glm::ivec3 reach = glm::ivec3(glm::ceil(settings_.snapRadiusMm / volume_->spacing));
  std::optional<glm::ivec3> nearest;
  double nearestMm = std::numeric_limits<double>::infinity();
  for (int dk = -reach.z; dk <= reach.z; ++dk)
    for (int dj = -reach.y; dj <= reach.y; ++dj)
      for (int di = -reach.x; di <= reach.x; ++di) {
        const glm::ivec3 voxel = centre + glm::ivec3(di, dj, dk);
        if (!field_.isLumen(voxel)) continue;
        const double mm = glm::length(glm::dvec3(voxel) * volume_->spacing - pointMm);
        if (mm <= settings_.snapRadiusMm && mm < nearestMm) {
          nearestMm = mm;
          nearest = voxel;
        }
      }
  return nearest;
}

// Up the distance map to its ridge: the lumen's centre in the voxel grid. Within the snap radius of
// the click: along a tapering vessel the map keeps rising towards its wider end.
glm::ivec3 VesselTracer::climbToRidge(glm::ivec3 voxel, glm::dvec3 clickMm) const {
  for (bool climbed = true; climbed;) {
    climbed = false;
    glm::ivec3 best = voxel;
    float bestWall = field_.wallDistanceMm(voxel);
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const glm::ivec3 next = voxel + glm::ivec3(di, dj, dk);
          const float wall = field_.wallDistanceMm(next);
          if (glm::length(glm::dvec3(next) * volume_->spacing - clickMm) > settings_.snapRadiusMm)
            continue;
          if (wall > bestWall) {
            bestWall = wall;
            best = next;
            climbed = true;
          }
        }
    voxel = best;
  }
  return voxel;
}

SnappedPoint VesselTracer::snap(glm::dvec3 pointMm, const std::atomic<bool>* cancel) {
  if (!insideVolume(*volume_, voxelAt(*volume_, pointMm)))
    return {std::nullopt, "the point lies outside the volume"};
  widenContrastFor(pointMm);
  if (!contrast_) {
    char problem[160];
    std::snprintf(problem, sizeof problem,
                  "no contrast-filled vessel within %.0f mm (nothing %.0f HU above tissue)",
                  settings_.snapRadiusMm, kMinContrastHu);
    return {std::nullopt, problem};
  }
  if (!prepare(boxAround(*volume_, {pointMm}, settings_.snapRadiusMm + settings_.marginMm), cancel))
    return {std::nullopt, "cancelled"};
  const auto nearest = nearestLumenVoxel(pointMm);
  if (!nearest) {
    char problem[160];
    std::snprintf(problem, sizeof problem, "no contrast-filled vessel (%.0f..%.0f HU) within %.0f mm",
                  contrast_->lowHu, contrast_->highHu, settings_.snapRadiusMm);
    return {std::nullopt, problem};
  }
  return {glm::dvec3(climbToRidge(*nearest, pointMm)) * volume_->spacing, ""};
}

std::optional<std::vector<glm::ivec3>> VesselTracer::joinThroughLumen(
    const std::vector<glm::ivec3>& ends, const std::atomic<bool>* cancel) {
  std::vector<glm::ivec3> voxels;
  for (std::size_t n = 0; n + 1 < ends.size(); ++n) {
    const auto piece = cheapestLumenPath(field_, ends[n], ends[n + 1], cancel);
    if (!piece) return std::nullopt;
    voxels.insert(voxels.end(), piece->begin() + (voxels.empty() ? 0 : 1), piece->end());
  }
  return voxels;
}

TracedPath VesselTracer::trace(const std::vector<glm::dvec3>& pointsMm,
                               const std::atomic<bool>* cancel) {
  if (pointsMm.size() < 2) return {std::nullopt, "a path needs at least two points"};
  for (const glm::dvec3& point : pointsMm) widenContrastFor(point);
  std::vector<glm::ivec3> ends;
  for (std::size_t n = 0; n < pointsMm.size(); ++n) {
    const SnappedPoint snapped = snap(pointsMm[n], cancel);
    if (cancel && cancel->load()) return {std::nullopt, "cancelled"};
    if (!snapped.positionMm) return {std::nullopt, pointName(n) + ": " + snapped.problem};
    ends.push_back(voxelAt(*volume_, *snapped.positionMm));
  }
  // A vessel may leave the box around its clicks (a femoral bows out between the aorta and the
  // foot): where no path joins them inside it, the whole volume is searched.
  std::optional<std::vector<glm::ivec3>> voxels;
  for (const VoxelBox& box :
       {boxAround(*volume_, pointsMm, settings_.marginMm), wholeVolume(*volume_)}) {
    if (!prepare(box, cancel)) return {std::nullopt, "cancelled"};
    voxels = joinThroughLumen(ends, cancel);
    if (voxels || (cancel && cancel->load())) break;
  }
  if (cancel && cancel->load()) return {std::nullopt, "cancelled"};
  if (!voxels) return {std::nullopt, "the points are not joined by contrast-filled lumen"};
  return {centerlineOf(*voxels), ""};
}

TracedTree VesselTracer::traceDownstream(glm::dvec3 seedMm, const std::atomic<bool>* cancel,
                                         const std::function<void(double)>& progress) {
  const SnappedPoint snapped = snap(seedMm, cancel);
  if (!snapped.positionMm) return {{}, snapped.problem};
  if (progress) progress(0.05);
  if (!prepare(wholeVolume(*volume_), cancel)) return {{}, "cancelled"};
  if (progress) progress(0.6);
  const auto chains = downstreamChains(*volume_, field_, voxelAt(*volume_, *snapped.positionMm),
                                       settings_.downstream, cancel, [&](double f) {
                                         if (progress) progress(0.6 + 0.2 * f);
                                       });
  if (cancel && cancel->load()) return {{}, "cancelled"};
  if (chains.empty()) return {{}, "no vessel leaves the click"};
  TracedTree tree;
  tree.centerlines.source = "traced";
  tree.centerlines.frame = CenterlineFrame::volume;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    CenterlinePath path = centerlineOf(chains[c]);
    shareTrunk(path, tree.centerlines.paths);
    path.name = std::to_string(c + 1);
    tree.centerlines.paths.push_back(std::move(path));
    if (progress) progress(0.8 + 0.2 * double(c + 1) / double(chains.size()));
  }
  return tree;
}

CenterlinePath VesselTracer::centerlineOf(const std::vector<glm::ivec3>& voxels) const {
  std::vector<float> wall;
  for (const glm::ivec3& v : voxels) wall.push_back(field_.wallDistanceMm(v));
  return centerlineFromVoxels(*volume_, *contrast_, voxels, wall, settings_.stepMm);
}

}  // namespace angio
