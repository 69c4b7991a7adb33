// Every option whose value is a number or a structured text (--seed, --jobs, --shard, --budget,
// --size, --radius, ...) × every way of writing a value outside its grammar (blanks before or
// after, a '+', a leading zero, inf, nan, empty, huge, hexadecimal, a blank inside a list): the
// command line is refused with exit 2 naming the option. The well-written value beside each is
// not refused. The arguments go to canopy through execv, one argv element each, with no shell
// between: a blank in a value reaches canopy as typed.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string output;  // stdout and stderr together
};

Outcome canopy(const std::vector<std::string>& arguments) {
  int pipe_ends[2];
  if (::pipe(pipe_ends) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipe_ends[1], STDOUT_FILENO);
    ::dup2(pipe_ends[1], STDERR_FILENO);
    ::close(pipe_ends[0]);
    ::close(pipe_ends[1]);
    std::vector<char*> argv{const_cast<char*>(CANOPY_BINARY)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(CANOPY_BINARY, argv.data());
    ::_exit(127);
  }
  ::close(pipe_ends[1]);
  Outcome outcome;
  std::array<char, 4096> buffer;
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer.data(), buffer.size())) > 0;)
    outcome.output.append(buffer.data(), static_cast<std::size_t>(n));
  ::close(pipe_ends[0]);
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return outcome;
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

struct OptionCase {
  std::vector<std::string> command;  // the rest of a command line that fails fast, or runs fast
  std::string option;
  std::string good;  // a value in the option's grammar
};

// Ways to write `good` outside the grammar. Every good value below is positive, starts with a
// non-zero digit (or a letter for --view), and has its separators (',', 'x', '/') inside.
std::vector<std::string> malformed(const std::string& good) {
  std::vector<std::string> forms = {
      " " + good, good + " ", "\t" + good, good + "\n", "+" + good,    "",
      "inf",      "-inf",     "nan",       "infinity",  "1e999",       std::string(40, '9'),
      "0x1p3",    "0x10",     good + ",",  good + "x",  good + "\xc3\xa9"};
  if (good[0] >= '1' && good[0] <= '9') forms.push_back("0" + good);  // a leading zero
  const std::size_t separator = good.find_first_of(",x/");
  if (separator != std::string::npos) {
    std::string spaced = good;
    spaced.insert(separator + 1, " ");  // "1, 2", "800x 600", "0/ 2"
    forms.push_back(spaced);
    spaced = good;
    spaced.insert(separator, " ");  // "1 ,2"
    forms.push_back(spaced);
    std::string signed_after = good;
    signed_after.insert(separator + 1, "+");  // "1,+2"
    forms.push_back(signed_after);
    std::string zero_after = good;
    if (good[separator + 1] >= '1' && good[separator + 1] <= '9') {
      zero_after.insert(separator + 1, "0");  // "800x0600", "0/02"
      forms.push_back(zero_after);
    }
  }
  return forms;
}

std::vector<OptionCase> optionCases(const fs::path& dir) {
  const std::string missing = (dir / "missing.json").string();
  const std::vector<std::string> run = {"run", missing, "--frames", "--video"};
  const std::vector<std::string> forest = {"forest", "--aoi",  "0,0,100,100", "--lambda",
                                           "0.01",   "--radius", "1,2"};
  auto forestWithout = [&forest](const std::string& option) {
    std::vector<std::string> rest;
    for (std::size_t i = 1; i < forest.size(); i += 2) {
      if (forest[i] != option) {
        rest.push_back(forest[i]);
        rest.push_back(forest[i + 1]);
      }
    }
    rest.insert(rest.begin(), "forest");
    return rest;
  };
  const std::vector<std::string> sweep = {"sweep", missing, "--out", (dir / "sweep").string()};
  return {
      {run, "--seed", "7"},
      {run, "--threads", "2"},
      {run, "--frame-every", "2"},
      {run, "--size", "800x600"},
      {run, "--fps", "12.5"},
      {run, "--view", "1,2,30,40"},
      {run, "--budget", "2"},
      {{"validate", missing}, "--budget", "2.5"},
      {sweep, "--jobs", "2"},
      {sweep, "--shard", "1/2"},
      {sweep, "--budget", "3"},
      {{"analyze", (dir / "no_sweep").string()}, "--before-hiding", "30"},
      {{"analyze", (dir / "no_sweep").string()}, "--budget", "3"},
      {{"reproduce"}, "--trials", "5"},  // without --out: refused once the options are read
      {{"reproduce"}, "--jobs", "2"},
      {{"reproduce"}, "--seed", "3"},
      {{"coverage", (dir / "no_run").string(), "--check", missing}, "--tolerance", "0.25"},
      {{"coverage", (dir / "no_run").string()}, "--size", "640x480"},
      {forestWithout("--aoi"), "--aoi", "1,2,30,40"},
      {forestWithout("--lambda"), "--lambda", "0.01"},
      {forestWithout("--radius"), "--radius", "1.5,2"},
      {forestWithout("--radius"), "--radius", "3"},
      {forest, "--seed", "11"},
      {forest, "--min-gap", "0.5"},
      {forest, "--budget", "2"},
  };
}

TEST(OptionGrammar, EveryValueOutsideItsOptionsGrammarIsRefusedNamingTheOption) {
  const fs::path dir = fs::temp_directory_path() / "canopy_option_grammar";
  fs::remove_all(dir);
  fs::create_directories(dir);
  int refused = 0;
  for (const OptionCase& c : optionCases(dir)) {
    std::vector<std::string> arguments = c.command;
    arguments.push_back(c.option);
    arguments.push_back(c.good);
    const Outcome accepted = canopy(arguments);
    EXPECT_EQ(accepted.output.find(c.option + ":"), std::string::npos)
        << c.option << " " << c.good << " was refused: " << accepted.output;
    for (const std::string& bad : malformed(c.good)) {
      arguments.back() = bad;
      const Outcome outcome = canopy(arguments);
      EXPECT_EQ(outcome.code, 2) << c.option << " '" << bad << "': " << outcome.output;
      EXPECT_NE(outcome.output.find(c.option + ": expected"), std::string::npos)
          << c.option << " '" << bad << "': " << outcome.output;
      ++refused;
    }
  }
  EXPECT_GT(refused, 25 * 17);  // every option × every form, not a loop that ran empty
  EXPECT_FALSE(fs::exists(dir / "sweep"));
  fs::remove_all(dir);
}

// --threads takes 1..256 (sim::Simulation::kMaxThreads): 0, negative, past the limit and
// non-numbers are refused before anything runs, with exit 2 and a message naming --threads and
// the range.
TEST(OptionGrammar, ThreadCountsOutsideOneTo256AreRefused) {
  const fs::path dir = fs::temp_directory_path() / "canopy_threads_option";
  fs::remove_all(dir);
  for (const std::string bad : {"0", "-1", "257", "99999", "abc", "2.5", "1e2"}) {
    const Outcome outcome = canopy({"run", "demo", "--out", dir.string(), "--threads", bad});
    EXPECT_EQ(outcome.code, 2) << bad << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("--threads: expected"), std::string::npos)
        << bad << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("256"), std::string::npos) << bad << ": " << outcome.output;
    EXPECT_FALSE(fs::exists(dir)) << bad;
  }
}

// The option reaches the simulation: a short run at --threads 1 and 2 writes the same record.jsonl
// (and both finish: exit 0).
TEST(OptionGrammar, RunAtTwoThreadsWritesTheSameRecordAsAtOne) {
  const fs::path dir = fs::temp_directory_path() / "canopy_threads_run";
  fs::remove_all(dir);
  std::string records[2];
  for (const int threads : {1, 2}) {
    const fs::path out = dir / std::to_string(threads);
    const Outcome outcome =
        canopy({"run", "mixed_team", "--set", "clock.duration=4", "--out", out.string(),
                "--threads", std::to_string(threads)});
    ASSERT_EQ(outcome.code, 0) << outcome.output;
    std::ifstream in(out / "record.jsonl", std::ios::binary);
    records[threads - 1].assign(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_GT(records[0].size(), 1000u);
  EXPECT_TRUE(records[0] == records[1]) << records[0].size() << " vs " << records[1].size();
  fs::remove_all(dir);
}

}  // namespace
