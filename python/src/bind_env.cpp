// The compiled half of canopy.TrackingEnv and canopy.VectorEnv (python/canopy/env.py, vector.py):
// _Observer writes every agent's observation and reward of a Simulation's last step, and
// _VectorCore steps n simulations on a pool of threads with the GIL released, writing batched
// observations, rewards and end flags into numpy arrays it owns; with `altitude` (issue 53) each
// observation ends with the UAV's z and each action carries a climb rate vz, as TrackingEnv's.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "python/src/bindings.h"
#include "python/src/env_core.h"
#include "python/src/frame_render.h"
#include "python/src/py_simulation.h"
#include "python/src/scenario_source.h"
#include "sim/simulation.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style>;
using DoubleArray = py::array_t<double, py::array::c_style>;

bool fullTrace(const std::string& reward_trace) {
  if (reward_trace != "position" && reward_trace != "full") {
    throw py::value_error("reward_trace: expected 'position' or 'full', got '" + reward_trace +
                          "'");
  }
  return reward_trace == "full";
}

EnvLayout layoutFor(const spec::ScenarioSpec& spec, int max_tracks, int max_trees,
                    double map_radius, const std::string& reward_trace) {
  try {
    return makeLayout(spec, max_tracks, max_trees, map_radius, fullTrace(reward_trace));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

FloatArray boundsArray(const std::vector<float>& values) {
  return FloatArray(static_cast<py::ssize_t>(values.size()), values.data());
}

/// The data of `a`, a writable C-contiguous array of T and of `shape`; else a ValueError.
template <typename T>
T* writable(py::array a, const std::vector<py::ssize_t>& shape, const char* what) {
  const bool ok = py::isinstance<py::array_t<T>>(a) && a.writeable() &&
                  (a.flags() & py::array::c_style) != 0 &&
                  a.ndim() == static_cast<py::ssize_t>(shape.size()) &&
                  std::equal(shape.begin(), shape.end(), a.shape());
  if (!ok) {
    throw py::value_error(std::string(what) +
                          ": expected a writable C-contiguous array of the layout's shape");
  }
  return static_cast<T*>(a.mutable_data());
}

class Observer {
 public:
  Observer(const py::object& scenario, int max_tracks, int max_trees, double map_radius,
           const std::string& reward_trace) {
    const spec::ScenarioSpec spec = specOf(scenario);
    layout_ = layoutFor(spec, max_tracks, max_trees, map_radius, reward_trace);
    steps_ = spec.steps();
    dt_ = spec.dt;
    n_targets_ = static_cast<int>(spec.targets.size());
  }

  const EnvLayout& layout() const { return layout_; }
  int steps() const { return steps_; }
  double dt() const { return dt_; }
  int nTargets() const { return n_targets_; }

  /// Every agent's observation of `sim`'s last step into obs (n_agent, size) float32 and,
  /// unless None, its reward into rewards (n_agent,) float64.
  void observeAll(py::handle sim, const py::array& obs, const py::object& rewards) const {
    const sim::StepRecord& record = simulationOf(sim).record();
    const auto n = static_cast<py::ssize_t>(record.uavs.size());
    float* o = writable<float>(obs, {n, layout_.size()}, "observations");
    double* r = rewards.is_none() ? nullptr : writable<double>(py::array(rewards), {n}, "rewards");
    for (py::ssize_t i = 0; i < n; ++i) {
      observe(record, static_cast<int>(i), layout_, o + i * layout_.size());
      if (r) r[i] = stageReward(record, static_cast<int>(i), layout_.full_trace);
    }
  }

 private:
  EnvLayout layout_;
  int steps_ = 0;
  double dt_ = 0.0;
  int n_targets_ = 0;
};

/// n simulations of one scenario, stepped together on a TaskPool.
class VectorCore {
 public:
  VectorCore(const py::object& scenario, int n, const Observer& observer, int max_cycles,
             int threads, bool altitude)
      : spec_(std::make_shared<const spec::ScenarioSpec>(specOf(scenario))),
        layout_(observer.layout()),
        n_(n),
        agents_(static_cast<int>(spec_->uavs.size())),
        max_cycles_(max_cycles),
        altitude_(altitude),
        width_(altitude ? 3 : 2),
        obs_size_(layout_.size() + (altitude ? 1 : 0)),
        pool_(threads),
        sims_(static_cast<std::size_t>(n)),
        commands_(static_cast<std::size_t>(n) * static_cast<std::size_t>(agents_) *
                  static_cast<std::size_t>(width_)) {
    if (n < 1) throw py::value_error("VectorEnv: n: expected at least 1 environment");
    observations_ = FloatArray({n_, agents_, obs_size_});
    rewards_ = DoubleArray({n_, agents_});
    ended_ = py::array_t<bool>(n_);
    steps_ = py::array_t<std::int64_t>(n_);
    std::fill_n(observations_.mutable_data(), observations_.size(), 0.0F);
    std::fill_n(rewards_.mutable_data(), rewards_.size(), 0.0);
    std::fill_n(ended_.mutable_data(), n_, true);  // no episode yet
    std::fill_n(steps_.mutable_data(), n_, 0);
  }

  /// Starts a new episode in each env of `envs`, env envs[j] with seed seeds[j].
  void reset(const std::vector<int>& envs, const std::vector<std::uint64_t>& seeds) {
    if (envs.size() != seeds.size()) throw py::value_error("reset: one seed per environment");
    // By environment, not by position in `envs`: environment e is made on the thread that
    // steps it (TaskPool runs task e on the same thread every call).
    std::vector<std::optional<std::uint64_t>> seed_of(static_cast<std::size_t>(n_));
    for (std::size_t j = 0; j < envs.size(); ++j) {
      checkEnv(envs[j]);
      seed_of[static_cast<std::size_t>(envs[j])] = seeds[j];
    }
    float* obs = observations_.mutable_data();
    double* rew = rewards_.mutable_data();
    bool* ended = ended_.mutable_data();
    std::int64_t* steps = steps_.mutable_data();
    py::gil_scoped_release release;
    pool_.run(static_cast<std::size_t>(n_), [&](std::size_t e) {
      if (!seed_of[e]) return;
      spec::ScenarioSpec spec = *spec_;
      spec.seed = *seed_of[e];
      sims_[e] = std::make_unique<sim::Simulation>(std::move(spec));
      sims_[e]->tick();  // step 0, as canopy.Simulation
      writeStep(e, obs, rew, ended, steps);
      std::fill_n(rew + e * static_cast<std::size_t>(agents_), agents_, 0.0);
    });
  }

  /// One step of every env with actions (n, n_agent, 2) m/s — (n, n_agent, 3) with a climb rate
  /// vz (m/s) under `altitude` — but those in `hold` (their rows of the outputs stay as they are:
  /// Gymnasium's next-step autoreset resets them instead).
  void step(const py::handle& actions, const std::vector<int>& hold = {}) {
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    const Array a = Array::ensure(actions);
    if (!a || a.ndim() != 3 || a.shape(0) != n_ || a.shape(1) != agents_ || a.shape(2) != width_) {
      std::ostringstream text;
      text << "VectorEnv.step: actions: expected an array of shape (" << n_ << ", " << agents_
           << ", " << width_
           << (altitude_ ? ") (one velocity and climb rate (vx, vy, vz) per environment and agent, "
                           "m/s)"
                         : ") (one velocity per environment and agent, m/s)");
      throw py::value_error(text.str());
    }
    const double* v = a.data();
    const auto width = static_cast<std::size_t>(width_);
    for (std::size_t k = 0; k < commands_.size(); ++k) {
      if (!std::isfinite(v[k])) {
        const std::size_t e = k / (width * static_cast<std::size_t>(agents_));
        const std::size_t i = k / width % static_cast<std::size_t>(agents_);
        throw py::value_error("VectorEnv.step: actions[" + std::to_string(e) + ", " +
                              std::to_string(i) + "]: expected a finite velocity (m/s)");
      }
      commands_[k] = v[k];
    }
    std::vector<char> held(static_cast<std::size_t>(n_), 0);
    for (const int e : hold) {
      checkEnv(e);
      held[static_cast<std::size_t>(e)] = 1;
    }
    for (int e = 0; e < n_; ++e) {
      if (ended_.data()[e] && !held[static_cast<std::size_t>(e)])
        throw std::runtime_error("VectorEnv.step: environment " + std::to_string(e) +
                                 " has ended; reset it first");
    }
    float* obs = observations_.mutable_data();
    double* rew = rewards_.mutable_data();
    bool* ended = ended_.mutable_data();
    std::int64_t* steps = steps_.mutable_data();
    py::gil_scoped_release release;
    pool_.run(static_cast<std::size_t>(n_), [&](std::size_t e) {
      if (held[e]) return;
      sim::Simulation& sim = *sims_[e];
      const double* c = commands_.data() + e * width * static_cast<std::size_t>(agents_);
      for (std::size_t i = 0; i < static_cast<std::size_t>(agents_); ++i, c += width) {
        sim.commandNext(static_cast<int>(i), Vec2(c[0], c[1]));
        if (altitude_) sim.commandClimbNext(static_cast<int>(i), c[2]);  // kept in ±climb_rate
      }
      sim.tick();
      writeStep(e, obs, rew, ended, steps);
    });
  }

  /// Fresh copies of the step's outputs: (observations, rewards, ended, steps).
  py::tuple results() const {
    return py::make_tuple(copyOf(observations_), copyOf(rewards_), copyOf(ended_), copyOf(steps_));
  }

  /// Environment e's last step drawn as canopy.Simulation.render draws it, (height, width, 3).
  py::array_t<std::uint8_t> render(int e, int width, int height) {
    checkEnv(e);
    if (!sims_[static_cast<std::size_t>(e)])
      throw std::runtime_error("VectorEnv.render: environment " + std::to_string(e) +
                               " has no episode yet; call reset() first");
    return renderer_.render(*sims_[static_cast<std::size_t>(e)], width, height, "VectorEnv.render");
  }

  py::object observations() const { return observations_; }
  py::object rewards() const { return rewards_; }
  py::object ended() const { return ended_; }
  py::object steps() const { return steps_; }
  int threads() const { return pool_.threads(); }

 private:
  template <typename T, int Flags>
  static py::array_t<T, Flags> copyOf(const py::array_t<T, Flags>& a) {
    py::array_t<T, Flags> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
    std::copy_n(a.data(), a.size(), out.mutable_data());
    return out;
  }

  void checkEnv(int e) const {
    if (e < 0 || e >= n_)
      throw py::index_error("environment " + std::to_string(e) + " out of range (" +
                            std::to_string(n_) + ")");
  }

  void writeStep(std::size_t e, float* obs, double* rew, bool* ended, std::int64_t* steps) const {
    const sim::Simulation& sim = *sims_[e];
    const sim::StepRecord& record = sim.lastStep();
    const auto size = static_cast<std::size_t>(obs_size_);
    const auto agents = static_cast<std::size_t>(agents_);
    for (std::size_t i = 0; i < agents; ++i) {
      float* row = obs + (e * agents + i) * size;
      observe(record, static_cast<int>(i), layout_, row);
      if (altitude_) row[layout_.size()] = static_cast<float>(record.uavs[i].z);  // z last (m)
      rew[e * agents + i] = stageReward(record, static_cast<int>(i), layout_.full_trace);
    }
    steps[e] = record.step;
    ended[e] = sim.done() || (max_cycles_ >= 0 && record.step >= max_cycles_);
  }

  std::shared_ptr<const spec::ScenarioSpec> spec_;
  EnvLayout layout_;
  int n_, agents_, max_cycles_;
  bool altitude_;  // observations end with z, actions carry vz (issue 53)
  int width_;      // numbers per action: 2, or 3 with altitude
  int obs_size_;   // numbers per observation: the layout's, and z with altitude
  TaskPool pool_;
  std::vector<std::unique_ptr<sim::Simulation>> sims_;
  std::vector<double> commands_;
  FloatArray observations_;
  DoubleArray rewards_;
  py::array_t<bool> ended_;
  py::array_t<std::int64_t> steps_;
  FrameRenderer renderer_;  // GL starts on the first render only
};

}  // namespace

void bindEnv(py::module_& m) {
  py::class_<Observer>(m, "_Observer")
      .def(py::init<const py::object&, int, int, double, const std::string&>(), py::arg("scenario"),
           py::arg("max_tracks"), py::arg("max_trees"), py::arg("map_radius"),
           py::arg("reward_trace"))
      .def_property_readonly("size", [](const Observer& o) { return o.layout().size(); })
      .def_property_readonly("steps", &Observer::steps)
      .def_property_readonly("dt", &Observer::dt)
      .def_property_readonly("n_targets", &Observer::nTargets)
      .def_property_readonly("position_bound",
                             [](const Observer& o) { return o.layout().position; })
      .def_property_readonly("speed_bound", [](const Observer& o) { return o.layout().speed; })
      .def_property_readonly("low", [](const Observer& o) { return boundsArray(o.layout().low); })
      .def_property_readonly("high", [](const Observer& o) { return boundsArray(o.layout().high); })
      .def("observe_all", &Observer::observeAll, py::arg("sim"), py::arg("observations"),
           py::arg("rewards") = py::none());

  py::class_<VectorCore>(m, "_VectorCore")
      .def(py::init([](const py::object& scenario, int n, const Observer& observer, int max_cycles,
                       int threads, bool altitude) {
             if (threads <= 0)
               threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
             threads = std::min(threads, std::max(n, 1));
             return std::make_unique<VectorCore>(scenario, n, observer, max_cycles, threads,
                                                 altitude);
           }),
           py::arg("scenario"), py::arg("n"), py::arg("observer"), py::arg("max_cycles"),
           py::arg("threads"), py::arg("altitude") = false)
      .def("reset", &VectorCore::reset, py::arg("envs"), py::arg("seeds"))
      .def("step", &VectorCore::step, py::arg("actions"), py::arg("hold") = std::vector<int>{})
      .def(
          "step_results",
          [](VectorCore& core, const py::handle& actions, const std::vector<int>& hold) {
            core.step(actions, hold);
            return core.results();
          },
          py::arg("actions"), py::arg("hold") = std::vector<int>{},
          "step(actions, hold), then fresh copies of (observations, rewards, ended, steps)")
      .def("render", &VectorCore::render, py::arg("env"), py::arg("width"), py::arg("height"))
      .def_property_readonly("observations", &VectorCore::observations)
      .def_property_readonly("rewards", &VectorCore::rewards)
      .def_property_readonly("ended", &VectorCore::ended)
      .def_property_readonly("steps", &VectorCore::steps)
      .def_property_readonly("threads", &VectorCore::threads);
}

}  // namespace canopy::python
