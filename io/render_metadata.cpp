#include "io/render_metadata.h"

#include <sstream>

namespace angio {

namespace {

std::string number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

}  // namespace

ImageMetadata renderMetadata(const RenderDescription& description) {
  const RenderParams& p = description.params;
  ImageMetadata metadata{
      {"version", ANGIORAY_VERSION},
      {"dataset", description.dataset},
      {"axis", toString(p.axis)},
      {"angle_deg", number(p.angleDeg)},
      {"mode", p.compositing == Compositing::mip ? "mip" : "dvr"},
      {"isd", number(p.sampling.isd)},
      {"osd", number(p.sampling.osd)},
      {"filter", toString(p.sampling.filter)},
      {"ert", number(p.sampling.ert)},
  };
  if (description.quality) metadata["quality"] = toString(*description.quality);
  if (p.compositing == Compositing::mip) {
    metadata["mip_window"] = number(p.mip.window);
    metadata["mip_level"] = number(p.mip.level);
  } else {
    metadata["transfer_function"] = description.transferFunction;
    metadata["shading"] = p.shading.enabled ? "on" : "off";
    metadata["ka"] = number(p.shading.ka);
    metadata["kd"] = number(p.shading.kd);
  }
  return metadata;
}

}  // namespace angio
