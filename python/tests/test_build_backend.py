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
