// experiments/sweep_mpi.h without linking MPI: the MPI code is the module canopy_mpi
// (mpi_module.cpp), loaded on the first use with dlopen from beside the program (the build tree)
// or from LIBDIR/canopy (an install). RTLD_GLOBAL: Open MPI's own plugins need libmpi's symbols.
#include "experiments/sweep_mpi.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

#include "core/program_module.h"

namespace canopy::experiments {
namespace fs = std::filesystem;
namespace {

struct Module {
  std::string problem;  // why it is not available; "" when it is
  void (*world)(int*, int*) = nullptr;
  int (*run)(const void*, const void*, int) = nullptr;
  int (*sum)(int) = nullptr;
};

const Module& module() {
  static const Module loaded = [] {
    Module m;
    const std::string name = CANOPY_MPI_MODULE;
    if (name.empty()) {
      m.problem =
          "this canopy was built without MPI: install the Debian packages libopenmpi-dev and "
          "openmpi-bin, then rebuild (./canopy does both)";
      return m;
    }
    const fs::path path = programModulePath(name, CANOPY_MPI_MODULE_LIBDIR);
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
      const char* why = ::dlerror();
      m.problem = "MPI sweeps need " + path.string() + ", which could not be loaded (" +
                  (why ? why : "unknown error") + ")";
      return m;
    }
    m.world = reinterpret_cast<void (*)(int*, int*)>(::dlsym(handle, "canopy_mpi_world"));
    m.run = reinterpret_cast<int (*)(const void*, const void*, int)>(
        ::dlsym(handle, "canopy_mpi_run_sweep"));
    m.sum = reinterpret_cast<int (*)(int)>(::dlsym(handle, "canopy_mpi_sum"));
    if (!m.world || !m.run || !m.sum)
      m.problem = path.string() + " is not canopy's MPI module (an entry point is missing)";
    return m;
  }();
  return loaded;
}

const Module& loadedModule() {
  const Module& m = module();
  if (!m.problem.empty()) throw std::runtime_error(m.problem);
  return m;
}

}  // namespace

bool mpiAvailable() {
  return module().problem.empty();
}

std::string mpiProblem() {
  return module().problem;
}

const MpiWorld& mpiWorld() {
  static const MpiWorld world = [] {
    MpiWorld w;
    loadedModule().world(&w.rank, &w.size);
    return w;
  }();
  return world;
}

int runSweepMpi(const experiments::SweepSpec& sweep, const std::filesystem::path& out_dir,
                int jobs) {
  return loadedModule().run(&sweep, &out_dir, jobs);
}

int sumOverRanks(int value) {
  return loadedModule().sum(value);
}

}  // namespace canopy::experiments
