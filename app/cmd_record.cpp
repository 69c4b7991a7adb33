// `canopy record RUN_DIR [--steps A:B] [--agent I]`: a run's record as JSON lines on stdout, the
// bytes `--record jsonl` writes, from either form (sim/record_lines.h). With --steps only those
// steps are decoded (the compact form's index); with --agent each line keeps only that agent's
// entry of "agents" and "scans" (sim/record_slice.h).
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "app/commands.h"
#include "sim/record_lines.h"
#include "sim/record_slice.h"
#include "spec/error.h"

namespace canopy::app {
namespace {

class Record : public Command {
 public:
  explicit Record(CLI::App& canopy)
      : Command(canopy, "record", "canopy record RUN_DIR [--steps A:B] [--agent I]",
                "Prints a finished run's record as JSON lines, one per step, byte for byte the "
                "lines of `canopy run --record jsonl`, from record.jsonl or the compact "
                "record.jsonl.zst (for jq, pandas and scripts).") {
    CLI::App& o = options();
    o.add_option("RUN_DIR", run_dir_, "the --out directory of `canopy run`");
    addValue(o, "--steps", "A:B", steps_, stepRange(),
             "steps A to B − 1 only (the compact record decodes only their blocks)")
        ->default_str("every step");
    addValue(o, "--agent", "I", agent_, integerIn(0, std::numeric_limits<int>::max()),
             "each line's \"agents\" and \"scans\" hold only agent I's entry")
        ->default_str("every agent");
  }

  int run() override {
    if (run_dir_.empty())
      usageError("record", "expected RUN_DIR, the --out directory of `canopy run`");
    std::error_code error;
    if (!std::filesystem::is_directory(run_dir_, error)) {
      throw spec::ScenarioError(run_dir_, "",
                                "no such directory (expected the --out directory of `canopy run`)");
    }
    const std::filesystem::path path = sim::recordFileOf(run_dir_);
    sim::forEachRecordLine(path, steps_, [&](const std::string& line, int number) {
      if (!agent_) {
        std::fwrite(line.data(), 1, line.size(), stdout);
      } else {
        const std::optional<std::string> slice =
            sim::agentSlice(line, static_cast<std::size_t>(*agent_));
        if (!slice) {
          throw spec::ScenarioError(path.string(), "line " + std::to_string(number),
                                    "expected \"agents\" and \"scans\" lists with an entry " +
                                        std::to_string(*agent_) + " (--agent)");
        }
        std::fwrite(slice->data(), 1, slice->size(), stdout);
      }
      std::fputc('\n', stdout);
    });
    return kExitOk;
  }

 private:
  std::string run_dir_;
  sim::LineRange steps_;
  std::optional<int> agent_;
};

}  // namespace

std::unique_ptr<Command> makeRecord(CLI::App& canopy) {
  return std::make_unique<Record>(canopy);
}

}  // namespace canopy::app
