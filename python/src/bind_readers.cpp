// The readers of canopy.Simulation. The truth is read without copying: numpy views with the
// record's stride over UavRecord / TargetRecord, whose fields sit next to each other (checked
// at run time; a copy otherwise). Those vectors are sized once, so a view stays valid for the
// simulation's life, shows the current step and is read-only; the same array object is returned
// at every step. Scans, tracks, maps and plans vary
// in length from step to step (their storage may move), so they are copied into new arrays.
#include <pybind11/numpy.h>

#include <cstddef>
#include <string>
#include <vector>

#include "python/src/py_simulation.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

using sim::StepRecord;

const char* bytes(const void* p) {
  return static_cast<const char*>(p);
}

/// A read-only (rows, cols) view of doubles starting at `first`, rows `row_stride` bytes apart;
/// `owner` (a capsule sharing the simulation) is kept alive by the array.
py::array view(const double* first, std::size_t rows, std::size_t cols, std::size_t row_stride,
               const py::handle& owner) {
  py::array out(py::dtype::of<double>(),
                {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)},
                {static_cast<py::ssize_t>(row_stride), static_cast<py::ssize_t>(sizeof(double))},
                first, owner);
  py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}

/// Copies `rows` rows of `cols` doubles, each read by `row(i, out_row)`.
template <typename Row>
py::array_t<double> copyRows(std::size_t rows, std::size_t cols, Row row) {
  py::array_t<double> out({rows, cols});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < rows; ++i) row(i, data + i * cols);
  return out;
}

/// The cached view in `slot`, made by `make(owner)` on first use; `make` returns None when the
/// layout does not allow a view, and then `copy()` is called every time.
template <typename Make, typename Copy>
py::object cachedView(PySimulation& s, py::object& slot, Make make, Copy copy) {
  if (!slot) slot = make(s.viewOwner());
  return slot.is_none() ? py::object(copy()) : slot;
}

}  // namespace

py::object uavStatesView(PySimulation& s) {
  const auto& u = s.record().uavs;
  return cachedView(
      s, s.views().uav_states,
      [&](const py::object& owner) -> py::object {
        if (!u.empty() && bytes(&u[0].yaw) == bytes(u[0].position.data() + 2))
          return view(u[0].position.data(), u.size(), 3, sizeof(u[0]), owner);
        return py::none();
      },
      [&] {
        return copyRows(u.size(), 3, [&](std::size_t i, double* o) {
          o[0] = u[i].position.x(), o[1] = u[i].position.y(), o[2] = u[i].yaw;
        });
      });
}

py::object targetStatesView(PySimulation& s) {
  const auto& t = s.record().targets;
  return cachedView(
      s, s.views().target_states,
      [&](const py::object& owner) -> py::object {
        if (!t.empty() && bytes(t[0].velocity.data()) == bytes(t[0].position.data() + 2))
          return view(t[0].position.data(), t.size(), 4, sizeof(t[0]), owner);
        return py::none();
      },
      [&] {
        return copyRows(t.size(), 4, [&](std::size_t i, double* o) {
          o[0] = t[i].position.x(), o[1] = t[i].position.y();
          o[2] = t[i].velocity.x(), o[3] = t[i].velocity.y();
        });
      });
}

namespace {

template <typename Member>
py::object uavVec2(PySimulation& s, py::object& slot, Member member) {
  const auto& u = s.record().uavs;
  return cachedView(
      s, slot,
      [&](const py::object& owner) -> py::object {
        if (u.empty()) return py::array_t<double>(std::vector<py::ssize_t>{0, 2});
        return view((u[0].*member).data(), u.size(), 2, sizeof(u[0]), owner);
      },
      [] { return py::none(); });
}

py::array targetOccluded(py::handle self) {
  const PySimulation& s = simulationOf(self);
  const auto& t = s.record().targets;
  py::array_t<bool> out(static_cast<py::ssize_t>(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i) out.mutable_at(i) = t[i].occluded;
  return out;
}

void checkIndex(std::size_t index, std::size_t count, const char* what) {
  if (index >= count) {
    throw py::index_error(std::string(what) + " " + std::to_string(index) + " out of range (" +
                          std::to_string(count) + ")");
  }
}

py::dict scan(py::handle self, std::size_t uav) {
  const PySimulation& s = simulationOf(self);
  checkIndex(uav, s.record().uavs.size(), "UAV");
  const sensing::Scan& scan = s.record().uavs[uav].scan;
  const auto& obs = scan.observations;
  const std::size_t m = obs.size();
  py::array_t<double> z({m, std::size_t{2}}), R({m, std::size_t{2}, std::size_t{2}});
  py::array_t<long> labels(static_cast<py::ssize_t>(m)), truth(static_cast<py::ssize_t>(m));
  py::array_t<double> radius(static_cast<py::ssize_t>(m));
  for (std::size_t j = 0; j < m; ++j) {
    z.mutable_at(j, 0) = obs[j].z.x(), z.mutable_at(j, 1) = obs[j].z.y();
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) R.mutable_at(j, a, b) = obs[j].R(a, b);
    labels.mutable_at(j) = obs[j].label;
    truth.mutable_at(j) = obs[j].truth;
    radius.mutable_at(j) = obs[j].radius;
  }
  py::dict out;
  out["z"] = z;            // (m, 2) m
  out["R"] = R;            // (m, 2, 2) m²
  out["labels"] = labels;  // (m,) label ids (Simulation.labels names them)
  out["truth"] = truth;    // (m,) target or tree index, −1 for clutter (analysis only)
  out["radius"] = radius;  // (m,) m, trees only
  out["in_footprint"] = py::array_t<long>(
      static_cast<py::ssize_t>(scan.in_footprint.size()),
      std::vector<long>(scan.in_footprint.begin(), scan.in_footprint.end()).data());
  out["visible"] =
      py::array_t<long>(static_cast<py::ssize_t>(scan.visible.size()),
                        std::vector<long>(scan.visible.begin(), scan.visible.end()).data());
  return out;
}

template <int N, typename Estimate>
py::dict gaussians(const std::vector<Estimate>& list) {
  const std::size_t m = list.size();
  const std::size_t n = N;
  py::array_t<long> keys({m, std::size_t{2}});
  py::array_t<double> means({m, n}), covariances({m, n, n});
  for (std::size_t j = 0; j < m; ++j) {
    keys.mutable_at(j, 0) = list[j].key.origin, keys.mutable_at(j, 1) = list[j].key.serial;
    for (int a = 0; a < N; ++a) {
      means.mutable_at(j, a) = list[j].belief.x(a);
      for (int b = 0; b < N; ++b) covariances.mutable_at(j, a, b) = list[j].belief.P(a, b);
    }
  }
  py::dict out;
  out["keys"] = keys;  // (m, 2): (origin agent, serial)
  out["means"] = means;
  out["covariances"] = covariances;
  return out;
}

py::dict tracks(py::handle self, std::size_t agent) {
  const PySimulation& s = simulationOf(self);
  checkIndex(agent, s.record().beliefs.size(), "agent");
  const auto& list = s.record().beliefs[agent].tracks;
  py::dict out = gaussians<4>(list);  // means (m, 4) px, py, vx, vy; covariances (m, 4, 4)
  py::array_t<long> labels(static_cast<py::ssize_t>(list.size()));
  py::array_t<bool> confirmed(static_cast<py::ssize_t>(list.size()));
  py::array_t<double> existence(static_cast<py::ssize_t>(list.size()));
  for (std::size_t j = 0; j < list.size(); ++j) {
    labels.mutable_at(j) = list[j].label;
    confirmed.mutable_at(j) = list[j].confirmed;
    existence.mutable_at(j) = list[j].existence;
  }
  out["labels"] = labels;
  out["confirmed"] = confirmed;
  out["existence"] = existence;  // probability of existence (JIPDA)
  return out;
}

py::dict occlusionMap(py::handle self, std::size_t agent) {
  const PySimulation& s = simulationOf(self);
  checkIndex(agent, s.record().beliefs.size(), "agent");
  const auto& trees = s.record().beliefs[agent].trees;
  py::dict out = gaussians<3>(trees);  // means (m, 3) cx, cy, r (m)
  // Per tree, its estimated outline's vertices (k, 2) in m, centre + offsets; (0, 2) for a disc.
  py::list outlines;
  for (const agents::TreeEstimate& tree : trees) {
    const Vec2 centre = tree.belief.x.head<2>();
    outlines.append(
        copyRows(static_cast<std::size_t>(tree.outline.vertices), 2, [&](std::size_t v, double* o) {
          const Vec2 p = centre + tree.outline.offsets[v];
          o[0] = p.x(), o[1] = p.y();
        }));
  }
  out["outlines"] = outlines;
  return out;
}

py::array_t<double> vec2Rows(const std::vector<Vec2>& points) {
  return copyRows(points.size(), 2,
                  [&](std::size_t i, double* o) { o[0] = points[i].x(), o[1] = points[i].y(); });
}

py::object plan(py::handle self) {
  const PySimulation& s = simulationOf(self);
  if (!s.lastPlan()) return py::none();
  const agents::planning::TeamPlan& plan = *s.lastPlan();
  py::list velocities;
  py::array_t<double> costs(static_cast<py::ssize_t>(plan.plans.size()));
  std::vector<Vec2> commands;
  for (std::size_t i = 0; i < plan.plans.size(); ++i) {
    velocities.append(vec2Rows(plan.plans[i].velocities));
    costs.mutable_at(i) = plan.plans[i].cost;
    commands.push_back(plan.plans[i].command());
  }
  py::dict out;
  out["epoch"] = plan.epoch;
  out["commands"] = vec2Rows(commands);  // (n_uav, 2) m/s, the first actions
  out["velocities"] = velocities;        // per UAV (H, 2) m/s
  out["costs"] = costs;                  // per UAV, m²
  return out;
}

}  // namespace

void bindReaders(py::class_<PySimulation>& cls) {
  cls.def_property_readonly(
         "uav_velocities",
         [](py::handle self) {
           PySimulation& s = simulationOf(self);
           return uavVec2(s, s.views().uav_velocities, &sim::UavRecord::velocity);
         },
         "(n_uav, 2) m/s flown over the last step (view)")
      .def_property_readonly(
          "uav_commands",
          [](py::handle self) {
            PySimulation& s = simulationOf(self);
            return uavVec2(s, s.views().uav_commands, &sim::UavRecord::command);
          },
          "(n_uav, 2) m/s, the planner's or path's command for the next step, clamped (view)")
      .def_property_readonly("target_occluded", &targetOccluded,
                             "(n_target,) bool: strictly under a crown")
      .def("scan", &scan, py::arg("uav"),
           "UAV's scan at the last step: z (m, 2), R (m, 2, 2), labels, truth, radius, "
           "in_footprint, visible")
      .def("tracks", &tracks, py::arg("agent"),
           "Agent's fused target tracks: keys (m, 2), labels, confirmed, existence, means (m, 4), "
           "covariances (m, 4, 4)")
      .def("occlusion_map", &occlusionMap, py::arg("agent"),
           "Agent's occlusion map: keys (m, 2), means (m, 3) cx, cy, r, covariances (m, 3, 3), "
           "outlines: per tree its polygon's vertices (k, 2), (0, 2) for a disc")
      .def(
          "planned_path",
          [](py::handle self, std::size_t agent) {
            const PySimulation& s = simulationOf(self);
            checkIndex(agent, s.record().beliefs.size(), "agent");
            return vec2Rows(s.record().beliefs[agent].planned_path);
          },
          py::arg("agent"), "Agent's planned positions (H, 2) m (empty without a planner)")
      .def_property_readonly("plan", &plan,
                             "The last planning epoch's plan (epoch, commands, velocities, costs), "
                             "or None");
}

}  // namespace canopy::python
