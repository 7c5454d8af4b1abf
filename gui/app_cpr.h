#pragma once
// The CPR view's state (thesis sec. 5.2.2; Kanitsar et al., IEEE Vis 2002): the
// curved planar reformation of the selected centerline path at the view's axis and angle, shown
// beside the DVR view; hovering it reads arc length and HU and marks the point on the DVR image.
// Drawn by gui/app_cpr.cpp.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <imgui.h>

#include "gui/app_gl.h"
#include "gui/background_job.h"
#include "gui/document.h"
#include "vessel/cpr.h"
#include "vessel/cross_section.h"

namespace angio {

// A point of a centerline: the CPR view's cursor (the document's CprCursor) where it is.
struct CenterlinePlace {
  int path = 0;             // index into the centerlines
  double arcMm = 0;         // from the path's first point
  glm::dvec3 pointMm{0.0};  // volume frame

  friend bool operator==(const CenterlinePlace&, const CenterlinePlace&) = default;
};

// What a CPR image is computed from: a change computes it again (off the UI thread).
struct CprInputs {
  std::string dataset;         // the dataset the centerlines were mapped for
  std::string centerlines;     // their file
  std::uint64_t revision = 0;  // of the document's vessel paths
  Axis axis = Axis::k;
  double angleDeg = 0;
  double pixelMm = 1;
  CprMode mode = CprMode::straightened;
  int path = -1;
  std::optional<double> widthMm;  // none: the projected CPR's whole rows

  friend bool operator==(const CprInputs&, const CprInputs&) = default;
};

struct ComputedCpr {
  CprInputs inputs;
  Cpr cpr;
};

// How the shown CPR and its cross-section are colored: grey through a window, or the focus TF's
// colors. Made again on the UI thread when it changes (a window drag), the CPR staying.
struct CprLook {
  WindowLevel window;
  std::optional<TransferFunction> focusTf;

  friend bool operator==(const CprLook&, const CprLook&) = default;
};

// The perpendicular cross-section at the cursor (vessel/cross_section.h), an inset of the pane.
struct CrossSectionInset {
  explicit CrossSectionInset(const GlApi& gl) : texture(gl) {}
  StreamedTexture texture;
  std::optional<std::pair<CenterlinePlace, CprLook>> madeFor;  // what the texture shows
};

struct CprViewPanel {
  explicit CprViewPanel(const GlApi& gl) : texture(gl), inset(gl) {}

  // What the user set is the document's CprState (shown, mode, path, coloring, hybrid).

  // What is shown.
  StreamedTexture texture;
  std::shared_ptr<const DisplayImage> frame;  // the CPR image as the texture uploads it
  std::optional<CprLook> look;                // ... colored so
  std::optional<Cpr> cpr;
  std::optional<CprInputs> madeFor;    // what `cpr` (or the last error) was computed from
  BackgroundJob<ComputedCpr> job;      // the next CPR being computed
  std::optional<CprInputs> computing;  // ... from these inputs
  std::string error;
  std::optional<CprPick> hovered;            // the CPR pixel under the mouse
  std::optional<ImVec2> markedOnDvr;         // where it was marked on the DVR image (screen)
  std::optional<glm::dvec2> cursorPixel;     // the cursor in the CPR image (pixel centres at integers)
  ImVec2 imageMin, imageMax;                 // where the CPR image was drawn (screen)
  std::optional<WindowLevel> windowAtPress;  // a right-drag's start
  bool held = false;  // the pane is pressed this frame (not an interaction with the 3-D view)
  CrossSectionInset inset;
};

}  // namespace angio
