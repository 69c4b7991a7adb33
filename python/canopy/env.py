"""TrackingEnv: canopy as a multi-agent environment with the PettingZoo ParallelEnv contract.

Pure Python over canopy.Simulation; neither pettingzoo nor gymnasium is imported (spaces are
gymnasium Boxes when gymnasium is importable). Agent i flies UAV i.

Observation of an agent (float32, length 3 + 7·max_tracks + 4·max_trees):
    [x, y, yaw]                                         its own pose (m, m, rad)
    max_tracks × [px, py, vx, vy, P_xx, P_yy, valid]    its fused target tracks, in the order
                                                        it holds them, zero-padded (valid 0)
    max_trees × [dx, dy, r, valid]                      the discs of its occlusion map nearest to
                                                        it within map_radius, relative to it
Action: a velocity (vx, vy) in m/s, within ±v_max per axis; the simulation clamps its norm.
Reward: minus the NBO stage cost of the agent's fused belief, −Σ_j tr(P_j) over its target
tracks, with the position block of P_j (reward_trace="position", the planner's default
cost_trace) or all of it ("full"); or reward_fn(sim, agent_index) when given.
Episodes end by truncation when the scenario's clock runs out (no termination); the agents
then leave ``agents``. Seeding follows Gymnasium: reset(seed=s) gives the same episode for the
same s (the simulation runs with seed s, as ``canopy run --seed s``); reset() without a seed
draws the next episode's seed from the generator the last seed started.
"""
import numpy as np

from . import _args, _canopy
from .scenario import Scenario, load
from .spaces import box

_TRACK = 7
_TREE = 4


class TrackingEnv:
    metadata = {"name": "canopy_tracking_v0", "render_modes": ["rgb_array"], "is_parallelizable": True}

    def __init__(self, scenario, max_tracks=8, max_trees=8, map_radius=30.0, render_mode=None,
                 render_size=(400, 300), reward_trace="position", reward_fn=None,
                 keep_planner=False):
        """scenario: a Scenario, a built-in name or a file. The planner is switched off
        (planner.algorithm = "none") unless keep_planner: the agents' actions fly the UAVs."""
        fn = "TrackingEnv"
        if not isinstance(scenario, Scenario):
            scenario = load(_args.path(scenario, fn, "scenario"))
        max_tracks = _args.integer(max_tracks, fn, "max_tracks", 0, 4096)
        max_trees = _args.integer(max_trees, fn, "max_trees", 0, 4096)
        map_radius = _args.number(map_radius, fn, "map_radius", 0.0, _args.MAX_COORDINATE,
                                  low_open=True, expected="a radius in (0, 1e7] m")
        render_size = _args.image_size(render_size, fn, "render_size")
        keep_planner = _args.boolean(keep_planner, fn, "keep_planner")
        if reward_fn is not None and not callable(reward_fn):
            raise _args.error(fn, "reward_fn", f"expected None or a callable, got {reward_fn!r:.60}")
        self.scenario = scenario.copy()
        if not keep_planner:
            self.scenario["planner.algorithm"] = "none"
        self.scenario.validate()
        if render_mode not in (None, "rgb_array"):
            raise _args.error(fn, "render_mode", f"expected None or 'rgb_array', got {render_mode!r:.60}")
        if reward_trace not in ("position", "full"):
            raise _args.error(fn, "reward_trace", f"expected 'position' or 'full', got {reward_trace!r:.60}")
        self.render_mode = render_mode
        self.render_size = tuple(render_size)
        self.max_tracks, self.max_trees, self.map_radius = int(max_tracks), int(max_trees), float(map_radius)
        self.reward_trace, self.reward_fn = reward_trace, reward_fn
        self.possible_agents = [u.get("name") or f"uav{i + 1}" for i, u in enumerate(self.scenario.uavs)]
        self._index = {a: i for i, a in enumerate(self.possible_agents)}
        self.agents = []
        self.sim = None
        self._rng = None
        v_max = [float(u["v_max"]) for u in self.scenario.uavs]
        size = 3 + _TRACK * self.max_tracks + _TREE * self.max_trees
        self._observation_spaces = {a: box(-np.inf, np.inf, (size,)) for a in self.possible_agents}
        self._action_spaces = {a: box(-v, v, (2,)) for a, v in zip(self.possible_agents, v_max)}

    # --- the ParallelEnv interface --------------------------------------------------------
    def observation_space(self, agent):
        return self._observation_spaces[agent]

    def action_space(self, agent):
        return self._action_spaces[agent]

    @property
    def num_agents(self):
        return len(self.agents)

    @property
    def max_num_agents(self):
        return len(self.possible_agents)

    def reset(self, seed=None, options=None):
        if seed is not None:
            # Gymnasium's seeds are non-negative integers; the simulation's --seed range.
            episode_seed = _args.seed(seed, "TrackingEnv.reset")
            self._rng = np.random.default_rng(episode_seed)
        else:
            if self._rng is None:
                self._rng = np.random.default_rng()
            episode_seed = int(self._rng.integers(0, 2**31 - 1))
        self.sim = _canopy.Simulation(self.scenario, seed=episode_seed)
        self.agents = list(self.possible_agents)
        observations = {a: self._observe(i) for a, i in self._index.items()}
        infos = {a: {"step": 0, "seed": episode_seed} for a in self.agents}
        return observations, infos

    def step(self, actions):
        if self.sim is None or not self.agents:
            raise RuntimeError("TrackingEnv.step: call reset() first (the episode has ended)")
        missing = [a for a in self.agents if a not in actions]
        unknown = [a for a in actions if a not in self._index]
        if missing or unknown:
            raise _args.error("TrackingEnv.step", "actions",
                              f"expected one per agent {self.agents}; "
                              f"missing {missing}, unknown {unknown}")
        commands = np.zeros((len(self.possible_agents), 2))
        for agent in self.agents:
            try:
                action = np.asarray(actions[agent], dtype=np.float64)
            except (TypeError, ValueError):
                raise _args.error("TrackingEnv.step", f"actions[{agent!r}]",
                                  f"expected (vx, vy) in m/s, got {actions[agent]!r:.60}") from None
            if action.shape != (2,) or not np.all(np.isfinite(action)):
                raise _args.error("TrackingEnv.step", f"actions[{agent!r}]",
                                  f"expected shape (2,) of finite numbers (vx, vy in m/s), got shape "
                                  f"{action.shape} {action!r:.60}")
            commands[self._index[agent]] = action
        self.sim.step(commands)
        acting = self.agents
        observations = {a: self._observe(self._index[a]) for a in acting}
        rewards = {a: self._reward(self._index[a]) for a in acting}
        truncated = self.sim.done
        terminations = {a: False for a in acting}
        truncations = {a: truncated for a in acting}
        infos = {a: {"step": self.sim.step_index} for a in acting}
        if truncated:
            self.agents = []
        return observations, rewards, terminations, truncations, infos

    def render(self):
        if self.render_mode != "rgb_array" or self.sim is None:
            return None
        return self.sim.render(*self.render_size)

    def close(self):
        self.sim = None
        self.agents = []

    def state(self):
        """The global state: every UAV's pose and every target's true state, flattened."""
        return np.concatenate([self.sim.uav_states.ravel(), self.sim.target_states.ravel()]).astype(np.float32)

    # --- observation and reward -----------------------------------------------------------
    def _observe(self, i):
        out = np.zeros(self._observation_spaces[self.possible_agents[i]].shape, np.float32)
        pose = self.sim.uav_states[i]
        out[:3] = pose
        tracks = self.sim.tracks(i)
        m = min(len(tracks["means"]), self.max_tracks)
        rows = out[3:3 + _TRACK * self.max_tracks].reshape(self.max_tracks, _TRACK)
        rows[:m, :4] = tracks["means"][:m]
        rows[:m, 4] = tracks["covariances"][:m, 0, 0]
        rows[:m, 5] = tracks["covariances"][:m, 1, 1]
        rows[:m, 6] = 1.0
        trees = self.sim.occlusion_map(i)["means"]
        if len(trees):
            offsets = trees[:, :2] - pose[:2]
            distance = np.hypot(offsets[:, 0], offsets[:, 1])
            near = np.argsort(distance, kind="stable")
            near = near[distance[near] <= self.map_radius][:self.max_trees]
            rows = out[3 + _TRACK * self.max_tracks:].reshape(self.max_trees, _TREE)
            rows[:len(near), :2] = offsets[near]
            rows[:len(near), 2] = trees[near, 2]
            rows[:len(near), 3] = 1.0
        return out

    def _reward(self, i):
        if self.reward_fn is not None:
            return float(self.reward_fn(self.sim, i))
        P = self.sim.tracks(i)["covariances"]
        block = P[:, :2, :2] if self.reward_trace == "position" else P
        return -float(np.trace(block, axis1=1, axis2=2).sum())
