#include "io/atomic_write.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include <stdlib.h>
#include <unistd.h>

#include "io/input_error.h"

namespace angio {

namespace {

// "name.tmp-<pid>-<random>.ext", a name no file has yet: the extension is kept last (writers pick
// the format by it), and for double extensions (.nii.gz) the whole suffix after the first dot of the
// file name is kept. The random part comes from the system, so no counter state is shared.
std::filesystem::path temporaryName(const std::filesystem::path& target) {
  const std::string file = target.filename().string();
  const auto dot = file.find('.', 1);
  const std::string stem = dot == std::string::npos ? file : file.substr(0, dot);
  const std::string extension = dot == std::string::npos ? "" : file.substr(dot);
  std::random_device random;
  for (;;) {
    const std::uint64_t draw = (std::uint64_t(random()) << 32) | random();
    char suffix[17];
    std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(draw));
    const std::filesystem::path name =
        target.parent_path() / (stem + ".tmp-" + std::to_string(::getpid()) + "-" + suffix + extension);
    std::error_code error;
    if (!std::filesystem::exists(std::filesystem::symlink_status(name, error))) return name;
  }
}

}  // namespace

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tempPath)>& write) {
  const std::filesystem::path temp = temporaryName(target);
  try {
    write(temp);
    std::filesystem::rename(temp, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

void writeBytesAtomically(const std::filesystem::path& target, const std::string& bytes) {
  try {
    writeAtomically(target, [&](const std::filesystem::path& temp) {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out) throw InputError(target, "cannot open for writing");
      out << bytes;
      out.close();
      if (!out) throw InputError(target, "write failed");
    });
  } catch (const std::filesystem::filesystem_error& error) {
    // The rename over the target failed (a folder of that name, another file system).
    throw InputError(target, "cannot write: " + error.code().message());
  }
}

namespace {

namespace fs = std::filesystem;

// One move of a commit: `moved` once `to` holds the new file, `backup` what `to` held before.
struct Move {
  fs::path from, to, backup;
  bool moved = false;
};

void undo(std::vector<Move>& moves) {
  std::error_code ignored;
  for (auto move = moves.rbegin(); move != moves.rend(); ++move) {
    if (move->moved) fs::remove(move->to, ignored);
    if (!move->backup.empty()) fs::rename(move->backup, move->to, ignored);
  }
}

void apply(Move& move) {
  if (fs::exists(fs::symlink_status(move.to))) {
    fs::path backup = temporaryName(move.to);
    backup += ".old";
    fs::rename(move.to, backup);
    move.backup = backup;
  }
  fs::rename(move.from, move.to);
  move.moved = true;
}

}  // namespace

void requireWritableTarget(const std::filesystem::path& target) {
  std::error_code error;
  if (fs::is_directory(target, error))
    throw InputError(target, "is a folder; cannot write a file over it");
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, error)) throw InputError(target, "its folder does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError(target, std::string("cannot write into its folder: ") + std::strerror(errno));
}

fs::path AtomicFileGroup::scratchFor(const fs::path& folder) {
  if (const auto found = scratch_.find(folder); found != scratch_.end()) return found->second;
  std::string name = ((folder.empty() ? fs::path(".") : folder) / ".angioray-write-XXXXXX").string();
  if (!::mkdtemp(name.data()))
    throw InputError(folder, std::string("cannot write into the folder: ") + std::strerror(errno));
  return scratch_[folder] = name;
}

void AtomicFileGroup::add(const fs::path& target, const Write& write) {
  requireWritableTarget(target);
  targets_.push_back(target);
  const fs::path file = scratchFor(target.parent_path()) / target.filename();
  try {
    write(file);
  } catch (const std::exception& error) {
    // The writer names the scratch file; the user knows the target.
    std::string message = error.what();
    for (auto at = message.find(file.string()); at != std::string::npos;
         at = message.find(file.string(), at))
      message.replace(at, file.string().size(), target.string());
    const std::string prefix = target.string() + ": ";
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InputError(target, message);
  }
}

void AtomicFileGroup::commit() {
  // Files that are not targets (the data of a .mhd) first, so a header never names missing data.
  std::vector<Move> moves;
  for (const auto& [folder, scratch] : scratch_)
    for (const auto& entry : fs::directory_iterator(scratch)) {
      const fs::path to = folder / entry.path().filename();
      const bool isTarget = std::find(targets_.begin(), targets_.end(), to) != targets_.end();
      moves.insert(isTarget ? moves.end() : moves.begin(), {entry.path(), to, {}});
    }
  for (Move& move : moves) {
    try {
      if (fs::is_directory(move.to))
        throw InputError(move.to, "is a folder; cannot write a file over it");
      apply(move);
    } catch (const fs::filesystem_error& error) {
      undo(moves);
      throw InputError(move.to, "cannot write: " + error.code().message());
    } catch (...) {
      undo(moves);
      throw;
    }
  }
  std::error_code ignored;
  for (const Move& move : moves)
    if (!move.backup.empty()) fs::remove(move.backup, ignored);
  for (const auto& [folder, scratch] : scratch_) fs::remove_all(scratch, ignored);
  scratch_.clear();
}

AtomicFileGroup::~AtomicFileGroup() {
  std::error_code ignored;
  for (const auto& [folder, scratch] : scratch_) fs::remove_all(scratch, ignored);
}

}  // namespace angio
