// `canopy view RUN_DIR [RUN_B [--overlay]] [--out FILE]`: the replay page of a finished run, or of
// two side by side (or RUN_B drawn over RUN_DIR) on one clock (replay/replay_page.h).
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "replay/replay_page.h"

namespace canopy::app {
namespace {

class View : public Command {
 public:
  explicit View(CLI::App& canopy)
      : Command(canopy, "view", "canopy view RUN_DIR [RUN_B [--overlay]] [--out FILE]",
                "Writes one self-contained replay.html of a finished run: plays it in any "
                "browser, offline, with the agents' beliefs, maps, plans and per-target "
                "timelines. With RUN_B, one page with both runs side by side on one clock; with "
                "--overlay, RUN_B drawn over RUN_DIR on one map.") {
    CLI::App& o = options();
    o.add_option("RUN_DIR", run_dir_, "the --out directory of `canopy run`");
    o.add_option("RUN_B", run_b_, "a second run, shown beside the first on one clock");
    o.add_flag("--overlay", overlay_, "draw RUN_B over RUN_DIR on one map instead of beside it");
    o.add_option("--out", out_, "where the page goes (- for the standard output)")
        ->type_name("FILE")
        ->default_str(
            "RUN_DIR/replay.html; with RUN_B RUN_DIR/side_by_side.html, overlaid "
            "RUN_DIR/overlay.html");
  }
  int run() override {
    if (run_dir_.empty())
      usageError("view", "expected RUN_DIR, the --out directory of `canopy run`");
    const bool two = !run_b_.empty();
    if (overlay_ && !two) usageError("view", "--overlay needs RUN_B, the run to draw over RUN_DIR");
    if (out_.empty())
      out_ = (std::filesystem::path(run_dir_) / (overlay_ ? "overlay.html"
                                                 : two    ? "side_by_side.html"
                                                          : "replay.html"))
                 .string();
    if (out_ == "-") {  // the page on stdout (main checks that it was all written)
      const std::string page = !two       ? replay::replayPage(replay::readRunFolder(run_dir_))
                               : overlay_ ? replay::overlayPage(replay::readRunFolder(run_dir_),
                                                                replay::readRunFolder(run_b_))
                                          : replay::sideBySidePage(replay::readRunFolder(run_dir_),
                                                                   replay::readRunFolder(run_b_));
      std::fwrite(page.data(), 1, page.size(), stdout);
      return kExitOk;
    }
    checkOutputFile(out_);  // a device, FIFO or directory is refused before the run is read
    const std::size_t bytes = !two       ? replay::writeReplay(run_dir_, out_)
                              : overlay_ ? replay::writeOverlay(run_dir_, run_b_, out_)
                                         : replay::writeSideBySide(run_dir_, run_b_, out_);
    std::printf("replay: %s (%.1f kB; open it in a browser, no server needed)\n",
                printable(out_, 300).c_str(), static_cast<double>(bytes) / 1000.0);
    return kExitOk;
  }

 private:
  std::string run_dir_, run_b_, out_;
  bool overlay_ = false;
};

}  // namespace

std::unique_ptr<Command> makeView(CLI::App& canopy) {
  return std::make_unique<View>(canopy);
}

}  // namespace canopy::app
