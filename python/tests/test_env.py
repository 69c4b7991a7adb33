"""TrackingEnv against the PettingZoo ParallelEnv contract (written from its documentation; the
package itself is not installed): reset/step return shapes, the agents list, terminations and
truncations per agent, spaces, rendering and determinism under a seed."""
import numpy as np
import pytest

import canopy


def _env(**kwargs):
    s = canopy.load("trajectory_handover", overrides={"clock.duration": 2.0})  # K = 10 steps
    return canopy.TrackingEnv(s, **kwargs)


def _rollout(env, seed, actions_rng_seed=0):
    obs, _ = env.reset(seed=seed)
    rng = np.random.default_rng(actions_rng_seed)
    trace = [obs]
    rewards = []
    while env.agents:
        actions = {a: rng.uniform(-3, 3, 2).astype(np.float32) for a in env.agents}
        obs, rew, _, _, _ = env.step(actions)
        trace.append(obs)
        rewards.append(rew)
    return trace, rewards


def test_parallel_api():
    env = _env(render_mode="rgb_array")
    assert isinstance(env.metadata, dict) and "rgb_array" in env.metadata["render_modes"]
    agents = env.possible_agents
    assert agents == ["UAV1", "UAV2"] and len(set(agents)) == len(agents)
    assert env.max_num_agents == 2
    for a in agents:  # spaces exist before reset, and are the same object every call
        assert env.observation_space(a) is env.observation_space(a)
        assert env.action_space(a) is env.action_space(a)
    observations, infos = env.reset(seed=1)
    assert env.agents == agents and env.num_agents == 2
    assert set(observations) == set(agents) and set(infos) == set(agents)
    for a in agents:
        space = env.observation_space(a)
        assert observations[a].shape == space.shape and observations[a].dtype == np.float32
        assert space.contains(observations[a])
    steps = 0
    while env.agents:
        live = list(env.agents)
        actions = {a: env.action_space(a).sample() for a in live}
        for a in live:
            assert env.action_space(a).contains(actions[a])
        result = env.step(actions)
        assert len(result) == 5
        obs, rewards, terminations, truncations, infos = result
        for d in result:
            assert set(d) == set(live)
        for a in live:
            assert env.observation_space(a).contains(obs[a])
            assert isinstance(rewards[a], float)
            assert terminations[a] is False and isinstance(truncations[a], bool)
        steps += 1
        last = truncations
    assert steps == 10 and all(last.values()) and env.agents == []
    with pytest.raises(RuntimeError, match="reset"):
        env.step({a: np.zeros(2) for a in agents})
    frame = env.render()
    assert frame.shape == (300, 400, 3) and frame.dtype == np.uint8
    env.close()


def test_same_seed_same_episode_other_seed_other_episode():
    env = _env()
    a_obs, a_rew = _rollout(env, seed=7)
    b_obs, b_rew = _rollout(env, seed=7)
    c_obs, _ = _rollout(env, seed=8)
    for x, y in zip(a_obs, b_obs):
        for agent in x:
            np.testing.assert_array_equal(x[agent], y[agent])
    assert a_rew == b_rew
    assert any(not np.array_equal(x[a], y[a]) for x, y in zip(a_obs, c_obs) for a in x)


def test_unseeded_resets_follow_the_first_seed():
    env = _env()
    env.reset(seed=5)
    seeds_a = [env.reset()[1]["UAV1"]["seed"] for _ in range(3)]
    env.reset(seed=5)
    seeds_b = [env.reset()[1]["UAV1"]["seed"] for _ in range(3)]
    assert seeds_a == seeds_b and len(set(seeds_a)) == 3


def test_observation_layout_and_reward_by_hand():
    env = _env(max_tracks=6, max_trees=2)
    obs, _ = env.reset(seed=3)
    o = obs["UAV1"]
    assert o.shape == (3 + 7 * 6 + 4 * 2,)
    np.testing.assert_array_equal(o[:3], [-9, 0, 0])  # UAV1 starts at (−9, 0), yaw 0
    tracks = o[3:3 + 42].reshape(6, 7)
    assert list(tracks[:, 6]) == [1, 1, 1, 1, 0, 0]  # four pre-seeded targets, two padding rows
    assert np.all(tracks[4:] == 0)
    _, rewards, _, _, _ = env.step({"UAV1": np.zeros(2), "UAV2": np.zeros(2)})
    P = env.sim.tracks(0)["covariances"]
    by_hand = -sum(P[j, 0, 0] + P[j, 1, 1] for j in range(len(P)))
    assert rewards["UAV1"] == pytest.approx(by_hand, rel=1e-12) and rewards["UAV1"] < 0


def test_actions_fly_the_uavs():
    env = _env()
    env.reset(seed=1)
    env.step({"UAV1": np.array([2.0, 0.0]), "UAV2": np.array([0.0, -1.0])})
    np.testing.assert_allclose(env.sim.uav_velocities, [[2, 0], [0, -1]], atol=1e-6)


def test_bad_actions_raise():
    env = _env()
    env.reset(seed=1)
    with pytest.raises(ValueError, match="missing"):
        env.step({"UAV1": np.zeros(2)})
    with pytest.raises(ValueError, match=r"expected shape \(2,\)"):
        env.step({"UAV1": np.zeros(3), "UAV2": np.zeros(2)})
    with pytest.raises(ValueError, match="finite"):
        env.step({"UAV1": np.array([np.nan, 0]), "UAV2": np.zeros(2)})


def test_custom_reward():
    env = _env(reward_fn=lambda sim, i: float(i))
    env.reset(seed=1)
    _, rewards, _, _, _ = env.step({"UAV1": np.zeros(2), "UAV2": np.zeros(2)})
    assert rewards == {"UAV1": 0.0, "UAV2": 1.0}
