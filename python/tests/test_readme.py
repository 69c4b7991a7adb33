"""The README's Python example runs as printed."""
import os
import pathlib
import re
import subprocess
import sys

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"


def test_readme_example_runs_as_printed(tmp_path):
    text = README.read_text(encoding="utf-8")
    match = re.search(r"<!-- python-example -->\n```python\n(.*?)```", text, re.S)
    assert match, "README.md: no python example after <!-- python-example -->"
    code = match.group(1)
    assert len(code.strip().splitlines()) == 10
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                          text=True, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    step, rest = done.stdout.split(" ", 1)
    assert step == "150"  # demo: 30 s at dt 0.2 s
    assert rest.strip().endswith("4, 4)")
