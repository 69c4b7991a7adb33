// The per-step calls of canopy.Simulation as plain CPython methods and getters. pybind11's
// dispatcher costs about 1 650 instructions a call (it builds argument vectors on the heap and
// walks the overloads; callgrind, bench/RESULTS.md "Stepping from Python"), against about
// 90 000 for a step of the demo: `while not sim.done: sim.step()` plus one view read spent 8 %
// of a step in dispatch. These reach the C++ object in a few dozen instructions. step(commands)
// with commands goes on to the pybind11 method _step_commands, which checks them.
#include <exception>

#include "python/src/py_simulation.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

PyTypeObject* simulation_type = nullptr;  // canopy.Simulation, set by addFastMethods

/// The C++ object behind `self`, or null with a Python error set when `self` is not a
/// canopy.Simulation or its __init__ has not run.
PySimulation* simulationOrNull(PyObject* self) {
  if (!simulation_type || !PyObject_TypeCheck(self, simulation_type)) {
    PyErr_SetString(PyExc_TypeError, "expected a canopy.Simulation");
    return nullptr;
  }
  auto* instance = reinterpret_cast<py::detail::instance*>(self);
  const py::detail::value_and_holder v = instance->get_value_and_holder();
  if (!v.holder_constructed()) {
    PyErr_SetString(PyExc_RuntimeError, "canopy.Simulation: not initialised (__init__ not run)");
    return nullptr;
  }
  auto* sim = v.value_ptr<PySimulation>();
  if (sim->busy()) {
    PyErr_SetString(PyExc_RuntimeError,
                    "canopy.Simulation: another thread is stepping it (step() released the GIL); "
                    "use one Simulation per thread");
    return nullptr;
  }
  return sim;
}

template <typename Body>
PyObject* guarded(Body body) {
  try {
    return body();
  } catch (py::error_already_set& e) {
    e.restore();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

PyObject* step(PyObject* self, PyObject* const* args, Py_ssize_t nargs) {
  if (nargs > 1) {
    PyErr_SetString(PyExc_TypeError, "Simulation.step: expected at most one argument (commands)");
    return nullptr;
  }
  if (nargs == 1 && args[0] != Py_None) {
    static PyObject* name = PyUnicode_InternFromString("_step_commands");
    return PyObject_CallMethodOneArg(self, name, args[0]);
  }
  PySimulation* sim = simulationOrNull(self);
  if (!sim) return nullptr;
  return guarded([&] {
    sim->step(py::none());
    Py_RETURN_NONE;
  });
}

PyObject* done(PyObject* self, void*) {
  PySimulation* sim = simulationOrNull(self);
  if (!sim) return nullptr;
  return PyBool_FromLong(sim->sim().done());
}

PyObject* stepIndex(PyObject* self, void*) {
  PySimulation* sim = simulationOrNull(self);
  return sim ? PyLong_FromLong(sim->record().step) : nullptr;
}

PyObject* time(PyObject* self, void*) {
  PySimulation* sim = simulationOrNull(self);
  return sim ? PyFloat_FromDouble(sim->record().time) : nullptr;
}

template <py::object (*Read)(PySimulation&)>
PyObject* view(PyObject* self, void*) {
  PySimulation* sim = simulationOrNull(self);
  if (!sim) return nullptr;
  return guarded([&] { return Read(*sim).release().ptr(); });
}

PyMethodDef kStep{"step", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&step)),
                  METH_FASTCALL,
                  "step(commands=None): advances one step; commands: None or (n_uav, 2) "
                  "velocities (m/s) for this step, clamped to each UAV's v_max."};

}  // namespace

PySimulation& simulationOf(py::handle self) {
  PySimulation* sim = simulationOrNull(self.ptr());
  if (!sim) throw py::error_already_set();
  return *sim;
}

void addFastMethods(py::class_<PySimulation>& cls) {
  auto* type = reinterpret_cast<PyTypeObject*>(cls.ptr());
  simulation_type = type;
  static PyGetSetDef getters[] = {
      {"done", &done, nullptr, "True once steps 0..K have all run.", nullptr},
      {"step_index", &stepIndex, nullptr, "k of the last step run.", nullptr},
      {"time", &time, nullptr, "t = k·dt of the last step (s).", nullptr},
      {"uav_states", &view<&uavStatesView>, nullptr,
       "(n_uav, 3) x, y (m), yaw (rad): a read-only view of the last step (the same array every "
       "step)",
       nullptr},
      {"target_states", &view<&targetStatesView>, nullptr,
       "(n_target, 4) x, y (m), vx, vy (m/s): a read-only view of the last step (the same array "
       "every step)",
       nullptr},
  };
  for (PyGetSetDef& getter : getters)
    cls.attr(getter.name) = py::reinterpret_steal<py::object>(PyDescr_NewGetSet(type, &getter));
  cls.attr("step") = py::reinterpret_steal<py::object>(PyDescr_NewMethod(type, &kStep));
}

}  // namespace canopy::python
