"""Scenario: a scenario's configuration as a Python dict, every default filled in.

The dict is the effective configuration the command line records in manifest.json, so it has
the scenario file's grammar (scenarios/library/demo.json documents every field). Edit it freely
(``scenario["uavs.0.v_max"] = 3``, ``del scenario["uavs.0.v_max"]``): each edit through ``[]`` is
checked at once with the command line's loader and refused (undone, ScenarioError naming the field)
when it makes an error; edits made to the dicts directly (``scenario.occluders.append(...)``) are
checked by ``validate()``. ``save(path)`` writes a file ``canopy run`` runs identically.
"""
import copy
import json
import math

from . import _args, _canopy


def _overrides(overrides):
    """{"planner.horizon": 1} → ["planner.horizon=1"], each value as JSON (the --set form)."""
    items = []
    if overrides is not None and not isinstance(overrides, dict):
        raise _args.error("canopy.load", "overrides",
                          f"expected a dict of dotted field paths to values, got {overrides!r:.60}")
    for path, value in (overrides or {}).items():
        if not isinstance(path, str) or not path:
            raise _args.error("canopy.load", "overrides",
                              f"expected dotted field paths as keys, got {path!r:.60}")
        _check_finite(value, "--set", _cli_path(path))
        try:
            items.append(f"{path}={json.dumps(value, allow_nan=False)}")
        except (TypeError, ValueError) as e:
            raise _args.error("--set", _cli_path(path), f"expected a JSON value, got {value!r:.60} "
                                                        f"({e})") from None
    return items


def _cli_path(path):
    """"uavs.0.v_max" → "uavs[0].v_max": the field path as the loader's messages spell it."""
    out = ""
    for part in str(path).split("."):
        out += f"[{part}]" if part.lstrip("-").isdigit() else (("." if out else "") + part)
    return out


def _error(file, field, reason):
    """A ScenarioError with the attributes the loader's carry."""
    error = _canopy.ScenarioError(f"{file}: {field}: {reason}" if field else f"{file}: {reason}")
    error.file, error.field, error.reason = file, field, reason
    return error


# JSON nests at most this many arrays and objects (spec/json_text.h's kMaxJsonDepth; the reader
# refuses a container opened when this many are open already, so one more than it is read).
MAX_JSON_DEPTH = 64


def _depth(value, limit):
    """How many arrays and objects `value` nests (iteratively: no RecursionError on deep input),
    counted up to limit + 1."""
    deepest, stack = 0, [(value, 1)]
    while stack:
        node, depth = stack.pop()
        if not isinstance(node, (dict, list, tuple)):
            continue
        deepest = max(deepest, depth)
        if deepest > limit:
            return deepest
        stack.extend((child, depth + 1) for child in (node.values() if isinstance(node, dict) else node))
    return deepest


def _check_depth(value, file, path):
    """A value set at `path` (k dotted parts: k containers above it) may nest at most
    MAX_JSON_DEPTH + 1 − k more: refused naming the field, not the file it came from."""
    room = MAX_JSON_DEPTH + 1 - len(str(path).split("."))
    if _depth(value, room) > room:
        raise _error(file, _cli_path(path),
                     f"expected a value nested at most {room} levels deep here (a scenario "
                     f"nests at most {MAX_JSON_DEPTH} arrays and objects), got a deeper one")


def _check_finite(value, file, path):
    """JSON has no NaN or infinity: refused where it is set, naming the field."""
    if isinstance(value, float) and not math.isfinite(value):
        raise _error(file, path, f"expected a finite number, got {value!r}")
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, file, f"{path}.{k}" if path else str(k))
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _check_finite(v, file, f"{path}[{i}]")


def load(name_or_path, overrides=None, allowed_roots=()):
    """A built-in scenario's name or a scenario file → Scenario. ``overrides`` maps dotted field
    paths to values, as ``--set`` does; ``allowed_roots`` are extra folders includes and track
    files may be read from (``--allow-path``). Raises ScenarioError."""
    roots = _args.paths(allowed_roots, "canopy.load", "allowed_roots")
    text, file = _canopy._load(_args.path(name_or_path, "canopy.load", "name_or_path"),
                               _overrides(overrides), roots)
    return Scenario(json.loads(text), file=file, allowed_roots=roots)


class Scenario:
    """A scenario's configuration (``config``, a dict) and where it came from (``file``: names it
    in errors and anchors relative includes and track files; empty when built in code)."""

    def __init__(self, config, file="<python>", allowed_roots=()):
        if not isinstance(config, dict):
            raise _args.error("Scenario", "config",
                              f"expected the configuration as a dict, got {type(config).__name__}")
        self.config = config
        self.file = _args.path(file, "Scenario", "file")
        self.allowed_roots = _args.paths(list(allowed_roots) if isinstance(allowed_roots, tuple)
                                         else allowed_roots, "Scenario", "allowed_roots")
        self._compiled = None  # (source, the loader's spec) for the last configuration checked

    # --- fields --------------------------------------------------------------------------
    def __getitem__(self, path):
        parent, key = self._parent(path)
        return parent[key]

    def __setitem__(self, path, value):
        """Sets a field and checks the edit at once with the loader's rules: an edit that makes an
        error the configuration did not have is undone and raises ScenarioError with the command
        line's message and field path (``uavs[0].v_max``), naming where the scenario came from."""
        parent, key = self._parent(path)
        if isinstance(parent, list) and not -len(parent) <= key < len(parent):
            raise KeyError(f"{self.file}: {_cli_path(path)}: no element {key} "
                           f"(the list has {len(parent)})")
        _check_depth(value, self.file, path)
        _check_finite(value, self.file, _cli_path(path))
        had, old = (key in parent, parent.get(key)) if isinstance(parent, dict) else (True, parent[key])
        before = self._errors()
        try:
            json.dumps(value, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise _error(self.file, _cli_path(path),
                         f"expected a JSON value, got {value!r:.60} ({e})") from None
        parent[key] = copy.deepcopy(value)
        try:
            self._refuse_new_errors(before)
        except Exception:
            if had:
                parent[key] = old
            else:
                del parent[key]
            raise

    def __delitem__(self, path):
        """Removes a field: the loader's default takes its place (a section left out is off), as
        if the file had never given it; a list element is removed from its list. Checked like an
        assignment."""
        parent, key = self._parent(path)
        if isinstance(parent, list) and not -len(parent) <= key < len(parent):
            raise KeyError(f"{self.file}: {_cli_path(path)}: no element {key} "
                           f"(the list has {len(parent)})")
        if isinstance(parent, dict) and key not in parent:
            raise KeyError(f"{self.file}: {_cli_path(path)}: no such field")
        before = self._errors()
        saved = copy.deepcopy(self.config)
        del parent[key]
        try:
            self._refuse_new_errors(before)
            if isinstance(parent, dict):
                filled = Scenario(json.loads(_canopy._check(*self._source())), self.file,
                                  self.allowed_roots)
                try:
                    parent[key] = filled[path]  # the default the loader filled in
                except KeyError:
                    pass  # an optional section with no default: left out
        except Exception:
            self.config = saved
            raise

    def _errors(self):
        """The loader's errors of the current configuration, one message each (empty: valid),
        and the loader's exception."""
        try:
            _canopy._check(*self._source())
        except _canopy.ScenarioError as error:
            return set(str(error).splitlines()), error
        return set(), None

    def _refuse_new_errors(self, before):
        after, error = self._errors()
        if after - before[0]:
            raise error

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
        try:
            text = json.dumps(self.config, allow_nan=False)
        except (TypeError, ValueError) as e:  # a NaN or a non-JSON value put in by hand
            _check_finite(self.config, self.file, "")  # names the field of a NaN or infinity
            raise _error(self.file, "", f"expected JSON values and finite numbers ({e})") from None
        return text, self.file, self.allowed_roots

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
        path = _args.output_file(path, "Scenario.save", "path")
        self.validate()
        # Through the C++ writer (core/output_file.h): a new temporary renamed over path, never
        # through a link or over a device, FIFO or socket put there meanwhile.
        _canopy._write_file(path, json.dumps(self.config, indent=2) + "\n")
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
