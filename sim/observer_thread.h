#pragma once
// Observers on a thread of their own, behind the simulation: the record of step k is written
// while the steps after it are computed. `run --threads N` (N ≥ 2) gives record.jsonl and the
// summary one, so that their formatting (a fifth of a swarm-sized run on one thread) overlaps the
// tick instead of adding to it. The observers see the same records in the same order as on the
// caller's thread, so they write the same bytes.
//
// The caller hands over up to `slots` steps before it waits. A planning step is several times the
// work of the steps between two plans while the observers' work is about even per step: with one
// slot the caller waited at the cheap steps (64 UAVs × 256 people × 10⁵ trees, two threads: 0.56 s
// of a 5.1-s tick loop), and the observers could not use the cores that the plan's serial parts
// leave idle. With kSlots they can catch up there; each slot holds one StepRecord (all agents'
// beliefs: about 3 MB at 64 × 256, 50 MB at 256 × 1024).
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "sim/step_observer.h"
#include "sim/step_record.h"

namespace canopy::sim {

class ObserverThread final : public StepObserver {
 public:
  static constexpr std::size_t kSlots = 4;

  /// Starts the thread. The observers are called on it, in the order given; they must not be
  /// used by anyone else until finish() has returned (or this is destroyed).
  explicit ObserverThread(std::vector<StepObserver*> observers, std::size_t slots = kSlots);
  /// Stops the thread; steps handed over and not yet observed are dropped.
  ~ObserverThread();
  ObserverThread(const ObserverThread&) = delete;
  ObserverThread& operator=(const ObserverThread&) = delete;

  /// Rethrows the first exception an observer threw; waits while every slot holds a step not yet
  /// observed; then copies `record` into a free slot for the thread and returns.
  void onStep(const StepRecord& record) override;
  /// Waits until every step handed over has been observed; rethrows as onStep() does.
  void finish();

 private:
  void work();

  std::vector<StepObserver*> observers_;
  // A ring: the thread observes slots_[first_], …, the `pending_` steps handed over in order.
  // A slot is written only while it is not pending, and read only while it is.
  std::vector<StepRecord> slots_;
  std::size_t first_ = 0;
  std::size_t pending_ = 0;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool stop_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once the members it uses exist
};

}  // namespace canopy::sim
