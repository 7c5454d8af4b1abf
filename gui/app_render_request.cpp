// The render-request path of App: what the window shows goes to the progressive renderer as a
// request (the main TF's table, VesselGlyph's regions, the DVR+CPR hybrid's finish step), and
// finished frames come back as the viewport's texture. It reads the document, never writes it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>

#include "gui/app.h"
#include "render/hybrid_cpr_step.h"

namespace angio {

namespace {

constexpr std::size_t kRememberedRequests = 256;
// Per UI frame: ~1 ms on a GPU driver, a few ms in software GL; a fast image goes in one frame.
constexpr std::size_t kUploadBytesPerFrame = 3 << 20;

using Ms = std::chrono::duration<double, std::milli>;

// What the hybrid's finish step depends on beyond the regions and the focus TF ("" = off).
std::string hybridSettingsKey(const CprState& cpr) {
  if (!cpr.hybrid) return "";
  char key[96];
  std::snprintf(key, sizeof key, "%d %d %.17g", cpr.path, int(cpr.colouring), cpr.transitionMm);
  return key;
}

}  // namespace

// Swaps in the newest finished frame: uploads it in strips (a few per UI frame for a large image)
// and shows it when complete; a frame with the pixels already shown (re-labelled) just replaces it.
void App::pollRenderer() {
  const std::shared_ptr<const ProgressiveFrame> frame = renderer_->latestFrame();
  if (frame && frame != shown_ && frame != incoming_) {
    if (shown_ && frame->serial == shown_->serial && !incoming_) {
      shown_ = frame;
      latency_.shown(*frame, Clock::now());
    } else if (incoming_ && frame->serial == incoming_->serial) {
      incoming_ = frame;
    } else {
      incoming_ = frame;
      latency_.seen(*frame, Clock::now());
      texture_.begin(frame);
    }
  }
  if (!incoming_) return;
  const auto start = Clock::now();
  const bool complete = texture_.step(kUploadBytesPerFrame);
  lastUploadMs_ = Ms(Clock::now() - start).count();
  maxUploadMs_ = std::max(maxUploadMs_, lastUploadMs_);
  if (!complete) return;
  shown_ = std::move(incoming_);
  incoming_.reset();
  latency_.shown(*shown_, Clock::now());
  // Input -> first image of the request that input made (whatever its level).
  const auto asked = std::find_if(requestTimes_.begin(), requestTimes_.end(),
                                  [&](const auto& entry) { return entry.first == shown_->request; });
  if (asked != requestTimes_.end()) {
    lastFirstImageMs_ = Ms(Clock::now() - asked->second).count();
    if (asked->first == 1) startupImageMs_ = lastFirstImageMs_;
    else firstImage_.add(lastFirstImageMs_);
    requestTimes_.erase(requestTimes_.begin(), asked + 1);
  }
}

// Asks for a render when anything that decides the image changed (or an interaction ended).
void App::requestRender(bool interactive) {
  if (!table_ || doc().tf != tableTf_) {
    table_ = std::make_shared<const TfTable>(buildTable(doc().tf));
    tableTf_ = doc().tf;
  }
  ProgressiveRequest request;
  request.params = renderParamsOf(doc());
  request.table = table_;
  request.regions = vesselRegions();
  request.interactive = interactive;
  request.levels = doc().levels;
  if (lastRequest_ && *lastRequest_ == request) return;
  lastRequestId_ = renderer_->request(request);
  latency_.requested(lastRequestId_, frameStart_);
  lastRequest_ = request;
  requestTimes_.emplace_back(lastRequestId_, Clock::now());
  if (requestTimes_.size() > kRememberedRequests) requestTimes_.pop_front();
}

// The request's regions: null for plain DVR (VesselGlyph off, nothing loaded, or a problem);
// a new source whenever the shape, a region TF or the outside TF changed, else the last one.
std::shared_ptr<const RegionSource> App::vesselRegions() {
  VesselGlyphPanel& vg = vessel_;
  const VesselGlyphState& set = doc().vesselGlyph;
  vg.problem.clear();
  if (!set.enabled || !vg.physical) return vg.source = nullptr;
  bool changed = !vg.source;
  try {
    const Centerlines* centerlines = framedCenterlines();
    if (!vg.builder || vg.builder->builder.settings() != set.settings) {
      vg.builder = std::make_shared<GuardedRegionBuilder>(*centerlines, set.settings);
      changed = true;
    }
  } catch (const std::exception& error) {
    vg.problem = error.what();
    return vg.source = nullptr;
  }
  const auto refresh = [&](std::shared_ptr<const TfTable>& table, TransferFunction& builtFrom,
                           const TransferFunction& tf) {
    if (table && builtFrom == tf) return;
    table = std::make_shared<const TfTable>(buildTable(tf));
    builtFrom = tf;
    changed = true;
  };
  refresh(vg.focusTable, vg.focusTableTf, set.focusTf);
  refresh(vg.contextTable, vg.contextTableTf, set.contextTf);
  const std::shared_ptr<const TfTable> outside = set.outsideRendered ? table_ : nullptr;
  if (outside != vg.outsideTable) vg.outsideTable = outside, changed = true;
  const std::string hybrid = hybridSettingsKey(doc().cpr);
  if (hybrid != vg.hybridFor) vg.hybridFor = hybrid, changed = true;
  if (!changed) return vg.source;

  auto source = std::make_shared<RegionSource>();
  source->build = [builder = vg.builder](const ViewGeometry& view, RayRegions& out) {
    std::lock_guard lock(builder->mutex);
    builder->builder.build(view, out);
  };
  source->focus = vg.focusTable;
  source->context = vg.contextTable;
  source->outside = vg.outsideTable;
  source->finish = hybridFinishStep();  // the DVR+CPR hybrid, if on (below)
  return vg.source = std::move(source);
}

// Null when the hybrid is off or cannot be made (the problem is shown in the CPR section).
std::function<void(const ViewGeometry&, const RayRegions&, Image&)> App::hybridFinishStep() {
  vessel_.hybridProblem.clear();
  const std::optional<HybridCprRecipe> hybrid = hybridRecipe();
  const std::optional<VesselGlyphRecipe> vesselGlyph = vesselGlyphRecipe();
  if (!hybrid || !vesselGlyph) return {};
  try {
    auto step = std::make_shared<HybridCprStep>(data_.volume, *framedCenterlines(), *vesselGlyph, *hybrid);
    return [step](const ViewGeometry& view, const RayRegions& regions, Image& image) {
      step->composite(view, regions, image);
    };
  } catch (const std::exception& error) {
    vessel_.hybridProblem = error.what();
    return {};
  }
}

}  // namespace angio
