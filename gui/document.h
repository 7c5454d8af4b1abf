#pragma once
// The workstation's document: what the user edits and a session file keeps (dataset, view, main
// TF with its MIP window, mode, shading, the quality levels' sampling, the CPR view and DVR+CPR
// hybrid, the VesselGlyph panel's settings and TFs, crop box, clip plane and slab, the slice view,
// which side-panel sections are open, recent files), as plain values. Only Workstation::apply (gui/workstation.h) changes one; the session
// file (gui/session_file.h) is its JSON. Runtime things (textures, the renderer, jobs) live in App.
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "gui/clip_state.h"
#include "render/progressive_renderer.h"
#include "render/slice_images.h"
#include "vessel/centerline.h"
#include "vessel/cpr_display.h"
#include "vessel/cpr_layout.h"
#include "vessel/vessel_glyph.h"

namespace angio {

constexpr std::size_t kMaxRecentFiles = 10;

// Rotation axis and angle (theta of the rendering model, kept in [0, 360)), zoom (1 = the whole
// volume fits the viewport), pan (screen pixels), drag speed, auto-spin.
struct ViewState {
  Axis axis = Axis::k;
  double angleDeg = 0;
  double zoom = 1;
  glm::dvec2 panPx{0.0};  // screen pixels
  double degreesPerPixel = 0.5;
  bool autoSpin = false;
  double spinDegreesPerSecond = 30;

  friend bool operator==(const ViewState&, const ViewState&) = default;
};

// How the CPR section colors a CPR: grey through the CTA-lumen or calcium window
// (vessel/cpr_display.h), or through the VesselGlyph focus TF.
enum class CprColoring { ctaLumen = 0, calcium = 1, focusTf = 2 };

// "cta-lumen", "calcium", "focus-tf" (session files and the state report).
const char* cprColoringName(CprColoring coloring);

// The CPR section: the view beside the image and the DVR+CPR hybrid in the image share the path
// and the coloring. (The VesselGlyph settings the hybrid builds on are VesselGlyphState's.)
constexpr double kMinCprWidthMm = 10, kMaxCprWidthMm = 200;  // the section's width slider

// The CPR's cursor: a place on a centerline path (the CPR, the DVR image, the slices and the
// cross-section show it). The path indexes the centerlines the CPR shows; a cursor that no longer
// fits them (a path deleted, another file) is not shown rather than moved.
struct CprCursor {
  int path = 0;
  double arcMm = 0;  // from the path's first point

  friend bool operator==(const CprCursor&, const CprCursor&) = default;
};

struct CprState {
  bool shown = false;  // the CPR view beside the image
  CprMode mode = CprMode::straightened;
  int path = -1;  // centerline path index, -1 = all paths
  CprColoring coloring = CprColoring::ctaLumen;
  WindowLevel window = kCtaLumenWindow;  // the grey colorings' (the presets set it, a drag too)
  double widthMm = kDefaultCprWidthMm;   // lateral extent of the straightened and stretched CPR
  bool hybrid = false;                   // the DVR+CPR hybrid (needs VesselGlyph on)
  double transitionMm = 0;               // the hybrid's transition band, 0 = hard edge
  // The CPR pane as a reading view (gui/cpr_pane.h): zoom about the fitted image's centre, pan in
  // screen pixels. Back to the fitted image for another path, mode, centerlines or dataset.
  double zoom = 1;
  glm::dvec2 panPx{0.0};
  std::optional<CprCursor> cursor;  // none until a click on a centerline or in the CPR

  friend bool operator==(const CprState&, const CprState&) = default;
};

// The VesselGlyph panel (thesis ch. 5): the centerline file and what the user set.
struct VesselGlyphState {
  std::string centerlines;          // the centerline file as given ("" = none)
  std::string centerlinesAbsolute;  // the same, absolute when it was loaded (tried first)
  bool enabled = false;             // VesselGlyph rendering on
  bool overlay = true;              // the projected centerlines over the image
  VesselGlyphSettings settings;
  bool outsideRendered = false;  // the outside: rendered with the main TF, else clipped
  // Each region's TF follows the main TF (render/region_tfs.h) until the user gives it its own: a
  // preset, a file or an edit in the TF editor. The own TFs below count only when not following.
  bool focusFollowsMain = true, contextFollowsMain = true;
  TransferFunction focusTf, contextTf;     // no points: the presets below, loaded on first use
  std::string focusPreset, contextPreset;  // "" = edited

  friend bool operator==(const VesselGlyphState&, const VesselGlyphState&) = default;
};

// The Labels section (rendering model, "Labels"): the label volume that goes with the dataset and
// whether hidden labels show as a translucent ghost. How each label renders (its name, color,
// mode, own TF) is the main TF's label list (Document::tf.labels), so TF files carry it.
struct LabelsState {
  std::string file;          // the label volume loaded or last saved ("" = none)
  bool showRemoved = false;  // hidden labels translucent instead of cut out

  friend bool operator==(const LabelsState&, const LabelsState&) = default;
};

// One vessel path of the Vessels section: what the user clicked (snapped to the lumen's centre) and
// the centerline traced through those points, both physical (LPS mm, as files hold them, so a
// session or a file keeps them whatever the dataset's grid). A path read from a file has no
// control points: it was not traced here, and snapping its ends again could move an expert's
// centerline; it can be renamed, deleted and used, not re-traced.
struct VesselPath {
  std::string name;
  std::vector<glm::dvec3> controlPointsMm;  // physical, in the order clicked
  CenterlinePath centerline;                // physical; fewer than 2 points: not traced yet

  friend bool operator==(const VesselPath&, const VesselPath&) = default;
};

// The Vessels section's paths: the centerlines VesselGlyph, the CPR view and the hybrid use.
struct VesselsState {
  std::vector<VesselPath> paths;
  std::string file;      // where they were read from or last saved ("" = none)
  bool unsaved = false;  // changed since (exports then write them beside themselves)
  // Bumped by Workstation::apply for every change of `paths`: what is derived from them (framed
  // centerlines, CPR, scene) compares this number, not the paths.
  std::uint64_t revision = 0;

  friend bool operator==(const VesselsState&, const VesselsState&) = default;
};

// The paths with a traced centerline (2 points or more), as centerlines in the physical frame.
Centerlines centerlinesOf(const VesselsState& vessels);

// The linked slice view (render/slice_images.h): axial, coronal and sagittal slices through the
// 3-D cursor beside the image, grey through a window/level. The cursor is in mm of the volume frame
// and belongs to the dataset: a new one starts at its centre.
// A slice pane's zoom about its fitted image's centre and its pan (screen pixels), as the CPR
// pane's; zoom 1 and no pan: the slice fits the pane.
constexpr double kMinSliceZoom = 1, kMaxSliceZoom = 16;
struct SlicePaneView {
  double zoom = 1;
  glm::dvec2 panPx{0.0};

  friend bool operator==(const SlicePaneView&, const SlicePaneView&) = default;
};

struct SliceViewState {
  bool shown = false;
  std::optional<glm::dvec3> cursorMm;    // none: the volume's centre
  WindowLevel windowLevel{600, 250};     // CTA
  std::array<SlicePaneView, 3> panes{};  // axial, coronal, sagittal (SliceOrientation order)

  friend bool operator==(const SliceViewState&, const SliceViewState&) = default;
};

struct Document {
  std::string dataset;  // file or folder; "phantom IxJxK" for the generated phantom
  ViewState view;
  TransferFunction tf;   // includes the MIP window/level
  std::string tfPreset;  // the preset's id or the file it was loaded from; empty once edited
  Compositing mode = Compositing::dvr;
  Shading shading;
  LevelSamplings levels = defaultLevelSamplings();
  CprState cpr;
  VesselGlyphState vesselGlyph;
  LabelsState labels;
  VesselsState vessels;
  ClipState clip;                          // the Crop & clip section
  SliceViewState slices;                   // the linked slice view
  std::map<std::string, bool> panelsOpen;  // side-panel section title -> open
  std::vector<std::string> recentFiles;    // newest first, at most kMaxRecentFiles

  friend bool operator==(const Document&, const Document&) = default;
};

// Which TF the TF editor edits.
enum class TfTarget { main = 0, focus = 1, context = 2 };

const char* tfTargetName(TfTarget target);  // "main", "focus", "context"
// The TF a target renders with: for a region following the main TF, the one it follows.
TransferFunction tfOf(const Document& document, TfTarget target);
const std::string& presetOf(const Document& document, TfTarget target);  // a region: its own
bool followsMainTf(const Document& document, TfTarget target);           // false for the main TF
const char* followingTfLabel(TfTarget region);  // "main TF", "main TF, faded": a region following it
// A region's TF given the main TF it would follow.
TransferFunction regionTf(const VesselGlyphState& vesselGlyph, TfTarget region,
                          const TransferFunction& main);

// The main TF as rendered: its labels, hidden ones translucent when the user shows what was removed.
TransferFunction renderedTf(const Document& document);

// The render parameters the document asks for (sampling left at its default: each level sets it).
RenderParams renderParamsOf(const Document& document);

// Puts `path` first in `recent` (removing an older entry of it), keeping kMaxRecentFiles.
void addRecentFile(std::vector<std::string>& recent, const std::string& path);

// "phantom IxJxK" names the generated phantom rather than a file.
bool isPhantomName(const std::string& dataset);
// A dataset on disk as an absolute path (sessions and sidecars work from any folder), else as is.
std::string absoluteDataset(const std::string& dataset);

}  // namespace angio
