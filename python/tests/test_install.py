"""The package as installed (issue 30): version, type stubs, the built-in scenarios it carries and
its `canopy` command. Under ctest python.install (install_check.py: a venv, pip install .) with
CANOPY_EXPECT_INSTALLED=1 it also checks that the copy under test is the installed one."""
import ast
import os
import pathlib
import re
import subprocess
import sys

import pytest

import canopy
from canopy import _canopy

SOURCE = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = pathlib.Path(canopy.__file__).resolve().parent
INSTALLED = os.environ.get("CANOPY_EXPECT_INSTALLED") == "1"


def test_one_version_everywhere():
    cmake = re.search(r"project\(canopy VERSION (\S+)", (SOURCE / "CMakeLists.txt").read_text())[1]
    pyproject = re.search(r'^version = "([^"]+)"', (SOURCE / "pyproject.toml").read_text(), re.M)[1]
    assert canopy.__version__ == cmake == pyproject


def _declared(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        elif isinstance(node, ast.FunctionDef):
            names[node.name] = set()
    return names


def test_the_stubs_declare_every_name_of_the_compiled_module():
    stub = PACKAGE / "_canopy.pyi"
    assert stub.is_file() and (PACKAGE / "py.typed").is_file()
    declared = _declared(ast.parse(stub.read_text(encoding="utf-8")))
    module_names = {n for n in dir(_canopy) if not n.startswith("__")}
    assert module_names == set(declared), module_names ^ set(declared)
    for cls in ("Simulation", "_Observer", "_VectorCore"):
        members = {n for n in dir(getattr(_canopy, cls)) if not n.startswith("__")}
        assert members - {"_pybind11_conduit_v1_"} == declared[cls] - {"__init__"}, cls


def test_the_builtin_scenarios_are_found():
    assert "demo" in canopy.library_scenarios()
    library = pathlib.Path(_canopy._library_dir())
    assert (library / "demo.json").is_file()
    if INSTALLED:
        assert library == PACKAGE / "scenarios" / "library"


@pytest.mark.skipif(not INSTALLED, reason="checks an installed package (ctest python.install)")
def test_the_installed_copy_is_under_test():
    assert PACKAGE.parent.name == "site-packages", PACKAGE  # not the source's or a build's
    assert pathlib.Path(sys.prefix).resolve() in PACKAGE.parents
    command = pathlib.Path(sys.executable).parent / "canopy"
    done = subprocess.run([command, "list"], capture_output=True, text=True)
    assert done.returncode == 0 and "demo" in done.stdout.split(), done.stderr
    done = subprocess.run([command, "--version"], capture_output=True, text=True)
    assert done.stdout.startswith(f"canopy {canopy.__version__}")
