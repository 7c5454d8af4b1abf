#include "gui/workstation.h"

#include <utility>

namespace angio {

namespace {

TransferFunction& tfIn(Document& document, TfTarget target) {
  if (target == TfTarget::focus) return document.vesselGlyph.focusTf;
  if (target == TfTarget::context) return document.vesselGlyph.contextTf;
  return document.tf;
}
std::string& presetIn(Document& document, TfTarget target) {
  if (target == TfTarget::focus) return document.vesselGlyph.focusPreset;
  if (target == TfTarget::context) return document.vesselGlyph.contextPreset;
  return document.tfPreset;
}
bool& followsMainIn(VesselGlyphState& vesselGlyph, TfTarget region) {
  return region == TfTarget::focus ? vesselGlyph.focusFollowsMain : vesselGlyph.contextFollowsMain;
}

// The paths' revision goes up when they change, and only then.
void setPaths(VesselsState& vessels, const std::vector<VesselPath>& paths) {
  if (vessels.paths == paths) return;
  vessels.paths = paths;
  ++vessels.revision;
}

void change(Document& d, const ViewEdit& edit) { d.view = edit.view; }
void change(Document& d, const RotateEdit& edit) { d.view.angleDeg += edit.degrees; }
void change(Document& d, const TfChange& edit) {
  if (edit.target != TfTarget::main) {
    followsMainIn(d.vesselGlyph, edit.target) = edit.followMain;
    if (edit.followMain) return;
  }
  TransferFunction& tf = tfIn(d, edit.target);
  std::vector<LabelStyle> labels = std::move(tf.labels);
  tf = edit.tf;
  if (edit.target == TfTarget::main && tf.labels.empty()) tf.labels = std::move(labels);
  presetIn(d, edit.target) = edit.preset;
}
void change(Document& d, const RenderingEdit& edit) {
  d.mode = edit.mode;
  d.shading = edit.shading;
  d.tf.mipWindow = edit.mipWindow;
  d.tf.mipLevel = edit.mipLevel;
  for (Sampling& level : d.levels) {
    level.preintegrated = edit.preintegrated;
    level.adaptive = edit.adaptive;
    level.adaptiveSampling = edit.adaptiveSampling;
  }
}
void change(Document& d, const VesselGlyphEdit& edit) { d.vesselGlyph = edit.vesselGlyph; }
// The CPR pane shows the fitted image again for another image: another path, mode or width.
void change(Document& d, const CprEdit& edit) {
  const CprState before = d.cpr;
  d.cpr = edit.cpr;
  if (before.path != d.cpr.path || before.mode != d.cpr.mode || before.widthMm != d.cpr.widthMm)
    fitCprPane(d.cpr);
}
void change(Document& d, const CenterlineFileEdit& edit) {
  d.vesselGlyph.centerlines = edit.given;
  d.vesselGlyph.centerlinesAbsolute = edit.absolute;
  fitCprPane(d.cpr);
}
// A session's labels and paths come back from App once its dataset is there.
void change(Document& d, const DatasetOpened& edit) {
  d.dataset = edit.dataset;
  d.labels.file.clear();    // the labels of the old dataset do not fit the new one
  setPaths(d.vessels, {});  // nor do its vessel paths
  d.vessels.file.clear();
  d.vessels.unsaved = false;
  d.view.zoom = 1;
  d.view.panPx = glm::dvec2(0.0);
  fitCprPane(d.cpr);
  addRecentFile(d.recentFiles, edit.dataset);
  if (edit.ofSession) return;
  d.vesselGlyph.centerlines.clear();
  d.vesselGlyph.centerlinesAbsolute.clear();
  d.vesselGlyph.enabled = false;  // nothing to show it on until paths are traced or loaded
  d.cpr.shown = false;
  d.cpr.hybrid = false;
  d.clip = {};                // the crop box was in the old dataset's millimetres
  d.slices.cursorMm.reset();  // so was the slice cursor
  d.slices.panes = {};        // and the slices' zoom and pan fitted its images
  d.cpr.cursor.reset();       // and the CPR's was on its paths
}
void change(Document& d, const RecentFilesEdit& edit) { d.recentFiles = edit.recentFiles; }
void change(Document& d, const LabelStylesEdit& edit) {
  d.tf.labels = edit.styles;
  d.labels.showRemoved = edit.showRemoved;
}
void change(Document& d, const LabelFileEdit& edit) { d.labels.file = edit.file; }
void change(Document& d, const VesselPathsEdit& edit) {
  if (d.vessels.paths == edit.paths) return;
  setPaths(d.vessels, edit.paths);
  d.vessels.unsaved = true;
}
void change(Document& d, const VesselFileEdit& edit) {
  setPaths(d.vessels, edit.paths);
  d.vessels.file = edit.file;
  d.vessels.unsaved = false;
}
void change(Document& d, const ClipEdit& edit) { d.clip = edit.clip; }
void change(Document& d, const SliceViewEdit& edit) { d.slices = edit.slices; }
void change(Document& d, const PanelOpenEdit& edit) { d.panelsOpen[edit.title] = edit.open; }
void change(Document& d, const SessionEdit& edit) {
  std::string dataset = std::move(d.dataset);
  std::vector<std::string> recent = std::move(d.recentFiles);
  VesselsState vessels = std::move(d.vessels);
  d = edit.session;
  setPaths(vessels, d.vessels.paths);
  vessels.file = d.vessels.file;
  vessels.unsaved = d.vessels.unsaved;
  d.vessels = std::move(vessels);
  d.dataset = std::move(dataset);
  d.recentFiles = std::move(recent);
}

// `brought`: the edit set the hybrid from elsewhere (a session) rather than toggling it.
void normalise(Document& next, const Document& before, bool brought) {
  next.view.angleDeg = wrapDegrees(next.view.angleDeg);
  if (next.cpr.hybrid && (brought || !before.cpr.hybrid)) next.vesselGlyph.enabled = true;
}

}  // namespace

void fitCprPane(CprState& cpr) {
  cpr.zoom = 1;
  cpr.panPx = glm::dvec2(0.0);
}

std::vector<std::string> droppedByNewDataset(const Document& before) {
  std::vector<std::string> dropped;
  if (const std::size_t paths = before.vessels.paths.size(); paths > 0)
    dropped.push_back(std::to_string(paths) + (paths == 1 ? " vessel path" : " vessel paths"));
  const VesselGlyphState& vg = before.vesselGlyph;
  if (!vg.centerlines.empty() || !vg.centerlinesAbsolute.empty())
    dropped.push_back("the centerline file");
  if (vg.enabled) dropped.push_back("VesselGlyph");
  if (before.cpr.shown || before.cpr.hybrid) dropped.push_back("the CPR view");
  if (!before.labels.file.empty()) dropped.push_back("the labels");
  const ClipState& clip = before.clip;
  if (clip.cropOn || clip.planeOn || clip.slabOn) dropped.push_back("the crop & clip");
  return dropped;
}

Workstation::Workstation(Document initial) : document_(std::move(initial)) {
  normalise(document_, document_, true);
}

void Workstation::apply(const Edit& edit) {
  Document next = document_;
  std::visit([&next](const auto& e) { change(next, e); }, edit);
  normalise(next, document_, std::holds_alternative<SessionEdit>(edit));
  if (next == document_) return;
  document_ = std::move(next);
  ++version_;
}

bool levelsPreintegrated(const Document& document) {
  for (const Sampling& level : document.levels)
    if (!level.preintegrated) return false;
  return true;
}

}  // namespace angio
