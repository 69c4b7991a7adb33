#!/usr/bin/env bash
# ./canopy runs the program at once when it is built and nothing it is built from changed since,
# and asks the build system otherwise. Checked on a copy of the script in a scratch tree with a
# stand-in program and a `cmake` on the PATH that fails: up to date → the program runs (exit 0);
# a source newer than the program → cmake is asked (and fails here). A `dpkg-query` stand-in
# that counts its calls: the packages are checked with one call, not one per package (issue 51:
# 29 calls, 1.5 s for `./canopy --version`).
set -u
root="$1"
tree="$(mktemp -d)"
trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree/stub" "$tree/sim" "$tree/build/release/app"
cp "$root/canopy" "$tree/canopy"
printf '#!/bin/sh\necho "cmake was called" >&2\nexit 3\n' >"$tree/stub/cmake"
chmod +x "$tree/stub/cmake"
real_dpkg_query="$(command -v dpkg-query)"
printf '#!/bin/sh\necho call >>"%s/dpkg-query.calls"\nexec "%s" "$@"\n' "$tree" "$real_dpkg_query" \
  >"$tree/stub/dpkg-query"
chmod +x "$tree/stub/dpkg-query"
echo "int x;" >"$tree/sim/simulation.cpp"
echo "CANOPY_WERROR:BOOL=OFF" >"$tree/build/release/CMakeCache.txt"
touch "$tree/build/release/Makefile"
printf '#!/bin/sh\necho "canopy stand-in $*"\n' >"$tree/build/release/app/canopy"
chmod +x "$tree/build/release/app/canopy"
touch -d '2000-01-01' "$tree/sim/simulation.cpp" "$tree/canopy"

out="$(CANOPY_WERROR=0 PATH="$tree/stub:$PATH" "$tree/canopy" --version 2>&1)"
if [ $? -ne 0 ] || [ "$out" != "canopy stand-in --version" ]; then
  echo "FAIL: an up-to-date ./canopy did not run the program at once: $out"
  exit 1
fi
calls="$(wc -l <"$tree/dpkg-query.calls")"
if [ "$calls" -ne 1 ]; then
  echo "FAIL: ./canopy --version ran dpkg-query $calls times (once is enough)"
  exit 1
fi
touch "$tree/sim/simulation.cpp"  # a source newer than the program
out="$(CANOPY_WERROR=0 PATH="$tree/stub:$PATH" "$tree/canopy" --version 2>&1)"
if [ $? -eq 0 ]; then
  echo "FAIL: a changed source did not make ./canopy build first: $out"
  exit 1
fi
echo "ok: up to date, run at once; a newer source, built first"
