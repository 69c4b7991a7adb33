"""The build backend says why when the Python running pip has no NumPy (issue 51: a pyenv Python
failed after 10 s with only pip's "No matching distribution found for numpy")."""
import os
import pathlib
import subprocess
import sys

BACKEND = pathlib.Path(__file__).resolve().parents[1] / "build_backend"


def _metadata(python, tmp_path):
    env = dict(os.environ, PYTHONPATH=str(BACKEND))
    return subprocess.run([str(python), "-c", "import canopy_build; print(canopy_build."
                           f"prepare_metadata_for_build_wheel({str(tmp_path / 'meta')!r}))"],
                          capture_output=True, text=True, env=env, cwd=tmp_path)


def test_a_python_without_numpy_is_told_what_to_do(tmp_path):
    # A venv without the system's site-packages: no NumPy, as in a pyenv or conda Python.
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(tmp_path / "bare")],
                   check=True)
    done = _metadata(tmp_path / "bare" / "bin" / "python", tmp_path)
    assert done.returncode != 0
    assert "has no NumPy" in done.stderr and "--system-site-packages" in done.stderr, done.stderr
    # The README's venv (Debian's NumPy through --system-site-packages) gets its metadata.
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", "--system-site-packages",
                    str(tmp_path / "debian")], check=True)
    done = _metadata(tmp_path / "debian" / "bin" / "python", tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "canopy-0.1.0.dist-info"
    assert "pip install -v ." in done.stderr


def test_the_build_shows_its_percentage_where_pip_hides_the_output(tmp_path):
    # pip captures the backend's output; the percentage goes to the terminal (here a file, as
    # CANOPY_PROGRESS says), once per new value, and every line still reaches the output.
    lines = ["[  3%] Building CXX object a.o", "[  3%] Building CXX object b.o",
             "note: no percentage", "[ 50%] Linking CXX executable canopy", "[100%] Built target x"]
    script = "import sys; print(" + repr("\n".join(lines)) + ")"
    sink = tmp_path / "progress"
    code = ("import canopy_build, sys; "
            f"canopy_build._run_with_progress([sys.executable, '-c', {script!r}])")
    env = dict(os.environ, PYTHONPATH=str(BACKEND), CANOPY_PROGRESS=str(sink))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    assert all(line in done.stdout for line in lines)
    assert sink.read_bytes() == b"\rcanopy build: 3%\rcanopy build: 50%\rcanopy build: 100%\n"
    # A failing build still fails, with its exit code.
    code = "import canopy_build, sys; canopy_build._run_with_progress([sys.executable, '-c', 'raise SystemExit(3)'])"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert done.returncode != 0 and "returned non-zero exit status 3" in done.stderr
