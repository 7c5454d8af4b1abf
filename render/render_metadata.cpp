#include "render/render_metadata.h"

#include "core/number_text.h"


namespace angio {

ImageMetadata renderMetadata(const RenderDescription& description) {
  const RenderParams& p = description.params;
  ImageMetadata metadata{
      {"version", ANGIORAY_VERSION},
      {"dataset", description.dataset},
      {"axis", toString(p.axis)},
      {"angle_deg", numberText(p.angleDeg)},
      {"mode", p.compositing == Compositing::mip ? "mip" : "dvr"},
      {"isd", numberText(p.sampling.isd)},
      {"osd", numberText(p.sampling.osd)},
      {"filter", toString(p.sampling.filter)},
      {"ert", numberText(p.sampling.ert)},
  };
  if (description.quality) metadata["quality"] = toString(*description.quality);
  if (p.compositing == Compositing::mip) {
    metadata["mip_window"] = numberText(p.mip.window);
    metadata["mip_level"] = numberText(p.mip.level);
  } else {
    metadata["transfer_function"] = description.transferFunction;
    metadata["shading"] = p.shading.enabled ? "on" : "off";
    metadata["ka"] = numberText(p.shading.ka);
    metadata["kd"] = numberText(p.shading.kd);
  }
  return metadata;
}

}  // namespace angio
