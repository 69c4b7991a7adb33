#pragma once
// canopy.Simulation: a sim::Simulation driven from Python. Constructing one runs step 0
// (the initial sensing), so the readers always have a step to show and every step() advances
// the world by dt; step(commands) replaces the planner's (or path's) command for that one step
// (Simulation::commandNext), clamped to each UAV's v_max.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

#include "agents/planning/team_planner.h"
#include "python/src/frame_render.h"
#include "sim/simulation.h"

namespace canopy::python {

class PySimulation {
 public:
  explicit PySimulation(spec::ScenarioSpec spec);

  /// One step. commands: None, or an (n_uav, 2) array-like of velocities (m/s). Raises
  /// ValueError for a wrong shape or a non-finite command, RuntimeError when done. The tick runs
  /// without the GIL (other Python threads run meanwhile); the simulation is marked busy then.
  void step(const pybind11::handle& commands);
  /// True while step() runs its tick without the GIL: no reader may look at the record then.
  bool busy() const { return busy_.load(std::memory_order_acquire); }

  const sim::Simulation& sim() const { return *sim_; }
  const sim::StepRecord& record() const { return sim_->lastStep(); }
  /// The truth views (bind_readers.cpp), made on first use and handed out again every step: the
  /// record's per-UAV and per-target vectors never move, so reading them allocates nothing.
  /// Their owner is a capsule sharing the simulation, not this object, so there is no cycle.
  struct Views {
    pybind11::object uav_states, uav_velocities, uav_commands, target_states;
  };
  Views& views() { return views_; }
  /// An object that keeps the simulation alive, for the base of a numpy view.
  pybind11::object viewOwner();
  /// The plan of the last planning epoch so far (none before the first, or without a planner).
  const std::optional<agents::planning::TeamPlan>& lastPlan() const { return last_plan_; }
  /// The current step drawn by the CLI's renderer (no trails), (height, width, 3) uint8.
  pybind11::array_t<std::uint8_t> render(int width, int height);

 private:
  void applyCommands(const pybind11::handle& commands);
  void keepPlan();

  std::shared_ptr<sim::Simulation> sim_;
  std::atomic<bool> busy_{false};
  pybind11::object owner_;  // capsule holding a share of sim_
  Views views_;
  std::optional<agents::planning::TeamPlan> last_plan_;
  FrameRenderer renderer_;  // GL starts on the first render only
};

/// The C++ object behind a canopy.Simulation; throws std::runtime_error when its __init__ has
/// not run (Simulation.__new__ alone leaves pybind11's storage unconstructed), so that every
/// method checks before it reads (fast_methods.cpp).
PySimulation& simulationOf(pybind11::handle self);

/// The readers (bind_readers.cpp): numpy views of the truth, copies of the variable-size lists.
void bindReaders(pybind11::class_<PySimulation>& cls);
/// The cached truth views (bind_readers.cpp), for the fast getters.
pybind11::object uavStatesView(PySimulation& s);
pybind11::object targetStatesView(PySimulation& s);
/// step, done, step_index, time, uav_states and target_states as plain CPython methods and
/// getters, replacing pybind11's (fast_methods.cpp).
void addFastMethods(pybind11::class_<PySimulation>& cls);

}  // namespace canopy::python
