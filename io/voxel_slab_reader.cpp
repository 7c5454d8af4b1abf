#include "io/voxel_slab_reader.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace angio {

namespace {

// About this many slabs per volume: progress moves in steps of about 1 %, and a cancelled load
// stops after at most one more slab.
constexpr std::uint64_t kSlabsPerVolume = 100;

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File openAt(const VoxelDataLayout& layout) {
  File file(std::fopen(layout.dataFile.c_str(), "rb"), &std::fclose);
  if (!file) throw VoxelStreamError("cannot be opened");
  if (::fseeko(file.get(), off_t(layout.fileOffset), SEEK_SET) != 0)
    throw VoxelStreamError("cannot seek to the voxel data");
  return file;
}

// The decoded bytes of a layout's data, read in order.
class DecodedBytes {
 public:
  explicit DecodedBytes(const VoxelDataLayout& layout) : file_(openAt(layout)) {
    if (layout.encoding == VoxelEncoding::raw) return;
    // 15 + 32: a zlib or a gzip stream, whichever the header says (MetaImage writes zlib).
    if (inflateInit2(&stream_, 15 + 32) != Z_OK) throw VoxelStreamError("zlib failed");
    inflating_ = true;
    input_.resize(1 << 20);
  }
  ~DecodedBytes() {
    if (inflating_) inflateEnd(&stream_);
  }
  DecodedBytes(const DecodedBytes&) = delete;
  DecodedBytes& operator=(const DecodedBytes&) = delete;

  void read(char* out, std::uint64_t bytes) {
    inflating_ ? inflateInto(out, bytes) : readRaw(out, bytes);
  }

  void skip(std::uint64_t bytes) {
    std::vector<char> scratch(std::min<std::uint64_t>(bytes, 1 << 16));
    for (std::uint64_t left = bytes; left > 0;) {
      const std::uint64_t chunk = std::min<std::uint64_t>(left, scratch.size());
      read(scratch.data(), chunk);
      left -= chunk;
    }
  }

 private:
  [[noreturn]] static void endsEarly() { throw VoxelStreamError("voxel data end early"); }

  void readRaw(char* out, std::uint64_t bytes) {
    if (std::fread(out, 1, bytes, file_.get()) != bytes) endsEarly();
  }

  void refill() {
    const std::size_t got = std::fread(input_.data(), 1, input_.size(), file_.get());
    if (got == 0) endsEarly();
    stream_.next_in = input_.data();
    stream_.avail_in = uInt(got);
  }

  void inflateInto(char* out, std::uint64_t bytes) {
    while (bytes > 0) {
      const uInt chunk = uInt(std::min<std::uint64_t>(bytes, 1u << 30));  // avail_out is 32-bit
      stream_.next_out = reinterpret_cast<Bytef*>(out);
      stream_.avail_out = chunk;
      while (stream_.avail_out > 0) {
        if (stream_.avail_in == 0) refill();
        const int status = inflate(&stream_, Z_NO_FLUSH);
        // A gzip file may hold several members one after the other (zlib's gzread reads on too).
        if (status == Z_STREAM_END && inflateReset(&stream_) == Z_OK) continue;
        if (status != Z_OK && status != Z_BUF_ERROR) throw notDecompressing(status);
      }
      out += chunk;
      bytes -= chunk;
    }
  }

  VoxelStreamError notDecompressing(int status) const {
    const char* why = status == Z_NEED_DICT ? "it asks for a preset dictionary"
                      : stream_.msg         ? stream_.msg
                                            : "zlib error";
    return VoxelStreamError(std::string("voxel data do not decompress (") + why + ")");
  }

  File file_;
  bool inflating_ = false;
  z_stream stream_{};
  std::vector<Bytef> input_;
};

// About 1 % of the volume per slab (whole slices).
std::uint64_t slicesPerSlab(const SlabbedVoxels& voxels) {
  return std::max<std::uint64_t>(1, (voxels.slices + kSlabsPerVolume - 1) / kSlabsPerVolume);
}

// Reads the slabs in order, each into the buffer `into(first, count)` gives, calling done(first,
// count) after it and betweenSlabs between slabs.
template <class Into, class Done>
void readSlabs(const VoxelDataLayout& layout, const SlabbedVoxels& voxels, Into into, Done done,
               const std::function<void(double)>& betweenSlabs) {
  DecodedBytes bytes(layout);
  bytes.skip(layout.skipBytes);
  const std::uint64_t slabSlices = slicesPerSlab(voxels);
  for (std::uint64_t first = 0; first < voxels.slices; first += slabSlices) {
    const std::uint64_t count = std::min(slabSlices, voxels.slices - first);
    bytes.read(into(first, count), count * voxels.sliceBytes);
    done(first, count);
    const std::uint64_t read = first + count;
    if (read < voxels.slices && betweenSlabs) betweenSlabs(double(read) / double(voxels.slices));
  }
}

}  // namespace

void readVoxelSlabs(const VoxelDataLayout& layout, const SlabbedVoxels& voxels, char* out,
                    const std::function<void(double)>& betweenSlabs) {
  readSlabs(
      layout, voxels,
      [&](std::uint64_t first, std::uint64_t) { return out + first * voxels.sliceBytes; },
      [](std::uint64_t, std::uint64_t) {}, betweenSlabs);
}

void streamVoxelSlabs(const VoxelDataLayout& layout, const SlabbedVoxels& voxels,
                      const std::function<void(const VoxelSlab&)>& visit,
                      const std::function<void(double)>& betweenSlabs) {
  // double storage: aligned for every component type.
  const std::uint64_t slabBytes = slicesPerSlab(voxels) * voxels.sliceBytes;
  const auto buffer = std::make_unique_for_overwrite<double[]>((slabBytes + 7) / 8);
  char* bytes = reinterpret_cast<char*>(buffer.get());
  readSlabs(
      layout, voxels, [&](std::uint64_t, std::uint64_t) { return bytes; },
      [&](std::uint64_t first, std::uint64_t count) {
        visit({bytes, first, count});
      },
      betweenSlabs);
}

}  // namespace angio
