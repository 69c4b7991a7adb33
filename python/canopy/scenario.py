"""Scenario: a scenario's configuration as a Python dict, every default filled in.

The dict is the effective configuration the command line records in manifest.json, so it has
the scenario file's grammar (scenarios/library/demo.json documents every field). Edit it freely
(``scenario["uavs.0.v_max"] = 3``, ``scenario.occluders.append(...)``); ``validate()`` checks it
with the command line's loader, and ``save(path)`` writes a file ``canopy run`` runs identically.
"""
import copy
import json
import os

from . import _canopy


def _overrides(overrides):
    """{"planner.horizon": 1} → ["planner.horizon=1"], each value as JSON (the --set form)."""
    items = []
    for path, value in (overrides or {}).items():
        if not isinstance(path, str) or not path:
            raise TypeError(f"overrides: expected dotted field paths as keys, got {path!r}")
        items.append(f"{path}={json.dumps(value)}")
    return items


def load(name_or_path, overrides=None, allowed_roots=()):
    """A built-in scenario's name or a scenario file → Scenario. ``overrides`` maps dotted field
    paths to values, as ``--set`` does; ``allowed_roots`` are extra folders includes and track
    files may be read from (``--allow-path``). Raises ScenarioError."""
    roots = [os.fspath(r) for r in allowed_roots]
    text, file = _canopy._load(os.fspath(name_or_path), _overrides(overrides), roots)
    return Scenario(json.loads(text), file=file, allowed_roots=roots)


class Scenario:
    """A scenario's configuration (``config``, a dict) and where it came from (``file``: names it
    in errors and anchors relative includes and track files; empty when built in code)."""

    def __init__(self, config, file="<python>", allowed_roots=()):
        if not isinstance(config, dict):
            raise TypeError(f"Scenario: expected the configuration as a dict, got {type(config).__name__}")
        self.config = config
        self.file = os.fspath(file)
        self.allowed_roots = [os.fspath(r) for r in allowed_roots]
        self._compiled = None  # (source, the loader's spec) for the last configuration checked

    # --- fields --------------------------------------------------------------------------
    def __getitem__(self, path):
        parent, key = self._parent(path)
        return parent[key]

    def __setitem__(self, path, value):
        parent, key = self._parent(path)
        if isinstance(parent, dict) or key < len(parent):
            parent[key] = value
        else:
            raise KeyError(f"{self.file}: {path}: no element {key} (the list has {len(parent)})")

    def _parent(self, path):
        """The container holding the dotted ``path`` and the last key (an int for lists)."""
        node, parts = self.config, str(path).split(".")
        for depth, part in enumerate(parts):
            key = int(part) if isinstance(node, list) and part.lstrip("-").isdigit() else part
            if isinstance(node, list) and not isinstance(key, int):
                raise KeyError(f"{self.file}: {'.'.join(parts[:depth + 1])}: expected a list index")
            if depth == len(parts) - 1:
                return node, key
            try:
                node = node[key]
            except (KeyError, IndexError, TypeError):
                raise KeyError(f"{self.file}: {'.'.join(parts[:depth + 1])}: no such field") from None
        raise KeyError(path)

    name = property(lambda self: self.config.get("name", ""))
    dt = property(lambda self: self.config["clock"]["dt"])
    duration = property(lambda self: self.config["clock"]["duration"])
    aoi = property(lambda self: self.config["aoi"])
    uavs = property(lambda self: self.config["uavs"], doc="list of UAV dicts (name, start, v_max, fov, …)")
    targets = property(lambda self: self.config["targets"], doc="list of target dicts (name, label, path)")
    occluders = property(lambda self: self.config.setdefault("occluders", []),
                         doc="list of occluder elements (disc, polygon, poisson, grid, cluster)")

    # --- checking and writing ------------------------------------------------------------
    def _source(self):
        return json.dumps(self.config), self.file, self.allowed_roots

    def _spec(self):
        """The loader's result for the current configuration; loaded again only after a change
        (a Simulation per episode then costs a json.dumps, not a parse and a layout draw)."""
        source = self._source()
        if self._compiled is None or self._compiled[0] != source:
            self._compiled = (source, _canopy._compile(*source))
        return self._compiled[1]

    def validate(self):
        """Checks the configuration as ``canopy validate`` does; raises ScenarioError naming the
        file and the field. Returns self."""
        self._spec()
        return self

    def filled(self):
        """A copy with every default filled in (what a run records as its effective config)."""
        return Scenario(json.loads(_canopy._check(*self._source())), self.file, self.allowed_roots)

    def save(self, path):
        """Validates, then writes the configuration as a scenario file. Relative includes and
        track files are read from beside the new file when the CLI runs it."""
        self.validate()
        path = os.fspath(path)
        tmp = path + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            json.dump(self.config, f, indent=2)
            f.write("\n")
        os.replace(tmp, path)
        return path

    def copy(self):
        return Scenario(copy.deepcopy(self.config), self.file, self.allowed_roots)

    def __getstate__(self):
        return {"config": self.config, "file": self.file, "allowed_roots": self.allowed_roots}

    def __setstate__(self, state):
        self.__init__(state["config"], state["file"], state["allowed_roots"])

    def __repr__(self):
        return (f"Scenario({self.name!r}: {len(self.uavs)} UAVs, {len(self.targets)} targets, "
                f"{len(self.occluders)} occluder elements, {self.duration} s)")
