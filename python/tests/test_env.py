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


# --- the ParallelEnv contract, item by item (issue 30) --------------------------------------
# Run here against the stand-ins (pettingzoo and gymnasium are not Debian packages);
# test_real_bases.py checks that the real classes are used when importable.

def test_base_class_and_unwrapped():
    env = _env()
    assert env.unwrapped is env
    assert str(env) == "canopy_tracking_v0"
    if canopy.env.PETTINGZOO:  # pragma: no cover - not on Debian 12
        import pettingzoo
        assert isinstance(env, pettingzoo.ParallelEnv)


def test_possible_agents_fixed_and_agents_shrink_to_empty():
    env = _env()
    before = list(env.possible_agents)
    assert env.agents == []  # before reset: no live agent
    env.reset(seed=2)
    seen = [list(env.agents)]
    while env.agents:
        env.step({a: np.zeros(2) for a in env.agents})
        seen.append(list(env.agents))
        assert env.possible_agents == before
    # All agents live for the whole episode (no agent is lost), then all leave at once.
    assert seen[:-1] == [before] * 10 and seen[-1] == []
    assert all(set(s) <= set(before) for s in seen)


def test_spaces_same_object_every_call_before_and_after_reset():
    env = _env()
    spaces = {a: (env.observation_space(a), env.action_space(a)) for a in env.possible_agents}
    env.reset(seed=1)
    env.step({a: np.zeros(2) for a in env.agents})
    for a in env.possible_agents:
        assert env.observation_space(a) is spaces[a][0] and env.action_space(a) is spaces[a][1]
        assert env.observation_spaces[a] is spaces[a][0] and env.action_spaces[a] is spaces[a][1]


def test_bounds_are_finite_and_as_documented():
    # trajectory_handover: AOI ±40 m, starts (±9, 0), v_max 5 m/s (the default); duration 2 s
    # here → positions within ceil(40 + 5 · 2) = 50 m; track speeds max(50, 5 · 5) = 50 m/s.
    env = _env(max_tracks=2, max_trees=1, map_radius=12.5)
    space = env.observation_space("UAV1")
    assert space.dtype == np.float32 and space.shape == (3 + 14 + 4,)
    assert np.all(np.isfinite(space.low)) and np.all(np.isfinite(space.high))
    pi = np.float32(np.pi)
    track = [50, 50, 50, 50, 1e4, 1e4, 1]
    np.testing.assert_array_equal(space.high, [50, 50, pi] + track * 2 + [12.5, 12.5, 12.5, 1])
    np.testing.assert_array_equal(space.low, [-50, -50, -pi] + [-50, -50, -50, -50, 0, 0, 0] * 2
                                  + [-12.5, -12.5, 0, 0])
    a = env.action_space("UAV2")
    assert a.dtype == np.float32 and a.shape == (2,)
    np.testing.assert_array_equal(a.low, [-5, -5]) and np.testing.assert_array_equal(a.high, [5, 5])
    # state: 2 UAV poses and 4 target states
    assert env.state_space.shape == (2 * 3 + 4 * 4,) and env.state_space.dtype == np.float32
    np.testing.assert_array_equal(env.state_space.high, [50, 50, pi] * 2 + [50, 50, 50, 50] * 4)


def test_observations_are_clipped_into_their_space():
    # A crown of radius 4 m whose centre is 1 m from UAV1, with map_radius 2 m: the disc is
    # mapped, its offset kept, and its radius clipped to the bound, 2 m.
    s = canopy.load("trajectory_handover", overrides={"clock.duration": 2.0})
    s.occluders.append(canopy.forest.disc((-8, 0), 4.0))
    env = canopy.TrackingEnv(s, max_trees=2, map_radius=2.0)
    obs, _ = env.reset(seed=1)
    for _ in range(3):
        obs, *_ = env.step({a: np.zeros(2) for a in env.agents})
    tree = env.sim.occlusion_map(0)["means"]
    assert len(tree) == 1 and tree[0, 2] > 3.5
    dx, dy, r, valid = obs["UAV1"][-8:-4]
    pose = env.sim.uav_states[0]
    assert (dx, dy) == (np.float32(tree[0, 0] - pose[0]), np.float32(tree[0, 1] - pose[1]))
    assert r == 2.0 and valid == 1 and np.all(obs["UAV1"][-4:] == 0)
    assert env.observation_space("UAV1").contains(obs["UAV1"])


def test_every_observation_inside_its_space_with_random_actions():
    env = _env(render_mode=None)
    for seed in (0, 1):
        obs, _ = env.reset(seed=seed)
        rng = np.random.default_rng(seed)
        while True:
            for a, o in obs.items():
                space = env.observation_space(a)
                assert o.dtype == space.dtype and o.shape == space.shape
                assert np.all(o >= space.low) and np.all(o <= space.high) and space.contains(o)
            state = env.state()
            assert env.state_space.contains(state) and state.dtype == np.float32
            if not env.agents:
                break
            # actions up to twice the action space's bounds: the simulation clamps them
            obs, *_ = env.step({a: rng.uniform(-10, 10, 2) for a in env.agents})


def test_state_is_the_truth():
    env = _env()
    env.reset(seed=4)
    env.step({a: np.array([1.0, -1.0]) for a in env.agents})
    expected = np.concatenate([env.sim.uav_states.ravel(), env.sim.target_states.ravel()])
    np.testing.assert_array_equal(env.state(), expected.astype(np.float32))
    env.close()
    with pytest.raises(RuntimeError, match="reset"):
        env.state()


def test_reset_with_options_and_seed_is_deterministic():
    env = _env()
    a, ia = env.reset(seed=11, options={})
    b, ib = env.reset(seed=11, options=None)
    for agent in a:
        np.testing.assert_array_equal(a[agent], b[agent])
    assert ia == ib and set(ia) == set(env.agents)
    c, _ = env.reset(seed=11, options={"difficulty": 3})  # keys ignored, as PettingZoo expects
    for agent in a:
        np.testing.assert_array_equal(a[agent], c[agent])
    with pytest.raises(ValueError, match="a dict"):
        env.reset(seed=1, options=3)


def test_infos_one_dict_per_live_agent():
    env = _env()
    _, infos = env.reset(seed=1)
    assert set(infos) == set(env.agents) and all(isinstance(v, dict) for v in infos.values())
    k = 0
    while env.agents:
        live = list(env.agents)
        *_, infos = env.step({a: np.zeros(2) for a in live})
        k += 1
        assert set(infos) == set(live) and all(i["step"] == k for i in infos.values())


def test_truncation_at_max_cycles_and_never_termination():
    env = _env(max_cycles=4)
    assert env.max_cycles == 4
    env.reset(seed=1)
    flags = []
    while env.agents:
        _, _, term, trunc, _ = env.step({a: np.zeros(2) for a in env.agents})
        assert not any(term.values())
        flags.append(all(trunc.values()))
        assert len(set(trunc.values())) == 1  # the whole team together
    assert flags == [False, False, False, True] and env.sim.step_index == 4
    assert _env(max_cycles=1000).max_cycles == 10  # at most the scenario's K
    for bad in (0, -1, 2.5, True):
        with pytest.raises(ValueError, match="max_cycles"):
            _env(max_cycles=bad)


def test_render_fps_is_the_scenario_step_rate():
    assert _env().metadata["render_fps"] == 5  # dt = 0.2 s
    s = canopy.load("trajectory_handover", overrides={"clock.dt": 0.5})
    assert canopy.TrackingEnv(s).metadata["render_fps"] == 2
    assert canopy.TrackingEnv.metadata["render_modes"] == ["human", "rgb_array"]


def test_render_rgb_array_and_none():
    env = _env(render_mode="rgb_array", render_size=(160, 120))
    assert env.render() is None  # before reset
    env.reset(seed=1)
    frame = env.render()
    assert frame.shape == (120, 160, 3) and frame.dtype == np.uint8 and frame.std() > 0
    assert _env().render() is None  # no render mode
    with pytest.raises(ValueError, match="render_mode"):
        _env(render_mode="ansi")


def test_render_human_shows_each_step_in_a_figure():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")  # no display here: the figure is drawn off screen
    env = _env(render_mode="human", render_size=(160, 120))
    assert env.reset(seed=1) and env.render() is None
    _, figure, image = env._window
    env.step({a: np.array([3.0, 0.0]) for a in env.agents})
    np.testing.assert_array_equal(image.get_array(), env.sim.render(160, 120))
    env.close()
    assert env._window is None and env.sim is None and env.agents == []


def test_close_ends_the_episode():
    env = _env()
    env.reset(seed=1)
    env.close()
    assert env.agents == [] and env.sim is None
    with pytest.raises(RuntimeError, match="reset"):
        env.step({})
    env.reset(seed=1)  # usable again after close
    assert env.agents == env.possible_agents


def test_pickled_env_is_the_env_as_built():
    # SuperSuit's concat_vec_envs and RLlib's workers copy environments by pickling them.
    import pickle
    env = _env(max_cycles=4)
    env.reset(seed=3)
    copy = pickle.loads(pickle.dumps(env))
    assert copy.agents == [] and copy.sim is None and copy.max_cycles == 4
    a, _ = env.reset(seed=8)
    b, _ = copy.reset(seed=8)
    for agent in a:
        np.testing.assert_array_equal(a[agent], b[agent])
        assert copy.observation_space(agent) == env.observation_space(agent)


def test_altitude_free_scenario_observes_z_and_takes_vz():
    # altitude_tradeoff: two UAVs at 20 m with z in [10, 60] and a climb rate of 2 m/s (issue 53).
    s = canopy.load("altitude_tradeoff", overrides={"clock.duration": 1.0})
    env = canopy.TrackingEnv(s)
    assert env.altitude
    plane = canopy.TrackingEnv(s, altitude=False)
    for a in env.possible_agents:
        space = env.action_space(a)
        assert space.shape == (3,)
        assert list(space.high) == [5.0, 5.0, 2.0] and list(space.low) == [-5.0, -5.0, -2.0]
        assert env.observation_space(a).shape[0] == plane.observation_space(a).shape[0] + 1
        assert env.observation_space(a).low[-1] == 10.0 and env.observation_space(a).high[-1] == 60.0
        assert plane.action_space(a).shape == (2,)
    obs, _ = env.reset(seed=3)
    assert [float(obs[a][-1]) for a in env.agents] == [20.0, 20.0]
    # UAV1 climbs at 2 m/s, UAV2 asks for 9 m/s down (clamped to 2): one 0.2 s step, ±0.4 m.
    obs, _, _, _, _ = env.step({"UAV1": [0.0, 0.0, 2.0], "UAV2": [0.0, 0.0, -9.0]})
    assert float(obs["UAV1"][-1]) == pytest.approx(20.4)
    assert float(obs["UAV2"][-1]) == pytest.approx(19.6)
    with pytest.raises(canopy.ScenarioError, match=r"shape \(3,\)"):
        env.step({"UAV1": [0.0, 0.0], "UAV2": [0.0, 0.0]})
    # A scenario without altitude keeps the plane: (vx, vy) and no z.
    assert not _env().altitude and _env().action_space("UAV1").shape == (2,)
