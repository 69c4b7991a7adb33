// ffmpeg is optional: without it the video is skipped and says so; with it, it gets the frames.
#include "render/video.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace canopy::render {
namespace {

namespace fs = std::filesystem;

// Sets $PATH for the life of the object.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) {
    if (const char* old = std::getenv("PATH")) old_ = old;
    ::setenv("PATH", path.c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", old_.c_str(), 1); }

 private:
  std::string old_;
};

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_video_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeExecutable(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  ::chmod(path.c_str(), 0755);
}

TEST(Video, FindsOnlyExecutablesOnThePath) {
  const fs::path a = scratch("find_a"), b = scratch("find_b");
  std::ofstream(a / "ffmpeg") << "not executable";
  writeExecutable(b / "ffmpeg", "#!/bin/sh\n");
  EXPECT_EQ(findExecutable("ffmpeg", a.string() + ":" + b.string()), b / "ffmpeg");
  EXPECT_TRUE(findExecutable("ffmpeg", a.string()).empty());
  EXPECT_TRUE(findExecutable("ffmpeg", "").empty());
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(Video, IsSkippedPlainlyWithoutFfmpeg) {
  const fs::path empty = scratch("empty");
  const ScopedPath path(empty.string());
  const VideoResult result = assembleVideo(empty, empty / "frames.mp4", 5.0);
  EXPECT_EQ(result.status, VideoStatus::skipped);
  EXPECT_NE(result.message.find("skipped"), std::string::npos);
  EXPECT_NE(result.message.find("ffmpeg is not on PATH"), std::string::npos);
  EXPECT_FALSE(fs::exists(empty / "frames.mp4"));
  fs::remove_all(empty);
}

TEST(Video, GivesFfmpegTheFramesInOrderAtTheRate) {
  const fs::path bin = scratch("bin"), frames = scratch("frames");
  // A stand-in that records its arguments and writes the output file (its last argument).
  writeExecutable(bin / "ffmpeg", "#!/bin/sh\nfor a in \"$@\"; do echo \"$a\"; done > \"" +
                                      (bin / "args").string() +
                                      "\"\nfor a; do last=$a; done\n: > \"$last\"\n");
  const ScopedPath path(bin.string());
  const VideoResult result = assembleVideo(frames, frames / "run.mp4", 2.5);
  EXPECT_EQ(result.status, VideoStatus::made) << result.message;
  EXPECT_TRUE(fs::exists(frames / "run.mp4"));
  std::stringstream args;
  args << std::ifstream(bin / "args").rdbuf();
  EXPECT_NE(args.str().find("-framerate\n2.5\n"), std::string::npos) << args.str();
  EXPECT_NE(args.str().find("-pattern_type\nglob\n-i\n" + (frames / "frame_").string() + "*.png\n"),
            std::string::npos)
      << args.str();

  writeExecutable(bin / "ffmpeg", "#!/bin/sh\nexit 3\n");
  const VideoResult failed = assembleVideo(frames, frames / "run.mp4", 2.5);
  EXPECT_EQ(failed.status, VideoStatus::failed);
  EXPECT_NE(failed.message.find("code 3"), std::string::npos);
  fs::remove_all(bin);
  fs::remove_all(frames);
}

}  // namespace
}  // namespace canopy::render
