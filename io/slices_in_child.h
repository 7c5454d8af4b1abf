#pragma once
// Decoding slices in a child process. GDCM's JPEG, JPEG-LS and JPEG 2000 codecs abort the process on
// many damaged streams (an assert on any libjpeg warning, on an unexpected colour space, ...), and a
// compressed stream cannot be checked for all of them before it is decoded. A fork()ed child
// decodes the slices and streams them back through a pipe: a damaged slice fails the load with a
// message naming it, and the app goes on with the dataset it had.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/voxel.h"

namespace angio {

// In the child: decode(k, out) writes slice k's `voxelsPerSlice` voxels to `out` and returns how
// many of its pixel values were not finite; it may throw (InputError: its message is the user's).
using SliceDecode = std::function<std::size_t(int k, Voxel* out)>;
// In the calling process: slice k's voxels, in order k = 0, 1, ... (valid during the call).
using SliceTake = std::function<void(int k, const Voxel* voxels)>;

// Decodes slices 0 .. files.size() - 1 in a child process, handing each to `take`; returns the sum
// of decode's counts. Throws InputError naming `folder` and the slice's file when decode throws,
// when the child dies on a slice (a signal: the library aborted) or takes over `sliceTimeoutMs` on
// one (it is killed).
std::size_t decodeSlicesInChild(const std::filesystem::path& folder,
                                const std::vector<std::string>& files, std::size_t voxelsPerSlice,
                                const SliceDecode& decode, const SliceTake& take,
                                int sliceTimeoutMs = 120000);

}  // namespace angio
