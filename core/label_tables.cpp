#include "core/label_tables.h"

namespace angio {

LabelTables::LabelTables() { read_.mask.fill(0x0FFF); }

LabelTables::LabelTables(const std::vector<LabelStyle>& styles) : LabelTables() {
  std::array<bool, kLabelCount> seen{};
  for (const LabelStyle& style : styles) {
    // Label 0 is "no label": it always renders with the main TF.
    if (style.label < 1 || style.label > kMaxLabel || seen[style.label]) continue;
    seen[style.label] = true;
    if (style.mode == LabelMode::hidden) {
      read_.mask[style.label] = 0;
      read_.hiddenLabels |= std::uint32_t{1} << style.label;
      hidesAny_ = true;
    } else if (style.mode == LabelMode::tf) {
      TransferFunction tf;
      tf.name = style.name;
      tf.points = style.points;
      own_[style.label] = std::make_shared<const TfTable>(buildTable(tf));
      ownsAny_ = true;
    }
  }
}

}  // namespace angio
