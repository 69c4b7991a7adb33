"""VectorEnv against TrackingEnv (the same episodes, bit for bit) and the GIL released by
Simulation.step (issue 30)."""
import sys
import threading

import numpy as np
import pytest

import canopy


def _scenario():
    return canopy.load("trajectory_handover", overrides={"clock.duration": 2.0})  # K = 10


def _actions(rng, n, agents):
    return rng.uniform(-4, 4, (n, agents, 2))


@pytest.mark.parametrize("threads", [None, 1, 3])
def test_eight_envs_equal_eight_single_envs_bit_for_bit(threads):
    n, seed, cycles = 8, 100, 4
    vec = canopy.VectorEnv(n, _scenario(), max_tracks=4, max_trees=4, max_cycles=cycles,
                           threads=threads, agent_axis=True, autoreset_mode="SameStep")
    singles = [canopy.TrackingEnv(_scenario(), max_tracks=4, max_trees=4, max_cycles=cycles)
               for _ in range(n)]
    agents = vec.possible_agents
    obs, infos = vec.reset(seed=seed)
    expected = [env.reset(seed=seed + i)[0] for i, env in enumerate(singles)]
    np.testing.assert_array_equal(infos["seed"], np.arange(seed, seed + n))
    rng = np.random.default_rng(0)
    ended = 0
    for k in range(2 * cycles + 1):  # two autoresets
        for i in range(n):
            for j, a in enumerate(agents):
                assert obs[i, j].tobytes() == expected[i][a].tobytes(), (k, i, a)
        actions = _actions(rng, n, len(agents))
        obs, rew, term, trunc, infos = vec.step(actions)
        if "final_obs" in infos:  # None exactly where the mask is clear
            assert [o is None for o in infos["final_obs"]] == [not m for m in infos["_final_obs"]]
        expected = []
        for i, env in enumerate(singles):  # one after another, on this thread
            o, r, t, tr, _ = env.step({a: actions[i, j] for j, a in enumerate(agents)})
            assert list(rew[i]) == [r[a] for a in agents]
            assert list(term[i]) == [t[a] for a in agents] and list(trunc[i]) == [tr[a] for a in agents]
            if not env.agents:  # the vector env reset it in the same call: so do we
                for j, a in enumerate(agents):
                    assert infos["final_observation"][i, j].tobytes() == o[a].tobytes()
                assert infos["_final_observation"][i]
                # Gymnasium 1.x's names for the same
                assert infos["_final_obs"][i] and infos["_final_info"][i]
                assert infos["final_obs"][i].tobytes() == infos["final_observation"][i].tobytes()
                assert infos["final_info"]["step"][i] == infos["step"][i]
                o, info = env.reset()  # the seed drawn as VectorEnv draws it
                assert info[agents[0]]["seed"] == infos["seed"][i]
                ended += 1
            expected.append(o)
    assert ended == 2 * n


def test_shapes_spaces_and_dtypes():
    vec = canopy.VectorEnv(3, _scenario(), max_tracks=2, max_trees=1, agent_axis=True)
    size = 3 + 7 * 2 + 4
    assert vec.num_envs == len(vec) == 3 and vec.possible_agents == ["UAV1", "UAV2"]
    assert vec.single_observation_space.shape == (2, size)
    assert vec.observation_space.shape == (3, 2, size) and vec.action_space.shape == (3, 2, 2)
    mode = vec.metadata["autoreset_mode"]  # gymnasium.vector.AutoresetMode.NEXT_STEP, or its value
    assert getattr(mode, "value", mode) == "NextStep"
    obs, _ = vec.reset(seed=0)
    assert obs.dtype == np.float32 and vec.observation_space.contains(obs)
    obs, rew, term, trunc, infos = vec.step(vec.action_space.sample())
    assert rew.shape == term.shape == trunc.shape == (3, 2) and rew.dtype == np.float64
    assert term.dtype == trunc.dtype == bool and not term.any() and not trunc.any()
    np.testing.assert_array_equal(infos["step"], [1, 1, 1])
    assert vec.observation_space.contains(obs)
    # returned arrays are the caller's: the next step does not overwrite them
    kept = obs.copy()
    vec.step(np.zeros((3, 2, 2)))
    np.testing.assert_array_equal(obs, kept)


def test_bad_input_raises():
    vec = canopy.VectorEnv(2, _scenario())
    with pytest.raises(RuntimeError, match="reset"):
        vec.step(np.zeros((2, 2, 2)))
    vec.reset(seed=1)
    with pytest.raises(ValueError, match=r"shape \(2, 2, 2\)"):
        vec.step(np.zeros((2, 2)))
    bad = np.zeros((2, 2, 2))
    bad[1, 0, 1] = np.inf
    with pytest.raises(ValueError, match=r"actions\[1, 0\]: expected a finite velocity"):
        vec.step(bad)
    with pytest.raises(ValueError, match="seed: expected an integer or a sequence of 2 integers"):
        vec.reset(seed=[1, 2, 3])
    for n in (0, -1, 1.5):
        with pytest.raises(ValueError, match="n: expected"):
            canopy.VectorEnv(n, _scenario())
    with pytest.raises(ValueError, match="threads"):
        canopy.VectorEnv(2, _scenario(), threads=0)


def test_step_releases_the_gil():
    # While one thread steps a Simulation, another runs Python: it finds the simulation busy
    # (a RuntimeError, never a half-written record). With the GIL held through step() no other
    # thread could run then, and it would never see it busy.
    # trajectory_handover with its planner: a planning step takes milliseconds, time enough for
    # the other thread to be scheduled even on a loaded machine.
    sim = canopy.Simulation(canopy.load("trajectory_handover"), seed=1)
    finished = threading.Event()

    def stepping():
        while not sim.done:
            sim.step()
        finished.set()

    seen_busy = 0
    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-4)
    try:
        thread = threading.Thread(target=stepping)
        thread.start()
        while not finished.is_set():
            try:
                sim.step_index
            except RuntimeError as e:
                assert "another thread is stepping it" in str(e)
                seen_busy += 1
        thread.join()
    finally:
        sys.setswitchinterval(old)
    assert seen_busy > 0 and sim.step_index == sim.last_step


def test_simulations_step_in_parallel_threads_give_the_same_runs():
    # Four simulations stepped on four Python threads at once end where a lone run ends.
    def run(out, seed):
        sim = canopy.Simulation(canopy.load("demo"), seed=seed)
        while not sim.done:
            sim.step()
        out[seed] = (sim.uav_states.copy(), sim.target_states.copy(), sim.record_line())

    alone, together = {}, {}
    for seed in range(4):
        run(alone, seed)
    threads = [threading.Thread(target=run, args=(together, seed)) for seed in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for seed in range(4):
        assert together[seed][2] == alone[seed][2]
        np.testing.assert_array_equal(together[seed][0], alone[seed][0])


def _altitude_scenario():
    # altitude_tradeoff: two UAVs at 20 m, z in [10, 60] m, climb rate 2 m/s, dt = 0.2 s (issue 53).
    return canopy.load("altitude_tradeoff", overrides={"clock.duration": 1.0})  # K = 5


def test_altitude_free_vector_env_observes_z_and_takes_vz():
    vec = canopy.VectorEnv(2, _altitude_scenario(), max_tracks=2, max_trees=1, threads=2)
    single = canopy.TrackingEnv(_altitude_scenario(), max_tracks=2, max_trees=1)
    assert vec.altitude and single.altitude
    size = 3 + 7 * 2 + 4 + 1  # the plane's observation, then z
    assert vec.single_observation_space.shape == (2, size)
    assert vec.action_space.shape == (2, 2, 3)
    np.testing.assert_array_equal(vec.single_action_space.high, [[5, 5, 2], [5, 5, 2]])
    np.testing.assert_array_equal(vec.single_observation_space.low[:, -1], [10, 10])
    np.testing.assert_array_equal(vec.single_observation_space.high[:, -1], [60, 60])
    obs, _ = vec.reset(seed=4)
    np.testing.assert_array_equal(obs[:, :, -1], [[20, 20], [20, 20]])
    # By hand, one 0.2 s step: +2 m/s → 20.4 m; −9 m/s clamped to −2 → 19.6 m; +1 m/s → 20.2 m;
    # 0 → 20 m.
    actions = np.zeros((2, 2, 3))
    actions[0, 0, 2], actions[0, 1, 2], actions[1, 0, 2] = 2.0, -9.0, 1.0
    obs, *_ = vec.step(actions)
    np.testing.assert_allclose(obs[:, :, -1], [[20.4, 19.6], [20.2, 20.0]], rtol=0, atol=1e-5)
    # Twice more at −9 m/s for UAV2 of env 0: 19.6 − 0.4 − 0.4 = 18.8 m.
    actions[0, 1, 2] = -9.0
    for _ in range(2):
        obs, *_ = vec.step(actions)
    assert obs[0, 1, -1] == pytest.approx(18.8, abs=1e-5)
    assert vec.observation_space.contains(obs)
    with pytest.raises(ValueError, match=r"shape \(2, 2, 3\) \(one velocity and climb rate"):
        vec.step(np.zeros((2, 2, 2)))
    # altitude=False keeps the plane: (vx, vy) and no z, the UAVs holding 20 m.
    plane = canopy.VectorEnv(2, _altitude_scenario(), max_tracks=2, max_trees=1, altitude=False)
    assert not plane.altitude and plane.action_space.shape == (2, 2, 2)
    assert plane.single_observation_space.shape == (2, size - 1)


def test_altitude_vector_env_equals_tracking_envs_bit_for_bit():
    n, seed = 3, 20
    vec = canopy.VectorEnv(n, _altitude_scenario(), max_tracks=4, max_trees=4, agent_axis=True,
                           autoreset_mode="SameStep")
    singles = [canopy.TrackingEnv(_altitude_scenario(), max_tracks=4, max_trees=4) for _ in range(n)]
    agents = vec.possible_agents
    obs, _ = vec.reset(seed=seed)
    expected = [env.reset(seed=seed + i)[0] for i, env in enumerate(singles)]
    rng = np.random.default_rng(1)
    for k in range(4):
        for i in range(n):
            for j, a in enumerate(agents):
                assert obs[i, j].tobytes() == expected[i][a].tobytes(), (k, i, a)
        actions = rng.uniform(-3, 3, (n, len(agents), 3))
        obs, rew, *_ = vec.step(actions)
        expected = []
        for i, env in enumerate(singles):
            o, r, *_ = env.step({a: actions[i, j] for j, a in enumerate(agents)})
            assert list(rew[i]) == [r[a] for a in agents]
            expected.append(o)
