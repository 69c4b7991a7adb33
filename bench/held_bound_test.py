"""bench/held_bound.py against cases worked by hand (ctest HeldBound.handworked)."""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from held_bound import bound  # noqa: E402


def scenario(people, v_max=0.5, duration=40.0):
    return {"clock": {"dt": 0.2, "duration": duration},
            "uavs": [{"start": [0, 0], "v_max": v_max, "fov": {"size": [20, 20]}}],
            "targets": [{"path": p} for p in people]}


def test_a_person_who_turns_out_of_view_is_held_until_the_prediction_is_5_m_off():
    # The person walks east at 1 m/s and turns north at t = 30 s; the UAV (0.5 m/s) loses sight of
    # it near t = 20 s with the true velocity (1, 0), so the prediction (t, 0) is exact until
    # t = 30 and then off by sqrt(2) (t - 30): held while t <= 30 + 5 / sqrt(2) = 33.54 s,
    # steps k = 0..167 of 0..200.
    spec = scenario([{"waypoints": [{"t": 0, "p": [0, 0]}, {"t": 30, "p": [30, 0]},
                                    {"t": 60, "p": [30, 30]}]}])
    held, last = bound(spec)
    assert 30 + 5 / math.sqrt(2) < 0.2 * 168
    assert held == 168 / 201
    assert last == 0.0


def test_people_standing_still_are_held_throughout_however_far_apart():
    spec = scenario([{"waypoints": [{"t": 0, "p": [0, 0]}]},
                     {"waypoints": [{"t": 0, "p": [100, 0]}]}])
    assert bound(spec) == (1.0, 1.0)


def test_an_unreadable_path_exits_2_naming_the_field(tmp_path):
    spec = scenario([{"track": [[0, 0, 0]]}])
    file = tmp_path / "s.json"
    file.write_text(json.dumps(spec))
    proc = subprocess.run([sys.executable, os.path.join(HERE, "held_bound.py"), str(file)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert "targets[0].path" in proc.stderr
