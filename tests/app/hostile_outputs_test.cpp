// Hostile input, third pass (issue 47), through the real command line. An output path is ours or
// it is refused: a FIFO or a device node where a command would write its file is refused with
// exit 2 before any work and left as it was (the page is never renamed over /dev/null). Result
// files read back: a step index or target index past 32 bits is refused naming the line, not
// wrapped; a record line whose document cannot fit in memory exits 1 with "out of memory"
// instead of aborting.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/text_file.h"

namespace {
namespace fs = std::filesystem;

struct Outcome {
  int code = -1;       // exit code, −1 when killed by a signal (an abort)
  std::string output;  // stdout and stderr together
};

// `canopy ARGUMENTS` in bash under `limits` (ulimit and timeout), output captured.
Outcome canopy(const std::string& arguments,
               const std::string& limits = "exec timeout -s KILL 120 ") {
  const std::string command = "bash -c '" + limits + CANOPY_BINARY + " " + arguments + "' 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

// Every folder scratch() made, removed when the tests end (the run and the sweep are shared).
std::vector<fs::path>& made() {
  static std::vector<fs::path> folders;
  return folders;
}
class RemoveScratch : public testing::Environment {
 public:
  void TearDown() override {
    std::error_code ignored;
    for (const fs::path& dir : made()) fs::remove_all(dir, ignored);
  }
};
const testing::Environment* const kRemoveScratch =
    testing::AddGlobalTestEnvironment(new RemoveScratch);

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_hostile3_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  made().push_back(dir);
  return dir;
}

// One finished demo run, made once per process.
const fs::path& finishedRun() {
  static const fs::path run = [] {
    const fs::path dir = scratch("run") / "run";
    const Outcome made = canopy("run demo --set clock.duration=2 --out " + dir.string());
    EXPECT_EQ(made.code, 0) << made.output;
    return dir;
  }();
  return run;
}

// One finished sweep of one demo trial, made once per process.
const fs::path& finishedSweep() {
  static const fs::path sweep = [] {
    const fs::path dir = scratch("sweep");
    std::ofstream(dir / "sweep.json")
        << R"({"name": "s", "scenario": "demo", "trials": 1, "set": {"clock.duration": 1}})";
    const Outcome made =
        canopy("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string());
    EXPECT_EQ(made.code, 0) << made.output;
    return dir / "out";
  }();
  return sweep;
}

// What a node is, to compare before and after: its type, and for a device its numbers.
std::string identity(const fs::path& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) return "missing";
  return std::to_string(info.st_mode & S_IFMT) + ":" + std::to_string(major(info.st_rdev)) + "," +
         std::to_string(minor(info.st_rdev)) + ":" + std::to_string(info.st_ino);
}

bool temporariesBeside(const fs::path& path) {
  for (const auto& entry : fs::directory_iterator(path.parent_path()))
    if (entry.path().extension() == ".tmp") return true;
  return false;
}

// A node where a command writes: a FIFO always, a character device (1, 3: the system's
// /dev/null) where mknod is permitted (root; otherwise skipped).
struct Node {
  std::string kind;  // the words of the refusal
  std::function<bool(const fs::path&)> make;
};
const std::vector<Node>& nodes() {
  static const std::vector<Node> all = {
      {"a FIFO", [](const fs::path& p) { return ::mkfifo(p.c_str(), 0600) == 0; }},
      {"a character device",
       [](const fs::path& p) { return ::mknod(p.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0; }},
  };
  return all;
}

// Each writing command with `target` (a path inside `dir`) where one of its files goes.
struct Writer {
  std::string name;
  std::string file;  // the output, relative to the command's folder
  std::function<std::string(const fs::path& dir)> arguments;
};
const std::vector<Writer>& writers() {
  static const std::vector<Writer> all = {
      {"view_out", "page.html",
       [](const fs::path& dir) {
         return "view " + finishedRun().string() + " --out " + (dir / "page.html").string();
       }},
      {"run_record", "record.jsonl",
       [](const fs::path& dir) { return "run demo --set clock.duration=1 --out " + dir.string(); }},
      {"run_summary", "summary.json",
       [](const fs::path& dir) { return "run demo --set clock.duration=1 --out " + dir.string(); }},
      {"run_html", "replay.html",
       [](const fs::path& dir) {
         return "run demo --set clock.duration=1 --html --out " + dir.string();
       }},
      {"sweep_summary", "summary.json",
       [](const fs::path& dir) {
         std::ofstream(dir.parent_path() / "sweep.json")
             << R"({"name": "s", "scenario": "demo", "trials": 1, "set": {"clock.duration": 1}})";
         return "sweep " + (dir.parent_path() / "sweep.json").string() + " --out " + dir.string();
       }},
      {"analyze_table", "coverage.csv",
       [](const fs::path& dir) {
         return "analyze " + finishedSweep().string() + " --out " + dir.string();
       }},
      {"reproduce_report", "report.md",
       [](const fs::path& dir) { return "reproduce --trials 1 --out " + dir.string(); }},
  };
  return all;
}

TEST(HostileOutputs, ANodeWhereAFileGoesIsRefusedBeforeAnyWorkAndLeftAsItWas) {
  int checked = 0;
  for (const Writer& writer : writers()) {
    for (const Node& node : nodes()) {
      const std::string label = writer.name + " onto " + node.kind;
      const fs::path dir = scratch("out") / "out";
      fs::create_directories(dir);
      const fs::path target = dir / writer.file;
      if (!node.make(target)) {
        std::printf("skipped: %s (mknod not permitted here)\n", label.c_str());
        continue;
      }
      const std::string before = identity(target);
      const Outcome outcome = canopy(writer.arguments(dir), "exec timeout -s KILL 60 ");
      EXPECT_EQ(outcome.code, 2) << label << "\n" << outcome.output;
      EXPECT_NE(outcome.output.find(target.string() + "': exists and is " + node.kind),
                std::string::npos)
          << label << "\n"
          << outcome.output;
      EXPECT_EQ(identity(target), before) << label << ": the node was replaced";
      EXPECT_FALSE(temporariesBeside(target)) << label;
      // Before any work: nothing of a run or a sweep was written beside it.
      for (const char* name : {"manifest.json", "trials", "sweep.json", "demo"})
        EXPECT_FALSE(fs::exists(dir / name)) << label << ": " << name << " was written";
      ++checked;
      fs::remove_all(dir.parent_path());
    }
  }
  EXPECT_GE(checked, static_cast<int>(writers().size()));  // the FIFOs at least
}

TEST(HostileOutputs, ViewOutDashWritesThePageToStandardOutput) {
  const fs::path dir = scratch("dash");
  const Outcome file =
      canopy("view " + finishedRun().string() + " --out " + (dir / "page.html").string());
  ASSERT_EQ(file.code, 0) << file.output;
  const Outcome dash =
      canopy("view " + finishedRun().string() + " --out - > " + (dir / "stdout.html").string());
  ASSERT_EQ(dash.code, 0) << dash.output;
  const auto written = canopy::readTextFile(dir / "page.html");
  const auto printed = canopy::readTextFile(dir / "stdout.html");
  ASSERT_TRUE(written && printed);
  EXPECT_GT(written->size(), 10000u);
  EXPECT_EQ(*written, *printed);
  EXPECT_FALSE(fs::exists(finishedRun() / "-"));
  fs::remove_all(dir);
}

// A copy of the finished run with line `line` of its record edited by `edit` (sed expression).
fs::path editedRun(const std::string& name, int line, const std::string& edit) {
  const fs::path dir = scratch(name) / "run";
  fs::copy(finishedRun(), dir, fs::copy_options::recursive);
  const std::string command =
      "sed -i '" + std::to_string(line) + edit + "' " + (dir / "record.jsonl").string();
  EXPECT_EQ(std::system(command.c_str()), 0);
  return dir;
}

TEST(HostileOutputs, IntegersPast32BitsAreRefusedNamingTheLineNotWrapped) {
  // 2³² + 1 wraps to 1, the index the line must hold; 2³² wraps to target 0, a real target.
  const fs::path step = editedRun("k", 2, R"(s/"k":1,/"k":4294967297,/)");
  for (const std::string& command :
       {"view " + step.string() + " --out -", "coverage " + step.string()}) {
    const Outcome outcome = canopy(command + " >/dev/null");
    EXPECT_EQ(outcome.code, 2) << command << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find("record.jsonl: line 2: k: expected"), std::string::npos)
        << command << "\n"
        << outcome.output;
  }
  const fs::path target =
      editedRun("in_footprint", 3, R"(s/"in_footprint":\[[^]]*\]/"in_footprint":[4294967296]/)");
  const Outcome outcome = canopy("view " + target.string() + " --out - >/dev/null");
  EXPECT_EQ(outcome.code, 2) << outcome.output;
  EXPECT_NE(outcome.output.find("record.jsonl: line 3: scans.0.in_footprint: expected target "
                                "indices below"),
            std::string::npos)
      << outcome.output;
  fs::remove_all(step.parent_path());
  fs::remove_all(target.parent_path());
}

TEST(HostileOutputs, ARecordLineLongerThan256MiBIsRefusedNamingTheLine) {
  // 257 MiB of NUL bytes, no newline: one line (sparse: nothing is written to the disk).
  const fs::path dir = scratch("long") / "run";
  fs::copy(finishedRun(), dir, fs::copy_options::recursive);
  fs::resize_file(dir / "record.jsonl", 0);
  fs::resize_file(dir / "record.jsonl", std::uintmax_t{257} << 20);
  for (const std::string& command :
       {"view " + dir.string() + " --out -", "coverage " + dir.string()}) {
    const Outcome outcome = canopy(command + " >/dev/null");
    EXPECT_EQ(outcome.code, 2) << command << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find("record.jsonl: line 1: expected a line of at most 256 MiB"),
              std::string::npos)
        << command << "\n"
        << outcome.output;
  }
  fs::remove_all(dir.parent_path());
}

#ifndef __SANITIZE_ADDRESS__  // ASan reserves terabytes of address space: no ulimit -v
TEST(HostileOutputs, ARecordLineThatCannotFitInMemoryIsOutOfMemoryNotAnAbort) {
  // One line of 120 MB holding 6·10⁷ numbers: its document takes gigabytes, under a 1.5 GB cap.
  const fs::path dir = scratch("huge") / "run";
  fs::copy(finishedRun(), dir, fs::copy_options::recursive);
  {
    std::ofstream record(dir / "record.jsonl", std::ios::binary | std::ios::trunc);
    record << R"({"k": 0, "pad": [)";
    const std::string chunk = [] {
      std::string c;
      for (int i = 0; i < 500000; ++i) c += "0,";
      return c;
    }();
    for (int i = 0; i < 120; ++i) record << chunk;  // 120 × 10⁶ bytes
    record << "0]}\n";
  }
  ASSERT_GT(fs::file_size(dir / "record.jsonl"), 100000000u);
  const Outcome outcome = canopy("view " + dir.string() + " --out " + (dir / "page.html").string(),
                                 "ulimit -v 1500000; exec timeout -s KILL 120 ");
  EXPECT_EQ(outcome.code, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("canopy: out of memory"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(dir / "page.html"));
  fs::remove_all(dir.parent_path());
}
#endif

}  // namespace
