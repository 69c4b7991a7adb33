"""Shared fixtures: the command-line program (CANOPY_CLI, set by ctest) and running it."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("CANOPY_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("CANOPY_CLI (the canopy program) not set; run through ctest")

    def run(*args, check=True):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"canopy {' '.join(map(str, args))} → {done.returncode}: {done.stderr}")
        return done

    return run
