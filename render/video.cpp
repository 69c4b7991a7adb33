#include "render/video.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

#include "core/output_file.h"

extern char** environ;

namespace canopy::render {
namespace {

// ffmpeg expands the pattern with glob(3): escape the directory's own wildcard characters.
std::string globEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '*' || c == '?' || c == '[' || c == ']' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::filesystem::path findExecutable(const std::string& name, const std::string& path_list) {
  std::stringstream dirs(path_list);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;  // an empty entry would mean the working directory: not searched
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return {};
}

VideoResult assembleVideo(const std::filesystem::path& frames_dir, const std::filesystem::path& out,
                          double fps) {
  const char* path = std::getenv("PATH");
  const std::filesystem::path ffmpeg = findExecutable("ffmpeg", path ? path : "");
  if (ffmpeg.empty()) {
    return {VideoStatus::skipped,
            "video skipped: ffmpeg is not on PATH (the frames are in " + frames_dir.string() + ")"};
  }
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  // ffmpeg writes into a temporary we have just created (never a link planted at `out`), which
  // becomes `out` only once it exits successfully; the format is named, as the name is not .mp4.
  std::optional<AtomicFile> video;
  try {
    video.emplace(out);
  } catch (const WriteError& e) {
    return {VideoStatus::failed, std::string("video failed: ") + e.what()};
  }
  const std::string pattern = globEscaped((frames_dir / "frame_").string()) + "*.png";
  std::vector<std::string> args = {ffmpeg.string(),
                                   "-nostdin",
                                   "-y",
                                   "-loglevel",
                                   "error",
                                   "-framerate",
                                   rate,
                                   "-pattern_type",
                                   "glob",
                                   "-i",
                                   pattern,
                                   "-vf",
                                   "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                   "-pix_fmt",
                                   "yuv420p",
                                   "-f",
                                   "mp4",
                                   video->temporary().string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  if (posix_spawn(&pid, ffmpeg.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
    return {VideoStatus::failed, "video failed: cannot start " + ffmpeg.string()};
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return {VideoStatus::failed,
            "video failed: " + ffmpeg.string() + " exited with code " + std::to_string(code)};
  }
  try {
    video->commit();
  } catch (const WriteError& e) {
    return {VideoStatus::failed, std::string("video failed: ") + e.what()};
  }
  return {VideoStatus::made, "video: " + out.string()};
}

}  // namespace canopy::render
