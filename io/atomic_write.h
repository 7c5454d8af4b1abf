#pragma once
// Writing user files safely: write to a temporary name beside the target, then rename over it,
// so a failed write never leaves a half file or clobbers an existing one.
#include <filesystem>
#include <functional>
#include <string>

namespace angio {

// Calls write(tempPath); on success renames tempPath to target, on any exception removes tempPath
// and rethrows. The temp name keeps the target's extension (writers choose formats by it).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tempPath)>& write);

// Writes `bytes` as the whole of `target`, atomically; throws InputError naming the target if it
// cannot (a missing or read-only folder, a folder of that name, a full disk).
void writeBytesAtomically(const std::filesystem::path& target, const std::string& bytes);

}  // namespace angio
