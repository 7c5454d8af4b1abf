#include "render/region_tfs.h"

namespace angio {

TransferFunction followingContextTf(const TransferFunction& main) {
  TransferFunction context = main;
  context.name = main.name + ", faded";
  context.modulators.opacityScale = main.modulators.opacityScale * kFollowingContextOpacity;
  return context;
}

}  // namespace angio
