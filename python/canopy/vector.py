"""VectorEnv: n TrackingEnv episodes stepped together on C++ threads, batched numpy arrays out; a
``gymnasium.vector.VectorEnv`` when Gymnasium is importable (a stand-in with its attributes
otherwise, python/canopy/_vector_base.py), so that Gymnasium's vector wrappers take it.

    envs = canopy.VectorEnv(16, "trajectory_handover")
    obs, infos = envs.reset(seed=0)                  # (16, n_agents, obs_size) float32
    obs, rew, term, trunc, infos = envs.step(actions)   # actions (16, n_agents, 2) m/s

Gymnasium's vector conventions: ``num_envs``, ``single_observation_space`` /
``single_action_space`` per environment (the agents as its first axis: one policy flies the
team), ``observation_space`` / ``action_space`` batched, rewards, terminations and truncations
(n,): the team's reward, the sum of its agents' (``agent_axis=True``: (n, n_agents), each agent's
own), and Gymnasium's default autoreset, ``AutoresetMode.NEXT_STEP``: the step after an episode
ends resets that environment (its action is ignored, its reward 0) and returns the new episode's
first observation. Height (issue 53) as TrackingEnv's: when some UAV's altitude is free
(``altitude=None``, the default, detects it; ``altitude=False`` keeps the plane, its UAVs holding
their altitudes) each agent's observation ends with its z (m) and actions are (n, n_agents, 3),
(vx, vy, vz) with vz the climb rate (m/s, kept within ±climb_rate and z within [z_min, z_max]).
``autoreset_mode=AutoresetMode.SAME_STEP`` (or "SameStep") resets it in the
same call instead: its row of the returned observations is then the new episode's first one, and
its last one is in the infos under both generations' names: ``infos["final_observation"]`` (the
batch, masked by ``infos["_final_observation"]``, Gymnasium ≤ 0.29) and ``infos["final_obs"]``
(an object array holding that environment's observation where the mask ``infos["_final_obs"]``
is set, None elsewhere) with ``infos["final_info"]`` / ``infos["_final_info"]`` (Gymnasium 1.x).
``metadata["autoreset_mode"]`` is the mode, a ``gymnasium.vector.AutoresetMode`` member where
that exists, else its value. ``render_mode="rgb_array"``: ``render()`` returns the n
environments' last steps as (height, width, 3) uint8 frames.

Environment i behaves exactly as ``TrackingEnv`` with the same arguments reset with seed
``seed + i`` (or ``seed[i]``), and after an episode ends with ``reset()``: the same observations
and rewards, bit for bit (python/tests/test_vector.py). The stepping, observations and rewards
run in C++ without the GIL, on ``threads`` threads (default: one per core).
"""
import numpy as np

from . import _args, _canopy
from ._vector_base import (GYMNASIUM_VECTOR, NEXT_STEP, SAME_STEP, _VectorEnvBase,  # noqa: F401
                           _random_generator, autoreset_value)
from .env import TrackingEnv
from .spaces import box

# The most environments one VectorEnv holds, checked before anything is built: 10⁷ ran into
# gigabytes before a MemoryError. Each is a whole simulation: measured after reset, demo 0.17 MB
# an environment (4096 of them: 0.7 GB), city_swarm 61 MB (its trees and maps; there memory ends
# the count long before this bound does).
MAX_ENVS = 4096


class VectorEnv(_VectorEnvBase):
    metadata = {"name": "canopy_tracking_v0", "render_modes": ["rgb_array"],
                "autoreset_mode": NEXT_STEP}

    def __init__(self, n, scenario, max_tracks=8, max_trees=8, map_radius=30.0,
                 reward_trace="position", keep_planner=False, max_cycles=None, threads=None,
                 render_mode=None, render_size=(400, 300), autoreset_mode=None, agent_axis=False,
                 altitude=None):
        """n environments of ``scenario`` (a Scenario, a built-in name or a file); the other
        arguments (altitude among them) are TrackingEnv's. threads: worker threads, the caller's
        included (default: one per core, at most n). render_mode: None or "rgb_array". autoreset_mode:
        AutoresetMode.NEXT_STEP (default) or SAME_STEP, or their values. agent_axis: rewards,
        terminations and truncations per agent, (n, n_agents), instead of the team's (n,)."""
        # The CLI's and TrackingEnv's rules (python/canopy/_args.py): a canopy.ScenarioError (a
        # ValueError) naming the argument, before anything is built.
        fn = "VectorEnv"
        n = _args.integer(n, fn, "n", 1, MAX_ENVS)
        if threads is not None:
            threads = _args.integer(threads, fn, "threads", 1, _args.MAX_JOBS)
        if render_mode not in (None, "rgb_array"):
            raise _args.error(fn, "render_mode", "expected None or 'rgb_array' (render() returns the "
                              "n environments' frames; TrackingEnv(render_mode='human') shows one in "
                              f"a window), got {render_mode!r:.60}")
        self.render_mode = render_mode
        self.render_size = tuple(_args.image_size(render_size, fn, "render_size"))
        modes = {autoreset_value(NEXT_STEP): NEXT_STEP, autoreset_value(SAME_STEP): SAME_STEP}
        if autoreset_mode is None:
            autoreset_mode = NEXT_STEP
        if not isinstance(autoreset_value(autoreset_mode), str) or autoreset_value(autoreset_mode) not in modes:
            raise _args.error(fn, "autoreset_mode", "expected AutoresetMode.NEXT_STEP or SAME_STEP, or "
                              f"'NextStep' or 'SameStep', got {autoreset_mode!r:.60}")
        self.autoreset_mode = modes[autoreset_value(autoreset_mode)]
        self.agent_axis = _args.boolean(agent_axis, fn, "agent_axis")
        # One TrackingEnv, never stepped: the same checks, scenario, spaces and agents.
        self.single_env = TrackingEnv(scenario, max_tracks=max_tracks, max_trees=max_trees,
                                      map_radius=map_radius, reward_trace=reward_trace,
                                      keep_planner=keep_planner, max_cycles=max_cycles,
                                      altitude=altitude)
        env = self.single_env
        self.altitude = env.altitude
        self.num_envs = int(n)
        self.possible_agents = list(env.possible_agents)
        self.agents = list(env.possible_agents)
        self.max_cycles = env.max_cycles
        self.metadata = dict(env.metadata, render_modes=["rgb_array"],
                             autoreset_mode=self.autoreset_mode)
        self._core = _canopy._VectorCore(env.scenario, self.num_envs, env._observer,
                                         env.max_cycles, 0 if threads is None else int(threads),
                                         self.altitude)
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
        self._autoreset = np.zeros(self.num_envs, bool)  # next step resets these (NEXT_STEP)

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
        """Starts the environments' episodes: every one, or with options["reset_mask"] (a bool
        array (n,)) those it marks. seed: None, an int s (environment i gets s + i) or a sequence
        of n ints; other keys of options are ignored. Returns (observations (n, n_agents, size),
        infos) with infos["seed"] the episodes' seeds (n,), infos["_seed"] the environments
        reset."""
        fn = "VectorEnv.reset"
        if options is not None and not isinstance(options, dict):
            raise ValueError(f"{fn}: options: expected None or a dict (its keys are ignored), got {type(options).__name__}")
        mask = np.ones(self.num_envs, bool)
        if options is not None and options.get("reset_mask") is not None:
            mask = np.asarray(options["reset_mask"])
            if mask.shape != (self.num_envs,) or mask.dtype != np.bool_ or not mask.any():
                raise _args.error(fn, "options['reset_mask']", f"expected a bool array of shape ({self.num_envs},) "
                                  f"with at least one True, got {options['reset_mask']!r:.60}")
            if not self._started and not mask.all():
                raise _args.error(fn, "options['reset_mask']", "expected every environment in the first reset")
        which = np.flatnonzero(mask)
        if seed is None:
            seeds = [self._next_seed(int(i)) for i in which]
        else:
            every = self._checked_seeds(seed)
            seeds = [every[i] for i in which]
            for i, s in zip(which, seeds):
                self._rngs[i] = np.random.default_rng(s)
            if np.ndim(seed) == 0:
                self._np_random, self._np_random_seed = _random_generator(every[0])
            else:
                self._np_random, self._np_random_seed = _random_generator(every)
        self._core.reset([int(i) for i in which], seeds)
        self._seeds[which] = seeds
        self._autoreset[which] = False
        self._started = True
        return self._core.observations.copy(), {"seed": self._seeds.copy(), "_seed": mask.copy()}

    def step(self, actions):
        """actions: (n, n_agents, 2) velocities (m/s), or (n, n_agents, 3) (vx, vy, vz) when
        altitude is on. Returns observations (n, n_agents, size)
        float32, rewards float64, terminations and truncations bool, (n,) or with agent_axis
        (n, n_agents), and infos: "step" (n,) the step each environment reached; "seed" and
        "_seed" when environments were reset. NEXT_STEP: an environment whose episode ended at
        the step before is reset instead of stepped. SAME_STEP: one whose episode ends is reset
        in the same call, and the infos hold "_final_observation" (n,) bool,
        "final_observation", "final_obs" / "_final_obs" and "final_info" / "_final_info"."""
        if not self._started:
            raise RuntimeError("VectorEnv.step: call reset() first")
        core = self._core
        infos = {}
        pending = [int(i) for i in np.flatnonzero(self._autoreset)]
        if pending:  # NEXT_STEP: the episodes that ended at the last step start now
            self._reset_envs(pending, infos)
        # one call, fresh arrays
        observations, rewards, ended, steps = core.step_results(actions, pending)
        infos["step"] = steps
        if self.autoreset_mode == NEXT_STEP:
            self._autoreset[:] = ended
        elif ended.any():
            infos["final_observation"] = observations
            infos["_final_observation"] = ended
            final_obs = np.full(self.num_envs, None, dtype=object)
            for i in np.flatnonzero(ended):
                final_obs[i] = observations[i]
            infos["final_obs"], infos["_final_obs"] = final_obs, ended
            infos["final_info"] = {"step": steps, "_step": ended}
            infos["_final_info"] = ended
            self._reset_envs([int(i) for i in np.flatnonzero(ended)], infos)
            observations = core.observations.copy()
        if self.agent_axis:
            terminations = np.zeros(rewards.shape, bool)
            truncations = np.empty(rewards.shape, bool)
            truncations[:] = ended[:, None]
        else:  # the team's reward; every agent is truncated together
            rewards = rewards.sum(axis=1)
            terminations = np.zeros(self.num_envs, bool)
            truncations = ended.copy()
        return observations, rewards, terminations, truncations, infos

    def _reset_envs(self, which, infos):
        """Starts new episodes in the environments `which`, seeded as TrackingEnv.reset() without
        a seed; their seeds go into infos["seed"] (mask "_seed")."""
        new_seeds = [self._next_seed(i) for i in which]
        self._core.reset(which, new_seeds)
        self._seeds[which] = new_seeds
        self._autoreset[which] = False
        mask = np.zeros(self.num_envs, bool)
        mask[which] = True
        infos["seed"], infos["_seed"] = self._seeds.copy(), mask

    def render(self):
        """rgb_array: a tuple of the n environments' last steps, each (height, width, 3) uint8 of
        render_size, drawn as TrackingEnv draws them. None without a render_mode or before
        reset()."""
        if self.render_mode is None or not self._started:
            return None
        return tuple(self._core.render(i, *self.render_size) for i in range(self.num_envs))

    def close_extras(self, **kwargs):
        if hasattr(self, "single_env"):  # not when __init__ refused its arguments
            self.single_env.close()
        self._started = False

    def __len__(self):
        return self.num_envs
