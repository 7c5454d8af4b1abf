#include "cli/clipping_options.h"

#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/number_list.h"
#include "core/clip_interval.h"

namespace angio {

namespace {

// The flag's part alone must be renderable.
void checkPart(const ViewClipping& part, const std::string& flag) {
  if (const std::string problem = clippingProblem(part); !problem.empty())
    throw std::invalid_argument(flag + ": " + problem);
}

}  // namespace

void addClippingOptions(CLI::App& cmd, ClippingCliOptions& o) {
  cmd.add_option("--crop", o.crop,
                 "Render only the box i0,i1,j0,j1,k0,k1 (mm of the volume frame: voxel centres "
                 "at index * spacing)");
  auto* clip = cmd.add_option("--clip", o.clip,
                              "Remove the half-space on the normal's side of the plane through "
                              "px,py,pz (mm) with normal nx,ny,nz");
  cmd.add_option("--clip-facing", o.clipFacing,
                 "Remove what lies in front of a plane facing the viewer, at this depth from the "
                 "volume centre (mm, positive: away from the viewer)")
      ->excludes(clip);
  cmd.add_option("--slab", o.slab,
                 "Render only the slab facing the viewer at offset_mm (depth from the volume "
                 "centre) with thickness_mm, as offset_mm,thickness_mm");
}

ViewClipping clippingFrom(const ClippingCliOptions& o) {
  ViewClipping clipping;
  if (o.crop) {
    const auto v = parseNumberList(*o.crop, 6, "--crop", "6 numbers i0,i1,j0,j1,k0,k1 (mm)");
    clipping.crop = CropBox{{v[0], v[2], v[4]}, {v[1], v[3], v[5]}};
    checkPart({clipping.crop, {}, {}}, "--crop");
  }
  if (o.clip) {
    const auto v = parseNumberList(*o.clip, 6, "--clip", "6 numbers px,py,pz,nx,ny,nz");
    clipping.plane = ClipPlane{false, 0, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    checkPart({{}, clipping.plane, {}}, "--clip");
  }
  if (o.clipFacing) {
    clipping.plane = facingPlane(*o.clipFacing);
    checkPart({{}, clipping.plane, {}}, "--clip-facing");
  }
  if (o.slab) {
    const auto v = parseNumberList(*o.slab, 2, "--slab", "2 numbers offset_mm,thickness_mm");
    clipping.slab = ThickSlab{v[0], v[1]};
    checkPart({{}, {}, clipping.slab}, "--slab");
  }
  return clipping;
}

}  // namespace angio
