#include "core/adaptive_sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/clip_interval.h"
#include "core/preintegration.h"
#include "core/view_geometry.h"
#include "core/volume_sampling.h"

namespace angio {

namespace {

// ceil(n / 2) for any integer n (a level's pixel index can be -1).
int ceilHalf(int n) { return (n + 1) >> 1; }
constexpr long kNever = std::numeric_limits<long>::min();
constexpr float kNotTaken = std::numeric_limits<float>::quiet_NaN();
long floorTo(long k, long step) { return k >= 0 ? k / step * step : -((-k + step - 1) / step) * step; }

// What every band reads.
struct Scene {
  const Volume& volume;
  const TfTable& table;
  const PreintegratedTable& segments;
  const SamplingOracle& oracle;
  const MaskedDensity& read;
  const RenderParams& params;
  const ViewGeometry& view;
  int levels = 0;         // l_max of the image pyramid
  int rayLevels = 0;      // the same along rays (>= levels): samples up to 2^rayLevels apart
  double unit = 1.0;      // u = max(isd, osd): the oracle's distances are divided by it
  glm::dvec3 stepQ{0.0};  // from one sample of a ray to the next, continuous voxel coordinates
  glm::vec3 viewDir{0.f};
};

// One level of a band's image pyramid: pixels [xBegin, xEnd) x [rowBegin, rowEnd) of the level,
// what they hold (sec. 3.2) and the buckets of pixels by the power of two they wait for.
struct Level {
  int xBegin = 0, xEnd = 0, rowBegin = 0, rowEnd = 0;
  std::vector<float> density, shade, distance;
  std::vector<long> updated;              // the slice each pixel was last updated on
  std::vector<std::vector<int>> buckets;  // [j - level]: pixels updated on slices divisible by 2^j

  int width() const { return xEnd - xBegin; }
  int size() const { return width() * (rowEnd - rowBegin); }
  int index(int x, int row) const { return (row - rowBegin) * width() + (x - xBegin); }
};

// Level 0's compositing per ray (Fig. 6): the colour so far and where its last segment ended.
struct Ray {
  RayAccumulator accumulated;
  float frontDensity = 0.f, frontShade = 1.f;
  long front = 0;            // the slice of the last update
  long first = 1, last = 0;  // the ray's samples (clipped)
  bool done = false;         // missed the volume, behind its last sample, or terminated

  void moveFront(long slice, float density, float shade) {
    front = slice;
    frontDensity = density;
    frontShade = shade;
  }
};

class Band {
 public:
  Band(const Scene& scene, int y0, int y1) : s_(scene), y0_(y0), y1_(y1), levels_(scene.levels + 1) {
    Level* finer = nullptr;
    for (int l = 0; l <= s_.levels; ++l) {
      Level& level = levels_[l];
      if (!finer) {
        level.xEnd = s_.view.width;
        level.rowBegin = y0;
        level.rowEnd = y1;
      } else {  // the parents that synthesis reads: ceil(x / 2) - 1 and ceil(x / 2) (Fig. 5)
        level.xBegin = ceilHalf(finer->xBegin) - 1;
        level.xEnd = ceilHalf(finer->xEnd - 1) + 1;
        level.rowBegin = ceilHalf(finer->rowBegin) - 1;
        level.rowEnd = ceilHalf(finer->rowEnd - 1) + 1;
      }
      level.density.assign(level.size(), 0.f);
      level.shade.assign(level.size(), 1.f);
      level.distance.assign(level.size(), 0.f);
      level.updated.assign(level.size(), kNever);
      level.buckets.resize(s_.rayLevels - l + 1);
      finer = &level;
    }
    setUpRays();
  }

  // Composites every slice of the band's rays into `image`; false if cancelled first.
  bool render(Image& image, AdaptiveSamplingStats& stats, const std::atomic<bool>* cancel) {
    const long period = 1L << s_.levels;
    for (long k = kBegin_; k <= kEnd_ && raysLeft_ > 0; ++k) {
      const long i = k - kBegin_;
      if (i % period == 0 && cancel && cancel->load(std::memory_order_relaxed)) return false;
      const int sliceLevel =
          i == 0 ? s_.rayLevels : std::min(std::countr_zero(std::uint64_t(i)), s_.rayLevels);
      for (int l = std::min(sliceLevel, s_.levels); l >= 0; --l) updateLevel(l, sliceLevel, k, stats);
    }
    for (int y = y0_; y < y1_; ++y)
      for (int x = 0; x < s_.view.width; ++x)
        image.at(x, y) = rays_[levels_[0].index(x, y)].accumulated.pixel();
    return true;
  }

 private:
  void setUpRays() {
    const Level& level = levels_[0];
    rays_.resize(level.size());
    long first = std::numeric_limits<long>::max(), last = std::numeric_limits<long>::min();
    for (int y = y0_; y < y1_; ++y)
      for (int x = 0; x < s_.view.width; ++x) {
        Ray& ray = rays_[level.index(x, y)];
        const SampleRange range =
            clippedSampleRange(s_.view, s_.params.clipping, s_.view.rayOrigin(x, y));
        ray.first = range.first;
        ray.last = range.last;
        ray.done = range.empty();
        if (ray.done) continue;
        ++raysLeft_;
        first = std::min(first, range.first);
        last = std::max(last, range.last);
      }
    // Slices from one before the first sample (the first segment's front), aligned so that slice 0
    // and the last one update every level (sec. 3.1: the last index divisible by 2^l_max).
    if (raysLeft_ == 0) return;  // no slice to walk
    const long period = 1L << s_.rayLevels;
    kBegin_ = floorTo(first - 1, period);
    kEnd_ = floorTo(last + period - 1, period);
  }

  // Level 0's position of level l's pixel (x, row): 2^l (x + 1/2) - 1/2 (Fig. 5).
  // Written as ViewGeometry::rayOrigin and RaySamples::at compute it, so that level 0 samples the
  // reference's positions to the bit (a ray through voxel boundaries must round as it does).
  glm::dvec3 positionQ(int l, int x, int row, long k) const {
    const double scale = double(1 << l);
    const double px = scale * (x + 0.5) - 0.5, py = scale * (row + 0.5) - 0.5;
    const ViewGeometry& v = s_.view;
    const double h = (px + 0.5 - v.width * 0.5) * v.pixelMm;
    const double u = (v.height * 0.5 - py - 0.5) * v.pixelMm;
    return samplePosition((v.centre + h * v.right + u * v.up) / s_.volume.spacing, s_.stepQ, double(k));
  }

  // The bucket a pixel of level l with distance d waits in: the smallest j >= l with d < 2^(j+1)
  // (so j = l: sample now), at most the ray levels.
  int waitLevel(float d, int l) const {
    int j = l;
    while (j < s_.rayLevels && d >= float(2L << j)) ++j;
    return j;
  }

  // Whether the four parents synthesis reads were updated on slice k. Along rays a pixel may wait
  // longer (2^rayLevels) than the pyramid's 2^l_max after which the seed refreshes every level; a
  // child must not be synthesised from parents that waited, so it is sampled instead.
  bool parentsUpdated(int l, int x, int row, long k) const {
    const Level& parent = levels_[l + 1];
    const int px = ceilHalf(x), py = ceilHalf(row);
    return parent.updated[parent.index(px - 1, py - 1)] == k &&
           parent.updated[parent.index(px, py - 1)] == k &&
           parent.updated[parent.index(px - 1, py)] == k && parent.updated[parent.index(px, py)] == k;
  }

  struct Point {
    float density = 0.f, shade = 1.f;
  };

  // The volume at level l's pixel (x, row) on slice k: density and shading factor. The gradient is
  // the costliest part of a sample, so it is taken where the density is visible; elsewhere the
  // shading factor is NaN ("not taken"), synthesis passes that on, and compositing takes the
  // gradient at level 0 only for the ends of segments that turn out visible.
  Point pointAt(int l, int x, int row, long k, AdaptiveSamplingStats& stats) const {
    return pointAt(positionQ(l, x, row, k), stats);
  }
  Point pointAt(const glm::dvec3& q, AdaptiveSamplingStats& stats) const {
    ++stats.samples;
    Point point{sampleDensity(s_.volume, q, s_.params.sampling.filter, s_.read), 1.f};
    if (s_.params.shading.enabled)
      point.shade = s_.table.rgba[tableIndex(point.density)].a > 0.f ? shadeAt(q) : kNotTaken;
    return point;
  }

  float shadeAt(const glm::dvec3& q) const {
    const glm::vec3 gradient = sampleGradient(s_.volume, q, s_.params.sampling.filter, s_.read);
    return shadingFactor(s_.params.shading, gradient, s_.viewDir);
  }
  float taken(float shade, int x, int row, long k) const {
    return std::isnan(shade) ? shadeAt(positionQ(0, x, row, k)) : shade;
  }

  // Fig. 5's SAMPLE and ORACLE.
  void sample(Level& level, int l, int p, int x, int row, long k, AdaptiveSamplingStats& stats) {
    const glm::dvec3 q = positionQ(l, x, row, k);
    const Point point = pointAt(q, stats);
    level.density[p] = point.density;
    level.shade[p] = point.shade;
    level.distance[p] = float(s_.oracle.distanceAt(q) / s_.unit);
  }

  // Biquadratic B-spline subdivision from level l + 1 (Fig. 4, 5): per axis 3/4 of the nearer
  // parent and 1/4 of the farther one.
  void synthesise(Level& level, int l, int p, int x, int row, AdaptiveSamplingStats& stats) {
    ++stats.synthesised;
    const Level& parent = levels_[l + 1];
    const int px = ceilHalf(x), py = ceilHalf(row);
    const float wx = (x & 1) ? 0.25f : 0.75f;  // of parent column px (the other: px - 1)
    const float wy = (row & 1) ? 0.25f : 0.75f;
    const int a = parent.index(px - 1, py - 1), b = parent.index(px, py - 1);
    const int c = parent.index(px - 1, py), d = parent.index(px, py);
    const float wa = (1 - wx) * (1 - wy), wb = wx * (1 - wy), wc = (1 - wx) * wy, wd = wx * wy;
    const auto mix = [&](const std::vector<float>& v) {
      return wa * v[a] + wb * v[b] + wc * v[c] + wd * v[d];
    };
    level.density[p] = mix(parent.density);
    level.shade[p] = mix(parent.shade);
    level.distance[p] = mix(parent.distance);
  }

  // The segment from the ray's front to `back` on slice `to` of level 0's pixel (x, row).
  void add(Ray& ray, Point back, int x, int row, long to, AdaptiveSamplingStats& stats) const {
    ++stats.segments;
    const glm::vec4 rgba = s_.segments.segment(ray.frontDensity, back.density, int(to - ray.front));
    if (rgba.a > 0.f)
      ray.accumulated.add(
          rgba, 0.5f * (taken(ray.frontShade, x, row, ray.front) + taken(back.shade, x, row, to)));
  }

  // Fig. 6's ACCUMULATECOLOR: the segment since the ray's last update. The ray's ends are taken as
  // the reference takes them (the seed's slices outside the volume read transparent; ours would
  // read the clamped faces and stretch them over a whole skip): entering, the samples first - 1
  // and first make the first segment; leaving, the segment ends at the last sample, taken.
  void composite(const Level& level, int p, int x, int row, long k, AdaptiveSamplingStats& stats) {
    Ray& ray = rays_[p];
    const Point now{level.density[p], level.shade[p]};
    if (ray.front <= ray.first - 1 && k >= ray.first) {
      if (ray.front < ray.first - 1) {
        const Point before = pointAt(0, x, row, ray.first - 1, stats);
        ray.moveFront(ray.first - 1, before.density, before.shade);
      }
      if (k > ray.first) {
        const Point first = pointAt(0, x, row, ray.first, stats);
        add(ray, first, x, row, ray.first, stats);
        ray.moveFront(ray.first, first.density, first.shade);
      }
    }
    const long to = std::min(k, ray.last);
    if (ray.front >= ray.first - 1 && to > ray.front)
      add(ray, to < k ? pointAt(0, x, row, to, stats) : now, x, row, to, stats);
    ray.moveFront(k, now.density, now.shade);
    ray.done = k >= ray.last || ray.accumulated.opacity >= s_.params.sampling.ert;
    raysLeft_ -= ray.done;
  }

  // One pixel of level l on a slice of level sliceLevel (Fig. 3); its new bucket, or -1 when its
  // ray is done.
  int update(Level& level, int l, int sliceLevel, int p, long k, AdaptiveSamplingStats& stats) {
    const int x = level.xBegin + p % level.width(), row = level.rowBegin + p / level.width();
    const bool synthesised = l < sliceLevel && l < s_.levels && parentsUpdated(l, x, row, k);
    if (synthesised) synthesise(level, l, p, x, row, stats);
    if (!synthesised || level.distance[p] < float(2L << l)) sample(level, l, p, x, row, k, stats);
    level.updated[p] = k;
    if (l == 0) {
      if (sliceLevel == s_.rayLevels || level.distance[p] < float(2L << sliceLevel))
        composite(level, p, x, row, k, stats);
      if (rays_[p].done) return -1;
    }
    return waitLevel(level.distance[p], l);
  }

  void updateLevel(int l, int sliceLevel, long k, AdaptiveSamplingStats& stats) {
    Level& level = levels_[l];
    if (sliceLevel == s_.rayLevels) {  // every pixel of the level; the buckets made anew
      for (auto& bucket : level.buckets) bucket.clear();
      for (int p = 0; p < level.size(); ++p) {
        if (l == 0 && rays_[p].done) continue;
        const int j = update(level, l, sliceLevel, p, k, stats);
        if (j >= 0) level.buckets[j - l].push_back(p);
      }
      return;
    }
    moved_.clear();
    for (int j = l; j <= sliceLevel; ++j) {
      std::vector<int>& bucket = level.buckets[j - l];
      std::size_t kept = 0;
      for (const int p : bucket) {
        const int to = update(level, l, sliceLevel, p, k, stats);
        if (to == j) bucket[kept++] = p;
        else if (to >= 0) moved_.push_back({p, to});
      }
      bucket.resize(kept);
    }
    for (const auto& [p, j] : moved_) level.buckets[j - l].push_back(p);
  }

  const Scene& s_;
  int y0_, y1_;
  std::vector<Level> levels_;
  std::vector<Ray> rays_;
  long kBegin_ = 0, kEnd_ = -1;
  long raysLeft_ = 0;  // level 0's rays not done
  std::vector<std::pair<int, int>> moved_;
};

Scene makeScene(const Volume& volume, const TfTable& table, const PreintegratedTable& segments,
                const SamplingOracle& oracle, const MaskedDensity& read, const RenderParams& params,
                const ViewGeometry& view) {
  Scene s{volume, table, segments, oracle, read, params, view};
  s.levels = params.sampling.adaptiveSampling->levels;
  s.rayLevels = params.sampling.adaptiveSampling->rayLevels;  // >= levels (samplingProblem)
  s.unit = std::max(params.sampling.isd, params.sampling.osd);
  s.stepQ = RaySamples(volume, view, view.centre).stepQ;
  s.viewDir = glm::vec3(view.viewDir);
  return s;
}

}  // namespace

std::string adaptiveSamplingProblem(const RenderParams& params) {
  if (!params.sampling.adaptiveSampling) return "adaptive sampling is not enabled";
  if (params.compositing == Compositing::mip) return "adaptive sampling is for DVR, not MIP";
  return samplingProblem(params.sampling);
}

SamplingOracle makeSamplingOracle(const Volume& volume, const RegionTables& tables, double tolerance) {
  if (!tables.outside) throw std::invalid_argument("adaptive sampling needs a TF");
  return SamplingOracle(volume, *tables.outside, tables.density(), tolerance,
                        SamplingOracle::kLongestReach);
}

Image renderAdaptiveSampling(const Volume& volume, const RegionTables& tables,
                             const SamplingOracle& oracle, const RenderParams& params,
                             AdaptiveSamplingStats* stats, const std::atomic<bool>* cancel,
                             std::atomic<int>* rowsDone) {
  if (const std::string problem = adaptiveSamplingProblem(params); !problem.empty())
    throw std::invalid_argument(problem);
  if (tables.regions || !tables.outside)
    throw std::invalid_argument("adaptive sampling does not render VesselGlyph regions");
  if (tables.labels && tables.labels->ownsAny())
    throw std::invalid_argument("adaptive sampling does not render labels with their own TF");
  const ViewGeometry view = makeViewGeometry(volume, params);
  Image image = makeImage(view.width, view.height);
  const MaskedDensity read = tables.density();
  const PreintegratedTable segments(*tables.outside, params.sampling.osd);
  const Scene scene = makeScene(volume, *tables.outside, segments, oracle, read, params, view);
  const int bandRows = std::max(32, 1 << scene.levels);
  const int bands = (view.height + bandRows - 1) / bandRows;
  std::mutex mutex;
  AdaptiveSamplingStats total;
  tbb::parallel_for(tbb::blocked_range<int>(0, bands, 1), [&](const tbb::blocked_range<int>& range) {
    AdaptiveSamplingStats local;
    for (int b = range.begin(); b != range.end(); ++b) {
      const int y0 = b * bandRows, y1 = std::min(view.height, y0 + bandRows);
      Band band(scene, y0, y1);
      if (!band.render(image, local, cancel)) {
        local.cancelled = true;
        break;
      }
      if (rowsDone) rowsDone->fetch_add(y1 - y0, std::memory_order_relaxed);
    }
    const std::lock_guard<std::mutex> lock(mutex);
    total.samples += local.samples;
    total.synthesised += local.synthesised;
    total.segments += local.segments;
    total.cancelled = total.cancelled || local.cancelled;
  });
  if (stats) *stats = total;
  return image;
}

}  // namespace angio
