#pragma once
// Observers on a thread of their own, one step behind the simulation: the record of step k is
// written while step k + 1 is computed. `run --threads N` (N ≥ 2) gives record.jsonl and the
// summary one, so that their formatting (about a tenth of a city-sized run) overlaps the tick's
// serial parts instead of adding to them. The observers see the same records in the same order
// as on the caller's thread, so they write the same bytes.
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "sim/step_observer.h"
#include "sim/step_record.h"

namespace canopy::sim {

class ObserverThread final : public StepObserver {
 public:
  /// Starts the thread. The observers are called on it, in the order given; they must not be
  /// used by anyone else until finish() has returned (or this is destroyed).
  explicit ObserverThread(std::vector<StepObserver*> observers);
  /// Stops the thread; a step handed over and not yet observed is dropped.
  ~ObserverThread();
  ObserverThread(const ObserverThread&) = delete;
  ObserverThread& operator=(const ObserverThread&) = delete;

  /// Waits until the thread has observed the previous step, rethrows the first exception an
  /// observer threw, then hands the thread a copy of `record` and returns.
  void onStep(const StepRecord& record) override;
  /// Waits until every step handed over has been observed; rethrows as onStep() does.
  void finish();

 private:
  void work();
  void waitIdle(std::unique_lock<std::mutex>& lock);

  std::vector<StepObserver*> observers_;
  StepRecord copy_;  // the step being observed (written only while the thread is idle)
  std::mutex mutex_;
  std::condition_variable changed_;
  bool pending_ = false;  // copy_ holds a step not yet observed
  bool stop_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once the members it uses exist
};

}  // namespace canopy::sim
