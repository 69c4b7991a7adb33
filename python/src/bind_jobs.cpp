// Whole jobs from Python, as the command line runs them: run (manifest, record, summary and
// optional frames), sweep (trials on a thread pool, resumable) and analyze (the CSV tables and
// figures; python/canopy/jobs.py reads the tables into numpy arrays). The GIL is released while
// they run: they touch no Python object.
#include <pybind11/stl.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/sweep_analysis.h"
#include "experiments/sweep.h"
#include "python/src/bindings.h"
#include "python/src/scenario_source.h"
#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/frame_writer.h"
#include "sim/run.h"
#include "spec/loader.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

struct FrameRequest {
  bool on = false;
  int every = 1;
  int width = 0, height = 0;  // px; 0: the CLI's default size
};

std::string runJob(const std::string& text, const std::string& file,
                   const std::vector<std::string>& roots, const std::string& out,
                   std::optional<std::uint64_t> seed, const FrameRequest& frames) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(text, file, loadOptions(roots, seed));
  sim::RunOptions options;
  options.out_dir = out;
  options.command_line = "python: canopy.run(" + spec.name + ")";
  std::optional<render::FrameWriter> writer;
  std::optional<render::FrameObserver> observer;
  if (frames.on) {
    render::FrameOptions frame_options;
    frame_options.dir = options.out_dir / "frames";
    frame_options.every = frames.every;
    frame_options.size = render::ImageSize{frames.width, frames.height};
    writer.emplace(render::sceneModel(spec, render::viewFor("action", spec)), frame_options);
    observer.emplace(*writer);
    options.observers.push_back(&*observer);
  }
  py::gil_scoped_release release;
  return sim::runScenario(spec, options).summary_json;
}

int sweepJob(const std::string& file, const std::string& out, int jobs,
             const std::vector<std::string>& roots) {
  const experiments::SweepSpec sweep =
      experiments::loadSweep(file, loadOptions(roots, std::nullopt));
  experiments::SweepOptions options;
  options.out_dir = out;
  options.jobs = jobs;
  py::gil_scoped_release release;
  return experiments::runSweep(sweep, options);
}

void analyzeJob(const std::string& dir, const std::string& out,
                const std::vector<std::string>& roots, bool figures) {
  py::gil_scoped_release release;
  const analysis::SweepAnalysis result =
      analysis::analyseSweep(dir, loadOptions(roots, std::nullopt));
  analysis::writeTables(result, out);
  if (figures) analysis::writeFigures(result, out);
}

}  // namespace

void bindJobs(py::module_& m) {
  m.def(
      "_run",
      [](const std::string& text, const std::string& file, const std::vector<std::string>& roots,
         const std::string& out, std::optional<std::uint64_t> seed, bool frames, int every,
         int width, int height) {
        if (every < 1) throw py::value_error("canopy.run: frame_every: expected an integer >= 1");
        return runJob(text, file, roots, out, seed, {frames, every, width, height});
      },
      py::arg("text"), py::arg("file"), py::arg("roots"), py::arg("out"), py::arg("seed"),
      py::arg("frames"), py::arg("every"), py::arg("width"), py::arg("height"));
  m.def("_sweep", &sweepJob, py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("roots"));
  m.def("_analyze", &analyzeJob, py::arg("dir"), py::arg("out"), py::arg("roots"),
        py::arg("figures"));
}

}  // namespace canopy::python
