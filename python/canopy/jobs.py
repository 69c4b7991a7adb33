"""Whole jobs, as the command line runs them: run, sweep, analyze."""
import csv
import json
import os

import numpy as np

from . import _canopy
from .scenario import Scenario, load


def run(scenario, out, seed=None, frames=False, frame_every=1, size=None):
    """Runs ``scenario`` (a Scenario, a built-in name or a file) to its end and writes what
    ``canopy run`` writes into ``out``: manifest.json, record.jsonl, timings.jsonl, summary.json
    and, with ``frames``, frames/frame_NNNNNN.png every ``frame_every`` steps (``size`` = (width,
    height) px, default the CLI's). Returns summary.json as a dict."""
    if not isinstance(scenario, Scenario):
        scenario = load(scenario)
    width, height = size if size is not None else (0, 0)
    text, file, roots = scenario._source()
    summary = _canopy._run(text, file, roots, os.fspath(out), seed, bool(frames), int(frame_every),
                           int(width), int(height))
    return json.loads(summary)


def sweep(file, out, jobs=1, allowed_roots=()):
    """Runs the sweep file's trials into ``out`` on ``jobs`` threads, as ``canopy sweep FILE
    --out OUT --jobs JOBS`` (resumable; the same bytes however it is run). Returns the number
    of trials run now (trials already in ``out`` are not run again)."""
    roots = [os.fspath(r) for r in allowed_roots]
    return _canopy._sweep(os.fspath(file), os.fspath(out), int(jobs), roots)


def _column(values):
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=str)


def read_table(path):
    """A CSV table → {column: numpy array} (float where every value is a number, else str)."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: _column([row[i] for row in body]) for i, name in enumerate(header)}


def analyze(dir, out=None, figures=False, allowed_roots=()):
    """Analyses the sweep in ``dir`` as ``canopy analyze`` does: writes the CSV tables (and with
    ``figures`` the SVG/PNG figures) into ``out`` (default DIR/analysis) and returns the tables
    as {table name: {column: numpy array}}, e.g. ``tables["coverage"]["mean_coverage"]``."""
    dir = os.fspath(dir)
    out = os.fspath(out) if out is not None else os.path.join(dir, "analysis")
    _canopy._analyze(dir, out, [os.fspath(r) for r in allowed_roots], bool(figures))
    return {name[:-4]: read_table(os.path.join(out, name))
            for name in sorted(os.listdir(out)) if name.endswith(".csv")}
