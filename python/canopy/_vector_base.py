"""The base class of canopy.VectorEnv: ``gymnasium.vector.VectorEnv`` when Gymnasium is importable
(so that its vector wrappers, which check ``isinstance(env, gymnasium.vector.VectorEnv)``, take
it), else a stand-in with the same attributes and methods: ``metadata``, ``spec``,
``render_mode``, ``closed``, ``np_random`` / ``np_random_seed``, ``unwrapped``, ``close()`` →
``close_extras()``. As TrackingEnv takes ``pettingzoo.ParallelEnv`` (env.py).

``GYMNASIUM_VECTOR`` tells which; ``SAME_STEP`` and ``NEXT_STEP`` are Gymnasium's
``AutoresetMode`` members where that exists, else their values ("SameStep", "NextStep")."""
import numpy as np

try:
    from gymnasium.vector import VectorEnv as _VectorEnvBase
    from gymnasium.vector import AutoresetMode as _AutoresetMode
    GYMNASIUM_VECTOR = True
    SAME_STEP, NEXT_STEP = _AutoresetMode.SAME_STEP, _AutoresetMode.NEXT_STEP
except ImportError:  # not installed (not a Debian package), or a Gymnasium before 1.0
    GYMNASIUM_VECTOR = False
    SAME_STEP, NEXT_STEP = "SameStep", "NextStep"

    class _VectorEnvBase:
        """The attributes and methods gymnasium.vector.VectorEnv (1.x) gives its subclasses."""

        metadata = {}
        spec = None
        render_mode = None
        closed = False
        _np_random = None
        _np_random_seed = None

        def render(self):
            raise NotImplementedError(f"{self} render function is not implemented.")

        def close(self, **kwargs):
            if self.closed:
                return
            self.close_extras(**kwargs)
            self.closed = True

        def close_extras(self, **kwargs):
            pass

        @property
        def np_random(self):
            if self._np_random is None:
                self._np_random, self._np_random_seed = _random_generator(None)
            return self._np_random

        @np_random.setter
        def np_random(self, value):
            self._np_random, self._np_random_seed = value, -1

        @property
        def np_random_seed(self):
            if self._np_random_seed is None:
                self._np_random, self._np_random_seed = _random_generator(None)
            return self._np_random_seed

        @property
        def unwrapped(self):
            return self

        def __repr__(self):
            return f"{type(self).__name__}(num_envs={self.num_envs})"


def _random_generator(seed):
    """As gymnasium.utils.seeding.np_random: a PCG64 generator and the seed it was made from (drawn
    when None; -1 for a sequence of seeds, which no one integer names)."""
    sequence = np.random.SeedSequence(seed)
    entropy = sequence.entropy
    return (np.random.Generator(np.random.PCG64(sequence)),
            int(entropy) if np.ndim(entropy) == 0 else -1)


def autoreset_value(mode):
    """The string value of an AutoresetMode member or of its value ("NextStep", "SameStep")."""
    return getattr(mode, "value", mode)
