#include "sim/observer_thread.h"

#include <utility>

namespace canopy::sim {

ObserverThread::ObserverThread(std::vector<StepObserver*> observers)
    : observers_(std::move(observers)), thread_([this] { work(); }) {}

ObserverThread::~ObserverThread() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void ObserverThread::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return pending_ || stop_; });
    if (stop_) return;
    lock.unlock();
    try {
      for (StepObserver* observer : observers_) observer->onStep(copy_);
    } catch (...) {
      lock.lock();
      error_ = std::current_exception();
      lock.unlock();
    }
    lock.lock();
    // After an exception the caller stops at its next onStep() or finish(): no step is observed
    // after the one that failed.
    pending_ = false;
    changed_.notify_all();
  }
}

void ObserverThread::waitIdle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [&] { return !pending_; });
  if (error_) std::rethrow_exception(error_);
}

void ObserverThread::onStep(const StepRecord& record) {
  {
    std::unique_lock lock(mutex_);
    waitIdle(lock);
    copy_ = record;  // vectors keep their capacity: no allocation once the largest step was seen
    pending_ = true;
  }
  changed_.notify_all();
}

void ObserverThread::finish() {
  std::unique_lock lock(mutex_);
  waitIdle(lock);
}

}  // namespace canopy::sim
