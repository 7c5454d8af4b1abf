#include "bench/frame_bench.h"
#include "bench/timing.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include "core/blocked_volume.h"
#include "core/fast_raycaster.h"
#include "render/frame_renderer.h"
#include "render/prepared_scene.h"
#include "render/render_recipe.h"

namespace angio {

namespace {

using Clock = BenchClock;

// What the "clipped" rows render (core/clip_interval.h): the middle 80 % of the volume along
// every axis, the half behind a plane facing the viewer through the centre.
ViewClipping benchClipping(const Volume& volume) {
  const glm::dvec3 extent = domainExtent(volume);
  ViewClipping clipping;
  clipping.crop = CropBox{0.1 * extent, 0.9 * extent};
  clipping.plane = facingPlane(0);
  return clipping;
}

// One frame: returns samples evaluated.
using FrameFunction = std::function<double(const RenderParams&)>;

FrameTimingRow timeFrames(const std::string& level, const std::string& variant, int angles,
                          const RenderParams& base, const FrameFunction& frame) {
  std::vector<double> ms, cpuMs, samples;
  for (int n = 0; n < angles; ++n) {
    RenderParams p = base;
    p.angleDeg = benchAngle(n, angles);
    const auto start = Clock::now();
    const double cpuStart = processCpuMs();
    samples.push_back(frame(p));
    ms.push_back(msSince(start));
    cpuMs.push_back(processCpuMs() - cpuStart);
  }
  return {level,
          variant,
          median(ms),
          *std::min_element(ms.begin(), ms.end()),
          *std::max_element(ms.begin(), ms.end()),
          median(cpuMs),
          median(samples),
          angles};
}

// The techniques the bench switches off one at a time (contribution) or on alone (potential).
struct Switches {
  FastRenderOptions options;
  bool ert = true;
  bool threads = true;
};

struct Technique {
  std::string name;
  void (*set)(Switches&, bool on);
};

std::vector<Technique> techniques() {
  return {
      {"tile groups", [](Switches& s, bool on) { s.options.skipGroups = on; }},
      {"tiles", [](Switches& s, bool on) { s.options.skipTiles = on; }},
      {"cell skipping", [](Switches& s, bool on) { s.options.skipCells = on; }},
      {"row bundles", [](Switches& s, bool on) { s.options.shareRows = on; }},
      {"sample batches", [](Switches& s, bool on) { s.options.batchSamples = on; }},
      {"ERT", [](Switches& s, bool on) { s.ert = on; }},
      {"threads", [](Switches& s, bool on) { s.threads = on; }},
  };
}

Switches allBut(const Technique& technique) {
  Switches s;
  technique.set(s, false);
  return s;
}

// Every technique off but `technique` (none: all off).
Switches onlyWith(const Technique* technique) {
  Switches s;
  for (const Technique& t : techniques()) t.set(s, false);
  if (technique) technique->set(s, true);
  return s;
}

// The "vessel glyph" rows: the phantom's tree with the default shapes, the focus through the
// bench's TF, the context through a translucent copy of it, the outside clipped; "hybrid cpr" adds
// the projected CPR of every path through the focus TF with a hard edge (thesis fig. 5.4), as
// `angioray render --hybrid-cpr` does.
RenderRecipe vesselGlyphRecipe(const TransferFunction& tf, bool hybrid) {
  RenderRecipe recipe;
  recipe.tf = tf;
  VesselGlyphRecipe& vg = recipe.vesselGlyph.emplace();
  vg.focusTf = vg.contextTf = tf;
  vg.contextTf.modulators.opacityScale *= 0.3;
  if (hybrid) recipe.hybrid = HybridCprRecipe{};
  return recipe;
}

// Every listed label with the main TF as its own: the image without labels, through the per-label
// path.
RenderRecipe ownTfRecipe(const RenderRecipe& recipe) {
  RenderRecipe own = recipe;
  for (LabelStyle& style : own.tf.labels) {
    style.mode = LabelMode::tf;
    style.points = recipe.tf.points;
  }
  return own;
}

// Re-classification after a label change: scenes alternating between the styles and the styles
// with the first label shown, each prepared anew; median ms over `count` changes.
double labelClassifyMs(FrameRenderer& frames, const Volume& volume, const RenderRecipe& recipe,
                       Axis axis, int count) {
  RenderRecipe shown = recipe;
  shown.tf.labels.front().mode = LabelMode::main;
  std::vector<double> times;
  for (int n = 0; n < count; ++n) {
    const auto scene = PreparedScene::prepare(volume, {}, n % 2 ? shown : recipe);
    const auto start = Clock::now();
    frames.prepare(scene, axis);
    times.push_back(msSince(start));
  }
  return median(times);
}

// One frame of `scene` (recycling the previous frame's memory, as the progressive renderer
// does); returns the samples evaluated.
FrameFunction sceneFrames(FrameRenderer& frames, std::shared_ptr<const PreparedScene> scene,
                          Image& previous) {
  return [&frames, scene = std::move(scene), &previous](const RenderParams& p) {
    FastRenderStats stats;
    previous = frames.render(scene, p, {.recycle = &previous}, &stats);
    return double(stats.samples);
  };
}

// Where the samples of a level's frames go: the "all" row's angles rendered again, untimed, with
// the profile counted; the row's CPU time over their evaluated samples is the cost per sample.
LevelProfile profileLevel(FrameRenderer& frames, const std::shared_ptr<const PreparedScene>& scene,
                          const RenderParams& base, const FrameTimingRow& timed) {
  LevelProfile profile{timed.level, {}, timed.frames, 0};
  frames.techniques.profile = true;
  std::vector<double> templateMs;
  for (int n = 0; n < timed.frames; ++n) {
    RenderParams p = base;
    p.angleDeg = benchAngle(n, timed.frames);
    FastRenderStats stats;
    frames.render(scene, p, {}, &stats);
    profile.total += stats.profile;
    templateMs.push_back(stats.templateMs);
  }
  frames.techniques.profile = false;
  if (!templateMs.empty()) profile.templateMs = median(templateMs);
  const double evaluatedPerFrame = double(profile.total.evaluated) / std::max(timed.frames, 1);
  if (evaluatedPerFrame > 0) profile.nsPerEvaluatedSample = timed.medianCpuMs * 1e6 / evaluatedPerFrame;
  return profile;
}

// Interruption latency (the progressive GUI restarts at fast on every change): high-quality frames
// at `count` angles, each cancelled 10-90 % into the time an uncancelled one takes; cancel flag
// set -> the render returned. A frame that finished before its cancel was not interrupted and is
// left out. `recycle`: each frame renders into the memory of the one before, as the GUI does once
// it has shown a high frame; otherwise into fresh memory, as the first high frame after a load.
InterruptLatency interruptLatency(FrameRenderer& frames,
                                  const std::shared_ptr<const PreparedScene>& scene, Axis axis,
                                  int count, bool recycle) {
  RenderParams warmUp;
  warmUp.axis = axis;
  warmUp.sampling = qualitySampling(Quality::high);
  Image previous = frames.render(scene, warmUp);
  const Clock::time_point start = Clock::now();
  previous = frames.render(scene, warmUp, {.recycle = recycle ? &previous : nullptr});
  const double frameMs = msSince(start);
  std::vector<double> latencies;
  for (int n = 0; n < count; ++n) {
    RenderParams p = warmUp;
    p.angleDeg = benchAngle(n, count) + 7.0;  // not the warm-up's angle
    std::atomic<bool> cancel{false};
    Clock::time_point returnedAt;
    if (!recycle) previous = Image{};  // the memory goes back before the next frame asks for its own
    std::thread worker([&] {
      previous = frames.render(scene, p, {.cancel = &cancel, .recycle = recycle ? &previous : nullptr});
      returnedAt = Clock::now();
    });
    const double fraction = 0.1 + 0.8 * ((n * 37) % 100) / 100.0;
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(frameMs * fraction));
    const Clock::time_point cancelledAt = Clock::now();
    cancel = true;
    worker.join();
    if (returnedAt > cancelledAt)
      latencies.push_back(std::chrono::duration<double, std::milli>(returnedAt - cancelledAt).count());
  }
  InterruptLatency latency;
  latency.frames = int(latencies.size());
  if (!latencies.empty()) {
    latency.medianMs = median(latencies);
    latency.maxMs = *std::max_element(latencies.begin(), latencies.end());
  }
  return latency;
}

}  // namespace

RenderParams BenchLevel::params(Axis axis) const {
  RenderParams p;
  p.axis = axis;
  p.sampling = sampling;
  return p;
}

std::vector<BenchLevel> benchLevels(const std::vector<std::string>& wanted) {
  Sampling trilinearMedium = qualitySampling(Quality::medium);
  trilinearMedium.filter = Filter::trilinear;
  std::vector<BenchLevel> levels = {{"fast", qualitySampling(Quality::fast)},
                                    {"medium", qualitySampling(Quality::medium)},
                                    {"medium-trilinear", trilinearMedium},
                                    {"high", qualitySampling(Quality::high)}};
  if (wanted.empty()) return levels;
  std::erase_if(levels, [&](const BenchLevel& level) {
    return std::find(wanted.begin(), wanted.end(), level.name) == wanted.end();
  });
  return levels;
}

double benchAngle(int n, int count) { return 360.0 * n / count; }

// The frame at angle 30 from the blocked volume against the flat volume's, pixel for pixel.
bool sameImageFromBlocks(FrameRenderer& frames, const std::shared_ptr<const PreparedScene>& scene,
                         RenderParams p, const BlockedVolume& blocked) {
  p.angleDeg = 30;
  const Image flat = frames.render(scene, p);
  frames.techniques.blocks = &blocked;
  const Image fromBlocks = frames.render(scene, p);
  frames.techniques = {};
  return fromBlocks.pixels == flat.pixels;
}

BenchReport runFrameBench(const Volume& volume, const TransferFunction& tf,
                          const BenchSettings& settings) {
  std::optional<tbb::global_control> limit;
  if (settings.threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, settings.threads);
  BenchReport report;
  report.transferFunction = tf.name;
  report.dims = volume.dims;
  report.volumeMiB = volume.voxelCount() * sizeof(Voxel) / 1048576.0;
  report.threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();

  RenderRecipe recipe;
  recipe.tf = tf;
  recipe.params.axis = settings.axis;
  const std::shared_ptr<const PreparedScene> scene = PreparedScene::prepare(volume, {}, recipe);
  FrameRenderer frames(volume);
  auto start = Clock::now();
  frames.prepare(scene, settings.axis);  // slice tiles and their classification
  report.preprocessMs = msSince(start);
  // A TF change: the same TF in a new scene is classified again, the tiles are kept.
  const std::shared_ptr<const PreparedScene> edited = PreparedScene::prepare(volume, {}, recipe);
  start = Clock::now();
  frames.prepare(edited, settings.axis);
  report.classifyMs = msSince(start);
  report.preprocessMs -= report.classifyMs;
  const int interrupts = std::max(settings.angles, 12);
  report.recycledInterrupt = interruptLatency(frames, scene, settings.axis, interrupts, true);
  report.freshInterrupt = interruptLatency(frames, scene, settings.axis, interrupts, false);
  report.accelerationMiB = frames.structureMiB();
  RenderRecipe labelled = recipe;
  labelled.tf.labels = settings.labels;
  if (!settings.labels.empty())
    report.labelClassifyMs = labelClassifyMs(frames, volume, labelled, settings.axis, 9);
  const auto labelScene = PreparedScene::prepare(volume, {}, labelled);
  const auto ownTfScene = PreparedScene::prepare(volume, {}, ownTfRecipe(labelled));
  report.blocking = blockingReport(volume, buildTable(tf));
  const BlockedVolume blocked = buildBlockedVolume(volume);

  Image previous;
  auto timeVariant = [&](const std::string& level, const std::string& variant, int angles,
                         RenderParams p, const Switches& switches) {
    if (!switches.ert) p.sampling.ert = 1.0;
    std::optional<tbb::global_control> oneThread;
    if (!switches.threads) oneThread.emplace(tbb::global_control::max_allowed_parallelism, 1);
    frames.techniques = switches.options;
    FrameTimingRow times = timeFrames(level, variant, angles, p, sceneFrames(frames, scene, previous));
    frames.techniques = {};
    return times;
  };
  for (const BenchLevel& level : benchLevels(settings.levels)) {
    const RenderParams p = level.params(settings.axis);
    report.rows.push_back(
        timeFrames(level.name, "all", settings.angles, p, sceneFrames(frames, scene, previous)));
    std::fprintf(stderr, "bench: %s %.1f ms\n", level.name.c_str(), report.rows.back().medianMs);
    if (settings.profile) report.profiles.push_back(profileLevel(frames, scene, p, report.rows.back()));
    RenderParams clipped = p;
    clipped.clipping = benchClipping(volume);
    report.rows.push_back(timeFrames(level.name, "clipped", settings.angles, clipped,
                                     sceneFrames(frames, scene, previous)));
    RenderParams mip = p;
    mip.compositing = Compositing::mip;
    report.rows.push_back(
        timeFrames(level.name, "mip", settings.angles, mip, sceneFrames(frames, scene, previous)));
    std::fprintf(stderr, "bench: %s mip %.1f ms\n", level.name.c_str(), report.rows.back().medianMs);
    if (blocksServe(blocked, scene->tables(nullptr), p)) {
      Switches fromBlocks;
      fromBlocks.options.blocks = &blocked;
      report.rows.push_back(timeVariant(level.name, "blocked volume", settings.angles, p, fromBlocks));
      std::fprintf(stderr, "bench: %s blocked volume %.1f ms\n", level.name.c_str(),
                   report.rows.back().medianMs);
      if (!sameImageFromBlocks(frames, scene, p, blocked))
        report.blockedImagesDiffering.push_back(level.name);
      ++report.blockedImagesCompared;
    }
    if (settings.withContributions) {
      // Thesis fig. 4.9 ff.: "contribution" = everything but one technique, at every level;
      // "potential" = one technique alone, at the fast level only (without any, a medium frame
      // takes seconds).
      const int few = std::min(std::max(settings.angles / 6, 6), settings.angles);
      // The reference for these rows: everything on, over the same (fewer) angles.
      report.rows.push_back(
          timeVariant(level.name, "all, " + std::to_string(few) + " angles", few, p, {}));
      for (const Technique& t : techniques())
        report.rows.push_back(timeVariant(level.name, "no " + t.name, few, p, allBut(t)));
      if (level.name == "fast") {
        report.rows.push_back(timeVariant(level.name, "none", few, p, onlyWith(nullptr)));
        for (const Technique& t : techniques())
          report.rows.push_back(timeVariant(level.name, "only " + t.name, few, p, onlyWith(&t)));
      }
    }
    if (!settings.labels.empty()) {
      for (const auto& [variant, labelledScene] :
           {std::pair{"labels", labelScene}, {"labels, own TF", ownTfScene}}) {
        report.rows.push_back(timeFrames(level.name, variant, settings.angles, p,
                                         sceneFrames(frames, labelledScene, previous)));
        std::fprintf(stderr, "bench: %s %s %.1f ms\n", level.name.c_str(), variant,
                     report.rows.back().medianMs);
      }
    }
    if (settings.vesselTree) {
      for (const bool hybrid : {false, true}) {
        const auto glyph =
            PreparedScene::prepare(volume, *settings.vesselTree, vesselGlyphRecipe(tf, hybrid));
        const char* variant = hybrid ? "hybrid cpr" : "vessel glyph";
        report.rows.push_back(
            timeFrames(level.name, variant, settings.angles, p, sceneFrames(frames, glyph, previous)));
        std::fprintf(stderr, "bench: %s %s %.1f ms\n", level.name.c_str(), variant,
                     report.rows.back().medianMs);
      }
    }
    if (settings.withReference) {
      RenderRecipe reference = recipe;
      reference.raycaster = Raycaster::reference;
      const auto referenceScene = PreparedScene::prepare(volume, {}, reference);
      report.rows.push_back(
          timeFrames(level.name, "reference", settings.angles, p, [&](const RenderParams& rp) {
            frames.render(referenceScene, rp);
            return 0.0;
          }));
    }
  }
  return report;
}

std::string formatTable(const BenchReport& r) {
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "volume %dx%dx%d (%.0f MiB), TF \"%s\", %d threads\n", r.dims.x,
                r.dims.y, r.dims.z, r.volumeMiB, r.transferFunction.c_str(), r.threads);
  out << line;
  std::snprintf(line, sizeof line,
                "preprocessing (slice tiles) %.0f ms, TF classification %.1f ms, label change "
                "re-classification %.1f ms, structures %.1f MiB\n",
                r.preprocessMs, r.classifyMs, r.labelClassifyMs, r.accelerationMiB);
  out << line;
  const BlockingReport& b = r.blocking;
  std::snprintf(
      line, sizeof line,
      "blocked volume (32^3 + overlap): %.0f ms, %.1f MiB = %.2fx raw, %d of %d blocks share the "
      "dummy, %d visible, block classification %.3f ms\n",
      b.buildMs, b.memoryMiB, b.memoryRatio, b.backgroundBlocks, b.blocks, b.visibleBlocks,
      b.classifyMs);
  out << line;
  if (r.blockedImagesCompared > 0) {
    out << "frames from the blocked volume equal to the flat volume's (angle 30): "
        << r.blockedImagesCompared - int(r.blockedImagesDiffering.size()) << " of "
        << r.blockedImagesCompared << " levels";
    for (const std::string& level : r.blockedImagesDiffering)
      out << (level == r.blockedImagesDiffering.front() ? "; differ: " : ", ") << level;
    out << "\n";
  }
  for (const auto& [latency, memory] : {std::pair{r.recycledInterrupt, "recycled"},
                                        std::pair{r.freshInterrupt, "fresh (first after a load)"}}) {
    std::snprintf(line, sizeof line,
                  "interrupting a high-quality frame in %s memory: median %.2f ms, max %.2f ms (%d "
                  "frames)\n",
                  memory, latency.medianMs, latency.maxMs, latency.frames);
    out << line;
  }
  std::snprintf(line, sizeof line, "%-17s %-24s %10s %10s %10s %10s %14s %7s\n", "level", "variant",
                "median ms", "min ms", "max ms", "cpu ms", "samples/frame", "frames");
  out << line;
  for (const FrameTimingRow& t : r.rows) {
    std::snprintf(line, sizeof line, "%-17s %-24s %10.1f %10.1f %10.1f %10.1f %14.3g %7d\n",
                  t.level.c_str(), t.variant.c_str(), t.medianMs, t.minMs, t.maxMs, t.medianCpuMs,
                  t.medianSamples, t.frames);
    out << line;
  }
  if (!r.profiles.empty()) out << formatProfiles(r.profiles);
  return out.str();
}

namespace {

nlohmann::json toJson(const InterruptLatency& latency) {
  return {{"median_ms", latency.medianMs}, {"max_ms", latency.maxMs}, {"frames", latency.frames}};
}

}  // namespace

std::string toJson(const BenchReport& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (const FrameTimingRow& t : r.rows)
    rows.push_back({{"level", t.level},
                    {"variant", t.variant},
                    {"median_ms", t.medianMs},
                    {"min_ms", t.minMs},
                    {"max_ms", t.maxMs},
                    {"median_cpu_ms", t.medianCpuMs},
                    {"median_samples", t.medianSamples},
                    {"frames", t.frames}});
  nlohmann::json j{{"dataset", r.dataset},
                   {"transfer_function", r.transferFunction},
                   {"dims", {r.dims.x, r.dims.y, r.dims.z}},
                   {"volume_mib", r.volumeMiB},
                   {"acceleration_mib", r.accelerationMiB},
                   {"preprocess_ms", r.preprocessMs},
                   {"classify_ms", r.classifyMs},
                   {"label_classify_ms", r.labelClassifyMs},
                   {"blocked_volume",
                    {{"build_ms", r.blocking.buildMs},
                     {"mib", r.blocking.memoryMiB},
                     {"ratio_to_raw", r.blocking.memoryRatio},
                     {"blocks", r.blocking.blocks},
                     {"dummy_blocks", r.blocking.backgroundBlocks},
                     {"visible_blocks", r.blocking.visibleBlocks},
                     {"classify_ms", r.blocking.classifyMs},
                     {"images_compared", r.blockedImagesCompared},
                     {"images_differing", r.blockedImagesDiffering}}},
                   {"interrupt_recycled", toJson(r.recycledInterrupt)},
                   {"interrupt_fresh", toJson(r.freshInterrupt)},
                   {"threads", r.threads},
                   {"frames", rows}};
  for (const LevelProfile& l : r.profiles) {
    const RayProfile& p = l.total;
    j["profiles"].push_back({{"level", l.level},
                             {"frames", l.frames},
                             {"domain_samples", p.domainSamples},
                             {"skipped_by_groups", p.skippedByGroups},
                             {"skipped_by_tiles", p.skippedByTiles},
                             {"skipped_by_cells", p.skippedByCells},
                             {"evaluated", p.evaluated},
                             {"saved_by_termination", p.savedByTermination()},
                             {"visible", p.visible},
                             {"faint", p.faint},
                             {"rays", p.rays},
                             {"terminated_rays", p.terminatedRays},
                             {"terminated_depth", p.terminatedDepth},
                             {"ns_per_evaluated_sample", l.nsPerEvaluatedSample},
                             {"template_ms", l.templateMs}});
  }
  return j.dump(2);
}

}  // namespace angio
