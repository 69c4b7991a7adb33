"""Layout generators: each returns a list of explicit trees (occluder elements
``{"type": "disc", "centre": [x, y], "radius": r}``) to put in ``Scenario.occluders``.

The generators are the scenario grammar's (``"type": "poisson"`` and so on, docs in
scenarios/library/demo.json): the arguments become that element and canopy's loader draws it,
so a list made here equals the trees a scenario file with the same element gets. Bad arguments
raise canopy.ScenarioError naming the generator and the field.
"""
import json

from . import _args, _canopy


def _radius(radius, fn):
    """A fixed radius, or (min, max) for radii drawn uniformly: positive, at most 1e7 m."""
    def one(r, field):
        return _args.number(r, fn, field, 0.0, _args.MAX_COORDINATE, low_open=True,
                            expected="a radius in (0, 1e7] m")
    if isinstance(radius, (list, tuple)) or hasattr(radius, "shape"):
        return _args.sequence(radius, fn, "radius", 2, one, "a radius or (min, max)")
    return one(radius, "radius")


def _generate(name, element):
    # Every value is checked above (finite, typed): the loader then checks ranges and shapes,
    # naming the field of this element.
    return _canopy._layout(json.dumps([element], allow_nan=False), f"canopy.forest.{name}")


def poisson(aoi, lam, radius, seed=1, min_gap=None):
    """A Poisson forest of ``lam`` trees per m² over ``aoi`` = (x_min, y_min, x_max, y_max);
    with ``min_gap`` (m), Matérn type-II thinning keeps crowns at least that far apart."""
    fn = "canopy.forest.poisson"
    element = {"type": "poisson", "region": _args.region(aoi, fn),
               "lambda": _args.number(lam, fn, "lambda (lam)", 0.0,
                                    expected="a density >= 0 (trees per m²)"),
               "radius": _radius(radius, fn), "seed": _args.integer(seed, fn, "seed", 0, 2147483647)}
    if min_gap is not None:
        element["min_gap"] = _args.number(min_gap, fn, "min_gap", 0.0, expected="a gap >= 0 (m)")
    return _generate("poisson", element)


def grid(origin, spacing, rows, cols, radius, angle=0.0, jitter=0.0, seed=1):
    """rows × cols trees from ``origin`` (m), ``spacing`` (dx, dy) apart, rotated by ``angle``
    (rad), each coordinate jittered by N(0, jitter²). A row is a grid with one row."""
    fn = "canopy.forest.grid"
    spacing = _args.sequence(spacing, fn, "spacing", 2,
                             lambda x, f: _args.number(x, fn, f, 0.0, _args.MAX_COORDINATE,
                                                       expected="a spacing in [0, 1e7] m"),
                             "(dx, dy) spacings (m)")
    return _generate("grid", {"type": "grid", "origin": _args.coordinates(origin, fn, "origin", 2),
                              "spacing": spacing, "rows": _args.integer(rows, fn, "rows", 1, 100000),
                              "cols": _args.integer(cols, fn, "cols", 1, 100000),
                              "angle": _args.number(angle, fn, "angle"),
                              "radius": _radius(radius, fn),
                              "jitter": _args.number(jitter, fn, "jitter", 0.0,
                                                     expected="a jitter >= 0 (m)"),
                              "seed": _args.integer(seed, fn, "seed", 0, 2147483647)})


def cluster(aoi, parent_lambda, mean_trees, spread, radius, seed=1, min_gap=None):
    """A Thomas cluster forest: Poisson(parent_lambda) cluster centres per m², each with
    Poisson(mean_trees) trees displaced by N(0, spread² I) (m); trees outside ``aoi`` dropped."""
    fn = "canopy.forest.cluster"
    element = {"type": "cluster", "region": _args.region(aoi, fn),
               "parent_lambda": _args.number(parent_lambda, fn, "parent_lambda", 0.0,
                                             expected="a density >= 0 (clusters per m²)"),
               "mean_trees": _args.number(mean_trees, fn, "mean_trees", 0.0,
                                          expected="a mean >= 0"),
               "spread": _args.number(spread, fn, "spread", 0.0, low_open=True,
                                      expected="a spread > 0 (m)"),
               "radius": _radius(radius, fn), "seed": _args.integer(seed, fn, "seed", 0, 2147483647)}
    if min_gap is not None:
        element["min_gap"] = _args.number(min_gap, fn, "min_gap", 0.0, expected="a gap >= 0 (m)")
    return _generate("cluster", element)


def disc(centre, radius):
    """One disc tree (m)."""
    fn = "canopy.forest.disc"
    return {"type": "disc", "centre": _args.coordinates(centre, fn, "centre", 2),
            "radius": _args.number(radius, fn, "radius", 0.0, _args.MAX_COORDINATE, low_open=True,
                                   expected="a radius in (0, 1e7] m")}
