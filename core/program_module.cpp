#include "core/program_module.h"

#include <system_error>

namespace canopy {

std::filesystem::path programModulePath(const std::string& name, const std::string& libdir) {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path beside = program.parent_path() / name;
  if (std::filesystem::exists(beside, error)) return beside;
  return program.parent_path().parent_path() / libdir / name;
}

}  // namespace canopy
