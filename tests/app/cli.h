#pragma once
// Running the `canopy` binary from a test, and the files it writes.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
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

struct Outcome {
  int code = -1;  // the exit code, or −1 if it did not exit
  std::string out, err;
};

/// Runs `canopy ARGUMENTS` through /bin/sh in the working directory `dir` (made if missing), its
/// stdout and stderr captured outside `dir` (stdout sent to `stdout_to` instead if given, e.g.
/// /dev/full). With `max_file_bytes`, files the
/// process writes are limited to that size (RLIMIT_FSIZE) and SIGXFSZ is ignored, so a write past
/// it fails with EFBIG as on a full disk, without root.
inline Outcome runIn(const fs::path& dir, const std::string& arguments,
                     std::optional<rlim_t> max_file_bytes = std::nullopt,
                     const std::string& stdout_to = "") {
  fs::create_directories(dir);
  static int runs = 0;
  const std::string capture =
      (fs::temp_directory_path() /
       ("canopy_cli_capture_" + std::to_string(::getpid()) + "_" + std::to_string(runs++)))
          .string();
  const fs::path out = stdout_to.empty() ? fs::path(capture + ".out") : fs::path(stdout_to);
  const fs::path err = capture + ".err";
  const std::string command = "cd '" + dir.string() + "' && exec '" + CANOPY_BINARY + "' " +
                              arguments + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (max_file_bytes) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{*max_file_bytes, *max_file_bytes};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return {};
  Outcome outcome;
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (stdout_to.empty()) outcome.out = readTextFile(out).value_or("");
  outcome.err = readTextFile(err).value_or("");
  std::error_code ignored;
  if (stdout_to.empty()) fs::remove(out, ignored);
  fs::remove(err, ignored);
  return outcome;
}

/// The file's text; a missing file throws, so it can never compare equal to another.
inline std::string slurp(const fs::path& path) {
  return readTextFile(path).value();
}

/// An empty temporary directory path for `name` (removed if present), of this process: two test
/// suites running at once (two checkouts on one machine) never share one.
inline fs::path fresh(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

}  // namespace canopy::cli_test
