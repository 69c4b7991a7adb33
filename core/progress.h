#pragma once
// How far long work got. Stages that can run for seconds when the budget is raised (reading a
// large JSON file, reading its occluders and targets, checking target paths, building the
// world, a run's steps) report (stage, done, total) here every so often; the command line shows
// a line on stderr when one has run for a while (app/main.cpp's showProgress). Without a hook, reporting
// costs one atomic load.
#include <cstdint>

namespace canopy {

/// Receives how far `stage` ("reading occluders") got: `done` of `total` units (total 0: not
/// known ahead). Called on the thread doing the work, possibly from several threads at once.
using ProgressHook = void (*)(const char* stage, double done, double total);

/// Sets the process-wide hook (nullptr: none, the default); returns the one it replaces.
ProgressHook setProgressHook(ProgressHook hook);
/// Hands (stage, done, total) to the hook, if one is set.
void reportProgress(const char* stage, double done, double total);

/// While alive, stages reach no hook (for a command that draws bars of its own, such as a
/// sweep's, into which a trial's "running steps" would break); the hook is restored after.
class StagesSilenced {
 public:
  StagesSilenced() : previous_(setProgressHook(nullptr)) {}
  ~StagesSilenced() { setProgressHook(previous_); }
  StagesSilenced(const StagesSilenced&) = delete;
  StagesSilenced& operator=(const StagesSilenced&) = delete;

 private:
  ProgressHook previous_;
};

/// A loop's progress: the start is reported, then add() counts units and reports every `every`
/// of them; the end of the stage (finish() or the destructor) is reported once more.
class ProgressCounter {
 public:
  ProgressCounter(const char* stage, double total, std::uint64_t every = 4096)
      : stage_(stage), total_(total), every_(every == 0 ? 1 : every), next_(every_) {
    reportProgress(stage_, 0.0, total_);  // the stage starts
  }
  ~ProgressCounter() { finish(); }
  ProgressCounter(const ProgressCounter&) = delete;
  ProgressCounter& operator=(const ProgressCounter&) = delete;

  void add(std::uint64_t units = 1) {
    done_ += units;
    if (done_ >= next_) {
      next_ = done_ + every_;
      reportProgress(stage_, static_cast<double>(done_), total_);
    }
  }
  void finish() {
    if (finished_) return;
    finished_ = true;
    reportProgress(stage_, static_cast<double>(done_), total_);
  }

 private:
  const char* stage_;
  double total_;
  std::uint64_t every_, next_;
  std::uint64_t done_ = 0;
  bool finished_ = false;
};

/// When a progress line is due: the first once `first_after` seconds have passed since the
/// start, then one every `interval` seconds. Times are seconds on any clock.
class ProgressThrottle {
 public:
  ProgressThrottle(double start, double first_after, double interval)
      : next_(start + first_after), interval_(interval) {}
  /// True when a line is due at `now` (and then the next is `interval` later).
  bool due(double now) {
    if (now < next_) return false;
    next_ = now + interval_;
    return true;
  }

 private:
  double next_, interval_;
};

}  // namespace canopy
