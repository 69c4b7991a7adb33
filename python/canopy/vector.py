"""VectorEnv: n TrackingEnv episodes stepped together on C++ threads, batched numpy arrays out.

    envs = canopy.VectorEnv(16, "trajectory_handover")
    obs, infos = envs.reset(seed=0)                  # (16, n_agents, obs_size) float32
    obs, rew, term, trunc, infos = envs.step(actions)   # actions (16, n_agents, 2) m/s

Gymnasium's vector conventions (``num_envs``, ``single_observation_space`` /
``single_action_space`` per environment, ``observation_space`` / ``action_space`` batched), with
the agents as the second axis: rewards, terminations and truncations are (n, n_agents) arrays.
An environment whose episode ends is reset in the same call (same-step autoreset, as Gymnasium
≤ 0.29, SuperSuit and Gymnasium 1.x's ``AutoresetMode.SAME_STEP``): its row of the returned
observations is then the new episode's first one, and its last one is in the infos under both
generations' names: ``infos["final_observation"]`` (the batch, masked by
``infos["_final_observation"]``, Gymnasium ≤ 0.29) and ``infos["final_obs"]`` (an object array
holding that environment's observation where the mask ``infos["_final_obs"]`` is set, None
elsewhere) with ``infos["final_info"]`` / ``infos["_final_info"]`` (Gymnasium 1.x).
``metadata["autoreset_mode"]`` is ``gymnasium.vector.AutoresetMode.SAME_STEP`` where that exists,
else its value ``"SameStep"``.

Environment i behaves exactly as ``TrackingEnv`` with the same arguments reset with seed
``seed + i`` (or ``seed[i]``), and after an episode ends with ``reset()``: the same observations
and rewards, bit for bit (python/tests/test_vector.py). The stepping, observations and rewards
run in C++ without the GIL, on ``threads`` threads (default: one per core).
"""
import numpy as np

from . import _args, _canopy
from .env import TrackingEnv
from .spaces import box

try:  # Gymnasium 1.x names its autoreset modes; older versions and its absence get the value
    from gymnasium.vector import AutoresetMode as _AutoresetMode
    _SAME_STEP = _AutoresetMode.SAME_STEP
except ImportError:
    _SAME_STEP = "SameStep"

# The most environments one VectorEnv holds, checked before anything is built: 10⁷ ran into
# gigabytes before a MemoryError. Each is a whole simulation: measured after reset, demo 0.17 MB
# an environment (4096 of them: 0.7 GB), city_swarm 61 MB (its trees and maps; there memory ends
# the count long before this bound does).
MAX_ENVS = 4096


class VectorEnv:
    def __init__(self, n, scenario, max_tracks=8, max_trees=8, map_radius=30.0,
                 reward_trace="position", keep_planner=False, max_cycles=None, threads=None):
        """n environments of ``scenario`` (a Scenario, a built-in name or a file); the other
        arguments are TrackingEnv's. threads: worker threads, the caller's included (default:
        one per core, at most n)."""
        # The CLI's and TrackingEnv's rules (python/canopy/_args.py): a canopy.ScenarioError (a
        # ValueError) naming the argument, before anything is built.
        n = _args.integer(n, "VectorEnv", "n", 1, MAX_ENVS)
        if threads is not None:
            threads = _args.integer(threads, "VectorEnv", "threads", 1, _args.MAX_JOBS)
        # One TrackingEnv, never stepped: the same checks, scenario, spaces and agents.
        self.single_env = TrackingEnv(scenario, max_tracks=max_tracks, max_trees=max_trees,
                                      map_radius=map_radius, reward_trace=reward_trace,
                                      keep_planner=keep_planner, max_cycles=max_cycles)
        env = self.single_env
        self.num_envs = int(n)
        self.possible_agents = list(env.possible_agents)
        self.agents = list(env.possible_agents)
        self.max_cycles = env.max_cycles
        self.metadata = dict(env.metadata, autoreset_mode=_SAME_STEP)
        self._core = _canopy._VectorCore(env.scenario, self.num_envs, env._observer,
                                         env.max_cycles, 0 if threads is None else int(threads))
        self.threads = self._core.threads

        agents = self.possible_agents
        obs_low = np.stack([env.observation_space(a).low for a in agents])
        obs_high = np.stack([env.observation_space(a).high for a in agents])
        act_low = np.stack([env.action_space(a).low for a in agents])
        act_high = np.stack([env.action_space(a).high for a in agents])
        self.single_observation_space = box(obs_low, obs_high, obs_low.shape)
        self.single_action_space = box(act_low, act_high, act_low.shape)
        batch = (self.num_envs,)
        self.observation_space = box(np.broadcast_to(obs_low, batch + obs_low.shape),
                                     np.broadcast_to(obs_high, batch + obs_high.shape),
                                     batch + obs_low.shape)
        self.action_space = box(np.broadcast_to(act_low, batch + act_low.shape),
                                np.broadcast_to(act_high, batch + act_high.shape),
                                batch + act_low.shape)
        self._rngs = [None] * self.num_envs
        self._seeds = np.zeros(self.num_envs, np.uint64)  # up to 2⁶⁴ − 1, as TrackingEnv's
        self._started = False

    def _next_seed(self, i):
        """As TrackingEnv.reset() without a seed: drawn from the generator the last seed started."""
        if self._rngs[i] is None:
            self._rngs[i] = np.random.default_rng()
        return int(self._rngs[i].integers(0, 2**31 - 1))

    def _checked_seeds(self, seed):
        """seed as TrackingEnv.reset checks it (an integer in [0, 2⁶⁴ − 1]; 1.7, -5, NaN, text and
        2⁷⁰ are refused naming seed): an int s gives s, s + 1, …, s + n − 1, all in range; a 1-D
        sequence gives one seed per environment."""
        fn = "VectorEnv.reset"
        if isinstance(seed, (str, bytes)) or np.ndim(seed) == 0:
            first = _args.seed(seed, fn)
            if first > _args.MAX_SEED - (self.num_envs - 1):
                raise _args.error(fn, "seed", f"expected at most {_args.MAX_SEED - (self.num_envs - 1)} "
                                  f"(seed + i for the {self.num_envs} environments stays below 2**64), got {first}")
            return [first + i for i in range(self.num_envs)]
        if np.ndim(seed) != 1 or len(seed) != self.num_envs:
            raise _args.error(fn, "seed", f"expected an integer or a sequence of {self.num_envs} integers, "
                              f"got an array of shape {np.shape(seed)}")
        return [_args.seed(s, fn, f"seed[{i}]") for i, s in enumerate(seed)]

    def reset(self, seed=None, options=None):
        """Starts every environment's episode. seed: None, an int s (environment i gets s + i)
        or a sequence of n ints; options: None or a dict, ignored. Returns (observations (n, n_agents, size), infos) with
        infos["seed"] the episodes' seeds (n,)."""
        if options is not None and not isinstance(options, dict):
            raise ValueError(f"VectorEnv.reset: options: expected None or a dict (its keys are ignored), got {type(options).__name__}")
        if seed is None:
            seeds = [self._next_seed(i) for i in range(self.num_envs)]
        else:
            seeds = self._checked_seeds(seed)
            self._rngs = [np.random.default_rng(s) for s in seeds]
        self._core.reset(list(range(self.num_envs)), seeds)
        self._seeds[:] = seeds
        self._started = True
        return self._core.observations.copy(), {"seed": self._seeds.copy()}

    def step(self, actions):
        """actions: (n, n_agents, 2) velocities (m/s). Returns observations (n, n_agents, size)
        float32, rewards (n, n_agents) float64, terminations and truncations (n, n_agents) bool
        and infos: "step" (n,) the step each environment reached, and for environments whose
        episode ended (and was reset) "_final_observation" (n,) bool, "final_observation",
        "final_obs" / "_final_obs" and "final_info" / "_final_info" (Gymnasium 1.x's names) and
        "seed" (the new episodes' seeds)."""
        if not self._started:
            raise RuntimeError("VectorEnv.step: call reset() first")
        core = self._core
        observations, rewards, ended, steps = core.step_results(actions)  # one call, fresh arrays
        shape = rewards.shape
        terminations = np.zeros(shape, bool)
        truncations = np.empty(shape, bool)
        truncations[:] = ended[:, None]
        infos = {"step": steps}
        if ended.any():
            infos["final_observation"] = observations
            infos["_final_observation"] = ended
            final_obs = np.full(self.num_envs, None, dtype=object)
            for i in np.flatnonzero(ended):
                final_obs[i] = observations[i]
            infos["final_obs"], infos["_final_obs"] = final_obs, ended
            infos["final_info"] = {"step": steps, "_step": ended}
            infos["_final_info"] = ended
            which = np.flatnonzero(ended)
            new_seeds = [self._next_seed(int(i)) for i in which]
            core.reset([int(i) for i in which], new_seeds)
            self._seeds[which] = new_seeds
            infos["seed"] = self._seeds.copy()
            observations = core.observations.copy()
        return observations, rewards, terminations, truncations, infos

    def close(self):
        self.single_env.close()
        self._started = False

    def __len__(self):
        return self.num_envs
