#pragma once
// Where one of the program's modules is: a shared object the `canopy` program opens with dlopen
// on first use (MPI for --mpi, GIS for `canopy import`), so that no other command loads what it
// links.
#include <filesystem>
#include <string>

namespace canopy {

/// Beside the program (the build tree, or a pip wheel's canopy/bin/) when it is there, else
/// PREFIX/`libdir`/`name` for a program installed as PREFIX/bin/canopy.
std::filesystem::path programModulePath(const std::string& name, const std::string& libdir);

}  // namespace canopy
