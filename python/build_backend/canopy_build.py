"""canopy's PEP 517 build backend (pyproject.toml names it; no setuptools, nothing downloaded).

``pip install .`` / ``pip wheel .`` call build_wheel, which builds the ``_canopy`` extension and
the ``canopy`` program with CMake and packs them into a wheel with the pure-Python files, the
type stubs (``*.pyi``, ``py.typed``), the built-in scenarios (``canopy/scenarios``) and the
``canopy`` console entry point (``canopy._cli:main``, which runs the packed program).

The CMake build folder: ``$CANOPY_BUILD_DIR`` when set (an already configured tree such as
``build/release``: only its two targets are brought up to date, which takes seconds when it is
built), else ``build/pip-cpXY`` in the source tree (configured on first use with tests and
benchmarks off, then rebuilt incrementally). ``$CANOPY_JOBS`` sets the build jobs (default: the
cores). The extension is built for the interpreter running pip (its real executable: pip's
isolated build environment hides Debian's numpy, the CMake run does not).
"""
import base64
import csv
import hashlib
import io
import os
import re
import stat
import subprocess
import sys
import sysconfig
import tarfile
import tomllib
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _project():
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        return tomllib.load(f)["project"]


def _dist_name(project):
    return re.sub(r"[-_.]+", "_", project["name"]).lower()


def _metadata(project):
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {project['version']}",
             f"Summary: {project['description']}"]
    if "requires-python" in project:
        lines.append(f"Requires-Python: {project['requires-python']}")
    if "license" in project and "text" in project["license"]:
        lines.append(f"License: {project['license']['text']}")
    lines += [f"Requires-Dist: {d}" for d in project.get("dependencies", [])]
    for extra, deps in project.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f"Requires-Dist: {d}; extra == \"{extra}\"" for d in deps]
    readme = project.get("readme")
    body = ""
    if readme:
        lines.append("Description-Content-Type: text/markdown")
        with open(os.path.join(ROOT, readme), encoding="utf-8") as f:
            body = "\n" + f.read()
    return "\n".join(lines) + "\n" + body


def _entry_points(project):
    scripts = project.get("scripts", {})
    return "[console_scripts]\n" + "".join(f"{k} = {v}\n" for k, v in scripts.items())


def _tag():
    impl = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{impl}-{impl}{sys.abiflags}-{platform}"


def _run(command, **kwargs):
    print("canopy build:", " ".join(command), flush=True)
    subprocess.run(command, check=True, **kwargs)


_PERCENT = re.compile(r"^\[\s*(\d+)%\]")


def _progress_sink():
    """Where the build's percentage goes while pip hides its output (issue 51: pip shows only
    "still running..." for the whole build): CANOPY_PROGRESS names a file; otherwise the
    terminal (/dev/tty) when there is one and our own output is not going to it already."""
    path = os.environ.get("CANOPY_PROGRESS")
    if path:
        return open(path, "a", encoding="utf-8")
    if sys.stdout.isatty():
        return None  # the lines themselves reach the terminal
    try:
        return open("/dev/tty", "w", encoding="utf-8")
    except OSError:
        return None


def _run_with_progress(command, **kwargs):
    """_run, echoing every line (pip shows them with -v) and writing "canopy build: N%" to
    _progress_sink() each time CMake's percentage grows."""
    print("canopy build:", " ".join(command), flush=True)
    sink = _progress_sink()
    shown = -1
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          errors="replace", **kwargs) as child:
        for line in child.stdout:
            sys.stdout.write(line)
            sys.stdout.flush()
            match = _PERCENT.match(line)
            if sink and match and int(match.group(1)) > shown:
                shown = int(match.group(1))
                sink.write(f"\rcanopy build: {shown}%")
                sink.flush()
    if sink:
        sink.write("\n")
        sink.close()
    if child.returncode != 0:
        raise subprocess.CalledProcessError(child.returncode, command)


def _cmake_env():
    """The environment for CMake: without pip's isolation variables, so that the real
    interpreter sees its own site-packages (Debian's numpy) when CMake asks it."""
    env = dict(os.environ)
    for name in ("PYTHONPATH", "PYTHONNOUSERSITE", "PYTHONHOME"):
        env.pop(name, None)
    return env


def _build():
    """Builds _canopy and canopy; returns the CMake build folder."""
    jobs = os.environ.get("CANOPY_JOBS") or str(os.cpu_count() or 2)
    python = os.path.realpath(sys.executable)
    build = os.environ.get("CANOPY_BUILD_DIR")
    if build:
        build = os.path.abspath(build)
        if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
            raise RuntimeError(f"CANOPY_BUILD_DIR={build}: not a configured CMake build folder "
                               "(no CMakeCache.txt); unset it to build in build/pip-*")
    else:
        build = os.path.join(ROOT, "build", f"pip-cp{sys.version_info.major}{sys.version_info.minor}")
        if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
            _run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                  "-DCANOPY_BUILD_TESTS=OFF", "-DCANOPY_BUILD_BENCH=OFF",
                  f"-DPython3_EXECUTABLE={python}"], env=_cmake_env())
    _run_with_progress(["cmake", "--build", build, "-j", jobs, "--target", "_canopy", "canopy"],
                       env=_cmake_env())
    return build


def _built_files(build):
    """(extension, program) of the build, checked against this interpreter."""
    package = os.path.join(build, "python", "canopy")
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    names = sorted(n for n in os.listdir(package) if n.startswith("_canopy.")) if os.path.isdir(package) else []
    if not names:
        raise RuntimeError(f"{build}: no _canopy extension was built: the Python module needs "
                           "pybind11 and NumPy (Debian: pybind11-dev python3-pybind11 python3-numpy "
                           "python3-dev); see the CMake output above")
    if os.path.join(package, "_canopy" + suffix) not in [os.path.join(package, n) for n in names]:
        raise RuntimeError(f"{build}: the extension {names} was built for another Python than "
                           f"{sys.executable} (needs _canopy{suffix}); set -DPython3_EXECUTABLE "
                           "in that build or unset CANOPY_BUILD_DIR")
    program = os.path.join(build, "app", "canopy")
    if not os.access(program, os.X_OK):
        raise RuntimeError(f"{build}: the canopy program was not built ({program})")
    return os.path.join(package, "_canopy" + suffix), program


def _package_files(build):
    """[(path in the wheel, path on disk)] of the package."""
    extension, program = _built_files(build)
    source = os.path.join(ROOT, "python", "canopy")
    files = [(f"canopy/{n}", os.path.join(source, n)) for n in sorted(os.listdir(source))
             if n.endswith((".py", ".pyi")) or n == "py.typed"]
    files.append((f"canopy/{os.path.basename(extension)}", extension))
    files.append(("canopy/bin/canopy", program))
    # The program's modules (GIS for `canopy import`, MPI), opened from beside it.
    app = os.path.dirname(program)
    files += [(f"canopy/bin/{n}", os.path.join(app, n)) for n in sorted(os.listdir(app))
              if n.startswith("libcanopy_") and n.endswith(".so")]
    scenarios = os.path.join(ROOT, "scenarios")
    for folder, dirs, names in os.walk(scenarios):
        dirs.sort()
        for n in sorted(names):
            path = os.path.join(folder, n)
            files.append(("canopy/scenarios/" + os.path.relpath(path, scenarios).replace(os.sep, "/"), path))
    return files


class _Wheel:
    def __init__(self, path):
        self.zip = zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED)
        self.records = []

    def add(self, name, data, executable=False):
        info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
        info.external_attr = (stat.S_IFREG | (0o755 if executable else 0o644)) << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        self.zip.writestr(info, data)
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        self.records.append((name, f"sha256={digest}", str(len(data))))

    def close(self, record_name):
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")
        writer.writerows(self.records + [(record_name, "", "")])
        info = zipfile.ZipInfo(record_name, date_time=(2020, 1, 1, 0, 0, 0))
        info.external_attr = (stat.S_IFREG | 0o644) << 16
        self.zip.writestr(info, text.getvalue())
        self.zip.close()


def _dist_info_files(project):
    return {"METADATA": _metadata(project),
            "WHEEL": f"Wheel-Version: 1.0\nGenerator: canopy_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n",
            "entry_points.txt": _entry_points(project),
            "top_level.txt": "canopy\n"}


# --- PEP 517 hooks --------------------------------------------------------------------------
def _require_numpy():
    """canopy builds against the NumPy of the Python running pip (Debian's python3-numpy, seen
    from a venv made with --system-site-packages). Without one pip would look for numpy on PyPI
    and, offline, say only "No matching distribution found for numpy" (issue 51): say why."""
    done = subprocess.run([sys.executable, "-c", "import numpy"], env=_cmake_env(),
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(
            f"canopy: this Python ({sys.executable}) has no NumPy, which canopy builds against and "
            "pip cannot fetch offline. canopy uses Debian's python3-numpy: make the venv from "
            "Debian's Python, `/usr/bin/python3 -m venv --system-site-packages ~/canopy-env`, "
            "and run its pip (a pyenv or conda Python needs `pip install numpy` first).")


def get_requires_for_build_wheel(config_settings=None):
    return []  # CMake, a compiler, pybind11 and NumPy come from the system (./canopy installs them)


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    _require_numpy()
    print("canopy build: the first build compiles canopy in Release (about 20 min on one core; "
          "its percentage goes to the terminal); `pip install -v .` shows CMake's lines",
          file=sys.stderr, flush=True)
    project = _project()
    name = f"{_dist_name(project)}-{project['version']}.dist-info"
    os.makedirs(os.path.join(metadata_directory, name), exist_ok=True)
    for file, text in _dist_info_files(project).items():
        if file == "WHEEL":
            continue
        with open(os.path.join(metadata_directory, name, file), "w", encoding="utf-8") as f:
            f.write(text)
    return name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    _require_numpy()
    project = _project()
    build = _build()
    dist = f"{_dist_name(project)}-{project['version']}"
    wheel_name = f"{dist}-{_tag()}.whl"
    os.makedirs(wheel_directory, exist_ok=True)
    wheel = _Wheel(os.path.join(wheel_directory, wheel_name))
    for name, path in _package_files(build):
        with open(path, "rb") as f:
            wheel.add(name, f.read(), executable=name == "canopy/bin/canopy")
    for file, text in _dist_info_files(project).items():
        wheel.add(f"{dist}.dist-info/{file}", text.encode())
    wheel.close(f"{dist}.dist-info/RECORD")
    return wheel_name


def build_sdist(sdist_directory, config_settings=None):
    """The source tree as git tracks it (or all of it but build/ and .git when git is missing)."""
    project = _project()
    base = f"{_dist_name(project)}-{project['version']}"
    try:
        listed = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, check=True,
                                capture_output=True).stdout.decode().split("\0")
        files = [f for f in listed if f and os.path.isfile(os.path.join(ROOT, f))]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for folder, dirs, names in os.walk(ROOT):
            dirs[:] = sorted(d for d in dirs if not (folder == ROOT and d in ("build", ".git", "out")))
            files += [os.path.relpath(os.path.join(folder, n), ROOT) for n in sorted(names)]
    os.makedirs(sdist_directory, exist_ok=True)
    name = f"{base}.tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for f in sorted(files):
            tar.add(os.path.join(ROOT, f), arcname=f"{base}/{f}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata(project).encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name
