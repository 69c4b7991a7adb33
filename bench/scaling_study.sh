#!/bin/bash
# Scaling study (issue 33): city swarms from scenarios/city_swarm.py at four sizes, each run once
# under /usr/bin/time -v. Prints one row per size: CPU seconds (user + sys) per simulated second,
# peak RSS, record size, and the share of CPU samples by stage from a second run under perf.
# Usage: bench/scaling_study.sh [CANOPY] [DURATION_S] [EXTRA generator options...]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
canopy=${1:-$here/build/release/app/canopy}
duration=${2:-10}
shift 2 2>/dev/null || true
extra=("$@")
work=$(mktemp -d "${TMPDIR:-/tmp}/scaling.XXXX")
echo "| UAVs | people | trees | CPU s / sim s | peak RSS MB | record MB / sim s | CPU samples by stage (perf) |"
echo "|---:|---:|---:|---:|---:|---:|---|"
for size in "3 4 70" "16 64 10000" "64 256 100000" "128 512 100000"; do
  set -- $size
  name=s_$1_$2_$3
  python3 "$here/scenarios/city_swarm.py" --uavs "$1" --people "$2" --trees "$3" \
    --duration "$duration" --name "$name" "${extra[@]}" > "$work/$name.json"
  /usr/bin/time -v "$canopy" run "$work/$name.json" --out "$work/$name" \
    > "$work/$name.out" 2> "$work/$name.time"
  # Stage shares from a second run under perf (sampling at 250 Hz; bench/stage_shares.py).
  perf record -q -F 250 -o "$work/$name.perf" "$canopy" run "$work/$name.json" \
    --out "$work/$name.p" > /dev/null 2>&1
  shares=$(python3 "$here/bench/stage_shares.py" "$work/$name.perf")
  python3 - "$work/$name" "$work/$name.time" "$duration" "$1" "$2" "$3" "$shares" <<'PY'
import json, os, re, sys
out, timing, duration = sys.argv[1], open(sys.argv[2]).read(), float(sys.argv[3])
user = float(re.search(r"User time \(seconds\): ([\d.]+)", timing).group(1))
system = float(re.search(r"System time \(seconds\): ([\d.]+)", timing).group(1))
rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", timing).group(1))
# the record as written: record.jsonl.zst at scale (--record auto), else record.jsonl
record = next(os.path.getsize(os.path.join(out, name)) for name in ("record.jsonl.zst", "record.jsonl")
              if os.path.exists(os.path.join(out, name)))
cpu = user + system
print(f"| {sys.argv[4]} | {sys.argv[5]} | {sys.argv[6]} | {cpu / duration:.3f} | {rss / 1024:.0f} | "
      f"{record / 1e6 / duration:.1f} | {sys.argv[7]} |")
PY
  rm -rf "$work/$name" "$work/$name.p" "$work/$name.perf"
done
rm -rf "$work"
