// The MPI half of experiments/sweep_mpi.h, a module of its own (canopy_mpi, a shared object
// loaded by sweep_mpi.cpp with dlopen on the first `--mpi`), so that the `canopy` program does not
// link libmpi (issue 51): a run that never asks for MPI neither loads nor initialises it. Its
// references to canopy's own functions (prepareSweep, runTrials, …) are resolved against the
// program, which exports them (ENABLE_EXPORTS). Its entry points are the extern "C" functions at
// the end; everything else is internal, so that no name of it is taken for the program's.
#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "experiments/sweep.h"
#include "experiments/sweep_mpi.h"

namespace canopy::experiments {
namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// Rank 0's outcome of a collective step, shared with every rank so that none waits for a rank
// that has given up.
bool everyoneSucceeded(bool mine) {
  int ok = mine ? 1 : 0, all = 0;
  check(MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return all == 1;
}

const MpiWorld& theWorld() {
  static const MpiWorld world = [] {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
    std::atexit([] { MPI_Finalize(); });
    if (provided < MPI_THREAD_SERIALIZED)
      throw std::runtime_error("MPI: this MPI library cannot serve several threads per rank");
    MpiWorld w;
    check(MPI_Comm_rank(MPI_COMM_WORLD, &w.rank), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &w.size), "MPI_Comm_size");
    return w;
  }();
  return world;
}

int runOverRanks(const experiments::SweepSpec& sweep, const std::filesystem::path& out_dir,
                 int jobs) {
  const MpiWorld& world = canopy::experiments::theWorld();
  // Rank 0 checks the directory, writes its manifests and lists the missing trials; the others
  // load the same configurations (their scenarios) without writing, and take rank 0's list.
  experiments::PreparedSweep prepared;
  std::exception_ptr failure;
  if (world.rank == 0) {
    try {
      prepared = experiments::prepareSweep(sweep, out_dir, /*strict=*/true, /*write=*/true);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (!everyoneSucceeded(!failure)) {
    if (failure) std::rethrow_exception(failure);
    throw std::runtime_error("MPI: rank 0 could not prepare the sweep (its message says why)");
  }
  if (world.rank != 0) prepared = experiments::prepareSweep(sweep, out_dir, true, false);
  long long count = static_cast<long long>(prepared.todo.size());
  check(MPI_Bcast(&count, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD), "MPI_Bcast");
  prepared.todo.resize(static_cast<std::size_t>(count));
  check(MPI_Bcast(prepared.todo.data(), static_cast<int>(count), MPI_INT, 0, MPI_COMM_WORLD),
        "MPI_Bcast");

  // The shared counter: one long long at rank 0, advanced by MPI_Fetch_and_op.
  long long* counter = nullptr;
  MPI_Win window;
  check(MPI_Win_allocate(world.rank == 0 ? sizeof(long long) : 0, sizeof(long long), MPI_INFO_NULL,
                         MPI_COMM_WORLD, &counter, &window),
        "MPI_Win_allocate");
  if (world.rank == 0) *counter = 0;
  check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
  std::mutex mpi;  // MPI_THREAD_SERIALIZED: one thread of this rank at MPI at a time
  const experiments::NextTrial next = [&]() -> std::optional<std::size_t> {
    const long long one = 1;
    long long taken = 0;
    {
      const std::lock_guard lock(mpi);
      check(MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window), "MPI_Win_lock");
      check(MPI_Fetch_and_op(&one, &taken, MPI_LONG_LONG, 0, 0, MPI_SUM, window),
            "MPI_Fetch_and_op");
      check(MPI_Win_unlock(0, window), "MPI_Win_unlock");
    }
    if (taken >= count) return std::nullopt;
    return static_cast<std::size_t>(taken);
  };
  int ran = 0;
  failure = nullptr;
  try {
    experiments::SweepProgress progress;
    progress.total = prepared.total;
    ran = experiments::runTrials(sweep, prepared, out_dir, jobs, next, progress);
  } catch (...) {
    failure = std::current_exception();
  }
  const bool all_ran = everyoneSucceeded(!failure);  // also: every rank is done
  check(MPI_Win_free(&window), "MPI_Win_free");
  if (failure) std::rethrow_exception(failure);
  if (!all_ran)
    throw std::runtime_error("MPI: a trial failed on another rank (its message says why)");
  if (world.rank == 0) experiments::finishSweep(out_dir);
  check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");  // the summary exists when any rank returns
  return ran;
}

int sumOf(int value) {
  int total = 0;
  check(MPI_Allreduce(&value, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return total;
}

}  // namespace
}  // namespace canopy::experiments

// The entry points sweep_mpi.cpp looks up (exceptions pass through them: one toolchain builds
// both sides).
extern "C" {

__attribute__((visibility("default"))) void canopy_mpi_world(int* rank, int* size) {
  const canopy::experiments::MpiWorld& w = canopy::experiments::theWorld();
  *rank = w.rank;
  *size = w.size;
}

__attribute__((visibility("default"))) int canopy_mpi_run_sweep(const void* sweep,
                                                                const void* out_dir, int jobs) {
  return canopy::experiments::runOverRanks(
      *static_cast<const canopy::experiments::SweepSpec*>(sweep),
      *static_cast<const std::filesystem::path*>(out_dir), jobs);
}

__attribute__((visibility("default"))) int canopy_mpi_sum(int value) {
  return canopy::experiments::sumOf(value);
}

}  // extern "C"
