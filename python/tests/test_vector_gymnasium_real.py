"""Gymnasium's own vector wrappers step canopy.VectorEnv (issue 51: they raised "TypeError:
Expected env to be a gymnasium.vector.VectorEnv"). Skipped where Gymnasium (1.x) is not
importable: it is not a Debian package. To run them, put a Gymnasium source tree on PYTHONPATH
(README, "Python")."""
import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")
vector = pytest.importorskip("gymnasium.vector")
if not hasattr(vector, "AutoresetMode"):
    pytest.skip("Gymnasium before 1.0 has no vector wrappers of this kind", allow_module_level=True)
from gymnasium.wrappers.vector import NormalizeObservation, RecordEpisodeStatistics  # noqa: E402

import canopy  # noqa: E402


def _demo(**kwargs):
    return canopy.VectorEnv(2, canopy.load("demo", overrides={"clock.duration": 1.0}), **kwargs)


def test_it_is_a_gymnasium_vector_env():
    vec = canopy.VectorEnv(2, "demo")
    assert isinstance(vec, gymnasium.vector.VectorEnv) and canopy.vector.GYMNASIUM_VECTOR
    assert vec.metadata["autoreset_mode"] is vector.AutoresetMode.NEXT_STEP
    assert type(vec.single_observation_space) is gymnasium.spaces.Box


def test_record_episode_statistics_steps_it_and_counts_the_team_return():
    env = RecordEpisodeStatistics(_demo())  # K = 5 steps
    env.reset(seed=1)
    total = np.zeros(2)
    for k in range(5):
        _, rewards, terms, truncs, infos = env.step(np.zeros(env.action_space.shape))
        total += rewards
    assert truncs.all() and not terms.any()
    np.testing.assert_allclose(infos["episode"]["r"], total)
    np.testing.assert_array_equal(infos["episode"]["l"], [5, 5])
    assert len(env.return_queue) == 2
    env.step(np.zeros(env.action_space.shape))  # the autoreset step
    env.close()


def test_normalize_observation_steps_it_through_an_autoreset():
    env = NormalizeObservation(_demo())
    obs, _ = env.reset(seed=2)
    for _ in range(12):
        obs, *_ = env.step(env.action_space.sample())
        assert obs.dtype == np.float32 and obs.shape == env.observation_space.shape
        assert np.isfinite(obs).all()
    assert env.obs_rms.count > 12


def test_render_through_a_wrapper():
    env = RecordEpisodeStatistics(_demo(render_mode="rgb_array", render_size=(32, 24)))
    env.reset(seed=3)
    frames = env.render()
    assert len(frames) == 2 and frames[0].shape == (24, 32, 3)
