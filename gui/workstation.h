#pragma once
// The workstation model: the document (gui/document.h) and the edits that change it. Panels draw
// from the document and return edits; App hands them to apply(), the one place the document
// changes, which keeps its invariants and bumps the version the renderer side compares (as Open
// VKL's Versioned does) instead of diffing fields by hand.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "gui/document.h"

namespace angio {

// The View section's settings as edited (the angle is wrapped by apply).
struct ViewEdit {
  ViewState view;
  friend bool operator==(const ViewEdit&, const ViewEdit&) = default;
};
// A turn by a drag, an arrow key or the auto-spin, relative to the angle at the time it applies.
struct RotateEdit {
  double degrees = 0;
  friend bool operator==(const RotateEdit&, const RotateEdit&) = default;
};
// A TF of the TF editor's targets (main, focus or context) and its preset: a preset's id, the file
// it was loaded from, or "" (edited). A region's TF set this way stops following the main TF;
// `followMain` makes it follow again (`tf` and `preset` then unused).
struct TfChange {
  TfTarget target = TfTarget::main;
  TransferFunction tf;
  std::string preset;
  bool followMain = false;
  friend bool operator==(const TfChange&, const TfChange&) = default;
};
// The Rendering section: DVR or MIP, its MIP window (kept in the main TF) and shading.
struct RenderingEdit {
  Compositing mode = Compositing::dvr;
  Shading shading;
  double mipWindow = 0, mipLevel = 0;
  bool preintegrated = false;  // every level's classification (rendering model, Approximations)
  std::optional<AdaptiveIntegration> adaptive;  // every level's integration (none: samples every osd)
  std::optional<AdaptiveSampling> adaptiveSampling;  // every level's (none: every ray, every sample)
  friend bool operator==(const RenderingEdit&, const RenderingEdit&) = default;
};
// On when every quality level pre-integrates (the Rendering panel switches them together).
bool levelsPreintegrated(const Document& document);
struct VesselGlyphEdit {
  VesselGlyphState vesselGlyph;
  friend bool operator==(const VesselGlyphEdit&, const VesselGlyphEdit&) = default;
};
// The CPR pane back to the fitted image (zoom 1, no pan).
void fitCprPane(CprState& cpr);

struct CprEdit {
  CprState cpr;
  friend bool operator==(const CprEdit&, const CprEdit&) = default;
};
// The centerline file now loaded, as given and absolute ("" and "": none).
struct CenterlineFileEdit {
  std::string given, absolute;
  friend bool operator==(const CenterlineFileEdit&, const CenterlineFileEdit&) = default;
};
// A dataset replaced the shown one: it is the document's, zoom and pan start over, it heads the
// recent files. What belonged to the old dataset goes (labels, vessel paths, the centerline file,
// VesselGlyph and the CPR view that showed them, clipping in its millimetres, the slice and CPR
// cursors)
// unless the dataset is the one a session named: the session's own state, applied before its load, stays.
struct DatasetOpened {
  std::string dataset;
  bool ofSession = false;
  friend bool operator==(const DatasetOpened&, const DatasetOpened&) = default;
};
struct RecentFilesEdit {
  std::vector<std::string> recentFiles;
  friend bool operator==(const RecentFilesEdit&, const RecentFilesEdit&) = default;
};
// The Labels section: the label styles (the main TF's label list) and the ghost of hidden labels.
struct LabelStylesEdit {
  std::vector<LabelStyle> styles;
  bool showRemoved = false;
  friend bool operator==(const LabelStylesEdit&, const LabelStylesEdit&) = default;
};
// The label volume now loaded or saved ("" = none).
struct LabelFileEdit {
  std::string file;
  friend bool operator==(const LabelFileEdit&, const LabelFileEdit&) = default;
};
// The Vessels section's paths as the user changed them (traced, renamed, deleted, undone): unsaved.
struct VesselPathsEdit {
  std::vector<VesselPath> paths;
  friend bool operator==(const VesselPathsEdit&, const VesselPathsEdit&) = default;
};
// The paths as read from or saved to `file`.
struct VesselFileEdit {
  std::vector<VesselPath> paths;
  std::string file;
  friend bool operator==(const VesselFileEdit&, const VesselFileEdit&) = default;
};
// The Crop & clip section: crop box, clip plane, thick slab.
struct ClipEdit {
  ClipState clip;
  friend bool operator==(const ClipEdit&, const ClipEdit&) = default;
};
// The slice view's settings, or its cursor moved (by a click in a slice or in the 3-D view).
struct SliceViewEdit {
  SliceViewState slices;
  friend bool operator==(const SliceViewEdit&, const SliceViewEdit&) = default;
};
// A side-panel section opened or closed.
struct PanelOpenEdit {
  std::string title;
  bool open = true;
  friend bool operator==(const PanelOpenEdit&, const PanelOpenEdit&) = default;
};
// A session's contents: everything but the dataset (its load replaces it, DatasetOpened) and the
// recent files (the app's own list).
struct SessionEdit {
  Document session;
  friend bool operator==(const SessionEdit&, const SessionEdit&) = default;
};

using Edit =
    std::variant<ViewEdit, RotateEdit, TfChange, RenderingEdit, VesselGlyphEdit, CprEdit,
                 CenterlineFileEdit, DatasetOpened, RecentFilesEdit, LabelStylesEdit, LabelFileEdit,
                 VesselPathsEdit, VesselFileEdit, PanelOpenEdit, SessionEdit, ClipEdit, SliceViewEdit>;

// What a DatasetOpened (not of a session) drops from `before`, for the status line: "3 vessel
// paths", "the centerline file", "VesselGlyph", "the CPR view", "the labels", "the crop & clip".
std::vector<std::string> droppedByNewDataset(const Document& before);

class Workstation {
 public:
  // `initial` is normalised as a session's contents are.
  explicit Workstation(Document initial = {});

  const Document& document() const { return document_; }
  // Bumped by every apply that changed the document.
  std::uint64_t version() const { return version_; }

  // Invariants, kept here only: the angle is in [0, 360); an edit or a session that turns the
  // DVR+CPR hybrid on turns VesselGlyph on (its focus is the hybrid's cut). VesselGlyph may be
  // turned off again while the hybrid is on: the CPR section then says the hybrid waits for it.
  // A main TF without labels (a preset) keeps the labels' styles: changing the TF does not bring
  // back removed bone. A new dataset starts without labels and without vessel paths (they were
  // traced in the old one), see DatasetOpened. Every edit that sets the vessel paths bumps their
  // revision.
  void apply(const Edit& edit);

 private:
  Document document_;
  std::uint64_t version_ = 0;
};

}  // namespace angio
