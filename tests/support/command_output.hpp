#pragma once
// Test helper: run a shell command and keep what it printed and its exit code.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace antipode::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout and stderr
};

/// Runs `command` through the shell with stderr joined to stdout.
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) result.out += buffer;
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace antipode::testing
