// AtomicFileGroup: files that appear together or not at all, and the user's earlier files kept
// whenever the group does not complete.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/volume_writer.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::fileBytes;

class AtomicFileGroupTest : public test_support::TempFolderTest {
 protected:
  AtomicFileGroup::Write bytes(const std::string& text) {
    return [text](const fs::path& file) { std::ofstream(file, std::ios::binary) << text; };
  }
};

TEST_F(AtomicFileGroupTest, CommitReplacesEveryTargetAndLeavesNothingElse) {
  write("a.png", "old a");
  {
    AtomicFileGroup files;
    files.add(dir_ / "a.png", bytes("new a"));
    files.add(dir_ / "a.png.json", bytes("new sidecar"));
    EXPECT_EQ(fileBytes(dir_ / "a.png"), "old a") << "nothing in place before commit";
    files.commit();
  }
  EXPECT_EQ(fileBytes(dir_ / "a.png"), "new a");
  EXPECT_EQ(fileBytes(dir_ / "a.png.json"), "new sidecar");
  EXPECT_EQ(filesInDir(), (std::vector<std::string>{"a.png", "a.png.json"}));
}

TEST_F(AtomicFileGroupTest, AFolderInTheWayStopsTheGroupBeforeAnythingIsReplaced) {
  write("a.png", "old a");
  fs::create_directory(dir_ / "a.png.json");
  AtomicFileGroup files;
  files.add(dir_ / "a.png", bytes("new a"));
  try {
    files.add(dir_ / "a.png.json", bytes("sidecar"));
    FAIL() << "a folder named like the sidecar was written over";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("a.png.json: is a folder"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(fileBytes(dir_ / "a.png"), "old a");
}

TEST_F(AtomicFileGroupTest, WithoutCommitNothingIsLeft) {
  {
    AtomicFileGroup files;
    files.add(dir_ / "a.png", bytes("a"));
    files.add(dir_ / "b.png", bytes("b"));
  }
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(AtomicFileGroupTest, AFailedMovePutsBackWhatWasReplaced) {
  write("a.png", "old a");
  write("b.png", "old b");
  AtomicFileGroup files;
  files.add(dir_ / "a.png", bytes("new a"));
  files.add(dir_ / "b.png", bytes("new b"));
  files.add(dir_ / "c.png", bytes("new c"));
  // A folder appears where the last target goes after its check: the commit's move fails there.
  fs::create_directory(dir_ / "c.png");
  EXPECT_THROW(files.commit(), InputError);
  EXPECT_EQ(fileBytes(dir_ / "a.png"), "old a");
  EXPECT_EQ(fileBytes(dir_ / "b.png"), "old b");
  EXPECT_TRUE(fs::is_directory(dir_ / "c.png"));
}

TEST_F(AtomicFileGroupTest, AWriterErrorNamesTheTargetNotTheScratchFile) {
  AtomicFileGroup files;
  try {
    files.add(dir_ / "a.png", [](const fs::path& file) { throw InputError(file, "disk full"); });
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), (dir_ / "a.png").string() + ": disk full");
  }
}

TEST_F(AtomicFileGroupTest, MissingFolderIsRefusedBeforeWriting) {
  AtomicFileGroup files;
  bool wrote = false;
  EXPECT_THROW(files.add(dir_ / "missing" / "c.csv", [&](const fs::path&) { wrote = true; }),
               InputError);
  EXPECT_FALSE(wrote);
  EXPECT_THROW(requireWritableTarget(dir_ / "missing" / "c.csv"), InputError);
}

TEST_F(AtomicFileGroupTest, DetachedHeaderArrivesWithItsDataFile) {
  Volume volume;
  volume.dims = {4, 3, 2};
  volume.voxels.assign(volume.voxelCount(), Voxel(1000));
  AtomicFileGroup files;
  files.add(dir_ / "v.mhd", [&](const fs::path& file) { writeVolume(volume, file); });
  files.commit();
  const std::vector<std::string> names = filesInDir();
  ASSERT_EQ(names.size(), 2u) << "the header and its data file, no scratch";
  EXPECT_EQ(names[0], "v.mhd");
  EXPECT_EQ(fs::path(names[1]).stem(), "v");
}

}  // namespace
}  // namespace angio
