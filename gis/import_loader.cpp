// gis/import_loader.h: finds the module canopy_gis, opens it once (RTLD_LOCAL: GDAL's and PROJ's
// symbols stay the module's), and calls its entry point.
#include "gis/import_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>

#include "core/program_module.h"
#include "gis/import_module.h"

namespace canopy::gis {
namespace fs = std::filesystem;
namespace {

struct Module {
  std::string problem;  // why it is not available; "" when it is
  ImportEntry import = nullptr;
};

const Module& module() {
  static const Module loaded = [] {
    Module m;
    const fs::path path = programModulePath(CANOPY_GIS_MODULE, CANOPY_GIS_MODULE_LIBDIR);
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      m.problem = "canopy import needs " + path.string() + ", which could not be loaded (" +
                  (why ? why : "unknown error") + ")";
      return m;
    }
    m.import = reinterpret_cast<ImportEntry>(::dlsym(handle, kImportEntryName));
    if (!m.import) m.problem = path.string() + " is not canopy's GIS module (no entry point)";
    return m;
  }();
  return loaded;
}

}  // namespace

ImportedLayout importThroughModule(const ImportOptions& options) {
  const Module& m = module();
  if (!m.problem.empty()) throw std::runtime_error(m.problem);
  ImportedLayout imported;
  m.import(&options, &imported.result, &imported.text);
  return imported;
}

}  // namespace canopy::gis
