#include "core/adaptive_integration.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/clip_interval.h"
#include "core/view_geometry.h"
#include "core/volume_sampling.h"

namespace angio {

namespace {

struct Node {
  float extinction = 0.f;   // k = -ln(1 - a) per voxel unit
  glm::vec3 emission{0.f};  // q = rgb s k
};

struct Interval {
  double left = 0, right = 0;  // voxel units along the ray from its first sample
  Node l, m, r;
  glm::vec3 trapezoid{0.f}, simpson{0.f};  // T(I), S(I) (4.11, 4.12)
  float transparency = 1.f;                // e^{-h/6 (k_l + 4 k_m + k_r)}
  float error = 0.f;                       // e_loc (4.13) of the last pass
  float parentError = -1.f;                // e_loc of P(I); < 0 for an initial interval
};

float largestChannel(glm::vec3 v) { return std::max({std::abs(v.r), std::abs(v.g), std::abs(v.b)}); }

// Both rules on one interval, from its three nodes.
void applyRules(Interval& i) {
  const float h = float(i.right - i.left);
  const float toMiddle = std::exp(-h / 4 * (i.l.extinction + i.m.extinction));
  i.trapezoid =
      h / 4 *
      (i.l.emission + 2.f * i.m.emission * toMiddle +
       i.r.emission * std::exp(-h / 4 * (i.l.extinction + 2 * i.m.extinction + i.r.extinction)));
  i.transparency = std::exp(-h / 6 * (i.l.extinction + 4 * i.m.extinction + i.r.extinction));
  i.simpson = h / 6 * (i.l.emission + 4.f * i.m.emission * toMiddle + i.r.emission * i.transparency);
}

// One ray: its nodes as the rendering model classifies samples, and the passes of sec. 4.3.
class RayIntegrator {
 public:
  RayIntegrator(const Volume& volume, const RegionTables& tables, const MaskedDensity& read,
                const RenderParams& params, const ViewGeometry& view,
                const AdaptiveIntegration& settings)
      : volume_(volume), tables_(tables), read_(read), params_(params), settings_(settings), view_(view),
        viewDir_(view.viewDir) {}

  // RGBA of the ray from `origin`; `intervals` is scratch memory kept between rays.
  glm::vec4 integrate(const glm::dvec3& origin, std::vector<Interval>& intervals,
                      AdaptiveIntegrationStats& stats) {
    const SampleRange samples = clippedSampleRange(view_, params_.clipping, origin);
    if (samples.empty()) return glm::vec4(0.f);
    const RaySamples positions(volume_, view_, origin);
    firstQ_ = positions.at(samples.first);
    stepQ_ = positions.stepQ / params_.sampling.osd;  // per voxel unit
    length_ = double(samples.last - samples.first) * params_.sampling.osd;
    initialCount_ = std::max(1L, long(std::ceil(length_ / settings_.initialStep - 1e-9)));
    nextInitial_ = 0;
    intervals.clear();
    glm::vec3 previousSum(0.f);
    for (int pass = 0;; ++pass) {
      ++stats.passes;
      const Pass result = traverse(intervals, stats);
      // e_glob (4.9); for the first discretisation the two rules' disagreement on it.
      const float change =
          largestChannel(pass == 0 ? result.trapezoid - result.simpson : result.simpson - previousSum);
      previousSum = result.simpson;
      if (change <= float(settings_.tolerance) * largestChannel(result.simpson) ||
          !refine(intervals, result.largestExtrapolated, stats))
        return glm::vec4(result.simpson, 1.f - result.transparency);
    }
  }

 private:
  struct Pass {
    glm::vec3 trapezoid{0.f}, simpson{0.f};  // T(G), S(G), attenuated front to back
    float transparency = 1.f;
    float largestExtrapolated = 0.f;  // m_extr (4.8)
  };

  Node nodeAt(double u, AdaptiveIntegrationStats& stats) const {
    ++stats.nodes;
    const Filter filter = params_.sampling.filter;
    const glm::dvec3 q = firstQ_ + u * stepQ_;
    const TfTable* own =
        tables_.labels ? tables_.labels->ownTf(sampleLabel(volume_, q, filter)) : nullptr;
    const TfTable& tf = own ? *own : *tables_.outside;
    const glm::vec4 rgba = tf.rgba[tableIndex(sampleDensity(volume_, q, filter, read_))];
    if (rgba.a <= 0.f) return {};
    const float extinction = float(extinctionPerVoxel(rgba.a));
    const float shade =
        shadingFactor(params_.shading, sampleGradient(volume_, q, filter, read_), viewDir_);
    return {extinction, glm::vec3(rgba) * shade * extinction};
  }

  // The next interval of the initial discretisation, nodes evaluated (none left: false).
  bool appendInitial(std::vector<Interval>& intervals, AdaptiveIntegrationStats& stats) {
    if (nextInitial_ >= initialCount_) return false;
    Interval i;
    i.left = length_ * double(nextInitial_) / double(initialCount_);
    i.right = length_ * double(nextInitial_ + 1) / double(initialCount_);
    i.l = intervals.empty() ? nodeAt(i.left, stats) : intervals.back().r;
    i.m = nodeAt(0.5 * (i.left + i.right), stats);
    i.r = nodeAt(i.right, stats);
    applyRules(i);
    intervals.push_back(i);
    ++nextInitial_;
    return true;
  }

  // Front to back: the weighted local errors (4.13), the extrapolated ones (4.7), the sums.
  // Intervals behind the early-ray-termination opacity count nothing and are not refined; initial
  // ones are made only as long as the ray is not yet that opaque.
  Pass traverse(std::vector<Interval>& intervals, AdaptiveIntegrationStats& stats) {
    Pass pass;
    const float stopBelow = 1.f - float(params_.sampling.ert);
    for (std::size_t n = 0;; ++n) {
      const bool terminated = pass.transparency <= stopBelow;
      if (n == intervals.size() && (terminated || !appendInitial(intervals, stats))) break;
      Interval& i = intervals[n];
      if (terminated) {
        i.error = 0.f;
        continue;
      }
      i.error = pass.transparency * largestChannel(i.trapezoid - i.simpson);
      if (i.parentError > 0.f)
        pass.largestExtrapolated = std::max(pass.largestExtrapolated, i.error * i.error / i.parentError);
      pass.trapezoid += pass.transparency * i.trapezoid;
      pass.simpson += pass.transparency * i.simpson;
      pass.transparency *= i.transparency;
    }
    return pass;
  }

  // Bisects the intervals with e_loc >= m_extr (and some error, and room above minStep); false if
  // none was.
  bool refine(std::vector<Interval>& intervals, float largestExtrapolated,
              AdaptiveIntegrationStats& stats) {
    refined_.clear();
    bool any = false;
    for (const Interval& i : intervals) {
      const double half = 0.5 * (i.right - i.left);
      if (i.error <= 0.f || i.error < largestExtrapolated || half < settings_.minStep) {
        refined_.push_back(i);
        continue;
      }
      any = true;
      const double middle = 0.5 * (i.left + i.right);
      Interval front{i.left, middle, i.l, nodeAt(0.5 * (i.left + middle), stats), i.m};
      Interval back{middle, i.right, i.m, nodeAt(0.5 * (middle + i.right), stats), i.r};
      for (Interval* child : {&front, &back}) {
        child->parentError = i.error;
        applyRules(*child);
        refined_.push_back(*child);
      }
    }
    intervals.swap(refined_);
    return any;
  }

  const Volume& volume_;
  const RegionTables& tables_;
  const MaskedDensity& read_;
  const RenderParams& params_;
  const AdaptiveIntegration& settings_;
  const ViewGeometry& view_;
  const glm::vec3 viewDir_;  // view_.viewDir in float, as shadingFactor takes it
  glm::dvec3 firstQ_{0.0}, stepQ_{0.0};
  double length_ = 0;
  long initialCount_ = 0, nextInitial_ = 0;
  std::vector<Interval> refined_;
};

}  // namespace

std::string adaptiveIntegrationProblem(const RenderParams& params) {
  if (!params.sampling.adaptive) return "adaptive integration is not enabled";
  if (params.compositing == Compositing::mip) return "adaptive integration is for DVR, not MIP";
  return samplingProblem(params.sampling);
}

Image renderAdaptive(const Volume& volume, const RegionTables& tables, const RenderParams& params,
                     AdaptiveIntegrationStats* stats, const std::atomic<bool>* cancel,
                     std::atomic<int>* rowsDone) {
  if (const std::string problem = adaptiveIntegrationProblem(params); !problem.empty())
    throw std::invalid_argument(problem);
  if (tables.regions || !tables.outside)
    throw std::invalid_argument("adaptive integration does not render VesselGlyph regions");
  const ViewGeometry view = makeViewGeometry(volume, params);
  Image image = makeImage(view.width, view.height);
  const MaskedDensity read = tables.density();
  std::mutex mutex;
  AdaptiveIntegrationStats total;
  tbb::parallel_for(tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& rows) {
    RayIntegrator integrator(volume, tables, read, params, view, *params.sampling.adaptive);
    std::vector<Interval> intervals;
    AdaptiveIntegrationStats local;
    for (int y = rows.begin(); y != rows.end(); ++y) {
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        local.cancelled = true;
        break;
      }
      for (int x = 0; x < view.width; ++x)
        image.at(x, y) = integrator.integrate(view.rayOrigin(x, y), intervals, local);
      if (rowsDone) rowsDone->fetch_add(1, std::memory_order_relaxed);
    }
    const std::lock_guard<std::mutex> lock(mutex);
    total.nodes += local.nodes;
    total.passes += local.passes;
    total.cancelled = total.cancelled || local.cancelled;
  });
  if (stats) *stats = total;
  return image;
}

}  // namespace angio
