"""TrackingEnv takes the real base classes when they are importable (issue 30).

pettingzoo and gymnasium are not Debian packages, so on this project's machines the first test
runs canopy against a minimal stand-in *shim* of both packages, written below, in a subprocess:
it proves that the conditional import picks pettingzoo.ParallelEnv and gymnasium.spaces.Box when
importable, not that canopy passes the real packages' checks. The last test runs PettingZoo's own
parallel API test only where the real pettingzoo is installed (skipped otherwise).
"""
import os
import subprocess
import sys
import textwrap

import pytest

SHIM = {
    "pettingzoo/__init__.py": """
        class ParallelEnv:
            metadata = {}
            @property
            def unwrapped(self):
                return self
        SHIM = True
    """,
    "gymnasium/__init__.py": "from . import spaces, vector\nSHIM = True\n",
    "gymnasium/vector.py": """
        import enum
        class AutoresetMode(enum.Enum):
            NEXT_STEP = "NextStep"
            SAME_STEP = "SameStep"
        class VectorEnv:
            metadata = {}
            spec = None
            render_mode = None
            closed = False
            def close(self, **kwargs):
                self.close_extras(**kwargs)
                self.closed = True
    """,
    "gymnasium/spaces.py": """
        import numpy as np
        class Box:
            def __init__(self, low, high, shape=None, dtype=np.float32):
                self.dtype = np.dtype(dtype)
                self.shape = tuple(shape)
                self.low = np.broadcast_to(np.asarray(low, self.dtype), self.shape)
                self.high = np.broadcast_to(np.asarray(high, self.dtype), self.shape)
            def contains(self, x):
                return x.shape == self.shape and bool(np.all((x >= self.low) & (x <= self.high)))
    """,
}

CHECK = """
import numpy as np, canopy, gymnasium, pettingzoo
assert gymnasium.SHIM and pettingzoo.SHIM
assert canopy.env.PETTINGZOO and canopy.spaces.GYMNASIUM
s = canopy.load("trajectory_handover", overrides={"clock.duration": 1.0})
env = canopy.TrackingEnv(s)
assert isinstance(env, pettingzoo.ParallelEnv)
for a in env.possible_agents:
    assert type(env.observation_space(a)) is gymnasium.spaces.Box
    assert type(env.action_space(a)) is gymnasium.spaces.Box
assert type(env.state_space) is gymnasium.spaces.Box
obs, _ = env.reset(seed=1)
assert all(env.observation_space(a).contains(o) for a, o in obs.items())
vec = canopy.VectorEnv(2, s)
assert type(vec.single_observation_space) is gymnasium.spaces.Box
assert isinstance(vec, gymnasium.vector.VectorEnv)  # Gymnasium's vector wrappers check this
assert vec.metadata["autoreset_mode"] is gymnasium.vector.AutoresetMode.NEXT_STEP
assert vec.observation_space.shape == (2,) + vec.single_observation_space.shape
print("real bases taken")
"""


def test_the_shimmed_packages_are_used_when_importable(tmp_path):
    for name, text in SHIM.items():
        path = tmp_path / name
        path.parent.mkdir(exist_ok=True)
        path.write_text(textwrap.dedent(text))
    env = dict(os.environ)
    import canopy  # the copy under test, found again from the subprocess
    here = os.path.dirname(os.path.dirname(os.path.abspath(canopy.__file__)))
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), here])
    done = subprocess.run([sys.executable, "-c", CHECK], capture_output=True, text=True, env=env,
                          cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "real bases taken"


def test_without_them_the_stand_ins_are_used():
    import canopy
    try:
        import pettingzoo  # noqa: F401
        pytest.skip("pettingzoo is installed here")
    except ImportError:
        pass
    assert not canopy.env.PETTINGZOO
    env = canopy.TrackingEnv("trajectory_handover")
    assert type(env).__mro__[1] is canopy.env._ParallelEnv and env.unwrapped is env
    if not canopy.spaces.GYMNASIUM:
        assert type(env.action_space("UAV1")) is canopy.spaces.Box


def test_pettingzoo_parallel_api_test():  # pragma: no cover - needs the real pettingzoo
    test = pytest.importorskip("pettingzoo.test")
    import canopy
    s = canopy.load("trajectory_handover", overrides={"clock.duration": 2.0})
    test.parallel_api_test(canopy.TrackingEnv(s), num_cycles=20)
