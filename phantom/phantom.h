#pragma once
// Peripheral run-off CTA phantom: the embedded default dataset and the benchmark volume.
// Air around a body (abdomen, then two legs), soft tissue and fat with noise, spine, pelvis,
// femur, tibia and fibula with cortical shell and marrow, and a contrast-filled arterial tree
// (aorta -> common/external iliac -> femoral -> popliteal -> anterior/posterior tibial) whose
// radius tapers, with a tortuous and a near-horizontal segment, calcified plaques and a stenosis.
// Under the body lies the scanner table: a curved carbon-fibre shell with a foam pad on it.
// The realistic style (the default) adds what makes real CT expensive to render: enhancing organs
// at arterial-phase densities (kidney cortex and medulla, liver, spleen, pancreas, bowel loops),
// psoas muscles, visceral fat, textured cancellous bone, fatty marrow, hundreds of small
// contrast-filled branches and in-plane correlated noise; the simple style is the phantom as it was
// before (clean tissue, white noise), kept for the golden images and the tests built on it; the
// portal-venous style is the realistic one in the portal-venous phase, veins enhanced.
// Same options, same bytes, whatever the thread count.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

// realistic: arterial phase (CTA timing); portalVenous: the same anatomy some 70 s after the
// injection, as in an abdominal staging CT: the arteries, the veins and the organs all read
// 100-190 HU, on the low-opacity ramp of vessel presets (a renderer's hardest case).
enum class PhantomStyle { realistic, simple, portalVenous };

struct PhantomOptions {
  glm::ivec3 dims{512, 512, 1200};
  std::uint64_t seed = 1;
  // The voxels' label bits carry the ground truth (core/labels.h): kBoneLabel for every voxel
  // inside a bone (cortex and marrow), kTableLabel for the table (shell and pad), 0 elsewhere, also
  // where lumen or plaque is painted over bone. Off, the label bits are 0. The label bits cost no
  // memory, where a separate label volume would add half the volume's size.
  bool groundTruthLabels = false;
  PhantomStyle style = PhantomStyle::realistic;

  friend bool operator==(const PhantomOptions&, const PhantomOptions&) = default;
};

// "realistic", "simple" or "portal-venous"; nullopt for anything else.
std::optional<PhantomStyle> parsePhantomStyle(const std::string& name);

struct Phantom {
  Volume volume;
  // Ground truth in the physical frame (mm, LPS), with lumen radii; path names such as
  // "aorta-left-anterior-tibial". Root (aorta) to each leaf; shared trunks repeated, as vmtk does.
  Centerlines centerlines;
};

// progress(fraction in [0, 1]) is called from the generating thread now and then; may be empty.
Phantom generatePhantom(const PhantomOptions& options, const std::function<void(double)>& progress = {});

}  // namespace angio
