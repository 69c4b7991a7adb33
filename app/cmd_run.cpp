#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>

#include "app/commands.h"
#include "app/help.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/frame_writer.h"
#include "render/video.h"
#include "replay/replay_page.h"
#include "sim/run.h"
#include "sim/run_report.h"
#include "spec/loader.h"

namespace canopy::app {
namespace {

std::string getenvOr(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value ? value : fallback;
}

}  // namespace

render::ImageSize imageSizeValue(Args& args, const std::string& name) {
  const std::string text = args.value(name);
  const std::optional<render::ImageSize> size = render::parseImageSize(text);
  if (!size) {
    usageError(name, "expected WxH with both sides in [" + std::to_string(render::kMinImageSide) +
                         ", " + std::to_string(render::kMaxImageSide) +
                         "] px (e.g. 800x600), got '" + text + "'");
  }
  return *size;
}

int runCommand(Args& args) {
  std::string scenario;
  std::string out_dir;
  spec::LoadOptions load;
  bool frames = false, video = false, json = false, html = false;
  std::optional<int> every;
  std::optional<double> fps;
  std::optional<std::string> view;
  std::optional<render::ImageSize> size;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out_dir = args.outputDirValue(arg);
    } else if (arg == "--seed") {
      load.seed = args.unsignedValue(arg);
    } else if (arg == "--set") {
      load.overrides.push_back(args.value(arg));
    } else if (takeLoadOption(args, arg, load)) {
    } else if (arg == "--frames") {
      frames = true;
    } else if (arg == "--frame-every") {
      every = args.intValue(arg, 1, 1000000);
    } else if (arg == "--size") {
      size = imageSizeValue(args, arg);
    } else if (arg == "--video") {
      video = frames = true;  // a video is made of frames
    } else if (arg == "--fps") {
      fps = args.doubleValue(arg);
      if (!(*fps > 0.0) || *fps > 1000.0)
        usageError(arg, "expected frames per second in (0, 1000]");
    } else if (arg == "--view") {
      view = args.value(arg);
    } else if (arg == "--json") {
      json = true;
    } else if (arg == "--html") {
      html = true;
    } else if (!arg.empty() && arg[0] == '-') {
      unknownOption("run", arg);
    } else if (scenario.empty()) {
      scenario = arg;
    } else {
      usageError(arg, "expected one scenario, got a second one");
    }
  }
  if (!frames && every) usageError("--frame-every", "only applies with --frames or --video");
  if (!frames && size) usageError("--size", "only applies with --frames or --video");
  if (!video && fps) usageError("--fps", "only applies with --video");
  if (!frames && view) usageError("--view", "only applies with --frames or --video");
  // A video that cannot be made is known before anything runs.
  if (video && render::findExecutable("ffmpeg", getenvOr("PATH", "")).empty()) {
    std::fprintf(stderr,
                 "canopy: --video: ffmpeg is not on PATH; install the Debian package ffmpeg "
                 "(apt-get install ffmpeg), or run with --frames only\n");
    return kExitFailure;
  }
  if (scenario.empty()) scenario = kDefaultScenario;
  const spec::ScenarioSpec spec = spec::loadScenario(scenario, load);
  if (out_dir.empty()) {
    // The scenario's name is the file's text: one safe component, so it stays under out/.
    out_dir = "out/" + safeFileName(spec.name);
    checkOutputDir(out_dir, "--out (default, from the scenario's name)");
  }

  sim::RunOptions options;
  options.out_dir = out_dir;
  options.command_line = args.joined();
  // Without --frames nothing of the renderer is made, so no GL context is ever created.
  std::optional<render::FrameWriter> writer;
  std::optional<render::FrameObserver> frame_observer;
  if (frames) {
    render::FrameOptions frame_options;
    frame_options.dir = options.out_dir / "frames";
    frame_options.every = every.value_or(1);
    frame_options.size = size.value_or(render::ImageSize{});
    writer.emplace(render::sceneModel(spec, render::viewFor(view.value_or("action"), spec)),
                   frame_options);
    frame_observer.emplace(*writer);
    options.observers.push_back(&*frame_observer);
  }
  const sim::RunResult result = sim::runScenario(spec, options);
  for (const std::string& warning : sim::runWarnings(result.summary_json))
    std::fprintf(stderr, "canopy: warning: %s\n", printable(warning).c_str());
  if (json) {
    // JSON escapes C0 controls but passes DEL and C1 in names through: printed line by line.
    std::stringstream summary(result.summary_json);
    for (std::string line; std::getline(summary, line);)
      std::printf("%s\n", printable(line).c_str());
  } else {
    std::printf(
        "%s: %d steps in %.3f s → %s/ (manifest.json, record.jsonl, timings.jsonl, "
        "summary.json)\n%s",
        printable(spec.name, 200).c_str(), result.steps, result.wall_seconds,
        printable(out_dir).c_str(), sim::runTable(result.summary_json).c_str());
  }
  if (html) {
    const std::filesystem::path page = options.out_dir / "replay.html";
    const std::size_t bytes = replay::writeReplay(options.out_dir, page);
    std::fprintf(json ? stderr : stdout, "replay: %s (%.1f kB)\n", printable(page.string()).c_str(),
                 static_cast<double>(bytes) / 1000.0);
  }
  if (!writer) return kExitOk;

  std::fprintf(json ? stderr : stdout,
               "frames: %d of %dx%d px, every %d steps → %s/frame_NNNNNN.png\n",
               writer->framesWritten(), writer->size().width, writer->size().height,
               every.value_or(1), printable(writer->dir().string()).c_str());
  if (!video) return kExitOk;
  const double rate = fps.value_or(1.0 / (spec.dt * every.value_or(1)));  // default: real time
  const render::VideoResult made =
      render::assembleVideo(writer->dir(), options.out_dir / "frames.mp4", rate);
  std::fprintf(made.status == render::VideoStatus::made && !json ? stdout : stderr, "%s\n",
               printable(made.message).c_str());
  return made.status == render::VideoStatus::made ? kExitOk : kExitFailure;
}

}  // namespace canopy::app
