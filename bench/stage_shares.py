#!/usr/bin/env python3
"""Shares of a run's CPU samples by stage (issue 33), from `perf report` of a `perf record` of
`canopy run`: each sampled function is put in a stage by its namespace or library.

    perf record -F 200 -o run.data canopy run SCENARIO --out DIR
    bench/stage_shares.py run.data
"""
import re
import subprocess
import sys

STAGES = [  # first match wins
    ("planning", r"agents::planning"),
    ("fusion", r"agents::fusion|CutoffAssignment"),
    ("tracking", r"agents::tracking|agents::Agent::|OcclusionMap"),
    ("world+sensing", r"box2d|b2[A-Z]|sensing::|world::|sim::Simulation::sense|readTruth"),
    ("record", r"sim::JsonLine|RecordLineWriter|sim::Recorder|DoubleTextCache|writeBelief|metrics::|"
               r"CompactRecordWriter|StepColumnEncoder|toPlanes|ZSTD_|libzstd|"
               r"write|memmove|memcpy|copy_"),
]


def main():
    report = subprocess.run(
        ["perf", "report", "-i", sys.argv[1], "--no-children", "--stdio", "--sort", "dso,sym",
         "-g", "none"], capture_output=True, text=True, check=True).stdout
    shares = {name: 0.0 for name, _ in STAGES}
    shares["other"] = 0.0
    for line in report.splitlines():
        m = re.match(r"\s+([\d.]+)%\s+(\S+)\s+\[[.k]\]\s+(.*)", line)
        if not m:
            continue
        share, text = float(m.group(1)), m.group(2) + " " + m.group(3)
        stage = next((name for name, pattern in STAGES if re.search(pattern, text)), "other")
        shares[stage] += share
    print(" | ".join(f"{name} {value:.0f} %" for name, value in shares.items()))


if __name__ == "__main__":
    main()
