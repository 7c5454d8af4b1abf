#include "io/slices_in_child.h"

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/input_error.h"

namespace angio {

namespace {

// What the child sends before each slice's voxels, or instead of them when decode threw.
struct FrameHeader {
  std::uint64_t nonFinite = 0;
  std::uint64_t errorBytes = 0;  // > 0: an error message of this many bytes follows, no voxels
};

bool writeAll(int fd, const void* data, std::size_t bytes) {
  const char* at = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t written = ::write(fd, at, bytes);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    at += written;
    bytes -= std::size_t(written);
  }
  return true;
}

// The child's whole life: decode every slice, send it, leave without running the parent's exit
// handlers or destructors (they belong to the parent's state, copied by fork).
[[noreturn]] void runChild(int fd, std::size_t count, std::size_t voxelsPerSlice,
                           const SliceDecode& decode) {
  // What the libraries print about a damaged stream (libjpeg's "Corrupt JPEG data", the failed
  // assertion) would surround the one line the parent reports: the child's stderr goes nowhere.
  if (const int nowhere = ::open("/dev/null", O_WRONLY); nowhere >= 0) ::dup2(nowhere, STDERR_FILENO);
  // A codec's failed assertion ends the child by SIGABRT, which the parent reports as the slice's
  // failure; a handler the process installed for its own aborts (a crash reporter, a fuzzer's
  // crash dump) has nothing to do with it.
  std::signal(SIGABRT, SIG_DFL);
  std::vector<Voxel> voxels(voxelsPerSlice);
  for (std::size_t k = 0; k < count; ++k) {
    FrameHeader header;
    std::string error;
    try {
      header.nonFinite = decode(int(k), voxels.data());
    } catch (const std::exception& problem) {
      error = problem.what();
    } catch (...) {
      error = "an unknown error";
    }
    header.errorBytes = error.size();
    if (!writeAll(fd, &header, sizeof header)) ::_exit(2);
    if (!error.empty()) ::_exit(writeAll(fd, error.data(), error.size()) ? 1 : 2);
    if (!writeAll(fd, voxels.data(), voxels.size() * sizeof(Voxel))) ::_exit(2);
  }
  ::_exit(0);
}

// The child process seen from the parent: killed and reaped however the parent leaves.
class Child {
 public:
  Child(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    ::close(fd_);
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      reap();
    }
  }
  // Reads exactly `bytes`; false when the child closed the pipe (it ended) or `timeoutMs` passed
  // without data (then `timedOut`).
  bool read(void* data, std::size_t bytes, int timeoutMs, bool& timedOut) {
    char* at = static_cast<char*>(data);
    while (bytes > 0) {
      pollfd ready{fd_, POLLIN, 0};
      const int polled = ::poll(&ready, 1, timeoutMs);
      if (polled < 0 && errno == EINTR) continue;
      if (polled == 0) timedOut = true;
      if (polled <= 0) return false;
      const ssize_t got = ::read(fd_, at, bytes);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return false;
      at += got;
      bytes -= std::size_t(got);
    }
    return true;
  }
  // How the child ended ("was killed by signal 6 (Aborted)", "exited with status 2").
  std::string ending() {
    const int status = reap();
    if (WIFSIGNALED(status))
      return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
             ::strsignal(WTERMSIG(status)) + ")";
    return "exited with status " + std::to_string(WEXITSTATUS(status));
  }

 private:
  int reap() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }
  pid_t pid_;
  int fd_;
};

// The user's part of an InputError's message about `folder` (after "FOLDER: ").
std::string problemPart(const std::filesystem::path& folder, const std::string& message) {
  const std::string prefix = folder.string() + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// "120", "0.3".
std::string seconds(int milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", milliseconds / 1000.0);
  return text;
}

}  // namespace

std::size_t decodeSlicesInChild(const std::filesystem::path& folder,
                                const std::vector<std::string>& files, std::size_t voxelsPerSlice,
                                const SliceDecode& decode, const SliceTake& take, int sliceTimeoutMs) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw InputError(folder, std::string("cannot start decoding its slices: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw InputError(folder, std::string("cannot start decoding its slices: ") + std::strerror(error));
  }
  if (pid == 0) {
    ::close(fds[0]);
    runChild(fds[1], files.size(), voxelsPerSlice, decode);
  }
  ::close(fds[1]);
  Child child(pid, fds[0]);
  std::vector<Voxel> voxels(voxelsPerSlice);
  std::size_t nonFinite = 0;
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string slice = "slice " + std::filesystem::path(files[k]).filename().string();
    bool timedOut = false;
    FrameHeader header;
    if (!child.read(&header, sizeof header, sliceTimeoutMs, timedOut)) {
      if (timedOut)
        throw InputError(folder, slice + ": decoding its compressed pixel data took over " +
                                     seconds(sliceTimeoutMs) + " s; stopped");
      throw InputError(folder, slice + ": its compressed pixel data cannot be decoded (the decoder " +
                                   child.ending() + ")");
    }
    if (header.errorBytes > 0) {
      std::string message(std::min<std::uint64_t>(header.errorBytes, 4096), '\0');
      if (!child.read(message.data(), message.size(), sliceTimeoutMs, timedOut))
        message = "cannot be decoded";
      throw InputError(folder, problemPart(folder, message));
    }
    if (!child.read(voxels.data(), voxels.size() * sizeof(Voxel), sliceTimeoutMs, timedOut))
      throw InputError(folder,
                       slice + ": its decoder stopped in the middle of it (it " + child.ending() + ")");
    nonFinite += header.nonFinite;
    take(int(k), voxels.data());
  }
  return nonFinite;
}

}  // namespace angio
