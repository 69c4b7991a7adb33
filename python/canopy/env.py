"""TrackingEnv: canopy as a multi-agent environment, a PettingZoo ``ParallelEnv``.

When pettingzoo is importable, TrackingEnv subclasses ``pettingzoo.ParallelEnv`` and its spaces
are ``gymnasium.spaces.Box``; without them it has stand-ins with the same attributes
(``canopy.env.PETTINGZOO`` and ``canopy.spaces.GYMNASIUM`` tell which). Agent i flies UAV i.

Observation of an agent (float32, length 3 + 7·max_tracks + 4·max_trees), computed in C++:
    [x, y, yaw]                                         its own pose (m, m, rad)
    max_tracks × [px, py, vx, vy, P_xx, P_yy, valid]    its fused target tracks, in the order
                                                        it holds them, zero-padded (valid 0)
    max_trees × [dx, dy, r, valid]                      the discs of its occlusion map nearest to
                                                        it within map_radius, relative to it
Every entry is clipped into the observation space's finite bounds: positions within the AOI and
the UAV starts grown by the distance the fastest UAV flies in the episode, yaw in [−π, π], track
velocities within max(50, 5·v_max) m/s, variances in [0, 10⁴] m², tree offsets and radii within
map_radius.
Action: a velocity (vx, vy) in m/s, within ±v_max per axis; the simulation clamps its norm.
Height (issue 53): when some UAV's altitude is free (its scenario gives z_min < z_max and a
climb_rate > 0; ``altitude=None``, the default, detects it, ``altitude=False`` keeps the plane),
every observation ends with the agent's altitude z (m, within [z_min, z_max]) and every action is
(vx, vy, vz), vz the climb rate in m/s within ±climb_rate (0 for a UAV whose altitude is fixed);
the world keeps z within [z_min, z_max].
Reward: minus the NBO stage cost of the agent's fused belief, −Σ_j tr(P_j) over its target
tracks, with the position block of P_j (reward_trace="position", the planner's default
cost_trace) or all of it ("full"); or reward_fn(sim, agent_index) when given.
Episodes end by truncation after max_cycles steps or when the scenario's clock runs out,
whichever is first (there is no termination: no agent is lost); the agents then leave
``agents``. Seeding follows Gymnasium: reset(seed=s) gives the same episode for the same s (the
simulation runs with seed s, as ``canopy run --seed s``); reset() without a seed draws the next
episode's seed from the generator the last seed started.
"""
import numpy as np

from . import _args, _canopy
from .scenario import Scenario, load
from .spaces import box

try:
    from pettingzoo import ParallelEnv as _ParallelEnv

    PETTINGZOO = True
except ImportError:  # not installed: a stand-in with ParallelEnv's own attributes
    PETTINGZOO = False

    class _ParallelEnv:
        """The attributes pettingzoo.ParallelEnv gives its subclasses."""

        metadata = {}

        @property
        def num_agents(self):
            return len(self.agents)

        @property
        def max_num_agents(self):
            return len(self.possible_agents)

        @property
        def unwrapped(self):
            return self

        def __str__(self):
            return self.metadata.get("name", type(self).__name__)


class TrackingEnv(_ParallelEnv):
    metadata = {"name": "canopy_tracking_v0", "render_modes": ["human", "rgb_array"],
                "is_parallelizable": True, "render_fps": 5}

    def __init__(self, scenario, max_tracks=8, max_trees=8, map_radius=30.0, render_mode=None,
                 render_size=(400, 300), reward_trace="position", reward_fn=None,
                 keep_planner=False, max_cycles=None, altitude=None):
        """scenario: a Scenario, a built-in name or a file. The planner is switched off
        (planner.algorithm = "none") unless keep_planner: the agents' actions fly the UAVs.
        max_cycles: the episode's length in steps (default and at most the scenario's K).
        altitude: None (on when some UAV's altitude is free), True or False: observations end
        with z and actions carry vz (module docstring)."""
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
        if render_mode not in (None, "human", "rgb_array"):
            raise _args.error(fn, "render_mode", f"expected None, 'human' or 'rgb_array', got {render_mode!r:.60}")
        if reward_trace not in ("position", "full"):
            raise _args.error(fn, "reward_trace", f"expected 'position' or 'full', got {reward_trace!r:.60}")
        self.render_mode = render_mode
        self.render_size = tuple(render_size)
        self.max_tracks, self.max_trees = max_tracks, max_trees
        self.map_radius = float(map_radius)
        self.reward_trace, self.reward_fn = reward_trace, reward_fn
        self._observer = _canopy._Observer(self.scenario, self.max_tracks, self.max_trees,
                                           self.map_radius, reward_trace)
        self.steps, self.dt, n_targets = self._observer.steps, self._observer.dt, self._observer.n_targets
        self.max_cycles = self.steps if max_cycles is None else min(
            _args.integer(max_cycles, fn, "max_cycles", 1, 2**31 - 1), self.steps)
        # An instance's own metadata: the frame rate is the scenario's (one frame per step).
        self.metadata = dict(type(self).metadata, render_fps=max(1, round(1.0 / self.dt)))

        self.possible_agents = [u.get("name") or f"uav{i + 1}" for i, u in enumerate(self.scenario.uavs)]
        self._index = {a: i for i, a in enumerate(self.possible_agents)}
        self.agents = []
        self.sim = None
        self._rng = None
        self._window = None
        v_max = [float(u["v_max"]) for u in self.scenario.uavs]
        # Height: each UAV's altitude limits and the climb rate it may use (0: fixed).
        limits = [_altitude_limits(u) for u in self.scenario.uavs]
        if altitude is None:
            altitude = any(climb > 0.0 for _, _, climb in limits)
        self.altitude = _args.boolean(altitude, fn, "altitude")
        low, high = self._observer.low, self._observer.high
        self.observation_spaces, self.action_spaces = {}, {}
        for a, v, (z_min, z_max, climb) in zip(self.possible_agents, v_max, limits):
            if self.altitude:
                o_low, o_high = np.append(low, np.float32(z_min)), np.append(high, np.float32(z_max))
                self.observation_spaces[a] = box(o_low, o_high, o_low.shape)
                a_high = np.array([v, v, climb], np.float32)
                self.action_spaces[a] = box(-a_high, a_high, (3,))
            else:
                self.observation_spaces[a] = box(low, high, low.shape)
                self.action_spaces[a] = box(-v, v, (2,))
        p, s, pi = self._observer.position_bound, self._observer.speed_bound, np.float32(np.pi)
        state_high = np.array([p, p, pi] * len(self.possible_agents) + [p, p, s, s] * n_targets,
                              np.float32)
        self.state_space = box(-state_high, state_high, state_high.shape)

    # --- the ParallelEnv interface --------------------------------------------------------
    def observation_space(self, agent):
        return self.observation_spaces[agent]

    def action_space(self, agent):
        return self.action_spaces[agent]

    @property
    def num_agents(self):
        return len(self.agents)

    @property
    def max_num_agents(self):
        return len(self.possible_agents)

    def reset(self, seed=None, options=None):
        """Starts an episode: seed s repeats it exactly. options: None or a dict, whose keys are
        ignored (none is read; PettingZoo's parallel_api_test passes {"options": 1} and expects
        it accepted)."""
        if options is not None and not isinstance(options, dict):
            raise ValueError(f"TrackingEnv.reset: options: expected None or a dict, got {type(options).__name__}")
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
        obs, _ = self._observe()
        observations = {a: obs[i] for a, i in self._index.items()}
        infos = {a: {"step": 0, "seed": episode_seed} for a in self.agents}
        if self.render_mode == "human":
            self.render()
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
        width = 3 if self.altitude else 2
        expected = "(vx, vy, vz)" if self.altitude else "(vx, vy)"
        commands = np.zeros((len(self.possible_agents), width))
        for agent in self.agents:
            try:
                action = np.asarray(actions[agent], dtype=np.float64)
            except (TypeError, ValueError):
                raise _args.error("TrackingEnv.step", f"actions[{agent!r}]",
                                  f"expected {expected} in m/s, got {actions[agent]!r:.60}") from None
            if action.shape != (width,) or not np.all(np.isfinite(action)):
                raise _args.error("TrackingEnv.step", f"actions[{agent!r}]",
                                  f"expected shape ({width},) of finite numbers ({expected[1:-1]} in "
                                  f"m/s), got shape {action.shape} {action!r:.60}")
            commands[self._index[agent]] = action
        self.sim.step(commands)  # without the GIL: other threads run meanwhile
        acting = self.agents
        obs, rew = self._observe()
        observations = {a: obs[self._index[a]] for a in acting}
        if self.reward_fn is not None:
            rewards = {a: float(self.reward_fn(self.sim, self._index[a])) for a in acting}
        else:
            rewards = {a: float(rew[self._index[a]]) for a in acting}
        truncated = self.sim.done or self.sim.step_index >= self.max_cycles
        terminations = {a: False for a in acting}
        truncations = {a: truncated for a in acting}
        infos = {a: {"step": self.sim.step_index} for a in acting}
        if truncated:
            self.agents = []
        if self.render_mode == "human":
            self.render()
        return observations, rewards, terminations, truncations, infos

    def render(self):
        """rgb_array: the last step drawn, (height, width, 3) uint8. human: shows it in a
        matplotlib window (returns None). None before reset() or without a render_mode."""
        if self.render_mode is None or self.sim is None:
            return None
        frame = self.sim.render(*self.render_size)
        if self.render_mode == "rgb_array":
            return frame
        self._show(frame)
        return None

    def close(self):
        if self._window is not None:
            plt, figure, _ = self._window
            plt.close(figure)
            self._window = None
        self.sim = None
        self.agents = []

    def state(self):
        """The global state: every UAV's pose (x, y, yaw) and every target's true state
        (x, y, vx, vy), flattened, float32, clipped into state_space."""
        if self.sim is None:
            raise RuntimeError("TrackingEnv.state: call reset() first")
        s = np.concatenate([self.sim.uav_states.ravel(), self.sim.target_states.ravel()])
        return np.clip(s.astype(np.float32), self.state_space.low, self.state_space.high)

    # --- pickling (SuperSuit's concat_vec_envs and RLlib's workers copy environments) --------
    def __getstate__(self):
        """An environment pickles as it was built, before reset(): the running simulation, the
        seed generator and a 'human' window are not carried over."""
        state = dict(self.__dict__)
        for key in ("_observer", "sim", "_window", "_rng"):
            state.pop(key, None)
        state["agents"] = []
        return state

    def __setstate__(self, state):
        self.__dict__.update(state)
        self._observer = _canopy._Observer(self.scenario, self.max_tracks, self.max_trees,
                                           self.map_radius, self.reward_trace)
        self.sim, self._rng, self._window = None, None, None

    # --- internals --------------------------------------------------------------------------
    def _observe(self):
        """Every agent's observation (a new (n, size) float32 array) and reward, from C++."""
        obs = np.empty((len(self.possible_agents), self._observer.size), np.float32)
        rew = np.empty(len(self.possible_agents))
        self._observer.observe_all(self.sim, obs, rew)
        if self.altitude:  # the agent's altitude last (m)
            obs = np.hstack([obs, self.sim.uav_altitudes.astype(np.float32).reshape(-1, 1)])
        return obs, rew

    def _show(self, frame):
        if self._window is None:
            try:
                import matplotlib
                import matplotlib.pyplot as plt
            except ImportError:
                raise RuntimeError("TrackingEnv: render_mode 'human' shows frames with matplotlib, "
                                   "which is not installed (Debian: apt-get install python3-matplotlib)") from None
            figure, axes = plt.subplots(figsize=(frame.shape[1] / 100, frame.shape[0] / 100), dpi=100)
            axes.set_axis_off()
            figure.subplots_adjust(0, 0, 1, 1)
            image = axes.imshow(frame)
            self._window = (plt, figure, image)
            interactive = matplotlib.get_backend().lower() in {
                b.lower() for b in matplotlib.rcsetup.interactive_bk}
            self._window_interactive = interactive
            if interactive:
                plt.show(block=False)
        plt, figure, image = self._window
        image.set_data(frame)
        figure.canvas.draw()
        if self._window_interactive:
            plt.pause(1.0 / self.metadata["render_fps"])


def _altitude_limits(uav):
    """(z_min, z_max, climb rate usable) of a scenario's UAV entry (m, m, m/s): its altitude is
    free when the entry gives z_min < z_max and a climb_rate > 0 (spec's defaults: z = 20 m,
    z_min = z_max = z, climb_rate 2 m/s once any of them is given)."""
    z = float(uav.get("z", 20.0))
    z_min, z_max = float(uav.get("z_min", z)), float(uav.get("z_max", z))
    climb = float(uav.get("climb_rate", 2.0)) if z_min < z_max else 0.0
    return z_min, z_max, climb
