// Whole jobs from Python, as the command line runs them: run (manifest, record, summary and
// optional frames), sweep (trials on a thread pool, resumable) and analyze (the CSV tables and
// figures; python/canopy/jobs.py reads the tables into numpy arrays). The GIL is released while
// they run: they touch no Python object.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/sweep_analysis.h"
#include "core/output_file.h"
#include "core/text_file.h"
#include "experiments/sweep.h"
#include "python/src/bindings.h"
#include "python/src/scenario_source.h"
#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/frame_writer.h"
#include "render/viewport.h"
#include "sim/record_reader.h"
#include "sim/run.h"
#include "spec/error.h"
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
  sim::checkRunOutputs(options.out_dir);  // before the frame writer makes anything
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
  checkOutputEntries(out);
  py::gil_scoped_release release;
  return experiments::runSweep(sweep, options);
}

void analyzeJob(const std::string& dir, const std::string& out,
                const std::vector<std::string>& roots, bool figures) {
  checkOutputEntries(out);
  py::gil_scoped_release release;
  const analysis::SweepAnalysis result =
      analysis::analyseSweep(dir, loadOptions(roots, std::nullopt));
  analysis::writeTables(result, out);
  if (figures) analysis::writeFigures(result, out);
}

/// The truth of a finished run through the one record reader (sim/record_reader.h), as arrays:
/// k (K), t (K), uav_positions (K, U, 2), uav_yaw (K, U), target_positions (K, T, 2).
py::dict readRunJob(const std::string& dir, std::uint64_t first, std::uint64_t end) {
  sim::RunRecord run;
  {
    py::gil_scoped_release release;
    run = sim::readRun(dir, {first, end});
  }
  const auto K = static_cast<py::ssize_t>(run.truth.size());
  const auto U = static_cast<py::ssize_t>(run.spec.uavs.size());
  const auto T = static_cast<py::ssize_t>(run.spec.targets.size());
  py::array_t<long long> k(K);
  py::array_t<double> t(K), uav_yaw({K, U}), uav_positions({K, U, py::ssize_t{2}}),
      target_positions({K, T, py::ssize_t{2}});
  auto k_ = k.mutable_unchecked<1>();
  auto t_ = t.mutable_unchecked<1>();
  auto yaw = uav_yaw.mutable_unchecked<2>();
  auto up = uav_positions.mutable_unchecked<3>();
  auto tp = target_positions.mutable_unchecked<3>();
  for (py::ssize_t s = 0; s < K; ++s) {
    const world::WorldSnapshot& step = run.truth[static_cast<std::size_t>(s)];
    k_(s) = step.step;
    t_(s) = step.time;
    for (py::ssize_t i = 0; i < U; ++i) {
      const world::UavState& uav = step.uavs[static_cast<std::size_t>(i)];
      yaw(s, i) = uav.yaw;
      up(s, i, 0) = uav.position.x();
      up(s, i, 1) = uav.position.y();
    }
    for (py::ssize_t j = 0; j < T; ++j) {
      const Vec2& p = step.targets[static_cast<std::size_t>(j)].position;
      tp(s, j, 0) = p.x();
      tp(s, j, 1) = p.y();
    }
  }
  py::dict out;
  out["k"] = k;
  out["t"] = t;
  out["uav_positions"] = uav_positions;
  out["uav_yaw"] = uav_yaw;
  out["target_positions"] = target_positions;
  return out;
}

}  // namespace

void bindJobs(py::module_& m) {
  // An output path that is not ours (a device, FIFO, socket or directory): bad input, as the
  // command line's exit code 2, so a ValueError; other failed writes stay RuntimeErrors.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const OutputRefused& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def(
      "_write_file",
      [](const std::string& path, const std::string& text) { writeFileAtomically(path, text); },
      py::arg("path"), py::arg("text"),
      "Writes text to a new temporary beside path and renames it over path (core/output_file.h): "
      "never through a link, never over a device, FIFO, socket or directory.");
  m.def(
      "_run",
      [](const std::string& text, const std::string& file, const std::vector<std::string>& roots,
         const std::string& out, std::optional<std::uint64_t> seed, bool frames, int every,
         int width, int height) {
        if (every < 1 || every > 1000000) {
          throw spec::ScenarioError(
              "canopy.run", "frame_every",
              "expected an integer in [1, 1000000], got " + std::to_string(every));
        }
        const bool default_size = width == 0 && height == 0;
        if (!default_size && (width < render::kMinImageSide || width > render::kMaxImageSide ||
                              height < render::kMinImageSide || height > render::kMaxImageSide)) {
          throw spec::ScenarioError(
              "canopy.run", "size",
              "expected (width, height) in [" + std::to_string(render::kMinImageSide) + ", " +
                  std::to_string(render::kMaxImageSide) + "] px, got (" + std::to_string(width) +
                  ", " + std::to_string(height) + ")");
        }
        return runJob(text, file, roots, out, seed, {frames, every, width, height});
      },
      py::arg("text"), py::arg("file"), py::arg("roots"), py::arg("out"), py::arg("seed"),
      py::arg("frames"), py::arg("every"), py::arg("width"), py::arg("height"));
  m.def(
      "_sweep",
      [](const std::string& file, const std::string& out, int jobs,
         const std::vector<std::string>& roots) {
        if (jobs < 1 || jobs > 1024)  // the CLI's --jobs range
          throw spec::ScenarioError(
              "canopy.sweep", "jobs",
              "expected an integer in [1, 1024], got " + std::to_string(jobs));
        return sweepJob(file, out, jobs, roots);
      },
      py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("roots"));
  m.def("_image_sides",
        [] { return std::make_pair(render::kMinImageSide, render::kMaxImageSide); });
  m.def("_read_run", &readRunJob, py::arg("dir"), py::arg("first"), py::arg("end"));
  // The record's lines [first, end) as bytes, from either form (sim/record_lines.h).
  m.def(
      "_record_lines",
      [](const std::string& dir, std::uint64_t first, std::uint64_t end) {
        std::vector<std::string> lines;
        {
          py::gil_scoped_release release;
          sim::forEachRecordLine(sim::recordFileOf(dir), {first, end},
                                 [&](const std::string& line, int) { lines.push_back(line); });
        }
        py::list out;
        for (const std::string& line : lines) out.append(py::bytes(line));
        return out;
      },
      py::arg("dir"), py::arg("first"), py::arg("end"));
  m.def("_analyze", &analyzeJob, py::arg("dir"), py::arg("out"), py::arg("roots"),
        py::arg("figures"));
}

}  // namespace canopy::python
