// canopy.Simulation: stepping with the scenario's planner or with commands from Python.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "python/src/bindings.h"
#include "python/src/py_simulation.h"
#include "python/src/scenario_source.h"
#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/viewport.h"
#include "sim/recorder.h"
#include "spec/error.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

// None, or an integer in [0, 2⁶⁴ − 1] (not a bool): the CLI's --seed.
std::optional<std::uint64_t> seedOf(const py::object& seed, const std::string& function) {
  if (seed.is_none()) return std::nullopt;
  if (!py::isinstance<py::int_>(seed) || py::isinstance<py::bool_>(seed)) {
    throw spec::ScenarioError(function, "seed",
                              "expected None or an integer in [0, 2^64 - 1], got " +
                                  py::repr(seed).cast<std::string>().substr(0, 60));
  }
  if (seed < py::int_(0) || seed > py::int_(std::numeric_limits<std::uint64_t>::max())) {
    throw spec::ScenarioError(function, "seed",
                              "expected an integer in [0, 2^64 - 1], got " +
                                  py::repr(seed).cast<std::string>().substr(0, 60));
  }
  return seed.cast<std::uint64_t>();
}

std::string shapeText(const py::array& a) {
  std::ostringstream text;
  text << "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text << (d ? ", " : "") << a.shape(d);
  text << (a.ndim() == 1 ? ",)" : ")");
  return text.str();
}

}  // namespace

PySimulation::PySimulation(spec::ScenarioSpec spec)
    : sim_(std::make_shared<sim::Simulation>(std::move(spec))) {
  sim_->tick();  // step 0: the initial sensing, no motion
  keepPlan();
}

py::object PySimulation::viewOwner() {
  if (!owner_) {
    auto* share = new std::shared_ptr<sim::Simulation>(sim_);
    owner_ = py::capsule(share,
                         [](void* p) { delete static_cast<std::shared_ptr<sim::Simulation>*>(p); });
  }
  return owner_;
}

void PySimulation::keepPlan() {
  if (sim_->lastStep().plan) last_plan_ = *sim_->lastStep().plan;
}

void PySimulation::applyCommands(const py::handle& commands) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Array a = Array::ensure(commands);
  const auto n = static_cast<py::ssize_t>(sim_->spec().uavs.size());
  if (!a) {
    throw spec::ScenarioError("Simulation.step", "commands",
                              "expected an array of numbers of shape (" + std::to_string(n) +
                                  ", 2) (m/s), got " +
                                  py::str(py::type::of(commands)).cast<std::string>());
  }
  // (n, 2) velocities, or (n, 3) with each UAV's climb rate (m/s, issue 53) as the third column.
  if (a.ndim() != 2 || a.shape(0) != n || (a.shape(1) != 2 && a.shape(1) != 3)) {
    throw spec::ScenarioError("Simulation.step", "commands",
                              "expected shape (" + std::to_string(n) +
                                  ", 2) (one velocity per UAV, m/s) or (" + std::to_string(n) +
                                  ", 3) (with a climb rate, m/s), got " + shapeText(a));
  }
  const auto v = a.unchecked<2>();
  const bool climbs = a.shape(1) == 3;
  for (py::ssize_t i = 0; i < n; ++i) {
    if (!std::isfinite(v(i, 0)) || !std::isfinite(v(i, 1)) ||
        (climbs && !std::isfinite(v(i, 2)))) {
      std::ostringstream text;
      text << "expected a finite velocity (m/s), got (" << v(i, 0) << ", " << v(i, 1)
           << (climbs ? ", " + std::to_string(v(i, 2)) : std::string()) << ")";
      throw spec::ScenarioError("Simulation.step", "commands[" + std::to_string(i) + "]",
                                text.str());
    }
  }
  for (py::ssize_t i = 0; i < n; ++i) {
    sim_->commandNext(static_cast<int>(i), Vec2(v(i, 0), v(i, 1)));
    if (climbs) sim_->commandClimbNext(static_cast<int>(i), v(i, 2));
  }
}

void PySimulation::step(const py::handle& commands) {
  if (sim_->done()) {
    throw std::runtime_error("Simulation.step: the run is done (it ended at step " +
                             std::to_string(sim_->spec().steps()) + ")");
  }
  if (!commands.is_none()) applyCommands(commands);
  // The tick touches no Python object: other threads run Python (or step other simulations)
  // meanwhile. A second thread that reaches this simulation meanwhile gets a RuntimeError
  // (simulationOf checks busy()), never a half-written record.
  struct Busy {
    std::atomic<bool>& flag;
    explicit Busy(std::atomic<bool>& f) : flag(f) { flag.store(true, std::memory_order_release); }
    ~Busy() { flag.store(false, std::memory_order_release); }
  } busy(busy_);
  py::gil_scoped_release release;
  sim_->tick();
  keepPlan();
}

py::array_t<std::uint8_t> PySimulation::render(int width, int height) {
  return renderer_.render(*sim_, width, height, "Simulation.render");
}

void bindSimulation(py::module_& m) {
  py::class_<PySimulation> cls(m, "Simulation", R"(A scenario stepped from Python.

Simulation(scenario, seed=None) runs step 0 (the initial sensing); each step() then advances the
world by dt with the scenario's planner or script, and step(commands) with an (n_uav, 2) array of
velocities (m/s, clamped to each UAV's v_max) instead, for that step only; an (n_uav, 3) array adds
each UAV's climb rate (m/s, clamped to its climb_rate and kept within [z_min, z_max]). The planner still plans
on its schedule (its plans are recorded as if flown). The readers show the last step.)");
  cls.def(py::init([](const py::object& scenario, const py::object& seed) {
            if (!py::hasattr(scenario, "_spec")) {
              throw spec::ScenarioError(
                  "Simulation", "scenario",
                  "expected a canopy.Scenario (canopy.load(NAME_OR_FILE) makes one), got " +
                      py::str(py::type::of(scenario)).cast<std::string>());
            }
            return std::make_unique<PySimulation>(specOf(scenario, seedOf(seed, "Simulation")));
          }),
          py::arg("scenario"), py::arg("seed") = py::none())
      .def(
          "_step_commands",
          [](py::handle self, py::handle commands) { simulationOf(self).step(commands); },
          py::arg("commands"))
      .def_property_readonly(
          "steps",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            return s.sim().spec().steps() + 1;
          },
          "The steps a run records, k = 0..K (K + 1: as `canopy validate` counts them and "
          "record.jsonl holds lines).")
      .def_property_readonly(
          "last_step",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            return s.sim().spec().steps();
          },
          "K = duration / dt: the last step, step_index when the run is done.")
      .def_property_readonly("dt",
                             [](py::handle self) {
                               const PySimulation& s = simulationOf(self);
                               return s.sim().spec().dt;
                             })
      .def_property_readonly("seed",
                             [](py::handle self) {
                               const PySimulation& s = simulationOf(self);
                               return s.sim().spec().seed;
                             })
      .def_property_readonly("n_uavs",
                             [](py::handle self) {
                               const PySimulation& s = simulationOf(self);
                               return s.record().uavs.size();
                             })
      .def_property_readonly("n_targets",
                             [](py::handle self) {
                               const PySimulation& s = simulationOf(self);
                               return s.record().targets.size();
                             })
      .def_property_readonly(
          "v_max",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            py::array_t<double> out(static_cast<py::ssize_t>(s.record().uavs.size()));
            for (std::size_t i = 0; i < s.sim().spec().uavs.size(); ++i)
              out.mutable_at(i) = s.sim().spec().uavs[i].body.v_max;
            return out;
          },
          "Each UAV's speed limit (m/s).")
      .def_property_readonly(
          "uav_altitudes",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            py::array_t<double> out(static_cast<py::ssize_t>(s.record().uavs.size()));
            for (std::size_t i = 0; i < s.record().uavs.size(); ++i)
              out.mutable_at(i) = s.record().uavs[i].z;
            return out;
          },
          "Each UAV's altitude at the last step (m; issue 53): it changes for a UAV whose "
          "scenario gives altitude limits, by the planner's climbs or step()'s third column.")
      .def_property_readonly(
          "labels",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            return s.sim().spec().labels;
          },
          "Label names by id (labels[0] is \"tree\").")
      .def(
          "record_line",
          [](py::handle self) {
            const PySimulation& s = simulationOf(self);
            return sim::recordLine(s.sim().spec().labels, s.record());
          },
          "The last step as the line record.jsonl holds for it (JSON text).")
      .def(
          "render",
          [](py::handle self, const py::object& width, const py::object& height) {
            // Typed like every public entry point: ScenarioError naming the argument.
            auto side = [](const py::object& value, const char* name) {
              if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value) ||
                  value < py::int_(render::kMinImageSide) ||
                  value > py::int_(render::kMaxImageSide)) {
                throw spec::ScenarioError("Simulation.render", name,
                                          "expected width and height integers in [" +
                                              std::to_string(render::kMinImageSide) + ", " +
                                              std::to_string(render::kMaxImageSide) + "] px, got " +
                                              py::repr(value).cast<std::string>().substr(0, 60));
              }
              return value.cast<int>();
            };
            return simulationOf(self).render(side(width, "width"), side(height, "height"));
          },
          py::arg("width") = 800, py::arg("height") = 600,
          "The last step drawn by the CLI's renderer (OSMesa), an (height, width, 3) uint8 array.");
  bindReaders(cls);
  addFastMethods(cls);
}

}  // namespace canopy::python
