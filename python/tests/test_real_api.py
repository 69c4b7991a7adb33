"""PettingZoo's, Gymnasium's and SuperSuit's own checks run against TrackingEnv and VectorEnv
(issue 30). Skipped where pettingzoo and gymnasium are not importable (they are not Debian
packages); README's Python section says how to run them from a venv that has them.

Every check runs with Python warnings turned into errors: PettingZoo's and Gymnasium's checkers
report most findings as warnings, so a test that only waited for an exception would pass
environments they object to. The one warning allowed is named where it is expected.
"""
import types
import warnings

import numpy as np
import pytest

pettingzoo = pytest.importorskip("pettingzoo")
gymnasium = pytest.importorskip("gymnasium")

import canopy  # noqa: E402
from gymnasium.utils import passive_env_checker as passive  # noqa: E402
from gymnasium.utils.env_checker import check_space_limit, data_equivalence  # noqa: E402
from pettingzoo.test import (api_test, max_cycles_test, parallel_api_test,  # noqa: E402
                             parallel_seed_test, render_test, seed_test)
from pettingzoo.test.state_test import state_test  # noqa: E402
from pettingzoo.utils.conversions import parallel_to_aec  # noqa: E402

# (built-in scenario, overrides, max_cycles): short clocks so that episodes end within the
# checks' cycles; the fourth episode is cut by max_cycles before the scenario's clock runs out.
CASES = [
    ("trajectory_handover", {"clock.duration": 2.0}, None),  # 2 UAVs, K = 10
    ("demo", {"clock.duration": 6.0}, None),  # 3 UAVs
    ("mixed_team", {"clock.duration": 3.0}, None),
    ("occlusion_sharing", {"clock.duration": 4.0}, 7),
]
IDS = [name for name, _, _ in CASES]


def _maker(name, overrides, max_cycles):
    scenario = canopy.load(name, overrides=overrides)

    def make(**kwargs):
        kwargs.setdefault("max_cycles", max_cycles)
        return canopy.TrackingEnv(scenario, **kwargs)

    return make


@pytest.fixture(params=CASES, ids=IDS)
def make(request):
    return _maker(*request.param)


@pytest.fixture(autouse=True)
def warnings_are_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


def test_it_is_the_real_parallel_env_with_gymnasium_spaces(make):
    env = make()
    assert canopy.env.PETTINGZOO and canopy.spaces.GYMNASIUM
    assert isinstance(env, pettingzoo.ParallelEnv)
    for a in env.possible_agents:
        assert type(env.observation_space(a)) is gymnasium.spaces.Box
        assert type(env.action_space(a)) is gymnasium.spaces.Box
    assert type(env.state_space) is gymnasium.spaces.Box


def test_pettingzoo_parallel_api_test(make):
    env = make()
    # parallel_api_test sets env.max_cycles = num_cycles: the episode is min(that, K) steps.
    parallel_api_test(env, num_cycles=40)
    env.max_cycles = 3
    env.reset(seed=2)
    steps = 0
    while env.agents:
        env.step({a: env.action_space(a).sample() for a in env.agents})
        steps += 1
    assert steps == 3


def test_pettingzoo_parallel_seed_test(make):
    parallel_seed_test(make, num_cycles=40)


def test_pettingzoo_aec_api_and_seed_tests_through_parallel_to_aec(make):
    # The one warning: PettingZoo recommends agent names like "uav_0"; canopy's agents carry
    # the scenario's UAV names ("UAV1", or a name the file gives).
    with pytest.warns(UserWarning, match="agents to be named"):
        api_test(parallel_to_aec(make()), num_cycles=40)
    seed_test(lambda: parallel_to_aec(make()), num_cycles=40)


def test_pettingzoo_state_test(make):
    state_test(parallel_to_aec(make()), make(), num_cycles=10)


def test_pettingzoo_max_cycles_test(make):
    module = types.SimpleNamespace(parallel_env=lambda max_cycles: make(max_cycles=max_cycles),
                                   env=lambda max_cycles: parallel_to_aec(make(max_cycles=max_cycles)))
    max_cycles_test(module)


def test_pettingzoo_render_test(make):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")  # "human" draws into an off-screen figure here
    render_test(lambda render_mode=None: parallel_to_aec(make(render_mode=render_mode,
                                                               render_size=(80, 60))))


def test_gymnasium_space_checks_and_observations(make):
    env = make()
    for a in env.possible_agents:
        passive.check_observation_space(env.observation_space(a))
        passive.check_action_space(env.action_space(a))
        check_space_limit(env.observation_space(a), "observation")
        # The action space is the UAV's velocity in m/s, not [−1, 1]: Gymnasium's checker
        # recommends normalised actions, the one warning it gives.
        with pytest.warns(UserWarning, match="symmetric and normalized"):
            check_space_limit(env.action_space(a), "action")
    passive.check_observation_space(env.state_space)
    check_space_limit(env.state_space, "observation")
    first, _ = env.reset(seed=5)
    episode = [first]
    while env.agents:
        for a, o in episode[-1].items():
            passive.check_obs(o, env.observation_space(a), "step" if len(episode) > 1 else "reset")
            assert o.dtype == np.float32 and o in env.observation_space(a)
        obs, *_ = env.step({a: env.action_space(a).sample() for a in env.agents})
        episode.append(obs)
    again, _ = env.reset(seed=5)
    assert data_equivalence(first, again, exact=True)


def test_rllib_style_dict_spaces_and_clipped_float32_actions(make):
    # RLlib's ParallelPettingZooEnv wraps the per-agent spaces in a Dict and, with its default
    # normalize_actions, sends float32 actions unsquashed and clipped into [low, high].
    env = make()
    obs_space = gymnasium.spaces.Dict({a: env.observation_space(a) for a in env.possible_agents})
    act_space = gymnasium.spaces.Dict({a: env.action_space(a) for a in env.possible_agents})
    obs, _ = env.reset(seed=3)
    rng = np.random.default_rng(3)
    assert obs_space.contains(obs)
    while env.agents:
        squashed = {a: rng.uniform(-1.5, 1.5, 2).astype(np.float32) for a in env.agents}
        actions = {}
        for a, x in squashed.items():
            low, high = env.action_space(a).low, env.action_space(a).high
            actions[a] = np.clip(low + (x + 1) * (high - low) / 2, low, high)  # RLlib's unsquash
            assert actions[a].dtype == np.float32 and act_space[a].contains(actions[a])
        obs, rewards, terms, truncs, infos = env.step(actions)
        if env.agents:
            assert obs_space.contains(obs)
        assert all(isinstance(r, float) for r in rewards.values())
        assert all(type(t) is bool for t in (*terms.values(), *truncs.values()))


def test_supersuit_markov_vector_env_and_concat(make):
    ss = pytest.importorskip("supersuit")
    env = make()
    first = env.action_space(env.possible_agents[0])
    if any(env.action_space(a) != first for a in env.possible_agents):  # SuperSuit's vector wrapper wants one action space for all agents
        pytest.skip("agents with different v_max")
    vec = ss.concat_vec_envs_v1(ss.pettingzoo_env_to_vec_env_v1(env), 2, num_cpus=0,
                                base_class="gymnasium")
    n = 2 * len(env.possible_agents)
    obs, infos = vec.reset(seed=7)
    assert obs.shape == (n,) + env.observation_space(env.possible_agents[0]).shape
    assert obs.dtype == np.float32 and vec.observation_space.contains(obs[0])
    vec.action_space.seed(7)
    ended = 0
    for _ in range(2 * env.max_cycles + 1):
        obs, rewards, terms, truncs, infos = vec.step(np.stack([vec.action_space.sample()
                                                                for _ in range(n)]))
        assert obs.dtype == np.float32 and all(vec.observation_space.contains(o) for o in obs)
        assert rewards.shape == (n,) and not terms.any()
        ended += int(truncs.all())
    assert ended == 2  # every episode truncated together, then reset by the wrapper
    vec.close()


def test_vector_env_spaces_are_gymnasium_batches():
    from gymnasium.vector.utils import batch_space
    vec = canopy.VectorEnv(3, canopy.load("demo", overrides={"clock.duration": 2.0}))
    assert type(vec.single_observation_space) is gymnasium.spaces.Box
    assert vec.observation_space == batch_space(vec.single_observation_space, 3)
    assert vec.action_space == batch_space(vec.single_action_space, 3)
    obs, _ = vec.reset(seed=1)
    assert obs in vec.observation_space
    for _ in range(12):  # through an autoreset
        obs, *_ = vec.step(vec.action_space.sample())
        assert obs in vec.observation_space
