#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>

#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/frame_writer.h"
#include "render/video.h"
#include "replay/replay_page.h"
#include "sim/run.h"
#include "sim/run_report.h"
#include "sim/simulation.h"
#include "spec/budget.h"
#include "spec/loader.h"

namespace canopy::app {
namespace {

std::string getenvOr(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value ? value : fallback;
}

}  // namespace

CLI::Option* addImageSize(CLI::App& command, std::optional<render::ImageSize>& size,
                          const std::string& meaning) {
  const Reader<render::ImageSize> image_size{
      [](const std::string& text) { return render::parseImageSize(text); },
      "WxH with both sides in [" + std::to_string(render::kMinImageSide) + ", " +
          std::to_string(render::kMaxImageSide) + "] px (e.g. 800x600)"};
  return addValue(command, "--size", "WxH", size, image_size, meaning);
}

namespace {

class Run : public Command {
 public:
  Run(CLI::App& canopy, std::string command_line)
      : Command(canopy, "run", "canopy run [SCENARIO] [options]",
                "Runs a scenario (a path or a built-in name; default demo) and writes "
                "manifest.json, record.jsonl (or record.jsonl.zst), timings.jsonl and summary.json; prints a short "
                "table of the outcome."),
        command_line_(std::move(command_line)) {
    CLI::App& o = options();
    o.add_option("SCENARIO", scenario_, "a path or a built-in name");
    addOutputDir(o, "--out", out_dir_, "where the run's files go")
        ->default_str("out/NAME (the scenario's name)");
    addValue(o, "--seed", "N", load_.seed, nonNegativeInteger(), "the seed of every random stream")
        ->default_str("the scenario's seed");
    o.add_option("--set", load_.overrides, "override a field by its dotted path (repeatable)")
        ->type_name("PATH=VALUE")
        ->default_str("none")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    addValue(o, "--threads", "N", threads_, integerIn(1, sim::Simulation::kMaxThreads),
             "threads that sense, track and plan the agents of each step side by side (the "
             "same record.jsonl as one thread)")
        ->default_str("1");
    o.add_flag("--json", json_, "print summary.json on stdout instead of the short table");
    o.add_flag("--frames", frames_, "write DIR/frames/frame_NNNNNN.png (or .svg, .pdf: --format)");
    addValue(o, "--format,--frame-format", "png|svg|pdf", format_,
             Reader<render::FrameFormat>{
                 [](const std::string& text) -> std::optional<render::FrameFormat> {
                   if (text == "png") return render::FrameFormat::png;
                   if (text == "svg") return render::FrameFormat::svg;
                   if (text == "pdf") return render::FrameFormat::pdf;
                   return std::nullopt;
                 },
                 "png, svg or pdf"},
             "what a frame is written as: a PNG, or the same drawing as an SVG or PDF document "
             "(vector, for a paper; drawn by cairo, no GL)")
        ->default_str("png");
    addValue(o, "--frame-every", "K", every_, integerIn(1, 1000000), "a frame every K steps")
        ->default_str("1");
    addImageSize(o, size_, "frame size")->default_str("800 px along the view's longer side");
    addValue(o, "--view", "aoi|action|x0,y0,x1,y1", view_,
             Reader<std::string>{[](const std::string& text) -> std::optional<std::string> {
                                   if (!render::isViewText(text)) return std::nullopt;
                                   return text;
                                 },
                                 "aoi, action or x0,y0,x1,y1 (m) with x1 > x0 and y1 > y0"},
             "what every frame shows: the AOI, the padded box of everything that moves, or a "
             "box (m)")
        ->default_str("action");
    o.add_flag("--video", video_, "also assemble DIR/frames.mp4 with ffmpeg (Debian ffmpeg)");
    addValue(o, "--fps", "F", fps_,
             finiteNumber("frames per second in (0, 1000]",
                          [](double f) { return f > 0.0 && f <= 1000.0; }),
             "frames per second of the video")
        ->default_str("real time, 1/(dt·K)");
    o.add_flag("--html", html_, "also write DIR/replay.html (as `canopy view DIR`)");
    addValue(o, "--record", "auto|jsonl|compact", record_,
             Reader<sim::RecordFormat>{
                 [](const std::string& text) -> std::optional<sim::RecordFormat> {
                   if (text == "auto") return sim::RecordFormat::automatic;
                   if (text == "jsonl") return sim::RecordFormat::jsonl;
                   if (text == "compact") return sim::RecordFormat::compact;
                   return std::nullopt;
                 },
                 "auto, jsonl or compact"},
             "record.jsonl (JSON lines), record.jsonl.zst (the same lines in zstd frames with a "
             "step index; `canopy record DIR` prints them), or auto: compact when the record is "
             "estimated above 64 MB")
        ->default_str("auto");
    addLoadOptions(o, load_);
  }

  int run() override;

 private:
  std::string command_line_;
  std::string scenario_ = kDefaultScenario;
  std::string out_dir_;
  spec::LoadOptions load_;
  bool frames_ = false, video_ = false, json_ = false, html_ = false;
  std::optional<int> every_;
  std::optional<int> threads_;
  std::optional<double> fps_;
  std::optional<std::string> view_;
  std::optional<render::ImageSize> size_;
  std::optional<render::FrameFormat> format_;
  sim::RecordFormat record_ = sim::RecordFormat::automatic;
};

int Run::run() {
  const bool frames = frames_ || video_;  // a video is made of frames
  if (!frames && every_) usageError("--frame-every", "only applies with --frames or --video");
  if (!frames && size_) usageError("--size", "only applies with --frames or --video");
  if (!video_ && fps_) usageError("--fps", "only applies with --video");
  if (!frames && view_) usageError("--view", "only applies with --frames or --video");
  if (!frames && format_) usageError("--format", "only applies with --frames");
  if (video_ && format_.value_or(render::FrameFormat::png) != render::FrameFormat::png)
    usageError("--format", "a video is made of PNG frames: --format png (the default) with --video");
  // A video that cannot be made is known before anything runs.
  if (video_ && render::findExecutable("ffmpeg", getenvOr("PATH", "")).empty()) {
    std::fprintf(stderr,
                 "canopy: --video: ffmpeg is not on PATH; install the Debian package ffmpeg "
                 "(apt-get install ffmpeg), or run with --frames only\n");
    return kExitFailure;
  }
  const spec::ScenarioSpec spec = spec::loadScenario(scenario_, load_);
  // The budget sized the record `--record auto` writes; plain lines asked for are sized here.
  if (record_ == sim::RecordFormat::jsonl) {
    const double bytes = spec::estimateWork(spec).record_bytes;
    const double limit = spec::workLimits(load_.budget_scale).record_bytes;
    if (bytes > limit) {
      usageError("--record",
                 "jsonl: " + spec::budgetMessage(bytes, limit, "bytes of record.jsonl") +
                     "; the compact record (--record compact or auto) is smaller");
    }
  }
  if (out_dir_.empty()) {
    // The scenario's name is the file's text: one safe component, so it stays under out/.
    out_dir_ = "out/" + safeFileName(spec.name);
    checkOutputDir(out_dir_, "--out (default, from the scenario's name)");
  }

  sim::checkRunOutputs(out_dir_);  // a device or FIFO where a file goes: refused before any work
  sim::RunOptions options;
  options.out_dir = out_dir_;
  options.command_line = command_line_;
  options.threads = threads_.value_or(1);
  options.record = record_;
  // Without --frames nothing of the renderer is made, so no GL context is ever created.
  std::optional<render::FrameWriter> writer;
  std::optional<render::FrameObserver> frame_observer;
  if (frames) {
    render::FrameOptions frame_options;
    frame_options.dir = options.out_dir / "frames";
    frame_options.every = every_.value_or(1);
    frame_options.size = size_.value_or(render::ImageSize{});
    frame_options.format = format_.value_or(render::FrameFormat::png);
    writer.emplace(render::sceneModel(spec, render::viewFor(view_.value_or("action"), spec)),
                   frame_options);
    frame_observer.emplace(*writer);
    options.observers.push_back(&*frame_observer);
  }
  const sim::RunResult result = sim::runScenario(spec, options);
  for (const std::string& warning : sim::runWarnings(result.summary_json))
    std::fprintf(stderr, "canopy: warning: %s\n", printable(warning).c_str());
  if (json_) {
    // JSON escapes C0 controls but passes DEL and C1 in names through: printed line by line.
    std::stringstream summary(result.summary_json);
    for (std::string line; std::getline(summary, line);)
      std::printf("%s\n", printable(line).c_str());
  } else {
    std::printf("%s: %d steps in %.3f s → %s/ (manifest.json, %s, timings.jsonl, summary.json)\n%s",
                printable(spec.name, 200).c_str(), result.steps, result.wall_seconds,
                printable(out_dir_).c_str(),
                sim::resolveRecordFormat(record_, spec) == sim::RecordFormat::compact
                    ? sim::kRecordCompactName
                    : sim::kRecordJsonlName,
                sim::runTable(result.summary_json).c_str());
  }
  if (html_) {
    const std::filesystem::path page = options.out_dir / "replay.html";
    const std::size_t bytes = replay::writeReplay(options.out_dir, page);
    std::fprintf(json_ ? stderr : stdout, "replay: %s (%.1f kB)\n",
                 printable(page.string()).c_str(), static_cast<double>(bytes) / 1000.0);
  }
  if (!writer) return kExitOk;

  std::fprintf(json_ ? stderr : stdout,
               "frames: %d of %dx%d px, every %d steps → %s/frame_NNNNNN.%s\n",
               writer->framesWritten(), writer->size().width, writer->size().height,
               every_.value_or(1), printable(writer->dir().string()).c_str(),
               render::frameExtension(format_.value_or(render::FrameFormat::png)));
  if (!video_) return kExitOk;
  const double rate = fps_.value_or(1.0 / (spec.dt * every_.value_or(1)));  // default: real time
  const render::VideoResult made =
      render::assembleVideo(writer->dir(), options.out_dir / "frames.mp4", rate);
  std::fprintf(made.status == render::VideoStatus::made && !json_ ? stdout : stderr, "%s\n",
               printable(made.message).c_str());
  return made.status == render::VideoStatus::made ? kExitOk : kExitFailure;
}

}  // namespace

std::unique_ptr<Command> makeRun(CLI::App& canopy, const std::string& command_line) {
  return std::make_unique<Run>(canopy, command_line);
}

}  // namespace canopy::app
