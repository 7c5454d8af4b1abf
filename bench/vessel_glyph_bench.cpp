#include "bench/vessel_glyph_bench.h"
#include "bench/timing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/info.h>

#include "core/view_geometry.h"

namespace angio {

namespace {

// Uniform in [lo, hi) from the raw engine (std distributions differ between libraries).
double uniform(std::mt19937_64& random, double lo, double hi) {
  return lo + (hi - lo) * double(random() >> 11) * 0x1.0p-53;
}

std::size_t vertexCount(const GlyphTubes& tubes) {
  std::size_t count = 0;
  for (const auto& chain : tubes.chains) count += chain.size();
  return count;
}

// FNV-1a over the bytes of the regions' offsets and interval fields (padding left out).
void hashRegions(const RayRegions& regions, std::uint64_t& hash) {
  const auto mix = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t n = 0; n < size; ++n) hash = (hash ^ bytes[n]) * 0x100000001b3ull;
  };
  mix(regions.rayBegin.data(), regions.rayBegin.size() * sizeof(std::uint32_t));
  for (const RegionInterval& interval : regions.intervals) {
    mix(&interval.begin, sizeof interval.begin);
    mix(&interval.end, sizeof interval.end);
    mix(&interval.region, sizeof interval.region);
  }
}

}  // namespace

GlyphBenchResult runVesselGlyphBench(const Volume& volume, const Centerlines& inVolumeFrame,
                                     const VesselGlyphSettings& glyph,
                                     const GlyphBenchSettings& settings) {
  std::optional<tbb::global_control> limit;
  if (settings.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, settings.threads);
  GlyphBenchResult result;
  result.threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  result.checksum = 0xcbf29ce484222325ull;
  RenderParams params;
  params.axis = settings.axis;
  params.sampling = qualitySampling(settings.quality);
  std::vector<double> fullMs, perViewMs, perViewCpuMs, prepareMs, intervals, covered;
  RayRegionBuilder builder(inVolumeFrame, glyph);
  RayRegions reused;
  for (int n = 0; n < settings.angles; ++n) {
    params.angleDeg = 360.0 * n / settings.angles;
    const ViewGeometry view = makeViewGeometry(volume, params);
    auto start = BenchClock::now();
    const RayRegions regions = buildRayRegions(volume, view, inVolumeFrame, glyph);
    fullMs.push_back(msSince(start));

    start = BenchClock::now();
    const GlyphTubes tubes = prepareGlyphTubes(inVolumeFrame, glyph);
    prepareMs.push_back(msSince(start));
    start = BenchClock::now();
    const double cpuStart = processCpuMs();
    builder.build(view, reused);
    perViewMs.push_back(msSince(start));
    perViewCpuMs.push_back(processCpuMs() - cpuStart);

    result.width = regions.width;
    result.height = regions.height;
    result.sourcePoints = tubes.sourcePoints;
    result.tubeVertices = vertexCount(tubes);
    hashRegions(reused, result.checksum);
    intervals.push_back(double(regions.intervals.size()));
    std::size_t hitPixels = 0;
    for (std::size_t p = 0; p + 1 < regions.rayBegin.size(); ++p) {
      hitPixels += regions.rayBegin[p + 1] > regions.rayBegin[p];
    }
    covered.push_back(double(hitPixels) / std::max<std::size_t>(1, regions.rayBegin.size() - 1));
  }
  result.views = settings.angles;
  if (!fullMs.empty()) {
    result.medianMs = median(fullMs);
    result.minMs = *std::min_element(fullMs.begin(), fullMs.end());
    result.maxMs = *std::max_element(fullMs.begin(), fullMs.end());
    result.perViewMedianMs = median(perViewMs);
    result.perViewMinMs = *std::min_element(perViewMs.begin(), perViewMs.end());
    result.perViewMaxMs = *std::max_element(perViewMs.begin(), perViewMs.end());
    result.perViewMedianCpuMs = median(perViewCpuMs);
    result.prepareMs = median(prepareMs);
    result.medianIntervals = median(intervals);
    result.coveredPixels = median(covered);
  }
  return result;
}

namespace {

struct TreeBranch {
  int parent = -1;
  std::vector<CenterlinePoint> points;  // the first one is the parent's last
};

// A branch from `from` down to height zEnd: drifting sideways by `drift` (mm) with wiggles,
// radius from r0 to r1, one point per `stepMm` of height.
TreeBranch growBranch(std::mt19937_64& random, int parent, glm::dvec3 from, glm::dvec2 drift,
                      double zEnd, double r0, double r1, double stepMm, glm::dvec3 extent) {
  TreeBranch branch;
  branch.parent = parent;
  const int steps = std::max(1, int(std::round((from.z - zEnd) / stepMm)));
  const double amplitude = uniform(random, 2, 8), frequency = uniform(random, 0.5, 3);
  const double phaseX = uniform(random, 0, 2 * std::numbers::pi);
  const double phaseY = uniform(random, 0, 2 * std::numbers::pi);
  for (int n = 0; n <= steps; ++n) {
    const double s = double(n) / steps;
    // Wiggles vanish at both ends so that branches join smoothly.
    const double envelope = std::sin(std::numbers::pi * s);
    const double w = 2 * std::numbers::pi * frequency * s;
    glm::dvec3 p(from.x + drift.x * s + amplitude * envelope * std::sin(w + phaseX),
                 from.y + drift.y * s + amplitude * envelope * std::cos(w + phaseY),
                 from.z + (zEnd - from.z) * s);
    p = glm::clamp(p, glm::dvec3(0.0), extent);
    branch.points.push_back({n == 0 ? from : p, r0 + (r1 - r0) * s});
  }
  return branch;
}

}  // namespace

Centerlines syntheticVesselTree(const Volume& volume, int leaves, int pointsPerPath,
                                std::uint64_t seed) {
  const glm::dvec3 extent = domainExtent(volume);
  std::mt19937_64 random(seed);
  const double top = 0.98 * extent.z, bottom = 0.02 * extent.z;
  const double stepMm = (top - bottom) / std::max(1, pointsPerPath);
  // Generation g ends at height levels[g]; radii shrink by generation.
  const double levels[] = {0.72, 0.58, 0.45, 0.32, 0.02};
  const double radii[] = {10, 5, 4, 3, 2, 1.2};
  std::vector<TreeBranch> branches;
  branches.push_back(growBranch(random, -1, {0.5 * extent.x, 0.45 * extent.y, top}, {0, 8},
                                levels[0] * extent.z, radii[0], 8, stepMm, extent));
  std::vector<int> tips{0};
  for (int generation = 1; generation < 5; ++generation) {
    std::vector<int> next;
    for (std::size_t t = 0; t < tips.size(); ++t) {
      // Split in two, or in three where that is needed to reach `leaves` at the last generation.
      const int remaining = leaves - int(next.size()) - 2 * int(tips.size() - t - 1);
      const int children = generation < 4 ? 2 : std::clamp(remaining, 1, 3);
      for (int c = 0; c < children; ++c) {
        const TreeBranch& parent = branches[std::size_t(tips[t])];
        const double spread = generation == 1 ? 120.0 : 60.0 / generation;  // legs, then branches
        const glm::dvec2 drift((c - (children - 1) / 2.0) * spread + uniform(random, -10, 10),
                               uniform(random, -15, 15));
        branches.push_back(growBranch(random, tips[t], parent.points.back().positionMm, drift,
                                      levels[generation] * extent.z, radii[generation],
                                      radii[generation + 1], stepMm, extent));
        next.push_back(int(branches.size()) - 1);
      }
    }
    tips = std::move(next);
  }
  Centerlines centerlines;
  centerlines.source = "synthetic tree";
  centerlines.frame = CenterlineFrame::volume;
  for (int tip : tips) {
    std::vector<int> chain;
    for (int b = tip; b >= 0; b = branches[std::size_t(b)].parent) chain.insert(chain.begin(), b);
    CenterlinePath& path = centerlines.paths.emplace_back();
    path.name = "leaf-" + std::to_string(tip);
    for (int b : chain) {
      const auto& points = branches[std::size_t(b)].points;
      path.points.insert(path.points.end(), points.begin() + (path.points.empty() ? 0 : 1),
                         points.end());
    }
  }
  return centerlines;
}

Centerlines syntheticCenterlines(const Volume& volume, int paths, int pointsPerPath,
                                 std::uint64_t seed) {
  const glm::dvec3 extent = domainExtent(volume);
  std::mt19937_64 random(seed);
  Centerlines centerlines;
  centerlines.source = "synthetic";
  centerlines.frame = CenterlineFrame::volume;
  for (int p = 0; p < paths; ++p) {
    CenterlinePath& path = centerlines.paths.emplace_back();
    path.name = "synthetic-" + std::to_string(p);
    const glm::dvec2 from(uniform(random, 0.3, 0.7) * extent.x, uniform(random, 0.3, 0.7) * extent.y);
    const glm::dvec2 to(uniform(random, 0.2, 0.8) * extent.x, uniform(random, 0.2, 0.8) * extent.y);
    double amplitude[4], frequency[4], phase[4];
    for (int w = 0; w < 4; ++w) {
      amplitude[w] = uniform(random, 5, 25);
      frequency[w] = uniform(random, 1, 6);
      phase[w] = uniform(random, 0, 2 * std::numbers::pi);
    }
    const auto wiggle = [&](int w, double s) {
      return amplitude[w] * std::sin(2 * std::numbers::pi * frequency[w] * s + phase[w]);
    };
    const int count = std::max(2, pointsPerPath);
    for (int n = 0; n < count; ++n) {
      const double s = double(n) / (count - 1);
      const glm::dvec2 lateral =
          glm::mix(from, to, s) + glm::dvec2(wiggle(0, s) + wiggle(1, s), wiggle(2, s) + wiggle(3, s));
      const glm::dvec3 position(std::clamp(lateral.x, 0.0, extent.x),
                                std::clamp(lateral.y, 0.0, extent.y), (0.98 - 0.96 * s) * extent.z);
      path.points.push_back({position, 10.0 - 8.0 * s});
    }
  }
  return centerlines;
}

std::string formatGlyphBench(const GlyphBenchResult& result) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << "VesselGlyph intervals, image " << result.width << " x " << result.height << ", "
      << result.views << " views: median " << result.medianMs << " ms (min " << result.minMs << ", max "
      << result.maxMs << "); per view with prepared tubes and reused output " << result.perViewMedianMs
      << " ms (min " << result.perViewMinMs << ", max " << result.perViewMaxMs << "; CPU "
      << result.perViewMedianCpuMs << " ms on " << result.threads << " threads); view-independent part "
      << result.prepareMs << " ms; " << result.sourcePoints << " centerline points -> "
      << result.tubeVertices << " tube vertices; " << std::size_t(result.medianIntervals)
      << " intervals, " << 100 * result.coveredPixels << "% of pixels covered; checksum " << std::hex
      << result.checksum << std::dec << "\n";
  return out.str();
}

}  // namespace angio
