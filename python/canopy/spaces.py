"""Box spaces for TrackingEnv: gymnasium.spaces.Box when gymnasium is importable, otherwise a
small stand-in with the same attributes (shape, dtype, low, high) and methods (sample, contains,
seed) that ParallelEnv users rely on."""
import numpy as np

try:  # pragma: no cover - depends on the machine
    from gymnasium.spaces import Box as _GymBox
except ImportError:  # gymnasium is not installable here (issue 15)
    _GymBox = None


class Box:
    """low ≤ x ≤ high elementwise, of a fixed shape and dtype."""

    def __init__(self, low, high, shape, dtype=np.float32, seed=None):
        self.shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self.low = np.broadcast_to(np.asarray(low, self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, self.dtype), self.shape).copy()
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        """Uniform where both bounds are finite, standard normal elsewhere (as gymnasium)."""
        finite = np.isfinite(self.low) & np.isfinite(self.high)
        x = self._rng.standard_normal(self.shape)
        x[finite] = self._rng.uniform(self.low[finite], self.high[finite])
        return x.astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    __contains__ = contains

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


def box(low, high, shape, dtype=np.float32):
    """A gymnasium Box when gymnasium is importable, else the stand-in."""
    if _GymBox is not None:  # pragma: no cover
        return _GymBox(low=np.broadcast_to(np.asarray(low, dtype), shape),
                       high=np.broadcast_to(np.asarray(high, dtype), shape), dtype=dtype)
    return Box(low, high, shape, dtype)
