// Decoding slices in a child process (io/slices_in_child.h): what the parent receives equals what
// the child decoded; a decoder that throws, dies by a signal or hangs fails the load with the
// slice's name; the parent survives, and no child is left behind whatever the parent does.
#include "io/slices_in_child.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "io/input_error.h"

namespace angio {
namespace {

const std::filesystem::path kFolder = "/data/series";
const std::vector<std::string> kFiles = {"/data/series/a.dcm", "/data/series/b.dcm",
                                         "/data/series/c.dcm"};

// The message of the InputError decoding kFiles with `decode` throws ("" if none).
std::string failure(const SliceDecode& decode, int timeoutMs = 120000) {
  try {
    decodeSlicesInChild(
        kFolder, kFiles, 4, decode, [](int, const Voxel*) {}, timeoutMs);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// True if this process has no child left (running or a zombie).
bool noChildLeft() {
  int status = 0;
  return ::waitpid(-1, &status, WNOHANG) == -1 && errno == ECHILD;
}

TEST(SlicesInChild, TheParentReceivesEachSliceInOrderWithTheNonFiniteCounts) {
  std::vector<std::vector<Voxel>> received;
  const std::size_t nonFinite = decodeSlicesInChild(
      kFolder, kFiles, 5,
      [](int k, Voxel* out) {
        for (int n = 0; n < 5; ++n) out[n] = Voxel(1000 * k + n);
        return std::size_t(k);
      },
      [&](int k, const Voxel* voxels) {
        EXPECT_EQ(k, int(received.size()));
        received.emplace_back(voxels, voxels + 5);
      });
  EXPECT_EQ(nonFinite, 0u + 1u + 2u);
  ASSERT_EQ(received.size(), 3u);
  for (int k = 0; k < 3; ++k)
    for (int n = 0; n < 5; ++n) EXPECT_EQ(received[k][n], Voxel(1000 * k + n));
  EXPECT_TRUE(noChildLeft());
}

TEST(SlicesInChild, ADecoderThatThrowsGivesItsMessage) {
  const std::string message = failure([](int k, Voxel*) -> std::size_t {
    if (k == 1) throw InputError(kFolder, "slice b.dcm is not greyscale; need CT slices");
    return 0;
  });
  EXPECT_EQ(message, "/data/series: slice b.dcm is not greyscale; need CT slices");
  EXPECT_TRUE(noChildLeft());
}

TEST(SlicesInChild, ADecoderThatAbortsFailsTheLoadNamingTheSlice) {
  const std::string message = failure([](int k, Voxel*) -> std::size_t {
    if (k == 2) std::abort();  // as GDCM's failed assertions do
    return 0;
  });
  EXPECT_EQ(message,
            "/data/series: slice c.dcm: its compressed pixel data cannot be decoded (the decoder was "
            "killed by signal 6 (Aborted))");
  EXPECT_TRUE(noChildLeft());
}

TEST(SlicesInChild, ADecoderThatHangsIsKilledAfterTheTimeout) {
  const std::string message = failure(
      [](int k, Voxel*) -> std::size_t {
        while (k == 0) ::pause();
        return 0;
      },
      300);
  EXPECT_EQ(message,
            "/data/series: slice a.dcm: decoding its compressed pixel data took over 0.3 s; stopped");
  EXPECT_TRUE(noChildLeft());
}

TEST(SlicesInChild, AParentThatStopsTakingLeavesNoChildBehind) {
  struct Cancelled {};
  EXPECT_THROW(decodeSlicesInChild(
                   kFolder, kFiles, 4, [](int, Voxel*) { return std::size_t(0); },
                   [](int k, const Voxel*) {
                     if (k == 1) throw Cancelled{};
                   }),
               Cancelled);
  EXPECT_TRUE(noChildLeft());
}

}  // namespace
}  // namespace angio
