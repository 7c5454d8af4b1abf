#pragma once
// The differential half of the volume_nrrd fuzz target: a NRRD header the checks before ITK accept
// (checkDeclaredGeometry) must read the same in teem (ITK's NrrdIO) where it matters, since those
// checks judge what io/nrrd_header.h reads: every size teem reads is one the checks bounded, every
// spacing ITK takes from it is > 0, and where io/ places the voxel data (nrrdData's place: the
// truncation check, the voxels io/ decodes itself) is where teem reads them. A disagreement is a
// finding: it aborts with both readings.
#include <NrrdIO.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "io/declared_geometry.h"
#include "io/input_error.h"
#include "io/voxel_data_layout.h"

namespace angio::fuzz {

// What teem reads of a header without its data (skipData), in terms of VoxelDataLayout.
struct TeemReading {
  std::string sizes;                     // the axis sizes, as a list
  bool sizesFitInt = true;               // every size <= INT_MAX
  std::string badSpacing;                // a spatial axis's spacing ITK would take and cannot use
  std::optional<VoxelDataLayout> place;  // raw or gzip, attached or one data file, no skips
};

// Owns what a header-only nrrdLoad leaves: the nrrd, the I/O state and its open data file.
class TeemHeaderRead {
 public:
  explicit TeemHeaderRead(const std::filesystem::path& file)
      : file_(file), nrrd_(nrrdNew()), io_(nrrdIoStateNew()) {
    io_->skipData = 1;
    io_->keepNrrdDataFileOpen = 1;  // positioned where the data start
    if (nrrdLoad(nrrd_, file.c_str(), io_)) std::free(biffGetDone(NRRD));
    else loaded_ = true;
  }
  ~TeemHeaderRead() {
    if (io_->dataFile && io_->dataFile != stdin) std::fclose(io_->dataFile);
    io_->dataFile = nullptr;
    nrrdIoStateNix(io_);
    nrrdNuke(nrrd_);
  }
  TeemHeaderRead(const TeemHeaderRead&) = delete;
  TeemHeaderRead& operator=(const TeemHeaderRead&) = delete;

  // Nothing if teem refuses the header (so will ITK, with a message).
  std::optional<TeemReading> reading() const {
    if (!loaded_) return std::nullopt;
    TeemReading reading;
    for (unsigned axis = 0; axis < nrrd_->dim; ++axis) {
      if (axis) reading.sizes += ' ';
      reading.sizes += std::to_string(nrrd_->axis[axis].size);
      reading.sizesFitInt = reading.sizesFitInt && nrrd_->axis[axis].size <= std::size_t(INT_MAX);
    }
    reading.badSpacing = badSpacing();
    const std::string encoding = io_->encoding ? io_->encoding->name : "";
    const unsigned files = io_->dataFNArr ? io_->dataFNArr->len : 0;
    if ((encoding != "raw" && encoding != "gzip") || io_->lineSkip || io_->byteSkip || files > 1)
      return reading;
    VoxelDataLayout place;
    place.encoding = encoding == "gzip" ? VoxelEncoding::deflate : VoxelEncoding::raw;
    if (files == 0) {
      if (!io_->dataFile) return reading;
      place.dataFile = file_;
      place.fileOffset = std::uint64_t(std::ftell(io_->dataFile));
    } else {
      const std::filesystem::path name(io_->dataFN[0]);
      place.dataFile = name.is_absolute() ? name : std::filesystem::path(io_->path) / name;
    }
    reading.place = place;
    return reading;
  }

 private:
  // The first three axes' spacing as ITK takes it: the length of the space direction if the header
  // has a space, else the spacing; where it is given (ITK takes 1 mm for none), it must be > 0.
  std::string badSpacing() const {
    for (unsigned axis = 0; axis < std::min(nrrd_->dim, 3u); ++axis) {
      const NrrdAxisInfo& info = nrrd_->axis[axis];
      double length = info.spacing;
      if (nrrd_->spaceDim > 0) {
        double squared = 0;
        for (unsigned d = 0; d < nrrd_->spaceDim; ++d)
          squared += info.spaceDirection[d] * info.spaceDirection[d];
        length = std::sqrt(squared);
      }
      if (AIR_EXISTS(length) && !(length > 0))
        return "axis " + std::to_string(axis) + " spacing " + std::to_string(length);
    }
    return "";
  }

  std::filesystem::path file_;
  Nrrd* nrrd_;
  NrrdIoState* io_;
  bool loaded_ = false;
};

inline std::string placeText(const std::optional<VoxelDataLayout>& place) {
  if (!place) return "(none: left to teem)";
  return place->dataFile.string() + " at " + std::to_string(place->fileOffset) +
         (place->encoding == VoxelEncoding::deflate ? " gzip" : " raw");
}

// Ours must be teem's where io/ has a place; where it has none, teem's must not be the attached
// data (whose truncation check would be missed); a data file io/ leaves to teem (a pattern of
// one file, say) is not a disagreement.
inline bool placesAgree(const std::optional<VoxelDataLayout>& ours,
                        const std::optional<VoxelDataLayout>& teem, const std::filesystem::path& file) {
  if (!ours) return !teem || teem->dataFile != file;
  return teem && ours->dataFile.lexically_normal() == teem->dataFile.lexically_normal() &&
         ours->fileOffset == teem->fileOffset && ours->encoding == teem->encoding;
}

inline void requireTeemAgrees(const std::filesystem::path& file) {
  try {
    checkDeclaredGeometry(file, VolumeFormat::nrrd);
  } catch (const InputError&) {
    return;  // refused before teem would read it
  }
  const std::optional<TeemReading> teem = TeemHeaderRead(file).reading();
  if (!teem) return;
  const std::optional<VoxelDataLayout> ours = nrrdData(file).place;
  if (teem->sizesFitInt && teem->badSpacing.empty() && placesAgree(ours, teem->place, file)) return;
  std::fprintf(stderr,
               "teem reads the header otherwise:\n  teem: sizes %s, data %s %s\n  ours: data %s\n",
               teem->sizes.c_str(), placeText(teem->place).c_str(), teem->badSpacing.c_str(),
               placeText(ours).c_str());
  std::abort();
}

}  // namespace angio::fuzz
