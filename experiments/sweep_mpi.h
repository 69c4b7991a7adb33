#pragma once
// Sweeps over MPI ranks (`mpirun -n K canopy sweep FILE --out DIR --mpi`): every rank runs trials
// with its own threads and writes each trial's file atomically itself, as a local run does; the
// trials still to run are listed once, by rank 0, and handed out dynamically through one counter
// held by rank 0 (MPI-3 one-sided fetch-and-add), so a fast rank takes more of them. Rank 0
// writes DIR/summary.json when every rank is done. A rank that dies loses only the trials it was
// running: their files were never renamed into place, and a later run (with or without --mpi)
// runs exactly the missing ones. Results are the bytes of `--jobs 1`: a trial's file depends on
// its seed only.
#include <filesystem>
#include <string>

#include "experiments/sweep.h"

namespace canopy::experiments {

/// Whether MPI sweeps can run: canopy was built with MPI (Open MPI found by CMake) and its MPI
/// module (mpi_module.cpp, the only code that links libmpi) loads. The first call loads it.
bool mpiAvailable();
/// Why not, "" when they can: built without MPI, or the module that could not be loaded.
std::string mpiProblem();

/// The process's MPI session, initialised on first use (MPI_THREAD_SERIALIZED: the threads of a
/// rank take turns at MPI) and finalised at exit. Throws std::runtime_error without MPI.
struct MpiWorld {
  int rank = 0;
  int size = 1;
};
const MpiWorld& mpiWorld();

/// Runs the sweep over every rank of MPI_COMM_WORLD with `jobs` threads each; every rank must
/// call it with the same sweep. Returns the number of trials this rank ran. A ScenarioError on
/// rank 0 (a different sweep in DIR, a bad scenario) is thrown there and reported as a
/// std::runtime_error on the other ranks; a failed trial on any rank stops the summary.
int runSweepMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out_dir,
                int jobs);

/// The sum of `value` over every rank (collective: every rank must call it).
int sumOverRanks(int value);

}  // namespace canopy::experiments
