// _canopy: the compiled half of the `canopy` Python package (python/canopy/ is the other half).
#include "python/src/bindings.h"

PYBIND11_MODULE(_canopy, m) {
  m.doc() = "canopy's C++ core: scenarios, layout generators, stepping, whole runs";
  canopy::python::bindScenario(m);
  canopy::python::bindForest(m);
  canopy::python::bindSimulation(m);
  canopy::python::bindJobs(m);
  canopy::python::bindEnv(m);
}
