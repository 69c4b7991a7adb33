"""Spaces for TrackingEnv and VectorEnv: ``gymnasium.spaces.Box`` when gymnasium is importable,
otherwise a small stand-in with the same attributes (shape, dtype, low, high) and methods
(sample, contains, seed, is_bounded) that ParallelEnv users rely on.

``GYMNASIUM`` tells which: True when the spaces are gymnasium's own."""
import numpy as np

try:
    import gymnasium.spaces as _gym_spaces
except ImportError:  # not installed (Debian 12 packages neither gymnasium nor pettingzoo)
    _gym_spaces = None

GYMNASIUM = _gym_spaces is not None


class Box:
    """low ≤ x ≤ high elementwise, of a fixed shape and dtype."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(int(n) for n in shape)
        self.low = np.broadcast_to(np.asarray(low, self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, self.dtype), self.shape).copy()
        self.low.flags.writeable = False
        self.high.flags.writeable = False
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def is_bounded(self, manner="both"):
        below, above = bool(np.all(np.isfinite(self.low))), bool(np.all(np.isfinite(self.high)))
        return {"both": below and above, "below": below, "above": above}[manner]

    def sample(self):
        """Uniform where both bounds are finite, standard normal elsewhere (as gymnasium)."""
        finite = np.isfinite(self.low) & np.isfinite(self.high)
        x = self._rng.standard_normal(self.shape)
        x[finite] = self._rng.uniform(self.low[finite], self.high[finite])
        return np.clip(x.astype(self.dtype), self.low, self.high)

    def contains(self, x):
        if not isinstance(x, np.ndarray):
            x = np.asarray(x, dtype=self.dtype)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    __contains__ = contains

    def __eq__(self, other):
        return (isinstance(other, Box) and self.shape == other.shape and self.dtype == other.dtype
                and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))

    __hash__ = None

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


def box(low, high, shape, dtype=np.float32):
    """A gymnasium Box when gymnasium is importable, else the stand-in; low and high are scalars
    or arrays of ``shape``."""
    low = np.broadcast_to(np.asarray(low, dtype), shape)
    high = np.broadcast_to(np.asarray(high, dtype), shape)
    if GYMNASIUM:
        return _gym_spaces.Box(low=low, high=high, shape=tuple(shape), dtype=dtype)
    return Box(low, high, shape, dtype)

