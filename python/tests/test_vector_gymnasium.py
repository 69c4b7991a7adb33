"""VectorEnv as a gymnasium.vector.VectorEnv (issue 51): Gymnasium's data layout by default (the
team's rewards, terminations and truncations (n,), next-step autoreset), render_mode and
render(), and the base class's attributes (spec, unwrapped, np_random, close). These run against
the stand-in base where Gymnasium is absent (it is not a Debian package) and against Gymnasium's
own class where it is importable; test_vector_gymnasium_real.py runs Gymnasium's wrappers."""
import numpy as np
import pytest

import canopy
from canopy import _vector_base


def _scenario():
    return canopy.load("trajectory_handover", overrides={"clock.duration": 2.0})  # K = 10


def test_next_step_autoreset_and_team_rewards_equal_single_envs_bit_for_bit():
    # Environment i is TrackingEnv reset with seed 40 + i; its episode is cut at 3 steps. At the
    # step after it ends, the vector env resets it (action ignored, reward 0, not done) and
    # returns the new episode's first observation, seeded as TrackingEnv.reset() without a seed.
    n, cycles = 3, 3
    vec = canopy.VectorEnv(n, _scenario(), max_tracks=4, max_trees=4, max_cycles=cycles)
    singles = [canopy.TrackingEnv(_scenario(), max_tracks=4, max_trees=4, max_cycles=cycles)
               for _ in range(n)]
    agents = vec.possible_agents
    obs, infos = vec.reset(seed=40)
    expected = [env.reset(seed=40 + i)[0] for i, env in enumerate(singles)]
    assert list(infos["seed"]) == [40, 41, 42] and infos["_seed"].all()
    rng = np.random.default_rng(1)
    resets = 0
    for k in range(2 * (cycles + 1)):
        for i in range(n):
            assert obs[i].tobytes() == np.stack([expected[i][a] for a in agents]).tobytes(), (k, i)
        actions = rng.uniform(-4, 4, (n, len(agents), 2))
        obs, rew, term, trunc, infos = vec.step(actions)
        assert rew.shape == term.shape == trunc.shape == (n,) and not term.any()
        for i, env in enumerate(singles):
            if not env.agents:  # it ended at the last step: reset now
                o, info = env.reset()
                assert infos["_seed"][i] and info[agents[0]]["seed"] == infos["seed"][i]
                assert rew[i] == 0.0 and not trunc[i] and infos["step"][i] == 0
                resets += 1
            else:
                o, r, _, tr, _ = env.step({a: actions[i, j] for j, a in enumerate(agents)})
                assert rew[i] == sum(r[a] for a in agents)  # the team's reward
                assert trunc[i] == all(tr.values())
            expected[i] = o
    assert resets == 2 * n  # twice each: at steps cycles + 1 and 2 (cycles + 1)


def test_render_rgb_array_gives_each_environments_frame():
    vec = canopy.VectorEnv(2, _scenario(), render_mode="rgb_array", render_size=(64, 48))
    assert vec.render_mode == "rgb_array" and vec.metadata["render_modes"] == ["rgb_array"]
    assert vec.render() is None  # before reset
    vec.reset(seed=3)
    vec.step(np.full((2, 2, 2), 1.5))
    frames = vec.render()
    assert isinstance(frames, tuple) and len(frames) == 2
    single = canopy.TrackingEnv(_scenario(), render_mode="rgb_array", render_size=(64, 48))
    single.reset(seed=4)  # environment 1
    single.step({a: np.full(2, 1.5) for a in single.possible_agents})
    for frame in frames:
        assert frame.shape == (48, 64, 3) and frame.dtype == np.uint8
    np.testing.assert_array_equal(frames[1], single.render())
    assert canopy.VectorEnv(2, _scenario()).render() is None  # no render_mode
    with pytest.raises(canopy.ScenarioError, match="VectorEnv: render_mode: expected None or 'rgb_array'"):
        canopy.VectorEnv(2, _scenario(), render_mode="human")
    with pytest.raises(canopy.ScenarioError, match="VectorEnv: autoreset_mode"):
        canopy.VectorEnv(2, _scenario(), autoreset_mode="Disabled")


def test_the_base_classes_attributes():
    vec = canopy.VectorEnv(2, _scenario())
    assert isinstance(vec, _vector_base._VectorEnvBase)
    assert vec.spec is None and vec.unwrapped is vec and not vec.closed
    vec.reset(seed=9)
    assert vec.np_random_seed == 9 and isinstance(vec.np_random, np.random.Generator)
    first = vec.np_random.integers(1 << 30)
    vec.reset(seed=9)
    assert vec.np_random.integers(1 << 30) == first  # reset(seed) reseeds it
    vec.reset(seed=[5, 2**64 - 1])  # one seed per environment: no one integer names the stream
    assert vec.np_random_seed == -1 and isinstance(vec.np_random, np.random.Generator)
    assert repr(vec).startswith("VectorEnv(")
    vec.close()
    assert vec.closed
    vec.close()  # a second close does nothing


def test_reset_mask_resets_only_the_environments_it_marks():
    vec = canopy.VectorEnv(3, _scenario())
    first, _ = vec.reset(seed=20)
    vec.step(np.full((3, 2, 2), 2.0))
    obs, infos = vec.reset(seed=20, options={"reset_mask": np.array([False, True, False])})
    assert list(infos["_seed"]) == [False, True, False] and infos["seed"][1] == 21
    np.testing.assert_array_equal(obs[1], first[1])  # environment 1 starts over with seed 21
    assert not np.array_equal(obs[0], first[0])  # environment 0 kept its step
    with pytest.raises(canopy.ScenarioError, match="reset_mask"):
        vec.reset(options={"reset_mask": np.zeros(3, bool)})
