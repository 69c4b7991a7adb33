#!/usr/bin/env bash
# ./canopy runs the program at once when it is built and no source changed since: with a `cmake`
# on the PATH that fails, `./canopy --version` still prints the version (exit 0). Then, with a
# source made newer than the program, it does ask the build system (and so fails here).
set -u
root="$1"
stub="$(mktemp -d)"
trap 'rm -rf "$stub"' EXIT
printf '#!/bin/sh\necho "cmake was called" >&2\nexit 3\n' >"$stub/cmake"
chmod +x "$stub/cmake"
out="$(PATH="$stub:$PATH" "$root/canopy" --version 2>&1)"
code=$?
if [ $code -ne 0 ] || ! printf '%s' "$out" | grep -q '^canopy '; then
  echo "FAIL: an up-to-date ./canopy --version exited $code: $out"
  exit 1
fi
echo "ok: up to date, no build: $out"
