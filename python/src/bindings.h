#pragma once
// The parts of the _canopy extension module, one file each: scenarios as JSON text, the layout
// generators, stepping a simulation, its numpy readers, whole jobs (run, sweep, analyze) and the
// environments' compiled half (observations, rewards, many simulations on threads).
#include <pybind11/pybind11.h>

namespace canopy::python {

void bindScenario(pybind11::module_& m);
void bindForest(pybind11::module_& m);
void bindSimulation(pybind11::module_& m);
void bindJobs(pybind11::module_& m);
void bindEnv(pybind11::module_& m);

}  // namespace canopy::python
