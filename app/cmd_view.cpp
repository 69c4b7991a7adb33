// `canopy view RUN_DIR [--out FILE]`: the replay page of a finished run (replay/replay_page.h).
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "app/help.h"
#include "core/printable.h"
#include "replay/replay_page.h"

namespace canopy::app {

int viewCommand(Args& args) {
  std::string run_dir, out;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--out") {
      out = args.value(arg);
    } else if (!arg.empty() && arg[0] == '-') {
      unknownOption("view", arg);
    } else if (run_dir.empty()) {
      run_dir = arg;
    } else {
      usageError(arg, "expected one run directory, got a second one");
    }
  }
  if (run_dir.empty()) usageError("view", "expected RUN_DIR, the --out directory of `canopy run`");
  if (out.empty()) out = (std::filesystem::path(run_dir) / "replay.html").string();
  const std::size_t bytes = replay::writeReplay(run_dir, out);
  std::printf("replay: %s (%.1f kB; open it in a browser, no server needed)\n",
              printable(out, 300).c_str(), static_cast<double>(bytes) / 1000.0);
  return kExitOk;
}

}  // namespace canopy::app
