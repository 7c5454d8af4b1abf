#pragma once
// Reading a volume file's voxel bytes from a VoxelDataLayout in slabs of whole slices, raw or
// inflated with zlib, straight into the caller's buffer: a load reports progress and can be stopped
// between slabs, where ITK reads a single-file volume in one call that neither reports nor stops.
#include <cstdint>
#include <functional>
#include <stdexcept>

#include "io/voxel_data_layout.h"

namespace angio {

// The data cannot be opened, end early or do not decode; the message names no file.
struct VoxelStreamError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SlabbedVoxels {
  std::uint64_t sliceBytes = 0;
  std::uint64_t slices = 0;
};

// Fills out[0, sliceBytes * slices) with the voxel bytes, then leaves the rest of the file unread.
// Calls betweenSlabs(fraction read so far) after every slab but the last; it may throw to stop the
// read. Throws VoxelStreamError on bad data.
void readVoxelSlabs(const VoxelDataLayout& layout, const SlabbedVoxels& voxels, char* out,
                    const std::function<void(double)>& betweenSlabs);

// One slab of whole slices, in a buffer the reader reuses for the next one.
struct VoxelSlab {
  const char* bytes = nullptr;  // sliceBytes * sliceCount bytes, aligned for any component type
  std::uint64_t firstSlice = 0;
  std::uint64_t sliceCount = 0;
};

// The same read without the whole volume's bytes in memory: visit(slab) is called for each slab in
// order (the caller converts it into its own array), then betweenSlabs as above. Holds one slab,
// about 1 % of the volume.
void streamVoxelSlabs(const VoxelDataLayout& layout, const SlabbedVoxels& voxels,
                      const std::function<void(const VoxelSlab&)>& visit,
                      const std::function<void(double)>& betweenSlabs);

}  // namespace angio
