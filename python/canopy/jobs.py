"""Whole jobs, as the command line runs them: run, sweep, analyze."""
import csv
import json
import os

import numpy as np

from . import _args, _canopy
from .scenario import Scenario, load


def run(scenario, out, seed=None, frames=False, frame_every=1, size=None):
    """Runs ``scenario`` (a Scenario, a built-in name or a file) to its end and writes what
    ``canopy run`` writes into ``out``: manifest.json, record.jsonl (record.jsonl.zst at city
    scale, read it with read_record), timings.jsonl, summary.json
    and, with ``frames``, frames/frame_NNNNNN.png every ``frame_every`` steps (``size`` = (width,
    height) px, default the CLI's). Returns summary.json as a dict."""
    fn = "canopy.run"
    if not isinstance(scenario, Scenario):
        scenario = load(_args.path(scenario, fn, "scenario"))
    out = _args.output_dir(out, fn, "out")
    seed = _args.seed(seed, fn)
    frames = _args.boolean(frames, fn, "frames")
    frame_every = _args.integer(frame_every, fn, "frame_every", 1, _args.MAX_FRAME_EVERY)
    width, height = _args.image_size(size, fn) if size is not None else (0, 0)
    text, file, roots = scenario._source()
    summary = _canopy._run(text, file, roots, out, seed, frames, frame_every, width, height)
    return json.loads(summary)


def sweep(file, out, jobs=1, allowed_roots=()):
    """Runs the sweep file's trials into ``out`` on ``jobs`` threads, as ``canopy sweep FILE
    --out OUT --jobs JOBS`` (resumable; the same bytes however it is run). Returns the number
    of trials run now (trials already in ``out`` are not run again)."""
    fn = "canopy.sweep"
    file, out = _args.path(file, fn, "file"), _args.output_dir(out, fn, "out")
    jobs = _args.integer(jobs, fn, "jobs", 1, _args.MAX_JOBS)
    roots = _args.paths(allowed_roots, fn, "allowed_roots")
    return _canopy._sweep(file, out, jobs, roots)


_ALL_STEPS = 2**64 - 1


def _steps(steps, fn):
    """(first, end) of ``steps``: None (every step) or a pair (A, B) of integers, steps A..B-1."""
    if steps is None:
        return 0, _ALL_STEPS
    if (not isinstance(steps, tuple) or len(steps) != 2
            or not all(isinstance(s, int) and not isinstance(s, bool) for s in steps)
            or not 0 <= steps[0] < steps[1] <= _ALL_STEPS):
        raise _args.error(fn, "steps", "expected None or a pair (A, B) of integers with "
                          f"0 <= A < B, got {_args._shown(steps)}")
    return steps


def read_run(dir, steps=None):
    """The truth of a finished run (the --out folder of canopy.run or ``canopy run``), read back
    from manifest.json and the record (record.jsonl or the compact record.jsonl.zst): a dict of
    numpy arrays k (K), t (K), uav_positions (K, U, 2), uav_yaw (K, U) and target_positions
    (K, T, 2). ``steps`` = (A, B): steps A..B-1 only (the compact record decodes only their
    blocks). Raises ScenarioError naming the file, the line and the field when the folder is not
    a finished run."""
    fn = "canopy.read_run"
    return _canopy._read_run(_args.path(dir, fn, "dir"), *_steps(steps, fn))


def read_record(dir, steps=None):
    """The record of a finished run as a list of dicts, one per step: the JSON lines of
    record.jsonl (``canopy record DIR`` prints them), from either form. ``steps`` = (A, B):
    steps A..B-1 only."""
    fn = "canopy.read_record"
    lines = _canopy._record_lines(_args.path(dir, fn, "dir"), *_steps(steps, fn))
    return [json.loads(line) for line in lines]


def _column(values):
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=str)


def read_table(path):
    """A CSV table → {column: numpy array} (float where every value is a number, else str)."""
    path = _args.path(path, "canopy.jobs.read_table", "path")
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: _column([row[i] for row in body]) for i, name in enumerate(header)}


def analyze(dir, out=None, figures=False, allowed_roots=()):
    """Analyses the sweep in ``dir`` as ``canopy analyze`` does: writes the CSV tables (and with
    ``figures`` the SVG/PNG figures) into ``out`` (default DIR/analysis) and returns the tables
    as {table name: {column: numpy array}}, e.g. ``tables["coverage"]["mean_coverage"]``."""
    fn = "canopy.analyze"
    dir = _args.path(dir, fn, "dir")
    out = (_args.output_dir(out, fn, "out") if out is not None
           else _args.output_dir(os.path.join(dir, "analysis"), fn, "out (default, dir/analysis)"))
    roots = _args.paths(allowed_roots, fn, "allowed_roots")
    _canopy._analyze(dir, out, roots, _args.boolean(figures, fn, "figures"))
    return {name[:-4]: read_table(os.path.join(out, name))
            for name in sorted(os.listdir(out)) if name.endswith(".csv")}
