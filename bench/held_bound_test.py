"""bench/held_bound.py against cases worked by hand (ctest HeldBound.handworked)."""
import json
import math
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from held_bound import bound  # noqa: E402


def scenario(people, v_max=0.5, duration=40.0):
    return {"clock": {"dt": 0.2, "duration": duration},
            "uavs": [{"start": [0, 0], "v_max": v_max, "fov": {"size": [20, 20]}}],
            "targets": [{"path": p} for p in people]}


@pytest.mark.parametrize("policy", ["nearest", "largest_error", "tracks_only"])
def test_a_person_who_turns_out_of_view_is_held_until_the_prediction_is_5_m_off(policy):
    # The person walks east at 1 m/s and turns north at t = 30 s; the UAV (0.5 m/s) loses sight of
    # it near t = 20 s with the true velocity (1, 0), so the prediction (t, 0) is exact until
    # t = 30 and then off by sqrt(2) (t - 30): held while t <= 30 + 5 / sqrt(2) = 33.54 s,
    # steps k = 0..167 of 0..200. Every policy flies after the one person (toward the truth, or
    # toward the track with tracks_only) and never catches up.
    spec = scenario([{"waypoints": [{"t": 0, "p": [0, 0]}, {"t": 30, "p": [30, 0]},
                                    {"t": 60, "p": [30, 30]}]}])
    held, last = bound(spec, policy)
    assert 30 + 5 / math.sqrt(2) < 0.2 * 168
    assert held == 168 / 201
    assert last == 0.0


@pytest.mark.parametrize("policy", ["nearest", "largest_error", "tracks_only"])
def test_people_standing_still_are_held_throughout_however_far_apart(policy):
    spec = scenario([{"waypoints": [{"t": 0, "p": [0, 0]}]},
                     {"waypoints": [{"t": 0, "p": [100, 0]}]}])
    assert bound(spec, policy) == (1.0, 1.0)


def test_tracks_only_flies_where_the_track_says_and_never_finds_a_person_who_turned():
    # The person walks east at 1 m/s from (60, 0) and turns north at t = 0.5 s, at 1.5 m/s; the
    # UAV starts at (0, 0) (20 x 20 footprint, 5 m/s) with the preseeded track (60 + t, 0).
    # tracks_only flies at that prediction: its x is 5t until it reaches it at t = 15 (x = 75),
    # then 60 + t. The person, at (60.5, 1.5 (t - 0.5)), would be in view for |5t - 60.5| <= 10
    # (t >= 10.1) and |y| <= 10 (t <= 7.2): never. The prediction is off by
    # (t - 0.5) sqrt(1 + 1.5^2) = 1.803 (t - 0.5) m: held while t <= 3.27 s, steps k = 0..16 of
    # 0..150. Flying at the truth (nearest) the UAV catches the person and holds it from then on.
    spec = scenario([{"waypoints": [{"t": 0, "p": [60, 0]}, {"t": 0.5, "p": [60.5, 0]},
                                    {"t": 40.5, "p": [60.5, 60]}]}], v_max=5.0, duration=30.0)
    tracks_held, tracks_last = bound(spec, "tracks_only")
    truth_held, truth_last = bound(spec, "nearest")
    assert math.sqrt(1 + 1.5 ** 2) * (3.2 - 0.5) <= 5 < math.sqrt(1 + 1.5 ** 2) * (3.4 - 0.5)
    assert tracks_held == 17 / 151 and tracks_last == 0.0
    assert truth_held > tracks_held and truth_last == 1.0


def test_an_unreadable_path_exits_2_naming_the_field(tmp_path):
    spec = scenario([{"track": [[0, 0, 0]]}])
    file = tmp_path / "s.json"
    file.write_text(json.dumps(spec))
    proc = subprocess.run([sys.executable, os.path.join(HERE, "held_bound.py"), str(file)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert "targets[0].path" in proc.stderr
