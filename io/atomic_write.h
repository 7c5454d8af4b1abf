#pragma once
// Writing user files safely: write to a temporary name beside the target, then rename over it,
// so a failed write never leaves a half file or clobbers an existing one.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace angio {

// Calls write(tempPath); on success renames tempPath to target, on any exception removes tempPath
// and rethrows. The temp name keeps the target's extension (writers choose formats by it).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tempPath)>& write);

// Writes `bytes` as the whole of `target`, atomically; throws InputError naming the target if it
// cannot (a missing or read-only folder, a folder of that name, a full disk).
void writeBytesAtomically(const std::filesystem::path& target, const std::string& bytes);

// Throws InputError unless a file can be written at `target`: its folder exists and is writable,
// and it is not a folder itself. For checking every output before a long computation.
void requireWritableTarget(const std::filesystem::path& target);

// Files that appear together or not at all: an image and its sidecar, a phantom and its ground
// truth, a rotation series. add() writes each file into a scratch folder beside its target (a
// .mhd's data file lands beside it there under its final name); commit() moves them all into
// place, putting back every file it replaced if a move fails; without commit() nothing of the group
// is left behind. add() refuses a target that is a folder or whose folder cannot be written
// before calling `write`, so a bad second target stops the group before the first is in place.
class AtomicFileGroup {
 public:
  using Write = std::function<void(const std::filesystem::path& file)>;
  AtomicFileGroup() = default;
  AtomicFileGroup(const AtomicFileGroup&) = delete;
  AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
  ~AtomicFileGroup();

  void add(const std::filesystem::path& target, const Write& write);
  // Throws InputError naming the file that could not be moved (the targets are as before then).
  void commit();

 private:
  std::filesystem::path scratchFor(const std::filesystem::path& folder);
  std::map<std::filesystem::path, std::filesystem::path> scratch_;  // target folder -> scratch
  std::vector<std::filesystem::path> targets_;
};

}  // namespace angio
