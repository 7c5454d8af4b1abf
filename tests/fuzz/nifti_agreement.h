#pragma once
// The differential half of the nifti_header fuzz target: where io/ decodes a NIfTI file's voxels
// itself (io/voxel_data_layout.h: one file, this machine's byte order, no scaling, vox_offset past
// the header), the NIfTI library ITK reads with must see the same: the voxels at the same offset,
// unscaled, in this byte order, in one file. Else io/ would read other voxels than ITK. A
// disagreement is a finding: it aborts with both readings.
#include <nifti1_io.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "io/declared_geometry.h"
#include "io/input_error.h"
#include "io/nifti_header.h"

namespace angio::fuzz {

// The fields io/'s layout depends on, as one line.
inline std::string niftiSummary(double offset, bool swapped, bool singleFile, bool scaled) {
  return "voxels at " + std::to_string(std::uint64_t(offset)) + (swapped ? ", swapped" : ", native") +
         (singleFile ? ", one file" : ", two files") + (scaled ? ", scaled" : ", unscaled");
}

inline bool niftiScaled(double slope, double inter) {
  return !((slope == 0.0 || slope == 1.0) && inter == 0.0);
}

inline void requireNiftiLibraryAgrees(const std::filesystem::path& file, const NiftiHeader& header) {
  const bool decodedByIo = !header.nifti2 && !header.swapped && header.singleFile &&
                           !niftiScaled(header.sclSlope, header.sclInter) && header.dataOffset >= 352;
  if (!decodedByIo) return;
  try {
    checkDeclaredGeometry(file, VolumeFormat::nifti);
  } catch (const InputError&) {
    return;  // refused before ITK would read it
  }
  nifti_set_debug_level(0);  // its messages are not findings
  const std::unique_ptr<nifti_image, decltype(&nifti_image_free)> image(
      nifti_image_read(file.c_str(), 0), &nifti_image_free);
  if (!image) return;  // ITK refuses it too
  const std::string ours = niftiSummary(double(header.dataOffset), false, true, false);
  const std::string library = niftiSummary(image->iname_offset, image->byteorder != nifti_short_order(),
                                           image->nifti_type == NIFTI_FTYPE_NIFTI1_1,
                                           niftiScaled(image->scl_slope, image->scl_inter));
  if (ours == library) return;
  std::fprintf(stderr, "the NIfTI library reads the header otherwise:\n  ours:    %s\n  library: %s\n",
               ours.c_str(), library.c_str());
  std::abort();
}

}  // namespace angio::fuzz
