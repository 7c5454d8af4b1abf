#include "cli/clipping_options.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/clip_interval.h"

namespace angio {

namespace {

// Exactly `count` finite numbers separated by commas.
std::vector<double> numbers(const std::string& text, std::size_t count, const std::string& flag,
                            const std::string& form) {
  const std::string usage = flag + " needs " + form + ", got '" + text + "'";
  std::vector<double> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value)) throw std::invalid_argument(usage);
    values.push_back(value);
    at = comma + 1;
  }
  if (values.size() != count) throw std::invalid_argument(usage);
  return values;
}

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
    const auto v = numbers(*o.crop, 6, "--crop", "6 numbers i0,i1,j0,j1,k0,k1 (mm)");
    clipping.crop = CropBox{{v[0], v[2], v[4]}, {v[1], v[3], v[5]}};
    checkPart({clipping.crop, {}, {}}, "--crop");
  }
  if (o.clip) {
    const auto v = numbers(*o.clip, 6, "--clip", "6 numbers px,py,pz,nx,ny,nz");
    clipping.plane = ClipPlane{false, 0, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    checkPart({{}, clipping.plane, {}}, "--clip");
  }
  if (o.clipFacing) {
    clipping.plane = facingPlane(*o.clipFacing);
    checkPart({{}, clipping.plane, {}}, "--clip-facing");
  }
  if (o.slab) {
    const auto v = numbers(*o.slab, 2, "--slab", "2 numbers offset_mm,thickness_mm");
    clipping.slab = ThickSlab{v[0], v[1]};
    checkPart({{}, {}, clipping.slab}, "--slab");
  }
  return clipping;
}

}  // namespace angio
