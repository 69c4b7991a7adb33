// Layout generators for Python: canopy.forest (python/canopy/forest.py) writes a generator as
// the scenario grammar's occluder element and the loader's own reader draws it, so the checks,
// defaults and trees are those of a scenario file with the same element.
#include <string>

#include "python/src/bindings.h"
#include "spec/loader.h"

namespace py = pybind11;

namespace canopy::python {
namespace {

py::list point(const Vec2& p) {
  py::list out;
  out.append(p.x());
  out.append(p.y());
  return out;
}

py::dict treeDict(const world::TreeDef& tree) {
  py::dict out;
  if (tree.shape == world::TreeShape::disc) {
    out["type"] = "disc";
    out["centre"] = point(tree.centre);
    out["radius"] = tree.radius;
  } else {
    out["type"] = "polygon";
    py::list vertices;
    for (const Vec2& v : tree.vertices) vertices.append(point(v));
    out["vertices"] = vertices;
  }
  return out;
}

}  // namespace

void bindForest(py::module_& m) {
  m.def(
      "_layout",
      [](const std::string& text, const std::string& name) {
        py::list trees;
        for (const world::TreeDef& tree : spec::layoutFromText(text, name))
          trees.append(treeDict(tree));
        return trees;
      },
      py::arg("text"), py::arg("name"),
      "The trees an occluder list (JSON text) generates, as explicit disc/polygon elements.");
}

}  // namespace canopy::python
