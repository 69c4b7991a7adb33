#!/usr/bin/env bash
# `canopy view` on bad input: a missing or garbled run folder exits with code 2 and a message
# naming the file. Usage: cli_test.sh CANOPY_BINARY SOURCE_DIR WORK_DIR
set -uo pipefail
canopy=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
passed=0 failed=0

expect_bad_input() {  # NAME RUN_DIR TEXT: exit code 2 and TEXT in the message
  local name=$1 dir=$2 text=$3 err code
  err=$("$canopy" view "$dir" --out "$work/out.html" 2>&1 >/dev/null)
  code=$?
  if [ "$code" -eq 2 ] && [[ "$err" == *"$text"* ]] && [ ! -e "$work/out.html" ]; then
    passed=$((passed + 1)); echo "ok - $name"
  else
    failed=$((failed + 1)); echo "not ok - $name: exit $code, message: $err"
  fi
}

"$canopy" run demo --out "$work/good" --set clock.duration=2 >/dev/null || { echo "0 passed, 1 failed"; exit 1; }
copy() { rm -rf "$work/$1" && cp -r "$work/good" "$work/$1"; }

expect_bad_input "a missing folder" "$work/nowhere" "$work/nowhere: no such directory"
copy no_manifest && rm "$work/no_manifest/manifest.json"
expect_bad_input "a missing manifest" "$work/no_manifest" "no_manifest/manifest.json: missing"
copy no_record && rm "$work/no_record/record.jsonl"
expect_bad_input "a missing record" "$work/no_record" "no_record/record.jsonl: missing"
copy garbled && sed -i '3s/.*/{"k": 2, "t": oops/' "$work/garbled/record.jsonl"
expect_bad_input "a garbled record line" "$work/garbled" "garbled/record.jsonl: line 3"
copy short && sed -i '2s/"p":\[[^]]*\]/"p":[1]/' "$work/short/record.jsonl"
expect_bad_input "a position that is not [x, y]" "$work/short" "short/record.jsonl: line 2"
copy no_summary && echo '{"uavs": []}' > "$work/no_summary/summary.json"
expect_bad_input "a summary of another run" "$work/no_summary" "no_summary/summary.json: uavs"

# --overlay without a second run is a usage error (exit 2), naming the missing RUN_B.
err=$("$canopy" view "$work/good" --overlay --out "$work/out.html" 2>&1 >/dev/null)
code=$?
if [ "$code" -eq 2 ] && [[ "$err" == *"--overlay needs RUN_B"* ]] && [ ! -e "$work/out.html" ]; then
  passed=$((passed + 1)); echo "ok - --overlay without RUN_B"
else
  failed=$((failed + 1)); echo "not ok - --overlay without RUN_B: exit $code, message: $err"
fi

# analyze links one replay per behaviour class (the ownership state at L of some trial).
if "$canopy" sweep "$source/tests/replay/data/replay_sweep.json" --out "$work/sweep" --jobs 1 \
     >/dev/null 2>&1 && "$canopy" analyze "$work/sweep" >"$work/analyze.txt" 2>&1; then
  classes=$(grep -c "^replay of " "$work/analyze.txt")
  links=$(grep -o 'href="replays/[^"]*"' "$work/sweep/analysis/replays.html" | grep -v '/pairs/' | sed 's/href="//; s/"$//')
  missing=0
  for link in $links; do [ -s "$work/sweep/analysis/$link" ] || missing=$((missing + 1)); done
  if [ "$classes" -ge 2 ] && [ "$(echo "$links" | wc -w)" -eq "$classes" ] && [ "$missing" -eq 0 ]; then
    passed=$((passed + 1)); echo "ok - analyze links $classes behaviour classes to replays"
  else
    failed=$((failed + 1)); echo "not ok - analyze's replays: $classes classes, links: $links, $missing missing"
  fi
  # ... and each replayed trial of the second configuration (planner none) to a page holding it
  # and the same trial of the first (sma) side by side: both runs of that trial's seed.
  later=$(grep -c "^replay of algorithm-none" "$work/analyze.txt")
  pairs=$(grep -o 'href="replays/pairs/[^"]*"' "$work/sweep/analysis/replays.html" | sed 's/href="//; s/"$//')
  bad=0
  for link in $pairs; do
    page="$work/sweep/analysis/$link"
    [ "$(grep -o 'id="run-[ab]"' "$page" | sort -u | wc -l)" -eq 2 ] || bad=$((bad + 1))
  done
  seeds_a=$(cat "$work"/sweep/analysis/replays/algorithm-sma/*/manifest.json | grep -o '"seed": *[0-9]*' | sort -u)
  seeds_b=$(cat "$work"/sweep/analysis/replays/algorithm-none/*/manifest.json | grep -o '"seed": *[0-9]*' | sort -u)
  unpaired=$(comm -13 <(echo "$seeds_a") <(echo "$seeds_b") | wc -l)
  if [ "$later" -ge 1 ] && [ "$(echo "$pairs" | wc -w)" -eq "$later" ] && [ "$bad" -eq 0 ] && [ "$unpaired" -eq 0 ]; then
    passed=$((passed + 1)); echo "ok - analyze pairs $later trials of the second configuration with the first's"
  else
    failed=$((failed + 1)); echo "not ok - analyze's pairs: $later replays, pairs: $pairs, $bad without both runs, $unpaired seeds unpaired"
  fi
else
  failed=$((failed + 1)); echo "not ok - sweep and analyze: $(tail -3 "$work/analyze.txt" 2>/dev/null)"
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
