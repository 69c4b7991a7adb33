#pragma once
// Assembling frames into a video with ffmpeg, when it is installed (it is optional).
#include <filesystem>
#include <string>

namespace canopy::render {

/// The first regular executable file called `name` in the ':'-separated directories of
/// `path_list` (the syntax of $PATH); empty when there is none.
std::filesystem::path findExecutable(const std::string& name, const std::string& path_list);

enum class VideoStatus { made, skipped, failed };

struct VideoResult {
  VideoStatus status = VideoStatus::skipped;
  std::string message;  // one line for the user: where the video is, or why there is none
};

/// Encodes frames_dir/frame_*.png, in name order, into `out` (MP4, yuv420p, sides padded to even)
/// at `fps` frames per second with the ffmpeg found on $PATH. Without ffmpeg the status is
/// `skipped` and the message says so plainly; a failing ffmpeg is `failed`, with its exit code.
VideoResult assembleVideo(const std::filesystem::path& frames_dir, const std::filesystem::path& out,
                          double fps);

}  // namespace canopy::render
