#pragma once
// Running the `canopy` binary from a test, and the files it writes.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/text_file.h"

namespace canopy::cli_test {
namespace fs = std::filesystem;

/// Runs `canopy ARGUMENTS` with its output discarded; its exit code, or −1 if it did not exit.
inline int run(const std::string& arguments) {
  const int status =
      std::system((std::string(CANOPY_BINARY) + " " + arguments + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The file's text; a missing file throws, so it can never compare equal to another.
inline std::string slurp(const fs::path& path) {
  return readTextFile(path).value();
}

/// An empty temporary directory path for `name` (removed if present).
inline fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_cli_" + name);
  fs::remove_all(dir);
  return dir;
}

}  // namespace canopy::cli_test
