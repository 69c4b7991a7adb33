"""The install route as a user takes it (ctest python.install, issue 30): a fresh venv with
--system-site-packages and `pip wheel --no-build-isolation .` (its contents checked); then the
README's command as printed (a venv in $HOME, `pip install .` with build isolation), with no
package index (offline); then the whole pytest suite from another folder against the installed
package (CANOPY_EXPECT_INSTALLED=1: test_install.py checks it is that copy), with the installed
`canopy` command as the CLI.

    python3 python/tests/install_check.py SOURCE_DIR BUILD_DIR WORK_DIR

BUILD_DIR is passed to the build backend as CANOPY_BUILD_DIR (a configured, built tree: the
backend only brings _canopy and canopy up to date there); "-" builds afresh in
SOURCE_DIR/build/pip-cpXY, as a plain `pip install .` does.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import zipfile


def run(command, **kwargs):
    print("+", " ".join(command), flush=True)
    subprocess.run(command, check=True, **kwargs)


def main():
    source, build, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    venv = os.path.join(work, "venv")
    run([sys.executable, "-m", "venv", "--system-site-packages", venv])
    python, pip = os.path.join(venv, "bin", "python"), os.path.join(venv, "bin", "pip")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CANOPY_CLI")}
    env["PIP_NO_INDEX"] = "1"  # offline: nothing from a package index
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    if build != "-":
        env["CANOPY_BUILD_DIR"] = build

    wheels = os.path.join(work, "wheels")
    run([pip, "wheel", "--no-build-isolation", "--no-deps", "-w", wheels, source], env=env, cwd=work)
    [wheel] = os.listdir(wheels)
    tag = f"cp{sys.version_info.major}{sys.version_info.minor}"
    assert wheel.startswith("canopy-") and f"-{tag}-{tag}" in wheel and wheel.endswith(".whl"), wheel
    with zipfile.ZipFile(os.path.join(wheels, wheel)) as z:
        names = set(z.namelist())
        info = {n: z.getinfo(n) for n in names}
        entry = z.read(next(n for n in names if n.endswith(".dist-info/entry_points.txt"))).decode()
    for needed in ("canopy/__init__.py", "canopy/env.py", "canopy/vector.py", "canopy/_canopy.pyi",
                   "canopy/py.typed", "canopy/bin/canopy", "canopy/bin/libcanopy_gis.so",
                   "canopy/scenarios/library/demo.json",
                   "canopy/scenarios/schema_probe.json"):
        assert needed in names, f"{wheel}: no {needed}"
    assert any(n.startswith("canopy/_canopy.cpython-") and n.endswith(".so") for n in names)
    assert (info["canopy/bin/canopy"].external_attr >> 16) & 0o111, "the program is not executable"
    assert "canopy = canopy._cli:main" in entry, entry
    print(f"{wheel}: {len(names)} files", flush=True)

    # The README's command, as printed (its venv in $HOME, pip with build isolation), offline.
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    command = re.search(r"^## Python\n\n```sh\n(.*?)\n```", readme, re.M | re.S)[1]
    assert command.startswith("/usr/bin/python3 -m venv --system-site-packages ~/canopy-env"), command
    home = os.path.join(work, "home")
    os.makedirs(home)
    path = os.pathsep.join([os.path.dirname(sys.executable), env.get("PATH", "")])
    run(["bash", "-c", command], env=dict(env, HOME=home, PATH=path), cwd=source)
    venv = os.path.join(home, "canopy-env")
    python = os.path.join(venv, "bin", "python")
    elsewhere = os.path.join(work, "elsewhere")
    os.makedirs(elsewhere)
    # `canopy import` opens the GIS module packed beside the installed program: one tree.
    tree = {"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"natural": "tree"},
            "geometry": {"type": "Point", "coordinates": [0.12, 52.2]}}]}
    with open(os.path.join(elsewhere, "tree.geojson"), "w") as f:
        json.dump(tree, f)
    run([os.path.join(venv, "bin", "canopy"), "import", "tree.geojson", "--out", "tree.json"], env=env,
        cwd=elsewhere)
    with open(os.path.join(elsewhere, "tree.json")) as f:
        layout = json.loads("".join(line for line in f if not line.lstrip().startswith("//")))
    assert len(layout["occluders"]) == 1, layout
    env["CANOPY_EXPECT_INSTALLED"] = "1"
    env["CANOPY_CLI"] = os.path.join(venv, "bin", "canopy")
    env["MPLBACKEND"] = "Agg"
    run([python, "-m", "pytest", "-q", "-p", "no:cacheprovider", os.path.join(source, "python", "tests")],
        env=env, cwd=elsewhere)


if __name__ == "__main__":
    main()
