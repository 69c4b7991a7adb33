"""Layout generators: each returns a list of explicit trees (occluder elements
``{"type": "disc", "centre": [x, y], "radius": r}``) to put in ``Scenario.occluders``.

The generators are the scenario grammar's (``"type": "poisson"`` and so on, docs in
scenarios/library/demo.json): the arguments become that element and canopy's loader draws it,
so a list made here equals the trees a scenario file with the same element gets. Bad arguments
raise canopy.ScenarioError naming the generator and the field.
"""
import json

from . import _canopy


def _radius(radius):
    """A fixed radius, or (min, max) for radii drawn uniformly."""
    if isinstance(radius, (list, tuple)):
        return [float(r) for r in radius]
    return float(radius)


def _generate(name, element):
    return _canopy._layout(json.dumps([element]), f"canopy.forest.{name}")


def poisson(aoi, lam, radius, seed=1, min_gap=None):
    """A Poisson forest of ``lam`` trees per m² over ``aoi`` = (x_min, y_min, x_max, y_max);
    with ``min_gap`` (m), Matérn type-II thinning keeps crowns at least that far apart."""
    element = {"type": "poisson", "region": [float(v) for v in aoi], "lambda": float(lam),
               "radius": _radius(radius), "seed": int(seed)}
    if min_gap is not None:
        element["min_gap"] = float(min_gap)
    return _generate("poisson", element)


def grid(origin, spacing, rows, cols, radius, angle=0.0, jitter=0.0, seed=1):
    """rows × cols trees from ``origin`` (m), ``spacing`` (dx, dy) apart, rotated by ``angle``
    (rad), each coordinate jittered by N(0, jitter²). A row is a grid with one row."""
    return _generate("grid", {"type": "grid", "origin": [float(v) for v in origin],
                              "spacing": [float(v) for v in spacing], "rows": int(rows),
                              "cols": int(cols), "angle": float(angle), "radius": _radius(radius),
                              "jitter": float(jitter), "seed": int(seed)})


def cluster(aoi, parent_lambda, mean_trees, spread, radius, seed=1, min_gap=None):
    """A Thomas cluster forest: Poisson(parent_lambda) cluster centres per m², each with
    Poisson(mean_trees) trees displaced by N(0, spread² I) (m); trees outside ``aoi`` dropped."""
    element = {"type": "cluster", "region": [float(v) for v in aoi],
               "parent_lambda": float(parent_lambda), "mean_trees": float(mean_trees),
               "spread": float(spread), "radius": _radius(radius), "seed": int(seed)}
    if min_gap is not None:
        element["min_gap"] = float(min_gap)
    return _generate("cluster", element)


def disc(centre, radius):
    """One disc tree (m)."""
    return {"type": "disc", "centre": [float(centre[0]), float(centre[1])], "radius": float(radius)}
