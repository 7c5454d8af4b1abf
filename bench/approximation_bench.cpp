#include "bench/approximation_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include "bench/frame_bench.h"
#include "bench/timing.h"
#include "core/image.h"
#include "render/frame_renderer.h"
#include "render/prepared_scene.h"
#include "render/render_recipe.h"

namespace angio {

namespace {

// Off the axes: in an axis-aligned view the voxel filters meet every voxel once per osd and agree
// with the converged image far better than in any other view (measured: 58 against 37 dB).
constexpr double kAngleOffsetDeg = 15;

// The images of one level and sampling at every bench angle, each frame timed.
struct Frames {
  std::vector<Image> images;
  std::vector<double> ms, samples;
};

Frames renderFrames(FrameRenderer& frames, const std::shared_ptr<const PreparedScene>& scene,
                    RenderParams p, int angles) {
  Frames out;
  for (int n = 0; n < angles; ++n) {
    p.angleDeg = benchAngle(n, angles) + kAngleOffsetDeg;
    FastRenderStats stats;
    const auto start = BenchClock::now();
    out.images.push_back(frames.render(scene, p, {}, &stats));
    out.ms.push_back(msSince(start));
    out.samples.push_back(double(stats.samples));
  }
  return out;
}

std::vector<double> psnrs(const Frames& frames, const Frames& exact) {
  std::vector<double> values;
  for (std::size_t n = 0; n < frames.images.size(); ++n)
    values.push_back(psnrDb(frames.images[n], exact.images[n]));
  return values;
}

std::string techniqueName(const Sampling& s) {
  if (s.adaptiveSampling) {
    char text[64];
    std::snprintf(text, sizeof text, "3-D adaptive L%d/%d, tol %g", s.adaptiveSampling->levels,
                  s.adaptiveSampling->rayLevels, s.adaptiveSampling->tolerance);
    return text;
  }
  if (s.adaptive) {
    char text[64];
    std::snprintf(text, sizeof text, "adaptive %g, h0 %g", s.adaptive->tolerance,
                  s.adaptive->initialStep);
    return text;
  }
  return s.preintegrated ? "pre-integrated" : "post";
}

ApproximationRow row(const std::string& level, const RenderParams& p, const Frames& frames,
                     const Frames& exact, const Frames& converged) {
  const std::vector<double> againstLevel = psnrs(frames, exact);
  return {level,
          p.sampling.osd,
          techniqueName(p.sampling),
          median(frames.ms),
          *std::min_element(frames.ms.begin(), frames.ms.end()),
          *std::max_element(frames.ms.begin(), frames.ms.end()),
          median(frames.samples),
          median(againstLevel),
          *std::min_element(againstLevel.begin(), againstLevel.end()),
          median(psnrs(frames, converged)),
          int(frames.images.size())};
}

std::string decibels(double db) {
  if (std::isinf(db)) return "exact";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", db);
  return text;
}

void report(const ApproximationRow& row) {
  std::fprintf(stderr, "bench: %s osd %.3g %s %.1f ms", row.level.c_str(), row.osd,
               row.technique.c_str(), row.medianMs);
  if (row.setupMs > 0) std::fprintf(stderr, " (first frame with the oracle %.1f ms)", row.setupMs);
  std::fprintf(stderr, "\n");
}

}  // namespace

std::vector<ApproximationRow> runApproximationBench(const Volume& volume, const TransferFunction& tf,
                                                    const ApproximationSettings& settings) {
  std::optional<tbb::global_control> limit;
  if (settings.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, settings.threads);
  RenderRecipe recipe;
  recipe.tf = tf;
  recipe.params.axis = settings.axis;
  const auto scene = PreparedScene::prepare(volume, {}, recipe);
  FrameRenderer frames(volume);
  frames.prepare(scene, settings.axis);
  std::vector<ApproximationRow> rows;
  for (const BenchLevel& level : benchLevels(settings.levels)) {
    const RenderParams p = level.params(settings.axis);
    renderFrames(frames, scene, p, 1);  // warm-up: first-touch of the frame memory
    const Frames exact = renderFrames(frames, scene, p, settings.angles);
    RenderParams fine = p;
    fine.sampling.osd /= 4;
    const Frames converged = renderFrames(frames, scene, fine, settings.angles);
    for (const double scale : settings.osdScales)
      for (const bool preintegrated : {false, true}) {
        RenderParams q = p;
        q.sampling.osd *= scale;
        q.sampling.preintegrated = preintegrated;
        const Frames approximate =
            scale == 1 && !preintegrated ? exact : renderFrames(frames, scene, q, settings.angles);
        rows.push_back(row(level.name, q, approximate, exact, converged));
        report(rows.back());
      }
    for (const ImageRefinement& refinement : settings.refinement) {
      frames.refinement = refinement;
      rows.push_back(
          row(level.name, p, renderFrames(frames, scene, p, settings.angles), exact, converged));
      frames.refinement.reset();
      char name[64];
      std::snprintf(name, sizeof name, "refined L%d, tol %g", refinement.levels, refinement.tolerance);
      rows.back().technique = name;
      report(rows.back());
    }
    for (const AdaptiveSampling& adaptive : settings.adaptiveSampling) {
      RenderParams q = p;
      q.sampling.adaptiveSampling = adaptive;
      const auto start = BenchClock::now();
      renderFrames(frames, scene, q, 1);  // makes the oracle, first-touches the bands' memory
      const double setupMs = msSince(start);
      rows.push_back(
          row(level.name, q, renderFrames(frames, scene, q, settings.angles), exact, converged));
      rows.back().setupMs = setupMs;
      report(rows.back());
    }
    for (const AdaptiveIntegration& adaptive : settings.adaptive) {
      RenderParams q = p;
      q.sampling.adaptive = adaptive;
      rows.push_back(
          row(level.name, q, renderFrames(frames, scene, q, settings.angles), exact, converged));
      report(rows.back());
    }
  }
  return rows;
}

std::string formatApproximationBench(const std::vector<ApproximationRow>& rows) {
  std::string out =
      "level             osd    technique                            median ms (min-max)       "
      "samples/frame   "
      "PSNR vs level dB (worst)   PSNR vs converged dB\n";
  for (const ApproximationRow& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-17s %-6.3g %-26s %8.1f (%.1f-%.1f)%*s %12.0f   %8s (%s)%*s %8s\n", r.level.c_str(),
                  r.osd, r.technique.c_str(), r.medianMs, r.minMs, r.maxMs, 4, "", r.medianSamples,
                  decibels(r.psnrLevelDb).c_str(), decibels(r.minPsnrLevelDb).c_str(), 10, "",
                  decibels(r.psnrConvergedDb).c_str());
    out += line;
  }
  return out;
}

}  // namespace angio
