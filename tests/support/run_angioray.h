#pragma once
// Runs the `angioray` executable under test with arguments; captures stdout and stderr together.
#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace angio::test_support {

struct ProgramRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

inline ProgramRun runAngioray(const std::string& arguments) {
  const std::string command = std::string(ANGIORAY_BINARY) + " " + arguments + " 2>&1";
  ProgramRun run;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace angio::test_support
