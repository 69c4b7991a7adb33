// Scenarios cross into Python as their effective configuration (JSON text, every default
// filled in); Python edits it as a dict and hands it back as text, checked by the same loader as
// the command line, so errors read the same: "FILE: FIELD: expected …".
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "python/src/bindings.h"
#include "python/src/scenario_source.h"
#include "spec/error.h"
#include "spec/loader.h"

namespace py = pybind11;

namespace canopy::python {
spec::ScenarioSpec specOf(const py::object& scenario, std::optional<std::uint64_t> seed) {
  spec::ScenarioSpec spec =
      *scenario.attr("_spec")().cast<std::shared_ptr<const spec::ScenarioSpec>>();
  // The loader's --seed sets spec.seed and the effective configuration's "seed" (a generator's
  // seed is its own field). A Simulation never reads effective_config; run() loads afresh.
  if (seed) spec.seed = *seed;
  return spec;
}

void bindScenario(py::module_& m) {
  // canopy.ScenarioError (a ValueError) with the parts of the message as attributes.
  static py::exception<spec::ScenarioError> error(m, "ScenarioError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const spec::ScenarioError& e) {
      py::object value = py::reinterpret_borrow<py::object>(error.ptr())(e.what());
      value.attr("file") = e.file();
      value.attr("field") = e.field();
      value.attr("reason") = e.message();
      PyErr_SetObject(error.ptr(), value.ptr());
    }
  });

  m.def(
      "_load",
      [](const std::string& scenario, const std::vector<std::string>& overrides,
         const std::vector<std::string>& allowed_roots) {
        spec::LoadOptions options = loadOptions(allowed_roots, std::nullopt);
        options.overrides = overrides;
        const std::string file = spec::resolveScenario(scenario).string();
        const spec::ScenarioSpec spec = spec::loadScenario(file, options);
        return std::make_pair(spec.effective_config, file);
      },
      py::arg("scenario"), py::arg("overrides"), py::arg("allowed_roots"),
      "(effective configuration as JSON text, the file it came from)");
  m.def(
      "_check",
      [](const std::string& text, const std::string& file,
         const std::vector<std::string>& allowed_roots) {
        return spec::loadScenarioText(text, file, loadOptions(allowed_roots, std::nullopt))
            .effective_config;
      },
      py::arg("text"), py::arg("file"), py::arg("allowed_roots"),
      "Validates a configuration; returns it with every default filled in.");
  // The loader's result, opaque to Python: Scenario caches it while its configuration is unchanged,
  // so that a Simulation per episode does not parse and generate the layout again.
  py::class_<spec::ScenarioSpec, std::shared_ptr<spec::ScenarioSpec>>(m, "_Spec");
  m.def(
      "_compile",
      [](const std::string& text, const std::string& file,
         const std::vector<std::string>& allowed_roots) {
        return std::make_shared<spec::ScenarioSpec>(
            spec::loadScenarioText(text, file, loadOptions(allowed_roots, std::nullopt)));
      },
      py::arg("text"), py::arg("file"), py::arg("allowed_roots"));
  m.def("library_scenarios", [] { return spec::libraryScenarios(); }, "The built-in scenarios' names.");
  m.def("_library_dir", [] { return spec::libraryDir().string(); });
  m.def(
      "_set_builtin_scenarios", [](const std::string& dir) { spec::setBuiltinScenarioDir(dir); },
      "Where the built-in scenarios (library/) and the schema's probe files are: the installed "
      "package's copy (python/canopy/__init__.py).");
}

}  // namespace canopy::python
